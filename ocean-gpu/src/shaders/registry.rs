//! The registry: every shader's WGSL, assembled from its files, and its entry in [`all`].

use super::*;

/// Declares a shader's WGSL from one list of files (shared snippets first): `$name`, their
/// concatenation, and `$files`, the list itself for the registry, so the two cannot disagree.
macro_rules! wgsl {
    ($(#[$doc:meta])* $name:ident, $files:ident = [$($file:literal),+ $(,)?]) => {
        $(#[$doc])*
        pub const $name: &str = concat!($(include_str!($file)),+);
        const $files: &[&str] = &[$($file),+];
    };
}

wgsl!(
    /// Source of the trochoid displacement pass, after the shared `grid_normal.wgsl` (the unit
    /// normal of the CPU kernel) and `grid_sums.wgsl` (the point and the sums of its wave
    /// terms). The host uploads sines and cosines, which the shader combines by angle addition.
    TROCHOID_WGSL, TROCHOID_FILES = ["grid_normal.wgsl", "grid_sums.wgsl", "trochoid.wgsl"]
);

wgsl!(
    /// Source of the layered (wave-train-box) displacement pass: sums of wave sets modulated by
    /// complex amplitude fields over grid rectangles, plus an additive height field. Like the
    /// trochoid pass it combines host-made sines and cosines by angle addition.
    LAYERS_WGSL, LAYERS_FILES = ["grid_normal.wgsl", "grid_sums.wgsl", "layers.wgsl"]
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
pub const IRRADIANCE_WGSL: &str = include_str!("irradiance.wgsl");

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

pub(super) static SHADERS: [ShaderEntry; 16] = [
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
