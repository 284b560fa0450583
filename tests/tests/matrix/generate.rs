//! Generates the bad-input matrix, a C11 program, from the parsed header (see
//! `tests/tests/c_matrix.rs` for what it checks and `tests/c/matrix_harness.h` for the fixed
//! half it includes).
//!
//! Every parameter is classified by its C type (and, for `size_t` and `void *`, its name) into a
//! [`Role`]; the role gives the base value and the bad values. A parameter or function that fits
//! no role is an error, so a new kind of argument can never be skipped silently.

use std::collections::BTreeSet;
use std::fmt::Write as _;

use super::header::{Base, Function, Header, Param, Struct};

/// Handle kinds that need a GPU device. Functions taking or making one are not exercised: the
/// matrix makes thousands of calls and CI's adapter may be a slow software rasteriser; the GPU
/// tests (`tests/tests/gpu_*.rs`, `tests/c/test_gpu.c`) cover their error paths.
pub const GPU_KINDS: &[&str] = &[
    "OceanGpuContext",
    "OceanRenderer",
    "OceanSaoGpu",
    "OceanScene",
];

/// Base values that plausible-by-type would get wrong, from each function's documentation in
/// `include/ocean.h`: (function, parameter, C code). For scalars the code is an expression; for
/// input arrays a statement filling `buf` (`unsigned char *`, the parameter's scratch buffer);
/// for strings an expression. An entry that names no parameter of the header fails the test.
pub const OVERRIDES: &[(&str, &str, &str)] = &[
    ("ocean_lighting_sky_map_create", "size", "8"),
    ("ocean_sky_map_copy_level", "len", "8 * 8 * 4"),
    ("ocean_spectrum_waves", "n", "60"),
    (
        "ocean_spectrum_slope_variance",
        "n_max",
        "OCEAN_FILTER_N_MAX",
    ),
    ("ocean_pixel_footprint", "width", "64"),
    ("ocean_pixel_footprint", "height", "48"),
    ("ocean_pixel_footprint", "py", "40.5"),
    ("ocean_pixel_footprint", "max_distance", "1000.0"),
    ("ocean_surface_uniforms", "width", "64"),
    ("ocean_surface_uniforms", "height", "48"),
    (
        "ocean_surface_uniforms",
        "len",
        "OCEAN_SURFACE_UNIFORMS_SIZE",
    ),
    ("ocean_surface_wave_texels", "len", "12 * 60"),
    (
        "ocean_surface_fresnel_texels",
        "len",
        "OCEAN_FRESNEL_TABLE_SIZE * OCEAN_FRESNEL_TABLE_SIZE",
    ),
    ("ocean_relief_map_create_f32", "len", "16 * 16"),
    ("ocean_relief_map_create_f32", "width", "16"),
    ("ocean_relief_map_create_f32", "height", "16"),
    ("ocean_relief_map_create_u8", "len", "16 * 16"),
    ("ocean_relief_map_create_u8", "width", "16"),
    ("ocean_relief_map_create_u8", "height", "16"),
    ("ocean_relief_map_create_u16", "len", "16 * 16"),
    ("ocean_relief_map_create_u16", "width", "16"),
    ("ocean_relief_map_create_u16", "height", "16"),
    ("ocean_relief_map_depths", "len", "16 * 16"),
    ("ocean_relief_normals", "len", "3 * 16 * 16"),
    ("ocean_relief_cones_texels", "len", "4 * 16 * 16"),
    ("ocean_relief_cones_encode", "len", "3 * 16 * 16"),
    ("ocean_relief_generate_texels", "len", "4 * 16 * 16"),
    ("ocean_relief_generate_encoded", "len", "3 * 16 * 16"),
    ("ocean_relief_mips_copy_level", "len", "3 * 16 * 16"),
    ("ocean_relief_uniforms", "size", "16"),
    ("ocean_relief_uniforms", "levels", "1"),
    ("ocean_relief_uniforms", "srgb_encode", "1"),
    ("ocean_relief_uniforms", "len", "OCEAN_RELIEF_UNIFORMS_SIZE"),
    ("ocean_relief_mip_atlas_size", "size", "16"),
    ("ocean_relief_mip_atlas_size", "levels", "2"),
    ("ocean_relief_mip_atlas_origin", "size", "16"),
    ("ocean_relief_mip_atlas_origin", "level", "1"),
    ("ocean_relief_mip_level", "du_x", "0.25f"),
    ("ocean_relief_mip_level", "size", "16"),
    ("ocean_relief_mip_level", "levels", "2"),
    ("ocean_relief_quad_cones_texels", "len", "16 * 16 * 16"),
    ("ocean_relief_quad_generate_texels", "len", "16 * 16 * 16"),
    ("ocean_relief_quad_shadow", "bias", "0.02f"),
    ("ocean_relief_shadow", "bias", "0.02f"),
    ("ocean_relief_ray_from_view", "view_z", "-1.0f"),
    ("ocean_sao_create", "input_width", "32"),
    ("ocean_sao_create", "input_height", "32"),
    ("ocean_sao_create", "guard", "2"),
    ("ocean_sao_create", "depth_source", "OCEAN_SAO_DEPTH_WINDOW"),
    ("ocean_sao_run", "depth_len", "32 * 32"),
    ("ocean_sao_run", "ao_len", "28 * 28"),
    ("ocean_sao_view_z", "depth_len", "32 * 32"),
    ("ocean_sao_view_z", "z_len", "32 * 32"),
    ("ocean_sao_uniforms", "len", "OCEAN_SAO_UNIFORMS_SIZE"),
    ("ocean_shader_export", "name", "\"trochoid\""),
    (
        "ocean_wtb_scene_create",
        "terrain_heights",
        "matrix_fill_f32(buf, 16 * 16, -20.0f, 10.0f)",
    ),
    ("ocean_wtb_scene_create", "terrain_len", "16 * 16"),
    (
        "ocean_wtb_scene_set_terrain",
        "terrain_heights",
        "matrix_fill_f32(buf, 16 * 16, -20.0f, 10.0f)",
    ),
    ("ocean_wtb_scene_set_terrain", "terrain_len", "16 * 16"),
    ("ocean_wtb_scene_update_box", "id", "matrix_box_a"),
    ("ocean_wtb_scene_remove_box", "id", "matrix_box_b"),
    ("ocean_wtb_scene_set_budget_explicit", "max_trains", "8"),
    ("ocean_wtb_scene_evaluate", "time", "2.0"),
    ("ocean_wtb_scene_evaluate", "n", "16 * 16"),
    ("ocean_wtb_scene_evaluate_incremental", "time", "2.0"),
    ("ocean_wtb_scene_evaluate_incremental", "n", "16 * 16"),
    ("ocean_wtb_scene_heights_continuous", "time", "2.0"),
    ("ocean_wtb_scene_set_train_filter", "min_cells", "2.0"),
    ("ocean_wtb_scene_set_train_filter", "max_cells", "4.0"),
];

/// A scalar type of the header.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Prim {
    F32,
    F64,
    U8,
    U16,
    U32,
    U64,
    Usize,
}

impl Prim {
    fn from_name(h: &Header, name: &str) -> Option<Prim> {
        Some(match name {
            "float" => Prim::F32,
            "double" => Prim::F64,
            "uint8_t" => Prim::U8,
            "uint16_t" => Prim::U16,
            "uint32_t" => Prim::U32,
            "uint64_t" => Prim::U64,
            "size_t" => Prim::Usize,
            // The C11 spelling of the enums is a `uint32_t` typedef.
            n if h.aliases.iter().any(|(a, t)| a == n && t == "uint32_t") => Prim::U32,
            _ => return None,
        })
    }

    fn is_float(self) -> bool {
        matches!(self, Prim::F32 | Prim::F64)
    }

    fn c(self) -> &'static str {
        match self {
            Prim::F32 => "float",
            Prim::F64 => "double",
            Prim::U8 => "uint8_t",
            Prim::U16 => "uint16_t",
            Prim::U32 => "uint32_t",
            Prim::U64 => "uint64_t",
            Prim::Usize => "size_t",
        }
    }
}

/// What a parameter is, from its type (and name where the type alone is ambiguous).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Role {
    /// `[const] struct OceanX *` with OceanX opaque.
    Handle {
        kind: String,
    },
    /// `struct OceanX **`: where a new handle is stored.
    OutHandle {
        kind: String,
    },
    /// `const struct S *`: one input struct or an array of them.
    InStruct {
        name: String,
    },
    /// `struct S *`: one output struct or an array of them.
    OutStruct {
        name: String,
    },
    /// `struct S` by value.
    ByValue {
        name: String,
    },
    /// `const float *`, `const uint8_t *`, ...: an input array.
    InArray {
        prim: Prim,
    },
    /// `float *`, `double *`, `size_t *`, ...: an output scalar or array.
    OutArray {
        prim: Prim,
    },
    /// `void *` (but `user`): an output whose element type another argument chooses.
    OutBytes,
    /// `char *`: an output text buffer.
    OutChars,
    /// `const char **`, `const uint8_t **`: where a pointer to library-owned data is stored.
    OutPointer,
    /// `const char *`: an input string.
    InString,
    /// `void *user`: passed through to a callback, never read.
    User,
    /// A function-pointer typedef of the header.
    Callback {
        ty: String,
    },
    Float(Prim),
    /// `size_t` named `len`, `n`, `count`, `*_len` or `n_*`: a buffer's element count.
    Length,
    /// `size_t` named `index` or `max_*`: a number that sizes no buffer.
    Index,
    /// `uint32_t` (or an enum's typedef): an enumeration value, a size or an id.
    U32,
    /// `uint8_t`: a flag.
    U8,
}

pub fn classify(h: &Header, p: &Param) -> Result<Role, String> {
    let ty = &p.ty;
    let name = ty.base_name();
    let prim = Prim::from_name(h, name);
    let is_struct = matches!(ty.base, Base::Struct(_)) && h.struct_def(name).is_some();
    let is_opaque = matches!(ty.base, Base::Struct(_)) && h.is_opaque(name);
    let role = match (ty.stars, ty.konst) {
        (0, false) if is_struct => Role::ByValue { name: name.into() },
        (0, false) if h.fn_types.iter().any(|f| f == name) => Role::Callback { ty: name.into() },
        (0, false) => match prim {
            Some(f) if f.is_float() => Role::Float(f),
            Some(Prim::U32) => Role::U32,
            Some(Prim::U8) => Role::U8,
            Some(Prim::Usize)
                if matches!(p.name.as_str(), "len" | "n" | "count")
                    || p.name.ends_with("_len")
                    || p.name.starts_with("n_") =>
            {
                Role::Length
            }
            Some(Prim::Usize) if p.name == "index" || p.name.starts_with("max_") => Role::Index,
            _ => return Err(format!("no role for the value parameter `{ty} {}`", p.name)),
        },
        (1, _) if is_opaque => Role::Handle { kind: name.into() },
        (1, true) if is_struct => Role::InStruct { name: name.into() },
        (1, false) if is_struct => Role::OutStruct { name: name.into() },
        (1, false) if name == "void" && p.name == "user" => Role::User,
        (1, false) if name == "void" => Role::OutBytes,
        (1, true) if name == "char" => Role::InString,
        (1, false) if name == "char" => Role::OutChars,
        (1, true) if prim.is_some() => Role::InArray {
            prim: prim.unwrap(),
        },
        (1, false) if prim.is_some() => Role::OutArray {
            prim: prim.unwrap(),
        },
        (2, false) if is_opaque => Role::OutHandle { kind: name.into() },
        (2, true) if matches!(name, "char" | "uint8_t") => Role::OutPointer,
        _ => return Err(format!("no role for the parameter `{ty} {}`", p.name)),
    };
    Ok(role)
}

/// What a function is.
#[derive(Debug)]
pub enum Class {
    /// Returns an OceanStatus.
    Fallible(Vec<Role>),
    /// `void ocean_*_destroy(struct OceanX *)`.
    Destroy { kind: String },
    /// Returns a `const char *`, a `size_t` or a `uint32_t` and takes nothing or `uint32_t`s:
    /// never fails.
    Plain(Vec<Role>),
}

pub fn classify_function(h: &Header, f: &Function) -> Result<Class, String> {
    let roles = f
        .params
        .iter()
        .map(|p| classify(h, p))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| format!("{}: {e}", f.name))?;
    let ret = &f.ret;
    let named = |n: &str| ret.base == Base::Named(n.into());
    if named("OceanStatus") && ret.stars == 0 {
        return Ok(Class::Fallible(roles));
    }
    if named("void")
        && ret.stars == 0
        && f.name.ends_with("_destroy")
        && let [Role::Handle { kind }] = roles.as_slice()
    {
        return Ok(Class::Destroy { kind: kind.clone() });
    }
    let plain_ret = (named("char") && ret.konst && ret.stars == 1)
        || (named("size_t") && ret.stars == 0)
        || (named("uint32_t") && ret.stars == 0);
    if plain_ret && roles.iter().all(|r| *r == Role::U32) {
        return Ok(Class::Plain(roles));
    }
    Err(format!(
        "{}: cannot classify the function returning `{ret}`",
        f.name
    ))
}

/// The length parameters that the function's documentation holds to one exact value: those
/// named in a sentence that promises `OCEAN_STATUS_LENGTH_MISMATCH` ("... if `len` is not
/// 4 N * N"). A sentence runs to the next full stop followed by a space.
fn exact_lengths(f: &Function) -> Vec<&str> {
    let sentences: Vec<&str> = f
        .doc
        .split(". ")
        .filter(|s| s.contains("OCEAN_STATUS_LENGTH_MISMATCH"))
        .collect();
    f.params
        .iter()
        .map(|p| p.name.as_str())
        .filter(|n| {
            let tick = format!("`{n}`");
            sentences.iter().any(|s| s.contains(&tick))
        })
        .collect()
}

/// The length parameter that the function's documentation gives as the extent of output `out`:
/// its Safety section says "`out` to `n` writable ..." (or "`a` and `b` `n` writable ...").
/// Scalar outputs (`out_id`) have none.
fn documented_extent<'f>(f: &'f Function, roles: &[Role], out: &str) -> Option<&'f str> {
    let doc = &f.doc;
    // The backticked words of the documentation, with where each ends.
    let mut ticks = Vec::new();
    let mut rest = doc.as_str();
    let mut offset = 0;
    while let Some(a) = rest.find('`') {
        let Some(b) = rest[a + 1..].find('`') else {
            break;
        };
        ticks.push((&rest[a + 1..a + 1 + b], offset + a + b + 2));
        offset += a + b + 2;
        rest = &rest[a + b + 2..];
    }
    let role_of = |name: &str| {
        f.params
            .iter()
            .zip(roles)
            .find(|(p, _)| p.name == name)
            .map(|(_, r)| r)
    };
    let is_output = |name: &str| {
        matches!(
            role_of(name),
            Some(Role::OutStruct { .. } | Role::OutArray { .. } | Role::OutBytes | Role::OutChars)
        )
    };
    for (i, (word, end)) in ticks.iter().enumerate() {
        let writable = doc[*end..].trim_start().starts_with("writable");
        if !writable || role_of(word) != Some(&Role::Length) {
            continue;
        }
        // The outputs named just before "`len` writable".
        for (name, _) in ticks[..i].iter().rev() {
            if *name == out {
                return f
                    .params
                    .iter()
                    .find(|p| p.name == *word)
                    .map(|p| p.name.as_str());
            }
            if !is_output(name) {
                break;
            }
        }
    }
    None
}

/// A leaf of a struct: a scalar member or array element, with its C access path.
#[derive(Clone, Debug)]
pub struct Leaf {
    /// `.cie.a`, `.view[3]`, `.k[2].g`.
    pub path: String,
    pub prim: Prim,
    /// The member's documentation allows `INFINITY` (an output may then hold +INFINITY).
    pub infinity_ok: bool,
}

fn leaves(h: &Header, s: &Struct, prefix: &str, out: &mut Vec<Leaf>) -> Result<(), String> {
    for m in &s.members {
        let mut paths = vec![format!("{prefix}.{}", m.name)];
        for d in &m.dims {
            paths = paths
                .iter()
                .flat_map(|p| (0..*d).map(move |i| format!("{p}[{i}]")))
                .collect();
        }
        let name = m.ty.base_name();
        for path in paths {
            if m.ty.stars > 0 {
                // A pointer member (an output's string): neither a value nor a float.
                continue;
            }
            if let (Base::Struct(_), Some(inner)) = (&m.ty.base, h.struct_def(name)) {
                leaves(h, inner, &path, out)?;
            } else if let Some(prim) = Prim::from_name(h, name) {
                out.push(Leaf {
                    path,
                    prim,
                    infinity_ok: m.doc.contains("INFINITY"),
                });
            } else {
                return Err(format!("{}.{}: member type `{}`", s.name, m.name, m.ty));
            }
        }
    }
    Ok(())
}

/// The access paths of the extension links (`const struct OceanChain *` members, `next`) of
/// struct `name` and of the structs inside it: `.next`, `.method.next`.
pub fn chain_links(h: &Header, name: &str) -> Vec<String> {
    let Some(s) = h.struct_def(name) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for m in s.members.iter().filter(|m| m.dims.is_empty()) {
        match (&m.ty.base, m.ty.stars) {
            (Base::Struct(n), 1) if n == "OceanChain" => out.push(format!(".{}", m.name)),
            (Base::Struct(n), 0) => {
                out.extend(
                    chain_links(h, n)
                        .into_iter()
                        .map(|p| format!(".{}{p}", m.name)),
                );
            }
            _ => {}
        }
    }
    out
}

pub fn struct_leaves(h: &Header, name: &str) -> Result<Vec<Leaf>, String> {
    let s = h.struct_def(name).ok_or(format!("no struct {name}"))?;
    let mut out = Vec::new();
    leaves(h, s, "", &mut out)?;
    Ok(out)
}

/// The bad values of a float: (label, C expression). For `float` the double extremes become
/// float ones (1e300 is no float: its analogue is FLT_MAX).
fn float_values(prim: Prim) -> &'static [(&'static str, &'static str)] {
    match prim {
        Prim::F64 => &[
            ("NaN", "NAN"),
            ("+Inf", "INFINITY"),
            ("-Inf", "-INFINITY"),
            ("1e300", "1e300"),
            ("-1e300", "-1e300"),
            ("-0.0", "-0.0"),
            ("DBL_TRUE_MIN", "DBL_TRUE_MIN"),
            ("FLT_MAX", "FLT_MAX"),
        ],
        _ => &[
            ("NaN", "NAN"),
            ("+Inf", "INFINITY"),
            ("-Inf", "-INFINITY"),
            ("FLT_MAX", "FLT_MAX"),
            ("-FLT_MAX", "-FLT_MAX"),
            ("-0.0", "-0.0f"),
            ("FLT_TRUE_MIN", "FLT_TRUE_MIN"),
            ("1e30", "1e30f"),
        ],
    }
}

/// The bad values of a struct member: NaN and a huge value for floats, an out-of-range value
/// for flags and enumerations, 0 and SIZE_MAX for counts.
fn member_values(prim: Prim) -> &'static [(&'static str, &'static str)] {
    match prim {
        Prim::F64 => &[("NaN", "NAN"), ("1e300", "1e300")],
        Prim::F32 => &[("NaN", "NAN"), ("FLT_MAX", "FLT_MAX")],
        Prim::U8 => &[("2", "2")],
        Prim::U32 => &[("0xFFFFFFFF", "0xFFFFFFFFu")],
        Prim::Usize => &[("0", "0"), ("SIZE_MAX", "SIZE_MAX")],
        Prim::U16 | Prim::U64 => &[],
    }
}

/// The stage of the header's error order a variant's bad value belongs to.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Stage {
    /// (1) a handle.
    Handle,
    /// (2) another pointer: NULL or misaligned.
    Pointer,
    /// (3)-(5) a count, a value, or the work it leads to.
    Value,
}

/// What a variant may return.
#[derive(Clone)]
enum Expect {
    Any,
    /// One of these statuses (names of `OceanStatus` values).
    Only(Vec<&'static str>),
    /// When the base call succeeded, exactly this status.
    IfBaseOk(&'static str),
    /// The base call's status.
    SameAsBase,
    /// OCEAN_STATUS_NULL_POINTER if parameter i alone NULL gave it (a required pointer).
    IfNullRefused(usize),
}

#[derive(Clone)]
struct Variant {
    param: String,
    value: String,
    /// C statements mutating `a` (the arguments) or the scratch buffers after the base.
    code: String,
    expect: Expect,
    /// A length value: run only if `matrix_length_ok` allows it.
    length: Option<String>,
    /// The parameter it changes (None: several).
    index: Option<usize>,
    stage: Stage,
    /// Records whether this single NULL of parameter i is refused (for [`Expect::IfNullRefused`]).
    mark_null: Option<usize>,
}

/// The generated program and what it covers.
pub struct Program {
    pub source: String,
    /// Functions exercised (status-returning, destroy and plain).
    pub functions: usize,
    /// Functions skipped because they take or make a GPU handle.
    pub gpu_skipped: Vec<String>,
    /// Variants per role, for the report.
    pub variants: usize,
    /// Structs filled with zeros (no `_default` function, no `plausible_` filler).
    pub zeroed_structs: BTreeSet<String>,
}

struct Gen<'a> {
    h: &'a Header,
    harness: &'a str,
    /// CPU handle kinds, in header order.
    kinds: Vec<String>,
    /// Kinds a function mutates (a non-const handle): remade before each such function.
    mutable: BTreeSet<String>,
    structs_filled: BTreeSet<String>,
    structs_checked: BTreeSet<String>,
    zeroed: BTreeSet<String>,
    out: String,
    variants: usize,
}

fn c_ident_ok(s: &str) -> bool {
    s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}

impl Gen<'_> {
    fn kind_index(&self, kind: &str) -> usize {
        self.kinds
            .iter()
            .position(|k| k == kind)
            .expect("kinds are collected first")
    }

    /// The `ocean_*_default(struct S *out)` function of a struct, if any.
    fn default_fn(&self, s: &str) -> Option<&str> {
        self.h.functions.iter().find_map(|f| {
            let only_out = matches!(
                f.params.as_slice(),
                [p] if p.ty.stars == 1 && !p.ty.konst && p.ty.base == Base::Struct(s.into())
            );
            (f.name.ends_with("_default") && only_out && f.ret.base_name() == "OceanStatus")
                .then_some(f.name.as_str())
        })
    }

    /// Name of the C function filling `n` elements of struct `s` at `buf` (generated once).
    fn filler(&mut self, s: &str) -> String {
        self.structs_filled.insert(s.to_owned());
        format!("fill_{s}")
    }

    fn emit_fillers(&mut self) -> Result<String, String> {
        let mut c = String::new();
        for s in self.structs_filled.clone() {
            let how = if let Some(d) = self.default_fn(&s) {
                format!(
                    "if ({d}(&e) != OCEAN_STATUS_OK)\n        \
                     matrix_fail(\"{d} failed: %s\", ocean_last_error_message());"
                )
            } else if self.harness.contains(&format!("plausible_{s}(")) {
                format!("plausible_{s}(&e);")
            } else {
                self.zeroed.insert(s.clone());
                "/* no default and no plausible value: zeroed */".to_owned()
            };
            // Copied member by member into a zeroed struct: a struct the library wrote may
            // hold indeterminate padding, which the check that const inputs come back
            // unchanged would compare (memcheck reports it).
            let members: String = struct_leaves(self.h, &s)?
                .iter()
                .map(|l| format!("    z{p} = e{p};\n", p = l.path))
                .collect();
            let _ = write!(
                c,
                "static inline void fill_{s}(unsigned char *buf, size_t n)\n{{\n    \
                 {s} e, z;\n    size_t i;\n    memset(&e, 0, sizeof e);\n    \
                 memset(&z, 0, sizeof z);\n    {how}\n{members}    \
                 if (n > MATRIX_BUF / sizeof z)\n        n = MATRIX_BUF / sizeof z;\n    \
                 for (i = 0; i < n; i++)\n        memcpy(buf + i * sizeof z, &z, sizeof z);\n}}\n\n"
            );
        }
        Ok(c)
    }

    fn checker(&mut self, s: &str) -> String {
        self.structs_checked.insert(s.to_owned());
        format!("finite_{s}")
    }

    fn emit_checkers(&self) -> Result<String, String> {
        let mut c = String::new();
        for s in &self.structs_checked {
            let mut body = String::new();
            for leaf in struct_leaves(self.h, s)?
                .iter()
                .filter(|l| l.prim.is_float())
            {
                let _ = write!(
                    body,
                    "        if (!matrix_ok_value(e.{p}, {inf})) {{\n            \
                     matrix_nonfinite(name, i, \"{path}\", e.{p});\n            return;\n        }}\n",
                    p = &leaf.path[1..],
                    path = leaf.path,
                    inf = i32::from(leaf.infinity_ok),
                );
            }
            let _ = write!(
                c,
                "static inline void finite_{s}(const unsigned char *buf, size_t n, const char *name)\n\
                 {{\n    size_t i;\n    for (i = 0; i < n; i++) {{\n        {s} e;\n        \
                 memcpy(&e, buf + i * sizeof e, sizeof e);\n{body}    }}\n}}\n\n"
            );
        }
        Ok(c)
    }

    fn has_float_leaves(&self, s: &str) -> Result<bool, String> {
        Ok(struct_leaves(self.h, s)?.iter().any(|l| l.prim.is_float()))
    }

    fn run(&mut self, f: &Function, roles: &[Role]) -> Result<(), String> {
        if f.params.len() > 12 {
            return Err(format!("{}: more parameters than scratch slots", f.name));
        }
        let fname = &f.name;
        let overrides: Vec<_> = OVERRIDES.iter().filter(|o| o.0 == *fname).collect();
        for o in &overrides {
            if !f.params.iter().any(|p| p.name == o.1) {
                return Err(format!("override for {fname}: no parameter `{}`", o.1));
            }
        }
        let over = |p: &str| overrides.iter().find(|o| o.1 == p).map(|o| o.2);
        // The lengths the documentation holds to an exact value (LENGTH_MISMATCH otherwise).
        let exact = exact_lengths(f);

        // The argument struct, the base, the call with its checks.
        let mut fields = String::new();
        let mut base = String::new();
        let mut checks_ok = String::new();
        let mut checks_fail = String::new();
        let mut sentinels = String::new();
        let mut inputs_kept = String::new();
        let mut elem_sizes = Vec::new();
        let mut variants: Vec<Variant> = Vec::new();
        let v = |param: &str, value: &str, code: String, expect: Expect| Variant {
            param: param.into(),
            value: value.into(),
            code,
            expect,
            length: None,
            index: None,
            stage: Stage::Value,
            mark_null: None,
        };

        for (i, (p, role)) in f.params.iter().zip(roles).enumerate() {
            let first_variant = variants.len();
            let n = &p.name;
            if !c_ident_ok(n) {
                return Err(format!("{fname}: parameter name {n:?}"));
            }
            let ty = p.ty.to_string();
            let _ = writeln!(fields, "    {ty} {n};");
            // The element count an output's checks cover: the nearest length parameter after
            // it, else before it, else a few elements.
            let len_param = f.params[i + 1..]
                .iter()
                .zip(&roles[i + 1..])
                .chain(f.params[..i].iter().zip(&roles[..i]).rev())
                .find(|(_, r)| **r == Role::Length)
                .map(|(q, _)| format!("a->{}", q.name));
            let count = |elem: &str| match &len_param {
                Some(l) => format!("matrix_count({l}, sizeof({elem}))"),
                None => format!("matrix_count(MATRIX_FEW, sizeof({elem}))"),
            };
            let null_expect = || Expect::Only(vec!["OCEAN_STATUS_NULL_POINTER", "OCEAN_STATUS_OK"]);
            let pointer_variants = |variants: &mut Vec<Variant>, align_gt1: bool| {
                variants.push(v(n, "NULL", format!("a.{n} = NULL;"), null_expect()));
                if align_gt1 {
                    variants.push(v(
                        n,
                        "misaligned",
                        format!("a.{n} = ({ty})(void *)(slot[{i}] + 1);"),
                        Expect::Only(vec!["OCEAN_STATUS_MISALIGNED_POINTER"]),
                    ));
                }
            };
            let is_output = matches!(
                role,
                Role::OutHandle { .. }
                    | Role::OutStruct { .. }
                    | Role::OutArray { .. }
                    | Role::OutBytes
                    | Role::OutChars
                    | Role::OutPointer
            );
            let is_input = matches!(role, Role::InStruct { .. } | Role::InArray { .. });
            if is_input {
                let _ = writeln!(sentinels, "    matrix_snapshot({i});");
                let _ = writeln!(inputs_kept, "    matrix_input_kept({i}, \"{n}\");");
            }
            // The element size of an output, for the check that a success wrote no further
            // than its length: `void *` outputs hold at most floats.
            let out_elem = match role {
                Role::OutStruct { name } => Some(name.clone()),
                Role::OutArray { prim } => Some(prim.c().to_owned()),
                Role::OutBytes => Some("float".to_owned()),
                Role::OutChars => Some("char".to_owned()),
                _ => None,
            };
            let extent = documented_extent(f, roles, n).map(|l| format!("a->{l}"));
            if let (Some(elem), Some(l)) = (&out_elem, &extent) {
                let _ = writeln!(
                    checks_ok,
                    "        if ((void *)a->{n} == (void *)slot[{i}])\n            \
                     matrix_written_within({i}, {l}, sizeof({elem}), \"{n}\");"
                );
            }
            if is_output {
                let _ = writeln!(sentinels, "    matrix_sentinel({i});");
                let _ = writeln!(checks_fail, "        matrix_untouched({i}, \"{n}\");");
            }
            if over(n).is_some() {
                let scalar = matches!(
                    role,
                    Role::Float(_)
                        | Role::Length
                        | Role::Index
                        | Role::U32
                        | Role::U8
                        | Role::InString
                );
                if !scalar && !matches!(role, Role::InArray { .. }) {
                    return Err(format!("{fname}: `{n}` ({role:?}) cannot be overridden"));
                }
            }
            match role {
                Role::Handle { kind } => {
                    let k = self.kind_index(kind);
                    if !p.ty.konst {
                        self.mutable.insert(kind.clone());
                    }
                    let _ = writeln!(base, "    a->{n} = ({ty})matrix_live({k});");
                    let invalid = || Expect::Only(vec!["OCEAN_STATUS_INVALID_HANDLE"]);
                    variants.push(v(
                        n,
                        "NULL",
                        format!("a.{n} = NULL;"),
                        Expect::Only(vec!["OCEAN_STATUS_NULL_POINTER"]),
                    ));
                    variants.push(v(
                        n,
                        "another kind",
                        format!("a.{n} = ({ty})matrix_other({k});"),
                        invalid(),
                    ));
                    variants.push(v(
                        n,
                        "destroyed",
                        format!("a.{n} = ({ty})matrix_dead({k});"),
                        invalid(),
                    ));
                    variants.push(v(
                        n,
                        "zeroed memory",
                        format!("a.{n} = ({ty})(void *)foreign_memory;"),
                        invalid(),
                    ));
                    variants.push(v(
                        n,
                        "(void*)1",
                        format!("a.{n} = ({ty})(void *)(uintptr_t)1;"),
                        invalid(),
                    ));
                }
                Role::OutHandle { kind } => {
                    let k = self.kind_index(kind);
                    let _ = writeln!(base, "    a->{n} = ({ty})(void *)slot[{i}];");
                    let _ = writeln!(checks_ok, "        matrix_got_handle({k}, {i}, \"{n}\");");
                    elem_sizes.push("sizeof(void *)".into());
                    pointer_variants(&mut variants, true);
                }
                Role::InStruct { name } => {
                    let fill = self.filler(name);
                    let _ = writeln!(
                        base,
                        "    {fill}(slot[{i}], MATRIX_FILL);\n    a->{n} = ({ty})(void *)slot[{i}];"
                    );
                    elem_sizes.push(format!("sizeof({name})"));
                    pointer_variants(&mut variants, true);
                    let all = struct_leaves(self.h, name)?;
                    // The last element too (one bad member), so that validation must cover
                    // every element, not only the first.
                    let count_after = f.params.get(i + 1).filter(|_| roles[i + 1] == Role::Length);
                    if let (Some(l), Some(leaf)) =
                        (count_after, all.iter().find(|l| l.prim.is_float()))
                    {
                        let l = format!("a.{}", l.name);
                        variants.push(v(
                            &format!("{n}[last]{}", leaf.path),
                            "NaN",
                            format!(
                                "if ({l} > 0 && {l} <= MATRIX_FILL)\n            \
                                 (({name} *)(void *)slot[{i}])[{l} - 1].{} = NAN;",
                                &leaf.path[1..]
                            ),
                            Expect::Any,
                        ));
                    }
                    for leaf in all {
                        for (label, value) in member_values(leaf.prim) {
                            variants.push(v(
                                &format!("{n}[0]{}", leaf.path),
                                label,
                                format!(
                                    "(({name} *)(void *)slot[{i}])->{} = {value};",
                                    &leaf.path[1..]
                                ),
                                Expect::Any,
                            ));
                        }
                    }
                    // Extensions: one of a type no version defines (refused, never ignored),
                    // and a misaligned link (refused before it is read).
                    for link in chain_links(self.h, name) {
                        let at = format!("(({name} *)(void *)slot[{i}])->{}", &link[1..]);
                        variants.push(v(
                            &format!("{n}[0]{link}"),
                            "unknown extension",
                            format!("{at} = &matrix_unknown_extension;"),
                            Expect::IfBaseOk("OCEAN_STATUS_INVALID_ARGUMENT"),
                        ));
                        variants.push(v(
                            &format!("{n}[0]{link}"),
                            "misaligned",
                            format!(
                                "{at} = (const OceanChain *)(const void *)\
                                 (matrix_chain_bytes + 4);"
                            ),
                            Expect::IfBaseOk("OCEAN_STATUS_MISALIGNED_POINTER"),
                        ));
                    }
                }
                Role::OutStruct { name } => {
                    let _ = writeln!(base, "    a->{n} = ({ty})(void *)slot[{i}];");
                    elem_sizes.push(format!("sizeof({name})"));
                    if self.has_float_leaves(name)? {
                        let check = self.checker(name);
                        let _ = writeln!(
                            checks_ok,
                            "        {check}(slot[{i}], {}, \"{n}\");",
                            count(name)
                        );
                    }
                    pointer_variants(&mut variants, true);
                }
                Role::ByValue { name } => {
                    let fill = self.filler(name);
                    let _ = writeln!(base, "    {fill}((unsigned char *)&a->{n}, 1);");
                    for leaf in struct_leaves(self.h, name)? {
                        if !leaf.prim.is_float() {
                            return Err(format!(
                                "{fname}: by-value {name}{} is no float",
                                leaf.path
                            ));
                        }
                        for (label, value) in float_values(leaf.prim) {
                            variants.push(v(
                                &format!("{n}{}", leaf.path),
                                label,
                                format!("a.{n}{} = {value};", leaf.path),
                                Expect::Any,
                            ));
                        }
                    }
                }
                Role::InArray { prim } => {
                    let fill = match (over(n), prim) {
                        (Some(o), _) => o.to_owned(),
                        (None, Prim::F32) => "matrix_fill_f32(buf, MATRIX_FILL, 0.0f, 1.0f)".into(),
                        (None, Prim::F64) => "matrix_fill_f64(buf, MATRIX_FILL)".into(),
                        (None, Prim::U8) => "matrix_fill_u8(buf, MATRIX_FILL)".into(),
                        (None, Prim::U16) => "matrix_fill_u16(buf, MATRIX_FILL)".into(),
                        (None, p) => return Err(format!("{fname}: input array of {p:?}")),
                    };
                    let _ = writeln!(
                        base,
                        "    {{\n        unsigned char *buf = slot[{i}];\n        {fill};\n    }}\n    \
                         a->{n} = ({ty})(void *)slot[{i}];"
                    );
                    elem_sizes.push(format!("sizeof({})", prim.c()));
                    pointer_variants(&mut variants, *prim != Prim::U8);
                    if prim.is_float() {
                        for (label, value) in &float_values(*prim)[..4] {
                            variants.push(v(
                                &format!("{n}[0]"),
                                label,
                                format!("(({} *)(void *)slot[{i}])[0] = {value};", prim.c()),
                                Expect::Any,
                            ));
                        }
                    }
                }
                Role::OutArray { prim } => {
                    let _ = writeln!(base, "    a->{n} = ({ty})(void *)slot[{i}];");
                    elem_sizes.push(format!("sizeof({})", prim.c()));
                    if prim.is_float() {
                        let _ = writeln!(
                            checks_ok,
                            "        matrix_finite_{}(slot[{i}], {}, \"{n}\");",
                            if *prim == Prim::F32 { "f32" } else { "f64" },
                            count(prim.c())
                        );
                    }
                    pointer_variants(&mut variants, *prim != Prim::U8);
                }
                Role::OutBytes => {
                    let _ = writeln!(base, "    a->{n} = (void *)slot[{i}];");
                    // Its element type is chosen by another argument: at most a float.
                    elem_sizes.push("sizeof(float)".into());
                    pointer_variants(&mut variants, false);
                }
                Role::OutChars => {
                    let _ = writeln!(base, "    a->{n} = (char *)slot[{i}];");
                    elem_sizes.push("1".into());
                    pointer_variants(&mut variants, false);
                }
                Role::OutPointer => {
                    let _ = writeln!(base, "    a->{n} = ({ty})(void *)slot[{i}];");
                    elem_sizes.push("sizeof(void *)".into());
                    pointer_variants(&mut variants, true);
                }
                Role::InString => {
                    let s = over(n).unwrap_or("\"\"");
                    let _ = writeln!(base, "    a->{n} = {s};");
                    variants.push(v(n, "NULL", format!("a.{n} = NULL;"), null_expect()));
                    for (label, value) in [
                        ("\\\"\\\"", "\"\""),
                        ("\\\"no such name\\\"", "\"no such name\""),
                        ("\\\"\\\\xff\\\" (not UTF-8)", "\"\\xff\""),
                    ] {
                        variants.push(v(n, label, format!("a.{n} = {value};"), Expect::Any));
                    }
                }
                Role::User => {
                    let _ = writeln!(base, "    a->{n} = &matrix_cookie;");
                    variants.push(v(n, "NULL", format!("a.{n} = NULL;"), Expect::SameAsBase));
                }
                Role::Callback { ty: cb } => {
                    for f in ["count", "cancel"] {
                        if !self.harness.contains(&format!("{f}_{cb}(")) {
                            return Err(format!(
                                "tests/c/matrix_harness.h has no `{f}_{cb}` for {fname}"
                            ));
                        }
                    }
                    let _ = writeln!(base, "    a->{n} = NULL;");
                    variants.push(v(
                        n,
                        "a callback going on",
                        format!("a.{n} = count_{cb};"),
                        Expect::IfBaseOk("OCEAN_STATUS_OK"),
                    ));
                    variants.push(v(
                        n,
                        "a callback cancelling",
                        format!("a.{n} = cancel_{cb};"),
                        Expect::IfBaseOk("OCEAN_STATUS_CANCELLED"),
                    ));
                }
                Role::Float(prim) => {
                    let b = over(n).unwrap_or(if *prim == Prim::F32 { "1.0f" } else { "1.0" });
                    let _ = writeln!(base, "    a->{n} = {b};");
                    for (label, value) in float_values(*prim) {
                        variants.push(v(n, label, format!("a.{n} = {value};"), Expect::Any));
                    }
                }
                Role::Length => {
                    let b = over(n).unwrap_or("4");
                    let _ = writeln!(base, "    a->{n} = {b};");
                    for (label, value) in [
                        ("0", "0"),
                        ("1", "1"),
                        ("SIZE_MAX", "SIZE_MAX"),
                        ("SIZE_MAX/2+1", "SIZE_MAX / 2 + 1"),
                    ] {
                        // Above PTRDIFF_MAX a count overflows whatever its element, and counts
                        // come before values: OCEAN_STATUS_LENGTH_OVERFLOW, never the
                        // LENGTH_MISMATCH of a length that disagrees with a size. A length held
                        // to an exact value answers any other (1 is none of the bases) with
                        // LENGTH_MISMATCH, whatever the buffer: nothing is read or written.
                        let expect = if value.starts_with("SIZE_MAX") {
                            Expect::Only(vec!["OCEAN_STATUS_LENGTH_OVERFLOW"])
                        } else if value == "1" && b != "1" && exact.contains(&n.as_str()) {
                            Expect::IfBaseOk("OCEAN_STATUS_LENGTH_MISMATCH")
                        } else {
                            Expect::Any
                        };
                        let mut var = v(n, label, format!("a.{n} = {value};"), expect);
                        var.length = Some(value.into());
                        variants.push(var);
                    }
                }
                Role::Index => {
                    let b = over(n).unwrap_or("0");
                    let _ = writeln!(base, "    a->{n} = {b};");
                    let mut values = vec![
                        ("1000", "1000"),
                        ("0xFFFFFFFF", "0xFFFFFFFFu"),
                        ("SIZE_MAX", "SIZE_MAX"),
                    ];
                    if b != "0" {
                        values.push(("0", "0"));
                    }
                    for (label, value) in values {
                        variants.push(v(n, label, format!("a.{n} = {value};"), Expect::Any));
                    }
                }
                Role::U32 => {
                    let b = over(n).unwrap_or("0");
                    let _ = writeln!(base, "    a->{n} = {b};");
                    let mut values = vec![("0xFFFFFFFF", "0xFFFFFFFFu"), ("1000", "1000")];
                    if b != "0" {
                        values.push(("0", "0"));
                    }
                    for (label, value) in values {
                        variants.push(v(n, label, format!("a.{n} = {value};"), Expect::Any));
                    }
                }
                Role::U8 => {
                    let b = over(n).unwrap_or("0");
                    let _ = writeln!(base, "    a->{n} = {b};");
                    for (label, value) in [("2", "2"), ("255", "255")] {
                        variants.push(v(n, label, format!("a.{n} = {value};"), Expect::Any));
                    }
                }
            }
            let pointer = !matches!(
                role,
                Role::Handle { .. }
                    | Role::User
                    | Role::Callback { .. }
                    | Role::Float(_)
                    | Role::Length
                    | Role::Index
                    | Role::U32
                    | Role::U8
                    | Role::ByValue { .. }
            );
            for var in &mut variants[first_variant..] {
                var.index = Some(i);
                var.stage = if matches!(role, Role::Handle { .. }) {
                    Stage::Handle
                } else if pointer
                    && var.param == *n
                    && matches!(var.value.as_str(), "NULL" | "misaligned")
                {
                    Stage::Pointer
                } else {
                    Stage::Value
                };
                if var.stage == Stage::Pointer && var.value == "NULL" {
                    var.mark_null = Some(i);
                }
            }
        }

        // The error order (header preamble): a bad handle is reported before anything else,
        // and a NULL pointer that is refused alone before any bad count or value. Each single
        // variant is run again with the first handle destroyed, and with each required pointer
        // NULL.
        let mut ordered = Vec::new();
        if let Some(h) = roles.iter().position(|r| matches!(r, Role::Handle { .. })) {
            let Role::Handle { kind } = &roles[h] else {
                unreachable!()
            };
            let (hn, hty, k) = (
                &f.params[h].name,
                f.params[h].ty.to_string(),
                self.kind_index(kind),
            );
            for var in variants.iter().filter(|x| x.index.is_some_and(|i| i != h)) {
                ordered.push(Variant {
                    param: format!("{hn}=destroyed, {}", var.param),
                    code: format!("{}\n        a.{hn} = ({hty})matrix_dead({k});", var.code),
                    expect: Expect::Only(vec!["OCEAN_STATUS_INVALID_HANDLE"]),
                    index: None,
                    mark_null: None,
                    ..var.clone()
                });
            }
        }
        for (i, p) in f.params.iter().enumerate() {
            let refused_alone = variants
                .iter()
                .any(|x| x.index == Some(i) && x.stage == Stage::Pointer && x.value == "NULL");
            if !refused_alone {
                continue;
            }
            let later = variants.iter().filter(|x| {
                x.stage == Stage::Value
                    && x.index.is_some_and(|j| j != i)
                    // NULL with a length of 0 is the documented "nothing" or size query.
                    && x.length.as_deref() != Some("0")
            });
            for var in later {
                ordered.push(Variant {
                    param: format!("{}=NULL, {}", p.name, var.param),
                    code: format!("{}\n        a.{} = NULL;", var.code, p.name),
                    expect: Expect::IfNullRefused(i),
                    index: None,
                    mark_null: None,
                    ..var.clone()
                });
            }
        }

        let args: Vec<String> = f.params.iter().map(|p| format!("a->{}", p.name)).collect();
        let id = fname;
        let fields = if fields.is_empty() {
            "    int unused;\n".to_owned()
        } else {
            fields
        };
        let max_elem = if elem_sizes.is_empty() {
            "1".to_owned()
        } else {
            elem_sizes.iter().fold(String::from("1"), |acc, s| {
                format!("MATRIX_MAX({acc}, {s})")
            })
        };
        let mut c = String::new();
        let _ = write!(
            c,
            "/* {ret} {fname}({sig}) */\n\
             typedef struct {{\n{fields}}} A_{id};\n\n\
             static void base_{id}(A_{id} *a)\n{{\n    (void)a;\n{base}}}\n\n\
             static void call_{id}(A_{id} *a)\n{{\n    OceanStatus s;\n{sentinels}    \
             matrix_pre_call();\n    s = {fname}({args});\n    matrix_post_call(s);\n{inputs_kept}    \
             if (s == OCEAN_STATUS_OK) {{\n{checks_ok}        (void)0;\n    }} else {{\n\
             {checks_fail}        (void)0;\n    }}\n}}\n\n\
             static void run_{id}(void)\n{{\n    A_{id} a;\n    \
             const size_t max_elem = {max_elem};\n    (void)max_elem;\n    \
             matrix_function(\"{fname}\");\n",
            ret = f.ret,
            sig = f
                .params
                .iter()
                .map(|p| format!("{} {}", p.ty, p.name))
                .collect::<Vec<_>>()
                .join(", "),
            args = args.join(", "),
        );
        for (p, role) in f.params.iter().zip(roles) {
            if let Role::Handle { kind } = role
                && !p.ty.konst
            {
                let _ = writeln!(c, "    matrix_refresh({});", self.kind_index(kind));
            }
        }
        let _ = write!(
            c,
            "    if (matrix_begin(\"(base)\", \"plausible arguments\")) {{\n        \
             base_{id}(&a);\n        call_{id}(&a);\n    }}\n"
        );
        variants.extend(ordered);
        for var in &variants {
            let expect = match &var.expect {
                Expect::Any => String::new(),
                Expect::Only(list) => format!(
                    "        matrix_expect({});\n",
                    list.iter()
                        .map(|s| format!("MATRIX_BIT({s})"))
                        .collect::<Vec<_>>()
                        .join(" | ")
                ),
                Expect::IfBaseOk(s) => format!("        matrix_expect_if_base_ok({s});\n"),
                Expect::SameAsBase => "        matrix_expect_same_as_base();\n".into(),
                Expect::IfNullRefused(i) => {
                    format!("        matrix_expect_if_null_refused({i});\n")
                }
            };
            let expect = match var.mark_null {
                Some(i) => format!("        matrix_mark_null({i});\n{expect}"),
                None => expect,
            };
            let guard = var
                .length
                .as_ref()
                .map(|l| format!("matrix_length_ok({l}, max_elem) && "))
                .unwrap_or_default();
            let _ = write!(
                c,
                "    if ({guard}matrix_begin(\"{p}\", \"{val}\")) {{\n        base_{id}(&a);\n        \
                 {code}\n{expect}        call_{id}(&a);\n    }}\n",
                p = var.param,
                val = var.value,
                code = var.code,
            );
        }
        if roles.iter().any(|r| matches!(r, Role::Handle { .. })) {
            let _ = writeln!(c, "    matrix_foreign_untouched();");
        }
        c.push_str("}\n\n");
        self.variants += variants.len() + 1;
        self.out.push_str(&c);
        Ok(())
    }

    fn run_destroy(&mut self, f: &Function, kind: &str) {
        let k = self.kind_index(kind);
        let fname = &f.name;
        let ty = f.params[0].ty.to_string();
        let n = &f.params[0].name;
        let mut c = format!(
            "/* void {fname}({ty} {n}) */\nstatic void run_{fname}(void)\n{{\n    \
             matrix_function(\"{fname}\");\n"
        );
        // (value label, handle expression, checks after the call)
        let cases: [(&str, String, String); 6] = [
            (
                "a live handle",
                format!("matrix_kinds_table[{k}].make()"),
                format!(
                    "        matrix_message_kept();\n        matrix_expect_alive({k}, h, 0);\n"
                ),
            ),
            (
                "NULL",
                "NULL".into(),
                "        matrix_message_kept();\n".into(),
            ),
            (
                "another kind",
                format!("matrix_other({k})"),
                format!(
                    "        matrix_message_set();\n        \
                     matrix_expect_alive(({k} + 1) % M.nkinds, h, 1);\n"
                ),
            ),
            (
                "destroyed",
                format!("matrix_dead({k})"),
                "        matrix_message_set();\n".into(),
            ),
            (
                "zeroed memory",
                "(void *)foreign_memory".into(),
                "        matrix_message_set();\n        matrix_foreign_untouched();\n".into(),
            ),
            (
                "(void*)1",
                "(void *)(uintptr_t)1".into(),
                "        matrix_message_set();\n".into(),
            ),
        ];
        for (i, (label, expr, after)) in cases.iter().enumerate() {
            let param = if i == 0 { "(base)" } else { n.as_str() };
            let _ = write!(
                c,
                "    if (matrix_begin(\"{param}\", \"{label}\")) {{\n        void *h = {expr};\n        \
                 matrix_pre_plain();\n        {fname}(({ty})h);\n        matrix_post_plain();\n{after}    }}\n"
            );
        }
        c.push_str("}\n\n");
        self.variants += cases.len();
        self.out.push_str(&c);
    }

    fn run_plain(&mut self, f: &Function, roles: &[Role]) {
        let fname = &f.name;
        let returns_string = f.ret.base_name() == "char";
        let mut c = format!(
            "/* {} {fname}(...) */\nstatic void run_{fname}(void)\n{{\n    matrix_function(\"{fname}\");\n",
            f.ret
        );
        // The base (every argument 0) and, per uint32_t argument, 1000 and 0xFFFFFFFF.
        let mut cases = vec![("(base)".to_owned(), "0".to_owned(), vec!["0"; roles.len()])];
        for (i, p) in f.params.iter().enumerate() {
            for value in ["1000", "0xFFFFFFFFu"] {
                let mut args = vec!["0"; roles.len()];
                args[i] = value;
                cases.push((p.name.clone(), value.to_owned(), args));
            }
        }
        for (param, value, args) in &cases {
            let check = if returns_string {
                "        if (!r)\n            matrix_fail(\"returned NULL\");\n"
            } else {
                "        (void)r;\n"
            };
            let _ = write!(
                c,
                "    if (matrix_begin(\"{param}\", \"{value}\")) {{\n        {ret} r;\n        \
                 matrix_pre_plain();\n        r = {fname}({args});\n        matrix_post_plain();\n\
                 {check}        matrix_message_kept();\n    }}\n",
                ret = f.ret,
                args = args.join(", "),
            );
        }
        c.push_str("}\n\n");
        self.variants += cases.len();
        self.out.push_str(&c);
    }
}

/// Generates the program for `h`; `harness` is the text of `tests/c/matrix_harness.h` (its
/// `plausible_` fillers and callbacks are used where it defines them).
pub fn generate(h: &Header, harness: &str) -> Result<Program, String> {
    // Statuses, dense from 0, so the program can name them.
    let status = h.enum_def("OceanStatus").ok_or("no enum OceanStatus")?;
    for (i, (name, v)) in status.values.iter().enumerate() {
        if *v != i as u64 {
            return Err(format!(
                "OceanStatus {name} = {v} breaks the dense numbering"
            ));
        }
    }
    let mut errors = Vec::new();
    for (f, p, _) in OVERRIDES {
        if !h.functions.iter().any(|x| x.name == *f) {
            errors.push(format!(
                "override for {f}.{p}: no such function in the header"
            ));
        }
    }
    let kinds: Vec<String> = h
        .opaque
        .iter()
        .filter(|k| !GPU_KINDS.contains(&k.as_str()))
        .cloned()
        .collect();
    for k in &kinds {
        if !harness.contains(&format!("make_{k}(void)")) {
            errors.push(format!(
                "handle kind {k}: tests/c/matrix_harness.h has no make_{k}() (a new kind: teach \
                 the harness to make one)"
            ));
        }
    }
    let mut g = Gen {
        h,
        harness,
        kinds: kinds.clone(),
        mutable: BTreeSet::new(),
        structs_filled: BTreeSet::new(),
        structs_checked: BTreeSet::new(),
        zeroed: BTreeSet::new(),
        out: String::new(),
        variants: 0,
    };
    let mut gpu_skipped = Vec::new();
    let mut runs = Vec::new();
    let mut classes = Vec::new();
    for f in &h.functions {
        match classify_function(h, f) {
            Ok(class) => classes.push((f, class)),
            Err(e) => errors.push(e),
        }
    }
    // A query per kind: the first status-returning function whose only arguments are one handle
    // of the kind and one output; it tells a live handle from a dead one.
    let mut alive = Vec::new();
    for k in &kinds {
        let q = classes.iter().find(|(f, c)| match c {
            Class::Fallible(r) => {
                matches!(r.as_slice(), [Role::Handle { kind }, Role::OutArray { .. } | Role::OutStruct { .. }] if kind == k)
                    && f.params[1].ty.stars == 1
            }
            _ => false,
        });
        match q {
            Some((f, _)) => alive.push((
                f.name.clone(),
                f.params[0].ty.clone(),
                f.params[1].ty.pointee(),
            )),
            None => errors.push(format!(
                "handle kind {k}: no query function to tell it alive"
            )),
        }
    }
    if !errors.is_empty() {
        return Err(errors.join("\n"));
    }
    for (f, class) in &classes {
        let gpu = f
            .params
            .iter()
            .any(|p| GPU_KINDS.contains(&p.ty.base_name()));
        if gpu {
            gpu_skipped.push(f.name.clone());
            continue;
        }
        match class {
            Class::Fallible(roles) => g.run(f, roles)?,
            Class::Destroy { kind } => g.run_destroy(f, kind),
            Class::Plain(roles) => g.run_plain(f, roles),
        }
        runs.push(f.name.clone());
    }

    let mut src = String::new();
    src.push_str(
        "/* Generated by tests/tests/c_matrix.rs from include/ocean.h: do not edit. */\n\
         #define _POSIX_C_SOURCE 200809L\n#include \"ocean.h\"\n\n",
    );
    let _ = writeln!(
        src,
        "static const char *const matrix_status_names[] = {{\n{}}};\n#define MATRIX_STATUS_COUNT {}\n",
        status
            .values
            .iter()
            .map(|(n, _)| format!("    \"{n}\",\n"))
            .collect::<String>(),
        status.values.len()
    );
    src.push_str(
        "#include \"matrix_harness.h\"\n\n#define MATRIX_MAX(a, b) ((a) > (b) ? (a) : (b))\n\n",
    );
    let _ = writeln!(src, "/* CPU handle kinds, in header order. */");
    for (i, k) in kinds.iter().enumerate() {
        let destroy = h
            .functions
            .iter()
            .find(
                |f| matches!(classify_function(h, f), Ok(Class::Destroy { ref kind }) if kind == k),
            )
            .ok_or(format!("handle kind {k}: no destroy function"))?;
        let (query, handle_ty, out_ty) = &alive[i];
        let _ = write!(
            src,
            "static void destroy_{k}(void *h) {{ {d}((struct {k} *)h); }}\n\
             static int alive_{k}(const void *h)\n{{\n    {out_ty} out;\n    \
             return {query}(({handle_ty})h, &out) == OCEAN_STATUS_OK;\n}}\n",
            d = destroy.name,
        );
    }
    let _ = writeln!(
        src,
        "\nstatic const struct matrix_kind matrix_kinds_table[] = {{\n{}}};\n",
        kinds
            .iter()
            .map(|k| format!("    {{\"{k}\", make_{k}, destroy_{k}, alive_{k}}},\n"))
            .collect::<String>()
    );
    src.push_str(&g.emit_fillers()?);
    src.push_str(&g.emit_checkers()?);
    src.push_str(&g.out);
    let _ = write!(
        src,
        "int main(int argc, char **argv)\n{{\n    matrix_init(argc, argv);\n    \
         matrix_setup_kinds(matrix_kinds_table, {});\n{}    return matrix_summary(\"{}\");\n}}\n",
        kinds.len(),
        runs.iter()
            .map(|r| format!("    run_{r}();\n"))
            .collect::<String>(),
        gpu_skipped.join(", ")
    );
    Ok(Program {
        source: src,
        functions: runs.len(),
        gpu_skipped,
        variants: g.variants,
        zeroed_structs: g.zeroed,
    })
}
