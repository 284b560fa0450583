//! Algorithm 5.1 on the GPU against the CPU's sea colour, term by term.

use super::*;

/// One of the three terms of a [`SeaLight`].
type Term = fn(&SeaLight) -> DVec3;

/// The absolute floor of the sea-colour parity, relative to each term's peak over the table.
const FLOOR: f64 = 1e-9;

fn f32_round(v: DVec3) -> DVec3 {
    v.as_vec3().as_dvec3()
}

/// Algorithm 5.1 on the GPU against `sea_color_unchecked`, term by term (§7.2 validates the
/// three terms apart, Fig. 10), over a table covering grazing (0.5°) to vertical views, vertical,
/// tilted (up to 35°) and back-facing normals, calm (no unresolved variance: the Sun's disc
/// only) to rough (σ² = 0.2) seas, two winds, and the Sun's glint in (views at the mirror
/// direction of the Sun, and 1 to 4 slope deviations off it) and out; and, as the fragment
/// stages light a pixel, with the normal made masking-aware first (`visible_normal`, §3.2):
/// normals off level and tilted geometry with normal-only variances, on the CPU
/// `sea_color_unchecked` of `sea::visible_normal`.
///
/// Tolerance: each channel of each term within 1 % of the CPU's value, or within an absolute
/// floor of [`FLOOR`] times that term's largest value over the table (f32 cannot promise 1 % of
/// a value 10⁹ times below the term's peak, deep in the tails of the Sun's Gaussian, nor
/// does it matter on screen). The inputs are rounded to f32 on both sides, so only the
/// arithmetic differs.
#[test]
fn sea_color_matches_the_cpu_twin() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let r = renderer(&ctx, OceanOptions::default());
    let light = lighting();
    let sky_map = light.sky_map(r.options().sky_map_size).expect("sky map");
    let sun = light.sky().sun_direction();

    let variances = [
        (0.0, 0.0),
        (1e-5, 8e-6),
        (1e-3, 6e-4),
        (0.01, 0.007),
        (0.05, 0.03),
        (0.2, 0.1),
    ];
    let normals = [
        DVec3::Y,
        unit(DVec3::new(0.1, 1.0, 0.05)),
        unit(DVec3::new(-0.3, 1.0, 0.4)),
        unit(DVec3::new(0.0, 1.0, -0.7)),
    ];
    let winds = [DVec2::X, DVec2::new(0.6, 0.8)];
    let mut inputs = Vec::new();
    for &(vx, vy) in &variances {
        let variance = SlopeVariance { x: vx, y: vy };
        let sigma = f64::max(vx.max(vy), 1.35e-6).sqrt();
        for (ni, &n) in normals.iter().enumerate() {
            let wind = winds[ni % 2];
            let mut views = vec![
                dir(0.5, 90.0),
                dir(0.5, -80.0),
                dir(2.0, 30.0),
                dir(5.0, 95.0),
                dir(15.0, 200.0),
                dir(30.0, 60.0),
                dir(60.0, -120.0),
                dir(89.0, 10.0),
                DVec3::Y,
            ];
            // The Sun's mirror direction about n (the glint's centre), and views off it by 1, 2
            // and 4 slope deviations (a slope δ turns the reflection by 2δ).
            let mirror = n * (2.0 * n.dot(sun)) - sun;
            if mirror.y > 0.0 {
                let side = unit(mirror.cross(DVec3::Y));
                for k in [0.0, 1.0, 2.0, 4.0] {
                    views.push(unit(mirror + side * (2.0 * k * sigma)));
                }
            }
            for v in views {
                inputs.push(SeaColorInput::plain(
                    f32_round(v),
                    f32_round(n),
                    wind,
                    variance,
                ));
            }
        }
    }
    // Back-facing normals (§3.2: reflected about the plane normal to v): grazing views over
    // normals tilted away from the viewer.
    for &(vx, vy) in &variances[2..] {
        for (v, n) in [
            (dir(1.0, 90.0), unit(DVec3::new(0.0, 0.2, -1.0))),
            (dir(3.0, -90.0), unit(DVec3::new(0.3, 0.1, 1.0))),
            (dir(10.0, 0.0), unit(DVec3::new(-1.0, 0.15, 0.0))),
        ] {
            assert!(v.dot(n) < 0.0, "back-facing case");
            inputs.push(SeaColorInput::plain(
                f32_round(v),
                f32_round(n),
                DVec2::X,
                SlopeVariance { x: vx, y: vy },
            ));
        }
    }
    // The masking-aware normal (§3.2, `visible_normal`): normals tilted off the geometry's by
    // the waves only they resolve, over level and tilted geometry, grazing to steep views,
    // small to large normal-only variances (up to a quarter of the slope variance of the
    // default sea) against small to large BRDF variances, two winds.
    let normal_only = [(0.004, 0.002), (0.02, 0.012)];
    let geometry = [DVec3::Y, unit(DVec3::new(0.06, 1.0, -0.03))];
    let tilted = [
        unit(DVec3::new(0.1, 1.0, 0.05)),
        unit(DVec3::new(-0.2, 1.0, 0.3)),
    ];
    for &(vx, vy) in &variances[2..5] {
        for &(nx, ny) in &normal_only {
            for (gi, &g) in geometry.iter().enumerate() {
                for &n in &tilted {
                    for v in [
                        dir(1.0, 90.0),
                        dir(3.0, -80.0),
                        dir(10.0, 30.0),
                        dir(40.0, 200.0),
                    ] {
                        inputs.push(SeaColorInput {
                            geometry_normal: f32_round(g),
                            normal_only: SlopeVariance { x: nx, y: ny },
                            ..SeaColorInput::plain(
                                f32_round(v),
                                f32_round(n),
                                winds[gi],
                                SlopeVariance { x: vx, y: vy },
                            )
                        });
                    }
                }
            }
        }
    }

    let gpu = r.probe_sea_color(&ctx, &inputs).expect("probe");
    let cpu: Vec<SeaLight> = inputs
        .iter()
        .map(|s| {
            let f32_var = |v: SlopeVariance| SlopeVariance {
                x: f64::from(v.x as f32),
                y: f64::from(v.y as f32),
            };
            let variance = f32_var(s.variance);
            let wind = s.wind.as_vec2().as_dvec2();
            let n = visible_normal(
                s.v,
                s.n,
                s.geometry_normal,
                wind,
                f32_var(s.normal_only),
                variance,
            );
            sea_color_unchecked(&light, &sky_map, s.v, n, wind, variance)
        })
        .collect();
    assert_eq!(gpu.len(), inputs.len());

    let terms: [(&str, Term); 3] = [("sun", |l| l.sun), ("sky", |l| l.sky), ("sea", |l| l.sea)];
    let mut failures = Vec::new();
    for (name, term) in terms {
        let peak = cpu
            .iter()
            .map(|l| term(l).max_element())
            .fold(0.0, f64::max);
        assert!(peak > 0.0, "{name}: the table must light this term");
        let floor = FLOOR * peak;
        let (mut worst, mut worst_at) = (0.0f64, 0);
        let mut compared = 0;
        for (i, (g, c)) in gpu.iter().zip(&cpu).enumerate() {
            let (g, c) = (term(g), term(c));
            for ch in 0..3 {
                let (g, c) = (g[ch], c[ch]);
                assert!(g.is_finite(), "{name} #{i}: GPU gives {g}");
                let err = (g - c).abs();
                if c.abs() > floor {
                    compared += 1;
                    let rel = err / c.abs();
                    if rel > worst {
                        (worst, worst_at) = (rel, i);
                    }
                }
                if err > 0.01 * c.abs() && err > floor {
                    failures.push(format!(
                        "{name} #{i} channel {ch}: GPU {g:e}, CPU {c:e} ({:?})",
                        inputs[i]
                    ));
                }
            }
        }
        println!(
            "sea colour, {name}: worst relative difference {worst:.2e} (input #{worst_at}, {:?}) \
             over {compared} channels above the floor {floor:.2e} (peak {peak:.3e})",
            inputs[worst_at]
        );
    }
    assert!(
        failures.is_empty(),
        "{} of {} terms outside 1 %:\n{}",
        failures.len(),
        inputs.len() * 9,
        failures.join("\n")
    );
}
