//! The antialiasing of `ocean render` measured: the built-in scene at 320 × 180 with one sample
//! per pixel and with four (multisampling), against a 4 × 4 supersampled render of the same
//! scene (1280 × 720, one sample, averaged over 4 × 4 blocks in linear light), on the pixels
//! that an edge crosses.
//!
//! Edge pixels are found in the reference's depth (`--depth-out`): a pixel is an edge pixel
//! when its 4 × 4 block holds both sky (window depth 1) and a surface, or when the window depth
//! has a second difference above 16/65535 along a row or a column anywhere in the block.
//! Window depth is affine in screen space over any plane, so only a discontinuity (a
//! silhouette: the rocks, the pier's deck and posts, the island, wave crests hiding troughs)
//! or a strong curvature makes one; its 16-bit quantisation moves a second difference by at
//! most 2.
//!
//! What antialiasing can remove is measured beside what it cannot: the mean absolute error on
//! the pixels no edge crosses, where the render at 320 × 180 differs from the reference only
//! because the reference resolves finer detail (the sea's filtered waves, the relief's mip
//! level, the obscurance's pixel-sized taps) and the antialiasing changes nothing. Measured
//! on lavapipe: edge pixels 14.0 levels with one sample, 7.7 with four; elsewhere 5.5 and 5.5.
//! The criterion is on the edge error above that floor: four samples must leave at most half
//! of what one sample leaves (measured: 2.3 against 8.4 levels).
//!
//! The depth is copied from the GPU, which wgpu's GL backend cannot do, and multisampling is
//! not available there either: these renders ask for Vulkan (lavapipe on a machine without a
//! GPU) whatever `WGPU_BACKEND` says. Skipped without that adapter unless
//! `OCEAN_REQUIRE_GPU=1`.

use std::path::Path;
use std::process::Command;

mod common;

const W: usize = 320;
const H: usize = 180;
/// Supersampling factor per axis of the reference.
const K: usize = 4;

/// Renders the built-in scene at `w × h` with `samples` per pixel on Vulkan into `d/name.png`
/// (and its depth into `d/name-depth.png` with `depth`); `None` without a Vulkan adapter
/// (unless `OCEAN_REQUIRE_GPU=1`).
fn render(d: &Path, name: &str, (w, h): (usize, usize), samples: u32, depth: bool) -> Option<()> {
    let out = d.join(format!("{name}.png"));
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_ocean"));
    cmd.env(
        "OCEAN_CACHE_DIR",
        Path::new(env!("CARGO_TARGET_TMPDIR")).join("render-cone-cache"),
    );
    cmd.args(["render", "--quiet", "--backend", "vulkan"]);
    cmd.args(["--width", &w.to_string(), "--height", &h.to_string()]);
    cmd.args(["--samples", &samples.to_string()]);
    if depth {
        cmd.arg("--depth-out")
            .arg(d.join(format!("{name}-depth.png")));
    }
    let o = cmd.arg("--out").arg(&out).output().expect("run ocean");
    if common::no_adapter(&o) {
        return None;
    }
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    Some(())
}

/// The samples of a PNG (8-bit RGBA or 16-bit grayscale) as numbers, with its size.
fn read_png(path: &Path) -> (usize, usize, Vec<f64>) {
    let (w, h, _, _, samples) = common::read_png(path);
    let samples = samples.into_iter().map(f64::from).collect();
    (w as usize, h as usize, samples)
}

fn srgb_to_linear(v: f64) -> f64 {
    let c = v / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

fn linear_to_srgb(c: f64) -> f64 {
    255.0
        * if c <= 0.003_130_8 {
            12.92 * c
        } else {
            1.055 * c.powf(1.0 / 2.4) - 0.055
        }
}

/// The reference at W × H: each 4 × 4 block of the supersampled RGBA image averaged in linear
/// light and encoded again (RGB per pixel).
fn downsample(rgba: &[f64]) -> Vec<[f64; 3]> {
    let mut out = vec![[0.0; 3]; W * H];
    for (p, px) in out.iter_mut().enumerate() {
        let (x, y) = (p % W, p / W);
        for (c, v) in px.iter_mut().enumerate() {
            let mut sum = 0.0;
            for j in 0..K {
                for i in 0..K {
                    sum += srgb_to_linear(rgba[4 * ((K * y + j) * K * W + K * x + i) + c]);
                }
            }
            *v = linear_to_srgb(sum / (K * K) as f64);
        }
    }
    out
}

/// The edge pixels at W × H from the reference's 16-bit window depth (see the module's doc).
fn edges(depth: &[f64]) -> Vec<bool> {
    const SKY: f64 = 65535.0;
    const JUMP: f64 = 16.0;
    let (rw, rh) = (K * W, K * H);
    let at = |x: usize, y: usize| depth[y * rw + x];
    let mut jump = vec![false; rw * rh];
    for y in 0..rh {
        for x in 0..rw {
            let second = |a: f64, b: f64, c: f64| (a - 2.0 * b + c).abs() > JUMP;
            jump[y * rw + x] =
                (x > 0 && x + 1 < rw && second(at(x - 1, y), at(x, y), at(x + 1, y)))
                    || (y > 0 && y + 1 < rh && second(at(x, y - 1), at(x, y), at(x, y + 1)));
        }
    }
    (0..W * H)
        .map(|p| {
            let (x, y) = (p % W, p / W);
            let block = (0..K).flat_map(|j| (0..K).map(move |i| (K * x + i, K * y + j)));
            let (mut sky, mut surface, mut any_jump) = (false, false, false);
            for (bx, by) in block {
                let s = at(bx, by) >= SKY;
                sky |= s;
                surface |= !s;
                any_jump |= jump[by * rw + bx];
            }
            (sky && surface) || any_jump
        })
        .collect()
}

/// Mean absolute difference per channel, in levels, of `image` (RGBA) from `reference` over
/// the pixels where `mask` is `on`.
fn mae(image: &[f64], reference: &[[f64; 3]], mask: &[bool], on: bool) -> f64 {
    let (mut sum, mut n) = (0.0, 0usize);
    for (p, r) in reference.iter().enumerate() {
        if mask[p] == on {
            sum += (0..3).map(|c| (image[4 * p + c] - r[c]).abs()).sum::<f64>() / 3.0;
            n += 1;
        }
    }
    sum / n.max(1) as f64
}

#[test]
fn multisampling_halves_the_edge_error_against_a_supersampled_render() {
    let d = common::dir("antialiasing", "built-in");
    if render(&d, "one", (W, H), 1, false).is_none() {
        return;
    }
    render(&d, "four", (W, H), 4, false).expect("rendered");
    render(&d, "reference", (K * W, K * H), 1, true).expect("rendered");
    let (rw, rh, reference) = read_png(&d.join("reference.png"));
    assert_eq!((rw, rh), (K * W, K * H));
    let (_, _, depth) = read_png(&d.join("reference-depth.png"));
    let reference = downsample(&reference);
    let mask = edges(&depth);
    let count = mask.iter().filter(|&&e| e).count();
    // The horizon alone crosses 320 pixels; the silhouettes add more.
    assert!((W..=W * H / 10).contains(&count), "{count} edge pixels");

    let mut floors = Vec::new();
    let mut excess = Vec::new();
    for name in ["one", "four"] {
        let (w, h, image) = read_png(&d.join(format!("{name}.png")));
        assert_eq!((w, h), (W, H));
        let (edge, floor) = (
            mae(&image, &reference, &mask, true),
            mae(&image, &reference, &mask, false),
        );
        println!(
            "{name} sample(s) per pixel: edge pixels {edge:.2} levels, {count} of them; \
             elsewhere {floor:.2}; edge error above it {:.2}",
            edge - floor
        );
        floors.push(floor);
        excess.push(edge - floor);
    }
    // Away from edges the two renders are the same image (a pixel one surface covers runs its
    // fragment once, at its centre): the floor must not move.
    assert!((floors[0] - floors[1]).abs() <= 0.5, "{floors:?}");
    assert!(excess[0] > 2.0, "no edge error to remove: {excess:?}");
    assert!(excess[1] <= 0.5 * excess[0], "{excess:?}");
}
