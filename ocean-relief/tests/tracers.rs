//! Tracers and the ground truth on analytic cases (a flat plane, a ramp, a box), the exact walk
//! against a dense march, the guarantee that valid cones never let a ray through a feature,
//! self-shadowing, the occlusion depth and the normal map.

mod common;

use common::{from_fn, maps, rays};
use glam::{DVec3, Vec2, Vec3};
use ocean_core::{DepthConvention, Far, Projection};
use ocean_relief::accuracy::adaptive_cone_steps;
use ocean_relief::occlusion::{occlusion_depth, view_distance};
use ocean_relief::relief::normals;
use ocean_relief::shadow::in_shadow;
use ocean_relief::trace::BinarySearch;
use ocean_relief::{ConeMap, ConeParams, Edge, HeightMap, Method, Ray, ReliefTexture, book, truth};

fn texture(map: &HeightMap, params: ConeParams) -> ReliefTexture {
    ReliefTexture::new(map, &ConeMap::generate(map, params).unwrap()).unwrap()
}

const LINEAR: Method = Method::Linear {
    linear: 15,
    binary: 6,
};
const RELAXED: Method = Method::Relaxed {
    cone: 15,
    binary: 6,
    search: BinarySearch::LastStep,
};
const SHARED: Method = Method::Relaxed {
    cone: 15,
    binary: 6,
    search: BinarySearch::Shared,
};
const BOOK: Method = Method::Relaxed {
    cone: 15,
    binary: 6,
    search: BinarySearch::Book,
};
const CONE_STEP: Method = Method::ConeStep { steps: 21 };

/// Depth error tolerated for each method on a flat plane: linear search ends with a bracket of
/// (1/15)/2⁶ in depth and returns its middle; the book's bisection halves the range from the
/// entry point 6 times; cone steps with cones capped at 64 texture widths reach a flat floor to
/// within f32 rounding in a few steps (each leaves ρ/(ρ + 64) of the height).
#[test]
fn flat_plane() {
    for edge in [Edge::Wrap, Edge::Clamp] {
        let map = from_fn(16, edge, |_, _| 0.3);
        let depth = f64::from(1.0f32 - 0.3f32);
        let relaxed = texture(&map, ConeParams::relaxed(64.0));
        let conservative = texture(&map, ConeParams::conservative(64.0));
        for ray in rays(500, 0.0, 80.0, 0.1, 1) {
            let t = truth::first_hit(&map, &ray).unwrap();
            assert!((t.z - depth).abs() < 1e-12, "{}", t.z);
            for (m, tex, tol) in [
                (LINEAR, &relaxed, 1.0 / 15.0 / 128.0 + 1e-6),
                (BOOK, &relaxed, 0.5f64.powi(7) + 1e-6),
                (RELAXED, &relaxed, 1e-5),
                (SHARED, &relaxed, 1e-5),
                (CONE_STEP, &conservative, 1e-5),
            ] {
                let z = f64::from(m.trace(tex, &ray).unwrap().pos.z);
                assert!((z - depth).abs() <= tol, "{m:?} {edge:?}: {z}");
            }
        }
    }
}

/// A ramp along x (heights 0.1 + 0.025·i, clamped): inside the texture the surface is the plane
/// `S(X) = 0.9 − 0.025·X` (X in texel-centre coordinates), and a ray entering at `X₀` that moves
/// `k = dx·N` texels per unit depth meets it at `z = (0.9 − 0.025·X₀)/(1 + 0.025·k)`. A ramp has
/// no peak, so its relaxed cones are the cap and the first step lands deep in it: with 6
/// bisections of that step (at most 1 in depth) the answer is within 2⁻⁷ of the hit; the shared
/// budget bisects it 20 times (within 1e-5).
#[test]
fn ramp() {
    let n = 32;
    let map = from_fn(n, Edge::Clamp, |i, _| 0.1 + 0.025 * i as f32);
    let tex = texture(&map, ConeParams::relaxed(4.0));
    let mut checked = 0;
    for (x0, dx) in [
        (3.0f32, 0.5f32),
        (8.0, 0.2),
        (20.0, -0.3),
        (25.0, -0.1),
        (10.0, 0.0),
    ] {
        let ray = Ray {
            start: Vec2::new((x0 + 0.5) / n as f32, 0.5),
            dir: Vec3::new(dx, 0.01, 1.0),
        };
        let (x0, k) = (f64::from(x0), f64::from(dx) * n as f64);
        // The small y component does not change the depth along a ramp in x.
        let expected = (0.9 - 0.025 * x0) / (1.0 + 0.025 * k);
        let t = truth::first_hit(&map, &ray).unwrap();
        assert!(
            (t.z - expected).abs() < 1e-6,
            "{x0} {dx}: {} vs {expected}",
            t.z
        );
        for (m, tol) in [(SHARED, 1e-5), (RELAXED, 0.5f64.powi(7))] {
            let z = f64::from(m.trace(&tex, &ray).unwrap().pos.z);
            assert!(
                (z - expected).abs() <= tol,
                "{m:?} {x0} {dx}: {z} vs {expected}"
            );
        }
        checked += 1;
    }
    assert_eq!(checked, 5);
}

/// A box (depth 0.2 over texels 12..=19 in x, all y) on a floor at depth 0.9, clamped. A ray from
/// X₀ = 2 moving k = 20 texels per unit depth is above the floor until the box and meets its
/// bilinear wall, `S = 0.9 − 0.7·(X − 11)` for `X ∈ [11, 12]`, at
/// `X = (8.6 + X₀/k)/(1/k + 0.7) = 11.6`, depth `(X − X₀)/k = 0.48`.
#[test]
fn box_wall() {
    let n = 32;
    let map = from_fn(n, Edge::Clamp, |i, _| {
        if (12..20).contains(&i) { 0.8 } else { 0.1 }
    });
    let ray = Ray {
        start: Vec2::new(2.5 / n as f32, 0.5),
        dir: Vec3::new(20.0 / n as f32, 0.0, 1.0),
    };
    let t = truth::first_hit(&map, &ray).unwrap();
    assert!((t.z - 0.48).abs() < 1e-6, "{}", t.z);
    let relaxed = texture(&map, ConeParams::relaxed(1.0));
    let conservative = texture(&map, ConeParams::conservative(1.0));
    // Relaxed cone stepping lands in the wall and bisects the last step: within half the final
    // bracket, at most 2⁻⁷ with 6 bisections and 1e-5 with the shared budget's. Cone step
    // mapping approaches the wall from outside and stops short, above it.
    for (m, tol) in [(RELAXED, 0.5f64.powi(7)), (SHARED, 1e-5)] {
        let z = f64::from(m.trace(&relaxed, &ray).unwrap().pos.z);
        assert!((z - 0.48).abs() <= tol, "{m:?}: {z}");
    }
    let z = f64::from(CONE_STEP.trace(&conservative, &ray).unwrap().pos.z);
    assert!(z <= 0.48 + 1e-6, "cone step went past the wall: {z}");
}

/// The exact walk agrees with a dense march (4096 depth steps, then bisection): it is never
/// later (it is the first point inside; the march can only miss slivers), and it matches on at
/// least 99% of the rays to 1e-6 in depth.
#[test]
fn truth_matches_dense_march() {
    for edge in [Edge::Wrap, Edge::Clamp] {
        for (name, map) in maps(32, edge) {
            let rays = rays(400, 0.0, 85.0, 0.2, 2);
            let mut agree = 0;
            for ray in &rays {
                let exact = truth::first_hit(&map, ray).unwrap();
                let marched = truth::march(&map, ray, 4096).unwrap();
                assert!(exact.z <= marched.z + 1e-12, "{name} {edge:?}");
                if (exact.z - marched.z).abs() < 1e-6 {
                    agree += 1;
                }
            }
            assert!(
                agree * 100 >= rays.len() * 99,
                "{name} {edge:?}: {agree} of {}",
                rays.len()
            );
        }
    }
}

/// Rays that went through the feature they first hit: ended more than a texel from the true hit
/// and deeper than where the ray first leaves the solid after it.
fn overshoots(map: &HeightMap, tex: &ReliefTexture, m: &Method, rays: &[Ray]) -> usize {
    let n = map.size() as f64;
    rays.iter()
        .filter(|ray| {
            let t = truth::first_hit(map, ray).unwrap();
            let exit = truth::exit_after(map, ray, t.z).unwrap();
            let h = m.trace(tex, ray).unwrap().pos;
            let d = f64::from(ray.dir.x / ray.dir.z).hypot(f64::from(ray.dir.y / ray.dir.z));
            let err = (f64::from(h.z) - t.z) * n * d.max(0.2);
            err > 1.0 && f64::from(h.z) > exit
        })
        .count()
}

/// With valid cones no ray goes through a thin feature — one-texel walls and pins, 2000 rays at
/// 50–85° — for relaxed cone stepping (book bisection, last step, shared budget, adaptive
/// budget) and cone step mapping; linear search does, and so does the relaxed tracer with the
/// book's cones.
#[test]
fn valid_cones_never_go_through_thin_features() {
    let n = 64;
    let set = maps(n, Edge::Wrap);
    let rays = rays(2000, 50.0, 85.0, 0.2, 3);
    for (name, map) in set
        .iter()
        .filter(|(n, _)| *n == "thin walls" || *n == "pins")
    {
        let relaxed = texture(map, ConeParams::relaxed(1.0));
        let conservative = texture(map, ConeParams::conservative(1.0));
        let adaptive = Method::Relaxed {
            cone: adaptive_cone_steps(15, 85.0),
            binary: 6,
            search: BinarySearch::Shared,
        };
        for m in [BOOK, RELAXED, SHARED, adaptive] {
            assert_eq!(overshoots(map, &relaxed, &m, &rays), 0, "{name} {m:?}");
        }
        assert_eq!(
            overshoots(map, &conservative, &CONE_STEP, &rays),
            0,
            "{name}"
        );
        let linear = overshoots(map, &relaxed, &LINEAR, &rays);
        assert!(
            linear > 100,
            "{name}: linear search went through {linear} features"
        );
    }
    // The book's listing on a 24² map with thin walls and pins.
    for (name, map) in maps(24, Edge::Wrap)
        .iter()
        .filter(|(n, _)| *n == "thin walls" || *n == "pins")
    {
        let tex = ReliefTexture::new(map, &book::listing_18_2(map, 128).unwrap()).unwrap();
        let through = overshoots(map, &tex, &RELAXED, &rays);
        assert!(through > 0, "{name}: book cones");
        println!(
            "{name}: {through} of {} rays went through a feature with the book's cones",
            rays.len()
        );
    }
}

/// A wall (height 1 on texels 12..=15 in x, all y) on a floor at height 0, relief 0.1 texture
/// widths deep, light from −x at 45°: the light ray towards a floor point travels 3.2 texels in
/// x per unit depth, so floor points at X = 17 and 18 are in the wall's shadow and points at
/// X ≥ 20 are lit (it passes above the wall). The exact first hit on the same light ray agrees.
#[test]
fn shadow_of_a_wall() {
    let n = 32;
    let map = from_fn(
        n,
        Edge::Wrap,
        |i, _| if (12..16).contains(&i) { 1.0 } else { 0.0 },
    );
    let tex = texture(&map, ConeParams::relaxed(1.0));
    let light = Vec3::new(-1.0, 0.0, 1.0).normalize();
    for (x, shadowed) in [
        (17, true),
        (18, true),
        (20, false),
        (22, false),
        (28, false),
        (8, false),
    ] {
        let point = Vec3::new((x as f32 + 0.5) / n as f32, 0.3, 1.0);
        for m in [SHARED, RELAXED] {
            assert_eq!(
                in_shadow(&tex, &m, point, light, 0.1, 1e-3).unwrap(),
                shadowed,
                "{m:?} X = {x}"
            );
        }
        // The exact hit of the same light ray.
        let per_depth = Vec2::new(-light.x, -light.y) * (0.1 / light.z);
        let start = Vec2::new(point.x, point.y) - per_depth * point.z;
        let ray = Ray::from_view(start, -light, 0.1).unwrap();
        assert_eq!(
            truth::first_hit(&map, &ray).unwrap().z < 1.0 - 1e-3,
            shadowed,
            "X = {x}"
        );
    }
    // A light below the polygon's plane leaves everything in shadow.
    assert!(
        in_shadow(
            &tex,
            &SHARED,
            Vec3::new(0.5, 0.5, 1.0),
            Vec3::new(1.0, 0.0, -0.1),
            0.1,
            1e-3
        )
        .unwrap()
    );
}

/// §18.2's depth: a hit at normalised depth 0.5 in a relief 2 m deep, seen 60° from the normal,
/// lies 0.5·2/cos 60° = 2 m beyond the fragment along the view ray; its NDC depth is the
/// projection's at the moved point.
#[test]
fn occlusion_depth_of_the_hit() {
    let (s, c) = 60f32.to_radians().sin_cos();
    let d = view_distance(0.5, Vec3::new(s, 0.0, -c), 2.0).unwrap();
    assert!((d - 2.0).abs() < 1e-6);
    let projection = Projection::Perspective {
        fov_y: 1.0,
        aspect: 1.5,
        near: 0.1,
        far: Far::Infinite,
    };
    for conv in DepthConvention::ALL {
        let (p, ndc) = occlusion_depth(
            &projection,
            conv,
            DVec3::new(1.0, 0.5, -5.0),
            DVec3::new(0.2, 0.1, -1.0),
            2.0,
        )
        .unwrap();
        let dir = DVec3::new(0.2, 0.1, -1.0).normalize();
        assert!((p - (DVec3::new(1.0, 0.5, -5.0) + dir * 2.0)).length() < 1e-12);
        assert_eq!(ndc, projection.ndc_depth(conv, p.z).unwrap());
    }
}

/// Normals by central differences: (0, 0, 1) on a flat map; on a ramp whose depth falls by
/// 0.025 per texel along x, `normalize(−0.025·D, 0, 1)` for a relief D texels deep, and half that
/// slope on the clamped border texels (their outer neighbour is themselves).
#[test]
fn normal_map() {
    let flat = from_fn(8, Edge::Wrap, |_, _| 0.5);
    assert!(normals(&flat, 10.0).unwrap().iter().all(|v| *v == Vec3::Z));
    let ramp = from_fn(16, Edge::Clamp, |i, _| 0.1 + 0.025 * i as f32);
    let ns = normals(&ramp, 8.0).unwrap();
    let expect = |slope: f32| Vec3::new(-slope * 8.0, 0.0, 1.0).normalize();
    for j in 0..16 {
        for i in 0..16 {
            let slope = if i == 0 || i == 15 { 0.0125 } else { 0.025 };
            assert!(
                (ns[j * 16 + i] - expect(slope)).length() < 1e-5,
                "({i}, {j})"
            );
        }
    }
}
