//! `ocean cone-map` end to end: the built binary on small generated PNGs. The output must decode
//! to exactly the relief texture ocean-relief computes for the input (the format of the
//! command's long help), and bad inputs must fail with a message naming the problem and leave no
//! output and no temporary file behind.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use ocean_relief::storage::{Encoded, Encoding, encode};
use ocean_relief::{ConeMap, ConeParams, Edge, HeightMap};

mod common;

use common::{files, read_png};

/// A fresh, empty directory for one test.
fn dir(name: &str) -> PathBuf {
    common::dir("cone_map", name)
}

fn ocean(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ocean"))
        .args(args)
        .output()
        .expect("run the ocean binary")
}

fn write_png(
    path: &Path,
    (w, h): (u32, u32),
    color: png::ColorType,
    depth: png::BitDepth,
    data: &[u8],
) {
    let file = std::fs::File::create(path).unwrap();
    let mut enc = png::Encoder::new(std::io::BufWriter::new(file), w, h);
    enc.set_color(color);
    enc.set_depth(depth);
    let mut writer = enc.write_header().unwrap();
    writer.write_image_data(data).unwrap();
    writer.finish().unwrap();
}

/// A 24 x 24 height field: two bumps and a ridge, 8 bits.
fn heights8() -> Vec<u8> {
    (0..24 * 24)
        .map(|k| {
            let (x, y) = ((k % 24) as f64, (k / 24) as f64);
            let b1 = (-((x - 6.0).powi(2) + (y - 7.0).powi(2)) / 8.0).exp();
            let b2 = 0.7 * (-((x - 16.0).powi(2) + (y - 15.0).powi(2)) / 12.0).exp();
            let ridge = if (x - y).abs() < 1.5 { 0.3 } else { 0.0 };
            ((b1 + b2 + ridge).min(1.0) * 255.0).round() as u8
        })
        .collect()
}

fn channel_u16(e: Encoded) -> Vec<u16> {
    match e {
        Encoded::Unorm8(v) => v.into_iter().map(u16::from).collect(),
        Encoded::F16(v) => v,
        Encoded::F32(_) => unreachable!("not written to PNG"),
    }
}

/// The samples `ocean cone-map` must write for `map` with `depth` (the R channel).
fn expected(map: &HeightMap, params: ConeParams, encoding: Encoding, depth: &[u16]) -> Vec<u16> {
    let cones = ConeMap::generate(map, params).unwrap();
    let [c, d, e] = [cones.ratios(), cones.clearance(), cones.near_cap()]
        .map(|v| channel_u16(encode(v, encoding)));
    (0..depth.len())
        .flat_map(|k| [depth[k], c[k], d[k], e[k]])
        .collect()
}

/// Default options (relaxed, u8, wrap, cap 1) on an 8-bit grayscale PNG: RGBA8 with
/// R = 255 - height and G/B/A the crate's relaxed cones encoded in 8 bits, bit for bit; the
/// directory then holds only the input and the output.
#[test]
fn writes_the_crates_relief_texture_rgba8() {
    let d = dir("rgba8");
    let h = heights8();
    let input = d.join("height.png");
    write_png(
        &input,
        (24, 24),
        png::ColorType::Grayscale,
        png::BitDepth::Eight,
        &h,
    );
    let output = d.join("relief.png");
    let out = ocean(&[
        "cone-map",
        input.to_str().unwrap(),
        output.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let (w, ht, color, depth, samples) = read_png(&output);
    assert_eq!(
        (w, ht, color, depth),
        (24, 24, png::ColorType::Rgba, png::BitDepth::Eight)
    );
    let map = HeightMap::from_u8(24, 24, &h, Edge::Wrap).unwrap();
    let r: Vec<u16> = h.iter().map(|&v| u16::from(255 - v)).collect();
    let want = expected(&map, ConeParams::relaxed(1.0), Encoding::Unorm8, &r);
    assert_eq!(samples, want);
    // The cones are not all at the cap: the bumps narrow them (else the test would not see a
    // generator at work).
    assert!(samples.chunks(4).any(|t| t[1] < 255));
    assert_eq!(files(&d), ["height.png", "relief.png"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("24x24 relaxed cones"), "{stdout}");
}

/// Every option changed, on a 16-bit input: conservative cones, clamp edges, cap 4, f16.
/// RGBA16 with R = 65535 - height16 and G/B/A the binary16 bits of the crate's cones. The same
/// input with u8-sqrt is rounded to 8 bits first, and R holds those 8-bit depths.
#[test]
fn writes_f16_and_rounds_16_bit_input_for_8_bit_storage() {
    let d = dir("rgba16");
    let h16: Vec<u16> = heights8()
        .iter()
        .enumerate()
        .map(|(k, &v)| (u16::from(v) * 257).saturating_sub((k % 7) as u16 * 13))
        .collect();
    let bytes: Vec<u8> = h16.iter().flat_map(|v| v.to_be_bytes()).collect();
    let input = d.join("height16.png");
    write_png(
        &input,
        (24, 24),
        png::ColorType::Grayscale,
        png::BitDepth::Sixteen,
        &bytes,
    );
    let output = d.join("relief16.png");
    let out = ocean(&[
        "cone-map",
        input.to_str().unwrap(),
        output.to_str().unwrap(),
        "--kind",
        "conservative",
        "--edge",
        "clamp",
        "--max-ratio",
        "4",
        "--encoding",
        "f16",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let (_, _, color, depth, samples) = read_png(&output);
    assert_eq!(
        (color, depth),
        (png::ColorType::Rgba, png::BitDepth::Sixteen)
    );
    let map = HeightMap::from_u16(24, 24, &h16, Edge::Clamp).unwrap();
    let r: Vec<u16> = h16.iter().map(|&v| 65535 - v).collect();
    assert_eq!(
        samples,
        expected(&map, ConeParams::conservative(4.0), Encoding::F16, &r)
    );

    let out8 = d.join("relief8.png");
    let out = ocean(&[
        "cone-map",
        input.to_str().unwrap(),
        out8.to_str().unwrap(),
        "--encoding",
        "u8-sqrt",
    ]);
    assert!(out.status.success());
    let h8: Vec<u8> = h16
        .iter()
        .map(|&v| ((u32::from(v) * 255 + 32767) / 65535) as u8)
        .collect();
    let map8 = HeightMap::from_u8(24, 24, &h8, Edge::Wrap).unwrap();
    let r8: Vec<u16> = h8.iter().map(|&v| u16::from(255 - v)).collect();
    let (_, _, _, depth8, samples8) = read_png(&out8);
    assert_eq!(depth8, png::BitDepth::Eight);
    assert_eq!(
        samples8,
        expected(&map8, ConeParams::relaxed(1.0), Encoding::Unorm8Sqrt, &r8)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("rounded to 8 bits"));
}

/// A grayscale image saved as RGB (R = G = B) gives the grayscale result; a real colour image
/// is refused, naming a pixel.
#[test]
fn gray_saved_as_rgb_is_accepted_and_colour_refused() {
    let d = dir("rgb");
    let h = heights8();
    let gray = d.join("gray.png");
    write_png(
        &gray,
        (24, 24),
        png::ColorType::Grayscale,
        png::BitDepth::Eight,
        &h,
    );
    let rgb = d.join("rgb.png");
    let data: Vec<u8> = h.iter().flat_map(|&v| [v, v, v]).collect();
    write_png(
        &rgb,
        (24, 24),
        png::ColorType::Rgb,
        png::BitDepth::Eight,
        &data,
    );
    let (a, b) = (d.join("a.png"), d.join("b.png"));
    for (i, o) in [(&gray, &a), (&rgb, &b)] {
        let out = ocean(&["cone-map", i.to_str().unwrap(), o.to_str().unwrap()]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    assert_eq!(read_png(&a).4, read_png(&b).4);

    let colour = d.join("colour.png");
    let mut data = data.clone();
    data[3 * (2 * 24 + 5) + 1] ^= 1; // pixel (5, 2): G differs from R
    write_png(
        &colour,
        (24, 24),
        png::ColorType::Rgb,
        png::BitDepth::Eight,
        &data,
    );
    let c = d.join("c.png");
    let out = ocean(&["cone-map", colour.to_str().unwrap(), c.to_str().unwrap()]);
    assert!(!out.status.success());
    let msg = String::from_utf8_lossy(&out.stderr);
    assert!(
        msg.contains("colour image") && msg.contains("(5, 2)"),
        "{msg}"
    );
    assert!(!c.exists());
}

/// A PNG whose image data is damaged (a byte of the compressed stream flipped, so the chunk's
/// CRC fails), a truncated one, a file that is not a PNG and a missing file: exit status 1, a
/// message naming the input, and no output or temporary file.
#[test]
fn corrupt_and_unreadable_inputs_fail_cleanly() {
    let d = dir("corrupt");
    let good = d.join("good.png");
    write_png(
        &good,
        (24, 24),
        png::ColorType::Grayscale,
        png::BitDepth::Eight,
        &heights8(),
    );
    let bytes = std::fs::read(&good).unwrap();
    std::fs::remove_file(&good).unwrap();
    let idat = bytes.windows(4).position(|w| w == b"IDAT").unwrap();
    let mut flipped = bytes.clone();
    flipped[idat + 10] ^= 0x55;
    let cases: [(&str, Vec<u8>, &str); 3] = [
        ("flipped.png", flipped, "corrupt"),
        ("truncated.png", bytes[..idat + 12].to_vec(), "corrupt"),
        (
            "text.png",
            b"this is not an image\n".to_vec(),
            "not a valid PNG",
        ),
    ];
    for (name, data, needle) in cases {
        let input = d.join(name);
        std::fs::write(&input, data).unwrap();
        let output = d.join("out.png");
        let out = ocean(&[
            "cone-map",
            input.to_str().unwrap(),
            output.to_str().unwrap(),
        ]);
        assert_eq!(out.status.code(), Some(1), "{name}");
        let msg = String::from_utf8_lossy(&out.stderr);
        assert!(msg.contains(name) && msg.contains(needle), "{name}: {msg}");
        assert!(!output.exists(), "{name}: output written");
        std::fs::remove_file(&input).unwrap();
        assert!(files(&d).is_empty(), "{name}: left {:?}", files(&d));
    }
    let out = ocean(&[
        "cone-map",
        d.join("missing.png").to_str().unwrap(),
        d.join("out.png").to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(1));
    let msg = String::from_utf8_lossy(&out.stderr);
    assert!(
        msg.contains("cannot read") && msg.contains("missing.png"),
        "{msg}"
    );
    assert!(files(&d).is_empty());
}

/// Non-square, too small and refused options: exit status 1, the reason, no output.
#[test]
fn non_square_and_bad_options_are_refused() {
    let d = dir("refused");
    let input = d.join("wide.png");
    write_png(
        &input,
        (24, 12),
        png::ColorType::Grayscale,
        png::BitDepth::Eight,
        &heights8()[..24 * 12],
    );
    let output = d.join("out.png");
    let out = ocean(&[
        "cone-map",
        input.to_str().unwrap(),
        output.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(1));
    let msg = String::from_utf8_lossy(&out.stderr);
    assert!(msg.contains("24 x 12") && msg.contains("square"), "{msg}");
    assert!(!output.exists());

    let tiny = d.join("tiny.png");
    write_png(
        &tiny,
        (1, 1),
        png::ColorType::Grayscale,
        png::BitDepth::Eight,
        &[7],
    );
    let out = ocean(&["cone-map", tiny.to_str().unwrap(), output.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("4096 x 4096"));

    let square = d.join("square.png");
    write_png(
        &square,
        (24, 24),
        png::ColorType::Grayscale,
        png::BitDepth::Eight,
        &heights8(),
    );
    for (args, needle) in [
        (&["--encoding", "f32"][..], "cannot be stored in a PNG"),
        (&["--max-ratio", "0"][..], "--max-ratio 0"),
        (&["--max-ratio", "65"][..], "--max-ratio 65"),
        // Below one texel of a 4096² map over the whole depth: a cap that means nothing.
        (&["--max-ratio", "1e-30"][..], "(2^-12)"),
        (&["--max-ratio", "NaN"][..], "--max-ratio NaN"),
        (&["--parts", "9"][..], "--parts 9 is above 8"),
    ] {
        let mut all = vec![
            "cone-map",
            square.to_str().unwrap(),
            output.to_str().unwrap(),
        ];
        all.extend_from_slice(args);
        let out = ocean(&all);
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        let msg = String::from_utf8_lossy(&out.stderr);
        assert!(msg.contains(needle), "{args:?}: {msg}");
    }
    assert!(!output.exists());
    assert_eq!(files(&d), ["square.png", "tiny.png", "wide.png"]);
}

/// OUT naming the input, in any spelling (the same path, `.` in it, a hard link), is refused
/// and leaves the height map as it was; with `--force` the texture replaces it.
#[test]
fn the_input_is_never_overwritten_without_force() {
    let d = dir("same_file");
    let input = d.join("heights.png");
    write_png(
        &input,
        (24, 24),
        png::ColorType::Grayscale,
        png::BitDepth::Eight,
        &heights8(),
    );
    let original = std::fs::read(&input).unwrap();
    let link = d.join("link.png");
    std::fs::hard_link(&input, &link).unwrap();
    let dotted = d.join(".").join("heights.png");
    for out in [&input, &dotted, &link] {
        let o = ocean(&["cone-map", input.to_str().unwrap(), out.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(1), "{}", out.display());
        let msg = String::from_utf8_lossy(&o.stderr);
        assert!(
            msg.contains("is the input") && msg.contains("--force"),
            "{msg}"
        );
        assert_eq!(
            std::fs::read(&input).unwrap(),
            original,
            "{}",
            out.display()
        );
    }
    assert_eq!(files(&d), ["heights.png", "link.png"]);
    let o = ocean(&[
        "cone-map",
        input.to_str().unwrap(),
        input.to_str().unwrap(),
        "--force",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (w, h, color, _, _) = read_png(&input);
    assert_eq!((w, h, color), (24, 24, png::ColorType::Rgba));
}

/// Ctrl-C during the generation of a 1024² map (seconds on any machine, in any profile): the
/// command stops, exits with status 130 and says so, and leaves neither the output nor its
/// temporary file.
#[cfg(unix)]
#[test]
fn an_interrupted_generation_leaves_nothing_behind() {
    let d = dir("interrupted");
    let n = 1024u32;
    // Hashed heights: rough everywhere, so no part of the map is quick.
    let heights: Vec<u8> = (0..n * n)
        .map(|i| (i.wrapping_mul(2_654_435_761) >> 24) as u8)
        .collect();
    let input = d.join("in.png");
    write_png(
        &input,
        (n, n),
        png::ColorType::Grayscale,
        png::BitDepth::Eight,
        &heights,
    );
    let output = d.join("out.png");
    let child = Command::new(env!("CARGO_BIN_EXE_ocean"))
        .args([
            "cone-map",
            input.to_str().unwrap(),
            output.to_str().unwrap(),
            "--quiet",
        ])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    std::thread::sleep(std::time::Duration::from_millis(700));
    let kill = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success());
    let out = child.wait_with_output().unwrap();
    let msg = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(130), "{msg}");
    assert!(
        msg.contains("interrupted") && msg.contains("out.png not written"),
        "{msg}"
    );
    assert_eq!(files(&d), ["in.png"]);
}
