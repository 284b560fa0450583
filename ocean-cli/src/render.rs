//! `ocean render`: a headless render of a scene file into PNG images.
//!
//! What it draws: the open sea to the horizon and the sky, lit by the geometry-to-BRDF model
//! (Bruneton, Neyret & Holzschuch 2010: Sun, sky and refracted light, Algorithm 5.1) on the
//! projected grid of `ocean_gpu::OceanRenderer`, with the scene file's spectrum, Sun, sky and
//! camera ([`crate::scene`]); the island's terrain ([`crate::terrain`]) and the wave trains of
//! its wave train boxes, drawn on the same sea as local waves ([`crate::island`]); the scene's
//! rock faces, relief-mapped by relaxed cone stepping (`ocean_gpu::ReliefRenderer`, cone maps
//! generated at start-up and cached on disk, [`crate::cone_cache`]), self-shadowed by the Sun
//! and writing the depth of their relief; and the ambient obscurance of the whole depth buffer
//! (`ocean_gpu::OceanRenderer::compose`).
//!
//! Every PNG is written to a temporary file and renamed when complete, the output directory is
//! checked before anything is rendered, and an interruption (Ctrl-C, SIGTERM, SIGHUP) stops the
//! sequence between frames, so only complete images are ever left.

use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::{Args, ValueEnum};
use glam::DVec3;
use ocean_brdf::{Filter, FilteredSurface, Irradiance, Lighting, Spectrum};
use ocean_core::Camera;
use ocean_gpu::{
    ComposeInputs, ContextOptions, DepthResolve, GpuContext, LightTargets, OceanOptions,
    OceanRenderer, RADIANCE_FORMAT, ReliefOptions, ReliefRenderer, ReliefScene,
};
use ocean_relief::{ConeParams, Edge, ReliefMips, ReliefTexture};
use ocean_scene::RockMesh;

use crate::cone_cache;
use crate::island::Island;
use crate::obscurance::Obscurance;
use crate::png::write_atomically;
use crate::scene::{DEFAULT_SCENE, Preset, SceneFile};
use crate::solids::SolidRenderer;
use crate::terrain::TerrainRenderer;

/// Most frames one run renders.
const MAX_FRAMES: u32 = 100_000;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Backend {
    /// `WGPU_BACKEND` if set, else every backend compiled in (Vulkan first).
    Auto,
    /// Vulkan (Mesa's lavapipe on a machine without a GPU).
    Vulkan,
    /// OpenGL through EGL (Mesa's llvmpipe on a machine without a GPU).
    Gl,
}

#[derive(Args, Debug)]
pub struct RenderArgs {
    /// Scene file (TOML, see `ocean-cli/scenes/default.toml`); the built-in scene by default.
    #[arg(long)]
    scene: Option<PathBuf>,
    /// Image width in pixels (overrides the scene's).
    #[arg(long)]
    width: Option<u32>,
    /// Image height in pixels (overrides the scene's).
    #[arg(long)]
    height: Option<u32>,
    /// Scene time of the first frame, seconds (overrides the scene's).
    #[arg(long)]
    time: Option<f64>,
    /// Number of frames, 1/fps seconds of scene time apart. With more than one, OUT's name
    /// gets a four-digit frame number before its extension (ocean.png: ocean-0000.png, ...).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=i64::from(MAX_FRAMES)))]
    frames: u32,
    /// Samples per pixel, 1 or 4 (overrides the scene's; 4 antialiases the edges).
    #[arg(long)]
    samples: Option<u32>,
    /// Camera preset (overrides the scene's).
    #[arg(long, value_enum)]
    camera: Option<Preset>,
    /// Graphics backend.
    #[arg(long, value_enum, default_value_t = Backend::Auto)]
    backend: Backend,
    /// Output PNG.
    #[arg(long, default_value = "ocean.png")]
    out: PathBuf,
    /// Also write each frame's depth as a 16-bit grayscale PNG (numbered as OUT is): the window
    /// depth d in [0, 1] (WebGPU's forward range; 1 on the far plane, the sky) times 65535,
    /// rounded. The depth the obscurance reads: with 4 samples, each pixel's nearest.
    #[arg(long)]
    depth_out: Option<PathBuf>,
    /// No progress bar.
    #[arg(long)]
    quiet: bool,
}

/// The file of frame `k` of `frames` for the output `out`.
pub fn frame_path(out: &Path, k: u32, frames: u32) -> PathBuf {
    if frames == 1 {
        return out.to_path_buf();
    }
    let stem = out
        .file_stem()
        .map_or_else(|| "frame".into(), |s| s.to_string_lossy().into_owned());
    let name = match out.extension() {
        Some(ext) => format!("{stem}-{k:04}.{}", ext.to_string_lossy()),
        None => format!("{stem}-{k:04}"),
    };
    out.with_file_name(name)
}

/// Fails unless a file can be created in `out`'s directory (checked by creating and removing
/// one), so a run never renders for minutes and then cannot write.
fn check_writable(out: &Path) -> Result<(), String> {
    if out.file_name().is_none() {
        return Err(format!("--out {} does not name a file", out.display()));
    }
    let dir = match out.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let probe = dir.join(format!(".ocean-render-probe-{}", std::process::id()));
    std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&probe)
        .map_err(|e| {
            format!(
                "cannot write into {} (for --out {}): {e}",
                dir.display(),
                out.display()
            )
        })?;
    let _ = std::fs::remove_file(&probe);
    Ok(())
}

/// Relief-mapped faces (of rocks, or of the pier's blocks) that share one relief texture: their
/// renderer and their faces.
struct RockDraw {
    renderer: ReliefRenderer,
    faces: Vec<ReliefScene>,
    /// How many of its levels' cone maps were generated and how many came from the cache.
    cones: (usize, usize),
}

/// The lighting of relief faces in the sea's radiance units (a Lambertian face's radiance is
/// albedo × E/π): the Sun's direction and its irradiance over π, and the environment's
/// irradiance on every orientation (`ocean_brdf::Irradiance`: the sky above the horizon, the
/// sea below it), in linear RGB, as the terrain is lit.
#[derive(Clone, Copy, Debug)]
pub struct FaceLight {
    pub sun_dir: DVec3,
    pub sun: DVec3,
    pub sky: Irradiance,
}

impl FaceLight {
    /// A Sun from above and in front, and a sky brighter towards the zenith: the light of the
    /// unit tests.
    #[cfg(test)]
    pub fn for_tests() -> Self {
        Self {
            sun_dir: DVec3::new(0.3, 0.8, -0.5),
            sun: DVec3::new(0.3, 0.25, 0.2),
            sky: Irradiance::from_radiance(|d| DVec3::splat(0.1 * d.y.max(0.0))),
        }
    }

    pub fn new(lighting: &Lighting) -> Self {
        let sky = lighting.sky();
        Self {
            sun_dir: sky.sun_direction(),
            sun: sky.sun_radiance() * sky.sun_solid_angle() / std::f64::consts::PI,
            sky: Irradiance::new(lighting),
        }
    }
}

/// Builds the relief texture of `heights` (an `n × n` map, wrapping) with its mip levels down to
/// 8 × 8 (`ocean_relief::lod`: each level's 2 × 2-mean map with its own relaxed cones, from the
/// cache on disk when there), so distant faces trace a coarser surface, and a renderer holding
/// it. A side that is not a power of two gets level 0 alone. Also returns how many levels' cones
/// were generated and how many came from the cache.
fn relief_renderer(
    ctx: &GpuContext,
    n: usize,
    heights: &[f32],
) -> Result<(ReliefRenderer, (usize, usize)), String> {
    let relief_error = |e: ocean_relief::ReliefError| format!("relief: {e}");
    let params = ConeParams::relaxed(4.0);
    let map = ocean_relief::maps::to_map(n, heights, Edge::Wrap).map_err(relief_error)?;
    let maps = if n.is_power_of_two() && n > 8 {
        // log₂ n − 2 levels: n down to 8.
        let levels = ocean_relief::lod::max_levels(n) - 2;
        ocean_relief::lod::level_maps(&map, levels).map_err(relief_error)?
    } else {
        vec![map]
    };
    let (mut generated, mut cached) = (0, 0);
    let mut levels = Vec::with_capacity(maps.len());
    for map in &maps {
        let (cones, source) = cone_cache::cones(map, params).map_err(relief_error)?;
        match source {
            cone_cache::Source::Cached => cached += 1,
            cone_cache::Source::Generated => generated += 1,
        }
        levels.push(ReliefTexture::new(map, &cones).map_err(relief_error)?);
    }
    let mips = ReliefMips::from_levels(levels).map_err(relief_error)?;
    let mut renderer =
        ReliefRenderer::new(ctx, ReliefOptions::default()).map_err(|e| e.to_string())?;
    renderer.set_mips(ctx, &mips).map_err(|e| e.to_string())?;
    Ok((renderer, (generated, cached)))
}

/// The rocks and the pier of `scene`: their relief textures and faces; `rocks` holds each
/// rock's centre and mesh ([`crate::rocks::Rock::mesh`]), in the scene's order.
fn rock_draws(
    ctx: &GpuContext,
    scene: &SceneFile,
    rocks: &[(DVec3, RockMesh)],
    light: FaceLight,
) -> Result<Vec<RockDraw>, String> {
    let mut draws = Vec::new();
    // Rocks with the same height map share one texture and one renderer, in the order of
    // their first rock.
    let mut maps: Vec<(usize, u64)> = Vec::new();
    for rock in &scene.rocks {
        if !maps.contains(&(rock.map_size, rock.map_seed)) {
            maps.push((rock.map_size, rock.map_seed));
        }
    }
    for (n, seed) in maps {
        let heights = ocean_relief::maps::value_noise(n, (n / 32).max(2), 5, seed);
        let (renderer, cones) = relief_renderer(ctx, n, &heights)?;
        let mut faces = Vec::new();
        for (rock, (centre, mesh)) in scene.rocks.iter().zip(rocks) {
            if (rock.map_size, rock.map_seed) == (n, seed) {
                faces.extend(rock.faces(*centre, mesh, light)?);
            }
        }
        draws.push(RockDraw {
            renderer,
            faces,
            cones,
        });
    }
    if let Some(pier) = &scene.pier {
        let (renderer, cones) = relief_renderer(ctx, pier.map_size, &pier.plank_heights())?;
        draws.push(RockDraw {
            renderer,
            faces: pier.deck().faces(light)?,
            cones,
        });
    }
    Ok(draws)
}

/// The targets of the frames: split light and depth (what every renderer draws into, with
/// `samples` samples per pixel), the single-sampled depth the obscurance reads (the resolve of
/// a multisampled depth) and the composed display colour (what is read back).
struct Targets {
    direct: ocean_gpu::wgpu::TextureView,
    ambient: ocean_gpu::wgpu::TextureView,
    depth: ocean_gpu::wgpu::Texture,
    depth_view: ocean_gpu::wgpu::TextureView,
    /// With multisampled targets, the resolve pass and the depth it writes.
    resolved: Option<(
        DepthResolve,
        ocean_gpu::wgpu::Texture,
        ocean_gpu::wgpu::TextureView,
    )>,
    color: ocean_gpu::wgpu::Texture,
    color_view: ocean_gpu::wgpu::TextureView,
}

impl Targets {
    fn new(ctx: &GpuContext, width: u32, height: u32, samples: u32) -> Result<Self, String> {
        use ocean_gpu::wgpu;
        let texture = |label, format, usage, sample_count| {
            ctx.device().create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d {
                    width,
                    height,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let drawn_and_read =
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING;
        let view = |t: &wgpu::Texture| t.create_view(&wgpu::TextureViewDescriptor::default());
        let direct = texture(
            "ocean render direct",
            RADIANCE_FORMAT,
            drawn_and_read,
            samples,
        );
        let ambient = texture(
            "ocean render ambient",
            RADIANCE_FORMAT,
            drawn_and_read,
            samples,
        );
        let depth_format = wgpu::TextureFormat::Depth32Float;
        // Copied too when the single-sampled depth is written out.
        let copied = drawn_and_read | wgpu::TextureUsages::COPY_SRC;
        let depth = if samples > 1 {
            texture("ocean render depth", depth_format, drawn_and_read, samples)
        } else {
            texture("ocean render depth", depth_format, copied, 1)
        };
        let resolved = if samples > 1 {
            let pass = DepthResolve::new(ctx, depth_format).map_err(|e| e.to_string())?;
            let t = texture("ocean render resolved depth", depth_format, copied, 1);
            let v = view(&t);
            Some((pass, t, v))
        } else {
            None
        };
        let color = texture(
            "ocean render colour",
            OceanOptions::default().color_format,
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            1,
        );
        Ok(Self {
            direct: view(&direct),
            ambient: view(&ambient),
            depth_view: view(&depth),
            color_view: view(&color),
            depth,
            resolved,
            color,
        })
    }

    /// The single-sampled depth: the resolved one with multisampled targets.
    fn single_depth(&self) -> &ocean_gpu::wgpu::Texture {
        self.resolved.as_ref().map_or(&self.depth, |(_, t, _)| t)
    }

    fn light(&self) -> LightTargets<'_> {
        LightTargets {
            direct: &self.direct,
            ambient: &self.ambient,
            depth: &self.depth_view,
        }
    }
}

/// What one frame draws besides the sea.
struct Dressing<'a> {
    terrain: Option<&'a TerrainRenderer>,
    obscurance: &'a mut Obscurance,
    lighting: &'a Lighting,
    /// The environment's irradiance on every orientation, once per run.
    sky: &'a Irradiance,
    rocks: &'a [RockDraw],
    solids: Option<&'a SolidRenderer>,
}

/// The passes of a frame, in order, for the timing summary.
const PASSES: [(&str, &str); 7] = [
    ("clear", "the split light and depth targets"),
    (
        "sea",
        "projected grid, filtered waves and local waves, Algorithm 5.1 split",
    ),
    ("island", "terrain"),
    (
        "rocks, pier",
        "relief mapping by relaxed cone stepping, self-shadowed; posts",
    ),
    (
        "obscurance",
        "SAO: depth resolve at 4 samples, z, MIP levels, samples, two blurs",
    ),
    (
        "compose",
        "direct + A x ambient, sky, tone mapping, sample average",
    ),
    ("readback", "copy to the CPU"),
];

/// One frame read back: RGBA8 rows from the top, and the single-sampled window depth when
/// asked for.
struct FrameImage {
    rgba: Vec<u8>,
    depth: Option<Vec<f32>>,
}

/// Draws one frame (the sea, the island, the rocks, their obscurance and the composition) and
/// reads it back (the depth too with `read_depth`). Each pass is submitted and waited for
/// alone, and its wall time added to `times` (in `PASSES` order): the figures are then per pass
/// on every backend, timestamp queries or not.
#[allow(clippy::too_many_arguments)]
fn draw_frame(
    ctx: &GpuContext,
    ocean: &OceanRenderer,
    dressing: &mut Dressing<'_>,
    camera: &Camera,
    time: f64,
    t: &Targets,
    read_depth: bool,
    times: &mut [f64; PASSES.len()],
) -> Result<FrameImage, ocean_gpu::GpuError> {
    use ocean_gpu::wgpu;
    let size = (t.color.width(), t.color.height());
    let encoder = || {
        ctx.device()
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("ocean render"),
            })
    };
    let submit = |encoder: wgpu::CommandEncoder, slot: &mut f64, started: Instant| {
        ctx.queue().submit([encoder.finish()]);
        ctx.wait_idle()?;
        *slot += started.elapsed().as_secs_f64();
        Ok::<_, ocean_gpu::GpuError>(())
    };
    let light = t.light();

    let started = Instant::now();
    let mut e = encoder();
    let clear = |view| {
        Some(wgpu::RenderPassColorAttachment {
            view,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations {
                load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                store: wgpu::StoreOp::Store,
            },
        })
    };
    // Every renderer loads the targets: clear them first (depth to the far plane, 1 in
    // WebGPU's forward range, which the scene's cameras use; alpha 0 marks the sky).
    e.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("ocean render clear"),
        color_attachments: &[clear(&t.direct), clear(&t.ambient)],
        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
            view: &t.depth_view,
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
    submit(e, &mut times[0], started)?;

    let started = Instant::now();
    let mut e = encoder();
    ocean.render_layers(ctx, &mut e, camera, time, &light, size)?;
    submit(e, &mut times[1], started)?;

    if let Some(terrain) = dressing.terrain {
        let started = Instant::now();
        let mut e = encoder();
        terrain.draw(ctx, &mut e, camera, dressing.lighting, dressing.sky, &light);
        submit(e, &mut times[2], started)?;
    }

    if !dressing.rocks.is_empty() || dressing.solids.is_some() {
        let started = Instant::now();
        let mut e = encoder();
        let eye = camera.eye();
        for rock in dressing.rocks {
            // Only the faces whose front the eye sees: the shader would discard the others
            // after rasterising them.
            let faces: Vec<ReliefScene> = rock
                .faces
                .iter()
                .filter(|f| (eye - f.origin).dot(f.edge_u.cross(f.edge_v)) > 0.0)
                .cloned()
                .collect();
            rock.renderer
                .render_layers(ctx, &mut e, camera, &faces, &light, size)?;
        }
        if let Some(solids) = dressing.solids {
            solids.draw(ctx, &mut e, camera, dressing.lighting, dressing.sky, &light);
        }
        submit(e, &mut times[3], started)?;
    }

    let started = Instant::now();
    let mut e = encoder();
    if let Some((pass, _, view)) = &t.resolved {
        pass.encode(ctx, &mut e, &t.depth_view, view, camera.depth().direction())?;
    }
    let obscurance = dressing.obscurance.encode(ctx, &mut e, t.single_depth())?;
    submit(e, &mut times[4], started)?;

    let started = Instant::now();
    let mut e = encoder();
    let inputs = ComposeInputs {
        direct: &t.direct,
        ambient: &t.ambient,
        obscurance,
    };
    ocean.compose(ctx, &mut e, &inputs, &t.color_view, size)?;
    submit(e, &mut times[5], started)?;

    let started = Instant::now();
    let rgba = ocean_gpu::readback::read_texture(ctx, &t.color, 0)?.data;
    let depth = if read_depth {
        let bytes = ocean_gpu::readback::read_texture(ctx, t.single_depth(), 0)?.data;
        Some(bytemuck::pod_collect_to_vec(&bytes))
    } else {
        None
    };
    times[6] += started.elapsed().as_secs_f64();
    Ok(FrameImage { rgba, depth })
}

/// Everything a scene's frames are drawn with, built once: the device, the renderers and
/// their textures, the island's wave trains and the targets.
pub struct Session {
    ctx: GpuContext,
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
    width: u32,
    height: u32,
}

impl Session {
    /// Builds the session of `scene` at its `[render]` size with `samples` per pixel on
    /// `backend`; with `read_depth` the frames can read their depth back (refused on GL).
    /// Stage times go to `times`.
    ///
    /// # Errors
    ///
    /// A message for a device, scene or renderer that fails.
    fn build(
        scene: &SceneFile,
        backend: Backend,
        preset: Option<Preset>,
        samples: u32,
        read_depth: bool,
        times: &mut Times,
    ) -> Result<Self, String> {
        let (width, height) = (scene.render.width, scene.render.height);
        let t = Instant::now();
        let ctx = GpuContext::headless_with(&ContextOptions {
            backends: match backend {
                Backend::Auto => None,
                Backend::Vulkan => Some(ocean_gpu::wgpu::Backends::VULKAN),
                Backend::Gl => Some(ocean_gpu::wgpu::Backends::GL),
            },
            ..ContextOptions::default()
        })
        .map_err(|e| e.to_string())?;
        if read_depth && ctx.adapter_info().map(|i| i.backend) == Some(ocean_gpu::wgpu::Backend::Gl)
        {
            return Err(format!(
                "--depth-out: {} cannot copy a depth texture to memory (wgpu's \
                 DEPTH_TEXTURE_AND_BUFFER_COPIES, absent on OpenGL); try --backend vulkan",
                ctx.describe()
            ));
        }
        // Where multisampled targets are lost (wgpu's GL backend), one sample per pixel, said in
        // the summary.
        let single_only = samples > 1 && !ctx.supports_multisampled_light();
        let samples = if single_only { 1 } else { samples };
        times.device = t.elapsed().as_secs_f64();

        let t = Instant::now();
        let spectrum = Spectrum::new(scene.spectrum()).map_err(|e| format!("spectrum: {e}"))?;
        let surface =
            FilteredSurface::new(&spectrum, Filter::PAPER).map_err(|e| format!("spectrum: {e}"))?;
        let lighting = scene.lighting()?;
        let gpu = |e: ocean_gpu::GpuError| e.to_string();
        let mut renderer = OceanRenderer::new(&ctx, OceanOptions::default()).map_err(gpu)?;
        renderer.set_surface(&ctx, &surface).map_err(gpu)?;
        renderer.set_lighting(&ctx, &lighting).map_err(gpu)?;
        ctx.wait_idle().map_err(gpu)?;
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
            &scene.camera(preset, scene.render.time, width, height)?,
            (width, height),
        )?;

        Ok(Self {
            ctx,
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
            width,
            height,
        })
    }

    /// The session `ocean render` draws `scene` with, as `args` ask.
    fn new(scene: &SceneFile, args: &RenderArgs, times: &mut Times) -> Result<Self, String> {
        Self::build(
            scene,
            args.backend,
            args.camera,
            scene.render.samples,
            args.depth_out.is_some(),
            times,
        )
    }

    /// Draws the frame at scene `time` seen from `preset` (or the scene's camera) and reads it
    /// back, its depth too with `read_depth`; the passes' times go to `times`. Also returns
    /// the camera and when the drawing started, after the wave trains were marched.
    fn frame(
        &mut self,
        scene: &SceneFile,
        preset: Option<Preset>,
        time: f64,
        read_depth: bool,
        times: &mut Times,
    ) -> Result<(FrameImage, Camera, Instant), String> {
        let gpu = |e: ocean_gpu::GpuError| e.to_string();
        let camera = scene.camera(preset, time, self.width, self.height)?;
        let t = Instant::now();
        if let Some(island) = self.island.as_mut() {
            let local = island.local_waves(&self.surface, time)?;
            self.renderer
                .set_local_waves(&self.ctx, Some(&local))
                .map_err(gpu)?;
        }
        times.waves += t.elapsed().as_secs_f64();
        let t = Instant::now();
        let mut dressing = Dressing {
            terrain: self.terrain.as_ref(),
            obscurance: &mut self.obscurance,
            lighting: &self.lighting,
            sky: &self.face_light.sky,
            rocks: &self.rocks,
            solids: self.solids.as_ref(),
        };
        let image = draw_frame(
            &self.ctx,
            &self.renderer,
            &mut dressing,
            &camera,
            time,
            &self.targets,
            read_depth,
            &mut times.passes,
        )
        .map_err(gpu)?;
        Ok((image, camera, t))
    }
}

/// The built-in scene's (or `scene`'s) first frame at its `[render]` size, one sample per
/// pixel, on the Vulkan backend: its camera and its window depth, rows from the top, what the
/// obscurance pass reads.
///
/// # Errors
///
/// A message where no Vulkan adapter exists or the scene fails.
pub fn scene_depth(scene: &SceneFile) -> Result<(Camera, Vec<f32>), String> {
    let mut times = Times::default();
    let mut session = Session::build(scene, Backend::Vulkan, None, 1, true, &mut times)?;
    let (image, camera, _) = session.frame(scene, None, scene.render.time, true, &mut times)?;
    let depth = image.depth.ok_or("the frame's depth was not read back")?;
    Ok((camera, depth))
}

/// A 16-bit grayscale PNG of window depths in `[0, 1]`: 65535 d, rounded (big-endian samples,
/// as PNG stores them).
fn depth_png(width: u32, height: u32, depth: &[f32]) -> Result<Vec<u8>, String> {
    let samples: Vec<u8> = depth
        .iter()
        .flat_map(|d| ((d.clamp(0.0, 1.0) * 65535.0).round() as u16).to_be_bytes())
        .collect();
    crate::png::encode(
        width,
        height,
        ::png::ColorType::Grayscale,
        ::png::BitDepth::Sixteen,
        &samples,
    )
}

/// Seconds spent per stage, summed over the frames.
#[derive(Default)]
struct Times {
    setup: f64,
    island: f64,
    waves: f64,
    rocks: f64,
    device: f64,
    frame: f64,
    /// The first frame's wall time, when more follow (then not in `frame` and `passes`).
    first: Option<f64>,
    passes: [f64; PASSES.len()],
    encode: f64,
    write: f64,
}

pub fn run(args: &RenderArgs) -> Result<(), String> {
    crate::interrupt::install()?;
    let started = Instant::now();
    let mut scene = match &args.scene {
        Some(path) => SceneFile::read(path)?,
        None => SceneFile::parse(DEFAULT_SCENE, "the built-in scene")?,
    };
    if let Some(w) = args.width {
        scene.render.width = w;
    }
    if let Some(h) = args.height {
        scene.render.height = h;
    }
    if let Some(t) = args.time {
        scene.render.time = t;
    }
    if let Some(n) = args.samples {
        scene.render.samples = n;
    }
    scene.check_overrides()?;
    check_writable(&args.out)?;
    if let Some(path) = &args.depth_out {
        check_writable(path)?;
    }
    let (width, height) = (scene.render.width, scene.render.height);
    let mut times = Times::default();
    let mut session = Session::new(&scene, args, &mut times)?;
    let samples = session.samples;
    let bar = !args.quiet && std::io::stderr().is_terminal();
    let frames = args.frames;
    let mut written = 0u32;
    for k in 0..frames {
        if crate::interrupt::requested() {
            break;
        }
        let time = scene.render.time + f64::from(k) / scene.render.fps;
        let (image, _, t) = session.frame(
            &scene,
            args.camera,
            time,
            args.depth_out.is_some(),
            &mut times,
        )?;
        if k == 0 && frames > 1 {
            // The first frame builds the pipelines (and the driver compiles their shaders):
            // reported apart, so the per-pass figures are those of a running sequence.
            times.first = Some(t.elapsed().as_secs_f64());
            times.passes = [0.0; PASSES.len()];
        } else {
            times.frame += t.elapsed().as_secs_f64();
        }
        let t = Instant::now();
        let png = crate::png::encode(
            width,
            height,
            ::png::ColorType::Rgba,
            ::png::BitDepth::Eight,
            &image.rgba,
        )?;
        let depth_png = match (&args.depth_out, &image.depth) {
            (Some(path), Some(depth)) => Some((path, depth_png(width, height, depth)?)),
            _ => None,
        };
        times.encode += t.elapsed().as_secs_f64();
        let t = Instant::now();
        let mut written_ok = write_atomically(&frame_path(&args.out, k, frames), &png);
        if let (Ok(()), Some((path, bytes))) = (&written_ok, &depth_png) {
            written_ok = write_atomically(&frame_path(path, k, frames), bytes);
        }
        if let Err(e) = written_ok {
            // Interrupted during the write: this frame was removed, the others are whole.
            if crate::interrupt::requested() {
                break;
            }
            return Err(e);
        }
        times.write += t.elapsed().as_secs_f64();
        written += 1;
        if bar {
            let filled = (written as usize * 40) / frames as usize;
            let mut err = std::io::stderr().lock();
            let _ = write!(
                err,
                "\rrender [{}{}] {written}/{frames}",
                "#".repeat(filled),
                ".".repeat(40 - filled)
            );
            if written == frames {
                let _ = writeln!(err);
            }
            let _ = err.flush();
        }
    }
    if bar && written < frames {
        eprintln!();
    }
    if written < frames {
        return Err(format!(
            "{}: {written} of {frames} frames written, each complete",
            crate::interrupt::MESSAGE
        ));
    }
    let per = |s: f64| 1e3 * s / f64::from(written);
    println!(
        "{}: {width}x{height}, {samples} sample{} per pixel{}, {written} frame{}, {} waves, on {}",
        if frames == 1 {
            args.out.display().to_string()
        } else {
            format!(
                "{} .. {}",
                frame_path(&args.out, 0, frames).display(),
                frame_path(&args.out, frames - 1, frames).display()
            )
        },
        if samples == 1 { "" } else { "s" },
        if session.single_only {
            " (multisampling is not available on this backend)"
        } else {
            ""
        },
        if written == 1 { "" } else { "s" },
        session.surface.wave_set().waves().len(),
        session.ctx.describe()
    );
    println!("  device           {:9.1} ms", 1e3 * times.device);
    println!(
        "  setup            {:9.1} ms  (spectrum, filtering, sky map and its upload)",
        1e3 * times.setup
    );
    println!(
        "  island           {:9.1} ms  (terrain, wave train boxes, terrain mesh upload)",
        1e3 * times.island
    );
    println!(
        "  wave trains      {:9.1} ms per frame  ({} boxes marched on the CPU, uploaded as local waves)",
        per(times.waves),
        scene.boxes.len()
    );
    let generated: usize = session.rocks.iter().map(|r| r.cones.0).sum();
    let cached: usize = session.rocks.iter().map(|r| r.cones.1).sum();
    println!(
        "  relief maps      {:9.1} ms  ({} relief textures for the rocks and the pier with {} levels down to 8 x 8, relaxed cones: {generated} generated on the CPU, {cached} from the cache{})",
        1e3 * times.rocks,
        session.rocks.len(),
        generated + cached,
        cone_cache::dir().map_or_else(
            || " (none: no cache directory)".to_owned(),
            |d| format!(" in {}", d.display())
        )
    );
    let steady = written - u32::from(times.first.is_some());
    let per_steady = |s: f64| 1e3 * s / f64::from(steady.max(1));
    if let Some(first) = times.first {
        println!(
            "  first frame      {:9.1} ms  (the passes below, and building their pipelines)",
            1e3 * first
        );
    }
    println!(
        "  frame            {:9.1} ms per frame{}  (wall time of the passes below)",
        per_steady(times.frame),
        if times.first.is_some() {
            " after the first"
        } else {
            " (with building the pipelines)"
        }
    );
    for ((name, what), s) in PASSES.iter().zip(times.passes) {
        let skipped = match *name {
            "island" => session.terrain.is_none(),
            "rocks, pier" => session.rocks.is_empty() && session.solids.is_none(),
            "obscurance" => !session.obscurance.enabled(),
            _ => false,
        };
        if skipped {
            println!("    {name:<14} {:>9}     (none in the scene)", "-");
        } else {
            println!("    {name:<14} {:9.1} ms  ({what})", per_steady(s));
        }
    }
    println!("  PNG encoding     {:9.1} ms per frame", per(times.encode));
    println!("  PNG writing      {:9.1} ms per frame", per(times.write));
    println!(
        "  total            {:9.1} ms",
        1e3 * started.elapsed().as_secs_f64()
    );
    Ok(())
}
