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
//! ([`crate::composite`]).
//!
//! Every PNG is written to a temporary file and renamed when complete, the output directory is
//! checked before anything is rendered, and an interruption (Ctrl-C, SIGTERM, SIGHUP) stops the
//! sequence between frames, so only complete images are ever left.

use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::{Args, ValueEnum};
use glam::{DVec2, DVec3};
use ocean_brdf::{Filter, FilteredSurface, Lighting, Spectrum};
use ocean_core::Camera;
use ocean_gpu::{
    ContextOptions, GpuContext, OceanOptions, OceanRenderer, ReliefOptions, ReliefRenderer,
    ReliefScene,
};
use ocean_relief::{ConeParams, Edge, ReliefTexture};

use crate::composite::Obscurance;
use crate::cone_cache;
use crate::island::Island;
use crate::png::write_atomically;
use crate::scene::{DEFAULT_SCENE, Preset, SceneFile};
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
    /// Camera preset (overrides the scene's).
    #[arg(long, value_enum)]
    camera: Option<Preset>,
    /// Graphics backend.
    #[arg(long, value_enum, default_value_t = Backend::Auto)]
    backend: Backend,
    /// Output PNG.
    #[arg(long, default_value = "ocean.png")]
    out: PathBuf,
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

/// A rock face ready to draw: its relief texture in a renderer of its own, and its quad.
struct RockDraw {
    renderer: ReliefRenderer,
    scene: ReliefScene,
    /// Whether its cone map came from the cache on disk.
    cached: bool,
}

/// The rocks of `scene`: each height map (value noise), its relaxed cone map and its quad, lit
/// by the Sun.
fn rock_draws(ctx: &GpuContext, scene: &SceneFile, sun: DVec3) -> Result<Vec<RockDraw>, String> {
    let relief_error = |e: ocean_relief::ReliefError| format!("rock: {e}");
    scene
        .rocks
        .iter()
        .map(|rock| {
            let n = rock.map_size;
            let heights = ocean_relief::maps::value_noise(n, (n / 32).max(2), 5, rock.seed);
            let map = ocean_relief::maps::to_map(n, &heights, Edge::Wrap).map_err(relief_error)?;
            let (cones, source) =
                cone_cache::cones(&map, ConeParams::relaxed(4.0)).map_err(relief_error)?;
            let texture = ReliefTexture::new(&map, &cones).map_err(relief_error)?;
            let mut renderer =
                ReliefRenderer::new(ctx, ReliefOptions::default()).map_err(|e| e.to_string())?;
            renderer
                .set_texture(ctx, &texture)
                .map_err(|e| e.to_string())?;
            // u to the right of the face, v up: u × v is the face's outward normal.
            let f = rock.facing.to_radians();
            let u = DVec3::new(f.cos(), 0.0, -f.sin());
            let centre = DVec3::from_array(rock.centre);
            let draw = ReliefScene {
                origin: centre - 0.5 * rock.width * u - 0.5 * rock.height * DVec3::Y,
                edge_u: rock.width * u,
                edge_v: rock.height * DVec3::Y,
                tiles: DVec2::new(rock.width / rock.tile, rock.height / rock.tile),
                depth: rock.relief_depth,
                light_dir: sun,
                light_intensity: 1.0,
                albedo: rock.albedo,
                ambient: 0.25,
                ..ReliefScene::default()
            };
            draw.tangent_frame().map_err(|e| e.to_string())?;
            Ok(RockDraw {
                renderer,
                scene: draw,
                cached: source == cone_cache::Source::Cached,
            })
        })
        .collect()
}

/// The colour and depth targets of the frames.
struct Targets {
    color: ocean_gpu::wgpu::Texture,
    color_view: ocean_gpu::wgpu::TextureView,
    depth: ocean_gpu::wgpu::Texture,
    depth_view: ocean_gpu::wgpu::TextureView,
    /// What the obscurance composite writes, and what is read back then.
    out: ocean_gpu::wgpu::Texture,
    out_view: ocean_gpu::wgpu::TextureView,
}

fn targets(ctx: &GpuContext, width: u32, height: u32) -> Targets {
    use ocean_gpu::wgpu;
    let texture = |label, format, usage| {
        ctx.device().create_texture(&wgpu::TextureDescriptor {
            label: Some(label),
            size: wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage,
            view_formats: &[],
        })
    };
    let color = texture(
        "ocean render colour",
        OceanOptions::default().color_format,
        wgpu::TextureUsages::RENDER_ATTACHMENT
            | wgpu::TextureUsages::COPY_SRC
            | wgpu::TextureUsages::TEXTURE_BINDING,
    );
    let depth = texture(
        "ocean render depth",
        wgpu::TextureFormat::Depth32Float,
        wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
    );
    let out = texture(
        "ocean render obscured colour",
        OceanOptions::default().color_format,
        wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
    );
    let view = |t: &wgpu::Texture| t.create_view(&wgpu::TextureViewDescriptor::default());
    Targets {
        color_view: view(&color),
        depth_view: view(&depth),
        out_view: view(&out),
        color,
        depth,
        out,
    }
}

/// What one frame draws besides the sea.
struct Dressing<'a> {
    terrain: Option<&'a TerrainRenderer>,
    obscurance: Option<&'a mut Obscurance>,
    lighting: &'a Lighting,
    rocks: &'a [RockDraw],
}

/// Draws one frame (the sea and sky, the island, then the rocks) and reads it back: RGBA8
/// rows from the top.
fn draw_frame(
    ctx: &GpuContext,
    ocean: &OceanRenderer,
    dressing: &mut Dressing<'_>,
    camera: &Camera,
    time: f64,
    t: &Targets,
) -> Result<Vec<u8>, ocean_gpu::GpuError> {
    use ocean_gpu::wgpu;
    let size = (t.color.width(), t.color.height());
    let mut encoder = ctx
        .device()
        .create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("ocean render"),
        });
    // Both renderers load their targets: clear them first (depth to the far plane, 1 in
    // WebGPU's forward range, which the scene's cameras use).
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("ocean render clear"),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view: &t.color_view,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations {
                load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                store: wgpu::StoreOp::Store,
            },
        })],
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
    ocean.render(
        ctx,
        &mut encoder,
        camera,
        time,
        &t.color_view,
        Some(&t.depth_view),
        size,
    )?;
    if let Some(terrain) = dressing.terrain {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("island terrain"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &t.color_view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Load,
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &t.depth_view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Load,
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        let o = ocean.options();
        terrain.draw(
            ctx,
            &mut pass,
            camera,
            dressing.lighting,
            o.exposure,
            !o.color_format.is_srgb(),
        );
    }
    for rock in dressing.rocks {
        rock.renderer.render(
            ctx,
            &mut encoder,
            camera,
            &rock.scene,
            &t.color_view,
            &t.depth_view,
            size,
        )?;
    }
    let result = match dressing.obscurance.as_deref_mut() {
        Some(o) => {
            o.encode(ctx, &mut encoder, &t.depth, &t.color_view, &t.out_view)?;
            &t.out
        }
        None => &t.color,
    };
    ctx.queue().submit([encoder.finish()]);
    Ok(ocean_gpu::readback::read_texture(ctx, result, 0)?.data)
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
    scene.check_overrides()?;
    check_writable(&args.out)?;
    let (width, height) = (scene.render.width, scene.render.height);
    let mut times = Times::default();

    let t = Instant::now();
    let ctx = GpuContext::headless_with(&ContextOptions {
        backends: match args.backend {
            Backend::Auto => None,
            Backend::Vulkan => Some(ocean_gpu::wgpu::Backends::VULKAN),
            Backend::Gl => Some(ocean_gpu::wgpu::Backends::GL),
        },
        ..ContextOptions::default()
    })
    .map_err(|e| e.to_string())?;
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
    let mut island = match &scene.island {
        Some(section) => Some(Island::new(section, &scene.boxes)?),
        None => None,
    };
    let terrain = match &island {
        Some(i) => Some(TerrainRenderer::new(
            &ctx,
            &i.heights,
            (i.grid.nx(), i.grid.nz()),
            i.grid.origin(),
            i.grid.spacing(),
            renderer.options().color_format,
        )?),
        None => None,
    };
    times.island = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let rocks = rock_draws(&ctx, &scene, lighting.sky().sun_direction())?;
    times.rocks = t.elapsed().as_secs_f64();
    let targets = targets(&ctx, width, height);
    let mut obscurance = match &scene.obscurance {
        o if o.enabled => Some(Obscurance::new(
            &ctx,
            o,
            &scene.camera(args.camera, scene.render.time, width, height)?,
            (width, height),
            renderer.options().color_format,
        )?),
        _ => None,
    };

    let bar = !args.quiet && std::io::stderr().is_terminal();
    let frames = args.frames;
    let mut written = 0u32;
    for k in 0..frames {
        if crate::interrupt::requested() {
            break;
        }
        let time = scene.render.time + f64::from(k) / scene.render.fps;
        let camera = scene.camera(args.camera, time, width, height)?;
        let t = Instant::now();
        if let Some(island) = island.as_mut() {
            let local = island.local_waves(&surface, time)?;
            renderer.set_local_waves(&ctx, Some(&local)).map_err(gpu)?;
        }
        times.waves += t.elapsed().as_secs_f64();
        let t = Instant::now();
        let mut dressing = Dressing {
            terrain: terrain.as_ref(),
            obscurance: obscurance.as_mut(),
            lighting: &lighting,
            rocks: &rocks,
        };
        let rgba =
            draw_frame(&ctx, &renderer, &mut dressing, &camera, time, &targets).map_err(gpu)?;
        times.frame += t.elapsed().as_secs_f64();
        let t = Instant::now();
        let png = crate::png::encode(
            width,
            height,
            ::png::ColorType::Rgba,
            ::png::BitDepth::Eight,
            &rgba,
        )?;
        times.encode += t.elapsed().as_secs_f64();
        let t = Instant::now();
        if let Err(e) = write_atomically(&frame_path(&args.out, k, frames), &png) {
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
        "{}: {width}x{height}, {written} frame{}, {} waves, on {}",
        if frames == 1 {
            args.out.display().to_string()
        } else {
            format!(
                "{} .. {}",
                frame_path(&args.out, 0, frames).display(),
                frame_path(&args.out, frames - 1, frames).display()
            )
        },
        if written == 1 { "" } else { "s" },
        surface.wave_set().waves().len(),
        ctx.describe()
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
    let cached = rocks.iter().filter(|r| r.cached).count();
    println!(
        "  rocks            {:9.1} ms  ({} height and cone maps, relaxed: {} generated on the CPU, {cached} from the cache{})",
        1e3 * times.rocks,
        rocks.len(),
        rocks.len() - cached,
        cone_cache::dir().map_or_else(
            || " (none: no cache directory)".to_owned(),
            |d| format!(" in {}", d.display())
        )
    );
    println!(
        "  frame            {:9.1} ms per frame  (sea, sky, island, rocks and obscurance; render and readback, wall time)",
        per(times.frame)
    );
    println!("  PNG encoding     {:9.1} ms per frame", per(times.encode));
    println!("  PNG writing      {:9.1} ms per frame", per(times.write));
    println!(
        "  total            {:9.1} ms",
        1e3 * started.elapsed().as_secs_f64()
    );
    Ok(())
}
