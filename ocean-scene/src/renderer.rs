//! The scene renderer: everything a scene's frames are drawn with, built once from a
//! [`SceneDescription`], and the frames it draws.

use std::time::Instant;

use ocean_brdf::{Filter, FilteredSurface, Lighting, Spectrum};
use ocean_core::Camera;
use ocean_gpu::{ContextOptions, GpuContext, OceanOptions, OceanRenderer, wgpu};

use crate::RockMesh;
use crate::SceneError;
use crate::description::{Preset, SceneDescription};
use crate::face_light::FaceLight;
use crate::frame::{Dressing, FrameImage, PASSES, draw_frame, draw_passes};
use crate::island::Island;
use crate::obscurance::Obscurance;
use crate::relief_draws::{RockDraw, rock_draws};
use crate::solids::SolidRenderer;
pub use crate::targets::COLOR_FORMAT;
use crate::targets::Targets;
use crate::terrain::TerrainRenderer;

/// Which graphics backend [`SceneRenderer::new`] opens its own headless device on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Backend {
    /// `WGPU_BACKEND` if set, else every backend compiled in (Vulkan first).
    #[default]
    Auto,
    /// Vulkan (Mesa's lavapipe on a machine without a GPU).
    Vulkan,
    /// OpenGL through EGL (Mesa's llvmpipe on a machine without a GPU).
    Gl,
}

/// How a [`SceneRenderer`] is built.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RenderOptions {
    /// The camera preset every frame is seen from; `None`: the scene's `[camera]`.
    pub preset: Option<Preset>,
    /// Samples per pixel, 1 or `ocean_gpu::MSAA_SAMPLES`; `None`: the scene's
    /// `[render] samples`. Where the device cannot draw multisampled light targets (wgpu's GL
    /// backend) the renderer draws one ([`SceneRenderer::single_only`]).
    pub samples: Option<u32>,
    /// Whether frames may read their depth back ([`SceneRenderer::frame`] with `read_depth`):
    /// refused on OpenGL, which cannot copy depth textures to memory.
    pub read_depth: bool,
}

/// Seconds spent building a [`SceneRenderer`], by stage.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BuildTimes {
    /// Opening the device (zero for a caller's context).
    pub device: f64,
    /// Spectrum, filtering, sky map and their upload.
    pub setup: f64,
    /// Terrain, wave train boxes, terrain mesh upload.
    pub island: f64,
    /// The rocks' and the pier's relief textures (cone maps generated or read from the cache).
    pub rocks: f64,
}

/// Seconds one frame spent, by stage.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FrameTimes {
    /// Marching the wave train boxes on the CPU and uploading them as local waves.
    pub waves: f64,
    /// Each pass's wall time, in [`PASSES`] order.
    pub passes: [f64; PASSES.len()],
    /// From the end of `waves` to the end of the readback.
    pub total: f64,
}

/// One frame read back.
#[derive(Clone, Debug)]
pub struct Frame {
    /// Display colour: RGBA8, sRGB-encoded, tone-mapped, rows from the top, tightly packed;
    /// alpha is 255.
    pub rgba: Vec<u8>,
    /// The single-sampled window depth in `[0, 1]` (rows from the top; 1 on the far plane),
    /// when asked for.
    pub depth: Option<Vec<f32>>,
    /// The camera it was seen from.
    pub camera: Camera,
    /// What it took.
    pub times: FrameTimes,
}

/// Everything a scene's frames are drawn with, built once: the device, the renderers and
/// their textures, the island's wave trains and the targets. Frames are drawn at the
/// description's `[render]` size.
pub struct SceneRenderer {
    ctx: GpuContext,
    scene: SceneDescription,
    preset: Option<Preset>,
    read_depth: bool,
    renderer: OceanRenderer,
    surface: FilteredSurface,
    lighting: Lighting,
    island: Option<Island>,
    terrain: Option<TerrainRenderer>,
    face_light: FaceLight,
    rocks: Vec<RockDraw>,
    solids: Option<SolidRenderer>,
    targets: Targets,
    obscurance: Obscurance,
    /// Samples per pixel drawn (1 where multisampling is not available).
    samples: u32,
    /// Whether the scene asked for more samples than the backend draws.
    single_only: bool,
    build_times: BuildTimes,
}

impl SceneRenderer {
    /// Builds the renderer of `scene` on a headless device of its own on `backend`.
    ///
    /// # Errors
    ///
    /// [`SceneError::Gpu`] when no device opens; otherwise as [`SceneRenderer::with_context`].
    pub fn new(
        scene: &SceneDescription,
        backend: Backend,
        options: RenderOptions,
    ) -> Result<Self, SceneError> {
        let t = Instant::now();
        let ctx = GpuContext::headless_with(&ContextOptions {
            backends: match backend {
                Backend::Auto => None,
                Backend::Vulkan => Some(wgpu::Backends::VULKAN),
                Backend::Gl => Some(wgpu::Backends::GL),
            },
            ..ContextOptions::default()
        })?;
        let device = t.elapsed().as_secs_f64();
        let mut renderer = Self::with_context(ctx, scene, options)?;
        renderer.build_times.device = device;
        Ok(renderer)
    }

    /// Builds the renderer of `scene` on `ctx` (a caller's device and queue: the renderer
    /// creates its own pipelines and targets on it).
    ///
    /// # Errors
    ///
    /// [`SceneError::Description`] for a description that fails its checks or a piece that
    /// cannot be built from it, [`SceneError::Unsupported`] for `read_depth` on OpenGL,
    /// [`SceneError::Gpu`] for a device error.
    pub fn with_context(
        ctx: GpuContext,
        scene: &SceneDescription,
        options: RenderOptions,
    ) -> Result<Self, SceneError> {
        let mut times = BuildTimes::default();
        let (width, height) = (scene.render.width, scene.render.height);
        if options.read_depth && ctx.adapter_info().map(|i| i.backend) == Some(wgpu::Backend::Gl) {
            return Err(SceneError::Unsupported(format!(
                "{} cannot copy a depth texture to memory (wgpu's \
                 DEPTH_TEXTURE_AND_BUFFER_COPIES, absent on OpenGL)",
                ctx.describe()
            )));
        }
        let samples = options.samples.unwrap_or(scene.render.samples);
        let mut checked = scene.clone();
        checked.render.samples = samples;
        checked.check_overrides()?;
        // Where multisampled targets are lost (wgpu's GL backend), one sample per pixel, said in
        // `single_only`.
        let single_only = samples > 1 && !ctx.supports_multisampled_light();
        let samples = if single_only { 1 } else { samples };

        let t = Instant::now();
        let spectrum = Spectrum::new(scene.spectrum()).map_err(|e| format!("spectrum: {e}"))?;
        let surface =
            FilteredSurface::new(&spectrum, Filter::PAPER).map_err(|e| format!("spectrum: {e}"))?;
        let lighting = scene.lighting()?;
        let ocean_options = OceanOptions {
            color_format: COLOR_FORMAT,
            ..OceanOptions::default()
        };
        let mut renderer = OceanRenderer::new(&ctx, ocean_options)?;
        renderer.set_surface(&ctx, &surface)?;
        renderer.set_lighting(&ctx, &lighting)?;
        ctx.wait_idle()?;
        times.setup = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let rock_meshes = scene
            .rocks
            .iter()
            .map(|r| r.mesh(scene.island.as_ref()))
            .collect::<Result<Vec<_>, _>>()?;
        let island = match &scene.island {
            Some(section) => {
                let meshes: Vec<&RockMesh> = rock_meshes.iter().map(|(_, m)| m).collect();
                Some(Island::new(section, &scene.boxes, &meshes)?)
            }
            None => None,
        };
        let terrain = match &island {
            Some(i) => Some(TerrainRenderer::new(
                &ctx,
                &i.heights,
                (i.grid.nx(), i.grid.nz()),
                i.grid.origin(),
                i.grid.spacing(),
                samples,
            )?),
            None => None,
        };
        times.island = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let face_light = FaceLight::new(&lighting);
        let rocks = rock_draws(&ctx, scene, &rock_meshes, face_light)?;
        let solids = match &scene.pier {
            Some(pier) => Some(SolidRenderer::new(&ctx, &pier.posts(), samples)?),
            None => None,
        };
        times.rocks = t.elapsed().as_secs_f64();
        let targets = Targets::new(&ctx, width, height, samples)?;
        let obscurance = Obscurance::new(
            &ctx,
            &scene.obscurance,
            &scene.camera(options.preset, scene.render.time, width, height)?,
            (width, height),
        )?;

        Ok(Self {
            ctx,
            scene: scene.clone(),
            preset: options.preset,
            read_depth: options.read_depth,
            renderer,
            surface,
            lighting,
            island,
            terrain,
            face_light,
            rocks,
            solids,
            targets,
            obscurance,
            samples,
            single_only,
            build_times: times,
        })
    }

    /// Draws the frame at scene `time` (seconds) and reads it back, its depth too with
    /// `read_depth` (the renderer must have been built with [`RenderOptions::read_depth`]).
    ///
    /// # Errors
    ///
    /// [`SceneError::Description`] for a time at which the camera or the wave trains cannot be
    /// evaluated, [`SceneError::Unsupported`] for `read_depth` without the option,
    /// [`SceneError::Gpu`] for a device error.
    pub fn frame(&mut self, time: f64, read_depth: bool) -> Result<Frame, SceneError> {
        if read_depth && !self.read_depth {
            return Err(SceneError::Unsupported(
                "this renderer was built without RenderOptions::read_depth".to_owned(),
            ));
        }
        let (camera, times, image) = self.draw(time, None, read_depth)?;
        let FrameImage { rgba, depth } = image.expect("drawn into the renderer's own targets");
        Ok(Frame {
            rgba,
            depth,
            camera,
            times,
        })
    }

    /// Draws the frame at scene `time` (seconds) into `target`, a view of the caller's texture
    /// on the renderer's device (built [`with_context`](Self::with_context) on the caller's
    /// device): 2D, [`COLOR_FORMAT`] (tone-mapped, sRGB-encoded bytes), `RENDER_ATTACHMENT`,
    /// single-sampled and at least [`size`](Self::size): the frame fills its top-left corner
    /// and the rest is cleared to black. The frame is submitted and finished when this returns;
    /// nothing is read back. Returns the camera it was seen from and what it took (the readback
    /// slot stays zero).
    ///
    /// # Errors
    ///
    /// As [`frame`](Self::frame); [`SceneError::Gpu`] (`GpuError::InvalidResource`) for a
    /// target of another format, smaller than the frame, or not a render attachment.
    pub fn render_into(
        &mut self,
        time: f64,
        target: &wgpu::TextureView,
    ) -> Result<(Camera, FrameTimes), SceneError> {
        let (camera, times, _) = self.draw(time, Some(target), false)?;
        Ok((camera, times))
    }

    /// The frame at `time`: composed into `target`, or with `None` into the renderer's own
    /// targets and read back (with the depth when `read_depth`).
    fn draw(
        &mut self,
        time: f64,
        target: Option<&wgpu::TextureView>,
        read_depth: bool,
    ) -> Result<(Camera, FrameTimes, Option<FrameImage>), SceneError> {
        let mut times = FrameTimes::default();
        let (camera, t) = self.prepare(time, &mut times)?;
        let mut dressing = Dressing {
            terrain: self.terrain.as_ref(),
            obscurance: &mut self.obscurance,
            lighting: &self.lighting,
            sky: &self.face_light.sky,
            rocks: &self.rocks,
            solids: self.solids.as_ref(),
        };
        let (ctx, ocean, targets) = (&self.ctx, &self.renderer, &self.targets);
        let image = match target {
            Some(out) => {
                draw_passes(
                    ctx,
                    ocean,
                    &mut dressing,
                    &camera,
                    time,
                    targets,
                    out,
                    &mut times.passes,
                )?;
                None
            }
            None => Some(draw_frame(
                ctx,
                ocean,
                &mut dressing,
                &camera,
                time,
                targets,
                read_depth,
                &mut times.passes,
            )?),
        };
        times.total = t.elapsed().as_secs_f64();
        Ok((camera, times, image))
    }

    /// The frame's camera, and its wave trains marched to `time` and uploaded as local waves
    /// (timed in `times.waves`); returns when the drawing may start.
    fn prepare(
        &mut self,
        time: f64,
        times: &mut FrameTimes,
    ) -> Result<(Camera, Instant), SceneError> {
        let (width, height) = self.size();
        let camera = self.scene.camera(self.preset, time, width, height)?;
        let t = Instant::now();
        if let Some(island) = self.island.as_mut() {
            let local = island.local_waves(&self.surface, time)?;
            self.renderer.set_local_waves(&self.ctx, Some(&local))?;
        }
        times.waves = t.elapsed().as_secs_f64();
        Ok((camera, Instant::now()))
    }

    /// The frames' size in pixels: the description's `[render]` width and height.
    pub fn size(&self) -> (u32, u32) {
        (self.scene.render.width, self.scene.render.height)
    }

    /// Samples per pixel drawn (1 where multisampling is not available).
    pub fn samples(&self) -> u32 {
        self.samples
    }

    /// Whether the description asked for more samples per pixel than the device draws.
    pub fn single_only(&self) -> bool {
        self.single_only
    }

    /// The description the renderer was built from.
    pub fn description(&self) -> &SceneDescription {
        &self.scene
    }

    /// The device's name, driver and backend.
    pub fn describe(&self) -> String {
        self.ctx.describe()
    }

    /// How many open-sea waves the spectrum holds.
    pub fn wave_count(&self) -> usize {
        self.surface.wave_set().waves().len()
    }

    /// What building took.
    pub fn build_times(&self) -> BuildTimes {
        self.build_times
    }

    /// The relief textures (one per rock height map, one for the pier) and, over all their
    /// levels, how many cone maps were generated and how many came from the cache.
    pub fn relief_textures(&self) -> (usize, usize, usize) {
        let generated = self.rocks.iter().map(|r| r.cones.0).sum();
        let cached = self.rocks.iter().map(|r| r.cones.1).sum();
        (self.rocks.len(), generated, cached)
    }

    /// Whether each pass of [`PASSES`] has something to draw in this scene.
    pub fn drawn_passes(&self) -> [bool; PASSES.len()] {
        let mut drawn = [true; PASSES.len()];
        drawn[2] = self.terrain.is_some();
        drawn[3] = !self.rocks.is_empty() || self.solids.is_some();
        drawn[4] = self.obscurance.enabled();
        drawn
    }
}

/// The built-in scene's (or `scene`'s) first frame at its `[render]` size, one sample per
/// pixel, on the Vulkan backend: its camera and its window depth, rows from the top, what the
/// obscurance pass reads.
///
/// # Errors
///
/// As [`SceneRenderer::new`], where no Vulkan adapter exists or the scene fails.
pub fn scene_depth(scene: &SceneDescription) -> Result<(Camera, Vec<f32>), SceneError> {
    let options = RenderOptions {
        preset: None,
        samples: Some(1),
        read_depth: true,
    };
    let mut renderer = SceneRenderer::new(scene, Backend::Vulkan, options)?;
    let frame = renderer.frame(scene.render.time, true)?;
    let depth = frame
        .depth
        .ok_or_else(|| SceneError::Unsupported("the frame's depth was not read back".into()))?;
    Ok((frame.camera, depth))
}
