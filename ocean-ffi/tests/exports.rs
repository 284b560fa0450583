//! The crate's re-export list (`src/lib.rs`) names every item of the C ABI: each
//! `#[unsafe(no_mangle)]` function and each public struct, enum and `OCEAN_*` constant
//! declared in a module, so that Rust users of the `ocean` crate reach what C users reach.
//! The list is written by hand (rustfmt keeps it readable); this test keeps it complete.

use std::collections::BTreeSet;
use std::path::Path;

/// The Rust sources under `dir`, its subdirectories included.
fn sources(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// Public items of the C ABI declared in the module sources (tests excluded), in `src/` and
/// its subdirectories (`src/boundary/` declares the extension chain's types).
fn declared() -> BTreeSet<String> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut items = BTreeSet::new();
    let mut paths = Vec::new();
    sources(&src, &mut paths);
    for path in paths {
        if path == src.join("lib.rs") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        // Everything after the first test module is test code.
        let text = text.split("#[cfg(test)]").next().unwrap();
        let mut no_mangle = false;
        for line in text.lines() {
            let line = line.trim_start();
            if line.starts_with("#[unsafe(no_mangle)]") {
                no_mangle = true;
                continue;
            }
            let words: Vec<&str> = line
                .split(|c: char| !(c.is_alphanumeric() || c == '_' || c == '"'))
                .filter(|w| !w.is_empty())
                .collect();
            let item = match words.as_slice() {
                ["pub", "unsafe", "extern", "\"C\"", "fn", name, ..]
                | ["pub", "extern", "\"C\"", "fn", name, ..]
                    if no_mangle =>
                {
                    Some(*name)
                }
                ["pub", "struct" | "enum" | "type", name, ..] if name.starts_with("Ocean") => {
                    Some(*name)
                }
                ["pub", "const", name, ..] if name.starts_with("OCEAN_") => Some(*name),
                _ => None,
            };
            if let Some(item) = item {
                items.insert(item.to_owned());
            }
            if !line.starts_with("#[") && !line.starts_with("///") {
                no_mangle = false;
            }
        }
    }
    items
}

/// Names in the `pub use` statements of `lib.rs`.
fn reexported() -> BTreeSet<String> {
    let lib =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("src/lib.rs")).unwrap();
    let mut names = BTreeSet::new();
    for statement in lib.split(';') {
        let Some(start) = statement.find("pub use ") else {
            continue;
        };
        let list = &statement[start..];
        let list = list.split_once('{').map_or(list, |(_, l)| l);
        for name in list.split(|c: char| !(c.is_alphanumeric() || c == '_')) {
            if name.starts_with("ocean_") || name.starts_with("Ocean") || name.starts_with("OCEAN_")
            {
                names.insert(name.to_owned());
            }
        }
    }
    names
}

#[test]
fn every_c_abi_item_is_reexported() {
    let declared = declared();
    // The scan finds the C ABI (more than 130 functions, the handle types, the constants).
    assert!(declared.len() > 200, "only {} items found", declared.len());
    assert!(declared.contains("ocean_waves_evaluate") && declared.contains("OceanWtbScene"));
    let reexported = reexported();
    let missing: Vec<_> = declared.difference(&reexported).collect();
    assert!(
        missing.is_empty(),
        "not re-exported from lib.rs: {missing:?}"
    );
    let stale: Vec<_> = reexported.difference(&declared).collect();
    assert!(stale.is_empty(), "re-exported but not declared: {stale:?}");
}
