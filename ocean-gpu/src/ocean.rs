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
//! origin"); and a wave enters a sum only where its wavelength spans a footprint, which bounds
//! `k·(x − o)`. The shader reduces the phase
//! modulo 2π again before its sine and cosine.
//!
//! Depth. Clip space is WebGPU's (`z ∈ [0, w]`); a camera with OpenGL's `[−1, 1]` range is
//! folded into it on the host (the depth buffer then holds `(z_ndc + 1)/2`), and a reversed-Z
//! camera keeps its direction (the depth test becomes `Greater`, the sky is drawn at depth 0).

use std::sync::{Mutex, MutexGuard, PoisonError};

use glam::{DMat4, DVec2, DVec3};
use ocean_brdf::sky_map::{SKY_MAP_EXTENT, SKY_MAP_MAX_SIZE, SKY_MAP_MIN_SIZE};
use ocean_brdf::{FilteredSurface, Lighting, LocalWaves, SeaLight, SlopeVariance};
use ocean_core::{Camera, DepthDirection, EvalError};

use crate::ocean_local::LocalTextures;

mod layers;
mod mesh;
mod probe;
mod render;
mod resources;
mod uniform;
use crate::readback::{GpuTimer, read_buffer_as, read_texture};
use crate::{GpuContext, GpuError, shaders};
pub use layers::ComposeInputs;
pub use mesh::MeshGeometry;
use probe::ProbePipelines;
pub use probe::{SeaColorInput, SurfaceProbe};
pub use resources::fresnel_table_texels;
use resources::*;
pub use uniform::{FrameUniform, MeshGrid, WaveTexels, frame_uniform};
use uniform::{WAVE_ROWS, grid_counts, lighting_uniform, rgb};

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

/// The render pipelines of one depth configuration.
#[derive(Debug)]
struct DrawPipelines {
    key: Option<DepthDirection>,
    sky: wgpu::RenderPipeline,
    ocean: wgpu::RenderPipeline,
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
            write_waves(ctx, &texture, waves.texels(), n as u32, WAVE_ROWS);
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
                if (l.wind() - surface.wind()).length() > 1e-9 {
                    return Err(invalid(
                        "local waves",
                        format!(
                            "wind {:?} is not the surface's {:?}: both variances must be measured along one wind",
                            l.wind(),
                            surface.wind()
                        ),
                    ));
                }
                let f = l.filter();
                if f.n_min() != surface.n_min() || f.n_max() != surface.n_max() {
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
}

/// A frame's phase rows: the open sea's waves', and the local trains'.
type FramePhases<'a> = (&'a [[f32; 4]], &'a [[f32; 4]]);

#[cfg(test)]
mod tests;
