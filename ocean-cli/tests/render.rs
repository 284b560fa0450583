//! `ocean render` end to end: the built binary on small images. Rendering needs a GPU adapter
//! (Mesa's lavapipe or llvmpipe will do); without one those tests are skipped unless
//! `OCEAN_REQUIRE_GPU=1`, which CI sets. The checks of bad input need none.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

mod common;

use common::{files, no_adapter};

/// A fresh, empty directory for one test.
fn dir(name: &str) -> PathBuf {
    common::dir("render", name)
}

/// The tests' cone-map cache (never the user's).
fn cache_dir() -> PathBuf {
    Path::new(env!("CARGO_TARGET_TMPDIR")).join("render-cone-cache")
}

fn ocean(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ocean"))
        .env("OCEAN_CACHE_DIR", cache_dir())
        .arg("render")
        .args(args)
        .output()
        .expect("run the ocean binary")
}

/// Decodes an RGBA8 PNG: (width, height, pixels).
fn read_png(path: &Path) -> (u32, u32, Vec<[u8; 4]>) {
    let (w, h, color, bits, samples) = common::read_png(path);
    assert_eq!((color, bits), (png::ColorType::Rgba, png::BitDepth::Eight));
    let px = samples
        .chunks(4)
        .map(|c| [c[0], c[1], c[2], c[3]].map(|v| v as u8))
        .collect();
    (w, h, px)
}

fn luminance(p: [u8; 4]) -> f64 {
    0.2126 * f64::from(p[0]) + 0.7152 * f64::from(p[1]) + 0.0722 * f64::from(p[2])
}

/// The horizon view of the built-in scene at 96 x 54: a sky above (every pixel of the top row
/// bluer than red and at least as blue as green, as a clear sky is; near the Sun, which this
/// view holds, blue and green saturate together), the sea below, darker than the sky on
/// average (the sea reflects 2% of the sky at normal incidence, Eq. 14, plus its own colour),
/// and not uniform: the waves modulate it.
#[test]
fn renders_sky_above_the_sea() {
    let d = dir("horizon");
    let out = d.join("h.png");
    let o = ocean(&[
        "--width",
        "96",
        "--height",
        "54",
        "--camera",
        "horizon",
        "--out",
        out.to_str().unwrap(),
    ]);
    if no_adapter(&o) {
        return;
    }
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{stderr}");
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        stdout.contains("96x54, ")
            && stdout.contains(" per pixel")
            && stdout.contains("1 frame, 60 waves")
            && stdout.contains("frame "),
        "{stdout}"
    );
    let (w, h, px) = read_png(&out);
    assert_eq!((w, h), (96, 54));
    let row = |y: u32| &px[(y * w) as usize..((y + 1) * w) as usize];
    let mean = |y: u32| row(y).iter().map(|&p| luminance(p)).sum::<f64>() / f64::from(w);
    for p in row(0) {
        assert!(
            p[2] > p[0] && p[2] >= p[1] && p[3] == 255,
            "sky pixel {p:?}"
        );
    }
    assert!(
        mean(0) > mean(h - 1) + 20.0,
        "{} vs {}",
        mean(0),
        mean(h - 1)
    );
    let sea = row(h - 1).iter().map(|&p| luminance(p));
    let (lo, hi) = sea.fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(v), b.max(v)));
    assert!(hi - lo > 2.0, "a uniform sea row: {lo}..{hi}");
    assert_eq!(files(&d), ["h.png"]);
}

/// Three frames of the orbit: three numbered PNGs, each complete, the camera moving between
/// them (the images differ).
#[test]
fn a_sequence_writes_numbered_frames() {
    let d = dir("sequence");
    let out = d.join("o.png");
    let o = ocean(&[
        "--width",
        "48",
        "--height",
        "32",
        "--frames",
        "3",
        "--camera",
        "orbit",
        "--out",
        out.to_str().unwrap(),
    ]);
    if no_adapter(&o) {
        return;
    }
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(files(&d), ["o-0000.png", "o-0001.png", "o-0002.png"]);
    let a = read_png(&d.join("o-0000.png"));
    let b = read_png(&d.join("o-0002.png"));
    assert_eq!((a.0, a.1, b.0, b.1), (48, 32, 48, 32));
    assert_ne!(a.2, b.2);
}

/// `--depth-out`: a 16-bit grayscale PNG of the window depth, 65535 on the far plane (the sky
/// of the horizon view's top row, forward range) and below it on the sea (its bottom row, 4 m
/// under the eye). wgpu's GL backend cannot copy depth to memory: there the option is refused
/// with the reason, and no file is written.
#[test]
fn depth_out_writes_the_window_depth() {
    let d = dir("depth-out");
    let (out, depth) = (d.join("c.png"), d.join("d.png"));
    let run = |backend: &str| {
        ocean(&[
            "--width",
            "96",
            "--height",
            "54",
            "--camera",
            "horizon",
            "--backend",
            backend,
            "--out",
            out.to_str().unwrap(),
            "--depth-out",
            depth.to_str().unwrap(),
        ])
    };
    let o = run("vulkan");
    if no_adapter(&o) {
        return;
    }
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (w, h, color, bits, samples) = common::read_png(&depth);
    assert_eq!(
        (w, h, color, bits),
        (96, 54, png::ColorType::Grayscale, png::BitDepth::Sixteen)
    );
    let at = |x: usize, y: usize| samples[y * 96 + x];
    for x in 0..96 {
        assert_eq!(at(x, 0), 65535, "sky at ({x}, 0)");
        let sea = at(x, 53);
        assert!(sea > 0 && sea < 65535, "sea at ({x}, 53): {sea}");
    }
    std::fs::remove_file(&out).unwrap();
    std::fs::remove_file(&depth).unwrap();
    let o = run("gl");
    if no_adapter(&o) {
        return;
    }
    let msg = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{msg}");
    assert!(
        msg.contains("--depth-out") && msg.contains("DEPTH_TEXTURE_AND_BUFFER_COPIES"),
        "{msg}"
    );
    assert!(files(&d).is_empty());
}

/// A malformed scene names the file, the line and the key; nothing is written.
#[test]
fn a_malformed_scene_names_the_line_and_the_key() {
    let d = dir("malformed");
    let cases = [
        ("[sun]\nelevation = 30.0\nglow = 2.0\n", "line 3", "glow"),
        ("[render]\nwidth = 0\n", "line 2", "render.width"),
        ("[render]\nsamples = 2\n", "line 2", "render.samples"),
        ("[spectrum]\nwaves = \"many\"\n", "line 2", "waves"),
    ];
    for (text, line, key) in cases {
        let scene = d.join("bad.toml");
        std::fs::write(&scene, text).unwrap();
        let out = d.join("x.png");
        let o = ocean(&[
            "--scene",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let msg = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{msg}");
        assert!(
            msg.contains("bad.toml") && msg.contains(line) && msg.contains(key),
            "{text:?}: {msg}"
        );
        assert_eq!(files(&d), ["bad.toml"]);
    }
    let o = ocean(&["--scene", d.join("none.toml").to_str().unwrap()]);
    assert!(String::from_utf8_lossy(&o.stderr).contains("cannot read the scene"));
}

/// An output directory that does not exist fails at once, before any device is created.
#[test]
fn an_unwritable_output_fails_before_rendering() {
    let d = dir("unwritable");
    let out = d.join("missing").join("x.png");
    let o = ocean(&["--out", out.to_str().unwrap(), "--backend", "gl"]);
    let msg = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{msg}");
    assert!(
        msg.contains("cannot write into") && msg.contains("missing"),
        "{msg}"
    );
    assert!(!String::from_utf8_lossy(&o.stdout).contains("device"));
    let o = ocean(&["--width", "0", "--out", d.join("y.png").to_str().unwrap()]);
    assert!(String::from_utf8_lossy(&o.stderr).contains("render.width"));
    let o = ocean(&["--samples", "8", "--out", d.join("y.png").to_str().unwrap()]);
    let msg = String::from_utf8_lossy(&o.stderr);
    assert!(
        msg.contains("render.samples") && msg.contains("neither 1 nor 4"),
        "{msg}"
    );
    assert!(files(&d).is_empty());
}

/// Ctrl-C during a long sequence: exit status 130, a message, and only complete PNGs (every
/// file there decodes), no temporary file.
#[cfg(unix)]
#[test]
fn an_interrupted_sequence_leaves_only_complete_frames() {
    let d = dir("interrupted");
    let out = d.join("f.png");
    let child = Command::new(env!("CARGO_BIN_EXE_ocean"))
        .args([
            "render",
            "--width",
            "64",
            "--height",
            "36",
            "--frames",
            "100000",
            "--quiet",
            "--out",
            out.to_str().unwrap(),
        ])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // Long enough for the device and a few frames on a software adapter.
    std::thread::sleep(std::time::Duration::from_millis(3000));
    let kill = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success());
    let o = child.wait_with_output().unwrap();
    if no_adapter(&o) {
        return;
    }
    let msg = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(130), "{msg}");
    assert!(
        msg.contains("interrupted") && msg.contains("frames written"),
        "{msg}"
    );
    let names = files(&d);
    for name in &names {
        assert!(
            name.starts_with("f-") && name.ends_with(".png"),
            "{names:?}"
        );
        assert_eq!(read_png(&d.join(name)).0, 64);
    }
}

/// The built-in scene's rocks and pier are drawn: against the same scene with no `[[rocks]]`
/// and no `[pier]` table, more than 0.5 % of the pixels change by more than 8 levels, none of
/// them above the horizon (row 26 of 72 for the shore preset: 0.5 − tan 8°/(2 tan 27.5°) ≈
/// 0.365 of the height; the largest rock, 105–115 m away, reaches at most 1.3 × 4.5 m above
/// its centre 1 m up, under 1 m above the camera's 6 m: half a row; two rows of margin for
/// rasterisation). Their silhouettes cover about 1.2 % of the 128 × 72 pixels (the rocks'
/// ellipses 14 × 9, 7 × 5 and 4 × 3 m at 105–115 m: about 64 pixels; the deck about 40 and
/// the posts 10), less what the pier hides of the rocks: measured 0.98 %.
#[test]
fn the_rocks_and_the_pier_are_drawn() {
    let d = dir("rock");
    let size = ["--width", "128", "--height", "72"];
    let with = d.join("with.png");
    let o = ocean(&[&size[..], &["--out", with.to_str().unwrap()]].concat());
    if no_adapter(&o) {
        return;
    }
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // The rock's map and the pier's planks, 256² each, with their levels down to 8²: 6 + 6.
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("2 relief textures for the rocks and the pier with 12 levels"),
        "{text}"
    );
    let default = include_str!("../../ocean-scene/scenes/default.toml");
    let scene = d.join("no-rocks.toml");
    std::fs::write(&scene, &default[..default.find("# Rocks:").unwrap()]).unwrap();
    let without = d.join("without.png");
    let o = ocean(
        &[
            &size[..],
            &[
                "--scene",
                scene.to_str().unwrap(),
                "--out",
                without.to_str().unwrap(),
            ],
        ]
        .concat(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (w, _, a) = read_png(&with);
    let (_, _, b) = read_png(&without);
    let mut changed = 0;
    for (k, (p, q)) in a.iter().zip(&b).enumerate() {
        if (0..3).any(|c| p[c].abs_diff(q[c]) > 8) {
            // Nothing above the horizon changes.
            assert!(
                k / w as usize >= 24,
                "pixel {k} (row {}) changed above the objects",
                k / w as usize
            );
            changed += 1;
        }
    }
    let share = changed as f64 / a.len() as f64;
    assert!(
        share > 0.005,
        "{share} of the pixels changed with the rocks and the pier"
    );
}

/// The cone maps (the rock's and the pier's planks', 256² each, with their levels down to 8²:
/// 6 + 6 maps) are generated once and then read from the cache, with the same image; a
/// corrupt cache file is ignored and written again.
#[test]
fn cone_maps_are_cached_on_disk() {
    let d = dir("cache");
    let cache = d.join("cones");
    let run = |name: &str| {
        let out = d.join(name);
        let o = Command::new(env!("CARGO_BIN_EXE_ocean"))
            .env("OCEAN_CACHE_DIR", &cache)
            .args(["render", "--width", "64", "--height", "36", "--out"])
            .arg(&out)
            .output()
            .expect("run the ocean binary");
        (o, out)
    };
    let (o, first) = run("first.png");
    if no_adapter(&o) {
        return;
    }
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(
        text.contains("12 generated on the CPU, 0 from the cache"),
        "{text}"
    );
    let stored = files(&cache);
    assert_eq!(stored.len(), 12, "{stored:?}");
    let (o, second) = run("second.png");
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(
        text.contains("0 generated on the CPU, 12 from the cache"),
        "{text}"
    );
    assert_eq!(read_png(&first), read_png(&second));
    // Corrupt the file: it is generated and stored again.
    let path = cache.join(&stored[0]);
    let mut bytes = std::fs::read(&path).unwrap();
    let mid = bytes.len() / 2;
    bytes[mid] ^= 1;
    std::fs::write(&path, &bytes).unwrap();
    let (o, third) = run("third.png");
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(
        text.contains("1 generated on the CPU, 11 from the cache"),
        "{text}"
    );
    assert_eq!(read_png(&first), read_png(&third));
    assert_ne!(std::fs::read(&path).unwrap(), bytes);
}
