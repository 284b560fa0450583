//! The bilateral reconstruction passes (§2.4).

use ocean_sao::blur::{Axis, BlurConstants};
use ocean_sao::pack::{SKY_KEY, Texel, dequantise_ao, encode_key, pack};
use ocean_sao::{BlurParams, BlurWeight, SKY_Z, Viewport};

const INV_Z_MIN: f32 = 1.0 / -200.0;

fn image(w: usize, h: usize, f: impl Fn(usize, usize) -> (f32, f32)) -> Vec<Texel> {
    let mut out = Vec::new();
    for y in 0..h {
        for x in 0..w {
            let (a, z) = f(x, y);
            out.push(pack(a, encode_key(z, INV_Z_MIN)));
        }
    }
    out
}

/// The paper's weights: Gaussian `exp(−t²/(2σ²))` with σ = 1.5 taps for taps 0..=3 of 7.
#[test]
fn gaussian_weights() {
    let g = BlurParams::paper().gaussian();
    let want = [
        1.0,
        (-1.0f64 / 4.5).exp(),
        (-4.0f64 / 4.5).exp(),
        (-9.0f64 / 4.5).exp(),
    ];
    assert_eq!(g.len(), 4);
    for (a, b) in g.iter().zip(want) {
        assert!((f64::from(*a) - b).abs() < 1e-7);
    }
}

/// A single dark pixel (A = 0) in a field of A = 1 at one depth: after the horizontal pass, the
/// pixel `s·k` away (stride s) reads `1 − g_k/Σg` (every tap in range, all depth weights 1), and
/// pixels not on the stride lattice stay 1: the paper's 7 taps of stride 3, and the default 13
/// of stride 1, which reach every pixel within 6.
#[test]
fn impulse_response() {
    let (w, h) = (41, 3);
    let img = image(w, h, |x, _| (if x == 20 { 0.0 } else { 1.0 }, -4.0));
    for params in [BlurParams::paper(), BlurParams::default()] {
        let blur = BlurConstants::new(&params, true);
        let g = &blur.gauss;
        let sum: f32 = g[0] + 2.0 * g[1..].iter().sum::<f32>();
        let (stride, r) = (i64::from(params.stride), g.len() as i64 - 1);
        for x in 5..36usize {
            let got = blur.blur_pixel(&img, w, h, x, 1, Axis::Horizontal);
            let d = x as i64 - 20;
            let want = if d % stride == 0 && d.abs() <= r * stride {
                1.0 - g[(d.abs() / stride) as usize] / sum
            } else {
                1.0
            };
            assert!(
                (got - want).abs() < 1e-6,
                "stride {stride}, x {x}: {got} vs {want}"
            );
        }
    }
}

/// The depth weight `max(0, 1 − 2¹¹·|Δkey|)` stops the blur at a 0.5 m depth step (Δkey =
/// 0.0025, weight 0): two flat halves keep their own A exactly, through both passes.
#[test]
fn depth_edges_are_kept() {
    let (w, h) = (24, 20);
    let img = image(w, h, |x, _| if x < 12 { (0.2, -3.0) } else { (0.8, -3.5) });
    let vp = Viewport::new(w, h, 0).unwrap();
    let blur = BlurConstants::new(&BlurParams::default(), true);
    let out = blur.vertical(&vp, &blur.horizontal(&vp, &img));
    for (i, a) in out.iter().enumerate() {
        let want = dequantise_ao(pack(if i % w < 12 { 0.2 } else { 0.8 }, 0)[0]);
        assert!((a - want).abs() < 1e-6, "pixel {i}: {a}");
    }
}

/// Sky pixels pass through unchanged and do not contribute: a sky column of A = 1 beside
/// geometry with A = 0.3 at the same nominal key leaves both as they are.
#[test]
fn sky_passes_through() {
    let (w, h) = (16, 8);
    let img: Vec<Texel> = (0..w * h)
        .map(|i| {
            if i % w < 8 {
                pack(0.3, encode_key(-5.0, INV_Z_MIN))
            } else {
                pack(1.0, SKY_KEY)
            }
        })
        .collect();
    let vp = Viewport::new(w, h, 0).unwrap();
    let blur = BlurConstants::new(&BlurParams::default(), true);
    let out = blur.vertical(&vp, &blur.horizontal(&vp, &img));
    for (i, a) in out.iter().enumerate() {
        let want = if i % w < 8 {
            dequantise_ao(pack(0.3, 0)[0])
        } else {
            1.0
        };
        assert!((a - want).abs() < 1e-6, "pixel {i}: {a}");
    }
    assert_eq!(encode_key(SKY_Z, INV_Z_MIN), SKY_KEY);
}

/// One tap is the identity; taps at the image border are skipped and the weights renormalised,
/// so a constant image stays constant up to the border.
#[test]
fn one_tap_and_borders() {
    let (w, h) = (10, 10);
    let img = image(w, h, |x, y| ((x * 7 + y * 3) as f32 / 100.0, -2.0));
    let vp = Viewport::new(w, h, 0).unwrap();
    let one = BlurConstants::new(
        &BlurParams {
            taps: 1,
            ..BlurParams::default()
        },
        true,
    );
    assert_eq!(one.horizontal(&vp, &img), img);
    let flat = image(w, h, |_, _| (0.6, -2.0));
    let blur = BlurConstants::new(&BlurParams::default(), true);
    let out = blur.vertical(&vp, &blur.horizontal(&vp, &flat));
    let want = dequantise_ao(flat[0][0]);
    assert!(out.iter().all(|a| (a - want).abs() < 1e-6));
}

/// The horizontal response at `x = 20 + d` to a dark pixel at `x = 20` on a row whose z is
/// `z(x)`, for a blur weight and projection kind, with the paper's taps (7, stride 3: the
/// farthest 9 px away, where a sloped plane strays farthest from the centre's depth).
fn impulse_on(z: impl Fn(usize) -> f32, weight: BlurWeight, perspective: bool) -> Vec<f32> {
    let (w, h) = (41, 3);
    let img = image(w, h, |x, _| (if x == 20 { 0.0 } else { 1.0 }, z(x)));
    let blur = BlurConstants::new(
        &BlurParams {
            weight,
            ..BlurParams::paper()
        },
        perspective,
    );
    (0..w)
        .map(|x| blur.blur_pixel(&img, w, h, x, 1, Axis::Horizontal))
        .collect()
}

/// The flat-surface response of `impulse_response` at lattice distance `d` (pixels) with the
/// paper's taps.
fn flat_response(d: i64) -> f32 {
    let g = BlurParams::paper().gaussian();
    let sum: f32 = g[0] + 2.0 * (g[1] + g[2] + g[3]);
    1.0 - g[(d.abs() / 3) as usize] / sum
}

/// On a plane sloped to the view the plane weight gives the flat-surface response, the paper's
/// weight does not.
///
/// In perspective a plane has `1/z` affine in screen x: here `1/z = −1/4 − 0.004·x` m⁻¹, about
/// 8 mm of depth per pixel at 4 m (a face at ~75° to the view at 640 px over 1 rad). With the
/// plane weight every tap lies within the key quantisation of the plane's prediction (at most
/// about 1.5 key steps, 0.05 of weight at 2¹¹), so the response is the flat one within 0.01;
/// with the paper's weight the taps 9 px away differ from the centre by ~0.07 m (Δkey 3.6e-4,
/// weight 0.27) and the response is far from it. The same holds for an orthographic view, where
/// z itself is affine.
#[test]
fn sloped_planes_blur_like_flat_ones() {
    let perspective_z = |x: usize| 1.0 / (-0.25 - 0.004 * x as f32);
    let orthographic_z = |x: usize| -4.0 - 0.008 * x as f32;
    type Depth<'a> = &'a dyn Fn(usize) -> f32;
    let cases: [(&str, bool, Depth); 2] = [
        ("perspective", true, &perspective_z),
        ("orthographic", false, &orthographic_z),
    ];
    for (name, perspective, z) in cases {
        let plane = impulse_on(z, BlurWeight::Plane, perspective);
        let depth = impulse_on(z, BlurWeight::Depth, perspective);
        let mut worst_depth = 0.0f32;
        for d in (-9..=9).step_by(3) {
            let x = (20 + d) as usize;
            let want = flat_response(d);
            assert!(
                (plane[x] - want).abs() < 0.01,
                "{name} d {d}: plane {} vs {want}",
                plane[x]
            );
            worst_depth = worst_depth.max((depth[x] - want).abs());
        }
        println!("{name}: paper weight off the flat response by {worst_depth:.3}");
        assert!(worst_depth > 0.03, "{name}: {worst_depth}");
    }
}

/// The plane weight still stops at a depth step: the two halves of a row, each a sloped plane,
/// 0.5 m apart at the step, keep their own A through both passes, the pixels at the step too
/// (their slope comes from the neighbour on their own side).
#[test]
fn plane_weight_keeps_depth_edges() {
    let (w, h) = (24, 20);
    let img = image(w, h, |x, _| {
        let z = -3.0 - 0.01 * x as f32;
        if x < 12 { (0.2, z) } else { (0.8, z - 0.5) }
    });
    let vp = Viewport::new(w, h, 0).unwrap();
    let blur = BlurConstants::new(&BlurParams::default(), true);
    let out = blur.vertical(&vp, &blur.horizontal(&vp, &img));
    for (i, a) in out.iter().enumerate() {
        let want = dequantise_ao(pack(if i % w < 12 { 0.2 } else { 0.8 }, 0)[0]);
        assert!((a - want).abs() < 1e-6, "pixel {i}: {a}");
    }
}
