//! GPU/CPU parity of relief mapping: `ocean_gpu::ReliefRenderer`'s tracer and shadow
//! test against `ocean_relief`'s CPU tracers and `shadow::in_shadow` (through its probe, on rays
//! at 0–80° from the normal over several maps, both edge modes and every method), its headless
//! render against the CPU twin pixel by pixel (the depth it writes against
//! `occlusion::occlusion_depth`, shadowed and lit pixels against `in_shadow`, the shading), its
//! occlusion in the caller's depth buffer, `ocean_gpu::ConeMapGenerator` against
//! `ConeMap::generate`; then bad input.
//!
//! Acceptance (ARCHITECTURE.md, "CPU and GPU twins"): GPU hits within 0.01 texel of the CPU's, cone maps equal up to
//! quantisation. Both were measured bit-identical on Mesa's lavapipe (Vulkan) and llvmpipe (GL):
//! the tracer does the CPU's exact bilinear fetch and rounds every operation as the CPU does
//! (`relief_common.wgsl`), the generator computes the CPU's `f64` bound in double-`f32`
//! (`relief_cone.wgsl`). On software adapters the tests assert that bit for bit, so a
//! divergence in arithmetic fails long before the parity tolerance would; on other adapters
//! they assert the parity tolerances.
//!
//! Run with `OCEAN_REQUIRE_GPU=1` to turn a missing adapter into a failure.

use std::time::Instant;

use glam::{DVec2, DVec3, Vec2, Vec3};
use ocean_brdf::Irradiance;
use ocean_core::{Camera, DepthConvention, Far, Projection};
use ocean_gpu::relief::window_depth;
use ocean_gpu::{
    ConeMapGenerator, GpuContext, GpuError, ReliefLayout, ReliefRay, ReliefRenderer, ReliefScene,
    TangentFrame, wgpu,
};
use ocean_relief::maps::{boxes, bumps, pins, thin_walls, to_map, value_noise, white_noise};
use ocean_relief::occlusion::{occlusion_depth, view_distance};
use ocean_relief::shadow::in_shadow;
use ocean_relief::trace::BinarySearch;
use ocean_relief::{
    ConeMap, ConeParams, Edge, HeightMap, Hit, Method, QuadConeMap, QuadReliefMips,
    QuadReliefTexture, Ray, ReliefError, ReliefMips, ReliefTexture,
};
use ocean_tests::{gpu_context_or_skip, texture_2d};

/// Whether the adapter is a software rasteriser (Mesa's lavapipe or llvmpipe): there the GPU
/// was measured to match the CPU bit for bit, and the tests hold it to that.
fn software(ctx: &GpuContext) -> bool {
    ctx.adapter_info()
        .is_some_and(|i| i.device_type == wgpu::DeviceType::Cpu)
}

/// Deterministic numbers in [0, 1) (SplitMix64).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f32 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        (z >> 40) as f32 / (1u64 << 24) as f32
    }
}

/// Side of the test maps.
const N: usize = 64;

/// The parity tolerance on hits, texels.
const HIT_TOL_TEXELS: f32 = 0.01;

/// Six procedural maps (smooth and white noise, boxes with steep walls, thin walls, pins,
/// bumps) in both edge modes, 64² and, for the noise, also 50² (a side that is not a power of
/// two: a wrap-mode texel index taken modulo 50 cannot hide a wrong remainder of a negative
/// index, which modulo 64 can).
fn test_maps() -> Vec<(&'static str, HeightMap)> {
    let mut out = Vec::new();
    for edge in [Edge::Wrap, Edge::Clamp] {
        let m = |h: Vec<f32>| to_map(N, &h, edge).unwrap();
        out.push((
            "noise 50",
            to_map(50, &value_noise(50, 5, 4, 21), edge).unwrap(),
        ));
        out.push(("noise", m(value_noise(N, 4, 4, 1))));
        out.push(("boxes", m(boxes(N, 12, 2))));
        out.push(("walls", m(thin_walls(N, 8))));
        out.push(("pins", m(pins(N, 40, 3))));
        out.push(("bumps", m(bumps(N, 10, 6.0, 4))));
        out.push(("white", m(white_noise(N, 5))));
    }
    out
}

/// Every method and binary search the shader supports, with the book's and the accuracy
/// table's step counts and the degenerate ones (one linear step; no bisection).
fn methods() -> Vec<Method> {
    vec![
        Method::Linear {
            linear: 15,
            binary: 6,
        },
        Method::Linear {
            linear: 1,
            binary: 0,
        },
        Method::ConeStep { steps: 21 },
        Method::Relaxed {
            cone: 15,
            binary: 6,
            search: BinarySearch::LastStep,
        },
        Method::Relaxed {
            cone: 15,
            binary: 6,
            search: BinarySearch::Book,
        },
        Method::Relaxed {
            cone: 32,
            binary: 6,
            search: BinarySearch::Shared,
        },
        Method::Relaxed {
            cone: 3,
            binary: 0,
            search: BinarySearch::LastStep,
        },
    ]
}

/// Polar angles of the rays from the normal, degrees.
const ANGLES: [f32; 6] = [0.0, 20.0, 40.0, 60.0, 70.0, 80.0];
/// Relief depths of the rays, texture widths.
const SCALES: [f32; 4] = [0.05, 0.1, 0.2, 0.4];

/// Rays at every angle of [`ANGLES`], any azimuth, every depth of [`SCALES`], starting
/// anywhere on the tile and its neighbours, each with a light from a random direction above the
/// polygon (and one in 16 at or below it, where `in_shadow` answers "shadowed" without tracing).
fn rays(rng: &mut Rng, count: usize) -> Vec<(Vec2, Vec3, f32, Vec3)> {
    (0..count)
        .map(|k| {
            let theta = ANGLES[k % ANGLES.len()].to_radians();
            let phi = rng.next() * std::f32::consts::TAU;
            let (s, c) = theta.sin_cos();
            let view = Vec3::new(s * phi.cos(), s * phi.sin(), -c);
            let start = Vec2::new(rng.next() * 1.5 - 0.25, rng.next() * 1.5 - 0.25);
            let scale = SCALES[(k / ANGLES.len()) % SCALES.len()];
            let lz = if k % 16 == 5 {
                -rng.next() * 0.5
            } else {
                rng.next() + 0.05
            };
            let light = Vec3::new(rng.next() - 0.5, rng.next() - 0.5, lz);
            (start, view, scale, light)
        })
        .collect()
}

/// The largest distance between two hits in texels, horizontally (uv) and vertically (a depth
/// unit is `scale` texture widths).
fn texel_distance(a: Vec3, b: Vec3, scale: f32, n: usize) -> f32 {
    let d = (a - b).abs();
    d.x.max(d.y).max(d.z * scale) * n as f32
}

/// The probe runs the draw pass's tracer and shadow test on 480 rays per map, edge mode and
/// method (47 040 rays and shadow tests). Expected: the CPU's fetch counts exactly, hits within
/// the parity bound of 0.01 texel (bit-identical and the same shadow flags on software adapters, as
/// measured on lavapipe and llvmpipe).
#[test]
fn probe_matches_the_cpu_tracers() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let exact = software(&ctx);
    let mut renderer = ReliefRenderer::new(&ctx, Default::default()).unwrap();
    let mut rng = Rng(7);
    let (mut worst, mut total, mut identical, mut shadow_mismatch) = (0.0f32, 0, 0, 0);
    for (name, map) in test_maps() {
        let relaxed = ConeMap::generate(&map, ConeParams::relaxed(1.0)).unwrap();
        let conservative = ConeMap::generate(&map, ConeParams::conservative(1.0)).unwrap();
        for method in methods() {
            // Cone step mapping needs conservative cones; the others read relaxed ones.
            let cones = match method {
                Method::ConeStep { .. } => &conservative,
                _ => &relaxed,
            };
            let texture = ReliefTexture::new(&map, cones).unwrap();
            renderer.set_texture(&ctx, &texture).unwrap();
            let set = rays(&mut rng, 480);
            let mut probe = Vec::new();
            let mut cpu = Vec::new();
            for &(start, view, scale, light) in &set {
                let hit = method
                    .trace(&texture, &Ray::from_view(start, view, scale).unwrap())
                    .unwrap();
                let shadow = in_shadow(&texture, &method, hit.pos, light, scale, 0.01).unwrap();
                cpu.push((hit, shadow));
                probe.push(ReliefRay {
                    start,
                    view,
                    depth_scale: scale,
                    point: hit.pos,
                    light,
                    bias: 0.01,
                    ..Default::default()
                });
            }
            let gpu = renderer.probe(&ctx, &method, &probe).unwrap();
            assert_eq!(gpu.len(), cpu.len());
            for ((g, (c, s)), r) in gpu.iter().zip(&cpu).zip(&probe) {
                let label = format!("{name} {:?} {method:?} {r:?}", map.edge());
                assert_eq!(g.hit.fetches, c.fetches, "{label}");
                let d = texel_distance(g.hit.pos, c.pos, r.depth_scale, map.size());
                assert!(d <= HIT_TOL_TEXELS, "{label}: {d} texels");
                worst = worst.max(d);
                total += 1;
                identical += usize::from(g.hit.pos == c.pos);
                shadow_mismatch += usize::from(g.shadow != *s);
                if exact {
                    assert_eq!(g.hit.pos, c.pos, "{label}: not bit-identical");
                    assert_eq!(g.shadow, *s, "{label}: shadow");
                }
            }
        }
    }
    eprintln!(
        "probe: {total} rays, worst {worst:e} texel, {identical} bit-identical, \
         {shadow_mismatch} shadow flags differ"
    );
}

/// The quadrant tracer (`relief_quad_probe`, the layer picked once per ray from its quadrant)
/// on the same maps, methods and rays as [`probe_matches_the_cpu_tracers`], against
/// `QuadReliefTexture::trace` and `QuadReliefTexture::in_shadow` (whose light rays pick their
/// own quadrant), relaxed quadrant cones for linear search and relaxed cone stepping,
/// conservative ones (QDCSM, §18.1) for cone step mapping. Expected as for the isotropic
/// tracer: the CPU's fetch counts exactly, hits within the parity bound of 0.01 texel, bit-identical
/// with the same shadow flags on software adapters (the WGSL is the isotropic tracer's
/// arithmetic; only the layer index of each `textureLoad` differs). Every quadrant must be
/// exercised: the rays' azimuths are uniform, so each layer gets about a quarter of them.
#[test]
fn quad_probe_matches_the_cpu_quad_tracer() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let exact = software(&ctx);
    let mut renderer = ReliefRenderer::new(&ctx, Default::default()).unwrap();
    let mut rng = Rng(11);
    let (mut worst, mut total, mut identical, mut shadow_mismatch) = (0.0f32, 0, 0, 0);
    let mut per_layer = [0usize; 4];
    for (name, map) in test_maps() {
        let relaxed = QuadConeMap::generate(&map, ConeParams::relaxed(1.0)).unwrap();
        let conservative = QuadConeMap::generate(&map, ConeParams::conservative(1.0)).unwrap();
        let relaxed = QuadReliefTexture::new(&map, &relaxed).unwrap();
        let conservative = QuadReliefTexture::new(&map, &conservative).unwrap();
        for method in methods() {
            let texture = match method {
                Method::ConeStep { .. } => &conservative,
                _ => &relaxed,
            };
            renderer.set_quad_texture(&ctx, texture).unwrap();
            assert_eq!(renderer.layout(), Some(ReliefLayout::Quad));
            let set = rays(&mut rng, 480);
            let mut probe = Vec::new();
            let mut cpu = Vec::new();
            for &(start, view, scale, light) in &set {
                let ray = Ray::from_view(start, view, scale).unwrap();
                per_layer[QuadReliefTexture::quadrant(&ray).unwrap().index()] += 1;
                let hit = texture.trace(&method, &ray).unwrap();
                let shadow = texture
                    .in_shadow(&method, hit.pos, light, scale, 0.01)
                    .unwrap();
                cpu.push((hit, shadow));
                probe.push(ReliefRay {
                    start,
                    view,
                    depth_scale: scale,
                    point: hit.pos,
                    light,
                    bias: 0.01,
                    ..Default::default()
                });
            }
            let gpu = renderer.probe(&ctx, &method, &probe).unwrap();
            assert_eq!(gpu.len(), cpu.len());
            for ((g, (c, s)), r) in gpu.iter().zip(&cpu).zip(&probe) {
                let label = format!("quad {name} {:?} {method:?} {r:?}", map.edge());
                assert_eq!(g.hit.fetches, c.fetches, "{label}");
                let d = texel_distance(g.hit.pos, c.pos, r.depth_scale, map.size());
                assert!(d <= HIT_TOL_TEXELS, "{label}: {d} texels");
                worst = worst.max(d);
                total += 1;
                identical += usize::from(g.hit.pos == c.pos);
                shadow_mismatch += usize::from(g.shadow != *s);
                if exact {
                    assert_eq!(g.hit.pos, c.pos, "{label}: not bit-identical");
                    assert_eq!(g.shadow, *s, "{label}: shadow");
                }
            }
        }
    }
    // 14 maps x 7 methods x 480 rays. Uniform azimuths give each layer a quarter of the
    // oblique rays; layer 0 also takes every ray at 0° (dx = dy = 0, the positive sides): a
    // sixth of all. Measured: [17467, 9940, 9753, 9880] (expected about 17640 and 9800).
    assert_eq!(total, 14 * 7 * 480);
    assert!(per_layer.iter().all(|&k| k > total / 5), "{per_layer:?}");
    eprintln!(
        "quad probe: {total} rays (per layer {per_layer:?}), worst {worst:e} texel, {identical} \
         bit-identical, {shadow_mismatch} shadow flags differ"
    );
}

/// Power-of-two maps of [`test_maps`] (every one but the 50² noise), for mip chains.
fn mip_maps() -> Vec<(&'static str, HeightMap)> {
    test_maps()
        .into_iter()
        .filter(|(_, m)| m.size().is_power_of_two())
        .collect()
}

/// Methods of the mip probes: each tracer family once.
fn mip_methods() -> Vec<Method> {
    vec![
        Method::Linear {
            linear: 15,
            binary: 6,
        },
        Method::ConeStep { steps: 21 },
        Method::Relaxed {
            cone: 15,
            binary: 6,
            search: BinarySearch::LastStep,
        },
        Method::Relaxed {
            cone: 32,
            binary: 6,
            search: BinarySearch::Shared,
        },
    ]
}

/// Mip levels of the 64² chains: 64 down to 2.
const MIP_LEVELS: usize = 6;

/// A footprint for ray `k` (the texture coordinates' screen derivatives, texture widths per
/// pixel): `1.2 · 2^t` texels a pixel with `t = k mod 7`, which is level `t` (between
/// `2^(t − ½)` and `2^(t + ½)`, `ocean_relief::lod::mip_level`), and `t = 6` the coarsest
/// level 5 by clamping; the longer derivative along a random direction, the other shorter.
fn footprint(rng: &mut Rng, k: usize) -> [Vec2; 2] {
    let rho = 1.2 * 2f32.powi((k % 7) as i32) / N as f32;
    let a = rng.next() * std::f32::consts::TAU;
    let b = rng.next() * std::f32::consts::TAU;
    let du = Vec2::from_angle(a) * rho;
    let dv = Vec2::from_angle(b) * rho * (0.2 + 0.8 * rng.next());
    if k.is_multiple_of(2) {
        [du, dv]
    } else {
        [dv, du]
    }
}

/// Level of detail through the probe: mip chains of the power-of-two test maps (each level its
/// own surface and cones, `ReliefMips` / `QuadReliefMips`, relaxed cones and conservative ones
/// for cone step mapping), 420 rays per map, edge mode and method, each with a footprint that
/// picks a level from 0 to 5 (`footprint`). Expected: the probe reads the level
/// `mip_level` picks for the footprint, exactly, and traces and shadows there as the CPU does on
/// that level's texture (`Method::trace`, `in_shadow`; `QuadReliefTexture::trace`,
/// `::in_shadow`): the same fetch counts, hits within the parity bound of 0.01 texel (of level 0),
/// bit-identical with the same shadow flags on software adapters. Every level must be read.
/// (Measured: 40 320 rays, 5 760 at each of levels 0–4 and 11 520 at level 5, all
/// bit-identical on lavapipe and llvmpipe. With the levels uploaded as a mip chain instead of
/// the atlas, llvmpipe's GL driver fetched wrong texels for up to 44 of 60 rays a level.)
#[test]
fn mip_probe_reads_the_footprints_level() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let exact = software(&ctx);
    let mut renderer = ReliefRenderer::new(&ctx, Default::default()).unwrap();
    let mut rng = Rng(23);
    let (mut total, mut worst) = (0usize, 0.0f32);
    let mut per_level = [0usize; MIP_LEVELS];
    for (name, map) in mip_maps() {
        let iso = |p| ReliefMips::generate(&map, p, MIP_LEVELS).unwrap();
        let quad = |p| QuadReliefMips::generate(&map, p, MIP_LEVELS).unwrap();
        let iso = [
            iso(ConeParams::relaxed(1.0)),
            iso(ConeParams::conservative(1.0)),
        ];
        let quad = [
            quad(ConeParams::relaxed(1.0)),
            quad(ConeParams::conservative(1.0)),
        ];
        for method in mip_methods() {
            let kind = usize::from(matches!(method, Method::ConeStep { .. }));
            for layout in [ReliefLayout::Isotropic, ReliefLayout::Quad] {
                match layout {
                    ReliefLayout::Isotropic => renderer.set_mips(&ctx, &iso[kind]).unwrap(),
                    ReliefLayout::Quad => renderer.set_quad_mips(&ctx, &quad[kind]).unwrap(),
                }
                let set = rays(&mut rng, 420);
                let mut probe = Vec::new();
                let mut cpu = Vec::new();
                for (k, &(start, view, scale, light)) in set.iter().enumerate() {
                    let fp = footprint(&mut rng, k);
                    let ray = Ray::from_view(start, view, scale).unwrap();
                    let (level, hit, shadow) = match layout {
                        ReliefLayout::Isotropic => {
                            let (l, t) = iso[kind].for_footprint(fp[0], fp[1]);
                            let hit = method.trace(t, &ray).unwrap();
                            let shadow =
                                in_shadow(t, &method, hit.pos, light, scale, 0.01).unwrap();
                            (l, hit, shadow)
                        }
                        ReliefLayout::Quad => {
                            let (l, t) = quad[kind].for_footprint(fp[0], fp[1]);
                            let hit = t.trace(&method, &ray).unwrap();
                            let shadow = t.in_shadow(&method, hit.pos, light, scale, 0.01).unwrap();
                            (l, hit, shadow)
                        }
                    };
                    cpu.push((level, hit, shadow));
                    probe.push(ReliefRay {
                        start,
                        view,
                        depth_scale: scale,
                        point: hit.pos,
                        light,
                        bias: 0.01,
                        footprint: fp,
                    });
                }
                let gpu = renderer.probe(&ctx, &method, &probe).unwrap();
                for ((g, (level, c, sh)), r) in gpu.iter().zip(&cpu).zip(&probe) {
                    let label = format!("{name} {:?} {layout:?} {method:?} {r:?}", map.edge());
                    assert_eq!(g.level as usize, *level, "{label}: level");
                    assert_eq!(g.hit.fetches, c.fetches, "{label}");
                    let d = texel_distance(g.hit.pos, c.pos, r.depth_scale, map.size());
                    assert!(d <= HIT_TOL_TEXELS, "{label}: {d} texels");
                    worst = worst.max(d);
                    if exact {
                        assert_eq!(g.hit.pos, c.pos, "{label}: not bit-identical");
                        assert_eq!(g.shadow, *sh, "{label}: shadow");
                    }
                    per_level[*level] += 1;
                    total += 1;
                }
            }
        }
    }
    eprintln!("mip probe: {total} rays, per level {per_level:?}, worst {worst:e} texel");
    // Levels 0–4 take a seventh of the rays each, level 5 two sevenths.
    assert!(per_level.iter().all(|&c| c * 8 >= total), "{per_level:?}");
}

/// With quadrant cones the GPU tracer must read the ray's own layer: a probe through a texture
/// whose layers were permuted (layer k holding quadrant k ^ 3's cones, the opposite quadrant)
/// stops elsewhere on rays that pass the boxes' walls. Expected: many hits differ by more than
/// the 0.01-texel tolerance (measured 135 of 480 on lavapipe and llvmpipe; asserted: more than
/// an eighth), so the parity above could not pass with a wrong layer choice.
#[test]
fn quad_probe_reads_the_rays_layer() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let map = to_map(N, &boxes(N, 12, 2), Edge::Wrap).unwrap();
    let cones = QuadConeMap::generate(&map, ConeParams::relaxed(1.0)).unwrap();
    let swapped =
        QuadConeMap::from_layers([3, 2, 1, 0].map(|k| cones.layers()[k].clone())).unwrap();
    let right = QuadReliefTexture::new(&map, &cones).unwrap();
    let wrong = QuadReliefTexture::new(&map, &swapped).unwrap();
    let method = Method::Relaxed {
        cone: 15,
        binary: 6,
        search: BinarySearch::LastStep,
    };
    let mut rng = Rng(5);
    let probe: Vec<ReliefRay> = rays(&mut rng, 480)
        .into_iter()
        .map(|(start, view, scale, light)| ReliefRay {
            start,
            view,
            depth_scale: scale,
            point: Vec3::new(start.x, start.y, 0.5),
            light,
            bias: 0.01,
            ..Default::default()
        })
        .collect();
    let mut renderer = ReliefRenderer::new(&ctx, Default::default()).unwrap();
    renderer.set_quad_texture(&ctx, &wrong).unwrap();
    let gpu = renderer.probe(&ctx, &method, &probe).unwrap();
    let off = gpu
        .iter()
        .zip(&probe)
        .filter(|(g, r)| {
            let ray = Ray::from_view(r.start, r.view, r.depth_scale).unwrap();
            let c = right.trace(&method, &ray).unwrap();
            texel_distance(g.hit.pos, c.pos, r.depth_scale, N) > HIT_TOL_TEXELS
        })
        .count();
    eprintln!("quad probe with opposite layers: {off} of 480 hits off by > 0.01 texel");
    assert!(off > 480 / 8, "{off}");
}

/// The quadrant draw pass (`relief_quad`: its pipelines, the 4-layer array binding, the layer
/// index of every fetch) against the isotropic one: a quad texture whose four layers all hold
/// the isotropic cones traces every ray, viewing and shadow, through the same texels with the
/// same arithmetic, so the image must equal the isotropic draw's bit for bit, colour and depth,
/// for every camera of the headless test (boxes, relaxed cones, shadows on). With the real
/// quadrant cones the draw differs (wider cones change where the steps land), which shows the
/// layers are read (measured: 316 of 4 × 3072 depths on lavapipe, 309 on llvmpipe GL).
#[test]
fn quad_draw_with_isotropic_layers_is_the_isotropic_draw() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let map = to_map(N, &boxes(N, 12, 2), Edge::Wrap).unwrap();
    let params = ConeParams::relaxed(1.0);
    let iso = ConeMap::generate(&map, params).unwrap();
    let same =
        QuadConeMap::from_layers([iso.clone(), iso.clone(), iso.clone(), iso.clone()]).unwrap();
    let quad = QuadConeMap::generate(&map, params).unwrap();
    let scene = ReliefScene {
        shadows: true,
        ..Default::default()
    };
    let mut renderer = ReliefRenderer::new(&ctx, Default::default()).unwrap();
    let (w, h) = (64, 48);
    let mut differs = 0;
    for (name, camera) in cameras() {
        renderer
            .set_texture(&ctx, &ReliefTexture::new(&map, &iso).unwrap())
            .unwrap();
        assert_eq!(renderer.layout(), Some(ReliefLayout::Isotropic));
        let a = renderer.render_image(&ctx, &camera, &scene, w, h).unwrap();
        renderer
            .set_quad_texture(&ctx, &QuadReliefTexture::new(&map, &same).unwrap())
            .unwrap();
        let b = renderer.render_image(&ctx, &camera, &scene, w, h).unwrap();
        assert!(a.rgba == b.rgba, "{name}: colour");
        assert!(
            a.depth
                .iter()
                .zip(&b.depth)
                .all(|(x, y)| x.to_bits() == y.to_bits()),
            "{name}: depth"
        );
        renderer
            .set_quad_texture(&ctx, &QuadReliefTexture::new(&map, &quad).unwrap())
            .unwrap();
        let c = renderer.render_image(&ctx, &camera, &scene, w, h).unwrap();
        differs += a.depth.iter().zip(&c.depth).filter(|(x, y)| x != y).count();
    }
    eprintln!(
        "quad draw: identical to isotropic with isotropic layers; {differs} depths differ with quadrant cones"
    );
    assert!(differs > 0);
}

/// The quadrant draw pass with mip levels against the isotropic one: the boxes map tiled 4 × 4
/// (so pixels read levels 1–3), drawn through `set_mips` and through `set_quad_mips` with four
/// copies of each level's isotropic cones, must give the same image bit for bit, colour and
/// depth, for every camera of the headless test; drawn with level 0 alone (`set_texture`) the
/// image differs, which shows the draw reads the coarser levels (measured: 912 of 4 × 3072
/// depths on lavapipe and on llvmpipe GL).
#[test]
fn quad_mip_draw_with_isotropic_layers_is_the_isotropic_mip_draw() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let map = to_map(N, &boxes(N, 12, 2), Edge::Wrap).unwrap();
    let params = ConeParams::relaxed(1.0);
    let iso = ReliefMips::generate(&map, params, MIP_LEVELS).unwrap();
    let maps = ocean_relief::lod::level_maps(&map, MIP_LEVELS).unwrap();
    let same = QuadReliefMips::from_levels(
        maps.iter()
            .map(|m| {
                let c = ConeMap::generate(m, params).unwrap();
                let layers = QuadConeMap::from_layers([c.clone(), c.clone(), c.clone(), c]);
                QuadReliefTexture::new(m, &layers.unwrap()).unwrap()
            })
            .collect(),
    )
    .unwrap();
    let scene = ReliefScene {
        tiles: DVec2::splat(4.0),
        shadows: true,
        ..Default::default()
    };
    let mut renderer = ReliefRenderer::new(&ctx, Default::default()).unwrap();
    let (w, h) = (64, 48);
    let mut differs = 0;
    for (name, camera) in cameras() {
        renderer.set_mips(&ctx, &iso).unwrap();
        let a = renderer.render_image(&ctx, &camera, &scene, w, h).unwrap();
        renderer.set_quad_mips(&ctx, &same).unwrap();
        assert_eq!(renderer.layout(), Some(ReliefLayout::Quad));
        let b = renderer.render_image(&ctx, &camera, &scene, w, h).unwrap();
        assert!(a.rgba == b.rgba, "{name}: colour");
        assert!(
            a.depth
                .iter()
                .zip(&b.depth)
                .all(|(x, y)| x.to_bits() == y.to_bits()),
            "{name}: depth"
        );
        renderer.set_texture(&ctx, iso.level(0)).unwrap();
        let c = renderer.render_image(&ctx, &camera, &scene, w, h).unwrap();
        differs += a.depth.iter().zip(&c.depth).filter(|(x, y)| x != y).count();
    }
    eprintln!(
        "quad mip draw: identical to isotropic mips with isotropic layers; {differs} depths \
         differ from the level-0 draw"
    );
    assert!(differs > 0);
}

/// ULPs between two non-negative f32 values.
fn ulps(a: f32, b: f32) -> u32 {
    a.to_bits().abs_diff(b.to_bits())
}

/// Per channel (ratio, clearance, near cap): texels that differ and the largest difference in
/// ulps, and whether any GPU value lies above the CPU's.
fn compare_cones(cpu: &ConeMap, gpu: &ConeMap) -> ([usize; 3], [u32; 3], bool) {
    let mut diff = [0usize; 3];
    let mut worst = [0u32; 3];
    let mut above = false;
    let pairs = [
        (cpu.ratios(), gpu.ratios()),
        (cpu.clearance(), gpu.clearance()),
        (cpu.near_cap(), gpu.near_cap()),
    ];
    for (c, (a, b)) in pairs.into_iter().enumerate() {
        for (x, y) in a.iter().zip(b) {
            if x != y {
                diff[c] += 1;
                worst[c] = worst[c].max(ulps(*x, *y));
                above |= y > x;
            }
        }
    }
    (diff, worst, above)
}

/// Maps whose cells meet the bound's exact ties: 8-bit pyramids and ramps (planar cells seen
/// along their level direction, diagonal faces: the falling test's zero and the arcs' shared
/// end points), 16-bit terraces (flat cells), at sides that are not powers of two (a padded
/// pyramid), in both edge modes.
fn tie_maps() -> Vec<(String, HeightMap)> {
    let mut out = Vec::new();
    for (n, edge) in [(37usize, Edge::Clamp), (50, Edge::Wrap)] {
        let c = n as i64 / 2;
        let diamond: Vec<u8> = (0..n * n)
            .map(|k| {
                let (x, y) = ((k % n) as i64, (k / n) as i64);
                (255 - 3 * ((x - c).abs() + (y - c).abs())).clamp(0, 255) as u8
            })
            .collect();
        out.push((
            format!("diamond {n}"),
            HeightMap::from_u8(n, n, &diamond, edge).unwrap(),
        ));
        let ramp: Vec<u8> = (0..n * n)
            .map(|k| (((k % n) + 2 * (k / n)) * 3 % 256) as u8)
            .collect();
        out.push((
            format!("ramp {n}"),
            HeightMap::from_u8(n, n, &ramp, edge).unwrap(),
        ));
        let terraces: Vec<u16> = (0..n * n)
            .map(|k| {
                let (x, y) = ((k % n) as u32, (k / n) as u32);
                (((x / 4) * 7919 + (y / 3) * 104_729) % 65536) as u16
            })
            .collect();
        out.push((
            format!("terraces {n}"),
            HeightMap::from_u16(n, n, &terraces, edge).unwrap(),
        ));
    }
    out
}

/// The cone-map parity cases: the procedural maps of [`test_maps`] with relaxed and
/// conservative cones capped at 1 and the `extra` parameters, and the tie maps with those two,
/// a cap of 64 (many tile copies in wrap mode) and one of 0.01 (every texel capped).
fn cone_cases(extra: &[ConeParams]) -> Vec<(String, HeightMap, Vec<ConeParams>)> {
    let book = [ConeParams::relaxed(1.0), ConeParams::conservative(1.0)];
    let procedural = test_maps()
        .into_iter()
        .map(|(name, map)| (name.to_owned(), map, [&book[..], extra].concat()));
    let ties = tie_maps().into_iter().map(|(name, map)| {
        let caps = [ConeParams::relaxed(64.0), ConeParams::relaxed(0.01)];
        (name, map, [&book[..], &caps[..]].concat())
    });
    procedural.chain(ties).collect()
}

/// GPU cone maps against `ConeMap::generate` on the six procedural maps in both edge modes and
/// the tie maps, relaxed and conservative, with the book's cap (1), a wide one (4, and 64 on the
/// tie maps: many tile copies in wrap mode) and a tiny one (0.01: every texel capped).
/// Expected: bit-identical on software adapters (measured: every texel of every channel, on
/// lavapipe and llvmpipe); elsewhere within 4 ulps per value and never above the CPU's by more
/// than that (the CPU's cones round down; an `f64` value within 2⁻⁴⁴ of an `f32` boundary may
/// round to the other side in double-`f32`).
#[test]
fn cone_maps_match_the_cpu() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let exact = software(&ctx);
    let generator = ConeMapGenerator::new(&ctx).unwrap();
    let cases = cone_cases(&[ConeParams::relaxed(4.0)]);
    let mut count = 0;
    for (name, map, params) in &cases {
        for &p in params {
            let cpu = ConeMap::generate(map, p).unwrap();
            let gpu = generator.generate(&ctx, map, p).unwrap();
            let (diff, worst, above) = compare_cones(&cpu, &gpu);
            let label = format!(
                "{name} {:?} {p:?}: differing {diff:?}, ulps {worst:?}",
                map.edge()
            );
            if exact {
                assert_eq!(diff, [0; 3], "{label}");
            }
            assert!(worst.iter().all(|&u| u <= 4), "{label} (above: {above})");
            count += 1;
        }
    }
    eprintln!("cone maps: {count} maps compared");
}

/// GPU quadrant cone maps (`ConeMapGenerator::generate_quad`, §18.1) against
/// `QuadConeMap::generate`, every layer and channel, on the maps of
/// [`cone_maps_match_the_cpu`] with its caps (the procedural maps without the cap of 4: the tie
/// maps' cap of 64 already sends the clipped search through many tile copies, and four layers
/// take four times as long). Expected as there, for the same reason: bit-identical on
/// software adapters, elsewhere within 4 ulps per value (the double-`f32` bound's values are
/// within about 2⁻⁴⁴ of the CPU's `f64` ones, and both round down to `f32`, so only a value that
/// close to an `f32` boundary can land one ulp away; 4 leaves room for the few such roundings
/// one value passes). The quadrant clip changes only which nodes and cells the search visits,
/// the vector boxes and the near-cell arcs, all exact integer or sign work, so it adds no
/// rounding. The GPU layers must differ from the isotropic cones wherever the CPU's do (else
/// the sector would not have reached the shader): everywhere but where every cone is capped.
#[test]
fn quad_cone_maps_match_the_cpu() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let exact = software(&ctx);
    let generator = ConeMapGenerator::new(&ctx).unwrap();
    let cases = cone_cases(&[]);
    let (mut count, mut wider) = (0, 0usize);
    for (name, map, params) in &cases {
        for &p in params {
            let cpu = QuadConeMap::generate(map, p).unwrap();
            let gpu = generator.generate_quad(&ctx, map, p).unwrap();
            let iso = ConeMap::generate(map, p).unwrap();
            let (mut cpu_from_iso, mut differs_from_iso) = (0, 0);
            for (k, (c, g)) in cpu.layers().iter().zip(gpu.layers()).enumerate() {
                let (diff, worst, above) = compare_cones(c, g);
                let label = format!(
                    "{name} {:?} {p:?} layer {k}: differing {diff:?}, ulps {worst:?}",
                    map.edge()
                );
                if exact {
                    assert_eq!(diff, [0; 3], "{label}");
                }
                assert!(worst.iter().all(|&u| u <= 4), "{label} (above: {above})");
                cpu_from_iso += compare_cones(&iso, c).0.iter().sum::<usize>();
                differs_from_iso += compare_cones(&iso, g).0.iter().sum::<usize>();
            }
            assert_eq!(
                differs_from_iso > 0,
                cpu_from_iso > 0,
                "{name} {p:?}: GPU layers vs isotropic"
            );
            wider += differs_from_iso;
            count += 1;
        }
    }
    assert!(wider > 0);
    eprintln!(
        "quad cone maps: {count} maps x 4 layers compared; {wider} layer values differ from \
         the isotropic maps"
    );
}

/// Generates the quadrant cone maps of the noise map of [`time_generation`] at side `n` in both
/// edge modes on the CPU and the GPU, prints both times next to the isotropic GPU time, and
/// checks parity as [`quad_cone_maps_match_the_cpu`] does.
fn time_quad_generation(ctx: &GpuContext, n: usize) {
    let generator = ConeMapGenerator::new(ctx).unwrap();
    for edge in [Edge::Wrap, Edge::Clamp] {
        let warm = to_map(16, &value_noise(16, 2, 2, 1), edge).unwrap();
        generator
            .generate_quad(ctx, &warm, ConeParams::relaxed(1.0))
            .unwrap();
    }
    for edge in [Edge::Wrap, Edge::Clamp] {
        let map = to_map(n, &value_noise(n, 8, 5, 3), edge).unwrap();
        let p = ConeParams::relaxed(1.0);
        let t = Instant::now();
        let cpu = QuadConeMap::generate(&map, p).unwrap();
        let cpu_time = t.elapsed();
        let (gpu, times) = generator.generate_quad_timed(ctx, &map, p).unwrap();
        let (_, iso) = generator.generate_timed(ctx, &map, p).unwrap();
        eprintln!(
            "quad cone map {n}² {edge:?}: CPU {cpu_time:?}, GPU {:?} (cells and pyramid {:?}, \
             search {:?}, texels and readback {:?}; isotropic GPU {:?}) on {}",
            times.total(),
            times.prepare,
            times.search,
            times.finish,
            iso.total(),
            ctx.describe()
        );
        for (k, (c, g)) in cpu.layers().iter().zip(gpu.layers()).enumerate() {
            let (diff, worst, _) = compare_cones(c, g);
            if software(ctx) {
                assert_eq!(diff, [0; 3], "{n}² {edge:?} layer {k}");
            }
            assert!(
                worst.iter().all(|&u| u <= 4),
                "{n}² {edge:?} layer {k}: {worst:?}"
            );
        }
    }
}

/// Quadrant generation at 128² (times printed; the assertion is parity).
#[test]
fn quad_cone_map_generation_128() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    time_quad_generation(&ctx, 128);
}

/// Quadrant generation at 256² (measured on lavapipe, 2 shared cores: 16.1 s in wrap mode and
/// 13.3 s in clamp mode, against 4.6 s and 4.2 s isotropic and 0.9 s on the CPU, so not run by
/// default: `cargo test -p ocean-tests --test gpu_relief -- --ignored`).
#[test]
#[ignore]
fn quad_cone_map_generation_256() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    time_quad_generation(&ctx, 256);
}

/// Generates the cone maps of a smooth noise map of side `n` in both edge modes on the CPU and
/// the GPU, prints both times, and checks parity as [`cone_maps_match_the_cpu`] does. A 16²
/// map in each mode goes first: drivers compile the shader at its first dispatch (about 10 s
/// on llvmpipe), which is no part of a generation's time.
fn time_generation(ctx: &GpuContext, sizes: &[usize]) {
    let generator = ConeMapGenerator::new(ctx).unwrap();
    for edge in [Edge::Wrap, Edge::Clamp] {
        let warm = to_map(16, &value_noise(16, 2, 2, 1), edge).unwrap();
        generator
            .generate(ctx, &warm, ConeParams::relaxed(1.0))
            .unwrap();
    }
    for &n in sizes {
        for edge in [Edge::Wrap, Edge::Clamp] {
            let map = to_map(n, &value_noise(n, 8, 5, 3), edge).unwrap();
            let p = ConeParams::relaxed(1.0);
            let t = Instant::now();
            let cpu = ConeMap::generate(&map, p).unwrap();
            let cpu_time = t.elapsed();
            let (gpu, times) = generator.generate_timed(ctx, &map, p).unwrap();
            eprintln!(
                "cone map {n}² {edge:?}: CPU {cpu_time:?}, GPU {:?} (cells and pyramid {:?}, \
                 search {:?}, texels and readback {:?}) on {}",
                times.total(),
                times.prepare,
                times.search,
                times.finish,
                ctx.describe()
            );
            let (diff, worst, _) = compare_cones(&cpu, &gpu);
            if software(ctx) {
                assert_eq!(diff, [0; 3], "{n}² {edge:?}");
            }
            assert!(worst.iter().all(|&u| u <= 4), "{n}² {edge:?}: {worst:?}");
        }
    }
}

/// Generation at 256² (times printed; the assertion is parity, as for the small maps).
#[test]
fn cone_map_generation_256() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    time_generation(&ctx, &[256]);
}

/// Generation at 512² and 1024² (15–18 s and 70–86 s each on llvmpipe, so not run by
/// default: `cargo test -p ocean-tests --test gpu_relief -- --ignored`).
#[test]
#[ignore]
fn cone_map_generation_large() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    time_generation(&ctx, &[512, 1024]);
}

/// What the CPU twin computes for one pixel.
#[derive(Clone, Copy, Debug)]
struct Truth {
    /// The mip level traced.
    level: usize,
    hit: Hit,
    /// Window depth of the hit ([`window_depth`] of `occlusion_depth`).
    depth: f64,
    shadow: bool,
    /// `max(N·L, 0)` with the relief normal at the hit.
    diffuse: f32,
    /// The relief normal at the hit in world space.
    world_normal: DVec3,
    /// How much the window depth changes from the polygon to the relief's bottom along this
    /// pixel's ray: the scale the depth tolerance is measured against.
    relief_span: f64,
}

/// A relief-mapped scene and the CPU twin of its draw pass.
struct Setup {
    map: HeightMap,
    texture: ReliefTexture,
    scene: ReliefScene,
    frame: TangentFrame,
    /// With mip levels: the chain the renderer draws with, and each level's height map.
    mips: Option<(ReliefMips, Vec<HeightMap>)>,
}

impl Setup {
    /// The scene of [`Setup::new`], tiled `tiles` times across each edge, with a mip chain of
    /// [`MIP_LEVELS`] levels (`ReliefMips::generate`, relaxed cones capped at 1).
    fn with_mips(method: Method, tiles: f64) -> Self {
        let mut s = Self::new(method);
        s.scene.tiles = DVec2::splat(tiles);
        s.frame = s.scene.tangent_frame().unwrap();
        let mips = ReliefMips::generate(&s.map, ConeParams::relaxed(1.0), MIP_LEVELS).unwrap();
        let maps = ocean_relief::lod::level_maps(&s.map, MIP_LEVELS).unwrap();
        s.mips = Some((mips, maps));
        s
    }

    /// The texture and height map of level `l`.
    fn level(&self, l: usize) -> (&ReliefTexture, &HeightMap) {
        match &self.mips {
            Some((mips, maps)) => (mips.level(l), &maps[l]),
            None => (&self.texture, &self.map),
        }
    }

    /// The level the draw pass reads at pixel `(px, py)`, if certain: `mip_level` of the
    /// texture coordinates' differences across the pixel's 2×2 quad (both rows for `dpdx`,
    /// both columns for `dpdy`, since an adapter may take either), scaled by 0.98 and 1.02 for
    /// the rasteriser's rounding, must agree; `None` where they do not (near a level's
    /// threshold). Level 0 without mips.
    fn level_at(&self, camera: &Camera, px: u32, py: u32, size: (u32, u32)) -> Option<usize> {
        let Some((mips, _)) = &self.mips else {
            return Some(0);
        };
        let (qx, qy) = (f64::from(px & !1) + 0.5, f64::from(py & !1) + 0.5);
        let uv = |dx: f64, dy: f64| self.plane_uv(camera, qx + dx, qy + dy, size);
        let (a, b, c, d) = (uv(0.0, 0.0)?, uv(1.0, 0.0)?, uv(0.0, 1.0)?, uv(1.0, 1.0)?);
        let mut levels = Vec::new();
        for du in [b - a, d - c] {
            for dv in [c - a, d - b] {
                for scale in [0.98, 1.02] {
                    let (du, dv) = ((du * scale).as_vec2(), (dv * scale).as_vec2());
                    levels.push(ocean_relief::lod::mip_level(du, dv, N, mips.len()));
                }
            }
        }
        levels.iter().all(|&l| l == levels[0]).then_some(levels[0])
    }

    fn new(method: Method) -> Self {
        let map = to_map(N, &value_noise(N, 4, 4, 11), Edge::Wrap).unwrap();
        let cones = ConeMap::generate(&map, ConeParams::relaxed(1.0)).unwrap();
        let texture = ReliefTexture::new(&map, &cones).unwrap();
        // A 2 × 2 quad in the xz plane facing +y, tiled twice: one texture width is one world
        // unit, the relief 0.1 deep (0.1 texture widths, 6.4 texels).
        let scene = ReliefScene {
            origin: DVec3::new(-1.0, 0.0, 1.0),
            edge_u: DVec3::new(2.0, 0.0, 0.0),
            edge_v: DVec3::new(0.0, 0.0, -2.0),
            tiles: DVec2::new(2.0, 2.0),
            depth: 0.1,
            method,
            shadows: true,
            shadow_bias: 0.01,
            light_dir: DVec3::new(1.0, 0.35, 0.3),
            light_intensity: 1.0,
            light_color: [0.9, 1.0, 1.1],
            albedo: [0.9, 0.9, 0.9],
            ambient: 0.05,
            sky: Some(test_sky()),
            corners: ReliefScene::QUAD,
        };
        let frame = scene.tangent_frame().unwrap();
        Self {
            map,
            texture,
            scene,
            frame,
            mips: None,
        }
    }

    /// The relief normal at texture coordinates `(u, v)` as `relief_common.wgsl` computes it:
    /// the bilinear blend of the four texels' central differences (`relief::normals`'s), then
    /// normalised.
    fn normal(&self, level: usize, u: f32, v: f32) -> Vec3 {
        let (_, map) = self.level(level);
        let side = map.size();
        let n = side as i64;
        let d = |i: i64, j: i64| map.depth(i, j);
        let grad = |i: i64, j: i64| {
            Vec2::new(
                (d(i + 1, j) - d(i - 1, j)) * 0.5,
                (d(i, j + 1) - d(i, j - 1)) * 0.5,
            )
        };
        let x = u * side as f32 - 0.5;
        let y = v * side as f32 - 0.5;
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let (i, j) = ((x0 as i64).rem_euclid(n), (y0 as i64).rem_euclid(n));
        let top = grad(i, j).lerp(grad(i + 1, j), fx);
        let bottom = grad(i, j + 1).lerp(grad(i + 1, j + 1), fx);
        let g = top.lerp(bottom, fy);
        // The shader's normal.w · 2^-level (exact): the depth in this level's texels.
        let texels = self.frame.depth_scale as f32 * N as f32 / (1u32 << level) as f32;
        Vec3::new(texels * g.x, texels * g.y, 1.0).normalize()
    }

    /// Where pixel position `(x, y)`'s ray meets the quad's plane: the world point, the ray's
    /// direction and the quad coordinates `(su, sv)` (0 to 1 on the quad, beyond it off it).
    fn plane_hit(
        &self,
        camera: &Camera,
        x: f64,
        y: f64,
        (w, h): (u32, u32),
    ) -> Option<(DVec3, DVec3, DVec2)> {
        let ndc = DVec2::new(2.0 * x / f64::from(w) - 1.0, 1.0 - 2.0 * y / f64::from(h));
        let conv = camera.depth();
        let near = conv.near_ndc();
        let mid = 0.5 * (near + conv.far_ndc());
        let p0 = camera.ndc_to_world(ndc.extend(near)).ok()?;
        let p1 = camera.ndc_to_world(ndc.extend(mid)).ok()?;
        let dir = (p1 - p0).normalize();
        let f = &self.frame;
        let s = &self.scene;
        let t = f.normal.dot(s.origin - p0) / f.normal.dot(dir);
        let p = p0 + dir * t;
        let rel = p - s.origin;
        let q = DVec2::new(
            rel.dot(f.tangent) / s.edge_u.length(),
            rel.dot(f.bitangent) / s.edge_v.length(),
        );
        Some((p, dir, q))
    }

    /// The texture coordinates of pixel position `(x, y)` on the quad's plane (off the quad
    /// too, as a helper invocation interpolates them).
    fn plane_uv(&self, camera: &Camera, x: f64, y: f64, size: (u32, u32)) -> Option<DVec2> {
        let (_, _, q) = self.plane_hit(camera, x, y, size)?;
        Some(q * self.scene.tiles)
    }

    /// The CPU twin at pixel position `(x, y)` (pixel centres at half-integers, y down) of a
    /// `w × h` image, traced at mip `level`, with the texture coordinates and the view and light
    /// vectors nudged by `nudge` (tangent space, for the stability test); `None` off the quad's
    /// front.
    fn truth(
        &self,
        camera: &Camera,
        x: f64,
        y: f64,
        size: (u32, u32),
        nudge: [f32; 4],
        level: usize,
    ) -> Option<Truth> {
        let (p, dir, q) = self.plane_hit(camera, x, y, size)?;
        let conv = camera.depth();
        let f = &self.frame;
        let s = &self.scene;
        let (su, sv) = (q.x, q.y);
        if !(0.0..=1.0).contains(&su) || !(0.0..=1.0).contains(&sv) {
            return None;
        }
        let (texture, _) = self.level(level);
        let view = match camera.projection() {
            Projection::Perspective { .. } => (p - camera.eye()).normalize(),
            Projection::Orthographic { .. } => dir,
        };
        let vt = f.to_tangent(view).as_vec3() + Vec3::new(nudge[2], nudge[3], 0.0);
        if vt.z >= 0.0 {
            return None;
        }
        let uv = Vec2::new((su * s.tiles.x) as f32, (sv * s.tiles.y) as f32)
            + Vec2::new(nudge[0], nudge[1]);
        let scale = f.depth_scale as f32;
        let hit = s
            .method
            .trace(texture, &Ray::from_view(uv, vt, scale).unwrap())
            .unwrap();
        let distance = view_distance(hit.pos.z, vt, s.depth as f32).unwrap();
        let v = camera.view_f64();
        let ndc_at = |d: f32| {
            occlusion_depth(
                &camera.projection(),
                conv,
                v.transform_point3(p),
                v.transform_vector3(view),
                f64::from(d),
            )
            .unwrap()
            .1
        };
        let ndc_depth = ndc_at(distance);
        let bottom = view_distance(1.0, vt, s.depth as f32).unwrap();
        let relief_span =
            (window_depth(camera, ndc_at(bottom)) - window_depth(camera, ndc_at(0.0))).abs();
        let light =
            f.to_tangent(s.light().unwrap()).as_vec3() + Vec3::new(nudge[2], nudge[3], 0.0) * 0.5;
        let shadow = in_shadow(texture, &s.method, hit.pos, light, scale, s.shadow_bias).unwrap();
        let normal = self.normal(level, hit.pos.x, hit.pos.y);
        let diffuse = normal.dot(light).max(0.0);
        let world_normal = (f.tangent * f64::from(normal.x)
            + f.bitangent * f64::from(normal.y)
            + f.normal * f64::from(normal.z))
        .normalize();
        Some(Truth {
            level,
            hit,
            depth: window_depth(camera, ndc_depth),
            shadow,
            diffuse,
            world_normal,
            relief_span,
        })
    }

    /// The colour the draw pass writes for a truth, sRGB-encoded to 8 bits.
    fn color(&self, t: &Truth) -> u8 {
        let s = &self.scene;
        let lit =
            t.diffuse * s.light_intensity * s.light_color[0] * if t.shadow { 0.0 } else { 1.0 };
        // The sky's light on the relief normal, a Lambertian surface's E/π.
        let sky = s
            .sky
            .map_or(0.0, |e| e.at(t.world_normal).x / std::f64::consts::PI);
        let c = (f64::from(s.albedo[0]) * (f64::from(s.ambient + lit) + sky)).clamp(0.0, 1.0);
        let e = if c <= 0.0031308 {
            c * 12.92
        } else {
            1.055 * c.powf(1.0 / 2.4) - 0.055
        };
        (e * 255.0).round() as u8
    }
}

/// A grey sky whose irradiance changes along every world axis (so a relief normal taken to
/// world space with a wrong frame shows): a radiance `0.5 + 0.3 x + 0.4 y − 0.2 z`, clamped
/// at 0, projected on order-2 spherical harmonics.
fn test_sky() -> Irradiance {
    Irradiance::from_radiance(|d| DVec3::splat((0.5 + 0.3 * d.x + 0.4 * d.y - 0.2 * d.z).max(0.0)))
}

/// Nudges of the CPU twin's inputs (texture coordinates in texture widths, then the tangent view
/// vector's x and y; the light moves by half as much): 100 times what the rasteriser's and the
/// shader's `f32` arithmetic (interpolation, the tangent frame's dot products) can move them.
const NUDGES: [[f32; 4]; 6] = [
    [1.0e-5, 0.0, 0.0, 0.0],
    [-1.0e-5, 0.0, 0.0, 0.0],
    [0.0, 1.0e-5, 0.0, 0.0],
    [0.0, -1.0e-5, 0.0, 0.0],
    [0.0, 0.0, 1.0e-5, -1.0e-5],
    [0.0, 0.0, -1.0e-5, 1.0e-5],
];

/// Whether the pixel's four neighbours are on the quad too: it is away from the quad's border,
/// where the rasteriser's coverage rule decides.
fn interior(setup: &Setup, camera: &Camera, px: u32, py: u32, size: (u32, u32)) -> bool {
    let (x, y) = (f64::from(px) + 0.5, f64::from(py) + 0.5);
    [(-1.0, 0.0), (1.0, 0.0), (0.0, -1.0), (0.0, 1.0)]
        .iter()
        .all(|&(dx, dy)| {
            setup
                .truth(camera, x + dx, y + dy, size, [0.0; 4], 0)
                .is_some()
        })
}

/// A pixel's truth, if it is stable: every nudged twin agrees on the shadow and lands within
/// 1e-3 texel of the centre's hit.
fn stable_truth(
    setup: &Setup,
    camera: &Camera,
    px: u32,
    py: u32,
    size: (u32, u32),
) -> Option<Truth> {
    let (x, y) = (f64::from(px) + 0.5, f64::from(py) + 0.5);
    let level = setup.level_at(camera, px, py, size)?;
    let t = setup.truth(camera, x, y, size, [0.0; 4], level)?;
    let scale = setup.frame.depth_scale as f32;
    for nudge in NUDGES {
        let n = setup.truth(camera, x, y, size, nudge, level)?;
        if n.shadow != t.shadow || texel_distance(n.hit.pos, t.hit.pos, scale, N) > 1.0e-3 {
            return None;
        }
    }
    Some(t)
}

fn cameras() -> Vec<(&'static str, Camera)> {
    let eye = DVec3::new(0.3, 1.4, 2.0);
    let target = DVec3::new(0.0, -0.05, 0.0);
    let perspective = |far| Projection::Perspective {
        fov_y: 0.9,
        aspect: 4.0 / 3.0,
        near: 0.5,
        far,
    };
    let ortho = Projection::Orthographic {
        left: -1.2,
        right: 1.2,
        bottom: -0.9,
        top: 0.9,
        near: 0.5,
        far: 6.0,
    };
    let cam = |p, c| Camera::look_at(eye, target, DVec3::Y, p, c).unwrap();
    vec![
        (
            "perspective [0,1]",
            cam(perspective(Far::Finite(20.0)), DepthConvention::ZERO_TO_ONE),
        ),
        (
            "perspective reversed, infinite",
            cam(
                perspective(Far::Infinite),
                DepthConvention::ZERO_TO_ONE_REVERSED,
            ),
        ),
        (
            "perspective [-1,1]",
            cam(
                perspective(Far::Finite(20.0)),
                DepthConvention::NEG_ONE_TO_ONE,
            ),
        ),
        ("orthographic", cam(ortho, DepthConvention::ZERO_TO_ONE)),
    ]
}

/// Window-depth tolerance: the draw pass forms the hit's position and its clip coordinates in
/// `f32` relative to the eye, from a rasterised texture coordinate. 2e-6 is 1/5000 of the
/// window-depth change across the relief's full depth along any ray of these views (at least
/// 1.0e-2, printed as the smallest relief span) and about 8 times the largest difference
/// measured on lavapipe (2.0e-7) and llvmpipe (2.4e-7).
const DEPTH_TOL: f64 = 2.0e-6;

/// Colour tolerance, 8-bit steps: the shader's `pow` in the sRGB curve and its `f32` normal.
const COLOR_TOL: u8 = 2;

/// What [`compare_render`] saw in one view.
struct ViewStats {
    name: &'static str,
    /// Interior pixels of the quad.
    quad: usize,
    /// Stable interior pixels, compared.
    stable: usize,
    /// Compared pixels where the light makes a difference, shadowed and lit.
    shadowed: usize,
    lit: usize,
    /// Compared pixels per mip level.
    per_level: [usize; MIP_LEVELS],
}

/// The draw tests' method: the book's 15 cone steps, then 6 bisections of the last step.
const RELAXED_15_6: Method = Method::Relaxed {
    cone: 15,
    binary: 6,
    search: BinarySearch::LastStep,
};

/// Draws `setup` (its mip chain when it has one, else its texture) at 96 × 72 for every camera
/// of [`cameras`] and compares each stable interior pixel with the CPU twin at the pixel's
/// level (see [`headless_render_matches_the_cpu_twin`] for what is compared and within what).
fn compare_render(ctx: &GpuContext, setup: &Setup) -> Vec<ViewStats> {
    let mut renderer = ReliefRenderer::new(ctx, Default::default()).unwrap();
    match &setup.mips {
        Some((mips, _)) => renderer.set_mips(ctx, mips).unwrap(),
        None => renderer.set_texture(ctx, &setup.texture).unwrap(),
    }
    let size = (96u32, 72u32);
    let mut out = Vec::new();
    for (name, camera) in cameras() {
        let t = Instant::now();
        let image = renderer
            .render_image(ctx, &camera, &setup.scene, size.0, size.1)
            .unwrap();
        let draw = t.elapsed();
        let clear = window_depth(&camera, camera.depth().clear_depth()) as f32;
        let mut v = ViewStats {
            name,
            quad: 0,
            stable: 0,
            shadowed: 0,
            lit: 0,
            per_level: [0; MIP_LEVELS],
        };
        let mut worst_depth = 0.0f64;
        let mut span = f64::INFINITY;
        for py in 0..size.1 {
            for px in 0..size.0 {
                let k = (py * size.0 + px) as usize;
                let gpu_depth = f64::from(image.depth[k]);
                let centre = setup.truth(
                    &camera,
                    f64::from(px) + 0.5,
                    f64::from(py) + 0.5,
                    size,
                    [0.0; 4],
                    0,
                );
                let Some(c) = centre else {
                    // Off the quad, unless next to its border.
                    if stable_border_free(setup, &camera, px, py, size) {
                        assert_eq!(image.depth[k], clear, "{name} ({px}, {py}): off the quad");
                    }
                    continue;
                };
                span = span.min(c.relief_span);
                if !interior(setup, &camera, px, py, size) {
                    continue;
                }
                v.quad += 1;
                let Some(t) = stable_truth(setup, &camera, px, py, size) else {
                    continue;
                };
                v.stable += 1;
                v.per_level[t.level] += 1;
                let dd = (gpu_depth - t.depth).abs();
                worst_depth = worst_depth.max(dd);
                assert!(
                    dd <= DEPTH_TOL,
                    "{name} ({px}, {py}) level {}: depth {gpu_depth} vs {}",
                    t.level,
                    t.depth
                );
                let g = image.rgba[4 * k];
                let expected = setup.color(&t);
                assert!(
                    g.abs_diff(expected) <= COLOR_TOL,
                    "{name} ({px}, {py}): colour {g} vs {expected} ({t:?})"
                );
                if t.diffuse >= 0.05 {
                    // Shadowed pixels show the ambient light alone.
                    let ambient = setup.color(&Truth { shadow: true, ..t });
                    let gpu_shadowed = g.abs_diff(ambient) <= COLOR_TOL;
                    assert_eq!(
                        gpu_shadowed, t.shadow,
                        "{name} ({px}, {py}): shadow ({t:?})"
                    );
                    if t.shadow {
                        v.shadowed += 1;
                    } else {
                        v.lit += 1;
                    }
                }
            }
        }
        eprintln!(
            "{name}: draw + readback {draw:?}; {} quad pixels, {} stable (per level {:?}), {} \
             shadowed, {} lit; worst depth difference {worst_depth:e}, smallest relief span \
             {span:e}",
            v.quad, v.stable, v.per_level, v.shadowed, v.lit
        );
        out.push(v);
    }
    out
}

/// A 96 × 72 headless render of the relief-mapped quad for four cameras (perspective `[0, 1]`,
/// reversed-Z with an infinite far plane, OpenGL's `[−1, 1]`, orthographic), compared pixel by
/// pixel with the CPU twin on the stable interior pixels (`interior`, `stable_truth`: at least
/// 90% of the interior, measured 95% in the perspective views and 93% in the orthographic one;
/// the rest are pixels where a nudge of the twin's inputs moves the hit by more than 1e-3 texel
/// or flips the shadow): the depth buffer holds `occlusion_depth`'s window depth within
/// [`DEPTH_TOL`]; a pixel is shadowed (ambient colour only) exactly where `in_shadow` says so,
/// wherever the light makes a visible difference (`N·L ≥ 0.05`); the colour is the CPU's
/// shading within [`COLOR_TOL`]; pixels off the quad keep the clear depth. Each view must show
/// at least 50 shadowed and 50 lit pixels (measured 329 and 1830 in perspective). One level:
/// every pixel reads level 0.
#[test]
fn headless_render_matches_the_cpu_twin() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let setup = Setup::new(RELAXED_15_6);
    for v in compare_render(&ctx, &setup) {
        let name = v.name;
        assert!(
            v.stable * 10 >= v.quad * 9,
            "{name}: {} of {} interior pixels stable",
            v.stable,
            v.quad
        );
        assert_eq!(v.per_level[0], v.stable, "{name}: one level");
        // The view must show both shadowed and lit relief for the comparison to mean anything.
        assert!(
            v.shadowed >= 50 && v.lit >= 50,
            "{name}: {} shadowed, {} lit",
            v.shadowed,
            v.lit
        );
    }
}

/// The same views of the quad tiled 4 times (so a pixel covers 2–8 level-0 texels) drawn with a
/// mip chain (`set_mips`, 6 levels): each stable pixel is compared, as above, with the CPU twin
/// traced, shadowed and shaded at the level `mip_level` picks from the pixel quad's texture
/// coordinate differences (`Setup::level_at`; pixels whose level is uncertain within ±2% of the
/// footprint are skipped, as are unstable ones). Expected: every compared pixel agrees within
/// the same tolerances; the views read several levels, each perspective view at least two with
/// 200 pixels or more; and at least 80% of the interior is compared.
#[test]
fn headless_mip_render_reads_each_pixels_level() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let setup = Setup::with_mips(RELAXED_15_6, 4.0);
    for v in compare_render(&ctx, &setup) {
        let name = v.name;
        assert!(
            v.stable * 10 >= v.quad * 8,
            "{name}: {} of {} interior pixels compared",
            v.stable,
            v.quad
        );
        let used = v.per_level.iter().filter(|&&c| c >= 200).count();
        if name.starts_with("perspective") {
            assert!(used >= 2, "{name}: levels {:?}", v.per_level);
        }
        assert!(
            v.per_level[0] < v.stable,
            "{name}: only level 0 {:?}",
            v.per_level
        );
    }
}

/// Whether point `q` (quad coordinates) lies inside the convex, counter-clockwise `polygon`.
fn inside(polygon: &[DVec2; 4], q: DVec2) -> bool {
    (0..4).all(|i| {
        let (a, b) = (polygon[i], polygon[(i + 1) % 4]);
        a == b || (b - a).perp_dot(q - a) > 0.0
    })
}

/// A triangle and a quadrilateral cut from the quad ([`ReliefScene::corners`]) draw exactly
/// their own pixels, with the relief the whole quad draws there: for the four cameras, every
/// pixel whose centre and eight neighbours at ±1 pixel all meet the quad's plane inside the
/// polygon has the whole quad's colour (within [`COLOR_TOL`]) and depth (within
/// [`DEPTH_TOL`]), and every pixel whose nine points all fall outside it keeps the clear colour
/// and depth. Pixels along the polygon's edges are not compared: the rasteriser decides them.
#[test]
fn a_polygon_draws_its_own_pixels() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let setup = Setup::new(RELAXED_15_6);
    let mut renderer = ReliefRenderer::new(&ctx, Default::default()).unwrap();
    renderer.set_texture(&ctx, &setup.texture).unwrap();
    let size = (96u32, 72u32);
    let polygons = [
        [
            DVec2::new(0.1, 0.05),
            DVec2::new(0.95, 0.3),
            DVec2::new(0.4, 0.9),
            DVec2::new(0.4, 0.9),
        ],
        [
            DVec2::new(0.2, 0.1),
            DVec2::new(0.9, 0.2),
            DVec2::new(0.8, 0.95),
            DVec2::new(0.05, 0.6),
        ],
    ];
    for (name, camera) in cameras() {
        let whole = renderer
            .render_image(&ctx, &camera, &setup.scene, size.0, size.1)
            .unwrap();
        let clear = window_depth(&camera, camera.depth().clear_depth()) as f32;
        for (p, corners) in polygons.iter().enumerate() {
            let scene = ReliefScene {
                corners: *corners,
                ..setup.scene
            };
            let image = renderer
                .render_image(&ctx, &camera, &scene, size.0, size.1)
                .unwrap();
            let (mut inner, mut outer, mut differ) = (0, 0, 0);
            for py in 0..size.1 {
                for px in 0..size.0 {
                    let k = (py * size.0 + px) as usize;
                    let mut seen = [0usize; 2];
                    for dy in [-1.0, 0.0, 1.0] {
                        for dx in [-1.0, 0.0, 1.0] {
                            let (x, y) = (f64::from(px) + 0.5 + dx, f64::from(py) + 0.5 + dy);
                            match setup.plane_hit(&camera, x, y, size) {
                                Some((_, _, q)) => seen[usize::from(inside(corners, q))] += 1,
                                None => seen[0] += 1,
                            }
                        }
                    }
                    if seen[1] == 9 {
                        inner += 1;
                        let rgba = &image.rgba[4 * k..4 * k + 4];
                        let want = &whole.rgba[4 * k..4 * k + 4];
                        let dd = f64::from((image.depth[k] - whole.depth[k]).abs());
                        let dc = rgba.iter().zip(want).map(|(a, b)| a.abs_diff(*b)).max();
                        if rgba != want || dd > 0.0 {
                            differ += 1;
                        }
                        assert!(
                            dc <= Some(COLOR_TOL) && dd <= DEPTH_TOL,
                            "{name} polygon {p} ({px}, {py}): {rgba:?} depth {} against the \
                             quad's {want:?} depth {}",
                            image.depth[k],
                            whole.depth[k]
                        );
                    } else if seen[0] == 9 {
                        outer += 1;
                        assert_eq!(
                            (&image.rgba[4 * k..4 * k + 4], image.depth[k]),
                            (&[0u8, 0, 0, 255][..], clear),
                            "{name} polygon {p} ({px}, {py}): drawn outside the polygon"
                        );
                    }
                }
            }
            eprintln!(
                "{name} polygon {p}: {inner} pixels inside ({differ} not bit-identical to the \
                 quad's), {outer} outside"
            );
            assert!(
                inner >= 200 && outer >= 200,
                "{name} polygon {p}: {inner}, {outer}"
            );
        }
    }
}

/// Whether the pixel and its four neighbours are all off the quad (so its coverage is certain).
fn stable_border_free(setup: &Setup, camera: &Camera, px: u32, py: u32, size: (u32, u32)) -> bool {
    let (x, y) = (f64::from(px) + 0.5, f64::from(py) + 0.5);
    [(0.0, 0.0), (-1.0, 0.0), (1.0, 0.0), (0.0, -1.0), (0.0, 1.0)]
        .iter()
        .all(|&(dx, dy)| {
            setup
                .truth(camera, x + dx, y + dy, size, [0.0; 4], 0)
                .is_none()
        })
}

/// The depth written is what occludes: drawing into the caller's targets over a depth buffer
/// cleared to a level inside the relief, a pixel is drawn exactly where the CPU's hit is nearer
/// than that level (forward `Less`), on stable pixels away from the level (1e-5); the rest keep
/// the caller's colour. Both kinds must occur.
#[test]
fn relief_depth_occludes_in_the_callers_targets() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let size = (96u32, 72u32);
    let setup = Setup::new(Method::Relaxed {
        cone: 32,
        binary: 6,
        search: BinarySearch::Shared,
    });
    let (_, camera) = cameras().remove(0);
    let mut renderer = ReliefRenderer::new(&ctx, Default::default()).unwrap();
    renderer.set_texture(&ctx, &setup.texture).unwrap();
    // The level: the median of the relief's window depths in this view.
    let mut depths: Vec<f64> = (0..size.1)
        .flat_map(|y| (0..size.0).map(move |x| (x, y)))
        .filter_map(|(x, y)| {
            setup
                .truth(
                    &camera,
                    f64::from(x) + 0.5,
                    f64::from(y) + 0.5,
                    size,
                    [0.0; 4],
                    0,
                )
                .map(|t| t.depth)
        })
        .collect();
    depths.sort_by(f64::total_cmp);
    let level = depths[depths.len() / 2] as f32;
    let device = ctx.device();
    let texture = |format, usage| texture_2d(&ctx, size, format, usage);
    let color = texture(
        wgpu::TextureFormat::Rgba8Unorm,
        wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
    );
    let depth = texture(
        wgpu::TextureFormat::Depth32Float,
        wgpu::TextureUsages::RENDER_ATTACHMENT,
    );
    let cv = color.create_view(&Default::default());
    let dv = depth.create_view(&Default::default());
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        // The caller's frame so far: magenta everywhere, depth at the level.
        let _pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: None,
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &cv,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color {
                        r: 1.0,
                        g: 0.0,
                        b: 1.0,
                        a: 1.0,
                    }),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &dv,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(level),
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
    }
    renderer
        .render(&ctx, &mut encoder, &camera, &setup.scene, &cv, &dv, size)
        .unwrap();
    ctx.queue().submit([encoder.finish()]);
    let rgba = ocean_gpu::readback::read_texture(&ctx, &color, 0)
        .unwrap()
        .data;
    let (mut drawn, mut hidden) = (0, 0);
    for py in 0..size.1 {
        for px in 0..size.0 {
            if !interior(&setup, &camera, px, py, size) {
                continue;
            }
            let Some(t) = stable_truth(&setup, &camera, px, py, size) else {
                continue;
            };
            if (t.depth - f64::from(level)).abs() < 1.0e-5 {
                continue;
            }
            let k = 4 * (py * size.0 + px) as usize;
            let magenta = rgba[k] == 255 && rgba[k + 1] == 0 && rgba[k + 2] == 255;
            let nearer = t.depth < f64::from(level);
            assert_eq!(
                !magenta, nearer,
                "({px}, {py}): hit at {} vs level {level}",
                t.depth
            );
            if nearer {
                drawn += 1;
            } else {
                hidden += 1;
            }
        }
    }
    eprintln!("occlusion: {drawn} drawn, {hidden} hidden behind the caller's depth");
    assert!(
        drawn >= 200 && hidden >= 200,
        "{drawn} drawn, {hidden} hidden"
    );
}

/// A device on the test's adapter with exactly WebGPU's downlevel limits.
fn downlevel_context() -> GpuContext {
    let instance =
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    let adapter =
        pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default()))
            .unwrap();
    let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        required_limits: wgpu::Limits::downlevel_defaults(),
        ..Default::default()
    }))
    .unwrap();
    GpuContext::from_device(device, queue)
}

fn input<T>(r: Result<T, GpuError>) -> bool {
    matches!(r, Err(GpuError::InvalidInput { .. }))
}

fn relief<T>(r: Result<T, GpuError>) -> bool {
    matches!(r, Err(GpuError::Relief(_)))
}

fn resource<T>(r: Result<T, GpuError>) -> bool {
    matches!(r, Err(GpuError::InvalidResource { .. }))
}

/// Bad input is an error, never a panic, and nothing is drawn.
#[test]
fn bad_input_is_refused() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let setup = Setup::new(Method::ConeStep { steps: 8 });
    let (_, camera) = cameras().remove(0);
    let mut renderer = ReliefRenderer::new(&ctx, Default::default()).unwrap();
    // No texture yet.
    assert!(matches!(
        renderer.render_image(&ctx, &camera, &setup.scene, 8, 8),
        Err(GpuError::NotConfigured { .. })
    ));
    assert!(matches!(
        renderer.probe(&ctx, &Method::ConeStep { steps: 1 }, &[]),
        Err(GpuError::NotConfigured { .. })
    ));
    renderer.set_texture(&ctx, &setup.texture).unwrap();

    // Scenes.
    let bad = |f: fn(&mut ReliefScene)| {
        let mut s = setup.scene;
        f(&mut s);
        renderer.render_image(&ctx, &camera, &s, 8, 8)
    };
    assert!(input(bad(|s| s.depth = f64::NAN)));
    assert!(input(bad(|s| s.depth = -0.1)));
    assert!(input(bad(|s| s.origin.x = f64::INFINITY)));
    assert!(
        input(bad(|s| s.edge_v = DVec3::new(0.5, 0.0, -2.0))),
        "not orthogonal"
    );
    assert!(
        input(bad(|s| s.tiles = DVec2::new(2.0, 3.0))),
        "texels not square"
    );
    assert!(input(bad(|s| s.edge_u = DVec3::ZERO)));
    assert!(input(bad(|s| s.light_dir = DVec3::ZERO)));
    assert!(input(bad(|s| s.light_dir.y = f64::NAN)));
    assert!(input(bad(|s| s.albedo[1] = f32::NAN)));
    assert!(input(bad(|s| s.ambient = -1.0)));
    assert!(relief(bad(|s| s.shadow_bias = f32::NAN)));
    assert!(relief(bad(|s| s.shadow_bias = 2.0)));
    assert!(relief(bad(|s| s.method = Method::ConeStep { steps: 0 })));
    assert!(relief(bad(|s| {
        s.method = Method::Linear {
            linear: 4,
            binary: 5000,
        }
    })));
    // Viewports and targets.
    assert!(input(renderer.render_image(
        &ctx,
        &camera,
        &setup.scene,
        0,
        8
    )));
    assert!(input(renderer.render_image(
        &ctx,
        &camera,
        &setup.scene,
        8,
        1 << 20
    )));
    let device = ctx.device();
    let target = |w, h, format| {
        device
            .create_texture(&wgpu::TextureDescriptor {
                label: None,
                size: wgpu::Extent3d {
                    width: w,
                    height: h,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                view_formats: &[],
            })
            .create_view(&Default::default())
    };
    let c16 = target(16, 16, wgpu::TextureFormat::Rgba8Unorm);
    let d16 = target(16, 16, wgpu::TextureFormat::Depth32Float);
    let d8 = target(8, 8, wgpu::TextureFormat::Depth32Float);
    let c16_float = target(16, 16, wgpu::TextureFormat::Rgba16Float);
    let mut encoder = device.create_command_encoder(&Default::default());
    let s = &setup.scene;
    assert!(resource(renderer.render(
        &ctx,
        &mut encoder,
        &camera,
        s,
        &c16,
        &d8,
        (16, 16)
    )));
    assert!(resource(renderer.render(
        &ctx,
        &mut encoder,
        &camera,
        s,
        &c16_float,
        &d16,
        (16, 16)
    )));
    assert!(resource(renderer.render(
        &ctx,
        &mut encoder,
        &camera,
        s,
        &d16,
        &d16,
        (16, 16)
    )));
    renderer
        .render(&ctx, &mut encoder, &camera, s, &c16, &d16, (16, 16))
        .unwrap();
    ctx.queue().submit([encoder.finish()]);

    // A texture wider than the device's largest 2D texture: on a device with WebGPU's
    // downlevel limits (2048; the headless context takes the adapter's larger one), a 2049²
    // relief texture.
    let small = downlevel_context();
    let side = small.device().limits().max_texture_dimension_2d as usize + 1;
    assert_eq!(side, 2049);
    let flat = HeightMap::from_depths(
        side,
        side,
        &vec![0.5; side * side],
        Edge::Wrap,
        Default::default(),
    )
    .unwrap();
    let none = ConeMap::from_ratios(side, Edge::Wrap, vec![0.0; side * side]).unwrap();
    let big = ReliefTexture::new(&flat, &none).unwrap();
    let mut small_renderer = ReliefRenderer::new(&small, Default::default()).unwrap();
    assert!(matches!(
        small_renderer.set_texture(&small, &big),
        Err(GpuError::TooLarge {
            needed: 2049,
            limit: 2048,
            ..
        })
    ));

    // Probe rays.
    let ok = ReliefRay {
        start: Vec2::new(0.5, 0.5),
        view: Vec3::new(0.3, 0.0, -1.0),
        depth_scale: 0.1,
        point: Vec3::new(0.5, 0.5, 0.2),
        light: Vec3::new(0.0, 0.5, 1.0),
        bias: 0.01,
        ..Default::default()
    };
    let m = Method::ConeStep { steps: 8 };
    assert_eq!(renderer.probe(&ctx, &m, &[ok]).unwrap().len(), 1);
    for r in [
        ReliefRay {
            start: Vec2::new(f32::NAN, 0.0),
            ..ok
        },
        ReliefRay {
            view: Vec3::new(0.0, 0.0, 1.0),
            ..ok
        },
        ReliefRay {
            depth_scale: -1.0,
            ..ok
        },
        ReliefRay {
            bias: f32::NAN,
            ..ok
        },
        ReliefRay {
            light: Vec3::new(0.0, f32::INFINITY, 1.0),
            ..ok
        },
        ReliefRay {
            footprint: [Vec2::new(f32::NAN, 0.0), Vec2::ZERO],
            ..ok
        },
    ] {
        assert!(input(renderer.probe(&ctx, &m, &[r])), "{r:?}");
    }
    assert!(input(renderer.probe(&ctx, &m, &[])));
    assert!(relief(renderer.probe(
        &ctx,
        &Method::ConeStep { steps: 0 },
        &[ok]
    )));

    // Cone map generation.
    let generator = ConeMapGenerator::new(&ctx).unwrap();
    for cap in [f32::NAN, 0.0, -1.0, 65.0] {
        assert!(
            matches!(
                generator.generate(&ctx, &setup.map, ConeParams::relaxed(cap)),
                Err(GpuError::Relief(
                    ReliefError::NotFinite(_) | ReliefError::OutOfRange { .. }
                ))
            ),
            "{cap}"
        );
    }
    // A clamp-mode map whose cell buffer exceeds the device's largest storage binding.
    let limit = device.limits().max_storage_buffer_binding_size;
    let side = ((limit / 32) as f64).sqrt() as usize + 1;
    let flat = HeightMap::from_depths(
        side,
        side,
        &vec![0.5; side * side],
        Edge::Clamp,
        Default::default(),
    )
    .unwrap();
    assert!(matches!(
        generator.generate(&ctx, &flat, ConeParams::relaxed(1.0)),
        Err(GpuError::TooLarge { .. })
    ));
}

/// Draw time of a 640 × 480 view of the quad (relaxed 15 + 6, with and without self-shadowing),
/// averaged over 5 draws after a first one, each waited for, and the share of the pixels the
/// quad covers (printed; not run by default:
/// `cargo test -p ocean-tests --test gpu_relief -- --ignored`).
#[test]
#[ignore]
fn draw_time() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let setup = Setup::new(Method::Relaxed {
        cone: 15,
        binary: 6,
        search: BinarySearch::LastStep,
    });
    let camera = Camera::look_at(
        DVec3::new(0.0, 1.2, 0.6),
        DVec3::new(0.0, -0.05, 0.0),
        DVec3::Y,
        Projection::Perspective {
            fov_y: 1.0,
            aspect: 4.0 / 3.0,
            near: 0.1,
            far: Far::Finite(20.0),
        },
        DepthConvention::ZERO_TO_ONE,
    )
    .unwrap();
    let mut renderer = ReliefRenderer::new(&ctx, Default::default()).unwrap();
    renderer.set_texture(&ctx, &setup.texture).unwrap();
    let device = ctx.device();
    let texture = |format| {
        texture_2d(
            &ctx,
            (640, 480),
            format,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        )
    };
    let color = texture(wgpu::TextureFormat::Rgba8Unorm).create_view(&Default::default());
    let depth = texture(wgpu::TextureFormat::Depth32Float).create_view(&Default::default());
    for shadows in [false, true] {
        let scene = ReliefScene {
            shadows,
            ..setup.scene
        };
        let mut times = Vec::new();
        for _ in 0..6 {
            let t = Instant::now();
            let mut encoder = device.create_command_encoder(&Default::default());
            // Clear to black and the far plane, as a frame would.
            encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: None,
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &color,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &depth,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(1.0),
                        store: wgpu::StoreOp::Store,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            renderer
                .render(
                    &ctx,
                    &mut encoder,
                    &camera,
                    &scene,
                    &color,
                    &depth,
                    (640, 480),
                )
                .unwrap();
            ctx.queue().submit([encoder.finish()]);
            ctx.wait_idle().unwrap();
            times.push(t.elapsed());
        }
        let mean = times[1..].iter().sum::<std::time::Duration>() / 5;
        let image = renderer
            .render_image(&ctx, &camera, &scene, 640, 480)
            .unwrap();
        let covered = image.depth.iter().filter(|&&d| d < 1.0).count();
        eprintln!(
            "640 x 480 draw, shadows {shadows}: {mean:?} ({:.1}% of the pixels on the quad) on {}",
            100.0 * covered as f64 / (640.0 * 480.0),
            ctx.describe()
        );
    }
}
