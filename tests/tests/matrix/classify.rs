//! What the bad-input matrix knows of each parameter and function of the header: its role
//! (from its C type and, for `size_t` and `void *`, its name), the base value and the bad values
//! each role gets, the documented overrides, and the leaves of parameter structs.

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

    pub(crate) fn is_float(self) -> bool {
        matches!(self, Prim::F32 | Prim::F64)
    }

    pub(crate) fn c(self) -> &'static str {
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
pub(crate) fn exact_lengths(f: &Function) -> Vec<&str> {
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
pub(crate) fn documented_extent<'f>(f: &'f Function, roles: &[Role], out: &str) -> Option<&'f str> {
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

pub(crate) fn leaves(
    h: &Header,
    s: &Struct,
    prefix: &str,
    out: &mut Vec<Leaf>,
) -> Result<(), String> {
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
pub(crate) fn float_values(prim: Prim) -> &'static [(&'static str, &'static str)] {
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
pub(crate) fn member_values(prim: Prim) -> &'static [(&'static str, &'static str)] {
    match prim {
        Prim::F64 => &[("NaN", "NAN"), ("1e300", "1e300")],
        Prim::F32 => &[("NaN", "NAN"), ("FLT_MAX", "FLT_MAX")],
        Prim::U8 => &[("2", "2")],
        Prim::U32 => &[("0xFFFFFFFF", "0xFFFFFFFFu")],
        Prim::Usize => &[("0", "0"), ("SIZE_MAX", "SIZE_MAX")],
        Prim::U16 | Prim::U64 => &[],
    }
}
