//! The paper's validation (§7.2, Fig. 10): per-row mean radiance of the filtered model against
//! detailed geometry with a perfect mirror (`ocean_brdf::validation`), for a calm (5 m/s) and an
//! agitated (15 m/s) sea, with a constant-BRDF model alongside.
//!
//! The reference holds **every** wave of the spectrum (2 cm to 30 m) in its geometry, profiles
//! sampled every 5 mm. An earlier reference kept only the waves longer than 10 cm in the
//! geometry (5 cm steps, the paper's triangle size) and the shorter ones in the normals only:
//! those carry 22–24 % of the slope variance and were not masked, so 3 % of its hits showed a
//! facet turned away from the viewer (0.02 % with every wave in the geometry), and its
//! refracted light was 10–13 % too low (sky light a few % high) at every distance. 2.5 and
//! 1.25 mm steps change the near rows' means by less than 0.5 %.
//!
//! Measured here (the default sampling: 32 reference planes × 32 rays per pixel row, 256 model
//! planes; 256² image 4 m above the sea; 108 rows from 46 to 300 m, 19 from 300 m to 3.9 km;
//! about 2.5 minutes on two shared cores), model error (model − reference)/reference:
//!
//! | sea, rows        | sky: bias, mean abs, worst | refracted: bias, mean abs, worst |
//! |------------------|----------------------------|----------------------------------|
//! | calm, near       | +6.0 %, 6.3 %, 16.8 %      | −6.5 %, 6.9 %, 16.3 %            |
//! | calm, far        | +12.0 %, 12.0 %, 14.3 %    | −13.2 %, 13.2 %, 15.1 %          |
//! | agitated, near   | +6.1 %, 7.4 %, 37.1 %      | −6.0 %, 6.7 %, 24.8 %            |
//! | agitated, far    | +13.0 %, 13.0 %, 19.1 %    | −13.5 %, 13.5 %, 17.0 %          |
//!
//! The constant-BRDF model is 32–49 % off beyond 300 m, 2.3–3.7 times the model's error on
//! every such row. The model is the renderer's (`FilteredSurface::pixel` lit by
//! `sea::pixel_color`, the CPU twin of `ocean_fs`), so these are the figures of what the GPU
//! draws. The 5 % per row is **not met** for either component:
//! - near rows: the model's masking-aware normal (`sea::visible_normal`) halves the bias of the
//!   waves resolved in the normals but not in the geometry (without it, rows 46–213 m: sky
//!   +9.7 %, refracted −12 %; with it +5.7 %, −6.2 %); with the geometry holding every wave the normals hold (a 1-pixel
//!   grid), the bias is +3.5 % / −4 %, the floor of the BRDF part below;
//! - far rows, where every wave is in the BRDF: the model there is Ross's BRDF on a flat normal,
//!   and it is within 0.2 % (F̄) and 2.5 % (I_sky) of Ross's exact integral
//!   `∬ q^e_vn F L d²ζ` at these grazing views; the 12–13 % left are Smith's masking (Eq. 8–10)
//!   against the trochoid sea, which `examples/masking_study.rs` takes apart (1 − F̄ at
//!   1000 m, wind 5 / 15 m/s): Gaussian slopes 0.440 / 0.472, the sea's own sampled slopes
//!   0.440 / 0.473, those masked by Smith's height visibility F(h)^Λ (keeping the sea's
//!   height–slope correlation: its highest 1 % have 13–37 % more slope variance) 0.451 /
//!   0.491, ray casting like this reference 0.496 / 0.537. The correlation is a fifth to under
//!   a third of the gap; the rest is Smith's premise that a facet's visibility depends on its
//!   height alone: the rays hit lower (mean height quantile 0.86 against Smith's 0.91 at wind
//!   5) and on facets tilted more towards the eye (0.141 against 0.124) than Smith's visible
//!   facets, so less light is reflected and more refracted.
//! - The Sun's term is not compared: a perfect mirror reflects the Sun's disc (7e-5 sr) into a
//!   handful of the reference's rays per row, too few for a row mean.

use glam::DVec3;
use ocean_brdf::SpectrumParams;
use ocean_brdf::validation::{RowMeans, ValidationParams, validate};

fn sum(c: DVec3) -> f64 {
    c.x + c.y + c.z
}

fn run(wind_speed: f64) -> Vec<RowMeans> {
    let params = ValidationParams {
        spectrum: SpectrumParams {
            wind_speed,
            ..SpectrumParams::default()
        },
        ..ValidationParams::default()
    };
    validate(&params).unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b) / b
}

/// Bias, mean absolute and worst relative error of `model` against `reference` over `rows`.
fn stats(rows: &[&RowMeans], pick: impl Fn(&RowMeans) -> (f64, f64)) -> (f64, f64, f64) {
    let n = rows.len() as f64;
    let e: Vec<f64> = rows
        .iter()
        .map(|r| {
            let (m, reference) = pick(r);
            rel(m, reference)
        })
        .collect();
    (
        e.iter().sum::<f64>() / n,
        e.iter().map(|x| x.abs()).sum::<f64>() / n,
        e.iter().fold(0.0f64, |w, x| w.max(x.abs())),
    )
}

#[test]
fn filtered_model_follows_the_reference_and_the_constant_brdf_diverges() {
    // The measured envelopes (see the module documentation), each about one point above the
    // measured value so that a regression shows: (sky mean abs, sky worst, sea mean abs, sea
    // worst) for the near rows, then for the far rows.
    let bounds = [
        (5.0, [0.07, 0.18, 0.075, 0.17], [0.13, 0.155, 0.14, 0.16]),
        (15.0, [0.08, 0.38, 0.075, 0.26], [0.14, 0.20, 0.145, 0.18]),
    ];
    for (wind, near_bounds, far_bounds) in bounds {
        let rows = run(wind);
        // Rows from the bottom (centre at 46 m) to the row whose centre is at 3.9 km and upper
        // edge at 5.9 km.
        assert_eq!(rows.len(), 127);
        assert!(rows[0].distance < 50.0 && rows.last().unwrap().distance > 3500.0);
        println!("wind {wind} m/s: row, distance, sky ref/model/constant, sea ref/model/constant");
        for r in &rows {
            let (rs, ms, cs) = (sum(r.reference.sky), sum(r.model.sky), sum(r.constant.sky));
            let (rw, mw, cw) = (sum(r.reference.sea), sum(r.model.sea), sum(r.constant.sea));
            println!(
                "{:3} {:7.0} m  sky {rs:.4} {ms:.4} {cs:.4}  sea {rw:.5} {mw:.5} {cw:.5}",
                r.row, r.distance
            );
            if r.distance > 300.0 {
                let (model, constant) = (
                    rel(ms, rs).abs().max(rel(mw, rw).abs()),
                    rel(cs, rs).abs().max(rel(cw, rw).abs()),
                );
                // Measured: at least 0.32, and 2.3 times the model's error.
                assert!(
                    constant > 0.25,
                    "row {}: constant BRDF off by only {constant}",
                    r.row
                );
                assert!(
                    constant > 2.0 * model,
                    "row {}: {constant} vs {model}",
                    r.row
                );
            }
        }
        for (name, near, b) in [("near", true, near_bounds), ("far", false, far_bounds)] {
            let part: Vec<&RowMeans> = rows
                .iter()
                .filter(|r| (r.distance < 300.0) == near)
                .collect();
            let sky = stats(&part, |r| (sum(r.model.sky), sum(r.reference.sky)));
            let sea = stats(&part, |r| (sum(r.model.sea), sum(r.reference.sea)));
            println!(
                "wind {wind}, {name} rows: sky bias {:+.1} %, mean {:.1} %, worst {:.1} %; \
                 refracted bias {:+.1} %, mean {:.1} %, worst {:.1} %",
                sky.0 * 100.0,
                sky.1 * 100.0,
                sky.2 * 100.0,
                sea.0 * 100.0,
                sea.1 * 100.0,
                sea.2 * 100.0
            );
            assert!(
                sky.1 < b[0] && sky.2 < b[1],
                "wind {wind} {name}: sky {sky:?}"
            );
            assert!(
                sea.1 < b[2] && sea.2 < b[3],
                "wind {wind} {name}: sea {sea:?}"
            );
            // The model's known sign (see the module documentation): too much sky, too little
            // refracted light, the effective Fresnel too high at grazing views.
            assert!(
                sky.0 > 0.0 && sea.0 < 0.0,
                "wind {wind} {name}: {sky:?} {sea:?}"
            );
        }
    }
}

/// The same inputs give the same bits, whatever rayon's thread count.
#[test]
fn validation_is_deterministic_across_thread_counts() {
    let params = ValidationParams {
        size: 64,
        planes: 4,
        model_planes: 8,
        rays_per_pixel: 4,
        max_distance: 1500.0,
        profile_step: 0.2,
        ..ValidationParams::default()
    };
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap()
        .install(|| validate(&params).unwrap());
    let three = rayon::ThreadPoolBuilder::new()
        .num_threads(3)
        .build()
        .unwrap()
        .install(|| validate(&params).unwrap());
    assert_eq!(one, three);
}
