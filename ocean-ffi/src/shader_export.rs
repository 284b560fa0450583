//! Shader export (crate `ocean-gpu`, module `shaders`): every registered WGSL pass translated by
//! naga to GLSL (3.30 core for draw passes, 4.30 core for compute passes), GLSL ES 3.10, HLSL
//! (Shader Model 5.1), MSL 2.0 or SPIR-V 1.0, with its resource bindings, for engines that run
//! the passes in their own OpenGL (or Vulkan, D3D, Metal) pipeline. No GPU is needed.
//!
//! Binding layout. WGSL `@group(g) @binding(b)` stays `set = g, binding = b` in SPIR-V and
//! `register(<b|t|u|s>b, space g)` in HLSL. In GLSL the groups are flattened: each namespace
//! (uniform blocks, shader storage blocks, texture units, image units) is numbered from 0 in
//! (group, binding) order. GLSL 4.30 and ES 3.10 write that number as `layout(binding = n)`;
//! GLSL 3.30 cannot, so the engine assigns it by the block or sampler name
//! (`glUniformBlockBinding`, `glUniform1i`). `OceanShaderBinding` gives both, and
//! `ocean_shader_export_bindings` the whole table as text (with the byte offsets of every
//! buffer member, std140/std430 as WGSL lays them out).

use core::ffi::{CStr, c_char};
use std::ffi::CString;
use std::sync::OnceLock;

use ocean_gpu::shaders::{self, BindingKind, Language, ShaderError, Stage};

use crate::boundary::{CEnum, borrow, check_enum, check_ptr, destroy, write_handle, write_out};
use crate::status::{Error, OceanStatus, guard};

/// Target language of `ocean_shader_export`.
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, bytemuck::NoUninit, bytemuck::CheckedBitPattern)]
pub enum OceanShaderLanguage {
    /// Desktop GLSL, one file per entry point: `#version 330 core` for draw passes (vertex and
    /// fragment), `#version 430 core` for compute passes. Clip space is OpenGL's (y flipped and
    /// depth remapped to [-1, 1] in the vertex stage, as wgpu's GL backend does).
    Glsl = 0,
    /// GLSL ES 3.10 (`#version 310 es`), one file per entry point.
    GlslEs = 1,
    /// HLSL, Shader Model 5.1, one file with every entry point.
    Hlsl = 2,
    /// Metal Shading Language 2.0, one file with every entry point.
    Msl = 3,
    /// SPIR-V 1.0, one binary module with every entry point (little-endian 32-bit words).
    Spirv = 4,
}

impl CEnum for OceanShaderLanguage {
    const REFUSAL: &'static str = "is not an OceanShaderLanguage (0 to 4)";
}

/// The stage of an exported file.
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OceanShaderStage {
    /// The file holds every entry point of the pass (HLSL, MSL, SPIR-V).
    Module = 0,
    /// A vertex shader (GLSL, GLSL ES).
    Vertex = 1,
    /// A fragment shader (GLSL, GLSL ES).
    Fragment = 2,
    /// A compute shader (GLSL, GLSL ES).
    Compute = 3,
}

/// What kind of resource a binding is.
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OceanBindingKind {
    /// A uniform buffer (a GLSL uniform block).
    Uniform = 0,
    /// A read-only storage buffer (a GLSL shader storage block).
    StorageRead = 1,
    /// A read-write storage buffer.
    StorageReadWrite = 2,
    /// A sampled texture (in GLSL a sampler combined with the binding's sampler).
    Texture = 3,
    /// A read-only storage texture (a GLSL image).
    StorageTextureRead = 4,
    /// A write-only storage texture.
    StorageTextureWrite = 5,
    /// A read-write storage texture.
    StorageTextureReadWrite = 6,
    /// A filtering or non-filtering sampler (folded into the textures it samples in GLSL).
    Sampler = 7,
    /// A comparison sampler.
    SamplerComparison = 8,
}

/// `OceanShaderBinding::glsl_binding` when the binding has no GLSL binding number: a sampler
/// (combined with its texture in GLSL), a GLSL 3.30 export (assign the number by name), or a
/// non-GLSL export.
pub const OCEAN_NO_GLSL_BINDING: u32 = u32::MAX;

/// One resource binding of an exported shader. The strings are NUL-terminated UTF-8, owned by
/// the export, and valid until it is destroyed.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct OceanShaderBinding {
    /// WGSL `@group` (the descriptor set in SPIR-V, the register space in HLSL).
    pub group: u32,
    /// WGSL `@binding`.
    pub binding: u32,
    /// What kind of resource it is.
    pub kind: OceanBindingKind,
    /// Byte size of the bound type, or of one element of a runtime-sized array; 0 for textures
    /// and samplers.
    pub size: u32,
    /// GLSL exports: the binding number in GLSL, which has no groups (`layout(binding = n)` in
    /// GLSL 4.30 and ES 3.10; what `glBindBufferBase`, `glActiveTexture` and `glBindImageTexture`
    /// take). Each GLSL namespace counts from 0 on its own, in (group, binding) order: uniform
    /// blocks, shader storage blocks, texture units and image units; so the first resource of
    /// each kind in a pass has number 0. `OCEAN_NO_GLSL_BINDING` where there is none (see
    /// there).
    pub glsl_binding: u32,
    /// Written as 0: room for a later member, and no padding the caller cannot see.
    pub reserved: u32,
    /// The variable's name in the WGSL source.
    pub name: *const c_char,
    /// Its WGSL type, e.g. `Frame` or `texture_2d<f32>`.
    pub wgsl_type: *const c_char,
    /// GLSL exports: the name of the uniform block, storage block or sampler naga wrote for it
    /// (set its binding number by this name under GLSL 3.30); "" when no exported entry point
    /// uses it, or for non-GLSL exports. Never NULL.
    pub glsl_name: *const c_char,
}

/// A shader translated to one language (opaque): its files and binding layout. Create with
/// `ocean_shader_export`, free with `ocean_shader_export_destroy`. Immutable: a
/// `const OceanShaderExport *` may be used by any number of threads at once.
pub struct OceanShaderExport {
    files: Vec<ExportedFile>,
    bindings: Vec<ExportedBinding>,
    table: CString,
}

struct ExportedFile {
    name: CString,
    entry_point: CString,
    stage: OceanShaderStage,
    /// The code, then zero bytes up to a multiple of 4 (at least one): 4-byte aligned for
    /// SPIR-V consumers and NUL-terminated for C string functions.
    words: Vec<u32>,
    len: usize,
}

struct ExportedBinding {
    group: u32,
    binding: u32,
    kind: OceanBindingKind,
    size: u32,
    glsl_binding: u32,
    name: CString,
    wgsl_type: CString,
    glsl_name: CString,
}

const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<OceanShaderExport>();
};

/// A C string from Rust text; NUL bytes (never produced by naga) become spaces.
fn c_string(s: &str) -> CString {
    CString::new(s.replace('\0', " ")).expect("interior NUL bytes were replaced")
}

/// The registered names as C strings, built once and kept for the life of the program.
fn names() -> &'static [CString] {
    static NAMES: OnceLock<Vec<CString>> = OnceLock::new();
    NAMES.get_or_init(|| shaders::all().iter().map(|s| c_string(s.name)).collect())
}

fn language_from(v: u32) -> Result<Language, Error> {
    Ok(match check_enum::<OceanShaderLanguage>("language", v)? {
        OceanShaderLanguage::Glsl => Language::Glsl,
        OceanShaderLanguage::GlslEs => Language::GlslEs,
        OceanShaderLanguage::Hlsl => Language::Hlsl,
        OceanShaderLanguage::Msl => Language::Msl,
        OceanShaderLanguage::Spirv => Language::SpirV,
    })
}

fn kind_to(k: BindingKind) -> OceanBindingKind {
    match k {
        BindingKind::Uniform => OceanBindingKind::Uniform,
        BindingKind::StorageRead => OceanBindingKind::StorageRead,
        BindingKind::StorageReadWrite => OceanBindingKind::StorageReadWrite,
        BindingKind::Texture => OceanBindingKind::Texture,
        BindingKind::StorageTexture {
            read: true,
            write: true,
        } => OceanBindingKind::StorageTextureReadWrite,
        BindingKind::StorageTexture { read: true, .. } => OceanBindingKind::StorageTextureRead,
        BindingKind::StorageTexture { .. } => OceanBindingKind::StorageTextureWrite,
        BindingKind::Sampler { comparison: false } => OceanBindingKind::Sampler,
        BindingKind::Sampler { comparison: true } => OceanBindingKind::SamplerComparison,
    }
}

fn stage_to(s: Option<Stage>) -> OceanShaderStage {
    match s {
        None => OceanShaderStage::Module,
        Some(Stage::Vertex) => OceanShaderStage::Vertex,
        Some(Stage::Fragment) => OceanShaderStage::Fragment,
        Some(Stage::Compute) => OceanShaderStage::Compute,
    }
}

fn shader_error(e: ShaderError) -> Error {
    let status = match e {
        ShaderError::UnknownShader { .. } => OceanStatus::NotFound,
        ShaderError::UnknownLanguage(_) => OceanStatus::InvalidArgument,
        _ => OceanStatus::GpuFailure,
    };
    Error::new(status, e.to_string())
}

/// Returns the number of registered shaders (passes), at least 1. Never fails; leaves the
/// last-error message alone.
#[unsafe(no_mangle)]
pub extern "C" fn ocean_shader_count() -> usize {
    shaders::all().len()
}

/// Stores the name of registered shader `index` (0 to `ocean_shader_count()` - 1) in `*out`:
/// a static NUL-terminated string such as "ocean" (the renderer's draw pass) or "trochoid",
/// valid for the life of the program. Pass it to `ocean_shader_export`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
/// `OCEAN_STATUS_INVALID_ARGUMENT` if `index` >= the count. `*out` is written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_shader_name(index: usize, out: *mut *const c_char) -> OceanStatus {
    guard("ocean_shader_name", || {
        check_ptr(out.cast_const(), "out")?;
        let names = names();
        let name = names.get(index).ok_or_else(|| {
            Error::new(
                OceanStatus::InvalidArgument,
                format!(
                    "index {index} does not exist: there are {} shaders",
                    names.len()
                ),
            )
        })?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", name.as_ptr()) }
    })
}

/// Translates the registered shader `name` to `language` (an `OceanShaderLanguage` value) with
/// naga and stores a new export in `*out`: its files (`ocean_shader_export_file`) and its
/// resource bindings (`ocean_shader_export_binding`, `ocean_shader_export_bindings`).
///
/// GLSL and GLSL ES give one file per entry point, named `<pass>.<entry>.<vert|frag|comp>.glsl`
/// (`.es.glsl` for ES), in the order the WGSL declares them; the draw pass "ocean" has the vertex
/// and fragment stages of the sea (`ocean_vs`, `ocean_fs`), of the sky (`sky_vs`, `sky_fs`), of
/// a caller's water mesh (`mesh_vs`, `mesh_fs`) and of the full-screen pass composing that
/// mesh's light with an ambient obscurance (`sky_vs`, `compose_fs`).
/// HLSL (`<pass>.hlsl`), MSL (`<pass>.metal`) and SPIR-V (`<pass>.spv`) give one file with every
/// entry point. The translation is deterministic: the same library gives the same bytes.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` for a `language` that is not an `OceanShaderLanguage` or a
/// `name` that is not UTF-8, `OCEAN_STATUS_NOT_FOUND` for an unknown name (the message lists
/// the registered ones), `OCEAN_STATUS_GPU_FAILURE` if naga cannot translate the pass. On
/// failure `*out` is unchanged. Free the export with `ocean_shader_export_destroy`.
///
/// # Safety
///
/// `name` must be NULL or a NUL-terminated string, and `out` point to a writable pointer;
/// `name` is not retained.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_shader_export(
    name: *const c_char,
    language: u32,
    out: *mut *mut OceanShaderExport,
) -> OceanStatus {
    guard("ocean_shader_export", || {
        check_ptr(name, "name")?;
        check_ptr(out.cast_const(), "out")?;
        let language = language_from(language)?;
        // SAFETY: non-NULL (checked), NUL-terminated (caller's guarantee); borrowed only for
        // this call.
        let name = unsafe { CStr::from_ptr(name) };
        let name = name.to_str().map_err(|e| {
            Error::new(
                OceanStatus::InvalidArgument,
                format!("`name` is not UTF-8: {e}"),
            )
        })?;
        let export = shaders::export(name, language).map_err(shader_error)?;
        let files = export
            .files
            .iter()
            .map(|f| {
                let bytes = f.code.as_bytes();
                let mut words = vec![0u32; bytes.len() / 4 + 1];
                bytemuck::cast_slice_mut::<u32, u8>(&mut words)[..bytes.len()]
                    .copy_from_slice(bytes);
                ExportedFile {
                    name: c_string(&f.file_name),
                    entry_point: c_string(f.entry_point.as_deref().unwrap_or("")),
                    stage: stage_to(f.stage),
                    words,
                    len: bytes.len(),
                }
            })
            .collect();
        let bindings = export
            .bindings
            .iter()
            .map(|b| ExportedBinding {
                group: b.group,
                binding: b.binding,
                kind: kind_to(b.kind),
                size: b.size,
                glsl_binding: b.glsl_binding.unwrap_or(OCEAN_NO_GLSL_BINDING),
                name: c_string(&b.name),
                wgsl_type: c_string(&b.ty),
                glsl_name: c_string(b.glsl_name.as_deref().unwrap_or("")),
            })
            .collect();
        let value = OceanShaderExport {
            files,
            bindings,
            table: c_string(&export.bindings_table()),
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_handle(out, value) }
    })
}

/// Frees an export; every pointer it handed out becomes invalid. NULL does nothing; a handle of
/// another kind or already destroyed frees nothing and sets the last-error message (see the
/// header's notes on handles).
#[unsafe(no_mangle)]
pub extern "C" fn ocean_shader_export_destroy(shader_export: *mut OceanShaderExport) {
    destroy(
        shader_export,
        "ocean_shader_export_destroy",
        "shader_export",
    );
}

/// Stores the number of files of the export (>= 1) in `*out`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_shader_export_file_count(
    shader_export: *const OceanShaderExport,
    out: *mut usize,
) -> OceanStatus {
    guard("ocean_shader_export_file_count", || {
        let e = borrow(shader_export, "shader_export")?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", e.files.len()) }
    })
}

fn file(e: &OceanShaderExport, index: usize) -> Result<&ExportedFile, Error> {
    e.files.get(index).ok_or_else(|| {
        Error::new(
            OceanStatus::InvalidArgument,
            format!(
                "file {index} does not exist: the export has {} files",
                e.files.len()
            ),
        )
    })
}

/// Stores file `index` (0 to the file count - 1) of the export: its suggested file name in
/// `*file_name` (NUL-terminated, e.g. "ocean.ocean_vs.vert.glsl"), its bytes in `*data` and
/// their number in `*len`.
///
/// The data is the shader's text (UTF-8) or, for SPIR-V, its binary module (little-endian
/// 32-bit words); `len` counts its bytes without any terminator. It is 4-byte aligned (cast it
/// to `const uint32_t *` for `vkCreateShaderModule`) and followed by at least one NUL byte,
/// so text can be passed as a C string (`glShaderSource` with a NULL length). The pointers stay
/// valid until the export is destroyed.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` if `index` >= the file count. Nothing is written on failure.
///
/// # Safety
///
/// The three out-pointers must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_shader_export_file(
    shader_export: *const OceanShaderExport,
    index: usize,
    file_name: *mut *const c_char,
    data: *mut *const u8,
    len: *mut usize,
) -> OceanStatus {
    guard("ocean_shader_export_file", || {
        let e = borrow(shader_export, "shader_export")?;
        check_ptr(file_name.cast_const(), "file_name")?;
        check_ptr(data.cast_const(), "data")?;
        check_ptr(len.cast_const(), "len")?;
        let f = file(&e, index)?;
        // SAFETY: each pointer checked and writable (this function's contract).
        unsafe {
            write_out(file_name, "file_name", f.name.as_ptr())?;
            write_out(data, "data", f.words.as_ptr().cast::<u8>())?;
            write_out(len, "len", f.len)
        }
    })
}

/// Stores the stage of file `index` in `*stage` (an `OceanShaderStage` value:
/// `OCEAN_SHADER_STAGE_MODULE` for a file with every entry point) and the name of its entry
/// point in `*entry_point` (NUL-terminated, e.g. "ocean_fs"; "" for a module), valid until the
/// export is destroyed.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` if `index` >= the file count. Nothing is written on failure.
///
/// # Safety
///
/// Both out-pointers must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_shader_export_file_stage(
    shader_export: *const OceanShaderExport,
    index: usize,
    stage: *mut OceanShaderStage,
    entry_point: *mut *const c_char,
) -> OceanStatus {
    guard("ocean_shader_export_file_stage", || {
        let e = borrow(shader_export, "shader_export")?;
        check_ptr(stage.cast_const(), "stage")?;
        check_ptr(entry_point.cast_const(), "entry_point")?;
        let f = file(&e, index)?;
        // SAFETY: both pointers checked and writable (this function's contract).
        unsafe {
            write_out(stage, "stage", f.stage)?;
            write_out(entry_point, "entry_point", f.entry_point.as_ptr())
        }
    })
}

/// Stores the export's binding layout as text in `*table`: NUL-terminated UTF-8 owned by the
/// export, valid until it is destroyed. A header line starting with `#`, then one line per
/// binding in (group, binding) order, `group binding name kind type (size N)` plus
/// ` glsl_name=NAME` and ` glsl_binding=N` where they apply, each followed by the members of a
/// buffer's struct, one per line: `    +OFFSET name: type`. The same text as the
/// `<pass>.bindings.txt` of `ocean shaders`.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*table` is
/// written only on success.
///
/// # Safety
///
/// `table` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_shader_export_bindings(
    shader_export: *const OceanShaderExport,
    table: *mut *const c_char,
) -> OceanStatus {
    guard("ocean_shader_export_bindings", || {
        let e = borrow(shader_export, "shader_export")?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(table, "table", e.table.as_ptr()) }
    })
}

/// Stores the number of resource bindings of the exported pass in `*out` (the same for every
/// language; 0 for a pass without resources).
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
/// written only on success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_shader_export_binding_count(
    shader_export: *const OceanShaderExport,
    out: *mut usize,
) -> OceanStatus {
    guard("ocean_shader_export_binding_count", || {
        let e = borrow(shader_export, "shader_export")?;
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", e.bindings.len()) }
    })
}

/// Stores binding `index` (0 to the binding count - 1, in (group, binding) order) in `*out`;
/// its strings are owned by the export and valid until it is destroyed.
///
/// Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
/// `OCEAN_STATUS_INVALID_ARGUMENT` if `index` >= the binding count. `*out` is written only on
/// success.
///
/// # Safety
///
/// `out` must be writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn ocean_shader_export_binding(
    shader_export: *const OceanShaderExport,
    index: usize,
    out: *mut OceanShaderBinding,
) -> OceanStatus {
    guard("ocean_shader_export_binding", || {
        let e = borrow(shader_export, "shader_export")?;
        check_ptr(out.cast_const(), "out")?;
        let b = e.bindings.get(index).ok_or_else(|| {
            Error::new(
                OceanStatus::InvalidArgument,
                format!(
                    "binding {index} does not exist: the export has {} bindings",
                    e.bindings.len()
                ),
            )
        })?;
        let value = OceanShaderBinding {
            group: b.group,
            binding: b.binding,
            kind: b.kind,
            size: b.size,
            glsl_binding: b.glsl_binding,
            reserved: 0,
            name: b.name.as_ptr(),
            wgsl_type: b.wgsl_type.as_ptr(),
            glsl_name: b.glsl_name.as_ptr(),
        };
        // SAFETY: forwarded from this function's contract.
        unsafe { write_out(out, "out", value) }
    })
}

crate::boundary::handle::handles!(OceanShaderExport);

#[cfg(test)]
mod tests {
    use super::*;

    use crate::status::last_error;

    fn export(name: &CStr, language: u32) -> (OceanStatus, *mut OceanShaderExport) {
        let mut e = core::ptr::null_mut();
        // SAFETY: NUL-terminated name, writable out.
        let s = unsafe { ocean_shader_export(name.as_ptr(), language, &mut e) };
        (s, e)
    }

    /// Every pass and language: the files and bindings are `ocean_gpu`'s, byte for byte.
    #[test]
    fn every_pass_and_language_matches_ocean_gpu() {
        assert_eq!(ocean_shader_count(), shaders::all().len());
        for (i, entry) in shaders::all().iter().enumerate() {
            let mut name = core::ptr::null();
            // SAFETY: writable out; the name is static.
            let got = unsafe {
                assert_eq!(ocean_shader_name(i, &mut name), OceanStatus::Ok);
                CStr::from_ptr(name)
            };
            assert_eq!(got.to_str().unwrap(), entry.name);
            for (lang, language) in [
                (OceanShaderLanguage::Glsl, Language::Glsl),
                (OceanShaderLanguage::GlslEs, Language::GlslEs),
                (OceanShaderLanguage::Hlsl, Language::Hlsl),
                (OceanShaderLanguage::Msl, Language::Msl),
                (OceanShaderLanguage::Spirv, Language::SpirV),
            ] {
                let want = shaders::export(entry.name, language).unwrap();
                let (s, e) = export(got, lang as u32);
                assert_eq!(s, OceanStatus::Ok, "{}", last_error());
                let mut n = 0;
                // SAFETY: live handle, writable outputs; the data pointers are read while the
                // export lives.
                unsafe {
                    assert_eq!(ocean_shader_export_file_count(e, &mut n), OceanStatus::Ok);
                    assert_eq!(n, want.files.len());
                    for (k, f) in want.files.iter().enumerate() {
                        let (mut fname, mut data, mut len) =
                            (core::ptr::null(), core::ptr::null(), 0);
                        let s = ocean_shader_export_file(e, k, &mut fname, &mut data, &mut len);
                        assert_eq!(s, OceanStatus::Ok);
                        assert_eq!(CStr::from_ptr(fname).to_str().unwrap(), f.file_name);
                        assert!(data.cast::<u32>().is_aligned());
                        assert_eq!(core::slice::from_raw_parts(data, len), f.code.as_bytes());
                        assert_eq!(*data.add(len), 0);
                        let (mut stage, mut ep) = (99u32, core::ptr::null());
                        // A C caller's `uint32_t`, written as the enum.
                        let st = (&raw mut stage).cast::<OceanShaderStage>();
                        let s = ocean_shader_export_file_stage(e, k, st, &mut ep);
                        assert_eq!(s, OceanStatus::Ok);
                        assert_eq!(stage, stage_to(f.stage) as u32);
                        assert_eq!(
                            CStr::from_ptr(ep).to_str().unwrap(),
                            f.entry_point.as_deref().unwrap_or("")
                        );
                    }
                    let mut table = core::ptr::null();
                    assert_eq!(ocean_shader_export_bindings(e, &mut table), OceanStatus::Ok);
                    assert_eq!(
                        CStr::from_ptr(table).to_str().unwrap(),
                        want.bindings_table()
                    );
                    assert_eq!(
                        ocean_shader_export_binding_count(e, &mut n),
                        OceanStatus::Ok
                    );
                    assert_eq!(n, want.bindings.len());
                    for (k, b) in want.bindings.iter().enumerate() {
                        let mut out = core::mem::MaybeUninit::<OceanShaderBinding>::uninit();
                        let s = ocean_shader_export_binding(e, k, out.as_mut_ptr());
                        assert_eq!(s, OceanStatus::Ok);
                        let out = out.assume_init();
                        assert_eq!(
                            (out.group, out.binding, out.size),
                            (b.group, b.binding, b.size)
                        );
                        assert_eq!(out.kind, kind_to(b.kind));
                        assert_eq!(
                            out.glsl_binding,
                            b.glsl_binding.unwrap_or(OCEAN_NO_GLSL_BINDING)
                        );
                        assert_eq!(CStr::from_ptr(out.name).to_str().unwrap(), b.name);
                        assert_eq!(CStr::from_ptr(out.wgsl_type).to_str().unwrap(), b.ty);
                        assert_eq!(
                            CStr::from_ptr(out.glsl_name).to_str().unwrap(),
                            b.glsl_name.as_deref().unwrap_or("")
                        );
                    }
                    ocean_shader_export_destroy(e);
                }
            }
        }
    }

    #[test]
    fn bad_names_languages_and_indices_are_refused() {
        let sentinel = core::ptr::dangling_mut::<OceanShaderExport>();
        for (name, lang, status, needle) in [
            (c"no_such_pass", 0, OceanStatus::NotFound, "ocean"),
            (
                c"ocean",
                5,
                OceanStatus::InvalidArgument,
                "OceanShaderLanguage",
            ),
            (c"ocean", u32::MAX, OceanStatus::InvalidArgument, "language"),
            (c"\xff", 0, OceanStatus::InvalidArgument, "UTF-8"),
        ] {
            let mut e = sentinel;
            // SAFETY: NUL-terminated name, writable out.
            let s = unsafe { ocean_shader_export(name.as_ptr(), lang, &mut e) };
            assert_eq!(s, status, "{}", last_error());
            assert!(last_error().contains(needle), "{}", last_error());
            assert_eq!(e, sentinel);
        }
        let mut name = c"untouched".as_ptr();
        // SAFETY: writable out.
        let s = unsafe { ocean_shader_name(ocean_shader_count(), &mut name) };
        assert_eq!(s, OceanStatus::InvalidArgument);
        // SAFETY: still the literal.
        assert_eq!(unsafe { CStr::from_ptr(name) }, c"untouched");
        let (s, e) = export(c"trochoid", OceanShaderLanguage::Hlsl as u32);
        assert_eq!(s, OceanStatus::Ok);
        let (mut f, mut d, mut l) = (core::ptr::null(), core::ptr::null(), 7usize);
        // SAFETY: live handle, writable outputs.
        unsafe {
            let s = ocean_shader_export_file(e, 1, &mut f, &mut d, &mut l);
            assert_eq!(s, OceanStatus::InvalidArgument);
            assert_eq!((f, d, l), (core::ptr::null(), core::ptr::null(), 7));
            let s = ocean_shader_export_file(e, 0, &mut f, core::ptr::null_mut(), &mut l);
            assert_eq!(s, OceanStatus::NullPointer);
            assert!(last_error().contains("data"), "{}", last_error());
            assert_eq!(l, 7);
            ocean_shader_export_destroy(e);
            ocean_shader_export_destroy(core::ptr::null_mut());
        }
    }
}
