//! Filling the renderer's uniform data: the `Frame` block of `ocean_common.wgsl`
//! ([`FrameUniform`], defined with the wave texture [`WaveTexels`] in `ocean_brdf::gpu_params`,
//! filled by [`frame_uniform`]) for the projected grid or the caller's water mesh
//! ([`MeshGrid`]), with the camera-relative matrices that it carries (the module documentation
//! of [`crate::ocean`], "Precision").

use super::*;

pub use ocean_brdf::gpu_params::{FrameUniform, WAVE_ROWS, WaveTexels};

/// A water mesh that `mesh_vs` draws (ocean.wgsl): a grid of `nx × nz` points, point `(i, j)`
/// resting at world `(origin.x + i·spacing, 0, origin.y + j·spacing)`, its vertex index
/// `j·nx + i` (a wave train box scene's water grid, [`ocean_wtb::WaterGrid`]'s layout).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshGrid {
    /// World `(x, z)` of grid point (0, 0), metres.
    pub origin: DVec2,
    /// Distance between neighbouring points along x and z, metres, > 0.
    pub spacing: f64,
    /// Points per row (along x), ≥ 1.
    pub nx: u32,
    /// Rows (along z), ≥ 1.
    pub nz: u32,
}

/// The grid's vertex counts (per row, rows) for a viewport.
pub(super) fn grid_counts(
    options: &OceanOptions,
    width: u32,
    height: u32,
) -> Result<(u32, u32), GpuError> {
    let count = |extent: u32| {
        let span = f64::from(extent) * (1.0 + 2.0 * options.margin);
        (span / options.cell_px).ceil() + 1.0
    };
    let (nx, ny) = (count(width), count(height));
    let vertices = nx * ny;
    if vertices > f64::from(u32::MAX) {
        return Err(GpuError::TooLarge {
            what: "projected grid (vertices)",
            needed: vertices as u64,
            limit: u64::from(u32::MAX),
        });
    }
    Ok((nx as u32, ny as u32))
}

pub(super) fn mat_f32(m: DMat4, what: &'static str) -> Result<[[f32; 4]; 4], GpuError> {
    let f = m.as_mat4();
    if f.is_finite() {
        Ok(f.to_cols_array_2d())
    } else {
        Err(invalid(
            what,
            "not representable in f32 (degenerate camera)",
        ))
    }
}

pub(super) fn rgb(v: DVec3, w: f32) -> [f32; 4] {
    [v.x as f32, v.y as f32, v.z as f32, w]
}

/// The uniform block `Frame` of `ocean_common.wgsl` for one frame of `width × height` pixels
/// (`size`) seen by `camera` at `time`: what [`OceanRenderer::render`] draws with, and what a
/// caller drawing the exported shader in its own pipeline uploads. The surface's filter and
/// wind and the lighting's Sun, sky and sea fill their fields (the lighting's stay zero for
/// `None`: nothing lit); `mesh`, if given, is the water mesh `mesh_vs` draws (its origin
/// stored relative to the eye, subtracted in `f64`). The local waves and the probe count are
/// zero (none). Pair it with [`WaveTexels::frame_texels`] for the same camera and time.
///
/// The camera's matrices are formed relative to its eye in `f64` and folded into WebGPU's
/// clip space (an OpenGL `[−1, 1]` camera's `z` is halved and shifted; naga's GLSL export maps
/// it back).
///
/// # Errors
///
/// [`GpuError::InvalidInput`] for an option outside its documented range, an empty viewport,
/// a camera not above the sea (`eye.y ≤ 0`) or whose matrices overflow `f32`, or a mesh with a
/// non-finite origin, a spacing that is not finite and positive, or no points;
/// [`GpuError::Eval`] for a non-finite time; [`GpuError::TooLarge`] for a projected grid
/// beyond 2³² − 1 vertices.
pub fn frame_uniform(
    options: &OceanOptions,
    surface: &WaveTexels,
    lighting: Option<&Lighting>,
    camera: &Camera,
    time: f64,
    size: (u32, u32),
    mesh: Option<&MeshGrid>,
) -> Result<FrameUniform, GpuError> {
    options.check()?;
    let (width, height) = size;
    if width == 0 || height == 0 {
        return Err(invalid("viewport", format!("{width} x {height} is empty")));
    }
    if !time.is_finite() {
        return Err(GpuError::Eval(EvalError::Time(time)));
    }
    let eye = camera.eye();
    if !eye.is_finite() || eye.y <= 0.0 {
        return Err(invalid(
            "camera",
            format!(
                "the eye at ({}, {}, {}) must be above the sea (y > 0)",
                eye.x, eye.y, eye.z
            ),
        ));
    }
    let (nx, ny) = grid_counts(options, width, height)?;
    let o = DVec2::new(eye.x, eye.z);
    let range = camera.depth().range();
    let remap = range.to_zero_to_one();
    let view_proj = remap * camera.view_projection_f64() * DMat4::from_translation(eye);
    let inv_view_proj =
        DMat4::from_translation(-eye) * camera.inverse_view_projection_f64() * remap.inverse();
    let depth = camera.depth();
    let near = range.window_depth(depth.near_ndc());
    let far = range.window_depth(depth.far_ndc());
    let mut u = lighting_uniform(options, surface, lighting);
    u.view_proj = mat_f32(view_proj, "camera view-projection")?;
    u.inv_view_proj = mat_f32(inv_view_proj, "camera inverse view-projection")?;
    u.camera = [
        eye.y as f32,
        options.max_distance as f32,
        near as f32,
        (0.5 * (near + far)) as f32,
    ];
    u.viewport = [
        width as f32,
        height as f32,
        (-options.margin * f64::from(width)) as f32,
        (-options.margin * f64::from(height)) as f32,
    ];
    u.counts[0] = nx;
    u.counts[1] = ny;
    u.sun_radiance[3] = far as f32;
    if let Some(m) = mesh {
        let origin = m.origin - o;
        let fits = |v: f64| v.is_finite() && (v as f32).is_finite();
        if !fits(origin.x) || !fits(origin.y) {
            return Err(invalid(
                "mesh",
                format!(
                    "its origin ({}, {}) must be finite and within f32's range of the eye",
                    m.origin.x, m.origin.y
                ),
            ));
        }
        if !(m.spacing.is_finite() && m.spacing > 0.0 && (m.spacing as f32) > 0.0) {
            return Err(invalid(
                "mesh",
                format!("its spacing {} must be finite and > 0", m.spacing),
            ));
        }
        if m.nx == 0 || m.nz == 0 {
            return Err(invalid(
                "mesh",
                format!("{} x {} points: it needs at least one", m.nx, m.nz),
            ));
        }
        u.mesh_grid = [
            origin.x as f32,
            (-eye.y) as f32,
            origin.y as f32,
            m.spacing as f32,
        ];
        u.mesh_counts = [m.nx, m.nz, 0, 0];
    }
    Ok(u)
}

/// The uniform block's surface and lighting fields (the lighting's are zero
/// without a lighting).
pub(super) fn lighting_uniform(
    options: &OceanOptions,
    surface: &WaveTexels,
    lighting: Option<&Lighting>,
) -> FrameUniform {
    let mut u = FrameUniform {
        grid: [
            options.cell_px as f32,
            surface.n_min() as f32,
            surface.n_max() as f32,
            options.exposure as f32,
        ],
        counts: [
            0,
            0,
            surface.wave_count() as u32,
            u32::from(!options.color_format.is_srgb()),
        ],
        sky: [
            options.sky_map_size as f32,
            SKY_MAP_EXTENT as f32,
            // Set with the lighting below; until then no Sun is drawn.
            0.0,
            0.0,
        ],
        ..Default::default()
    };
    u.sea[0] = surface.wind().x as f32;
    u.sea[1] = surface.wind().y as f32;
    if let Some(l) = lighting {
        let sky = l.sky();
        u.sea[2] = l.sea().fresnel_r as f32;
        u.sea[3] = sky.sun_solid_angle() as f32;
        u.sun_dir = rgb(sky.sun_direction(), sky.sun_angular_radius().cos() as f32);
        u.sky[2] = sky.sun_min_variance() as f32;
        u.sun_radiance = rgb(sky.sun_radiance(), 0.0);
        u.sea_radiance = rgb(l.sea_radiance(), 0.0);
    }
    u
}
