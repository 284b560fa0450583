//! Helpers shared by the command's end-to-end tests.

use std::path::{Path, PathBuf};
use std::process::Output;

/// A fresh, empty directory `group/name` under Cargo's temporary directory for the tests.
pub fn dir(group: &str, name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(group)
        .join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The names of the files in `d`, sorted.
// Each test binary compiles this module; not all of them list files.
#[allow(dead_code)]
pub fn files(d: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(d)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// Whether a failed render failed for want of an adapter (then skipped, with the reason on
/// stderr); panics on that under `OCEAN_REQUIRE_GPU=1`.
// Each test binary compiles this module; not all of them render.
#[allow(dead_code)]
pub fn no_adapter(out: &Output) -> bool {
    let msg = String::from_utf8_lossy(&out.stderr);
    let missing = !out.status.success() && msg.contains("no GPU adapter found");
    if missing && std::env::var("OCEAN_REQUIRE_GPU").as_deref() == Ok("1") {
        panic!("OCEAN_REQUIRE_GPU=1 but no adapter: {msg}");
    }
    if missing {
        eprintln!("skipped: {msg}");
    }
    missing
}

/// Decodes a PNG: (width, height, colour type, bit depth, samples as u16).
// Each test binary compiles this module; not all of them read PNGs.
#[allow(dead_code)]
pub fn read_png(path: &Path) -> (u32, u32, png::ColorType, png::BitDepth, Vec<u16>) {
    let file = std::fs::File::open(path).unwrap();
    let mut reader = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .unwrap();
    let mut buf = vec![0u8; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    buf.truncate(info.buffer_size());
    let samples = match info.bit_depth {
        png::BitDepth::Sixteen => buf
            .chunks(2)
            .map(|b| u16::from_be_bytes([b[0], b[1]]))
            .collect(),
        _ => buf.iter().map(|&b| u16::from(b)).collect(),
    };
    (
        info.width,
        info.height,
        info.color_type,
        info.bit_depth,
        samples,
    )
}
