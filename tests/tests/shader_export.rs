//! Every registered pass, exported through naga, is accepted by the Khronos reference tools:
//! `glslangValidator` for GLSL 330/430 core and GLSL ES 310 (what an OpenGL engine compiles),
//! `spirv-val` for SPIR-V (what a Vulkan engine loads). naga's own validation only covers the
//! WGSL source; this checks the translations an engine actually receives.
//!
//! The tools come from Debian's `glslang-tools` and `spirv-tools`. Without them the tests skip
//! with that hint, unless `OCEAN_REQUIRE_TOOLS=1` (set in CI) makes that a failure.

use std::path::{Path, PathBuf};
use std::process::Command;

use ocean_gpu::shaders::{self, Code, Language, Stage};
use ocean_tests::tool_or_skip;

fn out_dir(lang: Language) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("shader_export")
        .join(lang.name());
    std::fs::create_dir_all(&dir).expect("temporary directory");
    dir
}

fn run(cmd: &mut Command) {
    let out = cmd.output().expect("tool runs");
    assert!(
        out.status.success(),
        "{cmd:?} rejected the export:\n{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

fn glslang_stage(stage: Stage) -> &'static str {
    match stage {
        Stage::Vertex => "vert",
        Stage::Fragment => "frag",
        Stage::Compute => "comp",
    }
}

#[test]
fn glsl_and_glsl_es_exports_compile_with_glslang() {
    let Some(glslang) = tool_or_skip("glslangValidator", "glslang-tools") else {
        return;
    };
    let mut checked = 0;
    for lang in [Language::Glsl, Language::GlslEs] {
        let dir = out_dir(lang);
        for entry in shaders::all() {
            let export = shaders::export(entry.name, lang).expect("export");
            for file in &export.files {
                let Code::Text(text) = &file.code else {
                    panic!("{} is not text", file.file_name)
                };
                let stage = file.stage.expect("GLSL files hold one entry point");
                let path = dir.join(&file.file_name);
                std::fs::write(&path, text).expect("write export");
                run(Command::new(&glslang)
                    .arg("-S")
                    .arg(glslang_stage(stage))
                    .arg(&path));
                checked += 1;
            }
        }
    }
    // One file per entry point and language: at least the trochoid compute pass, twice.
    assert!(checked >= 2, "only {checked} GLSL files checked");
}

#[test]
fn spirv_exports_pass_spirv_val() {
    let Some(spirv_val) = tool_or_skip("spirv-val", "spirv-tools") else {
        return;
    };
    let dir = out_dir(Language::SpirV);
    let mut checked = 0;
    for entry in shaders::all() {
        let export = shaders::export(entry.name, Language::SpirV).expect("export");
        for file in &export.files {
            let Code::Binary(words) = &file.code else {
                panic!("{} is not binary", file.file_name)
            };
            // The SPIR-V magic number, little-endian, opens every module.
            assert_eq!(words[..4], 0x0723_0203u32.to_le_bytes());
            let path = dir.join(&file.file_name);
            std::fs::write(&path, words).expect("write export");
            run(Command::new(&spirv_val)
                .args(["--target-env", "vulkan1.0"])
                .arg(&path));
            checked += 1;
        }
    }
    assert!(checked >= 1, "no SPIR-V module checked");
}
