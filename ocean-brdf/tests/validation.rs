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
//! draws. The target of 5 % per row is **not met** for either component:
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
//!
//! **The Sun's term**, with the paper's Sun (1/8000 of the hemisphere, ρ = 0.906°; the default
//! `ValidationParams`), 1024 reference rays per pixel row and plane for it alone (+6–8 s per
//! sea). Each reference row comes with its standard error from the spread of its 32 planes
//! (`RowMeans::reference_sun_error`): 13–84 % (mean 35 %) per row below 300 m, 7–23 % (mean
//! 12 %) beyond. The planes set it, not the rays: 4–32 times more rays per plane leave it as it
//! is, because a plane crosses a row's strip of sea in a few glinting facets. The 1–2 % per
//! row that a per-row comparison needs would take about 1 000 planes beyond 300 m and 10⁴
//! below (each plane walks the 8 km profile at 5 mm: ~2.4 s), far beyond a test's budget; the
//! per-row comparison is therefore not made, and the rows are pooled where the errors allow
//! it. A slope bound does not help either: Σ kA = 1.8 (5 m/s) and 1.9 (15 m/s) exceed every
//! slope the glints need (≤ 0.25), so no column of the image can be excluded.
//!
//! | sea, rows        | Sun, model − reference: pooled (±1 SE), per-row bias, mean abs, worst |
//! |------------------|-----------------------------------------------------------------------|
//! | calm, near       | −21.9 ± 2.6 %, +5.2 %, 47 %, 1157 % (reference noise)               |
//! | calm, far        | −34.8 ± 1.9 %, −33.2 %, 33 %, 53 %                                    |
//! | agitated, near   | −16.9 ± 2.5 %, −5.6 %, 32 %, 119 % (reference noise)                |
//! | agitated, far    | −28.9 ± 2.1 %, −27.6 %, 28 %, 44 %                                    |
//!
//! (pooled: the model's sum over the rows against the reference's, the error from the rows'
//! standard errors.) So the model's glitter is **29–35 % too dim** far away and 17–22 % near,
//! 7–18 standard errors from the reference: the 5 % target is not met, and the per-row noise
//! of the reference (about 12 % far) is smaller than the miss. The likely cause (not measured directly) is the
//! one of the sky's far rows: the glints need a facet tilted about 12° towards the viewer, a
//! slope of 0.22 across the wind, 2.3 σ into the tail of Ross's Gaussian, where
//! `d ln p / d ln σ²` = (ζ²/σ² − 1)/2 ≈ 2.2, and the facets the rays see are tilted further
//! towards the eye than Smith's visible facets (above): the seen slopes are wider than the
//! Gaussian of the mean variance, and their tail brighter. The constant
//! BRDF loses 79–94 % of it on every row beyond 300 m.

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

/// The pooled relative error of `model` against `reference` over `rows` (ratio of the sums, less
/// one) and its standard error from the reference rows' own.
fn pooled_sun(rows: &[&RowMeans], model: impl Fn(&RowMeans) -> DVec3) -> (f64, f64) {
    let reference: f64 = rows.iter().map(|r| sum(r.reference.sun)).sum();
    let m: f64 = rows.iter().map(|r| sum(model(r))).sum();
    let se = rows
        .iter()
        .map(|r| sum(r.reference_sun_error).powi(2))
        .sum::<f64>()
        .sqrt();
    (m / reference - 1.0, se * m / (reference * reference))
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
        check_sun(wind, &rows);
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
        sun_rays_per_pixel: 8,
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

/// The Sun's term (see the module documentation): the reference's own error, and the model's
/// pooled shortfall, which is significant and of the measured size.
fn check_sun(wind: f64, rows: &[RowMeans]) {
    println!("wind {wind} m/s: row, distance, Sun reference ± SE, model, constant");
    for r in rows {
        let reference = sum(r.reference.sun);
        let se = sum(r.reference_sun_error) / reference;
        println!(
            "{:3} {:7.0} m  sun {reference:.4} ± {:.1} % model {:+.1} % constant {:+.1} %",
            r.row,
            r.distance,
            se * 100.0,
            rel(sum(r.model.sun), reference) * 100.0,
            rel(sum(r.constant.sun), reference) * 100.0
        );
        // Measured: at most 84 % below 300 m, 23 % beyond. A larger error would mean the
        // reference lost its glints (a broken Sun test), not a worse model.
        let bound = if r.distance < 300.0 { 0.9 } else { 0.25 };
        assert!(se < bound, "row {}: reference Sun error {se}", r.row);
        if r.distance > 300.0 {
            // Measured: 79–94 % low on every far row (the model: 13–53 % low, or up to 3 % high
            // on the agitated sea's 300 m row).
            let constant = rel(sum(r.constant.sun), reference);
            assert!(
                constant < -0.72,
                "row {}: constant BRDF Sun {constant}",
                r.row
            );
        }
    }
    // Measured pooled errors (calm, agitated): near −21.9 ± 2.6 %, −16.9 ± 2.5 %; far
    // −34.8 ± 1.9 %, −28.9 ± 2.1 %. The bounds hold the measured shortfall (the model's glitter
    // too dim, at least three standard errors from the reference) and about 8 points either
    // side of it, so that a change of the model or of the reference shows.
    let bounds = [
        (5.0, (-0.30, -0.14), (-0.43, -0.27)),
        (15.0, (-0.25, -0.09), (-0.37, -0.21)),
    ];
    let (_, near_bounds, far_bounds) = bounds.iter().find(|b| b.0 == wind).copied().unwrap();
    for (name, near, (lo, hi)) in [("near", true, near_bounds), ("far", false, far_bounds)] {
        let part: Vec<&RowMeans> = rows
            .iter()
            .filter(|r| (r.distance < 300.0) == near)
            .collect();
        let (model, se) = pooled_sun(&part, |r| r.model.sun);
        let (constant, _) = pooled_sun(&part, |r| r.constant.sun);
        println!(
            "wind {wind}, {name} rows: Sun pooled model {:+.1} ± {:.1} %, constant {:+.1} %",
            model * 100.0,
            se * 100.0,
            constant * 100.0
        );
        assert!(
            model > lo && model < hi,
            "wind {wind} {name}: Sun pooled {model} ± {se}"
        );
        assert!(
            model < -3.0 * se,
            "wind {wind} {name}: Sun pooled {model} ± {se}"
        );
    }
}

/// The paper's Sun covers 1/8000 of the hemisphere (§7.2): Ω = 2π(1 − cos ρ) = 2π/8000.
#[test]
fn paper_sun_is_one_8000th_of_the_hemisphere() {
    let rho = ocean_brdf::validation::PAPER_SUN_ANGULAR_RADIUS;
    let omega = std::f64::consts::TAU * (1.0 - rho.cos());
    assert!(
        (omega * 8000.0 / std::f64::consts::TAU - 1.0).abs() < 1e-9,
        "{omega}"
    );
}
