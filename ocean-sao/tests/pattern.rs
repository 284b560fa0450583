//! The reconstruction's residual pattern on obscured faces: the sampling pattern of the sample
//! pass (its per-pixel spiral rotation) must not survive the blur on surfaces sloped to the
//! view, the case a depth-keyed bilateral fails.

mod common;

use common::{Render, perspective};
use ocean_core::{DepthConvention, Far};
use ocean_sao::analytic::{AnalyticView, DepthFormat, NO_FACE};
use ocean_sao::{BlurParams, DepthSource, SaoParams};

/// 640 × 360 output with a 32 px guard band.
const SIZE: (usize, usize, usize) = (704, 424, 32);

/// RMS of `A − mean₇ₓ₇(A)` (in 1/255) over the obscured pixels (7 × 7 mean below 0.99) whose
/// 7 × 7 window lies on one face, for faces seen within 45°, at 45–70° and beyond 70° of their
/// normal; with the pixel counts.
fn pattern(r: &Render, ao: &[f32]) -> [(f64, usize); 3] {
    let ow = r.viewport.output_width();
    let oh = r.viewport.output_height();
    let face = |x: usize, y: usize| r.raster.face[r.input_index(y * ow + x)];
    let mut acc = [(0.0f64, 0usize); 3];
    for y in 3..oh - 3 {
        for x in 3..ow - 3 {
            let f = face(x, y);
            if f == NO_FACE {
                continue;
            }
            let mut sum = 0.0f64;
            let mut same = true;
            for j in y - 3..=y + 3 {
                for i in x - 3..=x + 3 {
                    same &= face(i, j) == f;
                    sum += f64::from(ao[j * ow + i]);
                }
            }
            let mean = sum / 49.0;
            if !same || mean >= 0.99 {
                continue;
            }
            let i = y * ow + x;
            let p = r.raster.view_position[r.input_index(i)];
            let n = r.raster.view_normal[r.input_index(i)];
            let angle = n
                .dot(-p.normalize())
                .abs()
                .clamp(0.0, 1.0)
                .acos()
                .to_degrees();
            let bin = if angle < 45.0 {
                0
            } else if angle < 70.0 {
                1
            } else {
                2
            };
            let d = (f64::from(ao[i]) - mean) * 255.0;
            acc[bin].0 += d * d;
            acc[bin].1 += 1;
        }
    }
    acc.map(|(s, n)| ((s / n.max(1) as f64).sqrt(), n))
}

fn render(e: f64, a: f64) -> Render {
    Render::new(
        AnalyticView::boxes(e.to_radians(), a.to_radians(), 4.5),
        perspective(SIZE.0, SIZE.1, Far::Infinite),
        DepthConvention::ZERO_TO_ONE_REVERSED,
        DepthSource::Window,
        DepthFormat::F32,
        SIZE,
    )
}

/// Camera placements (elevation, azimuth in degrees): low and high, face-on and oblique.
const VIEWS: [(f64, f64); 5] = [
    (12.0, 25.0),
    (12.0, 70.0),
    (30.0, 40.0),
    (55.0, 15.0),
    (20.0, 170.0),
];

/// Bins with fewer pixels than this are slivers (a box side seen edge-on): reported, not
/// asserted, since their 7 × 7 windows hold the obscurance's own gradient.
const MIN_PIXELS: usize = 500;

/// The pattern measure with the defaults, on every view: at most 4/255 within 45° and 6/255
/// beyond 70°. Measured 1.25–1.78 and 1.98–2.65 (3.0–3.9 and 4.6–5.7 with the plane weight
/// over the paper's 7 taps of stride 3). Printed beside it: the paper's blur (3.1–4.0, 4.2–6.8
/// at 45–70° and 10.9–12.4 beyond 70°: it rejects the taps of sloped faces) and no blur (20–30
/// everywhere), so the measure is seen to fail where the pattern is left.
#[test]
fn sampling_pattern_is_removed_on_sloped_faces() {
    let no_blur = SaoParams {
        blur: BlurParams {
            taps: 1,
            ..BlurParams::default()
        },
        ..SaoParams::default()
    };
    let mut paper_worst = 0.0f64;
    for (e, a) in VIEWS {
        let r = render(e, a);
        let mut got = [(0.0, 0); 3];
        for (name, p) in [
            ("defaults", SaoParams::default()),
            ("paper", SaoParams::paper()),
            ("no blur", no_blur),
        ] {
            let m = pattern(&r, &r.stages(p).ao);
            println!(
                "elevation {e:>2}° azimuth {a:>3}° {name:>8}: within 45° {:5.2}/255 ({} px), \
                 45–70° {:5.2} ({}), beyond 70° {:5.2} ({})",
                m[0].0, m[0].1, m[1].0, m[1].1, m[2].0, m[2].1
            );
            match name {
                "defaults" => got = m,
                "paper" if m[2].1 >= MIN_PIXELS => paper_worst = paper_worst.max(m[2].0),
                _ => {}
            }
        }
        for (bin, limit) in [(0, 4.0), (2, 6.0)] {
            let (rms, n) = got[bin];
            if n >= MIN_PIXELS {
                assert!(rms <= limit, "({e}, {a}) bin {bin}: {rms}/255 over {n} px");
            }
        }
    }
    assert!(paper_worst > 6.0, "the paper's weight: {paper_worst}");
}

/// No dark line along silhouettes: along every silhouette (a face pixel whose neighbour along
/// an axis lies on another face more than 0.3 m farther; the horizon is not one), the mean final A of the
/// one-pixel band is compared with the mean of the pixels three further in on the same face.
/// Measured with the defaults: within ±0.06/255 on four of the five views and 2.8/255 darker on
/// the view from 55° above (the paper's normals and blur: 7.2/255 there, up to 0.4 elsewhere).
/// Asserted: within 2/255 wherever the paper's band is within 2/255, else at most half of the
/// paper's darkening. The 55° view's remaining band is not explained yet.
#[test]
fn no_dark_line_along_silhouettes() {
    for (e, a) in VIEWS {
        let mut bands = Vec::new();
        let r = render(e, a);
        let ow = r.viewport.output_width();
        let oh = r.viewport.output_height();
        let at = |x: usize, y: usize| r.input_index(y * ow + x);
        for (name, p) in [
            ("defaults", SaoParams::default()),
            ("paper", SaoParams::paper()),
        ] {
            let ao = r.stages(p).ao;
            let (mut edge, mut inner, mut n) = (0.0f64, 0.0f64, 0usize);
            for y in 4..oh - 4 {
                for x in 4..ow - 4 {
                    let i = at(x, y);
                    let f = r.raster.face[i];
                    if f == NO_FACE {
                        continue;
                    }
                    let z = r.raster.view_position[i].z;
                    for (dx, dy) in [(-1i64, 0i64), (1, 0), (0, -1), (0, 1)] {
                        let o =
                            |k: i64| ((x as i64 + dx * k) as usize, (y as i64 + dy * k) as usize);
                        let (nx, ny) = o(1);
                        let j = at(nx, ny);
                        let behind =
                            r.raster.face[j] != NO_FACE && r.raster.view_position[j].z < z - 0.3;
                        let (ix, iy) = o(-3);
                        if !behind || r.raster.face[at(ix, iy)] != f {
                            continue;
                        }
                        edge += f64::from(ao[y * ow + x]);
                        inner += f64::from(ao[iy * ow + ix]);
                        n += 1;
                    }
                }
            }
            let diff = (inner - edge) / n as f64 * 255.0;
            println!("({e}, {a}) {name:>8}: silhouette band {diff:+.2}/255 darker over {n} px");
            bands.push(diff);
            assert!(n > 200, "{n}");
        }
        let (new, paper) = (bands[0], bands[1]);
        if paper.abs() <= 2.0 {
            assert!(new.abs() <= 2.0, "({e}, {a}): {new}/255");
        } else {
            assert!(
                new.abs() <= paper.abs() * 0.5,
                "({e}, {a}): {new} vs {paper}"
            );
        }
    }
}
