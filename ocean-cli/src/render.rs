//! `ocean render`: a headless render of a scene file into PNG images.
//!
//! What it draws is `ocean_scene::SceneRenderer`'s frame of the scene description (the open
//! sea and the sky lit by Algorithm 5.1 of Bruneton, Neyret & Holzschuch 2010, the island and
//! the wave train boxes that reach its shore, relief-mapped rocks and pier, ambient
//! obscurance); this module parses the arguments, shows progress, writes the PNGs and prints
//! the timings.
//!
//! Every PNG is written to a temporary file and renamed when complete, the output directory is
//! checked before anything is rendered, and an interruption (Ctrl-C, SIGTERM, SIGHUP) stops the
//! sequence between frames, so only complete images are ever left.

use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::Args;
use ocean_scene::frame::PASSES;
use ocean_scene::renderer::RenderOptions;
use ocean_scene::{Backend, BuildTimes, DEFAULT_SCENE, Preset, SceneDescription, SceneRenderer};

use crate::png::write_atomically;

/// Most frames one run renders.
const MAX_FRAMES: u32 = 100_000;

#[derive(Args, Debug)]
pub struct RenderArgs {
    /// Scene file (TOML, see `ocean-scene/scenes/default.toml`); the built-in scene by default.
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

/// A 16-bit grayscale PNG of window depths in `[0, 1]`: 65535 d, rounded (big-endian samples,
/// as PNG stores them).
fn depth_png(width: u32, height: u32, depth: &[f32]) -> Result<Vec<u8>, String> {
    let samples: Vec<u8> = depth
        .iter()
        .flat_map(|d| ((d.clamp(0.0, 1.0) * 65535.0).round() as u16).to_be_bytes())
        .collect();
    ocean_scene::image_file::encode_png(
        width,
        height,
        ::png::ColorType::Grayscale,
        ::png::BitDepth::Sixteen,
        &samples,
    )
}

/// Seconds spent per stage of the frames, summed over them, and on writing them.
#[derive(Default)]
struct Times {
    waves: f64,
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
        Some(path) => SceneDescription::read(path).map_err(|e| e.to_string())?,
        None => SceneDescription::parse(DEFAULT_SCENE, "the built-in scene")
            .map_err(|e| e.to_string())?,
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
    scene.check_overrides().map_err(|e| e.to_string())?;
    check_writable(&args.out)?;
    if let Some(path) = &args.depth_out {
        check_writable(path)?;
    }
    let (width, height) = (scene.render.width, scene.render.height);
    let mut times = Times::default();
    let options = RenderOptions {
        preset: args.camera,
        samples: None,
        read_depth: args.depth_out.is_some(),
    };
    let mut renderer = SceneRenderer::new(&scene, args.backend, options).map_err(|e| match e {
        ocean_scene::SceneError::Unsupported(why) => {
            format!("--depth-out: {why}; try --backend vulkan")
        }
        e => e.to_string(),
    })?;
    let samples = renderer.samples();
    let bar = !args.quiet && std::io::stderr().is_terminal();
    let frames = args.frames;
    let mut written = 0u32;
    for k in 0..frames {
        if crate::interrupt::requested() {
            break;
        }
        let time = scene.render.time + f64::from(k) / scene.render.fps;
        let image = renderer
            .frame(time, args.depth_out.is_some())
            .map_err(|e| e.to_string())?;
        times.waves += image.times.waves;
        if k == 0 && frames > 1 {
            // The first frame builds the pipelines (and the driver compiles their shaders):
            // reported apart, so the per-pass figures are those of a running sequence.
            times.first = Some(image.times.total);
        } else {
            times.frame += image.times.total;
            for (sum, s) in times.passes.iter_mut().zip(image.times.passes) {
                *sum += s;
            }
        }
        let t = Instant::now();
        let png = ocean_scene::image_file::encode_png(
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
        if renderer.single_only() {
            " (multisampling is not available on this backend)"
        } else {
            ""
        },
        if written == 1 { "" } else { "s" },
        renderer.wave_count(),
        renderer.describe()
    );
    let BuildTimes {
        device,
        setup,
        island,
        rocks,
    } = renderer.build_times();
    println!("  device           {:9.1} ms", 1e3 * device);
    println!(
        "  setup            {:9.1} ms  (spectrum, filtering, sky map and its upload)",
        1e3 * setup
    );
    println!(
        "  island           {:9.1} ms  (terrain, wave train boxes, terrain mesh upload)",
        1e3 * island
    );
    println!(
        "  wave trains      {:9.1} ms per frame  ({} boxes marched on the CPU, uploaded as local waves)",
        per(times.waves),
        scene.boxes.len()
    );
    let (textures, generated, cached) = renderer.relief_textures();
    println!(
        "  relief maps      {:9.1} ms  ({} relief textures for the rocks and the pier with {} levels down to 8 x 8, relaxed cones: {generated} generated on the CPU, {cached} from the cache{})",
        1e3 * rocks,
        textures,
        generated + cached,
        ocean_scene::cone_cache::dir().map_or_else(
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
    for (((name, what), s), drawn) in PASSES.iter().zip(times.passes).zip(renderer.drawn_passes()) {
        if !drawn {
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
