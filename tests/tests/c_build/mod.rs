//! What the C ABI tests share (`tests/tests/c_abi.rs`, `tests/tests/c_matrix.rs`): where
//! `libocean.a` is, the compiler, the flags, and running a command.
//!
//! Where the library comes from: `ocean-tests` depends on `ocean-ffi`, and cargo builds every
//! crate type of a dependency, so by the time a C ABI test runs `libocean.a` (crate-type
//! `staticlib`, lib name `ocean`) is fresh in the profile directory its test binary lives in
//! (`<target>/<profile>/deps/<test>-<hash>`). Observed with cargo 1.95: as a dependency it lands in
//! `<target>/<profile>/deps/libocean.a` (no hash in the name); built as a root package
//! (`cargo build -p ocean-ffi`, `cargo test --workspace`) it is also uplifted to
//! `<target>/<profile>/libocean.a`. [`libocean`] derives the profile directory from the test
//! binary's path (so `CARGO_TARGET_DIR` and `--release` work), collects `libocean.a` and
//! `libocean-*.a` (or the shared library) from both places and returns the newest, after checking
//! that it is not older than the `ocean-ffi` sources. It never runs cargo (that would wait
//! forever on the build lock that the `cargo test` running the test holds).
//!
//! Compilers: `$CC` / `$CXX`, else `cc` / `c++`. A missing compiler fails the test with a message;
//! it never passes silently.

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::SystemTime;

/// System libraries the Rust standard library inside `libocean.a` needs, as printed by
/// `cargo rustc -p ocean-ffi --lib --crate-type staticlib -- --print native-static-libs`
/// (x86_64-unknown-linux-gnu, Rust 1.95: `-lgcc_s -lutil -lrt -lpthread -lm -ldl -lc`).
#[cfg(target_os = "macos")]
pub const NATIVE_STATIC_LIBS: &[&str] = &["-lSystem", "-lc", "-lm"];
#[cfg(not(target_os = "macos"))]
pub const NATIVE_STATIC_LIBS: &[&str] = &[
    "-lgcc_s",
    "-lutil",
    "-lrt",
    "-lpthread",
    "-lm",
    "-ldl",
    "-lc",
];

pub const WARNINGS: &[&str] = &["-Wall", "-Wextra", "-Werror", "-pedantic"];

/// The workspace builds ocean-ffi with its `gpu` feature, the full library: its programs
/// declare the GPU entry points as the full library's packages do (`include/ocean.h`
/// declares them only where `OCEAN_GPU` is defined).
pub const FULL_LIBRARY: &str = "-DOCEAN_GPU";

pub fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("tests/ has a parent")
        .to_path_buf()
}

fn mtime(p: &Path) -> SystemTime {
    std::fs::metadata(p)
        .and_then(|m| m.modified())
        .unwrap_or_else(|e| panic!("cannot stat {}: {e}", p.display()))
}

/// Newest modification time of the files under `dir`.
fn newest_source(dir: &Path) -> SystemTime {
    let mut newest = SystemTime::UNIX_EPOCH;
    for entry in std::fs::read_dir(dir).unwrap_or_else(|e| panic!("read {}: {e}", dir.display())) {
        let path = entry.expect("directory entry").path();
        let t = if path.is_dir() {
            newest_source(&path)
        } else {
            mtime(&path)
        };
        newest = newest.max(t);
    }
    newest
}

/// The profile directory (`<target>/<profile>`) this test binary was built into.
fn profile_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("path of the test binary");
    let deps = exe.parent().expect("test binary has a parent directory");
    assert_eq!(
        deps.file_name().and_then(|n| n.to_str()),
        Some("deps"),
        "expected the test binary in <target>/<profile>/deps, found {}",
        exe.display()
    );
    deps.parent().expect("deps has a parent").to_path_buf()
}

/// The freshest `libocean.a` of this profile (see the module documentation), or with `shared`
/// the freshest `libocean.so` (the cdylib, found the same way).
pub fn libocean(shared: bool) -> PathBuf {
    let profile = profile_dir();
    let ext = if shared {
        std::env::consts::DLL_SUFFIX
    } else {
        ".a"
    };
    let file = format!("libocean{ext}");
    let mut found = Vec::new();
    for dir in [profile.clone(), profile.join("deps")] {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for entry in entries {
            let path = entry.expect("directory entry").path();
            let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
            if name == file || (name.starts_with("libocean-") && name.ends_with(ext)) {
                found.push((mtime(&path), path));
            }
        }
    }
    let (built, lib) = found.into_iter().max().unwrap_or_else(|| {
        panic!(
            "no {file} in {} or its deps/: ocean-ffi's library was not built \
             (run `cargo build -p ocean-ffi` with the same profile and target directory)",
            profile.display()
        )
    });
    let sources = newest_source(&workspace_root().join("ocean-ffi/src"));
    assert!(
        built >= sources,
        "{} is older than the ocean-ffi sources: it is stale; rebuild with `cargo build -p ocean-ffi`",
        lib.display()
    );
    lib
}

/// The SONAME ocean-ffi/build.rs gives the full library: `libocean.so.<abi>`, `<abi>` the major
/// version or `0.<minor>` before 1.0.
#[allow(dead_code, reason = "c_matrix.rs links the static library only")]
pub fn soname() -> String {
    let (major, minor) = (
        env!("CARGO_PKG_VERSION_MAJOR"),
        env!("CARGO_PKG_VERSION_MINOR"),
    );
    let abi = if major == "0" {
        format!("0.{minor}")
    } else {
        major.to_owned()
    };
    format!("libocean.so.{abi}")
}

pub fn compiler(var: &str, default: &str) -> OsString {
    std::env::var_os(var).unwrap_or_else(|| default.into())
}

/// Runs `cmd`, failing the test with its output if it cannot start or exits non-zero; returns
/// its stdout and stderr.
pub fn run(mut cmd: Command, what: &str) -> (String, String) {
    let out = match cmd.output() {
        Ok(out) => out,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => panic!(
            "{what}: `{}` was not found. The C ABI tests need a C11 and a C++17 compiler \
             (Debian: apt-get install gcc g++ libglm-dev), or set CC / CXX; \
             OCEAN_SANITIZE=memcheck needs valgrind (apt-get install valgrind).",
            cmd.get_program().to_string_lossy()
        ),
        Err(e) => panic!("{what}: cannot run {cmd:?}: {e}"),
    };
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    // Shown with --nocapture, and in the failure report otherwise.
    println!("{what}: {cmd:?}\n{stdout}{stderr}");
    assert!(
        out.status.success(),
        "{what} failed ({}):\n{stdout}\n{stderr}",
        out.status
    );
    (stdout, stderr)
}
