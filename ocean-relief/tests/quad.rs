//! Quad-directional cone maps ([`ocean_relief::quad`], §18.1): the fast generator against its
//! brute-force oracle, determinism, how they compare with isotropic cones, their validity under
//! the bilinear fetch for the directions they serve (and not beyond), and the tracer's choice of
//! layer.

mod common;

use common::{from_fn, maps, rays};
use ocean_relief::check::{Channels, CheckParams, check, check_quadrant};
use ocean_relief::storage::Encoding;
use ocean_relief::trace::BinarySearch;
use ocean_relief::{
    ConeKind, ConeMap, ConeParams, Edge, HeightMap, Method, QuadConeMap, QuadReliefTexture,
    Quadrant, Ray, ReliefError, truth,
};

/// Every layer of the branch-and-bound equals the brute force's, bit for bit, every channel:
/// the test set's maps at 16² and 32², both edge modes, relaxed and conservative with the book's
/// cap, and at 16² relaxed with a cap of 3.5 too (tile copies are visited); and the fBm map at
/// 64². (Four layers of the `Θ(N⁴)` oracle: the 32² cap-3.5 case is left to the isotropic test,
/// which shares every line of the search but the clip.)
#[test]
fn fast_generator_matches_brute_force() {
    let mut compared = 0;
    for n in [16, 32] {
        for edge in [Edge::Wrap, Edge::Clamp] {
            for (name, map) in maps(n, edge) {
                let mut cases = vec![ConeParams::relaxed(1.0), ConeParams::conservative(1.0)];
                if n == 16 {
                    cases.push(ConeParams::relaxed(3.5));
                }
                for params in cases {
                    let fast = QuadConeMap::generate(&map, params).unwrap();
                    let brute = QuadConeMap::brute_force(&map, params).unwrap();
                    assert!(fast == brute, "{name} {n}² {edge:?} {params:?}");
                    compared += 1;
                }
            }
        }
    }
    let (name, map) = maps(64, Edge::Wrap).swap_remove(1);
    assert_eq!(name, "fBm");
    let params = ConeParams::relaxed(1.0);
    assert!(
        QuadConeMap::generate(&map, params).unwrap()
            == QuadConeMap::brute_force(&map, params).unwrap()
    );
    compared += 1;
    assert_eq!(compared, 2 * 6 * 3 + 2 * 6 * 2 + 1);
}

/// Same input, same bits, on one thread or several.
#[test]
fn same_bits_for_any_thread_count() {
    for (name, map) in maps(32, Edge::Wrap) {
        let run = |threads: usize| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| QuadConeMap::generate(&map, ConeParams::relaxed(4.0)).unwrap())
        };
        let one = run(1);
        for threads in [2, 3] {
            assert!(run(threads) == one, "{name} with {threads} threads");
        }
    }
}

/// A quadrant cone is never narrower than the isotropic cone, channel by channel, relaxed and
/// conservative: it has fewer candidates, each with a vector box inside the isotropic one (a
/// longer shortest vector, less growth, fewer directions to rise along). And it is wider
/// somewhere on every map: that is the point of the quadrant maps.
#[test]
fn quadrant_cones_contain_isotropic_ones() {
    for edge in [Edge::Wrap, Edge::Clamp] {
        for (name, map) in maps(32, edge) {
            for params in [ConeParams::relaxed(4.0), ConeParams::conservative(4.0)] {
                let iso = ConeMap::generate(&map, params).unwrap();
                let quad = QuadConeMap::generate(&map, params).unwrap();
                let mut wider = 0;
                for layer in quad.layers() {
                    for (a, b) in [
                        (layer.ratios(), iso.ratios()),
                        (layer.clearance(), iso.clearance()),
                        (layer.near_cap(), iso.near_cap()),
                    ] {
                        assert!(
                            a.iter().zip(b).all(|(x, y)| x >= y),
                            "{name} {edge:?} {params:?}"
                        );
                        wider += a.iter().zip(b).filter(|(x, y)| x > y).count();
                    }
                }
                assert!(wider > 0, "{name} {edge:?} {params:?}");
            }
        }
    }
}

/// A one-texel wall (height 1 on column 8) on a floor at height 0, clamped, 16²: west of the
/// wall (texels with `i ≤ 5`, whose cells end at least a cell before the wall's rising cell
/// 7..8), no ray heading west or along `±y` can reach it and the floor is flat, so the layers of
/// `uₓ ≤ 0` are the cap (1 texture width per unit depth) there; the layers of `uₓ ≥ 0` and the
/// isotropic cone are limited by the wall, below the cap. East of the wall (`i ≥ 11`) the roles
/// swap.
#[test]
fn wall_limits_only_the_quadrants_facing_it() {
    let n = 16;
    let map = from_fn(n, Edge::Clamp, |i, _| if i == 8 { 1.0 } else { 0.0 });
    for kind in [ConeParams::relaxed(1.0), ConeParams::conservative(1.0)] {
        let iso = ConeMap::generate(&map, kind).unwrap();
        let quad = QuadConeMap::generate(&map, kind).unwrap();
        for k in 0..n * n {
            let i = k % n;
            let (toward, away) = match i {
                0..=5 => (false, true),
                11.. => (true, false),
                _ => continue,
            };
            assert!(iso.ratios()[k] < 1.0, "{kind:?} texel {k}");
            for q in Quadrant::ALL {
                let r = quad.layer(q).ratios()[k];
                if q.x_neg == toward {
                    // Facing the wall: as narrow as the isotropic cone may be, never narrower.
                    assert!(r < 1.0 && r >= iso.ratios()[k], "{kind:?} {q:?} texel {k}");
                } else {
                    assert_eq!(r, 1.0, "{kind:?} {q:?} texel {k} (away: {away})");
                }
            }
        }
    }
}

fn relaxed_params(apexes: usize, directions: usize) -> CheckParams {
    CheckParams {
        apexes,
        directions,
        usage: false,
    }
}

/// Checks every layer of `cones` for its quadrant and returns the lines examined.
fn assert_layers_valid(
    name: &str,
    map: &HeightMap,
    cones: &QuadConeMap,
    kind: ConeKind,
    params: CheckParams,
) -> u64 {
    let mut lines = 0;
    for q in Quadrant::ALL {
        let r = check_quadrant(map, Channels::of(cones.layer(q)), kind, params, q).unwrap();
        assert_eq!(r.violations, 0, "{name} {q:?} {kind:?}: {:?}", r.worst);
        lines += r.lines;
    }
    lines
}

/// The exhaustive check ([`check_quadrant`]) finds no ray of a quadrant, through any cone's axis
/// at any depth and slope, that crosses the surface twice inside the cone it uses: relaxed 64²
/// maps in both edge modes (cap 4, 2×2 apexes per cell, 32 directions, so 9 per quadrant with
/// both axes), conservative 64² wrap (cap 1, 16 directions: 5 per quadrant), and relaxed 128²
/// wrap (the largest size of the validity target; cap 1, 12 directions: 4 per quadrant).
#[test]
fn quadrant_cones_are_valid() {
    let cases = [
        (
            64,
            Edge::Wrap,
            ConeParams::relaxed(4.0),
            relaxed_params(2, 32),
        ),
        (
            64,
            Edge::Clamp,
            ConeParams::relaxed(4.0),
            relaxed_params(2, 32),
        ),
        (
            64,
            Edge::Wrap,
            ConeParams::conservative(1.0),
            relaxed_params(2, 16),
        ),
        (
            128,
            Edge::Wrap,
            ConeParams::relaxed(1.0),
            relaxed_params(2, 12),
        ),
    ];
    for (n, edge, params, check_params) in cases {
        for (name, map) in maps(n, edge) {
            let cones = QuadConeMap::generate(&map, params).unwrap();
            let lines = assert_layers_valid(name, &map, &cones, params.kind, check_params);
            // Cells × apexes × (directions/4 + 1 per quadrant) × (plain + 5 heights) × 4 layers.
            let cells = match edge {
                Edge::Wrap => n * n,
                Edge::Clamp => (n + 1) * (n + 1),
            };
            let per = check_params.directions / 4 + 1;
            assert_eq!(lines, (cells * 4 * per * 6 * 4) as u64, "{name}");
            println!(
                "{name:10} {n}² {edge:?} {:?}: {lines} lines, no violation",
                params.kind
            );
        }
    }
}

/// Quantised layers (8-bit, 8-bit square root, f16) round down, so they stay valid.
#[test]
fn quantised_quadrant_cones_stay_valid() {
    for (name, map) in maps(32, Edge::Wrap) {
        let cones = QuadConeMap::generate(&map, ConeParams::relaxed(4.0)).unwrap();
        for enc in [Encoding::Unorm8, Encoding::Unorm8Sqrt, Encoding::F16] {
            let q = cones.quantized(enc).unwrap();
            assert_layers_valid(name, &map, &q, ConeKind::Relaxed, relaxed_params(2, 32));
        }
    }
}

/// The check is not vacuous, and the quadrant matters: every map has a layer that fails the
/// check over all directions (its cones are wider than an isotropic cone may be), and widening
/// each layer's plain cone by 2× fails even its own quadrant's check.
#[test]
fn quadrant_cones_fail_outside_their_quadrant() {
    let params = relaxed_params(2, 32);
    for (name, map) in maps(32, Edge::Wrap) {
        let cones = QuadConeMap::generate(&map, ConeParams::relaxed(4.0)).unwrap();
        let outside: u64 = Quadrant::ALL
            .iter()
            .map(|&q| {
                check(
                    &map,
                    Channels::of(cones.layer(q)),
                    ConeKind::Relaxed,
                    params,
                )
                .unwrap()
                .violations
            })
            .sum();
        assert!(
            outside > 0,
            "{name}: quadrant cones valid for every direction"
        );
        for q in Quadrant::ALL {
            let l = cones.layer(q);
            let wide =
                ConeMap::from_ratios(32, Edge::Wrap, l.ratios().iter().map(|r| r * 2.0).collect())
                    .unwrap();
            let r =
                check_quadrant(&map, Channels::of(&wide), ConeKind::Relaxed, params, q).unwrap();
            assert!(r.violations > 0, "{name} {q:?}: plain cone ×2 passed");
        }
    }
}

/// The tracer picks the layer of the ray's scaled direction, negative components the negative
/// side and zero the positive one (`select(0, 1, dir.x < 0) + select(0, 2, dir.y < 0)`), and
/// traces exactly as the isotropic tracer does on that layer.
#[test]
fn tracer_picks_the_rays_quadrant() {
    let map = maps(32, Edge::Wrap).swap_remove(1).1;
    let cones = QuadConeMap::generate(&map, ConeParams::relaxed(4.0)).unwrap();
    let tex = QuadReliefTexture::new(&map, &cones).unwrap();
    let ray = |x: f32, y: f32| Ray {
        start: glam::Vec2::new(0.3, 0.6),
        dir: glam::Vec3::new(x, y, 2.0),
    };
    for (x, y, index) in [
        (0.5, 0.25, 0),
        (-0.5, 0.25, 1),
        (0.5, -0.25, 2),
        (-0.5, -0.25, 3),
        (0.0, 0.25, 0),
        (-0.0, -0.25, 2),
        (-0.5, 0.0, 1),
        (0.0, 0.0, 0),
    ] {
        let q = QuadReliefTexture::quadrant(&ray(x, y)).unwrap();
        assert_eq!(q.index(), index, "({x}, {y})");
        assert!(q.contains(f64::from(x), f64::from(y)));
    }
    let shared = Method::Relaxed {
        cone: 15,
        binary: 6,
        search: BinarySearch::Shared,
    };
    for r in rays(200, 0.0, 85.0, 0.2, 5) {
        let q = QuadReliefTexture::quadrant(&r).unwrap();
        assert_eq!(
            tex.trace(&shared, &r).unwrap(),
            shared.trace(tex.layer(q), &r).unwrap()
        );
    }
    assert_eq!(
        QuadReliefTexture::quadrant(&ray(1.0, 0.0).with_z(-1.0)),
        Err(ReliefError::RayDirection)
    );
}

trait WithZ {
    fn with_z(self, z: f32) -> Self;
}

impl WithZ for Ray {
    fn with_z(mut self, z: f32) -> Self {
        self.dir.z = z;
        self
    }
}

/// With valid quadrant cones no ray goes through a thin feature — one-texel walls and pins, 2000
/// rays at 50–85° — for relaxed quadrant cones (shared budget, last step) and QDCSM.
#[test]
fn quadrant_cones_never_go_through_thin_features() {
    let n = 64;
    let rays = rays(2000, 50.0, 85.0, 0.2, 3);
    for (name, map) in maps(n, Edge::Wrap)
        .iter()
        .filter(|(n, _)| *n == "thin walls" || *n == "pins")
    {
        let relaxed = QuadReliefTexture::new(
            map,
            &QuadConeMap::generate(map, ConeParams::relaxed(1.0)).unwrap(),
        )
        .unwrap();
        let conservative = QuadReliefTexture::new(
            map,
            &QuadConeMap::generate(map, ConeParams::conservative(1.0))
                .unwrap()
                .plain()
                .unwrap(),
        )
        .unwrap();
        let through = |tex: &QuadReliefTexture, m: &Method| {
            rays.iter()
                .filter(|ray| {
                    let t = truth::first_hit(map, ray).unwrap();
                    let exit = truth::exit_after(map, ray, t.z).unwrap();
                    let h = tex.trace(m, ray).unwrap().pos;
                    let d =
                        f64::from(ray.dir.x / ray.dir.z).hypot(f64::from(ray.dir.y / ray.dir.z));
                    let err = (f64::from(h.z) - t.z) * n as f64 * d.max(0.2);
                    err > 1.0 && f64::from(h.z) > exit
                })
                .count()
        };
        for search in [BinarySearch::Shared, BinarySearch::LastStep] {
            let m = Method::Relaxed {
                cone: 15,
                binary: 6,
                search,
            };
            assert_eq!(through(&relaxed, &m), 0, "{name} {search:?}");
        }
        assert_eq!(
            through(&conservative, &Method::ConeStep { steps: 21 }),
            0,
            "{name}"
        );
    }
}

/// Layers of different sizes are refused.
#[test]
fn mismatched_layers_are_refused() {
    let a = ConeMap::from_ratios(4, Edge::Wrap, vec![1.0; 16]).unwrap();
    let b = ConeMap::from_ratios(8, Edge::Wrap, vec![1.0; 64]).unwrap();
    assert!(matches!(
        QuadConeMap::from_layers([a.clone(), a.clone(), b, a.clone()]),
        Err(ReliefError::Mismatch(_))
    ));
    let ok = QuadConeMap::from_layers([a.clone(), a.clone(), a.clone(), a]).unwrap();
    assert_eq!(ok.plain_rgba(), vec![[1.0; 4]; 16]);
    let map = from_fn(8, Edge::Wrap, |_, _| 0.5);
    assert!(matches!(
        QuadReliefTexture::new(&map, &ok),
        Err(ReliefError::Mismatch(_))
    ));
}

/// `generate_with` under the isotropic progress contract over the whole job: the first call is
/// `(0, 4R)` and the last `(4R, 4R)` with `R` the rows of cells (`N` wrap, `N + 1` clamp),
/// reports never decrease, there are at most `BANDS + 1` calls (each layer in at most
/// `BANDS / 4` bands), and the cones are `generate`'s bit for bit. Returning `false` at the
/// first call, or at a report inside the second layer, cancels.
#[test]
fn progress_covers_the_four_layers_and_cancels() {
    use ocean_relief::progress::BANDS;
    for (n, edge, rows) in [
        (40, Edge::Wrap, 40),
        (40, Edge::Clamp, 41),
        (130, Edge::Wrap, 130),
    ] {
        let map = maps(n, edge).swap_remove(1).1;
        let params = ConeParams::relaxed(1.0);
        let mut calls: Vec<(usize, usize)> = Vec::new();
        let mut record = |done: usize, total: usize| {
            calls.push((done, total));
            true
        };
        let cones = QuadConeMap::generate_with(&map, params, &mut record).unwrap();
        assert!(
            cones == QuadConeMap::generate(&map, params).unwrap(),
            "{n} {edge:?}"
        );
        assert_eq!(calls.first(), Some(&(0, 4 * rows)), "{n} {edge:?}");
        assert_eq!(calls.last(), Some(&(4 * rows, 4 * rows)), "{n} {edge:?}");
        assert!(calls.windows(2).all(|w| w[0].0 <= w[1].0), "{calls:?}");
        assert!(calls.iter().all(|&(_, t)| t == 4 * rows));
        assert!(calls.len() <= BANDS + 1, "{} calls", calls.len());
        // 130 rows in bands of ceil(130 / 16) = 9: 15 bands a layer, 60 + 1 calls.
        if n == 130 {
            assert_eq!(calls.len(), 61);
        }
        let mut first = |_: usize, _: usize| false;
        assert_eq!(
            QuadConeMap::generate_with(&map, params, &mut first),
            Err(ReliefError::Cancelled)
        );
        let mut in_second = |done: usize, _: usize| done <= rows;
        assert_eq!(
            QuadConeMap::generate_with(&map, params, &mut in_second),
            Err(ReliefError::Cancelled)
        );
    }
}

/// Self-shadowing through quadrant cones traces the light ray through the layer of the light
/// ray's own direction, `-light.xy` (the ray runs from the light towards the point): so it
/// equals the isotropic `in_shadow` on that one layer, for every point and light; and a light
/// at or below the polygon shadows every point, as `in_shadow` says.
#[test]
fn shadow_rays_read_their_own_quadrant() {
    use glam::Vec3;
    use ocean_relief::shadow::in_shadow;
    let map = maps(32, Edge::Wrap).swap_remove(2).1;
    let cones = QuadConeMap::generate(&map, ConeParams::relaxed(1.0)).unwrap();
    let tex = QuadReliefTexture::new(&map, &cones).unwrap();
    let method = Method::Relaxed {
        cone: 15,
        binary: 6,
        search: BinarySearch::LastStep,
    };
    let (mut shadowed, mut total) = (0, 0);
    for (k, r) in rays(400, 5.0, 80.0, 0.2, 9).into_iter().enumerate() {
        let hit = tex.trace(&method, &r).unwrap();
        // Lights from every azimuth: the view rays' directions turned by 90° k.
        let (x, y) = (r.dir.x, r.dir.y);
        let (lx, ly) = [(x, y), (-y, x), (-x, -y), (y, -x)][k % 4];
        let light = Vec3::new(lx, ly, 0.6);
        let q = Quadrant::of(-lx, -ly);
        let quad = tex.in_shadow(&method, hit.pos, light, 0.2, 0.01).unwrap();
        let layer = in_shadow(tex.layer(q), &method, hit.pos, light, 0.2, 0.01).unwrap();
        assert_eq!(quad, layer, "{r:?} {light}");
        shadowed += usize::from(quad);
        total += 1;
    }
    // The boxes cast shadows on some points and leave others lit.
    assert!(shadowed > 0 && shadowed < total, "{shadowed} of {total}");
    let below = Vec3::new(0.3, 0.1, -0.2);
    assert!(
        tex.in_shadow(&method, Vec3::new(0.5, 0.5, 0.9), below, 0.2, 0.01)
            .unwrap()
    );
    assert_eq!(
        tex.in_shadow(&method, Vec3::ZERO, Vec3::Z, 0.2, 2.0),
        Err(ReliefError::OutOfRange {
            name: "bias",
            value: 2.0,
            min: 0.0,
            max: 1.0
        })
    );
}
