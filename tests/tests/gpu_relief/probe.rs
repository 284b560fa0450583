//! The probe against the CPU tracers: isotropic, quadrant and mip-mapped cones, and draws
//! with isotropic layers against the isotropic draw.

use super::*;

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
pub(crate) const MIP_LEVELS: usize = 6;

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
