//! Names the shared library as C libraries are named, so that programs record an ABI version
//! and not a path: the SONAME is `libocean.so.<abi>` (`libocean-cpu.so.<abi>` for the CPU-only
//! build, without the `gpu` feature), where `<abi>` is the major version, or `0.<minor>` before
//! 1.0 (a minor version may break the ABI until then, as `oceanConfigVersion.cmake` says).
//! `scripts/install.sh` installs the file under the full version with the two usual links.

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let var = |name: &str| std::env::var(name).unwrap_or_default();
    let name = if std::env::var_os("CARGO_FEATURE_GPU").is_some() {
        "ocean"
    } else {
        "ocean-cpu"
    };
    let major = var("CARGO_PKG_VERSION_MAJOR");
    let abi = if major == "0" {
        format!("0.{}", var("CARGO_PKG_VERSION_MINOR"))
    } else {
        major
    };
    match var("CARGO_CFG_TARGET_OS").as_str() {
        "macos" | "ios" => {
            println!("cargo:rustc-cdylib-link-arg=-Wl,-install_name,@rpath/lib{name}.{abi}.dylib")
        }
        "windows" => {}
        _ => println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,lib{name}.so.{abi}"),
    }
}
