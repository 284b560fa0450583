//! The accuracy table ([`ocean_relief::accuracy`]): printed with `--nocapture`, and the claims it
//! supports asserted. 128² maps, relief depths 12.8 and 25.6 texels, 0–80°, 4096 rays per row.
//!
//! What holds, and is asserted:
//! - no relaxed, cone-step or quadrant-cone ray goes through a feature (the cones are valid), on
//!   any map;
//! - relaxed cone stepping with a shared budget of 21 fetches beats cone step mapping with 21
//!   steps at 70° and 80°, in the share of rays more than a texel off and in the mean error, on
//!   every map but the thin walls, where the two tie (0.8–1.0% of rays each, mean errors within
//!   1%, either ahead): both stall on the same rays, which skim along a wall's one-texel ramp,
//!   where relaxed and conservative cones are equally narrow;
//! - it beats linear search 15 + 6 at 70° and 80° on the thin-walls map, which linear search
//!   steps over;
//! - the angle-adaptive budget (`15/cos θ` cone steps + 6) keeps 80° below 1% of rays more than a
//!   texel off on every map but the pins;
//! - quad-directional relaxed cones (`quad 21 shared`: one cone per quadrant of the ray's
//!   direction, §18.1, [`ocean_relief::quad`]; the same 21-fetch shared budget) beat isotropic
//!   relaxed cones, cone step mapping and QDCSM (`quad cone step 21`) at 70° and 80° on every map,
//!   in both measures (e.g. boxes at 25.6 texels, 80°: 6.1% of rays more than a texel off, mean
//!   0.92 texels, against 27.6% / 5.8 isotropic and 44% / 7.8 QDCSM);
//! - they beat linear search 15 + 6 in both measures at 70° and 80° on the boxes (0.7 / 2.7% at
//!   12.8 texels, 2.5 / 6.1% at 25.6, against 5.0 / 12.7% and 12.1 / 27.0%) and the thin walls
//!   (0.3–0.4% against 72–98%), and on the bumps at 25.6 texels and 80° (20.7% / 4.2 against
//!   21.5% / 11.1, a narrow margin in the share);
//! - their mean error is below linear search's at 80° on the fBm (0.90 / 3.8 texels at 12.8 /
//!   25.6 against 1.08 / 6.2) and the bumps (0.60 / 4.2 against 1.17 / 11.1), and at 25.6 texels
//!   also at 70° on those two (0.89 against 0.99, 0.69 against 0.93) and at 80° on the smooth
//!   noise (0.72 against 1.23): linear search's misses step through features and land far away
//!   (hundreds of overshoots a row), the quadrant tracer's stop short of the hit;
//! - with the angle-adaptive budget they keep 80° below 1% on every map but the pins (at most
//!   0.12%), and on the pins they halve the isotropic budget's failures at 80° (6.5% against
//!   15.4% at 12.8 texels, 25.0% against 45.7% at 25.6), still far above 1%.
//!
//! What does not hold, and is reported instead of asserted: at equal fetches, valid relaxed cones
//! lose to linear search 15 + 6 at 70–80° on the noise, boxes, bumps and pins maps. A grazing ray
//! advances about `cone·height` per step, and cones that are valid for every ray through their
//! axis (see `bound`) are limited by every peak around them; on smooth terrain linear search
//! rarely steps over anything, so its fixed stride wins. Quadrant cones, limited only by the peaks
//! ahead of the ray, remove the loss on the boxes but not the rest: in the share of rays more than
//! a texel off they still lose on the smooth noise (0.5 / 1.6% at 12.8 texels, 70 / 80°, against
//! 0.0 / 0.3%; 1.7 / 3.7% at 25.6 against 0.4 / 3.1%), the fBm (3.5 / 11.0% against 1.4 / 8.4%;
//! 11.4 / 26.3% against 7.9 / 22.5%) and the bumps but at 25.6 texels and 80° (1.2 / 6.0%
//! against 0.4 / 3.8%; 6.3% against 2.8% at 70°); in the mean error on the smooth noise but at
//! 25.6 texels and 80°, and at 12.8 texels and 70° on the fBm and bumps. On
//! the pins map every method fails (quadrant cones 64–96% of rays, linear search 25–82%): each
//! pin limits the cones of every texel in front of it, in every quadrant that faces it. The
//! book's four-ratio layout (`quad 21 plain`: no clearance or near cap) mostly lies between the
//! isotropic cones and the full quadrant layers: fBm at 25.6 texels and 80°, 27.8% against 41.7%
//! and 26.3%; on box floors the clearance matters most (boxes, same row: 16.8% against 27.6% and
//! 6.1%); on the pins at 12.8 texels and 70° it is worse than the isotropic cones with their
//! clearance (83.7% against 80.4%).

use ocean_relief::accuracy::{Config, Table, table};

fn standard() -> Table {
    let t = table(&Config::standard(128, 4096).unwrap()).unwrap();
    println!("{t}");
    t
}

#[test]
fn accuracy_table() {
    let t = standard();
    let maps = [
        "smooth noise",
        "fBm noise",
        "boxes",
        "bumps",
        "thin walls",
        "pins",
    ];
    // Valid cones: nothing goes through a feature.
    for r in &t.rows {
        if r.method.starts_with("relaxed")
            || r.method.starts_with("cone step")
            || r.method.starts_with("quad")
        {
            assert_eq!(r.overshoots, 0, "{r:?}");
        }
    }
    for map in maps {
        for depth in [12.8, 25.6] {
            for angle in [70.0, 80.0] {
                let row = |m: &str| t.find(map, depth, angle, m).unwrap();
                let (shared, csm, linear) = (
                    row("relaxed 21 shared"),
                    row("cone step 21"),
                    row("linear 15+6"),
                );
                assert_eq!(
                    (shared.fetches, csm.fetches, linear.fetches),
                    (21.0, 21.0, 21.0)
                );
                if map == "thin walls" {
                    // Full-height walls leave relaxed cones little wider than conservative ones,
                    // and cone stepping spends all 21 fetches on steps where the shared search
                    // spends some on bisection: a near tie. Measured at 12.8 and 80°: 0.78 % of
                    // rays over a texel for both, mean error 0.0419 against 0.0402 texels
                    // (both generators bounding half cells; with whole cells the means were
                    // 0.0420 and 0.0425).
                    assert!(
                        shared.over_one <= csm.over_one + 1e-3 && shared.mean <= csm.mean * 1.1,
                        "{map} {depth} {angle}"
                    );
                } else {
                    assert!(
                        shared.over_one < csm.over_one && shared.mean < csm.mean,
                        "{map} {depth} {angle}: {shared:?} vs {csm:?}"
                    );
                }
                if map == "thin walls" {
                    assert!(
                        shared.over_one < linear.over_one && shared.mean < linear.mean,
                        "{map} {depth} {angle}"
                    );
                }
                if angle == 80.0 && map != "pins" {
                    let adaptive = row("relaxed adaptive");
                    assert!(
                        adaptive.over_one < 0.01,
                        "{map} {depth}: {:.2}%",
                        100.0 * adaptive.over_one
                    );
                }
                // Quadrant cones, the same 21-fetch shared budget.
                let (quad, qdcsm) = (row("quad 21 shared"), row("quad cone step 21"));
                assert_eq!((quad.fetches, qdcsm.fetches), (21.0, 21.0));
                for other in [shared, csm, qdcsm] {
                    assert!(
                        quad.over_one < other.over_one && quad.mean < other.mean,
                        "{map} {depth} {angle}: {quad:?} vs {other:?}"
                    );
                }
                if map == "boxes"
                    || map == "thin walls"
                    || (map == "bumps" && depth == 25.6 && angle == 80.0)
                {
                    assert!(
                        quad.over_one < linear.over_one && quad.mean < linear.mean,
                        "{map} {depth} {angle}: {quad:?} vs {linear:?}"
                    );
                }
                if ((map == "fBm noise" || map == "bumps") && (angle == 80.0 || depth == 25.6))
                    || (map == "smooth noise" && depth == 25.6 && angle == 80.0)
                {
                    assert!(
                        quad.mean < linear.mean,
                        "{map} {depth}: {quad:?} vs {linear:?}"
                    );
                }
                if angle == 80.0 {
                    let (qa, ra) = (row("quad adaptive"), row("relaxed adaptive"));
                    assert_eq!(qa.fetches, ra.fetches);
                    if map == "pins" {
                        assert!(qa.over_one < ra.over_one && qa.mean < ra.mean, "{depth}");
                    } else {
                        assert!(
                            qa.over_one < 0.01,
                            "{map} {depth}: {:.2}%",
                            100.0 * qa.over_one
                        );
                    }
                }
            }
        }
    }
}
