//! Local waves on the GPU ocean renderer (Bruneton et al. 2010, §6) against their CPU twin,
//! `ocean_brdf::LocalWaves::point`: the trains of a wave train box scene (Yrjölä & Larsson),
//! modulated by its boxes' μ around an island, drawn on the open sea by
//! `OceanRenderer::set_local_waves`, with the open sea faded out over the shallows.
//!
//! Run with `OCEAN_REQUIRE_GPU=1` to turn a missing adapter into a failure.

use glam::{DVec2, DVec3};
use ocean_brdf::{
    Filter, FilteredSurface, Lighting, LocalWaves, SeaParams, SkyParams, Spectrum, SpectrumParams,
};
use ocean_core::{Camera, DepthConvention, Far, Projection};
use ocean_gpu::{GpuContext, OceanOptions, OceanRenderer};
use ocean_tests::gpu_context_or_skip;

fn surface() -> FilteredSurface {
    let spectrum = Spectrum::new(SpectrumParams::default()).expect("default spectrum");
    FilteredSurface::new(&spectrum, Filter::PAPER).expect("default surface")
}

/// The island scene of `ocean_wtb::scenarios` at 64² (1 m spacing) at time `t`, as local
/// waves on `sea`: its boxes' trains and μ, and the open sea's factor rising from 0 on land
/// and in water shallower than 2 m to 1 from 10 m deep.
fn island_local_waves(sea: &FilteredSurface, t: f64) -> LocalWaves {
    let mut scene = ocean_wtb::scenarios::island(64).expect("island scene");
    let grid = *scene.grid();
    let depths: Vec<f32> = (0..grid.nz())
        .flat_map(|j| (0..grid.nx()).map(move |i| (i, j)))
        .map(|(i, j)| scene.terrain().depth(i, j) as f32)
        .collect();
    let frame = scene.frame(t, None).expect("frame");
    let mut local = LocalWaves::new(
        grid.origin(),
        grid.spacing(),
        grid.nx(),
        grid.nz(),
        sea.wind(),
        *sea.filter(),
    )
    .expect("local waves");
    for layer in frame.layers() {
        local
            .add_set(layer.waves, layer.modulation)
            .expect("layer fits");
    }
    let scale: Vec<f32> = depths
        .iter()
        .map(|&d| ((d - 2.0) / 8.0).clamp(0.0, 1.0))
        .collect();
    local.set_open_scale(&scale).expect("factors");
    local
}

fn camera(width: u32, height: u32) -> Camera {
    Camera::look_at(
        DVec3::new(20.0, 25.0, 75.0),
        DVec3::new(32.0, 0.0, 30.0),
        DVec3::Y,
        Projection::Perspective {
            fov_y: 60f64.to_radians(),
            aspect: f64::from(width) / f64::from(height),
            near: 0.1,
            far: Far::Finite(100_000.0),
        },
        DepthConvention::ZERO_TO_ONE,
    )
    .expect("camera")
}

fn renderer(ctx: &GpuContext, local: Option<&LocalWaves>) -> OceanRenderer {
    let mut r = OceanRenderer::new(ctx, OceanOptions::default()).expect("renderer");
    r.set_surface(ctx, &surface()).expect("surface");
    r.set_lighting(
        ctx,
        &Lighting::new(SkyParams::default(), SeaParams::default()).expect("lighting"),
    )
    .expect("lighting");
    r.set_local_waves(ctx, local).expect("local waves");
    r
}

/// Every probed point against `LocalWaves::point` at the GPU's own rest position and
/// footprints, at t = 37 s (the box fully grown):
/// - Eq. 2 (open sea × s plus the trains × w_p × μ): 1 mm;
/// - Eq. 3: 0.1°;
/// - Eq. 4 (s² times the open sea's plus each train's k·A·|μ|·w_r): 10⁻⁴ relative to
///   max(σ², 10⁻⁶) plus 10⁻⁶ (μ read from f32 texels by f32 bilinear weights);
/// - the fragment stage's geometry normal (w_p for its cell_px · l) and normal-only variance
///   (weights w_n − w_p): 0.1° and the tolerance of Eq. 4, as Eq. 3 and 4. The probe's fragment
///   cell is the vertex stage's L at the same pixel, so `LocalWaves::point` is given L.
///
/// Not vacuous: the points cover the island's shallows (s < 1) and the box's trains (|μ| > 0.2),
/// where the surface differs from the open sea's by more than 5 cm or 2°.
#[test]
fn local_waves_match_the_cpu_twin() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let sea = surface();
    let t = 37.0;
    let local = island_local_waves(&sea, t);
    let r = renderer(&ctx, Some(&local));
    let (width, height) = (96, 64);
    let cam = camera(width, height);
    let mut pixels = Vec::new();
    for y in (0..height).step_by(2) {
        for x in (0..width).step_by(2) {
            pixels.push(DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5));
        }
    }
    let gpu = r
        .probe_surface(&ctx, &cam, t, width, height, &pixels)
        .expect("probe");
    let (mut pos, mut normal, mut var) = (0.0f64, 0.0f64, 0.0f64);
    let (mut geometry, mut only) = (0.0f64, 0.0f64);
    let (mut shallow, mut trains, mut changed) = (0, 0, 0);
    for g in &gpu {
        let cpu = local
            .point(&sea, g.rest, t, g.cell_footprint, g.pixel_footprint)
            .expect("cpu point");
        pos = pos.max((g.position - cpu.position).length());
        normal = normal.max(g.normal.angle_between(cpu.normal).to_degrees());
        geometry = geometry.max(
            g.geometry_normal
                .angle_between(cpu.geometry_normal)
                .to_degrees(),
        );
        let o = cpu.normal_only;
        let tol = 1e-4 * o.x.max(o.y).max(1e-6) + 1e-6;
        only = only.max(
            (g.normal_only.x - o.x)
                .abs()
                .max((g.normal_only.y - o.y).abs())
                / tol,
        );
        let v = cpu.variance;
        let tol = 1e-4 * v.x.max(v.y).max(1e-6) + 1e-6;
        var = var.max((g.variance.x - v.x).abs().max((g.variance.y - v.y).abs()) / tol);
        if local.open_scale_at(g.rest) < 0.99 {
            shallow += 1;
        }
        let mu = local.modulation_at(0, g.rest);
        if mu[0].hypot(mu[1]) > 0.2 {
            trains += 1;
        }
        let open = sea.position(g.rest, t, g.cell_footprint).expect("open sea");
        let open_n = sea.normal(g.rest, t, g.pixel_footprint).expect("open sea");
        if (cpu.position - open).length() > 0.05
            || cpu.normal.angle_between(open_n) > 2f64.to_radians()
        {
            changed += 1;
        }
    }
    println!(
        "{} points: position {pos} m, normal {normal}°, variance {var} (of its tolerance); shallow {shallow}, trains {trains}, changed {changed}",
        gpu.len()
    );
    assert!(pos <= 1e-3, "Eq. 2 differs by {pos} m");
    assert!(normal <= 0.1, "Eq. 3 differs by {normal}°");
    assert!(var <= 1.0, "Eq. 4 differs by {var} times its tolerance");
    println!("geometry normal {geometry}°, normal-only variance {only} (of its tolerance)");
    assert!(
        geometry <= 0.1,
        "the geometry normal differs by {geometry}°"
    );
    assert!(
        only <= 1.0,
        "the normal-only variance differs by {only} times its tolerance"
    );
    assert!(shallow > 50 && trains > 50 && changed > 50);
}

/// Removing the local waves gives back the open sea exactly (the renderer's probe equals one
/// that never had them), setting new ones of the same shape equals a renderer given only those,
/// and a wind or filter other than the surface's is refused.
#[test]
fn local_waves_can_be_removed_and_must_share_the_wind() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let sea = surface();
    let local = island_local_waves(&sea, 5.0);
    let mut r = renderer(&ctx, Some(&local));
    let plain = renderer(&ctx, None);
    let (width, height) = (32, 24);
    let cam = camera(width, height);
    let pixels: Vec<DVec2> = (0..24)
        .map(|k| DVec2::new(1.5 + f64::from(k), 12.5))
        .collect();
    let with = r
        .probe_surface(&ctx, &cam, 5.0, width, height, &pixels)
        .expect("probe");
    r.set_local_waves(&ctx, None).expect("removed");
    let without = r
        .probe_surface(&ctx, &cam, 5.0, width, height, &pixels)
        .expect("probe");
    let reference = plain
        .probe_surface(&ctx, &cam, 5.0, width, height, &pixels)
        .expect("probe");
    assert_eq!(without, reference);
    assert_ne!(with, reference);
    // Local waves of the same shape at another time (the per-frame case, written into the
    // renderer's textures in place) probe exactly as in a renderer given only them.
    r.set_local_waves(&ctx, Some(&local)).expect("set again");
    let mut later = island_local_waves(&sea, 40.0);
    // A field that differs from the first one's, so a texture left unwritten would show.
    let half = vec![0.5f32; later.open_scale().len()];
    later.set_open_scale(&half).expect("factors");
    r.set_local_waves(&ctx, Some(&later))
        .expect("same shape, rewritten");
    let fresh = renderer(&ctx, Some(&later));
    let want = fresh
        .probe_surface(&ctx, &cam, 40.0, width, height, &pixels)
        .expect("probe");
    let got = r
        .probe_surface(&ctx, &cam, 40.0, width, height, &pixels)
        .expect("probe");
    assert_eq!(got, want);
    let other = LocalWaves::new(DVec2::ZERO, 1.0, 4, 4, DVec2::new(0.0, 1.0), Filter::PAPER)
        .expect("local waves");
    assert!(r.set_local_waves(&ctx, Some(&other)).is_err());
    let filter = Filter::new(2.0, 4.0).expect("filter");
    let other_filter =
        LocalWaves::new(DVec2::ZERO, 1.0, 4, 4, sea.wind(), filter).expect("local waves");
    assert!(r.set_local_waves(&ctx, Some(&other_filter)).is_err());
}
