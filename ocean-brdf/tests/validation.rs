//! The paper's validation (§7.2, Fig. 10): per-row mean radiance of the filtered model against
//! detailed geometry with a perfect mirror (`ocean_brdf::validation`), for a calm and an
//! agitated sea, with a constant-BRDF model alongside.
//!
//! Measured here (the default sampling: 32 reference planes × 32 rays per pixel row, 256 model
//! planes; 256² image 4 m above the sea; rows from 46 m to 5.9 km), over both seas:
//! - sky: mean error 8.4 %, worst row 26.5 % (a near row); beyond 300 m
//!   the model is 0–12 % above the reference. The paper's own form of Eq. 22, before this
//!   crate's visible-slope footprint, was 20–35 % *below* it on every row;
//! - refracted light: mean error 4.1 %, worst row 18 %; beyond 300 m 8 % below to 1 % above;
//! - beyond 300 m the constant-BRDF model is off by 25–45 %, at least twice the model's error.
//!
//! The target is 5 % per row and component and is **not met yet**. Beyond 300 m the
//! calm sea's rows are within 7 % (sky) and 5 % (refracted), the agitated sea's within 12 % and
//! 8 %, 4.5 % on average. The effective Fresnel is not the cause there any more: the table of
//! Eq. 24 (`fresnel_table`) is within 0.008 of the anisotropic integral at these grazing views
//! (measured for σ from 0.1 to 0.25 and anisotropy up to 2:1); what remains is the model's
//! other approximations (Smith's masking for trochoids, the product of averages of Eq. 21) and
//! the reference's sampling. The near rows (46–200 m) are biased too, sky about +9 % and
//! refracted light about −2 to −4 % on average, and this is the paper's own approximation
//! rather than noise: 4× more reference planes left the worst rows unchanged, and shrinking
//! the pixel footprint by 10 (more waves in the normals, fewer in the BRDF) *raised* the bias
//! to +16 % / −12 %. Waves resolved in the normals but not in the filtered geometry lose their
//! masking (§3.2: "the apparent normals become wrong"), so facets the detailed surface hides
//! are seen, at grazing Fresnel. The reference resolves masking only for waves longer than
//! 10 cm, as the paper's did. The Sun's term is not compared: a perfect mirror reflects the
//! Sun's disc (7e-5 sr) into a handful of the reference's rays per row, too few for a row mean.

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
    (a - b).abs() / b
}

#[test]
fn filtered_model_follows_the_reference_and_the_constant_brdf_diverges() {
    let mut worst_sky: f64 = 0.0;
    let mut worst_sea: f64 = 0.0;
    for wind in [5.0, 15.0] {
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
            worst_sky = worst_sky.max(rel(ms, rs));
            worst_sea = worst_sea.max(rel(mw, rw));
            if r.distance > 300.0 {
                let (model, constant) =
                    (rel(ms, rs).max(rel(mw, rw)), rel(cs, rs).max(rel(cw, rw)));
                assert!(
                    constant > 0.2,
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
    }
    println!(
        "worst row: sky {:.1} %, sea {:.1} %",
        worst_sky * 100.0,
        worst_sea * 100.0
    );
    // The measured envelope (see the module documentation), so a regression shows.
    assert!(worst_sky < 0.28, "{worst_sky}");
    assert!(worst_sea < 0.19, "{worst_sea}");
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
