//! Every WGSL source of the crate, validated by naga and exportable to other shading languages.
//!
//! An OpenGL, Vulkan, D3D or Metal engine that does not use wgpu can still run the ocean passes:
//! [`export`] translates a shader with naga and lists its resource bindings, so the engine can
//! create matching buffers and bind them.
//!
//! | [`Language`]        | output                                   | versions                       |
//! |---------------------|------------------------------------------|--------------------------------|
//! | [`Language::Glsl`]  | one file per entry point                 | 430 core (compute), 330 core (draw) |
//! | [`Language::GlslEs`]| one file per entry point                 | ES 3.10                        |
//! | [`Language::Hlsl`]  | one file, every entry point              | Shader Model 5.1               |
//! | [`Language::Msl`]   | one file, every entry point              | MSL 2.0                        |
//! | [`Language::SpirV`] | one binary module, every entry point     | SPIR-V 1.0                     |
//!
//! Bindings: WGSL `@group(g) @binding(b)` stays `set = g, binding = b` in SPIR-V,
//! `register(<b|t|u|s>b, space g)` in HLSL. In GLSL the groups are flattened: each namespace
//! (uniform blocks, shader storage blocks, texture units, image units) is numbered from 0 in
//! (group, binding) order; [`Binding::glsl_binding`] gives the number and [`Binding::glsl_name`]
//! the block or sampler name naga gave it. GLSL 3.30 has no `binding =` qualifier, so there the
//! engine assigns the number itself (`glUniformBlockBinding`, `glUniform1i`) by that name.
//! MSL resources are numbered per kind (`[[buffer(n)]]`, `[[texture(n)]]`) by naga's defaults.

use std::collections::BTreeMap;
use std::fmt;
use std::str::FromStr;

use naga::common::wgsl::TypeContext;
use naga::valid::{Capabilities, ModuleInfo, ValidationFlags, Validator};

/// Whether a shader is a compute pass or a draw (vertex + fragment) pass. It selects the GLSL
/// version: 4.30 core for compute (the first desktop version with compute shaders and storage
/// blocks), 3.30 core for draw passes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ShaderKind {
    /// Compute shader entry points only.
    Compute,
    /// Vertex and fragment entry points.
    Draw,
}

/// A pipeline stage.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Stage {
    /// Vertex shader.
    Vertex,
    /// Fragment shader.
    Fragment,
    /// Compute shader.
    Compute,
}

impl Stage {
    fn to_naga(self) -> naga::ShaderStage {
        match self {
            Stage::Vertex => naga::ShaderStage::Vertex,
            Stage::Fragment => naga::ShaderStage::Fragment,
            Stage::Compute => naga::ShaderStage::Compute,
        }
    }

    /// The conventional file-name suffix: `vert`, `frag` or `comp`.
    pub fn suffix(self) -> &'static str {
        match self {
            Stage::Vertex => "vert",
            Stage::Fragment => "frag",
            Stage::Compute => "comp",
        }
    }
}

/// An entry point of a registered shader.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EntryPoint {
    /// Function name in the WGSL source.
    pub name: &'static str,
    /// Its stage.
    pub stage: Stage,
}

/// A WGSL shader of the crate.
#[derive(Clone, Copy, Debug)]
pub struct ShaderEntry {
    /// Registry name, also the stem of exported file names.
    pub name: &'static str,
    /// The WGSL files it is assembled from, in order (shared snippets first).
    pub files: &'static [&'static str],
    /// The complete WGSL source (the files concatenated).
    pub source: &'static str,
    /// Compute or draw.
    pub kind: ShaderKind,
    /// Entry points, as declared in the source.
    pub entry_points: &'static [EntryPoint],
    /// One line on what it computes.
    pub description: &'static str,
}

/// Declares a shader's WGSL from one list of files (shared snippets first): `$name`, their
/// concatenation, and `$files`, the list itself for the registry, so the two cannot disagree.
macro_rules! wgsl {
    ($(#[$doc:meta])* $name:ident, $files:ident = [$($file:literal),+ $(,)?]) => {
        $(#[$doc])*
        pub const $name: &str = concat!($(include_str!(concat!("shaders/", $file))),+);
        const $files: &[&str] = &[$($file),+];
    };
}

wgsl!(
    /// Source of the trochoid displacement pass, after the shared `grid_normal.wgsl` (the unit
    /// normal of the CPU kernel). The host uploads sines and cosines, which the shader combines by
    /// angle addition.
    TROCHOID_WGSL, TROCHOID_FILES = ["grid_normal.wgsl", "trochoid.wgsl"]
);

wgsl!(
    /// Source of the layered (wave-train-box) displacement pass: sums of wave sets modulated by
    /// complex amplitude fields over grid rectangles, plus an additive height field. Like the
    /// trochoid pass it combines host-made sines and cosines by angle addition.
    LAYERS_WGSL, LAYERS_FILES = ["grid_normal.wgsl", "layers.wgsl"]
);

wgsl!(
    /// Source of the wave-train-box ray march: the modulation of one box from its rays, land and
    /// depth, for the layers pass; after the shared time snippet.
    WTB_MARCH_WGSL, WTB_MARCH_FILES = ["wtb_time.wgsl", "wtb_march.wgsl"]
);

wgsl!(
    /// Source of the wave-train-box height field: capillary noise (Eq. 9) and the beach run-up on
    /// every grid point, for the layers pass; after the shared time snippet.
    WTB_HEIGHT_WGSL, WTB_HEIGHT_FILES = ["wtb_time.wgsl", "wtb_height.wgsl"]
);

wgsl!(
    /// Source of the ocean renderer (Bruneton et al. 2010, §7.1): the projected grid's vertex stage
    /// (Eq. 2), the per-pixel normals, slope variances and lighting of the fragment stage (Eq. 3,
    /// 4, Algorithm 5.1), and a sky background; after the shared grid normal, ocean and
    /// lighting snippets.
    OCEAN_WGSL, OCEAN_FILES = [
        "grid_normal.wgsl",
        "ocean_common.wgsl",
        "ocean_light.wgsl",
        "ocean.wgsl",
    ]
);

wgsl!(
    /// Source of the ocean renderer's probes: compute entry points running the renderer's own
    /// surface and lighting functions on lists of inputs, for the parity tests.
    OCEAN_PROBE_WGSL, OCEAN_PROBE_FILES = [
        "grid_normal.wgsl",
        "ocean_common.wgsl",
        "ocean_light.wgsl",
        "ocean_probe.wgsl",
    ]
);

wgsl!(
    /// Source of SAO pass 1 (McGuire, Mara & Luebke 2012, §2.2): camera-space z from the depth
    /// buffer (Eq. 2), after the shared `sao_common.wgsl` (the parameter block).
    SAO_Z_WGSL, SAO_Z_FILES = ["sao_common.wgsl", "sao_z.wgsl"]
);

wgsl!(
    /// Source of SAO pass 2: one z MIP level from the previous one under Table 1's filters.
    SAO_MIP_WGSL, SAO_MIP_FILES = ["sao_common.wgsl", "sao_mip.wgsl"]
);

wgsl!(
    /// Source of SAO pass 3: the distributed AO samples (Eq. 1, 3–10 and the appendix's falloff),
    /// the 2×2 quad bilateral and the packing of A and z (§2.3).
    SAO_AO_WGSL, SAO_AO_FILES = ["sao_common.wgsl", "sao_ao.wgsl"]
);

wgsl!(
    /// Source of SAO passes 4 and 5: the horizontal and vertical bilateral blur (§2.4).
    SAO_BLUR_WGSL, SAO_BLUR_FILES = ["sao_common.wgsl", "sao_blur.wgsl"]
);

/// The order-2 spherical-harmonic irradiance of an environment (`sh_irradiance`, from
/// `ocean_brdf::Irradiance::gpu_rows`): part of the relief draw passes, and a snippet for an
/// engine's own shaders that light solids with the sea's sky.
pub const IRRADIANCE_WGSL: &str = include_str!("shaders/irradiance.wgsl");

wgsl!(
    /// Source of the relief-mapping draw pass (Policarpo & Oliveira, GPU Gems 3 ch. 18): the quad's
    /// vertex stage and the fragment stage that traces, shades, self-shadows and writes the hit's
    /// depth; after the shared tracer `relief_common.wgsl` and the isotropic texture
    /// `relief_texture.wgsl`.
    RELIEF_WGSL, RELIEF_FILES = [
        "relief_common.wgsl",
        "relief_texture.wgsl",
        "irradiance.wgsl",
        "relief_draw.wgsl",
    ]
);

wgsl!(
    /// [`RELIEF_WGSL`] reading a quad-directional cone map (§18.1, `ocean_relief::quad`): the same
    /// tracer and draw pass, the texture a 4-layer array (`relief_texture_quad.wgsl`) whose layer
    /// each ray picks once from its direction's quadrant.
    RELIEF_QUAD_WGSL, RELIEF_QUAD_FILES = [
        "relief_common.wgsl",
        "relief_texture_quad.wgsl",
        "irradiance.wgsl",
        "relief_draw.wgsl",
    ]
);

wgsl!(
    /// Source of the relief tracer's probe: the draw pass's own tracer and shadow test on lists of
    /// rays (parity tests), and a depth-texture copy for headless readback.
    RELIEF_PROBE_WGSL, RELIEF_PROBE_FILES = [
        "relief_common.wgsl",
        "relief_texture.wgsl",
        "relief_probe.wgsl",
    ]
);

wgsl!(
    /// [`RELIEF_PROBE_WGSL`] on a quad-directional cone map (`relief_texture_quad.wgsl`).
    RELIEF_QUAD_PROBE_WGSL, RELIEF_QUAD_PROBE_FILES = [
        "relief_common.wgsl",
        "relief_texture_quad.wgsl",
        "relief_probe.wgsl",
    ]
);

wgsl!(
    /// Source of the cone-map generator: relaxed and conservative cone maps by the branch-and-bound
    /// over a min-depth pyramid of `ocean_relief::ConeMap::generate`, in double-`f32` arithmetic.
    RELIEF_CONE_WGSL, RELIEF_CONE_FILES = ["relief_cone.wgsl"]
);

wgsl!(
    /// Source of the depth resolve of a multisampled frame: each pixel's nearest sample.
    DEPTH_RESOLVE_WGSL, DEPTH_RESOLVE_FILES = ["depth_resolve.wgsl"]
);

static SHADERS: [ShaderEntry; 16] = [
    ShaderEntry {
        name: "trochoid",
        files: TROCHOID_FILES,
        source: TROCHOID_WGSL,
        kind: ShaderKind::Compute,
        entry_points: &[EntryPoint {
            name: "displace",
            stage: Stage::Compute,
        }],
        description: "trochoid (Gerstner) displacement and normals of a grid (wave-train-boxes Eq. 6-7)",
    },
    ShaderEntry {
        name: "layers",
        files: LAYERS_FILES,
        source: LAYERS_WGSL,
        kind: ShaderKind::Compute,
        entry_points: &[EntryPoint {
            name: "displace",
            stage: Stage::Compute,
        }],
        description: "sums of wave sets modulated by complex amplitudes over grid rectangles, plus \
                      a height field: displacement and normals (wave-train-boxes Eq. 6-7)",
    },
    ShaderEntry {
        name: "wtb_march",
        files: WTB_MARCH_FILES,
        source: WTB_MARCH_WGSL,
        kind: ShaderKind::Compute,
        entry_points: &[
            EntryPoint {
                name: "clear",
                stage: Stage::Compute,
            },
            EntryPoint {
                name: "march",
                stage: Stage::Compute,
            },
            EntryPoint {
                name: "erode_x",
                stage: Stage::Compute,
            },
            EntryPoint {
                name: "erode_z",
                stage: Stage::Compute,
            },
            EntryPoint {
                name: "mean_x",
                stage: Stage::Compute,
            },
            EntryPoint {
                name: "mean_z",
                stage: Stage::Compute,
            },
            EntryPoint {
                name: "combine",
                stage: Stage::Compute,
            },
        ],
        description: "the ray march of a wave train box: per-ray land, shadow, shoaling and \
                      refraction, the land factor's smoothing and the time-dependent effects \
                      (wave-train-boxes §2, Fig. 2, 4-7, Eq. 8-10)",
    },
    ShaderEntry {
        name: "wtb_height",
        files: WTB_HEIGHT_FILES,
        source: WTB_HEIGHT_WGSL,
        kind: ShaderKind::Compute,
        entry_points: &[EntryPoint {
            name: "height_field",
            stage: Stage::Compute,
        }],
        description: "the height-only terms of wave train boxes on every grid point: capillary \
                      noise (wave-train-boxes Eq. 9) and the beach run-up",
    },
    ShaderEntry {
        name: "ocean",
        files: OCEAN_FILES,
        source: OCEAN_WGSL,
        kind: ShaderKind::Draw,
        entry_points: &[
            EntryPoint {
                name: "ocean_vs",
                stage: Stage::Vertex,
            },
            EntryPoint {
                name: "ocean_fs",
                stage: Stage::Fragment,
            },
            EntryPoint {
                name: "sky_vs",
                stage: Stage::Vertex,
            },
            EntryPoint {
                name: "sky_fs",
                stage: Stage::Fragment,
            },
            EntryPoint {
                name: "mesh_vs",
                stage: Stage::Vertex,
            },
            EntryPoint {
                name: "mesh_fs",
                stage: Stage::Fragment,
            },
            EntryPoint {
                name: "compose_fs",
                stage: Stage::Fragment,
            },
            EntryPoint {
                name: "compose_ms_fs",
                stage: Stage::Fragment,
            },
            EntryPoint {
                name: "ocean_layers_fs",
                stage: Stage::Fragment,
            },
        ],
        description: "ocean surface: projected grid displaced by filtered trochoids, per-pixel \
                      filtered normals and slope variance lit by the Sun, the sky and the sea \
                      (Bruneton et al. 2010 Eq. 2-4, 15, 26-28, Algorithm 5.1), and the sky; \
                      or the caller's own mesh lit the same way; either with its direct and \
                      ambient light apart, composed with an ambient obscurance",
    },
    ShaderEntry {
        name: "ocean_probe",
        files: OCEAN_PROBE_FILES,
        source: OCEAN_PROBE_WGSL,
        kind: ShaderKind::Compute,
        entry_points: &[
            EntryPoint {
                name: "probe_surface",
                stage: Stage::Compute,
            },
            EntryPoint {
                name: "probe_sea_color",
                stage: Stage::Compute,
            },
        ],
        description: "probes of the ocean renderer: its grid vertices, per-pixel surface and sea \
                      colour for lists of inputs (parity tests)",
    },
    ShaderEntry {
        name: "sao_z",
        files: SAO_Z_FILES,
        source: SAO_Z_WGSL,
        kind: ShaderKind::Compute,
        entry_points: &[EntryPoint {
            name: "z_pass",
            stage: Stage::Compute,
        }],
        description: "scalable ambient obscurance, pass 1: camera-space z from depth for every \
                      depth convention (SAO Eq. 2)",
    },
    ShaderEntry {
        name: "sao_mip",
        files: SAO_MIP_FILES,
        source: SAO_MIP_WGSL,
        kind: ShaderKind::Compute,
        entry_points: &[EntryPoint {
            name: "downsample",
            stage: Stage::Compute,
        }],
        description: "scalable ambient obscurance, pass 2: one z MIP level (rotated grid, \
                      arithmetic or harmonic mean, min, max: SAO Table 1)",
    },
    ShaderEntry {
        name: "sao_ao",
        files: SAO_AO_FILES,
        source: SAO_AO_WGSL,
        kind: ShaderKind::Compute,
        entry_points: &[
            EntryPoint {
                name: "ao",
                stage: Stage::Compute,
            },
            EntryPoint {
                name: "ao_stages",
                stage: Stage::Compute,
            },
        ],
        description: "scalable ambient obscurance, pass 3: spiral samples over the z hierarchy, \
                      AlchemyAO or the appendix's falloff, 2x2 quad bilateral, A and z packed \
                      (SAO Eq. 1, 3-10)",
    },
    ShaderEntry {
        name: "sao_blur",
        files: SAO_BLUR_FILES,
        source: SAO_BLUR_WGSL,
        kind: ShaderKind::Compute,
        entry_points: &[
            EntryPoint {
                name: "blur_horizontal",
                stage: Stage::Compute,
            },
            EntryPoint {
                name: "blur_vertical",
                stage: Stage::Compute,
            },
        ],
        description: "scalable ambient obscurance, passes 4 and 5: depth-aware separable \
                      bilateral blur (SAO 2.4)",
    },
    ShaderEntry {
        name: "relief",
        files: RELIEF_FILES,
        source: RELIEF_WGSL,
        kind: ShaderKind::Draw,
        entry_points: &[
            EntryPoint {
                name: "relief_vs",
                stage: Stage::Vertex,
            },
            EntryPoint {
                name: "relief_fs",
                stage: Stage::Fragment,
            },
            EntryPoint {
                name: "relief_layers_fs",
                stage: Stage::Fragment,
            },
        ],
        description: "relief mapping: a quad traced per pixel by linear search, cone step \
                      mapping or relaxed cone stepping with binary search through an exact \
                      bilinear fetch, shaded with the relief normal, self-shadowed, writing the \
                      hit's depth (GPU Gems 3 ch. 18, Listing 18-3); one colour or the direct \
                      and ambient light apart",
    },
    ShaderEntry {
        name: "relief_probe",
        files: RELIEF_PROBE_FILES,
        source: RELIEF_PROBE_WGSL,
        kind: ShaderKind::Compute,
        entry_points: &[
            EntryPoint {
                name: "probe_trace",
                stage: Stage::Compute,
            },
            EntryPoint {
                name: "copy_depth",
                stage: Stage::Compute,
            },
        ],
        description: "probes of the relief tracer: the draw pass's tracer and shadow test on \
                      lists of rays (parity tests), and a depth-texture copy",
    },
    ShaderEntry {
        name: "relief_quad",
        files: RELIEF_QUAD_FILES,
        source: RELIEF_QUAD_WGSL,
        kind: ShaderKind::Draw,
        entry_points: &[
            EntryPoint {
                name: "relief_vs",
                stage: Stage::Vertex,
            },
            EntryPoint {
                name: "relief_fs",
                stage: Stage::Fragment,
            },
            EntryPoint {
                name: "relief_layers_fs",
                stage: Stage::Fragment,
            },
        ],
        description: "relief mapping through a quad-directional cone map: the `relief` draw \
                      pass reading a 4-layer texture array, one layer per quadrant of the ray's \
                      direction, picked once per ray (GPU Gems 3 section 18.1)",
    },
    ShaderEntry {
        name: "relief_quad_probe",
        files: RELIEF_QUAD_PROBE_FILES,
        source: RELIEF_QUAD_PROBE_WGSL,
        kind: ShaderKind::Compute,
        entry_points: &[
            EntryPoint {
                name: "probe_trace",
                stage: Stage::Compute,
            },
            EntryPoint {
                name: "copy_depth",
                stage: Stage::Compute,
            },
        ],
        description: "probes of the quad-directional relief tracer: the `relief_quad` draw \
                      pass's tracer and shadow test on lists of rays (parity tests), and a \
                      depth-texture copy",
    },
    ShaderEntry {
        name: "relief_cone",
        files: RELIEF_CONE_FILES,
        source: RELIEF_CONE_WGSL,
        kind: ShaderKind::Compute,
        entry_points: &[
            EntryPoint {
                name: "cells_pass",
                stage: Stage::Compute,
            },
            EntryPoint {
                name: "reduce_pass",
                stage: Stage::Compute,
            },
            EntryPoint {
                name: "search_pass",
                stage: Stage::Compute,
            },
            EntryPoint {
                name: "texels_pass",
                stage: Stage::Compute,
            },
        ],
        description: "relaxed and conservative cone maps: per-cell bounds, the min-depth \
                      pyramid and the branch-and-bound search per apex cell in double-f32 \
                      arithmetic (GPU Gems 3 ch. 18; ocean_relief::ConeMap::generate)",
    },
    ShaderEntry {
        name: "depth_resolve",
        files: DEPTH_RESOLVE_FILES,
        source: DEPTH_RESOLVE_WGSL,
        kind: ShaderKind::Draw,
        entry_points: &[
            EntryPoint {
                name: "resolve_vs",
                stage: Stage::Vertex,
            },
            EntryPoint {
                name: "nearest_forward_fs",
                stage: Stage::Fragment,
            },
            EntryPoint {
                name: "nearest_reversed_fs",
                stage: Stage::Fragment,
            },
        ],
        description: "the depth of a multisampled (4x) frame for single-sampled readers: each \
                      pixel's nearest sample",
    },
];

/// Shader capabilities the passes may use: none beyond core WGSL. wgpu enables extra
/// capabilities only for optional device features, and this crate requests none that affect
/// shaders, so validating with the empty set proves the sources run on every device the crate
/// accepts (and in browsers).
pub const CAPABILITIES: Capabilities = Capabilities::empty();

/// Every registered shader.
pub fn all() -> &'static [ShaderEntry] {
    &SHADERS
}

/// The shader called `name`, if any.
pub fn get(name: &str) -> Option<&'static ShaderEntry> {
    SHADERS.iter().find(|s| s.name == name)
}

/// Why a shader could not be found, parsed, validated or translated.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ShaderError {
    /// No shader has that name.
    #[error("no shader named {name:?} (available: {available})")]
    UnknownShader {
        /// The requested name.
        name: String,
        /// The registered names, comma-separated.
        available: String,
    },
    /// Unknown language name.
    #[error("unknown shader language {0:?} (expected glsl, glsles, hlsl, msl or spirv)")]
    UnknownLanguage(String),
    /// The WGSL does not parse.
    #[error("shader {name}: WGSL parse error:\n{message}")]
    Parse {
        /// Shader name.
        name: &'static str,
        /// naga's report, with source excerpts.
        message: String,
    },
    /// The WGSL parses but does not validate.
    #[error("shader {name}: validation error:\n{message}")]
    Validation {
        /// Shader name.
        name: &'static str,
        /// naga's report, with source excerpts.
        message: String,
    },
    /// naga could not translate it to the requested language.
    #[error("shader {name}: {language} translation failed: {message}")]
    Translation {
        /// Shader name.
        name: &'static str,
        /// Target language.
        language: Language,
        /// naga's error.
        message: String,
    },
}

/// Target language of [`export`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Language {
    /// Desktop GLSL: 4.30 core for compute passes, 3.30 core for draw passes.
    Glsl,
    /// GLSL ES 3.10.
    GlslEs,
    /// HLSL, Shader Model 5.1.
    Hlsl,
    /// Metal Shading Language 2.0.
    Msl,
    /// SPIR-V 1.0 binary.
    SpirV,
}

impl Language {
    /// Every language, in CLI order.
    pub const ALL: [Language; 5] = [
        Language::Glsl,
        Language::GlslEs,
        Language::Hlsl,
        Language::Msl,
        Language::SpirV,
    ];

    /// The CLI spelling: `glsl`, `glsles`, `hlsl`, `msl`, `spirv`.
    pub fn name(self) -> &'static str {
        match self {
            Language::Glsl => "glsl",
            Language::GlslEs => "glsles",
            Language::Hlsl => "hlsl",
            Language::Msl => "msl",
            Language::SpirV => "spirv",
        }
    }
}

impl fmt::Display for Language {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Language {
    type Err = ShaderError;

    /// Parses the CLI spelling (case-insensitive); `spv`, `metal` and `essl` are accepted too.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Ok(match s.to_ascii_lowercase().as_str() {
            "glsl" => Language::Glsl,
            "glsles" | "essl" => Language::GlslEs,
            "hlsl" => Language::Hlsl,
            "msl" | "metal" => Language::Msl,
            "spirv" | "spv" => Language::SpirV,
            _ => return Err(ShaderError::UnknownLanguage(s.to_owned())),
        })
    }
}

/// What kind of resource a binding is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BindingKind {
    /// A uniform buffer.
    Uniform,
    /// A read-only storage buffer.
    StorageRead,
    /// A read-write storage buffer.
    StorageReadWrite,
    /// A sampled (or depth) texture.
    Texture,
    /// A storage texture; `read`/`write` access as declared.
    StorageTexture {
        /// Readable.
        read: bool,
        /// Writable.
        write: bool,
    },
    /// A sampler (`comparison` for depth comparisons).
    Sampler {
        /// Comparison sampler.
        comparison: bool,
    },
}

impl fmt::Display for BindingKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            BindingKind::Uniform => f.write_str("uniform"),
            BindingKind::StorageRead => f.write_str("storage(read)"),
            BindingKind::StorageReadWrite => f.write_str("storage(read_write)"),
            BindingKind::Texture => f.write_str("texture"),
            BindingKind::StorageTexture { read, write } => {
                let access = match (read, write) {
                    (true, true) => "read_write",
                    (true, false) => "read",
                    _ => "write",
                };
                write!(f, "storage_texture({access})")
            }
            BindingKind::Sampler { comparison: false } => f.write_str("sampler"),
            BindingKind::Sampler { comparison: true } => f.write_str("sampler_comparison"),
        }
    }
}

/// A member of a struct bound as a buffer, with its byte offset (std140/std430 as WGSL lays it
/// out, which every export keeps).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Member {
    /// Member name.
    pub name: String,
    /// Byte offset in the struct.
    pub offset: u32,
    /// WGSL type.
    pub ty: String,
}

/// One resource binding of a shader.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Binding {
    /// WGSL `@group`.
    pub group: u32,
    /// WGSL `@binding`.
    pub binding: u32,
    /// Variable name in the WGSL source.
    pub name: String,
    /// Resource kind.
    pub kind: BindingKind,
    /// WGSL type of the variable, e.g. `array<vec4<f32>>`.
    pub ty: String,
    /// Byte size of the type, or of one element for a runtime-sized array.
    pub size: u32,
    /// The struct's members (or the array element struct's), with offsets; empty otherwise.
    pub members: Vec<Member>,
    /// In a GLSL export: the name of the block or sampler naga wrote for this binding.
    pub glsl_name: Option<String>,
    /// In a GLSL export: the flattened binding number (see the module docs), written as
    /// `layout(binding = n)` in GLSL 4.30 and ES 3.10; `None` for GLSL 3.30 (assign it by
    /// name) and samplers (combined with their texture in GLSL).
    pub glsl_binding: Option<u32>,
}

/// Output code: text, or SPIR-V bytes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Code {
    /// Source text.
    Text(String),
    /// SPIR-V module, little-endian 32-bit words.
    Binary(Vec<u8>),
}

impl Code {
    /// The bytes to write to a file.
    pub fn as_bytes(&self) -> &[u8] {
        match self {
            Code::Text(s) => s.as_bytes(),
            Code::Binary(b) => b,
        }
    }
}

/// One output file of an export.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExportFile {
    /// Suggested file name, e.g. `trochoid.displace.comp.glsl`, `trochoid.hlsl`,
    /// `trochoid.metal`, `trochoid.spv`.
    pub file_name: String,
    /// The entry point this file holds, for languages with one entry point per file (GLSL).
    pub entry_point: Option<String>,
    /// Its stage, for per-entry-point files.
    pub stage: Option<Stage>,
    /// The code.
    pub code: Code,
}

/// A shader translated to one language, with its binding layout.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Export {
    /// Registry name of the shader.
    pub shader: &'static str,
    /// Target language.
    pub language: Language,
    /// Output files.
    pub files: Vec<ExportFile>,
    /// Resource bindings, in (group, binding) order.
    pub bindings: Vec<Binding>,
}

impl Export {
    /// The binding layout as a plain-text table, one binding per line, for a `bindings.txt`
    /// next to the exported files.
    pub fn bindings_table(&self) -> String {
        let mut out = format!("# {} ({}): resource bindings\n", self.shader, self.language);
        out.push_str("# group binding name kind type [glsl name, glsl binding]\n");
        for b in &self.bindings {
            out.push_str(&format!(
                "{} {} {} {} {} (size {})",
                b.group, b.binding, b.name, b.kind, b.ty, b.size
            ));
            if let Some(n) = &b.glsl_name {
                out.push_str(&format!(" glsl_name={n}"));
            }
            if let Some(n) = b.glsl_binding {
                out.push_str(&format!(" glsl_binding={n}"));
            }
            out.push('\n');
            for m in &b.members {
                out.push_str(&format!("    +{} {}: {}\n", m.offset, m.name, m.ty));
            }
        }
        out
    }
}

impl ShaderEntry {
    /// Parses and validates the source with [`ValidationFlags::all`] and [`CAPABILITIES`].
    pub fn module(&self) -> Result<(naga::Module, ModuleInfo), ShaderError> {
        let module = naga::front::wgsl::parse_str(self.source).map_err(|e| ShaderError::Parse {
            name: self.name,
            message: e.emit_to_string(self.source),
        })?;
        let info = Validator::new(ValidationFlags::all(), CAPABILITIES)
            .validate(&module)
            .map_err(|e| ShaderError::Validation {
                name: self.name,
                message: e.emit_to_string(self.source),
            })?;
        Ok((module, info))
    }

    /// The shader's resource bindings, in (group, binding) order (GLSL fields unset).
    pub fn bindings(&self) -> Result<Vec<Binding>, ShaderError> {
        let (module, _) = self.module()?;
        Ok(bindings_of(&module))
    }
}

fn members_of(module: &naga::Module, ty: naga::Handle<naga::Type>) -> Vec<Member> {
    let inner = match module.types[ty].inner {
        naga::TypeInner::Array { base, .. } => &module.types[base].inner,
        ref other => other,
    };
    match inner {
        naga::TypeInner::Struct { members, .. } => members
            .iter()
            .map(|m| Member {
                name: m.name.clone().unwrap_or_default(),
                offset: m.offset,
                ty: module.types.type_to_string(m.ty),
            })
            .collect(),
        _ => Vec::new(),
    }
}

fn bindings_of(module: &naga::Module) -> Vec<Binding> {
    let mut out: Vec<Binding> = module
        .global_variables
        .iter()
        .filter_map(|(_, var)| {
            let rb = var.binding.as_ref()?;
            let inner = &module.types[var.ty].inner;
            let kind = match (var.space, inner) {
                (naga::AddressSpace::Uniform, _) => BindingKind::Uniform,
                (naga::AddressSpace::Storage { access }, _) => {
                    if access.contains(naga::StorageAccess::STORE) {
                        BindingKind::StorageReadWrite
                    } else {
                        BindingKind::StorageRead
                    }
                }
                (_, naga::TypeInner::Sampler { comparison }) => BindingKind::Sampler {
                    comparison: *comparison,
                },
                (
                    _,
                    naga::TypeInner::Image {
                        class: naga::ImageClass::Storage { access, .. },
                        ..
                    },
                ) => BindingKind::StorageTexture {
                    read: access.contains(naga::StorageAccess::LOAD),
                    write: access.contains(naga::StorageAccess::STORE),
                },
                _ => BindingKind::Texture,
            };
            let size = match *inner {
                naga::TypeInner::Array {
                    size: naga::ArraySize::Dynamic,
                    stride,
                    ..
                } => stride,
                _ => inner.size(module.to_ctx()),
            };
            Some(Binding {
                group: rb.group,
                binding: rb.binding,
                name: var.name.clone().unwrap_or_default(),
                kind,
                ty: module.types.type_to_string(var.ty),
                size,
                members: members_of(module, var.ty),
                glsl_name: None,
                glsl_binding: None,
            })
        })
        .collect();
    out.sort_by_key(|b| (b.group, b.binding));
    out
}

/// GL binding namespaces: each is numbered from 0 independently.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum GlNamespace {
    UniformBlock,
    StorageBlock,
    TextureUnit,
    ImageUnit,
}

fn gl_namespace(kind: BindingKind) -> Option<GlNamespace> {
    match kind {
        BindingKind::Uniform => Some(GlNamespace::UniformBlock),
        BindingKind::StorageRead | BindingKind::StorageReadWrite => Some(GlNamespace::StorageBlock),
        BindingKind::Texture => Some(GlNamespace::TextureUnit),
        BindingKind::StorageTexture { .. } => Some(GlNamespace::ImageUnit),
        BindingKind::Sampler { .. } => None,
    }
}

/// The flattened GL binding of every non-sampler binding (see the module docs).
fn gl_binding_numbers(bindings: &[Binding]) -> BTreeMap<(u32, u32), u32> {
    let mut next: BTreeMap<GlNamespace, u32> = BTreeMap::new();
    let mut out = BTreeMap::new();
    for b in bindings {
        if let Some(ns) = gl_namespace(b.kind) {
            let n = next.entry(ns).or_insert(0);
            out.insert((b.group, b.binding), *n);
            *n += 1;
        }
    }
    out
}

/// Translates the shader `name` to `language` and lists its bindings.
pub fn export(name: &str, language: Language) -> Result<Export, ShaderError> {
    let entry = get(name).ok_or_else(|| ShaderError::UnknownShader {
        name: name.to_owned(),
        available: all().iter().map(|s| s.name).collect::<Vec<_>>().join(", "),
    })?;
    entry.export(language)
}

impl ShaderEntry {
    /// Translates this shader to `language` and lists its bindings.
    pub fn export(&self, language: Language) -> Result<Export, ShaderError> {
        let (module, info) = self.module()?;
        let mut bindings = bindings_of(&module);
        let translation = |message: String| ShaderError::Translation {
            name: self.name,
            language,
            message,
        };
        let files = match language {
            Language::Glsl | Language::GlslEs => {
                self.export_glsl(&module, &info, language, &mut bindings)?
            }
            Language::Hlsl => {
                let options = naga::back::hlsl::Options::default();
                let pipeline = naga::back::hlsl::PipelineOptions::default();
                let mut text = String::new();
                naga::back::hlsl::Writer::new(&mut text, &options, &pipeline)
                    .write(&module, &info, None)
                    .map_err(|e| translation(e.to_string()))?;
                vec![ExportFile {
                    file_name: format!("{}.hlsl", self.name),
                    entry_point: None,
                    stage: None,
                    code: Code::Text(text),
                }]
            }
            Language::Msl => {
                let options = naga::back::msl::Options {
                    lang_version: (2, 0),
                    ..Default::default()
                };
                let pipeline = naga::back::msl::PipelineOptions::default();
                let (text, _) = naga::back::msl::write_string(&module, &info, &options, &pipeline)
                    .map_err(|e| translation(e.to_string()))?;
                vec![ExportFile {
                    file_name: format!("{}.metal", self.name),
                    entry_point: None,
                    stage: None,
                    code: Code::Text(text),
                }]
            }
            Language::SpirV => {
                // No DEBUG flag: debug builds would otherwise embed names and source, and the
                // output would differ between debug and release builds.
                let options = naga::back::spv::Options {
                    flags: naga::back::spv::WriterFlags::ADJUST_COORDINATE_SPACE
                        | naga::back::spv::WriterFlags::LABEL_VARYINGS
                        | naga::back::spv::WriterFlags::CLAMP_FRAG_DEPTH,
                    ..Default::default()
                };
                let words = naga::back::spv::write_vec(&module, &info, &options, None)
                    .map_err(|e| translation(e.to_string()))?;
                vec![ExportFile {
                    file_name: format!("{}.spv", self.name),
                    entry_point: None,
                    stage: None,
                    code: Code::Binary(words.iter().flat_map(|w| w.to_le_bytes()).collect()),
                }]
            }
        };
        Ok(Export {
            shader: self.name,
            language,
            files,
            bindings,
        })
    }

    fn export_glsl(
        &self,
        module: &naga::Module,
        info: &ModuleInfo,
        language: Language,
        bindings: &mut [Binding],
    ) -> Result<Vec<ExportFile>, ShaderError> {
        let version = match (language, self.kind) {
            (Language::GlslEs, _) => naga::back::glsl::Version::new_gles(310),
            (_, ShaderKind::Compute) => naga::back::glsl::Version::Desktop(430),
            (_, ShaderKind::Draw) => naga::back::glsl::Version::Desktop(330),
        };
        let explicit = version.supports_explicit_locations();
        let numbers = gl_binding_numbers(bindings);
        let mut binding_map = naga::back::glsl::BindingMap::default();
        for (&(group, binding), &n) in &numbers {
            let n = u8::try_from(n).map_err(|_| ShaderError::Translation {
                name: self.name,
                language,
                message: format!("GL binding number {n} exceeds 255"),
            })?;
            binding_map.insert(naga::ResourceBinding { group, binding }, n);
        }
        let options = naga::back::glsl::Options {
            version,
            // ADJUST_COORDINATE_SPACE flips y and remaps depth for GL's clip space in vertex
            // shaders, as wgpu's GL backend does.
            writer_flags: naga::back::glsl::WriterFlags::ADJUST_COORDINATE_SPACE,
            binding_map,
            zero_initialize_workgroup_memory: true,
        };
        let mut files = Vec::new();
        for ep in self.entry_points {
            let pipeline = naga::back::glsl::PipelineOptions {
                shader_stage: ep.stage.to_naga(),
                entry_point: ep.name.to_owned(),
                multiview: None,
            };
            let mut text = String::new();
            let reflection = naga::back::glsl::Writer::new(
                &mut text,
                module,
                info,
                &options,
                &pipeline,
                naga::proc::BoundsCheckPolicies::default(),
            )
            .and_then(|mut w| w.write())
            .map_err(|e| ShaderError::Translation {
                name: self.name,
                language,
                message: format!("entry point {}: {e}", ep.name),
            })?;
            // Names of the blocks and samplers this entry point uses.
            for (handle, glsl) in &reflection.uniforms {
                let var = &module.global_variables[*handle];
                if let Some(rb) = &var.binding
                    && let Some(b) = bindings
                        .iter_mut()
                        .find(|b| (b.group, b.binding) == (rb.group, rb.binding))
                {
                    b.glsl_name = Some(glsl.clone());
                }
            }
            for (glsl, mapping) in &reflection.texture_mapping {
                let var = &module.global_variables[mapping.texture];
                if let Some(rb) = &var.binding
                    && let Some(b) = bindings
                        .iter_mut()
                        .find(|b| (b.group, b.binding) == (rb.group, rb.binding))
                {
                    b.glsl_name = Some(glsl.clone());
                }
            }
            let es = if language == Language::GlslEs {
                ".es"
            } else {
                ""
            };
            files.push(ExportFile {
                file_name: format!("{}.{}.{}{es}.glsl", self.name, ep.name, ep.stage.suffix()),
                entry_point: Some(ep.name.to_owned()),
                stage: Some(ep.stage),
                code: Code::Text(text),
            });
        }
        for b in bindings.iter_mut() {
            b.glsl_binding = if explicit {
                numbers.get(&(b.group, b.binding)).copied()
            } else {
                None
            };
        }
        Ok(files)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// FNV-1a, 64-bit: a stable hash for snapshotting binary output.
    fn fnv1a(bytes: &[u8]) -> u64 {
        let mut h: u64 = 0xcbf2_9ce4_8422_2325;
        for &b in bytes {
            h ^= u64::from(b);
            h = h.wrapping_mul(0x0000_0100_0000_01b3);
        }
        h
    }

    #[test]
    fn every_shader_validates_with_the_requested_capabilities() {
        for s in all() {
            let (module, _) = s.module().unwrap_or_else(|e| panic!("{e}"));
            // The registry's entry-point table must match the source, stage included.
            let mut declared: Vec<(String, naga::ShaderStage)> = module
                .entry_points
                .iter()
                .map(|e| (e.name.clone(), e.stage))
                .collect();
            let mut listed: Vec<(String, naga::ShaderStage)> = s
                .entry_points
                .iter()
                .map(|e| (e.name.to_owned(), e.stage.to_naga()))
                .collect();
            declared.sort_by(|a, b| a.0.cmp(&b.0));
            listed.sort_by(|a, b| a.0.cmp(&b.0));
            assert_eq!(declared, listed, "{}", s.name);
            let compute = s.entry_points.iter().all(|e| e.stage == Stage::Compute);
            assert_eq!(compute, s.kind == ShaderKind::Compute, "{}", s.name);
        }
    }

    #[test]
    fn registry_lookup() {
        assert!(get("trochoid").is_some());
        assert!(get("layers").is_some());
        assert!(get("no-such-shader").is_none());
        let e = export("no-such-shader", Language::Glsl).unwrap_err();
        assert!(e.to_string().contains("trochoid"), "{e}");
        let names: Vec<&str> = all().iter().map(|s| s.name).collect();
        let mut dedup = names.clone();
        dedup.dedup();
        assert_eq!(names, dedup, "shader names must be unique");
    }

    #[test]
    fn language_names_round_trip() {
        for l in Language::ALL {
            assert_eq!(l.name().parse::<Language>().unwrap(), l);
        }
        assert!("cuda".parse::<Language>().is_err());
    }

    #[test]
    fn invalid_wgsl_is_an_error_not_a_panic() {
        let bad = ShaderEntry {
            name: "bad",
            files: &[],
            source: "fn f() -> f32 { return 1u; }",
            kind: ShaderKind::Compute,
            entry_points: &[],
            description: "",
        };
        assert!(matches!(bad.module(), Err(ShaderError::Validation { .. })));
        let unparsable = ShaderEntry {
            source: "fn (",
            ..bad
        };
        assert!(matches!(
            unparsable.module(),
            Err(ShaderError::Parse { .. })
        ));
    }

    #[test]
    fn trochoid_binding_layout() {
        // The layout TrochoidPass creates its bind group for: one uniform block, two read-only
        // and two read-write storage buffers (4 storage buffers: the downlevel limit).
        let b = get("trochoid").unwrap().bindings().unwrap();
        let summary: Vec<(u32, u32, &str, String, &str, u32)> = b
            .iter()
            .map(|b| {
                (
                    b.group,
                    b.binding,
                    b.name.as_str(),
                    b.kind.to_string(),
                    b.ty.as_str(),
                    b.size,
                )
            })
            .collect();
        assert_eq!(
            summary,
            vec![
                (0, 0, "params", "uniform".into(), "Params", 32),
                (
                    0,
                    1,
                    "coeffs",
                    "storage(read)".into(),
                    "array<WaveCoeffs>",
                    32
                ),
                (
                    0,
                    2,
                    "tables",
                    "storage(read)".into(),
                    "array<vec2<f32>>",
                    8
                ),
                (
                    0,
                    3,
                    "positions",
                    "storage(read_write)".into(),
                    "array<vec4<f32>>",
                    16
                ),
                (
                    0,
                    4,
                    "normals",
                    "storage(read_write)".into(),
                    "array<vec4<f32>>",
                    16
                ),
            ]
        );
        // Params members at the offsets of the Rust TrochoidParams.
        let offsets: Vec<(&str, u32)> = b[0]
            .members
            .iter()
            .map(|m| (m.name.as_str(), m.offset))
            .collect();
        assert_eq!(
            offsets,
            vec![
                ("nx", 0),
                ("nz", 4),
                ("waves", 8),
                ("cols_offset", 12),
                ("groups_x", 16),
                ("_pad", 20),
                ("spacing_x", 24),
                ("spacing_z", 28),
            ]
        );
    }

    #[test]
    fn glsl_bindings_are_flattened_per_namespace() {
        // Uniform blocks and storage blocks are separate GL namespaces, each numbered from 0.
        let e = export("trochoid", Language::Glsl).unwrap();
        let gl: Vec<(&str, Option<u32>)> = e
            .bindings
            .iter()
            .map(|b| (b.name.as_str(), b.glsl_binding))
            .collect();
        assert_eq!(
            gl,
            vec![
                ("params", Some(0)),
                ("coeffs", Some(0)),
                ("tables", Some(1)),
                ("positions", Some(2)),
                ("normals", Some(3)),
            ]
        );
        let Code::Text(text) = &e.files[0].code else {
            panic!("GLSL is text")
        };
        assert!(
            text.starts_with("#version 430 core"),
            "{}",
            &text[..40.min(text.len())]
        );
        for b in &e.bindings {
            let name = b
                .glsl_name
                .as_deref()
                .expect("every buffer has a GLSL block name");
            assert!(text.contains(name), "{name} not in the GLSL");
        }
        let es = export("trochoid", Language::GlslEs).unwrap();
        let Code::Text(text) = &es.files[0].code else {
            panic!("GLSL ES is text")
        };
        assert!(text.starts_with("#version 310 es"));
    }

    /// A draw pass (vertex + fragment) with a uniform block, a texture and a sampler, to check
    /// the GLSL 3.30 path: no `binding =` qualifiers there (3.30 lacks them), so
    /// `glsl_binding` is `None` and the engine binds by `glsl_name`; ES 3.10 does write them.
    const DRAW_TEST: ShaderEntry = ShaderEntry {
        name: "draw_test",
        files: &[],
        source: "
            struct View { view_proj: mat4x4<f32>, tint: vec4<f32> }
            @group(0) @binding(0) var<uniform> view: View;
            @group(0) @binding(1) var albedo: texture_2d<f32>;
            @group(0) @binding(2) var albedo_sampler: sampler;
            struct VsOut { @builtin(position) clip: vec4<f32>, @location(0) uv: vec2<f32> }
            @vertex fn vs(@location(0) p: vec4<f32>) -> VsOut {
                return VsOut(view.view_proj * vec4<f32>(p.xyz, 1.0), p.xz);
            }
            @fragment fn fs(v: VsOut) -> @location(0) vec4<f32> {
                return view.tint * textureSample(albedo, albedo_sampler, v.uv);
            }",
        kind: ShaderKind::Draw,
        entry_points: &[
            EntryPoint {
                name: "vs",
                stage: Stage::Vertex,
            },
            EntryPoint {
                name: "fs",
                stage: Stage::Fragment,
            },
        ],
        description: "test draw pass",
    };

    #[test]
    fn draw_passes_export_glsl_330_without_binding_qualifiers() {
        let e = DRAW_TEST.export(Language::Glsl).unwrap();
        let names: Vec<&str> = e.files.iter().map(|f| f.file_name.as_str()).collect();
        assert_eq!(names, ["draw_test.vs.vert.glsl", "draw_test.fs.frag.glsl"]);
        for f in &e.files {
            let Code::Text(t) = &f.code else {
                panic!("GLSL is text")
            };
            assert!(t.starts_with("#version 330 core"), "{}", f.file_name);
            assert!(
                !t.contains("binding ="),
                "GLSL 3.30 has no binding qualifier"
            );
        }
        let kinds: Vec<String> = e.bindings.iter().map(|b| b.kind.to_string()).collect();
        assert_eq!(kinds, ["uniform", "texture", "sampler"]);
        assert!(e.bindings.iter().all(|b| b.glsl_binding.is_none()));
        // The uniform block and the combined texture+sampler have GLSL names to bind by.
        assert!(e.bindings[0].glsl_name.is_some() && e.bindings[1].glsl_name.is_some());
        assert_eq!(e.bindings[0].size, 80, "mat4x4 (64) + vec4 (16)");

        // ES 3.10 writes explicit bindings: uniform block 0, texture unit 0.
        let es = DRAW_TEST.export(Language::GlslEs).unwrap();
        let gl: Vec<Option<u32>> = es.bindings.iter().map(|b| b.glsl_binding).collect();
        assert_eq!(gl, [Some(0), Some(0), None]);
        let Code::Text(vs) = &es.files[0].code else {
            panic!("GLSL ES is text")
        };
        assert!(vs.starts_with("#version 310 es") && vs.contains("binding = 0"));
        // Every other language translates the draw pass too.
        for l in [Language::Hlsl, Language::Msl, Language::SpirV] {
            DRAW_TEST
                .export(l)
                .unwrap_or_else(|err| panic!("{l}: {err}"));
        }
    }

    #[test]
    fn wgsl_degenerate_normal_threshold_is_f32_min_positive() {
        // The CPU kernel takes the normal as +y where |n|² < f32::MIN_POSITIVE; the WGSL
        // literal must round to exactly that f32, or the two sides disagree next to cusps.
        for name in ["trochoid", "layers"] {
            let (module, _) = get(name).unwrap().module().unwrap();
            let (_, c) = module
                .constants
                .iter()
                .find(|(_, c)| c.name.as_deref() == Some("F32_MIN_POSITIVE"))
                .expect("WGSL constant F32_MIN_POSITIVE");
            match module.global_expressions[c.init] {
                naga::Expression::Literal(naga::Literal::F32(v)) => {
                    assert_eq!(v.to_bits(), f32::MIN_POSITIVE.to_bits(), "{name}: {v:e}");
                }
                ref other => panic!("{name}: F32_MIN_POSITIVE is {other:?}"),
            }
        }
    }

    /// A deterministic, human-readable record of an export: bindings table, then each file
    /// (text in full; SPIR-V as a header summary, word count and FNV-1a hash).
    fn snapshot_text(e: &Export) -> String {
        let mut out = e.bindings_table();
        for f in &e.files {
            out.push_str(&format!("\n===== {} =====\n", f.file_name));
            match &f.code {
                Code::Text(t) => out.push_str(t),
                Code::Binary(b) => {
                    let words: Vec<u32> = b
                        .chunks_exact(4)
                        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
                        .collect();
                    out.push_str(&format!(
                        "magic {:#010x}\nversion {}.{}\nid bound {}\nwords {}\nfnv1a64 {:#018x}\n",
                        words[0],
                        (words[1] >> 16) & 0xff,
                        (words[1] >> 8) & 0xff,
                        words[3],
                        words.len(),
                        fnv1a(b)
                    ));
                }
            }
        }
        out
    }

    #[test]
    fn exports_match_snapshots() {
        for s in all() {
            for l in Language::ALL {
                let e = s.export(l).unwrap_or_else(|err| panic!("{err}"));
                insta::assert_snapshot!(format!("{}_{}", s.name, l.name()), snapshot_text(&e));
            }
        }
    }

    #[test]
    fn spirv_is_a_valid_module_header() {
        let e = export("trochoid", Language::SpirV).unwrap();
        let Code::Binary(b) = &e.files[0].code else {
            panic!("SPIR-V is binary")
        };
        assert_eq!(b.len() % 4, 0);
        // SPIR-V magic number, little-endian, and version 1.0 (0x00010000).
        assert_eq!(&b[..4], &0x0723_0203u32.to_le_bytes());
        assert_eq!(&b[4..8], &0x0001_0000u32.to_le_bytes());
    }
}
