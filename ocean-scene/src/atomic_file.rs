//! Files written whole or not at all: the cone cache here, and the images of `ocean render`.

use std::fs::OpenOptions;
use std::io::Write;
use std::path::{Path, PathBuf};

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
