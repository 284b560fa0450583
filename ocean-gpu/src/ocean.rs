//! The ocean renderer of Bruneton, Neyret & Holzschuch, "Real-time Realistic Ocean Lighting
//! using Seamless Transitions from Geometry to BRDF" (2010), §3.2, §5 and §7.1, on the GPU.
//!
//! A regular grid in screen space (cells of [`OceanOptions::cell_px`] pixels, overlapping the
//! viewport by [`OceanOptions::margin`] on every side) is projected on the sea at rest, displaced
//! by the trochoids weighted by `w_p` for the projected cell size `L` (Eq. 2) and projected back
//! (vertex stage). Each pixel then computes its own normal with `w_n` for its projected size `l`
//! (Eq. 3), the slope variance of the waves the normal cannot show (Eq. 4), and the Sun's, the
//! sky's and the sea's light of Algorithm 5.1 (Eq. 15, 26, 27, 28), tone-mapped (fragment
//! stage). Waves are sorted longest first and every sum stops at the first zero weight, so the
//! cost follows the number of resolved waves and distant views are cheaper (§7.1). A sky
//! background fills the rest of the screen.
//!
//! Local waves (§6, [`OceanRenderer::set_local_waves`]): wave trains modulated over a grid, such
//! as a wave train box scene's near a shore, join the same sums, each train filtered by the same
//! weights for the same footprints, so near and far water are one surface lit one way; the open
//! sea's own waves can be faded out over that grid (an amplitude factor per grid point). The
//! CPU twin is [`ocean_brdf::local`]. The projected grid evaluates the trains at each of its own
//! vertices, so the surface it draws approaches the wave train box scene's *continuous* surface
//! (`ocean_wtb::continuous`, the model between the scene's grid points) as its cells shrink,
//! not the scene grid's triangles (`ocean_wtb::drawn`); since it filters every train on its own
//! footprints, give it the scene's trains unfiltered (`Scene::set_train_filter(None)`).
//!
//! A caller's own water mesh (a wave train box scene evaluated on the CPU) can take the
//! projected grid's place: `mesh_vs`/`mesh_fs` light it the same way, with the surface's waves
//! filtered per pixel on top of it, into direct and ambient light that `compose_fs` combines
//! with an ambient obscurance ([`OceanRenderer::render_mesh_image`]; an engine runs the same
//! exported shaders with [`frame_uniform`]'s block, [`WaveTexels`] and
//! [`fresnel_table_texels`]).
//!
//! Every stage has a CPU twin in `ocean_brdf`: [`ocean_brdf::surface`] (rays, sea-plane hits,
//! footprints, Eq. 2–4; a fragment's whole surface is [`ocean_brdf::FilteredSurface::pixel`]
//! with the footprints `l` and `cell_px · l`), [`ocean_brdf::sea::pixel_color`] (Algorithm 5.1
//! with the masking-aware normal of §3.2, [`ocean_brdf::sea::visible_normal`]) and
//! [`ocean_brdf::tonemap`]. The probes ([`OceanRenderer::probe_surface`],
//! [`OceanRenderer::probe_sea_color`]) run the shaders' own functions on lists of inputs so the
//! parity tests compare what the GPU draws with them.
//!
//! Precision. The shaders work in a camera-relative frame: positions relative to the eye, rest
//! positions relative to its horizontal position `o`. The host forms the matrices of that frame
//! in `f64` and, per wave and frame, `θ₀ = k·o − ωt + Φ` reduced modulo 2π in `f64`, so the
//! shader's phase `k·(x − o) + θ₀` grows with the distance from the camera only, never with the
//! time or the distance from the world origin (ARCHITECTURE.md, "Precision far from the
//! origin"); and a wave enters a sum only where
//! its wavelength spans a footprint, which bounds `k·(x − o)`. The shader reduces the phase
//! modulo 2π again before its sine and cosine.
//!
//! Depth. Clip space is WebGPU's (`z ∈ [0, w]`); a camera with OpenGL's `[−1, 1]` range is
//! folded into it on the host (the depth buffer then holds `(z_ndc + 1)/2`), and a reversed-Z
//! camera keeps its direction (the depth test becomes `Greater`, the sky is drawn at depth 0).

use std::sync::{Mutex, MutexGuard, PoisonError};

use glam::{DMat4, DVec2, DVec3, DVec4};
use ocean_brdf::sky_map::{SKY_MAP_EXTENT, SKY_MAP_MAX_SIZE, SKY_MAP_MIN_SIZE};
use ocean_brdf::variance::{trochoid_slope_variance, wave_variance_term};
use ocean_brdf::{FilteredSurface, Lighting, LocalWaves, SeaLight, SlopeVariance};
use ocean_core::phase::reduce_angle;
use ocean_core::{Camera, DepthDirection, DepthRange, EvalError, Wave};

use crate::ocean_local::LocalTextures;

mod layers;
mod mesh;
use crate::readback::{GpuTimer, read_buffer_as, read_texture};
use crate::{GpuContext, GpuError, shaders};
pub use layers::ComposeInputs;
pub use mesh::MeshGeometry;

/// Invocations per workgroup of the probe entry points (`@workgroup_size(64)`).
const PROBE_WORKGROUP: u32 = 64;

/// Rows of the wave texture (see `ocean_common.wgsl`).
const WAVE_ROWS: u32 = 3;

/// How an [`OceanRenderer`] draws.
#[derive(Clone, Debug, PartialEq)]
pub struct OceanOptions {
    /// Format of the colour targets [`OceanRenderer::render`] draws into. For a non-sRGB format
    /// the shader writes sRGB-encoded values (display-ready bytes in `rgba8unorm`); for an sRGB
    /// format it writes linear values and the hardware encodes them. Either way the values are
    /// tone-mapped ([`ocean_brdf::tonemap::tone_map`]).
    pub color_format: wgpu::TextureFormat,
    /// Format of the depth targets, or `None` to draw without depth (the grid is then drawn far
    /// rows first, so nearer waves still cover farther ones).
    pub depth_format: Option<wgpu::TextureFormat>,
    /// Screen-space size of a projected-grid cell, pixels, in `[1, 256]` (the paper: 8).
    pub cell_px: f64,
    /// How far the grid extends beyond the viewport on every side, as a fraction of the
    /// viewport's width (left and right) and height (top and bottom), in `[0, 2]`: large waves
    /// displace the grid's edges inwards, and the margin keeps them off screen.
    pub margin: f64,
    /// Distance cap of the rays' sea-plane hits, metres, in `(0, 10⁷]`: rays above the horizon,
    /// or meeting the sea farther, stop there ([`ocean_brdf::surface::sea_plane_hit`]).
    pub max_distance: f64,
    /// Level-0 size of the sky map texture, a power of two in `[4, 4096]`.
    pub sky_map_size: u32,
    /// Exposure of the tone mapping, `1 − exp(−exposure · L)`, in `(0, 10⁶]`.
    pub exposure: f64,
    /// Whether [`OceanRenderer::render`] draws the sky background (the sky map's radiance
    /// towards each pixel and the Sun's disc) before the sea.
    pub draw_sky: bool,
}

impl Default for OceanOptions {
    /// `rgba8unorm` with a `depth32float` depth buffer, 8-pixel cells, a 10 % margin, a 50 km
    /// distance cap, a 512² sky map, [`ocean_brdf::tonemap::DEFAULT_EXPOSURE`], sky on.
    fn default() -> Self {
        Self {
            color_format: wgpu::TextureFormat::Rgba8Unorm,
            depth_format: Some(wgpu::TextureFormat::Depth32Float),
            cell_px: 8.0,
            margin: 0.1,
            max_distance: 50_000.0,
            sky_map_size: 512,
            exposure: ocean_brdf::tonemap::DEFAULT_EXPOSURE,
            draw_sky: true,
        }
    }
}

/// The shaders' uniform block, byte for byte the WGSL `Frame` of `ocean_common.wgsl` (352 bytes,
/// std140); the field documentation is there.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct FrameUniform {
    /// Camera-relative position → clip (WebGPU depth range).
    pub view_proj: [[f32; 4]; 4],
    /// Clip → camera-relative position.
    pub inv_view_proj: [[f32; 4]; 4],
    /// Eye height, distance cap, NDC depth of the near plane, NDC depth halfway to the far one.
    pub camera: [f32; 4],
    /// Viewport size (px), pixel position of grid vertex (0, 0).
    pub viewport: [f32; 4],
    /// Cell size (px), N_min, N_max, exposure.
    pub grid: [f32; 4],
    /// Grid vertices per row, grid rows, waves, flags (bit 0: sRGB-encode in the shader).
    pub counts: [u32; 4],
    /// Wind direction (x, z), Fresnel R, the Sun's solid angle.
    pub sea: [f32; 4],
    /// Unit vector towards the Sun, cos of its angular radius.
    pub sun_dir: [f32; 4],
    /// The Sun's radiance (rgb), NDC depth of the far plane.
    pub sun_radiance: [f32; 4],
    /// `L_sea` (rgb).
    pub sea_radiance: [f32; 4],
    /// Sky map size, its stereographic half-width, the Sun's least slope variance.
    pub sky: [f32; 4],
    /// Probe item count.
    pub probe: [u32; 4],
    /// Local waves: the local grid's point (0, 0) relative to o, 1 / its spacing.
    pub local: [f32; 4],
    /// Local grid points per row and rows, local trains.
    pub local_counts: [u32; 4],
    /// The caller's mesh (`mesh_vs`): its grid point (0, 0) at rest relative to the eye, its
    /// spacing.
    pub mesh_grid: [f32; 4],
    /// The mesh's grid points per row and rows.
    pub mesh_counts: [u32; 4],
}

/// What [`OceanRenderer::probe_surface`] reads back for one screen point: what the vertex stage
/// computes for a grid vertex there and what the fragment stage computes for a pixel centred
/// there (before interpolation). World coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceProbe {
    /// The rest position `(x, z)` the point's view ray meets ([`ocean_brdf::surface::sea_plane_hit`]).
    pub rest: DVec2,
    /// `L`, the grid-cell footprint: `cell_px` times the pixel footprint, metres.
    pub cell_footprint: f64,
    /// Eq. 2: the displaced position for `L`. Beyond the distance cap the vertex stage draws
    /// the point higher, on its pixel's ray (at most at the eye's height), so the sea reaches
    /// the horizon (`cap_lift` in `ocean.wgsl`); this is the position before that lift.
    pub position: DVec3,
    /// How many waves the vertex stage summed (those with `w_p > 0`).
    pub position_waves: u32,
    /// `l`, the pixel footprint ([`ocean_brdf::surface::pixel_footprint`]), metres.
    pub pixel_footprint: f64,
    /// Eq. 3: the unit normal at `rest` for `l`.
    pub normal: DVec3,
    /// Eq. 4: the slope variances of the waves `l` does not resolve.
    pub variance: SlopeVariance,
    /// How many waves the fragment stage summed (those with `w_n > 0`).
    pub normal_waves: u32,
    /// The fragment stage's geometry normal: Eq. 2's waves weighted by `w_p` for the grid-cell
    /// footprint `cell_px · l` at the pixel ([`ocean_brdf::PixelSurface::geometry_normal`]).
    pub geometry_normal: DVec3,
    /// The fragment stage's normal-only slope variances, weights `w_n − w_p` for `l` and
    /// `cell_px · l` ([`ocean_brdf::PixelSurface::normal_only`]).
    pub normal_only: SlopeVariance,
}

/// One input of [`OceanRenderer::probe_sea_color`]: what the fragment stages light, the
/// arguments of [`ocean_brdf::sea::sea_color_unchecked`] besides the lighting with the normal
/// made masking-aware first ([`ocean_brdf::sea::visible_normal`]), as
/// [`ocean_brdf::sea::pixel_color`] does.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SeaColorInput {
    /// Unit vector from the surface towards the viewer.
    pub v: DVec3,
    /// Unit filtered normal (a back-facing one is reflected, §3.2).
    pub n: DVec3,
    /// Horizontal wind direction `(x, z)`, any non-zero length.
    pub wind: DVec2,
    /// σ_x², σ_y² of the unresolved waves, ≥ 0.
    pub variance: SlopeVariance,
    /// Unit normal of the geometry (`n` itself, with `normal_only` zero, to light `n` as it is).
    pub geometry_normal: DVec3,
    /// σ_x², σ_y² of the waves in `n` and not in the geometry, ≥ 0.
    pub normal_only: SlopeVariance,
}

impl SeaColorInput {
    /// The input that lights the normal `n` as it is: geometry normal `n`, no normal-only
    /// slopes.
    pub fn plain(v: DVec3, n: DVec3, wind: DVec2, variance: SlopeVariance) -> Self {
        Self {
            v,
            n,
            wind,
            variance,
            geometry_normal: n,
            normal_only: SlopeVariance::default(),
        }
    }
}

/// The render pipelines of one depth configuration.
#[derive(Debug)]
struct DrawPipelines {
    key: Option<DepthDirection>,
    sky: wgpu::RenderPipeline,
    ocean: wgpu::RenderPipeline,
}

/// The probe pipelines, built on first use.
#[derive(Debug)]
struct ProbePipelines {
    layout: wgpu::BindGroupLayout,
    surface: wgpu::ComputePipeline,
    sea_color: wgpu::ComputePipeline,
}

/// The index buffer of the last grid size drawn.
#[derive(Debug)]
struct GridIndices {
    size: (u32, u32),
    count: u32,
    buffer: wgpu::Buffer,
}

/// The wave texture of a filtered surface (binding 1 of `ocean_common.wgsl`): one column per
/// wave, longest first, three rows of `rgba32float` texels.
///
/// Row 0 holds `(λ, k_x, k_z, θ₀)` with the phase `θ₀ = k·o − ωt + Φ` of the frame (`o` the
/// eye's horizontal position), reduced modulo 2π in `f64`; row 1 `(A, A k_x/|k|, A k_z/|k|, 0)`;
/// row 2 `(k·A, (k̂·wind)², S_x, S_y)`, `S` the slope variance (Eq. 4 with `w_r = 1`, Appendix
/// A) of the wave and every shorter one, summed in `f64`. Rows 1 and 2 are fixed; row 0
/// changes every frame ([`WaveTexels::phases`]).
#[derive(Clone, Debug, PartialEq)]
pub struct WaveTexels {
    waves: Vec<Wave>,
    /// Rows 0 to 2, row-major, row 0's phases 0.
    texels: Vec<[f32; 4]>,
    n_min: f64,
    n_max: f64,
    wind: DVec2,
}

impl WaveTexels {
    /// The texels of `surface`'s waves (sorted longest first, as [`FilteredSurface`] keeps
    /// them), with its filter thresholds and wind for the uniform block.
    pub fn new(surface: &FilteredSurface) -> Self {
        let waves = surface.wave_set().waves();
        let n = waves.len();
        let wind = surface.wind();
        let mut texels = vec![[0.0f32; 4]; n * WAVE_ROWS as usize];
        // The variance of wave i and every shorter one (they follow it), in f64.
        let mut suffix = DVec2::ZERO;
        for i in (0..n).rev() {
            let w = &waves[i];
            let k = w.wave_vector();
            let m = w.wavenumber();
            let a = w.amplitude();
            let (ka, cos2) = wave_variance_term(w, wind);
            let var = trochoid_slope_variance(ka);
            suffix += DVec2::new(var * cos2, var * (1.0 - cos2));
            texels[i] = [surface.wavelengths()[i] as f32, k.x as f32, k.y as f32, 0.0];
            texels[n + i] = [a as f32, (a * k.x / m) as f32, (a * k.y / m) as f32, 0.0];
            texels[2 * n + i] = [ka as f32, cos2 as f32, suffix.x as f32, suffix.y as f32];
        }
        Self {
            waves: waves.to_vec(),
            texels,
            n_min: surface.filter().n_min(),
            n_max: surface.filter().n_max(),
            wind,
        }
    }

    /// The number of waves: the texture's width.
    pub fn wave_count(&self) -> usize {
        self.waves.len()
    }

    /// Row 0 for a frame at `time` seen from an eye at horizontal position `o` (world x, z):
    /// `θ₀ = k·o − ωt + Φ` reduced modulo 2π in `f64` (ARCHITECTURE.md), so the shader's phase
    /// `k·(x − o) + θ₀` never holds a large number in `f32`.
    pub fn phases(&self, o: DVec2, time: f64) -> Vec<[f32; 4]> {
        self.waves
            .iter()
            .zip(&self.texels)
            .map(|(w, t)| [t[0], t[1], t[2], reduce_angle(w.phase_at(o, time)) as f32])
            .collect()
    }

    /// The whole texture for a frame at `time` seen by `camera`: the three rows, row-major,
    /// row 0 with [`phases`](Self::phases) at the eye's horizontal position.
    pub fn frame_texels(&self, camera: &Camera, time: f64) -> Vec<[f32; 4]> {
        let eye = camera.eye();
        let phases = self.phases(DVec2::new(eye.x, eye.z), time);
        let mut texels = self.texels.clone();
        texels[..phases.len()].copy_from_slice(&phases);
        texels
    }
}

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

/// The GPU ocean renderer: projected grid, filtered waves, Algorithm 5.1, sky.
///
/// Create it once per device, give it a surface ([`set_surface`](Self::set_surface)) and
/// lighting ([`set_lighting`](Self::set_lighting)), then [`render`](Self::render) each frame into
/// the caller's targets, or [`render_image`](Self::render_image) headless.
///
/// As with the other passes of this crate, a frame's inputs (the uniform block and the waves'
/// phases) are written with `Queue::write_*` into buffers the renderer keeps, and take effect at
/// the caller's next `Queue::submit`: submit between two `render` calls of one renderer.
#[derive(Debug)]
pub struct OceanRenderer {
    options: OceanOptions,
    layout: wgpu::BindGroupLayout,
    pipeline_layout: wgpu::PipelineLayout,
    module: wgpu::ShaderModule,
    pipelines: Mutex<Vec<DrawPipelines>>,
    /// The split-light sea pipelines, per depth direction ([`OceanRenderer::render_layers`]).
    layer_pipelines: Mutex<Vec<((DepthDirection, u32), wgpu::RenderPipeline)>>,
    /// The composition's pipeline and bind group layout, built on first use.
    /// The compose pipelines, by the light targets' sample count.
    compose: Mutex<Vec<(u32, layers::ComposePipeline)>>,
    probes: Mutex<Option<ProbePipelines>>,
    indices: Mutex<Option<GridIndices>>,
    uniform: wgpu::Buffer,
    sampler: wgpu::Sampler,
    sky_texture: wgpu::Texture,
    sky_view: wgpu::TextureView,
    wave_texture: wgpu::Texture,
    wave_view: wgpu::TextureView,
    /// The effective Fresnel table (binding 6; the view keeps its texture alive).
    fresnel_view: wgpu::TextureView,
    bind_group: wgpu::BindGroup,
    surface: Option<WaveTexels>,
    lighting: Option<Lighting>,
    /// The local waves (§6), empty until [`OceanRenderer::set_local_waves`].
    local: LocalTextures,
}

fn invalid(what: &'static str, reason: impl Into<String>) -> GpuError {
    GpuError::InvalidInput {
        what,
        reason: reason.into(),
    }
}

fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    // The guarded values are rebuilt from scratch when missing, never left half-written: a
    // panic elsewhere does not make them unusable.
    m.lock().unwrap_or_else(PoisonError::into_inner)
}

impl OceanOptions {
    /// Checks every field against its documented range and the device's limits.
    fn validate(&self, device: &wgpu::Device) -> Result<(), GpuError> {
        self.check()?;
        let size = self.sky_map_size;
        let max_dim = device.limits().max_texture_dimension_2d;
        if size > max_dim {
            return Err(invalid(
                "sky_map_size",
                format!("{size} exceeds the device's largest texture ({max_dim})"),
            ));
        }
        Ok(())
    }

    /// Checks every field against its documented range.
    fn check(&self) -> Result<(), GpuError> {
        let range = |what, v: f64, lo: f64, hi: f64, lo_open: bool| {
            let above = if lo_open { v > lo } else { v >= lo };
            if v.is_finite() && above && v <= hi {
                Ok(())
            } else {
                let open = if lo_open { "(" } else { "[" };
                Err(invalid(what, format!("{v} is outside {open}{lo}, {hi}]")))
            }
        };
        range("cell_px", self.cell_px, 1.0, 256.0, false)?;
        range("margin", self.margin, 0.0, 2.0, false)?;
        range("max_distance", self.max_distance, 0.0, 1e7, true)?;
        range("exposure", self.exposure, 0.0, 1e6, true)?;
        let size = self.sky_map_size;
        if !size.is_power_of_two() || !(SKY_MAP_MIN_SIZE..=SKY_MAP_MAX_SIZE).contains(&size) {
            return Err(invalid(
                "sky_map_size",
                format!(
                    "{size} must be a power of two in [{SKY_MAP_MIN_SIZE}, {SKY_MAP_MAX_SIZE}]"
                ),
            ));
        }
        if self.color_format.is_depth_stencil_format() {
            return Err(invalid(
                "color_format",
                format!("{:?} is a depth format", self.color_format),
            ));
        }
        if let Some(d) = self.depth_format
            && !d.has_depth_aspect()
        {
            return Err(invalid(
                "depth_format",
                format!("{d:?} has no depth aspect"),
            ));
        }
        Ok(())
    }
}

/// The depth remap from a camera's NDC depth to WebGPU's: `z' = (z + 1)/2` for OpenGL's
/// `[−1, 1]` range, the identity otherwise (as a matrix acting on clip coordinates, and on one
/// NDC value).
fn depth_remap(camera: &Camera) -> (DMat4, fn(f64) -> f64) {
    match camera.depth().range() {
        DepthRange::NegOneToOne => (
            DMat4::from_cols(
                DVec4::X,
                DVec4::Y,
                DVec4::new(0.0, 0.0, 0.5, 0.0),
                DVec4::new(0.0, 0.0, 0.5, 1.0),
            ),
            |z| 0.5 * z + 0.5,
        ),
        DepthRange::ZeroToOne => (DMat4::IDENTITY, |z| z),
    }
}

/// The grid's vertex counts (per row, rows) for a viewport.
fn grid_counts(options: &OceanOptions, width: u32, height: u32) -> Result<(u32, u32), GpuError> {
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

fn mat_f32(m: DMat4, what: &'static str) -> Result<[[f32; 4]; 4], GpuError> {
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

fn rgb(v: DVec3, w: f32) -> [f32; 4] {
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
    let (remap, to_wgpu) = depth_remap(camera);
    let view_proj = remap * camera.view_projection_f64() * DMat4::from_translation(eye);
    let inv_view_proj =
        DMat4::from_translation(-eye) * camera.inverse_view_projection_f64() * remap.inverse();
    let depth = camera.depth();
    let near = to_wgpu(depth.near_ndc());
    let far = to_wgpu(depth.far_ndc());
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
fn lighting_uniform(
    options: &OceanOptions,
    surface: &WaveTexels,
    lighting: Option<&Lighting>,
) -> FrameUniform {
    let mut u = FrameUniform {
        grid: [
            options.cell_px as f32,
            surface.n_min as f32,
            surface.n_max as f32,
            options.exposure as f32,
        ],
        counts: [
            0,
            0,
            surface.waves.len() as u32,
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
    u.sea[0] = surface.wind.x as f32;
    u.sea[1] = surface.wind.y as f32;
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

impl OceanRenderer {
    /// Compiles the shaders and creates the renderer's buffers, textures and sampler on
    /// `ctx`'s device. Nothing is drawn until a surface and lighting are set.
    ///
    /// # Errors
    ///
    /// [`GpuError::InvalidInput`] for an option outside its documented range;
    /// [`GpuError::Wgpu`] if the device refuses an object.
    pub fn new(ctx: &GpuContext, options: OceanOptions) -> Result<Self, GpuError> {
        let device = ctx.device();
        options.validate(device)?;
        let entry = shaders::get("ocean").ok_or_else(|| {
            GpuError::Shader(shaders::ShaderError::UnknownShader {
                name: "ocean".to_owned(),
                available: String::new(),
            })
        })?;
        crate::scoped(device, || {
            let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("ocean shader"),
                source: wgpu::ShaderSource::Wgsl(entry.source.into()),
            });
            let stages = wgpu::ShaderStages::VERTEX | wgpu::ShaderStages::FRAGMENT;
            let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("ocean bind group layout"),
                entries: &common_layout_entries(stages),
            });
            let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("ocean pipeline layout"),
                bind_group_layouts: &[Some(&layout)],
                immediate_size: 0,
            });
            let uniform = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("ocean frame uniform"),
                size: std::mem::size_of::<FrameUniform>() as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
                label: Some("ocean sky sampler"),
                address_mode_u: wgpu::AddressMode::ClampToEdge,
                address_mode_v: wgpu::AddressMode::ClampToEdge,
                address_mode_w: wgpu::AddressMode::ClampToEdge,
                mag_filter: wgpu::FilterMode::Linear,
                min_filter: wgpu::FilterMode::Linear,
                mipmap_filter: wgpu::MipmapFilterMode::Linear,
                ..Default::default()
            });
            let size = options.sky_map_size;
            let sky_texture = device.create_texture(&wgpu::TextureDescriptor {
                label: Some("ocean sky map"),
                size: wgpu::Extent3d {
                    width: size,
                    height: size,
                    depth_or_array_layers: 1,
                },
                mip_level_count: size.ilog2() + 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: wgpu::TextureFormat::Rgba16Float,
                usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
                view_formats: &[],
            });
            let sky_view = sky_texture.create_view(&wgpu::TextureViewDescriptor::default());
            // A placeholder until `set_surface`: one wave of zeros.
            let wave_texture = wave_texture(device, 1);
            let wave_view = wave_texture.create_view(&wgpu::TextureViewDescriptor::default());
            let fresnel_view =
                fresnel_table_texture(ctx).create_view(&wgpu::TextureViewDescriptor::default());
            let local = LocalTextures::empty(ctx);
            let bind_group = draw_bind_group(
                device,
                &layout,
                &uniform,
                &wave_view,
                &sky_view,
                &sampler,
                &fresnel_view,
                &local,
            );
            Ok(Self {
                options,
                layout,
                pipeline_layout,
                module,
                pipelines: Mutex::new(Vec::new()),
                layer_pipelines: Mutex::new(Vec::new()),
                compose: Mutex::new(Vec::new()),
                probes: Mutex::new(None),
                indices: Mutex::new(None),
                uniform,
                sampler,
                sky_texture,
                sky_view,
                wave_texture,
                wave_view,
                fresnel_view,
                bind_group,
                surface: None,
                lighting: None,
                local,
            })
        })
    }

    /// The options it was created with.
    pub fn options(&self) -> &OceanOptions {
        &self.options
    }

    /// Uploads the waves of `surface` (sorted longest first, as [`FilteredSurface`] keeps them)
    /// with what the shaders need: wavelength, wave vector, amplitude terms, steepness, the
    /// share of each wave's slope variance along the wind, and the variance of each wave and
    /// all shorter ones (Eq. 4, summed in `f64`); the filter thresholds and the wind go into the
    /// uniform block. The phases are formed per frame.
    ///
    /// # Errors
    ///
    /// [`GpuError::TooLarge`] for more waves than the device's largest 2D texture is wide;
    /// [`GpuError::Wgpu`] if the device refuses the texture.
    pub fn set_surface(
        &mut self,
        ctx: &GpuContext,
        surface: &FilteredSurface,
    ) -> Result<(), GpuError> {
        let device = ctx.device();
        let n = surface.wave_set().waves().len();
        let limit = device.limits().max_texture_dimension_2d;
        if n == 0 || n as u64 > u64::from(limit) {
            return Err(GpuError::TooLarge {
                what: "waves (one wave-texture column each)",
                needed: n as u64,
                limit: u64::from(limit),
            });
        }
        let waves = WaveTexels::new(surface);
        let (texture, view, bind_group) = crate::scoped(device, || {
            let texture = wave_texture(device, n as u32);
            let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
            write_waves(ctx, &texture, &waves.texels, n as u32, WAVE_ROWS);
            let bind_group = draw_bind_group(
                device,
                &self.layout,
                &self.uniform,
                &view,
                &self.sky_view,
                &self.sampler,
                &self.fresnel_view,
                &self.local,
            );
            Ok((texture, view, bind_group))
        })?;
        self.wave_texture = texture;
        self.wave_view = view;
        self.bind_group = bind_group;
        self.surface = Some(waves);
        Ok(())
    }

    /// Builds the sky map of `lighting` ([`Lighting::sky_map`] at
    /// [`OceanOptions::sky_map_size`], every mip level) and uploads it as `rgba16float` texels
    /// (the binary16 values the CPU map holds); keeps the Sun's and the sea's radiances for the
    /// uniform block.
    ///
    /// # Errors
    ///
    /// [`GpuError::Brdf`] if the sky cannot be mapped (a radiance beyond binary16's range);
    /// [`GpuError::Wgpu`] if the upload fails.
    pub fn set_lighting(&mut self, ctx: &GpuContext, lighting: &Lighting) -> Result<(), GpuError> {
        let map = lighting.sky_map(self.options.sky_map_size)?;
        crate::scoped(ctx.device(), || {
            for level in 0..map.level_count() {
                let texels = map.level(level).unwrap_or_default();
                let size = (map.size() >> level).max(1);
                let bytes: Vec<u8> = texels
                    .iter()
                    .flat_map(|t| t.iter().map(|&c| half::f16::from_f32(c).to_bits()))
                    .flat_map(u16::to_le_bytes)
                    .collect();
                ctx.queue().write_texture(
                    wgpu::TexelCopyTextureInfo {
                        texture: &self.sky_texture,
                        mip_level: level,
                        origin: wgpu::Origin3d::ZERO,
                        aspect: wgpu::TextureAspect::All,
                    },
                    &bytes,
                    wgpu::TexelCopyBufferLayout {
                        offset: 0,
                        bytes_per_row: Some(size * 8),
                        rows_per_image: Some(size),
                    },
                    wgpu::Extent3d {
                        width: size,
                        height: size,
                        depth_or_array_layers: 1,
                    },
                );
            }
            Ok(())
        })?;
        self.lighting = Some(*lighting);
        Ok(())
    }

    /// Sets the local waves drawn on the open sea (§6, [`ocean_brdf::local`]): wave trains
    /// modulated over a grid, such as a wave train box scene's (`ocean_wtb::Frame::layers`),
    /// each filtered like the open sea's waves into the geometry (w_p), the normals (w_n) and
    /// the slope variances (w_r), and the open sea's amplitude factor over that grid. `None`
    /// removes them. Set them again when the sets change (each frame, for boxes that move,
    /// grow or die); the trains' phases follow the frame's time by themselves.
    ///
    /// # Errors
    ///
    /// [`GpuError::NotConfigured`] before [`set_surface`](Self::set_surface);
    /// [`GpuError::InvalidInput`] if `local`'s wind is not the surface's (the variances must
    /// share one frame) or its filter differs; [`GpuError::TooLarge`] for a grid side or train
    /// count beyond the device's largest 2D texture or more sets than its array layers;
    /// [`GpuError::Wgpu`] if the device refuses a texture. The previous local waves stay on
    /// error.
    pub fn set_local_waves(
        &mut self,
        ctx: &GpuContext,
        local: Option<&LocalWaves>,
    ) -> Result<(), GpuError> {
        let surface = self.surface.as_ref().ok_or(GpuError::NotConfigured {
            what: "ocean surface",
            call: "OceanRenderer::set_surface",
        })?;
        let textures = match local {
            Some(l) => {
                if (l.wind() - surface.wind).length() > 1e-9 {
                    return Err(invalid(
                        "local waves",
                        format!(
                            "wind {:?} is not the surface's {:?}: both variances must be measured along one wind",
                            l.wind(),
                            surface.wind
                        ),
                    ));
                }
                let f = l.filter();
                if f.n_min() != surface.n_min || f.n_max() != surface.n_max {
                    return Err(invalid(
                        "local waves",
                        "their filter must be the surface's (the shader has one)",
                    ));
                }
                // The same shape as the last local waves (each frame of a scene): rewrite the
                // textures in place, with no new texture or bind group.
                if self.local.rewrite(ctx, l) {
                    return Ok(());
                }
                LocalTextures::new(ctx, l)?
            }
            None => LocalTextures::empty(ctx),
        };
        let bind_group = crate::scoped(ctx.device(), || {
            Ok(draw_bind_group(
                ctx.device(),
                &self.layout,
                &self.uniform,
                &self.wave_view,
                &self.sky_view,
                &self.sampler,
                &self.fresnel_view,
                &textures,
            ))
        })?;
        self.local = textures;
        self.bind_group = bind_group;
        Ok(())
    }

    /// The projected grid's vertex counts `(per row, rows)` for a `width × height` viewport:
    /// `ceil((1 + 2 margin) · extent / cell_px) + 1` each.
    ///
    /// # Errors
    ///
    /// [`GpuError::InvalidInput`] for an empty viewport; [`GpuError::TooLarge`] beyond 2³² − 1
    /// vertices.
    pub fn grid_size(&self, width: u32, height: u32) -> Result<(u32, u32), GpuError> {
        if width == 0 || height == 0 {
            return Err(invalid("viewport", format!("{width} x {height} is empty")));
        }
        grid_counts(&self.options, width, height)
    }

    /// Records the sky (if [`OceanOptions::draw_sky`]) and the sea seen by `camera` at `time`
    /// into `encoder`, drawing into the top-left `size` = `(width, height)` pixels of `color`
    /// (and `depth`, required exactly when [`OceanOptions::depth_format`] is set), whose
    /// contents are kept (load) and whose formats must be the options'. Depth is tested and
    /// written in the camera's direction (forward: `Less`; reversed: `Greater`).
    ///
    /// The frame's uniform block and phases are written through the queue (see the type's
    /// documentation); the caller submits `encoder`.
    ///
    /// # Errors
    ///
    /// [`GpuError::NotConfigured`] before [`set_surface`](Self::set_surface) and
    /// [`set_lighting`](Self::set_lighting); [`GpuError::InvalidInput`] for a non-finite time,
    /// an empty or oversized viewport, a camera not above the sea (`eye.y ≤ 0`), or targets that
    /// do not fit; [`GpuError::Wgpu`] for a device error. Nothing is recorded on error.
    #[allow(clippy::too_many_arguments)]
    pub fn render(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        camera: &Camera,
        time: f64,
        color: &wgpu::TextureView,
        depth: Option<&wgpu::TextureView>,
        size: (u32, u32),
    ) -> Result<(), GpuError> {
        self.record(ctx, encoder, camera, time, color, depth, size, None, None)
    }

    /// [`render`](Self::render) with the render pass timed by `timer` (its beginning and end
    /// timestamps, resolved into the timer after the pass; read them with
    /// [`GpuTimer::read`] once the encoder is submitted).
    ///
    /// # Errors
    ///
    /// As [`render`](Self::render).
    #[allow(clippy::too_many_arguments)]
    pub fn render_timed(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        camera: &Camera,
        time: f64,
        color: &wgpu::TextureView,
        depth: Option<&wgpu::TextureView>,
        size: (u32, u32),
        timer: &GpuTimer,
    ) -> Result<(), GpuError> {
        self.record(
            ctx,
            encoder,
            camera,
            time,
            color,
            depth,
            size,
            None,
            Some(timer),
        )?;
        timer.resolve(encoder);
        Ok(())
    }

    /// Renders the sea and the sky seen by `camera` at `time` into a new `width × height`
    /// image and reads it back: tightly packed RGBA8 rows from the top, sRGB-encoded.
    ///
    /// Needs an 8-bit RGBA or BGRA [`OceanOptions::color_format`] (sRGB or not); creates its
    /// own colour target (cleared to black) and, if [`OceanOptions::depth_format`] is set, its
    /// own depth target (cleared to the camera's far end). A one-off: it allocates per call and
    /// waits for the GPU.
    ///
    /// # Errors
    ///
    /// As [`render`](Self::render), and [`GpuError::InvalidInput`] for another colour format
    /// or a size beyond the device's largest texture.
    pub fn render_image(
        &self,
        ctx: &GpuContext,
        camera: &Camera,
        time: f64,
        width: u32,
        height: u32,
    ) -> Result<Vec<u8>, GpuError> {
        use wgpu::TextureFormat as F;
        let bgra = match self.options.color_format {
            F::Rgba8Unorm | F::Rgba8UnormSrgb => false,
            F::Bgra8Unorm | F::Bgra8UnormSrgb => true,
            other => {
                return Err(invalid(
                    "color_format",
                    format!("render_image reads back 8-bit RGBA or BGRA targets, not {other:?}"),
                ));
            }
        };
        self.check_viewport(ctx, width, height)?;
        // Everything that can fail on the inputs fails here, before anything is allocated.
        self.frame(camera, time, width, height, 0)?;
        self.lighting_set()?;
        let device = ctx.device();
        let extent = wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        };
        let (color, depth) = crate::scoped(device, || {
            let color = device.create_texture(&wgpu::TextureDescriptor {
                label: Some("ocean image"),
                size: extent,
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: self.options.color_format,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
                view_formats: &[],
            });
            let depth = self.options.depth_format.map(|format| {
                device.create_texture(&wgpu::TextureDescriptor {
                    label: Some("ocean image depth"),
                    size: extent,
                    mip_level_count: 1,
                    sample_count: 1,
                    dimension: wgpu::TextureDimension::D2,
                    format,
                    usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                    view_formats: &[],
                })
            });
            Ok((color, depth))
        })?;
        let color_view = color.create_view(&wgpu::TextureViewDescriptor::default());
        let depth_view = depth
            .as_ref()
            .map(|d| d.create_view(&wgpu::TextureViewDescriptor::default()));
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("ocean image"),
        });
        let (_, to_wgpu) = depth_remap(camera);
        let clear_depth = to_wgpu(camera.depth().clear_depth()) as f32;
        self.record(
            ctx,
            &mut encoder,
            camera,
            time,
            &color_view,
            depth_view.as_ref(),
            (width, height),
            Some(clear_depth),
            None,
        )?;
        crate::scoped(device, || {
            ctx.queue().submit([encoder.finish()]);
            Ok(())
        })?;
        let mut data = read_texture(ctx, &color, 0)?.data;
        if bgra {
            for px in data.chunks_exact_mut(4) {
                px.swap(0, 2);
            }
        }
        Ok(data)
    }

    fn lighting_set(&self) -> Result<(), GpuError> {
        match self.lighting {
            Some(_) => Ok(()),
            None => Err(GpuError::NotConfigured {
                what: "ocean lighting",
                call: "OceanRenderer::set_lighting",
            }),
        }
    }

    fn check_viewport(&self, ctx: &GpuContext, width: u32, height: u32) -> Result<(), GpuError> {
        let max = ctx.device().limits().max_texture_dimension_2d;
        if width == 0 || height == 0 || width > max || height > max {
            return Err(invalid(
                "viewport",
                format!("{width} x {height}: each side must be in [1, {max}]"),
            ));
        }
        Ok(())
    }

    /// The uniform block and the wave texture's phase row for one frame ([`frame_uniform`] with
    /// the renderer's options, surface, lighting and local waves). Also returns `o`, the eye's
    /// horizontal position.
    fn frame(
        &self,
        camera: &Camera,
        time: f64,
        width: u32,
        height: u32,
        probe_items: u32,
    ) -> Result<(FrameUniform, Vec<[f32; 4]>, DVec2), GpuError> {
        let surface = self.surface.as_ref().ok_or(GpuError::NotConfigured {
            what: "ocean surface",
            call: "OceanRenderer::set_surface",
        })?;
        let mut u = frame_uniform(
            &self.options,
            surface,
            self.lighting.as_ref(),
            camera,
            time,
            (width, height),
            None,
        )?;
        let eye = camera.eye();
        let o = DVec2::new(eye.x, eye.z);
        u.probe[0] = probe_items;
        (u.local, u.local_counts) = self.local.uniform(o);
        Ok((u, surface.phases(o, time), o))
    }

    /// Validates the targets against the options and the viewport.
    fn check_targets(
        &self,
        color: &wgpu::TextureView,
        depth: Option<&wgpu::TextureView>,
        size: (u32, u32),
    ) -> Result<(), GpuError> {
        let fits = |what, t, format| crate::pipeline::check_render_target(what, t, format, size);
        fits("colour target", color.texture(), self.options.color_format)?;
        match (self.options.depth_format, depth) {
            (Some(format), Some(d)) => fits("depth target", d.texture(), format),
            (None, None) => Ok(()),
            (Some(_), None) => Err(GpuError::InvalidResource {
                what: "depth target",
                reason: "the renderer was created with a depth format: pass a depth view"
                    .to_owned(),
            }),
            (None, Some(_)) => Err(GpuError::InvalidResource {
                what: "depth target",
                reason: "the renderer was created without a depth format".to_owned(),
            }),
        }
    }

    /// [`render`](Self::render), clearing the targets first when `clear_depth` is given (to
    /// black and to that depth).
    #[allow(clippy::too_many_arguments)]
    fn record(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        camera: &Camera,
        time: f64,
        color: &wgpu::TextureView,
        depth: Option<&wgpu::TextureView>,
        size: (u32, u32),
        clear_depth: Option<f32>,
        timer: Option<&GpuTimer>,
    ) -> Result<(), GpuError> {
        self.check_viewport(ctx, size.0, size.1)?;
        self.check_targets(color, depth, size)?;
        let (u, phases, o) = self.frame(camera, time, size.0, size.1, 0)?;
        let local_phases = self.local.phases(o, time);
        self.lighting_set()?;
        let device = ctx.device();
        let key = self
            .options
            .depth_format
            .map(|_| camera.depth().direction());
        let mut pipelines = lock(&self.pipelines);
        if !pipelines.iter().any(|p| p.key == key) {
            let p = crate::scoped(device, || Ok(self.draw_pipelines(device, key)))?;
            pipelines.push(p);
        }
        let Some(p) = pipelines.iter().find(|p| p.key == key) else {
            return Err(GpuError::Wgpu("ocean pipelines missing".to_owned()));
        };
        let (indices, index_count) = self.grid_index_buffer(ctx, &u)?;
        crate::scoped(device, || {
            self.write_frame(ctx, &u, &phases, &local_phases);
            let load_color = match clear_depth {
                Some(_) => wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                None => wgpu::LoadOp::Load,
            };
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("ocean"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: color,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: load_color,
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: depth.map(|view| {
                    wgpu::RenderPassDepthStencilAttachment {
                        view,
                        depth_ops: Some(wgpu::Operations {
                            load: match clear_depth {
                                Some(d) => wgpu::LoadOp::Clear(d),
                                None => wgpu::LoadOp::Load,
                            },
                            store: wgpu::StoreOp::Store,
                        }),
                        stencil_ops: None,
                    }
                }),
                timestamp_writes: timer.map(GpuTimer::render_pass_writes),
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_viewport(0.0, 0.0, size.0 as f32, size.1 as f32, 0.0, 1.0);
            pass.set_scissor_rect(0, 0, size.0, size.1);
            pass.set_bind_group(0, &self.bind_group, &[]);
            if self.options.draw_sky {
                pass.set_pipeline(&p.sky);
                pass.draw(0..3, 0..1);
            }
            pass.set_pipeline(&p.ocean);
            pass.set_index_buffer(indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..index_count, 0, 0..1);
            Ok(())
        })
    }

    /// The index buffer of the projected grid of frame `u` (built when the grid's size changes)
    /// and its index count.
    fn grid_index_buffer(
        &self,
        ctx: &GpuContext,
        u: &FrameUniform,
    ) -> Result<(wgpu::Buffer, u32), GpuError> {
        let (nx, ny) = (u.counts[0], u.counts[1]);
        let mut indices = lock(&self.indices);
        if indices.as_ref().is_none_or(|i| i.size != (nx, ny)) {
            *indices = Some(grid_indices(ctx, nx, ny)?);
        }
        match indices.as_ref() {
            Some(grid) => Ok((grid.buffer.clone(), grid.count)),
            None => Err(GpuError::Wgpu("ocean grid indices missing".to_owned())),
        }
    }

    /// Writes a frame's uniform block and phases (they take effect at the next submit).
    fn write_frame(
        &self,
        ctx: &GpuContext,
        u: &FrameUniform,
        phases: &[[f32; 4]],
        local_phases: &[[f32; 4]],
    ) {
        ctx.queue()
            .write_buffer(&self.uniform, 0, bytemuck::bytes_of(u));
        write_waves(ctx, &self.wave_texture, phases, phases.len() as u32, 1);
        self.local.write_phases(ctx, local_phases);
    }

    /// The sky and sea pipelines for a depth direction (`None`: no depth buffer).
    fn draw_pipelines(&self, device: &wgpu::Device, key: Option<DepthDirection>) -> DrawPipelines {
        let depth = |write: bool| {
            let format = self.options.depth_format?;
            let reversed = key == Some(DepthDirection::Reversed);
            // The sky lies on the far plane: it passes where nothing nearer was drawn and
            // writes no depth; the sea tests and writes.
            let compare = match (write, reversed) {
                (true, false) => wgpu::CompareFunction::Less,
                (true, true) => wgpu::CompareFunction::Greater,
                (false, false) => wgpu::CompareFunction::LessEqual,
                (false, true) => wgpu::CompareFunction::GreaterEqual,
            };
            Some(wgpu::DepthStencilState {
                format,
                depth_write_enabled: Some(write),
                depth_compare: Some(compare),
                stencil: wgpu::StencilState::default(),
                bias: wgpu::DepthBiasState::default(),
            })
        };
        let pipeline = |label, vs, fs, depth_stencil| {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(label),
                layout: Some(&self.pipeline_layout),
                vertex: wgpu::VertexState {
                    module: &self.module,
                    entry_point: Some(vs),
                    compilation_options: wgpu::PipelineCompilationOptions::default(),
                    buffers: &[],
                },
                primitive: wgpu::PrimitiveState {
                    topology: wgpu::PrimitiveTopology::TriangleList,
                    // Waves can turn cells over: no culling.
                    cull_mode: None,
                    ..Default::default()
                },
                depth_stencil,
                multisample: wgpu::MultisampleState::default(),
                fragment: Some(wgpu::FragmentState {
                    module: &self.module,
                    entry_point: Some(fs),
                    compilation_options: wgpu::PipelineCompilationOptions::default(),
                    targets: &[Some(self.options.color_format.into())],
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        DrawPipelines {
            key,
            sky: pipeline("ocean sky pipeline", "sky_vs", "sky_fs", depth(false)),
            ocean: pipeline("ocean sea pipeline", "ocean_vs", "ocean_fs", depth(true)),
        }
    }

    /// Runs the vertex stage's and the fragment stage's surface functions at each of `pixels`
    /// (pixel coordinates of a `width × height` viewport, origin at the top-left corner, y down,
    /// pixel centres at half-integers; points outside the viewport, like the grid's margin, are
    /// allowed) for `camera` at `time`, and reads the results back in world coordinates: the
    /// GPU side of the renderer's geometry parity with [`ocean_brdf::surface`].
    ///
    /// # Errors
    ///
    /// As [`render`](Self::render) for the camera, time and viewport (lighting is not needed);
    /// [`GpuError::InvalidInput`] for no pixels, a non-finite one, or more than 2²² of them.
    #[allow(clippy::too_many_arguments)]
    pub fn probe_surface(
        &self,
        ctx: &GpuContext,
        camera: &Camera,
        time: f64,
        width: u32,
        height: u32,
        pixels: &[DVec2],
    ) -> Result<Vec<SurfaceProbe>, GpuError> {
        self.check_viewport(ctx, width, height)?;
        let items = probe_items(pixels.len())?;
        if !pixels.iter().all(|p| p.is_finite()) {
            return Err(invalid("probe pixels", "every pixel must be finite"));
        }
        let (u, phases, o) = self.frame(camera, time, width, height, items)?;
        let inputs: Vec<[f32; 4]> = pixels
            .iter()
            .map(|p| [p.x as f32, p.y as f32, 0.0, 0.0])
            .collect();
        let local_phases = self.local.phases(o, time);
        let out = self.run_probe(
            ctx,
            &u,
            Some((&phases, &local_phases)),
            &inputs,
            5 * items,
            true,
        )?;
        let v3 = |c: [f32; 4]| DVec3::new(c[0].into(), c[1].into(), c[2].into());
        Ok(out
            .chunks_exact(5)
            .take(pixels.len())
            .map(|c| {
                let p = DVec3::new(c[0][0].into(), c[0][1].into(), c[0][2].into());
                SurfaceProbe {
                    rest: o + DVec2::new(c[1][0].into(), c[1][1].into()),
                    cell_footprint: c[1][2].into(),
                    position: p + DVec3::new(o.x, 0.0, o.y),
                    position_waves: c[0][3] as u32,
                    pixel_footprint: c[1][3].into(),
                    normal: DVec3::new(c[2][0].into(), c[2][1].into(), c[2][2].into()),
                    variance: SlopeVariance {
                        x: c[3][0].into(),
                        y: c[3][1].into(),
                    },
                    normal_waves: c[2][3] as u32,
                    geometry_normal: v3(c[4]),
                    normal_only: SlopeVariance {
                        x: c[3][2].into(),
                        y: c[3][3].into(),
                    },
                }
            })
            .collect())
    }

    /// Runs the fragment stage's Algorithm 5.1 on each input with the current lighting and its
    /// sky map, the normal made masking-aware first (`visible_normal`), and reads the three
    /// terms back: the GPU side of the lighting parity with
    /// [`ocean_brdf::sea::sea_color_unchecked`] of [`ocean_brdf::sea::visible_normal`]. Inputs
    /// are rounded to `f32`.
    ///
    /// # Errors
    ///
    /// [`GpuError::NotConfigured`] before [`set_lighting`](Self::set_lighting);
    /// [`GpuError::InvalidInput`] for no inputs, more than 2²² of them, a direction that is not
    /// a finite unit vector (within 10⁻⁴), a zero or non-finite wind, or a negative or
    /// non-finite variance.
    pub fn probe_sea_color(
        &self,
        ctx: &GpuContext,
        inputs: &[SeaColorInput],
    ) -> Result<Vec<SeaLight>, GpuError> {
        self.lighting_set()?;
        let items = probe_items(inputs.len())?;
        let unit = |d: DVec3| d.is_finite() && (d.length() - 1.0).abs() <= 1e-4;
        for (i, s) in inputs.iter().enumerate() {
            let variance =
                |v: SlopeVariance| v.x.is_finite() && v.y.is_finite() && v.x >= 0.0 && v.y >= 0.0;
            let ok = unit(s.v)
                && unit(s.n)
                && unit(s.geometry_normal)
                && s.wind.is_finite()
                && s.wind != DVec2::ZERO
                && variance(s.variance)
                && variance(s.normal_only);
            if !ok {
                return Err(invalid(
                    "sea colour input",
                    format!(
                        "input {i} ({s:?}): v and the normals must be unit vectors, the wind non-zero, the variances finite and >= 0"
                    ),
                ));
            }
        }
        // Lighting only: the surface fields of a default surface state are unused by the probe.
        let placeholder = WaveTexels {
            waves: Vec::new(),
            texels: Vec::new(),
            n_min: 1.0,
            n_max: 2.5,
            wind: DVec2::X,
        };
        let mut u = lighting_uniform(
            &self.options,
            self.surface.as_ref().unwrap_or(&placeholder),
            self.lighting.as_ref(),
        );
        u.probe[0] = items;
        let mut data = Vec::with_capacity(5 * inputs.len());
        for s in inputs {
            data.push(rgb(s.v, 0.0));
            data.push(rgb(s.n, 0.0));
            data.push([
                s.wind.x as f32,
                s.wind.y as f32,
                s.variance.x as f32,
                s.variance.y as f32,
            ]);
            data.push(rgb(s.geometry_normal, 0.0));
            data.push([s.normal_only.x as f32, s.normal_only.y as f32, 0.0, 0.0]);
        }
        let out = self.run_probe(ctx, &u, None, &data, 3 * items, false)?;
        let v = |c: [f32; 4]| DVec3::new(c[0].into(), c[1].into(), c[2].into());
        Ok(out
            .chunks_exact(3)
            .take(inputs.len())
            .map(|c| SeaLight {
                sun: v(c[0]),
                sky: v(c[1]),
                sea: v(c[2]),
            })
            .collect())
    }

    /// Dispatches a probe entry point (`surface`: `probe_surface`, else `probe_sea_color`) over
    /// `u.probe[0]` items with its own uniform, input and output buffers, and reads back
    /// `outputs` vec4s. `phases`, if given, is the wave texture's phase row for the frame (the
    /// probe then reads the surface's waves with these phases; otherwise the renderer's wave
    /// texture, which `probe_sea_color` does not read).
    fn run_probe(
        &self,
        ctx: &GpuContext,
        u: &FrameUniform,
        phases: Option<FramePhases<'_>>,
        inputs: &[[f32; 4]],
        outputs: u32,
        surface: bool,
    ) -> Result<Vec<[f32; 4]>, GpuError> {
        let device = ctx.device();
        let mut probes = lock(&self.probes);
        if probes.is_none() {
            *probes = Some(crate::scoped(device, || probe_pipelines(device))?);
        }
        let Some(p) = probes.as_ref() else {
            return Err(GpuError::Wgpu("ocean probe pipelines missing".to_owned()));
        };
        let out_size = u64::from(outputs) * 16;
        let limits = device.limits();
        let limit = limits
            .max_storage_buffer_binding_size
            .min(limits.max_buffer_size);
        if out_size > limit || inputs.len() as u64 * 16 > limit {
            return Err(GpuError::TooLarge {
                what: "probe buffers (bytes)",
                needed: out_size.max(inputs.len() as u64 * 16),
                limit,
            });
        }
        let output = crate::scoped(device, || {
            let buffer = |label, size: u64, usage| {
                device.create_buffer(&wgpu::BufferDescriptor {
                    label: Some(label),
                    size,
                    usage: usage | wgpu::BufferUsages::COPY_DST,
                    mapped_at_creation: false,
                })
            };
            let uniform = buffer(
                "ocean probe uniform",
                std::mem::size_of::<FrameUniform>() as u64,
                wgpu::BufferUsages::UNIFORM,
            );
            let input = buffer(
                "ocean probe inputs",
                inputs.len() as u64 * 16,
                wgpu::BufferUsages::STORAGE,
            );
            let output = buffer(
                "ocean probe outputs",
                out_size,
                wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            );
            let queue = ctx.queue();
            queue.write_buffer(&uniform, 0, bytemuck::bytes_of(u));
            queue.write_buffer(&input, 0, bytemuck::cast_slice(inputs));
            // The surface probe reads a wave texture of its own, so that probing never changes
            // the phases a `render` recorded but not yet submitted will see.
            let probe_local = phases.map(|(_, local)| self.local.view_with_phases(ctx, local));
            let probe_waves = match (phases, self.surface.as_ref()) {
                (Some((phases, _)), Some(surface)) => {
                    let n = phases.len();
                    let mut texels = surface.texels.clone();
                    texels[..n].copy_from_slice(phases);
                    let texture = wave_texture(device, n as u32);
                    write_waves(ctx, &texture, &texels, n as u32, WAVE_ROWS);
                    Some(texture.create_view(&wgpu::TextureViewDescriptor::default()))
                }
                _ => None,
            };
            let entry = |binding, resource| wgpu::BindGroupEntry { binding, resource };
            let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("ocean probe bind group"),
                layout: &p.layout,
                entries: &[
                    entry(0, uniform.as_entire_binding()),
                    entry(
                        1,
                        wgpu::BindingResource::TextureView(
                            probe_waves.as_ref().unwrap_or(&self.wave_view),
                        ),
                    ),
                    entry(2, wgpu::BindingResource::TextureView(&self.sky_view)),
                    entry(3, wgpu::BindingResource::Sampler(&self.sampler)),
                    entry(4, input.as_entire_binding()),
                    entry(5, output.as_entire_binding()),
                    entry(
                        FRESNEL_BINDING,
                        wgpu::BindingResource::TextureView(&self.fresnel_view),
                    ),
                    entry(
                        LOCAL_FIELDS_BINDING,
                        wgpu::BindingResource::TextureView(&self.local.fields_view),
                    ),
                    entry(
                        LOCAL_TRAINS_BINDING,
                        wgpu::BindingResource::TextureView(
                            probe_local.as_ref().unwrap_or(&self.local.trains_view),
                        ),
                    ),
                ],
            });
            let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("ocean probe"),
            });
            {
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some("ocean probe"),
                    timestamp_writes: None,
                });
                pass.set_pipeline(if surface { &p.surface } else { &p.sea_color });
                pass.set_bind_group(0, &group, &[]);
                pass.dispatch_workgroups(u.probe[0].div_ceil(PROBE_WORKGROUP), 1, 1);
            }
            queue.submit([encoder.finish()]);
            Ok(output)
        })?;
        read_buffer_as(ctx, &output)
    }
}

/// A frame's phase rows: the open sea's waves', and the local trains'.
type FramePhases<'a> = (&'a [[f32; 4]], &'a [[f32; 4]]);

/// The probe's item count as `u32`, at least 1 and at most 2²² (64 × 65536 workgroups).
fn probe_items(n: usize) -> Result<u32, GpuError> {
    const MAX: usize = 1 << 22;
    if n == 0 || n > MAX {
        return Err(invalid(
            "probe inputs",
            format!("{n} items; between 1 and {MAX} are accepted"),
        ));
    }
    Ok(n as u32)
}

/// Bindings 0–3 and 6–8 of `ocean_common.wgsl`, visible to `stages`.
fn common_layout_entries(stages: wgpu::ShaderStages) -> [wgpu::BindGroupLayoutEntry; 7] {
    let texture = |binding, filterable| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: stages,
        ty: wgpu::BindingType::Texture {
            sample_type: wgpu::TextureSampleType::Float { filterable },
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        },
        count: None,
    };
    [
        wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: stages,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: wgpu::BufferSize::new(std::mem::size_of::<FrameUniform>() as u64),
            },
            count: None,
        },
        texture(1, false),
        texture(2, true),
        wgpu::BindGroupLayoutEntry {
            binding: 3,
            visibility: stages,
            ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
            count: None,
        },
        texture(FRESNEL_BINDING, false),
        wgpu::BindGroupLayoutEntry {
            binding: LOCAL_FIELDS_BINDING,
            visibility: stages,
            ty: wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { filterable: false },
                view_dimension: wgpu::TextureViewDimension::D2Array,
                multisampled: false,
            },
            count: None,
        },
        texture(LOCAL_TRAINS_BINDING, false),
    ]
}

/// Binding of the effective Fresnel table (after the probes' 4 and 5).
const FRESNEL_BINDING: u32 = 6;
/// Bindings of the local waves' fields and trains.
const LOCAL_FIELDS_BINDING: u32 = 7;
const LOCAL_TRAINS_BINDING: u32 = 8;

/// The texels of the effective Fresnel table texture (binding 6 of `ocean_common.wgsl`, 33 × 33
/// `r32float`, row-major): texel `(j, i)`, element `33 i + j`, holds the roughness correction
/// `D(cos θ_v = (i/32)², σ_v = (j/32)²)` of [`ocean_brdf::fresnel_table`] (Eq. 24) rounded to
/// `f32`.
pub fn fresnel_table_texels() -> Vec<f32> {
    ocean_brdf::fresnel_table::FRESNEL_TABLE
        .iter()
        .map(|&m| m as f32)
        .collect()
}

/// The effective Fresnel table (`ocean_brdf::fresnel_table`) as a 33 × 33 `r32float` texture:
/// texel (j, i) holds the correction `D(cos θ_v = (i/32)², σ_v = (j/32)²)` to Schlick's value.
fn fresnel_table_texture(ctx: &GpuContext) -> wgpu::Texture {
    let n = ocean_brdf::fresnel_table::FRESNEL_TABLE_SIZE as u32;
    let texture = ctx.device().create_texture(&wgpu::TextureDescriptor {
        label: Some("ocean effective Fresnel table"),
        size: wgpu::Extent3d {
            width: n,
            height: n,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::R32Float,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    let texels = fresnel_table_texels();
    ctx.queue().write_texture(
        wgpu::TexelCopyTextureInfo {
            texture: &texture,
            mip_level: 0,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        bytemuck::cast_slice(&texels),
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(4 * n),
            rows_per_image: Some(n),
        },
        wgpu::Extent3d {
            width: n,
            height: n,
            depth_or_array_layers: 1,
        },
    );
    texture
}

#[allow(clippy::too_many_arguments)]
fn draw_bind_group(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    uniform: &wgpu::Buffer,
    waves: &wgpu::TextureView,
    sky: &wgpu::TextureView,
    sampler: &wgpu::Sampler,
    fresnel: &wgpu::TextureView,
    local: &LocalTextures,
) -> wgpu::BindGroup {
    let entry = |binding, resource| wgpu::BindGroupEntry { binding, resource };
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("ocean bind group"),
        layout,
        entries: &[
            entry(0, uniform.as_entire_binding()),
            entry(1, wgpu::BindingResource::TextureView(waves)),
            entry(2, wgpu::BindingResource::TextureView(sky)),
            entry(3, wgpu::BindingResource::Sampler(sampler)),
            entry(FRESNEL_BINDING, wgpu::BindingResource::TextureView(fresnel)),
            entry(
                LOCAL_FIELDS_BINDING,
                wgpu::BindingResource::TextureView(&local.fields_view),
            ),
            entry(
                LOCAL_TRAINS_BINDING,
                wgpu::BindingResource::TextureView(&local.trains_view),
            ),
        ],
    })
}

/// The wave texture for `n` waves: `n × 3` texels of `rgba32float`.
fn wave_texture(device: &wgpu::Device, n: u32) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: Some("ocean waves"),
        size: wgpu::Extent3d {
            width: n,
            height: WAVE_ROWS,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Rgba32Float,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    })
}

/// Writes the first `rows` rows of `n` texels each (`texels`, row-major) into the wave texture.
fn write_waves(ctx: &GpuContext, texture: &wgpu::Texture, texels: &[[f32; 4]], n: u32, rows: u32) {
    ctx.queue().write_texture(
        wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: 0,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        bytemuck::cast_slice(texels),
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(n * 16),
            rows_per_image: Some(rows),
        },
        wgpu::Extent3d {
            width: n,
            height: rows,
            depth_or_array_layers: 1,
        },
    );
}

/// The index buffer of an `nx × ny` grid: two triangles per cell, rows from the top of the
/// screen (the far sea) down, so that without a depth buffer nearer cells are drawn last.
fn grid_indices(ctx: &GpuContext, nx: u32, ny: u32) -> Result<GridIndices, GpuError> {
    let cells = u64::from(nx.saturating_sub(1)) * u64::from(ny.saturating_sub(1));
    let count = cells * 6;
    let bytes = count * 4;
    let device = ctx.device();
    let limit = device.limits().max_buffer_size;
    if count > u64::from(u32::MAX) || bytes > limit || count == 0 {
        return Err(GpuError::TooLarge {
            what: "projected grid index buffer (bytes)",
            needed: bytes,
            limit: limit.min(u64::from(u32::MAX)),
        });
    }
    let mut indices = Vec::with_capacity(count as usize);
    for j in 0..ny - 1 {
        for i in 0..nx - 1 {
            let a = j * nx + i;
            let c = a + nx;
            indices.extend_from_slice(&[a, c, a + 1, a + 1, c, c + 1]);
        }
    }
    crate::scoped(device, || {
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("ocean grid indices"),
            size: bytes,
            usage: wgpu::BufferUsages::INDEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        ctx.queue()
            .write_buffer(&buffer, 0, bytemuck::cast_slice(&indices));
        Ok(GridIndices {
            size: (nx, ny),
            count: count as u32,
            buffer,
        })
    })
}

fn probe_pipelines(device: &wgpu::Device) -> Result<ProbePipelines, GpuError> {
    let entry = shaders::get("ocean_probe").ok_or_else(|| {
        GpuError::Shader(shaders::ShaderError::UnknownShader {
            name: "ocean_probe".to_owned(),
            available: String::new(),
        })
    })?;
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("ocean probe shader"),
        source: wgpu::ShaderSource::Wgsl(entry.source.into()),
    });
    let stages = wgpu::ShaderStages::COMPUTE;
    let [e0, e1, e2, e3, e6, e7, e8] = common_layout_entries(stages);
    let storage = |binding, read_only| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: stages,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    };
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("ocean probe bind group layout"),
        entries: &[
            e0,
            e1,
            e2,
            e3,
            e6,
            e7,
            e8,
            storage(4, true),
            storage(5, false),
        ],
    });
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some("ocean probe pipeline layout"),
        bind_group_layouts: &[Some(&layout)],
        immediate_size: 0,
    });
    let pipeline = |name| {
        device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(name),
            layout: Some(&pipeline_layout),
            module: &module,
            entry_point: Some(name),
            compilation_options: wgpu::PipelineCompilationOptions::default(),
            cache: None,
        })
    };
    Ok(ProbePipelines {
        surface: pipeline("probe_surface"),
        sea_color: pipeline("probe_sea_color"),
        layout,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_uniform_matches_the_wgsl_struct() {
        // Two mat4x4 (128 bytes) and fourteen vec4 (224): 352 bytes, the WGSL `Frame`.
        assert_eq!(std::mem::size_of::<FrameUniform>(), 352);
        let b = shaders::get("ocean").unwrap().bindings().unwrap();
        assert_eq!(b[0].name, "frame");
        assert_eq!(b[0].size as usize, std::mem::size_of::<FrameUniform>());
        let offsets: Vec<(&str, u32)> = b[0]
            .members
            .iter()
            .map(|m| (m.name.as_str(), m.offset))
            .collect();
        assert_eq!(
            offsets,
            vec![
                ("view_proj", 0),
                ("inv_view_proj", 64),
                ("camera", 128),
                ("viewport", 144),
                ("grid", 160),
                ("counts", 176),
                ("sea", 192),
                ("sun_dir", 208),
                ("sun_radiance", 224),
                ("sea_radiance", 240),
                ("sky", 256),
                ("probe", 272),
                ("local", 288),
                ("local_counts", 304),
                ("mesh_grid", 320),
                ("mesh_counts", 336),
            ]
        );
        // The probe module declares the same block.
        let p = shaders::get("ocean_probe").unwrap().bindings().unwrap();
        assert_eq!(p[0].members, b[0].members);
    }

    #[test]
    fn grid_covers_the_viewport_and_its_margin() {
        let o = OceanOptions::default();
        // 96 px at 8 px cells with 10 % on each side: 115.2 px → 15 cells → 16 vertices.
        assert_eq!(grid_counts(&o, 96, 64).unwrap(), (16, 11));
        let no_margin = OceanOptions {
            margin: 0.0,
            ..OceanOptions::default()
        };
        // Exactly 12 cells of 8 px span 96 px: 13 vertices, the last on the right edge.
        assert_eq!(grid_counts(&no_margin, 96, 64).unwrap(), (13, 9));
        let huge = OceanOptions {
            cell_px: 1.0,
            margin: 2.0,
            ..OceanOptions::default()
        };
        assert!(matches!(
            grid_counts(&huge, u32::MAX, u32::MAX),
            Err(GpuError::TooLarge { .. })
        ));
    }

    #[test]
    fn opengl_depth_folds_into_webgpu_clip_space() {
        use ocean_core::{DepthConvention, Far, Projection};
        let projection = Projection::Perspective {
            fov_y: 1.0,
            aspect: 1.5,
            near: 0.5,
            far: Far::Finite(1000.0),
        };
        let gl = Camera::look_at(
            DVec3::new(0.0, 4.0, 0.0),
            DVec3::new(0.0, 3.0, -10.0),
            DVec3::Y,
            projection,
            DepthConvention::NEG_ONE_TO_ONE,
        )
        .unwrap();
        let wgpu_cam = Camera::look_at(
            DVec3::new(0.0, 4.0, 0.0),
            DVec3::new(0.0, 3.0, -10.0),
            DVec3::Y,
            projection,
            DepthConvention::ZERO_TO_ONE,
        )
        .unwrap();
        // Folding [−1, 1] into [0, 1] gives the [0, 1] camera's matrix.
        let (remap, to_wgpu) = depth_remap(&gl);
        let folded = remap * gl.view_projection_f64();
        let direct = wgpu_cam.view_projection_f64();
        assert!(folded.abs_diff_eq(direct, 1e-12), "{folded} vs {direct}");
        assert_eq!(to_wgpu(-1.0), 0.0);
        assert_eq!(to_wgpu(0.0), 0.5);
        assert_eq!(to_wgpu(1.0), 1.0);
    }

    fn test_surface() -> FilteredSurface {
        let spectrum =
            ocean_brdf::Spectrum::new(ocean_brdf::SpectrumParams::default()).expect("spectrum");
        FilteredSurface::new(&spectrum, ocean_brdf::Filter::PAPER).expect("surface")
    }

    /// An OpenGL camera 3 m above the sea, 100 km and 40 km from the origin, looking ahead and
    /// down.
    fn far_camera() -> Camera {
        use ocean_core::{DepthConvention, Far, Projection};
        let eye = DVec3::new(1.0e5 + 2.0, 3.0, -4.0e4);
        Camera::look_at(
            eye,
            eye + DVec3::new(0.0, -1.0, -10.0),
            DVec3::Y,
            Projection::Perspective {
                fov_y: 1.0,
                aspect: 1.5,
                near: 0.1,
                far: Far::Finite(1000.0),
            },
            DepthConvention::NEG_ONE_TO_ONE,
        )
        .unwrap()
    }

    #[test]
    fn the_mesh_origin_is_stored_relative_to_the_eye() {
        let waves = WaveTexels::new(&test_surface());
        let camera = far_camera();
        let mesh = MeshGrid {
            origin: DVec2::new(1.0e5 - 10.0, -4.0e4 - 20.0),
            spacing: 0.5,
            nx: 129,
            nz: 65,
        };
        let options = OceanOptions::default();
        let with =
            frame_uniform(&options, &waves, None, &camera, 7.0, (96, 64), Some(&mesh)).unwrap();
        // (1e5 − 10, 0, −4e4 − 20) − (1e5 + 2, 3, −4e4), formed in f64: exact in f32.
        assert_eq!(with.mesh_grid, [-12.0, -3.0, -20.0, 0.5]);
        assert_eq!(with.mesh_counts, [129, 65, 0, 0]);
        // Everything else is the renderer's block: the projected grid of a 96 x 64 viewport
        // (16 x 11 vertices, as `grid_covers_the_viewport_and_its_margin`), the spectrum's
        // waves, sRGB encoding for rgba8unorm, no lighting, no local waves.
        let without = frame_uniform(&options, &waves, None, &camera, 7.0, (96, 64), None).unwrap();
        assert_eq!(
            FrameUniform {
                mesh_grid: [0.0; 4],
                mesh_counts: [0; 4],
                ..with
            },
            without
        );
        assert_eq!(without.counts, [16, 11, waves.wave_count() as u32, 1]);
        assert_eq!(without.camera[0], 3.0);
        // No Sun without a lighting; w is the far plane's depth, OpenGL's 1 folded into
        // WebGPU's range (still 1).
        assert_eq!(without.sun_radiance, [0.0, 0.0, 0.0, 1.0]);
    }

    #[test]
    fn frame_uniform_refuses_bad_input() {
        let waves = WaveTexels::new(&test_surface());
        let camera = far_camera();
        let options = OceanOptions::default();
        let mesh = MeshGrid {
            origin: DVec2::ZERO,
            spacing: 1.0,
            nx: 2,
            nz: 2,
        };
        let call = |o: &OceanOptions, time: f64, size, m: &MeshGrid| {
            frame_uniform(o, &waves, None, &camera, time, size, Some(m))
        };
        assert!(call(&options, 0.0, (8, 8), &mesh).is_ok());
        assert!(matches!(
            call(&options, f64::NAN, (8, 8), &mesh),
            Err(GpuError::Eval(_))
        ));
        assert!(matches!(
            call(&options, 0.0, (0, 8), &mesh),
            Err(GpuError::InvalidInput {
                what: "viewport",
                ..
            })
        ));
        let bad_options = OceanOptions {
            exposure: 0.0,
            ..OceanOptions::default()
        };
        assert!(matches!(
            call(&bad_options, 0.0, (8, 8), &mesh),
            Err(GpuError::InvalidInput {
                what: "exposure",
                ..
            })
        ));
        for m in [
            MeshGrid {
                spacing: 0.0,
                ..mesh
            },
            MeshGrid {
                spacing: f64::INFINITY,
                ..mesh
            },
            MeshGrid { nx: 0, ..mesh },
            MeshGrid {
                origin: DVec2::new(f64::NAN, 0.0),
                ..mesh
            },
            MeshGrid {
                origin: DVec2::new(1e300, 0.0),
                ..mesh
            },
        ] {
            assert!(
                matches!(
                    call(&options, 0.0, (8, 8), &m),
                    Err(GpuError::InvalidInput { what: "mesh", .. })
                ),
                "{m:?}"
            );
        }
    }

    #[test]
    fn wave_texels_form_each_frames_phases_in_f64() {
        let surface = test_surface();
        let waves = WaveTexels::new(&surface);
        let n = waves.wave_count();
        assert_eq!(n, surface.wave_set().waves().len());
        let camera = far_camera();
        let time = 1.0e6;
        let texels = waves.frame_texels(&camera, time);
        assert_eq!(texels.len(), 3 * n);
        // Rows 1 and 2 are the fixed ones; row 0 keeps (λ, k) and gains θ₀ at o.
        assert_eq!(texels[n..], waves.texels[n..]);
        let o = DVec2::new(1.0e5 + 2.0, -4.0e4);
        for (i, w) in surface.wave_set().waves().iter().enumerate() {
            assert_eq!(texels[i][..3], waves.texels[i][..3]);
            // k·o − ωt + Φ reaches about 10⁸ rad here; reduced in f64 it lies in [−π, π] and
            // equals the unreduced phase modulo 2π.
            let theta = f64::from(texels[i][3]);
            assert!(theta.abs() <= std::f64::consts::PI + 1e-6, "{theta}");
            let d = (w.phase_at(o, time) - theta) / std::f64::consts::TAU;
            assert!((d - d.round()).abs() < 1e-6, "wave {i}: {d}");
        }
    }
}
