//! The C ABI driven from C11 and C++17: compiles `tests/c/test_waves.c`, `tests/c/test_wtb.c`,
//! `tests/c/test_lighting.c`, `tests/c/test_sao.c`, `tests/c/test_relief.c`, `tests/c/test_draw.c`,
//! `tests/c/test_gpu.c`, `tests/c/test_misuse.c`, `tests/c/test_threads.c` (with `-pthread`),
//! `tests/cpp/test_waves.cpp`, `tests/cpp/test_lighting.cpp` and `tests/cpp/test_hpp.cpp` (the C++
//! wrapper `include/ocean.hpp`) against `include/ocean.h` and the static library `libocean.a` with the system compilers and `-Wall -Wextra -Werror -pedantic`,
//! runs them, and fails unless each reports `0 failures` after a positive number of checks and
//! exits 0.
//!
//! How the library is found, the compiler chosen and the programs linked:
//! `tests/tests/c_build/mod.rs`.
//!
//! `OCEAN_SANITIZE` builds and runs every program under a checker instead (docs/sanitizers.md;
//! `.ci/sanitize` runs them all):
//! - `address`: AddressSanitizer and UndefinedBehaviorSanitizer compiled into the program
//!   (`-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all`), leak
//!   detection on at exit, suppressions `tests/lsan.supp`;
//! - `thread`: ThreadSanitizer compiled into the program, linked with the shared `libocean.so`
//!   (the cdylib built next to `libocean.a`) so that TSan can tell the uninstrumented library
//!   apart from the program (`ignore_noninstrumented_modules=1`);
//! - `memcheck`: the ordinary build run under valgrind's memcheck, suppressions
//!   `tests/valgrind.supp`.
//!
//! Any report fails the test. The programs are written to `<target>/tmp/c_abi/<mode>/`.
#![cfg(unix)]

mod c_build;
#[path = "c_abi/runner.rs"]
mod runner;

use std::ffi::OsString;
use std::path::Path;
use std::process::Command;

use c_build::{
    FULL_LIBRARY, NATIVE_STATIC_LIBS, WARNINGS, compiler, libocean, run, workspace_root,
};
use runner::{Extras, build_and_run, build_and_run_with};

#[test]
fn c11_program_against_the_static_library() {
    build_and_run(
        compiler("CC", "cc"),
        "-std=c11",
        "tests/c/test_waves.c",
        "test_waves_c",
    );
}

/// Handle misuse from C11: every CPU handle kind given where another is expected, destroyed
/// twice, destroyed through another kind's function, used after destroy, and foreign memory:
/// `OCEAN_STATUS_INVALID_HANDLE` with both kinds named, outputs untouched, no crash or hang.
#[test]
fn c11_handle_misuse_against_the_static_library() {
    build_and_run(
        compiler("CC", "cc"),
        "-std=c11",
        "tests/c/test_misuse.c",
        "test_misuse_c",
    );
}

/// The Wave Train Boxes scene API (`ocean_wtb_scene_*`) from C11: scenario 1 with an island,
/// culling, height queries, moving and removing boxes, and every error path.
#[test]
fn c11_wave_train_boxes_against_the_static_library() {
    build_and_run(
        compiler("CC", "cc"),
        "-std=c11",
        "tests/c/test_wtb.c",
        "test_wtb_c",
    );
}

/// The lighting API (`ocean_spectrum_*`, `ocean_pixel_footprint`, the BRDF and Fresnel
/// evaluations, `ocean_lighting_*`, `ocean_sky_map_*`, `ocean_sea_color*`) from C11: values
/// against the paper's formulas computed in C, and every error path.
#[test]
fn c11_lighting_against_the_static_library() {
    build_and_run(
        compiler("CC", "cc"),
        "-std=c11",
        "tests/c/test_lighting.c",
        "test_lighting_c",
    );
}

/// The Scalable Ambient Obscurance API (`ocean_sao_*`) from C11: a floor meeting a wall with
/// analytic depth through an OpenGL and a reversed-Z infinite projection, the planes read from
/// the matrices, view z against the analytic depth, AO exactly 1 away from the crease and
/// darkening monotonically toward it, the two conventions agreeing, and every error path.
#[test]
fn c11_sao_against_the_static_library() {
    build_and_run_with(
        compiler("CC", "cc"),
        "-std=c11",
        "tests/c/test_sao.c",
        "test_sao_c",
        // Its last part runs the GPU passes when an adapter exists.
        &Extras {
            gpu: true,
            ..Extras::default()
        },
    );
}

/// The relief-mapping API (`ocean_relief_*`) from C11: flat maps (rays stop at their entry
/// point on a map at height 1, at the analytic point on a plane at depth 0.5; cones at the cap;
/// normals (0, 0, 1); a constant mip chain), a single box (its top, the floor, the analytic hit
/// on its wall, its shadow), progress to completion and cancellation from a C callback, and
/// every error path with the outputs untouched.
#[test]
fn c11_relief_against_the_static_library() {
    build_and_run(
        compiler("CC", "cc"),
        "-std=c11",
        "tests/c/test_relief.c",
        "test_relief_c",
    );
}

/// The shader side of the ocean renderer (`ocean_surface_*`) from C11: the uniform block of the
/// exported `ocean` shader field by field (the mesh's origin relative to the eye, the
/// projected grid, the waves, the Sun, the sky map), the wave texture (order, phases per
/// frame, steepness, the suffix variances summing to the spectrum's total), the Fresnel table
/// against `ocean_effective_fresnel_table` at its nodes, and every error path.
#[test]
fn c11_ocean_draw_against_the_static_library() {
    build_and_run(
        compiler("CC", "cc"),
        "-std=c11",
        "tests/c/test_draw.c",
        "test_draw_c",
    );
}

/// The GPU part of the C ABI from C11 (`tests/c/test_gpu.c`): the shader export of every pass
/// and language (no GPU needed), then the ocean renderer on the library's headless device with
/// every error path. The program writes its 64 x 48 frame to `OCEAN_GPU_IMAGE`; this test
/// renders the same frame through `ocean_gpu` (same adapter, chosen by the same `WGPU_BACKEND`)
/// and requires the same bytes. Without an adapter both sides skip the renderer, unless
/// `OCEAN_REQUIRE_GPU=1`, under which the C program itself fails.
#[test]
fn c11_gpu_renderer_and_shader_export_against_the_static_library() {
    use glam::DMat4;
    use ocean_brdf::{
        Filter, FilteredSurface, Lighting, SeaParams, SkyParams, Spectrum, SpectrumParams,
    };
    use ocean_core::{Camera, DepthConvention, Far, Projection};
    use ocean_gpu::{OceanOptions, OceanRenderer};

    let image_path = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("c_abi")
        .join("test_gpu_c.rgba");
    std::fs::create_dir_all(image_path.parent().expect("a parent")).expect("create the directory");
    let _ = std::fs::remove_file(&image_path);
    let stdout = build_and_run_with(
        compiler("CC", "cc"),
        "-std=c11",
        "tests/c/test_gpu.c",
        "test_gpu_c",
        &Extras {
            env: &[("OCEAN_GPU_IMAGE", &image_path)],
            gpu: true,
            ..Extras::default()
        },
    );
    let Ok(from_c) = std::fs::read(&image_path) else {
        assert!(
            stdout.contains("SKIPPED") && !ocean_tests::gpu_required(),
            "test_gpu.c neither rendered nor skipped:\n{stdout}"
        );
        return;
    };
    let Some(ctx) = ocean_tests::gpu_context_or_skip() else {
        panic!("the C program found an adapter but ocean_gpu does not");
    };
    // The C program's frame: 64 x 48, eye 4 m up looking along -z (view = a translation by
    // (0, -4, 0)), 60 degrees, near 0.1 m, far 100 km, [0, 1] depth, t = 2.5 s; the default
    // spectrum with the paper's filter, the default lighting, the default renderer options.
    let (w, h) = (64u32, 48u32);
    let camera = Camera::new(
        DMat4::from_translation(glam::DVec3::new(0.0, -4.0, 0.0)),
        Projection::Perspective {
            fov_y: 60.0 * std::f64::consts::PI / 180.0,
            aspect: f64::from(w) / f64::from(h),
            near: 0.1,
            far: Far::Finite(100_000.0),
        },
        DepthConvention::ZERO_TO_ONE,
    )
    .expect("camera");
    let spectrum = Spectrum::new(SpectrumParams::default()).expect("spectrum");
    let surface = FilteredSurface::new(&spectrum, Filter::PAPER).expect("surface");
    let lighting = Lighting::new(SkyParams::default(), SeaParams::default()).expect("lighting");
    let mut renderer = OceanRenderer::new(&ctx, OceanOptions::default()).expect("renderer");
    renderer.set_surface(&ctx, &surface).expect("set_surface");
    renderer
        .set_lighting(&ctx, &lighting)
        .expect("set_lighting");
    let from_rust = renderer
        .render_image(&ctx, &camera, 2.5, w, h)
        .expect("render_image");
    assert_eq!(from_c.len(), from_rust.len());
    let differing = from_c
        .iter()
        .zip(&from_rust)
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(
        differing,
        0,
        "{differing} of {} bytes differ between the C ABI's frame and ocean_gpu's on {}",
        from_c.len(),
        ctx.describe()
    );
}

/// The scene renderer of the C ABI from C11 (`tests/c/test_scene.c`): the built-in description
/// built and rendered through `ocean_scene_*` with every error path. The program writes its
/// 96 x 54 frame at t = 1.5 s (one sample per pixel) to `OCEAN_SCENE_IMAGE`; this test draws
/// the same frame with `ocean_scene::SceneRenderer` (same adapter, chosen by the same
/// `WGPU_BACKEND`) and requires the same bytes. Without an adapter both sides skip, unless
/// `OCEAN_REQUIRE_GPU=1`, under which the C program itself fails.
#[test]
fn c11_scene_renderer_against_the_static_library() {
    use ocean_scene::renderer::RenderOptions;
    use ocean_scene::{Backend, DEFAULT_SCENE, SceneDescription, SceneRenderer};

    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("c_abi");
    let image_path = dir.join("test_scene_c.rgba");
    // The C program's cone maps go to a cache of its own (generation is deterministic: a
    // cached map is bit for bit the generated one).
    let cache = dir.join("scene-cache");
    std::fs::create_dir_all(&cache).expect("create the directories");
    let _ = std::fs::remove_file(&image_path);
    let stdout = build_and_run_with(
        compiler("CC", "cc"),
        "-std=c11",
        "tests/c/test_scene.c",
        "test_scene_c",
        &Extras {
            env: &[
                ("OCEAN_SCENE_IMAGE", &image_path),
                ("OCEAN_CACHE_DIR", &cache),
            ],
            gpu: true,
            ..Extras::default()
        },
    );
    let Ok(from_c) = std::fs::read(&image_path) else {
        assert!(
            stdout.contains("SKIPPED") && !ocean_tests::gpu_required(),
            "test_scene.c neither rendered nor skipped:\n{stdout}"
        );
        return;
    };
    let mut scene = SceneDescription::parse(DEFAULT_SCENE, "built-in").expect("the built-in scene");
    scene.render.width = 96;
    scene.render.height = 54;
    let options = RenderOptions {
        samples: Some(1),
        ..RenderOptions::default()
    };
    let mut renderer = SceneRenderer::new(&scene, Backend::Auto, options).expect("renderer");
    let from_rust = renderer.frame(1.5, false).expect("frame").rgba;
    assert_eq!(from_c.len(), from_rust.len());
    let differing = from_c
        .iter()
        .zip(&from_rust)
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(
        differing,
        0,
        "{differing} of {} bytes differ between the C ABI's scene frame and ocean_scene's on {}",
        from_c.len(),
        renderer.describe()
    );
}

/// The thread-safety promises of `include/ocean.h` from C11 and POSIX threads
/// (`tests/c/test_threads.c`): 8 threads making the library's first calls at once, then 8
/// threads sharing one handle of every shareable kind (and one scene) while 8 others create,
/// use and destroy their own, every result and error message bit for bit equal to the same
/// calls made on one thread. `.ci/sanitize` also runs it under ThreadSanitizer.
#[test]
fn c11_threads_against_the_static_library() {
    build_and_run_with(
        compiler("CC", "cc"),
        "-std=c11",
        "tests/c/test_threads.c",
        "test_threads_c",
        &Extras {
            threads: true,
            ..Extras::default()
        },
    );
}

#[test]
fn cpp17_glm_program_against_the_static_library() {
    let cxx = compiler("CXX", "c++");
    if !ocean_tests::cpp_header_or_skip(&cxx, "glm/glm.hpp", "libglm-dev") {
        return;
    }
    build_and_run(
        cxx,
        "-std=c++17",
        "tests/cpp/test_waves.cpp",
        "test_waves_cpp",
    );
}

/// The C++17 wrapper `include/ocean.hpp` (`tests/cpp/test_hpp.cpp`): every CPU handle kind
/// through its move-only owner, errors as `ocean::error` with the C status and message, the span
/// and vector overloads bit for bit equal to the C calls, the defaults, the version check, and
/// the GPU part (the shader export and draw data; the context, renderer and GPU SAO where an
/// adapter exists).
#[test]
fn cpp17_ocean_hpp_against_the_static_library() {
    build_and_run_with(
        compiler("CXX", "c++"),
        "-std=c++17",
        "tests/cpp/test_hpp.cpp",
        "test_hpp_cpp",
        &Extras {
            gpu: true,
            ..Extras::default()
        },
    );
}

#[test]
fn cpp17_glm_lighting_against_the_static_library() {
    let cxx = compiler("CXX", "c++");
    if !ocean_tests::cpp_header_or_skip(&cxx, "glm/glm.hpp", "libglm-dev") {
        return;
    }
    build_and_run(
        cxx,
        "-std=c++17",
        "tests/cpp/test_lighting.cpp",
        "test_lighting_cpp",
    );
}

/// The header alone compiles as C99 and C++11 too (the oldest standards it claims), without
/// warnings, for the CPU-only library and for the full one (`OCEAN_GPU`).
#[test]
fn header_compiles_as_c99_and_cpp11() {
    let include = workspace_root().join("include");
    for (compiler, lang, std_flag, variant) in [
        (compiler("CC", "cc"), "c", "-std=c99", None),
        (compiler("CXX", "c++"), "c++", "-std=c++11", None),
        (compiler("CC", "cc"), "c", "-std=c99", Some(FULL_LIBRARY)),
        (
            compiler("CXX", "c++"),
            "c++",
            "-std=c++11",
            Some(FULL_LIBRARY),
        ),
    ] {
        let mut cmd = Command::new(compiler);
        cmd.args(["-x", lang, std_flag])
            .args(WARNINGS)
            .args(variant)
            .arg("-fsyntax-only")
            .arg("-I")
            .arg(&include)
            .arg(include.join("ocean.h"));
        run(cmd, &format!("{lang} {std_flag} syntax check of ocean.h"));
    }
}

/// The C++ wrapper `include/ocean.hpp` alone compiles as C++17 without warnings, for the
/// CPU-only library and for the full one (`OCEAN_GPU`).
#[test]
fn cpp_header_compiles_as_cpp17() {
    let include = workspace_root().join("include");
    for variant in [None, Some(FULL_LIBRARY)] {
        let mut cmd = Command::new(compiler("CXX", "c++"));
        cmd.args(["-x", "c++", "-std=c++17"])
            .args(WARNINGS)
            .args(variant)
            .arg("-fsyntax-only")
            .arg("-I")
            .arg(&include)
            .arg(include.join("ocean.hpp"));
        run(
            cmd,
            &format!("c++ -std=c++17 syntax check of ocean.hpp ({variant:?})"),
        );
    }
}

/// Enumeration members of the header's structs have their enum type, so C++ refuses a plain
/// integer there and takes the enumerator (and an explicit cast, for deliberate misuse). Each
/// snippet is type-checked with `-fsyntax-only`: the integer ones must fail, the others pass.
/// A member that regresses to `uint32_t` makes an integer snippet compile, and this fail.
#[test]
fn cpp_refuses_integers_in_enum_members() {
    let include = workspace_root().join("include");
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("enum_members");
    std::fs::create_dir_all(&dir).expect("create the output directory");
    // (struct, member, enumerator): every enumeration member of an input struct.
    let members = [
        ("OceanEffects", "refraction", "OCEAN_REFRACTION_DISPERSION"),
        (
            "OceanCamera",
            "depth_convention",
            "OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE",
        ),
        ("OceanSaoParams", "mip_filter", "OCEAN_SAO_MIP_FILTER_MAX"),
        ("OceanSaoParams", "estimator", "OCEAN_SAO_ESTIMATOR_ALCHEMY"),
        ("OceanSaoParams", "normals", "OCEAN_SAO_NORMALS_QUAD"),
        (
            "OceanSaoBlurParams",
            "weight",
            "OCEAN_SAO_BLUR_WEIGHT_DEPTH",
        ),
        (
            "OceanReliefConeParams",
            "kind",
            "OCEAN_RELIEF_CONE_KIND_CONSERVATIVE",
        ),
        (
            "OceanReliefMethod",
            "method",
            "OCEAN_RELIEF_TRACER_CONE_STEP",
        ),
        ("OceanReliefMethod", "search", "OCEAN_RELIEF_SEARCH_BOOK"),
    ];
    let check = |name: &str, body: &str| -> bool {
        let source = dir.join(format!("{name}.cpp"));
        std::fs::write(
            &source,
            format!("#include \"ocean.h\"\nvoid f()\n{{\n{body}\n}}\n"),
        )
        .expect("write the snippet");
        let mut cmd = Command::new(compiler("CXX", "c++"));
        cmd.args(["-x", "c++", "-std=c++11", "-fsyntax-only", "-I"])
            .arg(&include)
            .arg(&source);
        let out = cmd.output().expect("run the C++ compiler");
        out.status.success()
    };
    for (i, (ty, member, enumerator)) in members.iter().enumerate() {
        let int = format!("    {ty} s = {{}};\n    int v = 1;\n    s.{member} = v;\n    (void)s;");
        assert!(
            !check(&format!("int_{i}"), &int),
            "C++ accepts an int in {ty}::{member}: is it a uint32_t again?"
        );
        let good = format!(
            "    {ty} s = {{}};\n    s.{member} = {enumerator};\n    \
             s.{member} = static_cast<decltype(s.{member})>(7);\n    (void)s;"
        );
        assert!(
            check(&format!("enum_{i}"), &good),
            "C++ refuses {enumerator} (or a cast) in {ty}::{member}"
        );
    }
}

/// The README's code blocks fenced with `fence` (e.g. ```c), in order.
fn readme_blocks(fence: &str) -> Vec<String> {
    let readme =
        std::fs::read_to_string(workspace_root().join("README.md")).expect("read README.md");
    let mut blocks = Vec::new();
    let mut block: Option<String> = None;
    for line in readme.lines() {
        match (&mut block, line.trim_end()) {
            (None, l) if l == fence => block = Some(String::new()),
            (Some(_), "```") => blocks.push(block.take().expect("open block")),
            (Some(text), _) => {
                text.push_str(line);
                text.push('\n');
            }
            (None, _) => {}
        }
    }
    blocks
}

/// Compiles `source` as `lang` under `std_flag` against the static library with the other
/// tests' warnings, and runs it.
fn build_and_run_snippet(
    source: &Path,
    exe: &Path,
    compiler: OsString,
    lang: &str,
    std_flag: &str,
) {
    let mut cc = Command::new(compiler);
    cc.args(["-x", lang, std_flag])
        .args(WARNINGS)
        .arg("-I")
        .arg(workspace_root().join("include"))
        .arg(source)
        .args(["-x", "none"])
        .arg(libocean(false))
        .args(NATIVE_STATIC_LIBS)
        .arg("-o")
        .arg(exe);
    run(
        cc,
        &format!("compile {} as {lang} {std_flag}", source.display()),
    );
    run(Command::new(exe), &format!("run {}", exe.display()));
    // Passed: drop the executable (it carries the static library's debug information).
    let _ = std::fs::remove_file(exe);
}

/// Every C example of the README (its ```c blocks) compiles as C11 and as C++17 with the
/// warnings of the other C tests, links against the library and exits 0: a user copying one
/// into either kind of project gets a working program. Its C++ examples (```cpp, through
/// `ocean.hpp` and GLM) do the same as C++17.
#[test]
fn readme_examples_build_and_run() {
    let out_dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("readme");
    std::fs::create_dir_all(&out_dir).expect("create the output directory");
    let c = readme_blocks("```c");
    assert!(!c.is_empty(), "no ```c block in README.md");
    for (i, example) in c.iter().enumerate() {
        let source = out_dir.join(format!("example_{i}.c"));
        std::fs::write(&source, example).expect("write the example");
        for (compiler, lang, std_flag) in [
            (compiler("CC", "cc"), "c", "-std=c11"),
            (compiler("CXX", "c++"), "c++", "-std=c++17"),
        ] {
            let exe = out_dir.join(format!("example_{i}_{lang}"));
            build_and_run_snippet(&source, &exe, compiler, lang, std_flag);
        }
    }
    let cpp = readme_blocks("```cpp");
    assert!(!cpp.is_empty(), "no ```cpp block in README.md");
    let cxx = compiler("CXX", "c++");
    if !ocean_tests::cpp_header_or_skip(&cxx, "glm/glm.hpp", "libglm-dev") {
        return;
    }
    for (i, example) in cpp.iter().enumerate() {
        let source = out_dir.join(format!("example_{i}.cpp"));
        std::fs::write(&source, example).expect("write the example");
        let exe = out_dir.join(format!("example_{i}_cpp17"));
        build_and_run_snippet(&source, &exe, cxx.clone(), "c++", "-std=c++17");
    }
}
