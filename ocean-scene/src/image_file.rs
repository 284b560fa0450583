//! Image files: PNG encoding, and files written whole or not at all (the cone cache here, the
//! frames of `ocean render` and the plots of `ocean bench`).

use std::fs::OpenOptions;
use std::io::Write;
use std::path::{Path, PathBuf};

/// `data` (rows from the top, big-endian samples for 16 bits) as PNG bytes, compressed with
/// fdeflate's PNG-tuned fast mode: several times faster than the default level for about the
/// same size on rendered images.
///
/// # Errors
///
/// The encoder's, for a size that does not match `data`.
pub fn encode_png(
    width: u32,
    height: u32,
    color: png::ColorType,
    depth: png::BitDepth,
    data: &[u8],
) -> Result<Vec<u8>, String> {
    let mut bytes = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut bytes, width, height);
        enc.set_color(color);
        enc.set_depth(depth);
        enc.set_compression(png::Compression::Fast);
        let mut w = enc.write_header().map_err(|e| e.to_string())?;
        w.write_image_data(data).map_err(|e| e.to_string())?;
        w.finish().map_err(|e| e.to_string())?;
    }
    Ok(bytes)
}

/// Writes `bytes` to `path` atomically: a hidden temporary file in the same directory, flushed
/// to disk, then renamed over `path`. `before_rename` runs last, the moment a caller can still
/// stop the write without leaving a file (an interruption): its error fails the write. The
/// temporary file is removed on any failure.
///
/// # Errors
///
/// The file system's, naming `path`, or `before_rename`'s.
pub fn write_atomically(
    path: &Path,
    bytes: &[u8],
    before_rename: impl FnOnce() -> Result<(), String>,
) -> Result<(), String> {
    let p = path.display();
    let name = path
        .file_name()
        .ok_or_else(|| format!("{p} does not name a file"))?;
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let tmp = dir.join(format!(
        ".{}.tmp-{}",
        name.to_string_lossy(),
        std::process::id()
    ));
    let result = (|| -> Result<(), String> {
        let mut f = OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&tmp)
            .map_err(|e| format!("cannot write {p}: {e}"))?;
        f.write_all(bytes)
            .and_then(|()| f.sync_all())
            .map_err(|e| format!("cannot write {p}: {e}"))?;
        before_rename()?;
        std::fs::rename(&tmp, path).map_err(|e| format!("cannot write {p}: {e}"))
    })();
    result.inspect_err(|_| {
        let _ = std::fs::remove_file(&tmp);
    })
}
