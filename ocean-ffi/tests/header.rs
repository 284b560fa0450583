//! `include/ocean.h` must be exactly what cbindgen generates from this crate.
//!
//! Fails on any difference and prints the first differing line; `OCEAN_BLESS=1` rewrites the
//! checked-in header instead.

use std::path::Path;

fn generate() -> String {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(crate_dir.join("cbindgen.toml"))
        .expect("ocean-ffi/cbindgen.toml parses");
    let bindings = cbindgen::Builder::new()
        .with_crate(crate_dir)
        .with_config(config)
        .generate()
        .expect("cbindgen generates the header");
    let mut out = Vec::new();
    bindings.write(&mut out);
    String::from_utf8(out).expect("the header is UTF-8")
}

#[test]
fn checked_in_header_is_up_to_date() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../include/ocean.h");
    let fresh = generate();
    if std::env::var_os("OCEAN_BLESS").is_some_and(|v| v == "1") {
        std::fs::write(&path, &fresh).expect("write include/ocean.h");
        return;
    }
    let checked_in = std::fs::read_to_string(&path).unwrap_or_default();
    if checked_in != fresh {
        let line = checked_in
            .lines()
            .zip(fresh.lines())
            .position(|(a, b)| a != b)
            .unwrap_or_else(|| checked_in.lines().count().min(fresh.lines().count()));
        panic!(
            "{} is out of date (first difference at line {}: checked in {:?}, generated {:?}); \
             run `OCEAN_BLESS=1 cargo test -p ocean-ffi --test header` and commit the result",
            path.display(),
            line + 1,
            checked_in.lines().nth(line),
            fresh.lines().nth(line),
        );
    }
}

#[test]
fn header_has_the_promised_shape() {
    // Independent of the snapshot: the things C callers rely on by name.
    let h = generate();
    for needle in [
        "#ifndef OCEAN_H",
        "#include <stdint.h>",
        "#include <stddef.h>",
        "extern \"C\" {",
        "OCEAN_STATUS_OK = 0,",
        "OCEAN_STATUS_PANIC = 8,",
        &format!(
            "#define OCEAN_VERSION_MAJOR {}",
            env!("CARGO_PKG_VERSION_MAJOR")
        ),
        &format!(
            "#define OCEAN_VERSION_MINOR {}",
            env!("CARGO_PKG_VERSION_MINOR")
        ),
        &format!(
            "#define OCEAN_VERSION_PATCH {}",
            env!("CARGO_PKG_VERSION_PATCH")
        ),
        "OCEAN_STATUS_NOT_FOUND = 9,",
        "OCEAN_STATUS_OUTSIDE_GRID = 10,",
        "typedef struct OceanWaves OceanWaves;",
        "typedef struct OceanWtbScene OceanWtbScene;",
        "OCEAN_REFRACTION_PHASE_SHIFT = 1,",
        "OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE = 2,",
        "size_t n,",
        "double time,",
        // Queries take const handles, as C++ callers holding a const object expect.
        "ocean_wtb_scene_box_count(const struct OceanWtbScene *scene",
        "ocean_wtb_scene_heights_drawn(const struct OceanWtbScene *scene",
        "ocean_wtb_scene_heights_continuous(const struct OceanWtbScene *scene",
        "ocean_waves_evaluate(const struct OceanWaves *waves",
        // One number to compare, and the run-time check of header against library.
        "#define OCEAN_VERSION (((OCEAN_VERSION_MAJOR << 16)",
        "OceanStatus ocean_check_version(uint32_t header_version);",
        // Struct members that hold an enumeration have its type, so that C++ type-checks
        // them (tests/tests/c_abi.rs compiles the misuse).
        "OceanRefraction refraction;",
        "OceanDepthConvention depth_convention;",
        "OceanSaoMipFilter mip_filter;",
        "OceanSaoEstimator estimator;",
        "OceanSaoNormals normals;",
        "OceanSaoBlurWeight weight;",
        "OceanReliefConeKind kind;",
        "OceanReliefTracer method;",
        "OceanReliefSearch search;",
        "OceanBindingKind kind;",
        "OceanShaderStage *stage,",
        // Enumerations that only parameters take are emitted too.
        "OCEAN_SAO_DEPTH_NDC = 1,",
        "OCEAN_RELIEF_EDGE_CLAMP = 1,",
        "OCEAN_RELIEF_RANGE_NORMALIZE = 1,",
        "OCEAN_RELIEF_ENCODING_F32 = 3,",
        "OCEAN_RELIEF_MIP_GROUP = 1,",
        "OCEAN_SHADER_LANGUAGE_SPIRV = 4,",
    ] {
        assert!(
            h.contains(needle),
            "generated header lacks {needle:?}:\n{h}"
        );
    }
    assert!(
        !h.contains("Vec3A") && !h.contains("glam"),
        "glam types leaked into the header"
    );
}
