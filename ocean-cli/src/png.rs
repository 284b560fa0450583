//! PNG files of the command: atomic writing that an interruption stops, and the height maps
//! `ocean cone-map` reads. Every file is written to a hidden temporary name and renamed when
//! complete, so a failure or an interruption never leaves a half-written image; encoding is
//! `ocean_scene::image_file::encode_png`.

use std::path::Path;

/// Writes `bytes` to `path` atomically (`ocean_scene::image_file`), failing instead when an
/// interruption was asked for before the rename ([`crate::interrupt`]).
///
/// # Errors
///
/// The file system's, or the interruption, naming `path`.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), String> {
    ocean_scene::image_file::write_atomically(path, bytes, || {
        // The last moment an interruption can stop the job without leaving a file behind.
        if crate::interrupt::requested() {
            return Err(format!(
                "{}: {} not written",
                crate::interrupt::MESSAGE,
                path.display()
            ));
        }
        Ok(())
    })
}
