//! What one relief-mapped face is (`ReliefScene`: the quad or polygon, its tangent frame, the
//! relief's depth and tiling, the light and material) and the uniform block a draw of it reads
//! (`scene_uniforms`, ocean-relief's `ReliefUniforms`).

use super::*;

/// The relief-mapped quad, how it is traced and how it is lit (module documentation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReliefScene {
    /// World position of the corner at texture coordinates `(0, 0)`.
    pub origin: DVec3,
    /// World vector from `origin` along the texture's `u` axis to the next corner.
    pub edge_u: DVec3,
    /// World vector from `origin` along the texture's `v` axis (rows) to the next corner.
    pub edge_v: DVec3,
    /// Texture widths across `edge_u` and `edge_v` (the tiling; both `> 0`).
    pub tiles: DVec2,
    /// Depth of the relief below the polygon, world units (`≥ 0`).
    pub depth: f64,
    /// The tracer of the viewing ray and of the light ray.
    pub method: Method,
    /// Whether the light ray is traced for self-shadowing ([`ocean_relief::shadow::in_shadow`]).
    pub shadows: bool,
    /// How far (depth units) above a point the light ray must stop to shadow it, in `[0, 1]`.
    pub shadow_bias: f32,
    /// World direction towards the (directional) light; any length but zero.
    pub light_dir: DVec3,
    /// The light's intensity (`≥ 0`).
    pub light_intensity: f32,
    /// The light's linear colour, multiplying `light_intensity` (each `≥ 0`; white by
    /// default).
    pub light_color: [f32; 3],
    /// Linear albedo (each `≥ 0`).
    pub albedo: [f32; 3],
    /// Light that reaches every point regardless of the light and shadows (`≥ 0`).
    pub ambient: f32,
    /// The environment's irradiance `E` (world space, y up), or none: the ambient term gains
    /// `albedo × E(n)/π`, a Lambertian surface's radiance under it, `n` the relief's normal at
    /// the hit in world space, so faces turned to the sky are lit more than faces turned to
    /// the sea. `light_intensity` and `ambient` must then be in the same radiance units.
    pub sky: Option<Irradiance>,
    /// The polygon drawn: its corners `(s, t)`, the points `origin + s·edge_u + t·edge_v`,
    /// counter-clockwise seen from the front, convex, enclosing an area; a triangle repeats
    /// its last corner. [`ReliefScene::QUAD`] (the default) draws the whole rectangle.
    /// Corners may lie outside the rectangle: the texture repeats (or clamps) beyond it.
    pub corners: [DVec2; 4],
}

impl Default for ReliefScene {
    /// A unit quad in the `xz` plane facing `+y` (`u` along `+x`, `v` along `−z`), one tile,
    /// 0.1 deep; relaxed cone stepping with 15 cone steps and 6 bisections of the last step;
    /// self-shadowing with a bias of 0.02; a white light from `(1, 2, 1)`, grey albedo 0.8,
    /// ambient 0.2, no sky.
    fn default() -> Self {
        Self {
            origin: DVec3::ZERO,
            edge_u: DVec3::X,
            edge_v: DVec3::NEG_Z,
            tiles: DVec2::ONE,
            depth: 0.1,
            method: Method::Relaxed {
                cone: 15,
                binary: 6,
                search: BinarySearch::LastStep,
            },
            shadows: true,
            shadow_bias: 0.02,
            light_dir: DVec3::new(1.0, 2.0, 1.0),
            light_intensity: 1.0,
            light_color: [1.0; 3],
            albedo: [0.8, 0.8, 0.8],
            ambient: 0.2,
            sky: None,
            corners: Self::QUAD,
        }
    }
}

/// The quad's tangent frame and scales, from [`ReliefScene::tangent_frame`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TangentFrame {
    /// Unit world vector along `u`.
    pub tangent: DVec3,
    /// Unit world vector along `v`.
    pub bitangent: DVec3,
    /// `tangent × bitangent`: out of the polygon, towards its front.
    pub normal: DVec3,
    /// World length of one texture width.
    pub texture_width: f64,
    /// Relief depth in texture widths: the tracers' `depth`
    /// ([`ocean_relief::Ray::from_view`]).
    pub depth_scale: f64,
}

impl TangentFrame {
    /// A world vector in tangent space.
    pub fn to_tangent(&self, v: DVec3) -> DVec3 {
        DVec3::new(
            v.dot(self.tangent),
            v.dot(self.bitangent),
            v.dot(self.normal),
        )
    }
}

/// Relative tolerance of the quad's shape checks (orthogonal edges, square texture widths).
pub const SHAPE_TOLERANCE: f64 = 1.0e-6;

impl ReliefScene {
    /// [`ReliefScene::corners`] of the whole rectangle.
    pub const QUAD: [DVec2; 4] = [
        DVec2::new(0.0, 0.0),
        DVec2::new(1.0, 0.0),
        DVec2::new(1.0, 1.0),
        DVec2::new(0.0, 1.0),
    ];

    /// The tangent frame, after checking the quad (module documentation).
    ///
    /// # Errors
    ///
    /// [`GpuError::InvalidInput`] for a non-finite value, a zero edge, edges that are not
    /// orthogonal (within [`SHAPE_TOLERANCE`]), texture widths of different world lengths along
    /// `u` and `v` (within [`SHAPE_TOLERANCE`]), tiles `≤ 0`, a negative depth, or a depth scale
    /// above 10⁶ texture widths.
    pub fn tangent_frame(&self) -> Result<TangentFrame, GpuError> {
        let finite = self.origin.is_finite()
            && self.edge_u.is_finite()
            && self.edge_v.is_finite()
            && self.tiles.is_finite()
            && self.depth.is_finite();
        if !finite {
            return Err(invalid("relief quad", "every coordinate must be finite"));
        }
        let (lu, lv) = (self.edge_u.length(), self.edge_v.length());
        if !(lu > 0.0 && lv > 0.0 && lu.is_finite() && lv.is_finite()) {
            return Err(invalid(
                "relief quad",
                "its edges must have a non-zero length",
            ));
        }
        if !(self.tiles.x > 0.0 && self.tiles.y > 0.0) {
            return Err(invalid("relief quad", "tiles must be positive"));
        }
        let (t, b) = (self.edge_u / lu, self.edge_v / lv);
        if t.dot(b).abs() > SHAPE_TOLERANCE {
            return Err(invalid(
                "relief quad",
                "edge_u and edge_v must be orthogonal",
            ));
        }
        let (wu, wv) = (lu / self.tiles.x, lv / self.tiles.y);
        if (wu - wv).abs() > SHAPE_TOLERANCE * wu.max(wv) {
            return Err(invalid(
                "relief quad",
                format!("a texture width must have one world length: {wu} along u, {wv} along v"),
            ));
        }
        if self.depth < 0.0 {
            return Err(invalid("relief depth", "must be at least 0"));
        }
        let depth_scale = self.depth / wu;
        if !(wu.is_normal() && depth_scale.is_finite()) || depth_scale > 1.0e6 {
            return Err(invalid(
                "relief depth",
                format!("{depth_scale} texture widths is above 1e6"),
            ));
        }
        Ok(TangentFrame {
            tangent: t,
            bitangent: b,
            normal: t.cross(b),
            texture_width: wu,
            depth_scale,
        })
    }

    /// The unit direction towards the light.
    ///
    /// # Errors
    ///
    /// [`GpuError::InvalidInput`] for a zero or non-finite direction.
    pub fn light(&self) -> Result<DVec3, GpuError> {
        let l = self.light_dir.normalize_or_zero();
        if !self.light_dir.is_finite() || l == DVec3::ZERO {
            return Err(invalid("light direction", "must be finite and non-zero"));
        }
        Ok(l)
    }

    fn check_shading(&self) -> Result<(), GpuError> {
        let ok = |v: f32| v.is_finite() && v >= 0.0;
        if !(ok(self.light_intensity)
            && ok(self.ambient)
            && self.albedo.iter().chain(&self.light_color).all(|&a| ok(a)))
        {
            return Err(invalid(
                "relief shading",
                "light intensity and colour, albedo and ambient must be finite and >= 0",
            ));
        }
        let sky = self.sky.is_none_or(|e| {
            e.scaled_rows(std::f64::consts::FRAC_1_PI)
                .iter()
                .flatten()
                .all(|v| v.is_finite())
        });
        if !sky {
            return Err(invalid(
                "relief sky",
                "its irradiance coefficients must be finite in f32",
            ));
        }
        Ok(())
    }
}

/// The window depth (what a depth buffer of a [`ReliefRenderer`] holds) of an NDC depth in the
/// camera's convention: `(z + 1)/2` for OpenGL's `[−1, 1]` range, `z` otherwise.
pub fn window_depth(camera: &Camera, ndc_depth: f64) -> f64 {
    camera.depth().range().window_depth(ndc_depth)
}

fn f4(v: DVec3, w: f32) -> [f32; 4] {
    [v.x as f32, v.y as f32, v.z as f32, w]
}

/// The uniform block (binding 0 of `relief_draw.wgsl`, and of its GLSL export) of one draw of
/// `scene` seen by `camera`, for a relief texture of side `size`, edge mode `edge` and `levels`
/// mip levels (1 for level 0 alone; [`ocean_relief::lod`]); with `srgb_encode` the fragment
/// stage sRGB-encodes its colour (for a non-sRGB target).
/// [`ReliefRenderer`] draws with exactly this block; an engine that draws the exported shader
/// in its own pipeline uploads it as it is.
///
/// # Errors
///
/// [`GpuError::InvalidInput`] for a quad, light or shading [`ReliefScene`] refuses, a camera
/// whose eye-relative view-projection is not representable in `f32` or whose view matrix is
/// degenerate; the [`ReliefError`](ocean_relief::ReliefError)s of the texture size, the level
/// count ([`ReliefUniforms::set_levels`]) and the method's step counts.
pub fn scene_uniforms(
    camera: &Camera,
    scene: &ReliefScene,
    size: usize,
    edge: Edge,
    levels: usize,
    srgb_encode: bool,
) -> Result<ReliefUniforms, GpuError> {
    let frame = scene.tangent_frame()?;
    let light = scene.light()?;
    scene.check_shading()?;
    polygon::check_corners(&scene.corners)?;
    let eye = camera.eye();
    let view_proj = camera.depth().range().to_zero_to_one()
        * camera.view_projection_f64()
        * DMat4::from_translation(eye);
    let vp = view_proj.as_mat4();
    if !vp.is_finite() || !eye.is_finite() {
        return Err(invalid(
            "camera",
            "its view-projection is not representable in f32",
        ));
    }
    // The camera's forward direction: view-space −z taken back to the world.
    let forward = camera
        .view_f64()
        .inverse()
        .transform_vector3(DVec3::NEG_Z)
        .normalize_or_zero();
    if forward == DVec3::ZERO || !forward.is_finite() {
        return Err(invalid("camera", "degenerate view matrix"));
    }
    let ortho = matches!(camera.projection(), Projection::Orthographic { .. });
    let mut u = ReliefUniforms {
        view_proj: vp.to_cols_array_2d(),
        quad_origin: f4(scene.origin - eye, 0.0),
        quad_u: f4(scene.edge_u, scene.tiles.x as f32),
        quad_v: f4(scene.edge_v, scene.tiles.y as f32),
        polygon: polygon::corner_block(&scene.corners),
        tangent: f4(frame.tangent, 0.0),
        bitangent: f4(frame.bitangent, scene.depth as f32),
        normal: f4(frame.normal, 0.0),
        view_dir: f4(forward, if ortho { 1.0 } else { 0.0 }),
        light: f4(light, scene.light_intensity),
        albedo: [
            scene.albedo[0],
            scene.albedo[1],
            scene.albedo[2],
            scene.ambient,
        ],
        light_color: [
            scene.light_color[0],
            scene.light_color[1],
            scene.light_color[2],
            0.0,
        ],
        irradiance: scene.sky.map_or([[0.0; 4]; 9], |e| {
            e.scaled_rows(std::f64::consts::FRAC_1_PI)
        }),
        ..Default::default()
    };
    if !(u.quad_origin.iter().all(|v| v.is_finite())
        && u.quad_u.iter().all(|v| v.is_finite())
        && u.quad_v.iter().all(|v| v.is_finite())
        && u.bitangent[3].is_finite())
    {
        return Err(invalid(
            "relief quad",
            "not representable in f32 relative to the eye",
        ));
    }
    u.set_texture(size, edge)?;
    u.set_levels(levels)?;
    u.set_method(&scene.method)?;
    u.set_depth(frame.depth_scale as f32, scene.shadow_bias)?;
    u.set_flag(FLAG_SHADOWS, scene.shadows);
    u.set_flag(FLAG_SRGB_ENCODE, srgb_encode);
    Ok(u)
}
