//! `ocean shaders`: every WGSL pass translated through naga, with its binding layout.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

use clap::Args;
use ocean_gpu::shaders::{self, Language};

#[derive(Args)]
pub struct ShadersArgs {
    /// Target language: glsl (330 core for draw passes, 430 core for compute), glsles (ES 310),
    /// hlsl, msl or spirv.
    #[arg(long, value_parser = parse_language)]
    lang: Language,
    /// Directory to write into (created if missing). Each pass gives one file per entry point
    /// (or one module) and a `<pass>.bindings.txt` with its resource bindings.
    #[arg(long)]
    out: PathBuf,
}

fn parse_language(s: &str) -> Result<Language, String> {
    s.parse::<Language>().map_err(|e| e.to_string())
}

pub fn run(args: &ShadersArgs) -> Result<(), String> {
    fs::create_dir_all(&args.out)
        .map_err(|e| format!("cannot create {}: {e}", args.out.display()))?;
    // Translate everything before writing anything, so a failure leaves no partial export.
    let exports = shaders::all()
        .iter()
        .map(|s| shaders::export(s.name, args.lang).map_err(|e| e.to_string()))
        .collect::<Result<Vec<_>, _>>()?;
    for export in &exports {
        for file in &export.files {
            write_atomic(&args.out.join(&file.file_name), file.code.as_bytes())?;
            println!("{}", args.out.join(&file.file_name).display());
        }
        let table = args.out.join(format!("{}.bindings.txt", export.shader));
        write_atomic(&table, export.bindings_table().as_bytes())?;
        println!("{}", table.display());
    }
    Ok(())
}

/// Writes `bytes` to a temporary file beside `path`, then renames it into place: readers see
/// either the old file or the whole new one, never a half-written file.
fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), String> {
    let name = path
        .file_name()
        .ok_or_else(|| format!("{} has no file name", path.display()))?;
    let tmp = path.with_file_name(format!(".{}.tmp", name.to_string_lossy()));
    let result = (|| {
        let mut f = fs::File::create(&tmp)?;
        f.write_all(bytes)?;
        f.sync_all()?;
        fs::rename(&tmp, path)
    })();
    result.map_err(|e| {
        let _ = fs::remove_file(&tmp);
        format!("cannot write {}: {e}", path.display())
    })
}
