//! Headless renders against the CPU twin pixel by pixel, polygons, and the relief's depth in the
//! caller's targets; the draw time (ignored by default).

use super::*;

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
pub(crate) struct Setup {
    pub(crate) map: HeightMap,
    pub(crate) texture: ReliefTexture,
    pub(crate) scene: ReliefScene,
    pub(crate) frame: TangentFrame,
    /// With mip levels: the chain the renderer draws with, and each level's height map.
    pub(crate) mips: Option<(ReliefMips, Vec<HeightMap>)>,
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

    pub(crate) fn new(method: Method) -> Self {
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

pub(crate) fn cameras() -> Vec<(&'static str, Camera)> {
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
