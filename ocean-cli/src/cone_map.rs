//! `ocean cone-map HEIGHT.png OUT.png`: a relief texture (depth and cone channels) from a
//! height-map PNG, by ocean-relief's generator (`ConeMap::generate_with`).
//!
//! See [`FORMAT`] for what is read and written; it is the command's long help.

use std::fs::File;
use std::io::{BufRead, BufReader, IsTerminal, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::{Args, ValueEnum};
use ocean_relief::storage::{Encoded, Encoding, encode};
use ocean_relief::{ConeMap, ConeParams, Edge, HeightMap, MAX_PARTS, MAX_RATIO_LIMIT, MAX_SIDE};

/// The long help: input conversions and the output format.
pub const FORMAT: &str = "\
INPUT: a PNG whose pixels are heights (white = the polygon surface, black = the bottom of the \
relief), square, 2x2 to 4096x4096 pixels (ocean-relief's cap), any PNG bit depth:
  - grayscale, 8 or 16 bits (1, 2 and 4 bits are expanded to 8): used as they are;
  - gray + alpha: the gray channel; alpha is ignored;
  - RGB, RGBA and palette images: accepted only when every pixel has R = G = B (a grayscale \
image saved as colour), then that channel; alpha is ignored; any other colour image is refused \
(convert it to grayscale first: no luminance weighting is guessed).
A 16-bit input keeps 16 bits with --encoding f16; the 8-bit encodings round it to 8 bits \
(nearest) before generating, so that the cones are valid for exactly the depths stored.

OUTPUT: a PNG with the relief texture, row 0 at the top as in the input:
  - --encoding u8 / u8-sqrt: RGBA, 8 bits. R = depth = 255 - height (the book's convention: 0 \
at the polygon surface); G = cone ratio c, B = clearance D, A = near cap E, each clamped to 1.0 \
and rounded down: k = floor(255 v), read back as k/255 (u8) or k = floor(255 sqrt(v)), read \
back as (k/255)^2 (u8-sqrt).
  - --encoding f16: RGBA, 16 bits. R = depth as 16-bit unorm = 65535 - height16 (an 8-bit \
height v is height16 = 257 v, exact); G, B, A = the IEEE binary16 bit patterns of c, D, E, \
rounded toward zero (up to 65504). Read the file's samples as uint16 and reinterpret G, B, A \
as half floats.
  - --encoding f32: refused (a PNG holds 16 bits per channel at most); the C ABI \
(ocean_relief_generate_texels) gives float cones.
c and E are in texture widths per unit of depth, D in texture widths (see ocean-relief's cone \
module): a ray h above the surface may step with the cone max(c, min(D/h, E)); a one-channel \
tracer (the book's) uses c alone.

The output is written to a hidden temporary file in the same directory and renamed over OUT \
only when complete: a failure or a crash never leaves a partial OUT. Ctrl-C, SIGTERM and \
SIGHUP stop the generation (exit status 130) and remove the temporary file; a second signal \
exits at once. Progress goes to stderr as a bar when stderr is a terminal \
(nothing otherwise, or with --quiet).";

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Kind {
    /// Relaxed cones (section 18.4): for relaxed cone stepping.
    Relaxed,
    /// Conservative cones (Dummer 2006): for cone step mapping.
    Conservative,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum StorageArg {
    /// RGBA8, cones as k/255, clamped to 1.
    U8,
    /// RGBA8, cones as (k/255)^2, clamped to 1.
    U8Sqrt,
    /// RGBA16: depth as unorm16, cones as binary16 bit patterns.
    F16,
    /// Refused: a PNG holds 16 bits per channel at most.
    F32,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum EdgeArg {
    /// The texture tiles (sampler addressing repeat).
    Wrap,
    /// The border texels extend outwards (clamp-to-edge).
    Clamp,
}

#[derive(Args)]
pub struct ConeMapArgs {
    /// The height map (PNG; see below).
    input: PathBuf,
    /// The relief texture to write (PNG; see below). Replaced atomically if it exists; never
    /// the input itself without --force.
    output: PathBuf,
    /// Which cones.
    #[arg(long, value_enum, default_value_t = Kind::Relaxed)]
    kind: Kind,
    /// How the cone channels are stored.
    #[arg(long, value_enum, default_value_t = StorageArg::U8)]
    encoding: StorageArg,
    /// What lies beyond the map's borders (use the sampler's addressing mode).
    #[arg(long, value_enum, default_value_t = EdgeArg::Wrap)]
    edge: EdgeArg,
    /// Cap on the cone ratios and clearances, texture widths (per unit depth), in [2^-12, 64]
    /// (2^-12: one texel of the largest map across the whole relief depth). The 8-bit encodings
    /// store at most 1.0.
    #[arg(long, default_value_t = 1.0)]
    max_ratio: f32,
    /// How finely the cones are bounded, 0 to 8: the apex and candidate cells are halved this
    /// many times in turn. 0 bounds whole cells (what the GPU generator computes); each step
    /// widens the cones a little and costs more time (default 2: about 7 % wider than 0 on
    /// average for twice the time; 4: about 10 % wider for three to five times the time).
    #[arg(long, default_value_t = ocean_relief::DEFAULT_PARTS)]
    parts: u32,
    /// Allow OUT to be the input file (it is replaced only once the texture is complete).
    #[arg(long)]
    force: bool,
    /// No progress bar.
    #[arg(long)]
    quiet: bool,
}

/// Smallest `--max-ratio`: one texel of the largest map (`MAX_SIDE` = 4096) per unit depth.
const MIN_RATIO: f32 = 1.0 / 4096.0;
const _: () = assert!(MAX_SIDE == 4096);

/// Whether `a` and `b` name one existing file (through links, `..` or another spelling).
fn same_file(a: &Path, b: &Path) -> bool {
    match (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
        (Ok(a), Ok(b)) if a == b => true,
        #[cfg(unix)]
        _ => {
            // Hard links: one inode under two names.
            use std::os::unix::fs::MetadataExt;
            match (std::fs::metadata(a), std::fs::metadata(b)) {
                (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
                _ => false,
            }
        }
        #[cfg(not(unix))]
        _ => false,
    }
}

/// Heights as read from the PNG.
#[derive(Clone, Debug, PartialEq)]
pub enum Heights {
    U8(Vec<u8>),
    U16(Vec<u16>),
}

/// A square height map read from a PNG.
#[derive(Clone, Debug, PartialEq)]
pub struct HeightImage {
    pub side: usize,
    pub heights: Heights,
}

/// The largest ratio of decompressed to compressed size of zlib's deflate (RFC 1951): a run
/// of 258 repeated bytes costs at least 2 bits, so 1 byte expands to at most 1032 bytes. The
/// image data of a PNG cannot be larger than this many times the file.
const MAX_INFLATE_RATIO: u64 = 1032;

/// Reads and converts a height-map PNG (see [`FORMAT`]).
pub fn read_heights(path: &Path) -> Result<HeightImage, String> {
    let file = File::open(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    decode_heights(BufReader::new(file), &path.display().to_string())
}

/// Converts the height-map PNG that `input` yields (see [`FORMAT`]); `p` names it in messages.
/// [`read_heights`] without the file, so the PNG can come from memory (the `height_png` fuzz
/// target, `fuzz/fuzz_targets/height_png.rs`).
pub fn decode_heights(mut input: impl BufRead + Seek, p: &str) -> Result<HeightImage, String> {
    let io = |e: std::io::Error| format!("cannot read {p}: {e}");
    let start = input.stream_position().map_err(io)?;
    let bytes = input.seek(SeekFrom::End(0)).map_err(io)? - start;
    input.seek(SeekFrom::Start(start)).map_err(io)?;
    let mut decoder = ::png::Decoder::new(input);
    decoder.set_transformations(::png::Transformations::EXPAND);
    let mut reader = decoder.read_info().map_err(|e| match e {
        ::png::DecodingError::IoError(e) => format!("cannot read {p}: {e}"),
        e => format!("{p} is not a valid PNG file: {e}"),
    })?;
    let (w, h) = (reader.info().width, reader.info().height);
    if w != h {
        return Err(format!(
            "{p} is {w} x {h} pixels: relief height maps must be square (cone ratios are measured \
             in texture widths, which are only isotropic on a square)"
        ));
    }
    let side = w as usize;
    if !(HeightMap::MIN_SIDE..=MAX_SIDE).contains(&side) {
        return Err(format!(
            "{p} is {w} x {h} pixels, outside the supported {0} x {0} to {MAX_SIDE} x {MAX_SIDE}",
            HeightMap::MIN_SIDE
        ));
    }
    // The png crate (0.18.1) panics expanding a palette that is not a whole number of RGB
    // triples, or shorter than its transparency table, instead of refusing the file: refuse it
    // here first (found by the height_png fuzz target; the input is kept in its corpus).
    if let Some(palette) = &reader.info().palette {
        let entries = palette.len() / 3;
        let alphas = reader.info().trns.as_ref().map_or(0, |t| t.len());
        if palette.len() % 3 != 0 || alphas > entries {
            return Err(format!(
                "{p} is corrupt: its palette (PLTE) has {} bytes, {alphas} transparency entries: \
                 not a whole number of RGB entries, each with at most one alpha",
                palette.len()
            ));
        }
    }
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| format!("{p}: the decoded image would not fit in memory"))?;
    // Refused before the buffer is allocated: otherwise a header of a hundred bytes that
    // declares 4096 x 4096 RGBA16 pixels makes this allocate 128 MiB, only to find no data
    // (found by the height_png fuzz target, fuzz/fuzz_targets/height_png.rs). The pixels as
    // stored (before the expansion to 8 bits) come out of zlib, so they are at most
    // MAX_INFLATE_RATIO times the file.
    let stored = u64::from(w) * u64::from(h) * reader.info().bits_per_pixel() as u64 / 8;
    if stored > MAX_INFLATE_RATIO.saturating_mul(bytes) {
        return Err(format!(
            "{p} is corrupt: its header declares {w} x {h} pixels ({stored} bytes of samples), \
             more than its {bytes} bytes can hold (zlib expands data at most \
             {MAX_INFLATE_RATIO} times)"
        ));
    }
    let mut buf = vec![0u8; size];
    let frame = reader
        .next_frame(&mut buf)
        .map_err(|e| format!("{p} is corrupt: its image data cannot be decoded: {e}"))?;
    let channels = match frame.color_type {
        ::png::ColorType::Grayscale => 1,
        ::png::ColorType::GrayscaleAlpha => 2,
        ::png::ColorType::Rgb => 3,
        ::png::ColorType::Rgba => 4,
        ::png::ColorType::Indexed => {
            return Err(format!(
                "{p}: a palette image was not expanded to RGB by the decoder (unsupported)"
            ));
        }
    };
    let colour = matches!(
        frame.color_type,
        ::png::ColorType::Rgb | ::png::ColorType::Rgba
    );
    let bytes = match frame.bit_depth {
        ::png::BitDepth::Eight => 1,
        ::png::BitDepth::Sixteen => 2,
        d => {
            return Err(format!(
                "{p}: {} bit samples were not expanded to 8 bits by the decoder (unsupported)",
                d as u8
            ));
        }
    };
    let sample = |x: usize, y: usize, c: usize| -> u16 {
        let at = y * frame.line_size + (x * channels + c) * bytes;
        if bytes == 1 {
            u16::from(buf[at])
        } else {
            u16::from_be_bytes([buf[at], buf[at + 1]])
        }
    };
    let mut values = Vec::with_capacity(side * side);
    for y in 0..side {
        for x in 0..side {
            let v = sample(x, y, 0);
            if colour {
                let (g, b) = (sample(x, y, 1), sample(x, y, 2));
                if g != v || b != v {
                    return Err(format!(
                        "{p} is a colour image (pixel ({x}, {y}) has R, G, B = {v}, {g}, {b}): \
                         height maps must be grayscale; convert it first"
                    ));
                }
            }
            values.push(v);
        }
    }
    let heights = if bytes == 1 {
        Heights::U8(values.into_iter().map(|v| v as u8).collect())
    } else {
        Heights::U16(values)
    };
    Ok(HeightImage { side, heights })
}

/// A 16-bit height rounded to the nearest 8-bit one.
pub fn round_to_u8(v: u16) -> u8 {
    ((u32::from(v) * 255 + 32767) / 65535) as u8
}

/// The relief texture of `image` as PNG bytes, with its side: what `ocean cone-map` writes.
pub fn relief_png(
    image: &HeightImage,
    params: ConeParams,
    edge: Edge,
    encoding: Encoding,
    progress: &mut impl FnMut(usize, usize) -> bool,
) -> Result<Vec<u8>, String> {
    let n = image.side;
    let eight = matches!(encoding, Encoding::Unorm8 | Encoding::Unorm8Sqrt);
    // The heights whose depths the texture stores (see FORMAT): 8 bits for the 8-bit
    // encodings, else as read.
    let heights = match (&image.heights, eight) {
        (Heights::U16(v), true) => Heights::U8(v.iter().map(|&h| round_to_u8(h)).collect()),
        (h, _) => h.clone(),
    };
    let map = match &heights {
        Heights::U8(v) => HeightMap::from_u8(n, n, v, edge),
        Heights::U16(v) => HeightMap::from_u16(n, n, v, edge),
    }
    .map_err(|e| e.to_string())?;
    let cones = ConeMap::generate_with(&map, params, progress).map_err(|e| e.to_string())?;
    let channels =
        [cones.ratios(), cones.clearance(), cones.near_cap()].map(|v| encode(v, encoding));
    let mut data = Vec::with_capacity(n * n * if eight { 4 } else { 8 });
    match (&channels, &heights) {
        ([Encoded::Unorm8(c), Encoded::Unorm8(d), Encoded::Unorm8(e)], Heights::U8(h)) => {
            for k in 0..n * n {
                data.extend_from_slice(&[255 - h[k], c[k], d[k], e[k]]);
            }
        }
        ([Encoded::F16(c), Encoded::F16(d), Encoded::F16(e)], h) => {
            for k in 0..n * n {
                let depth = match h {
                    Heights::U8(h) => 257 * u16::from(255 - h[k]),
                    Heights::U16(h) => 65535 - h[k],
                };
                for v in [depth, c[k], d[k], e[k]] {
                    data.extend_from_slice(&v.to_be_bytes());
                }
            }
        }
        _ => return Err(format!("{encoding:?} cannot be stored in a PNG")),
    }
    ocean_scene::image_file::encode_png(
        n as u32,
        n as u32,
        ::png::ColorType::Rgba,
        if eight {
            ::png::BitDepth::Eight
        } else {
            ::png::BitDepth::Sixteen
        },
        &data,
    )
}

/// The progress bar: redrawn on stderr when it is a terminal.
struct Bar {
    enabled: bool,
    last: Option<usize>,
}

impl Bar {
    fn report(&mut self, done: usize, total: usize) {
        if !self.enabled || total == 0 {
            return;
        }
        let pct = done * 100 / total;
        if self.last == Some(pct) {
            return;
        }
        self.last = Some(pct);
        let filled = done * 40 / total;
        let mut err = std::io::stderr().lock();
        let _ = write!(
            err,
            "\rcone map [{}{}] {pct:3}%",
            "#".repeat(filled),
            ".".repeat(40 - filled)
        );
        if done == total {
            let _ = writeln!(err);
        }
        let _ = err.flush();
    }
}

pub fn run(args: &ConeMapArgs) -> Result<(), String> {
    let encoding = match args.encoding {
        StorageArg::U8 => Encoding::Unorm8,
        StorageArg::U8Sqrt => Encoding::Unorm8Sqrt,
        StorageArg::F16 => Encoding::F16,
        StorageArg::F32 => {
            return Err(
                "--encoding f32 cannot be stored in a PNG (16 bits per channel at \
                        most): use --encoding f16 (rounded down, up to 65504) or the C ABI's \
                        ocean_relief_generate_texels for float cones"
                    .into(),
            );
        }
    };
    if !(MIN_RATIO..=MAX_RATIO_LIMIT).contains(&args.max_ratio) {
        return Err(format!(
            "--max-ratio {} is outside [{MIN_RATIO} (2^-12), {MAX_RATIO_LIMIT}]: a smaller cap \
             makes every cone narrower than one texel of a 4096 x 4096 map across the whole \
             relief depth",
            args.max_ratio
        ));
    }
    if args.parts > MAX_PARTS {
        return Err(format!(
            "--parts {} is above {MAX_PARTS}: finer parts than 1/16 of a texel widen no cone \
             measurably and multiply the time",
            args.parts
        ));
    }
    if !args.force && same_file(&args.input, &args.output) {
        return Err(format!(
            "{} is the input: writing the texture there would replace the height map (choose \
             another OUT, or pass --force)",
            args.output.display()
        ));
    }
    let params = match args.kind {
        Kind::Relaxed => ConeParams::relaxed(args.max_ratio),
        Kind::Conservative => ConeParams::conservative(args.max_ratio),
    }
    .with_parts(args.parts);
    let edge = match args.edge {
        EdgeArg::Wrap => Edge::Wrap,
        EdgeArg::Clamp => Edge::Clamp,
    };
    crate::interrupt::install()?;
    let image = read_heights(&args.input)?;
    let mut bar = Bar {
        enabled: !args.quiet && std::io::stderr().is_terminal(),
        last: None,
    };
    let start = Instant::now();
    let bytes = relief_png(&image, params, edge, encoding, &mut |done, total| {
        bar.report(done, total);
        !crate::interrupt::requested()
    })
    .map_err(|e| {
        if crate::interrupt::requested() {
            format!(
                "{}: {} not written",
                crate::interrupt::MESSAGE,
                args.output.display()
            )
        } else {
            e
        }
    })?;
    let seconds = start.elapsed().as_secs_f64();
    crate::png::write_atomically(&args.output, &bytes)?;
    let n = image.side;
    let bits = match (&image.heights, encoding) {
        (Heights::U16(_), Encoding::Unorm8 | Encoding::Unorm8Sqrt) => {
            " (16-bit heights rounded to 8 bits)"
        }
        _ => "",
    };
    println!(
        "{}: {n}x{n} {} cones, {} edges, cap {}, {} ({}){bits}; generated in {seconds:.2} s",
        args.output.display(),
        match args.kind {
            Kind::Relaxed => "relaxed",
            Kind::Conservative => "conservative",
        },
        match edge {
            Edge::Wrap => "wrapped",
            Edge::Clamp => "clamped",
        },
        args.max_ratio,
        match encoding {
            Encoding::Unorm8 => "u8",
            Encoding::Unorm8Sqrt => "u8-sqrt",
            _ => "f16",
        },
        if matches!(encoding, Encoding::F16) {
            "RGBA16: R depth unorm16, G/B/A cone, clearance, near cap as binary16"
        } else {
            "RGBA8: R depth, G cone, B clearance, A near cap"
        },
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// CRC-32 of PNG chunks (ISO 3309, the polynomial reflected), bit by bit.
    fn crc32(bytes: &[u8]) -> u32 {
        let mut c = !0u32;
        for &b in bytes {
            c ^= u32::from(b);
            for _ in 0..8 {
                c = if c & 1 == 1 {
                    0xedb8_8320 ^ (c >> 1)
                } else {
                    c >> 1
                };
            }
        }
        !c
    }

    fn chunk(out: &mut Vec<u8>, kind: &[u8; 4], data: &[u8]) {
        out.extend_from_slice(&(data.len() as u32).to_be_bytes());
        let start = out.len();
        out.extend_from_slice(kind);
        out.extend_from_slice(data);
        let crc = crc32(&out[start..]);
        out.extend_from_slice(&crc.to_be_bytes());
    }

    #[test]
    fn a_header_larger_than_its_file_can_hold_is_refused_before_decoding() {
        // 4096 x 4096 RGBA, 16 bits: 128 MiB of samples declared by a file of 65 bytes, whose
        // IDAT is an empty zlib stream (78 9c 03 00 00 00 00 01). Refused with the sizes, not
        // with the decoder's error after allocating the 128 MiB output buffer.
        let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
        let mut ihdr = Vec::new();
        ihdr.extend_from_slice(&4096u32.to_be_bytes());
        ihdr.extend_from_slice(&4096u32.to_be_bytes());
        ihdr.extend_from_slice(&[16, 6, 0, 0, 0]);
        chunk(&mut png, b"IHDR", &ihdr);
        chunk(
            &mut png,
            b"IDAT",
            &[0x78, 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01],
        );
        chunk(&mut png, b"IEND", &[]);
        assert_eq!(png.len(), 65);
        let e = decode_heights(std::io::Cursor::new(&png), "bomb.png").unwrap_err();
        assert!(
            e.starts_with(
                "bomb.png is corrupt: its header declares 4096 x 4096 pixels (134217728 bytes \
                 of samples), more than its 65 bytes can hold"
            ),
            "{e}"
        );
    }

    /// A 2 x 2 palette image, 8-bit indices 0, 1, 1, 0, with the given PLTE and tRNS data.
    fn palette_png(plte: &[u8], trns: &[u8]) -> Vec<u8> {
        let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
        let mut ihdr = Vec::new();
        ihdr.extend_from_slice(&2u32.to_be_bytes());
        ihdr.extend_from_slice(&2u32.to_be_bytes());
        ihdr.extend_from_slice(&[8, 3, 0, 0, 0]);
        chunk(&mut png, b"IHDR", &ihdr);
        chunk(&mut png, b"PLTE", plte);
        if !trns.is_empty() {
            chunk(&mut png, b"tRNS", trns);
        }
        // zlib, stored block: the rows [filter 0, 0, 1] and [filter 0, 1, 0], then Adler-32.
        let raw = [0u8, 0, 1, 0, 1, 0];
        let mut idat = vec![0x78, 0x01, 0x01, 6, 0, !6, 0xff];
        idat.extend_from_slice(&raw);
        let (a, b) = raw.iter().fold((1u32, 0u32), |(a, b), &x| {
            let a = (a + u32::from(x)) % 65521;
            (a, (b + a) % 65521)
        });
        idat.extend_from_slice(&((b << 16) | a).to_be_bytes());
        chunk(&mut png, b"IDAT", &idat);
        chunk(&mut png, b"IEND", &[]);
        png
    }

    #[test]
    fn a_palette_that_is_not_whole_rgb_entries_is_refused_not_a_panic() {
        // Two grays: the reference file, accepted (indices 0, 1 read as gray 16 and 200).
        let good = palette_png(&[16, 16, 16, 200, 200, 200], &[]);
        let image = decode_heights(std::io::Cursor::new(&good), "good.png").unwrap();
        assert_eq!(image.heights, Heights::U8(vec![16, 200, 200, 16]));
        // 7 bytes (two entries and one stray byte): png 0.18.1 panics on this in
        // `create_rgba_palette`; refused with the sizes instead.
        let odd = palette_png(&[16, 16, 16, 200, 200, 200, 9], &[]);
        let e = decode_heights(std::io::Cursor::new(&odd), "odd.png").unwrap_err();
        assert_eq!(
            e,
            "odd.png is corrupt: its palette (PLTE) has 7 bytes, 0 transparency entries: not a \
             whole number of RGB entries, each with at most one alpha"
        );
    }

    #[test]
    fn a_legitimately_well_compressed_image_is_accepted() {
        // 1024 x 1024 at 1 bit, all black: 128 KiB of samples deflate to a few hundred
        // bytes, yet at most 1032 times less, so the bound above never refuses a real file.
        let mut png = Vec::new();
        let mut enc = ::png::Encoder::new(&mut png, 1024, 1024);
        enc.set_color(::png::ColorType::Grayscale);
        enc.set_depth(::png::BitDepth::One);
        let mut w = enc.write_header().unwrap();
        w.write_image_data(&vec![0u8; 1024 * 1024 / 8]).unwrap();
        w.finish().unwrap();
        assert!(png.len() * 1032 >= 1024 * 1024 / 8, "{} bytes", png.len());
        let image = decode_heights(std::io::Cursor::new(&png), "black.png").unwrap();
        assert_eq!(image.side, 1024);
        assert_eq!(image.heights, Heights::U8(vec![0; 1024 * 1024]));
    }
}
