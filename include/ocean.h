/*
 * ocean: real-time water rendering. C ABI (C99 or later, and C++).
 *
 * Contents (functions by prefix)
 * - The library: ocean_version, ocean_version_number, ocean_check_version,
 *   ocean_status_message, ocean_last_error_message.
 * - Waves, trochoid (Gerstner) sums: ocean_waves_*.
 * - Wave train boxes (Yrjola & Larsson): ocean_wtb_scene_* on an OceanWtbScene,
 *   ocean_wtb_*_default for its boxes, winds and effects.
 * - Ocean lighting (Bruneton, Neyret & Holzschuch 2010): ocean_spectrum_*, ocean_lighting_*,
 *   ocean_sky_map_*, ocean_sea_color*, ocean_ross_brdf, ocean_schlick,
 *   ocean_effective_fresnel_*, ocean_sun_radiance, ocean_tone_map, ocean_linear_to_srgb,
 *   ocean_pixel_footprint.
 * - Scalable Ambient Obscurance (McGuire, Mara & Luebke 2012), CPU reference: ocean_sao_*.
 * - Relief mapping by relaxed cone stepping (Policarpo & Oliveira): ocean_relief_map_*,
 *   ocean_relief_cones_*, ocean_relief_quad_*, ocean_relief_mips_*, ocean_relief_trace,
 *   ocean_relief_shadow and their helpers.
 * - GPU, declared only where OCEAN_GPU is defined (the full library, libocean; the CPU-only
 *   libocean-cpu lacks them): ocean_gpu_context_*, ocean_renderer_*, ocean_scene_* (the
 *   composed scene of `ocean render` from its TOML description), ocean_sao_gpu_*,
 *   ocean_shader_* (every pass exported to GLSL, HLSL, MSL, SPIR-V), and the uniform blocks
 *   and textures of the library's shaders for your own pipeline: ocean_surface_* (the ocean
 *   surface), ocean_sao_uniforms, ocean_relief_uniforms.
 *
 * Conventions
 * - Version: call ocean_check_version(OCEAN_VERSION) once at start-up; it refuses a library
 *   whose ABI differs from this header's.
 * - Parameter structs (the options a caller tunes: OceanSpectrumParams, OceanSkyParams,
 *   OceanSeaParams, OceanWindDesc, OceanBoxDesc, OceanEffects, OceanSaoParams,
 *   OceanReliefConeParams, OceanReliefMethod, OceanReliefScene, OceanSurfaceDrawParams,
 *   OceanRendererOptions) each have an ocean_*_default(&out) function: start from it and set
 *   what you need. Descriptions of the caller's own data (a wave, a grid, a camera, a ray)
 *   have none. Flags are uint32_t members, 0 or 1 (other values are refused). No struct has
 *   padding the compiler inserts unseen: where alignment would leave a hole, a `reserved`
 *   member fills it, which callers must set to 0 (the _default functions do) and which the
 *   library writes as 0.
 * - Extensions: every parameter struct starts with `OceanNext next` (a `const OceanChain *`),
 *   as webgpu.h's descriptors start with `nextInChain`. A parameter struct never changes its
 *   layout, so a program built against this header keeps working with later versions of the
 *   library, and an ocean_*_default function never writes past the caller's struct. New
 *   parameters come as extension structs, each starting with an OceanChain whose `s_type`
 *   names it, linked from `next` and from each other's `next`. A library refuses an extension
 *   it does not know (OCEAN_STATUS_INVALID_ARGUMENT, naming the member and the `s_type`)
 *   rather than ignore what it asks for. This version defines none: `next` must be NULL, as
 *   the _default functions and zero-initialisation leave it.
 * - Enumerations are enums with underlying type uint32_t (in C before C23, typedefs of
 *   uint32_t), and struct members that hold one have its type, so a C++ compiler refuses a
 *   plain integer there; the library checks every value it reads (others are refused with
 *   OCEAN_STATUS_INVALID_ARGUMENT). Function parameters that take one (edge, range, encoding,
 *   rule, depth_source, language, ocean_status_message's status) are plain uint32_t, because the
 *   library (in Rust) would have undefined behaviour receiving an enum type that holds none of
 *   its enumerators: it takes the integer and checks it instead.
 * - Units: metres, seconds, radians. Time is a double, in seconds, everywhere.
 * - Axes: right-handed, y up; the sea at rest is the plane y = 0, so rest positions and wave
 *   directions are (x, z) pairs on it.
 * - Errors: every fallible function returns an OceanStatus. OCEAN_STATUS_OK (0) is success; on
 *   any other value no output parameter has been written. When several errors apply, the
 *   first in this order is reported: (1) handles, in parameter order (NULL: NULL_POINTER;
 *   another kind, destroyed or never made: INVALID_HANDLE); (2) other pointers, in parameter
 *   order (NULL_POINTER, then MISALIGNED_POINTER); (3) counts (EMPTY, then LENGTH_OVERFLOW,
 *   then LENGTH_MISMATCH, after the values that decide a length where some do, then
 *   INVALID_ARGUMENT for overlapping buffers); (4) values, in parameter and field order, a
 *   struct's `next` first (MISALIGNED_POINTER, then INVALID_ARGUMENT for an extension the
 *   library does not know), then NON_FINITE, then range (INVALID_ARGUMENT, TOO_STEEP); (5) the handle's state (NOT_FOUND,
 *   NOT_EVALUATED, OUTSIDE_GRID) and the work itself (INVALID_ARGUMENT when a result would not
 *   be finite, CANCELLED, GPU_FAILURE).
 * - The last-error message: ocean_last_error_message() is the calling thread's message of its
 *   most recent failure, naming the function, the argument and the value ("" after a success).
 *   Every status-returning function sets it on failure and clears it on success. The destroy
 *   functions return nothing: they leave it alone, but for misuse (a handle of another kind,
 *   destroyed or never made), which they refuse and describe there. ocean_version,
 *   ocean_status_message and ocean_last_error_message never change it. The text stays valid
 *   until the thread's next call of a status-returning function. ocean_status_message()
 *   gives a fixed text per code.
 * - Output sizes: every output array has a length the caller knows before the call, in one
 *   of two ways, each function saying which: (1) one result per input (`xz` and `n` in, `n`
 *   results out, no length of their own); (2) an exact length, from the call's own arguments,
 *   a constant (OCEAN_SURFACE_UNIFORMS_SIZE, OCEAN_RELIEF_UNIFORMS_SIZE,
 *   OCEAN_SAO_UNIFORMS_SIZE, OCEAN_FRESNEL_TABLE_SIZE squared) or a size query named in the function's
 *   documentation (ocean_spectrum_wave_count, ocean_sky_map_level_info, ocean_relief_map_size,
 *   ocean_relief_cones_size, ocean_relief_quad_cones_size, ocean_relief_mips_level_size),
 *   passed with the buffer as its length in elements (bytes for the uniform blocks). Any other
 *   length, larger or smaller, is OCEAN_STATUS_LENGTH_MISMATCH and nothing is written: a buffer
 *   sized for another texture or another version of a block is refused, never half-filled.
 *   Text and code the library owns (messages, the adapter's description, exported shaders) are
 *   returned as pointers, valid for as long as each function says.
 * - Every pointer is checked for NULL and alignment, every count for 0 and for overflow, every
 *   float for NaN and infinity; no call can crash the process on such input. What cannot be
 *   checked (that a non-NULL pointer really points to enough memory) is stated in each
 *   function's Safety section; a struct's `next` must, like the struct, be NULL or point to
 *   readable memory (an OceanChain).
 * - Handles are opaque ids, not addresses: the library never reads through one. Each is
 *   registered with its kind while alive, and ids are never reused, so a handle of the wrong
 *   kind, a destroyed handle, a second destroy or a value the library never returned is
 *   refused with OCEAN_STATUS_INVALID_HANDLE (SQLite's SQLITE_MISUSE is the model). Each
 *   _create has a _destroy; destroying NULL does nothing.
 * - Threads: every function may be called from any thread, and every handle may be used by
 *   many threads at once (the mutable ones lock inside). A handle destroyed while another
 *   thread is inside a call on it stays alive until that call returns; calls made after the
 *   destroy are refused.
 */

#ifndef OCEAN_H
#define OCEAN_H

/* Generated by cbindgen from the ocean-ffi crate. Do not edit: change the Rust source and run
   OCEAN_BLESS=1 cargo test -p ocean-ffi --test header */

#include <stdint.h>
#include <stddef.h>

/**
 * Half-width E of the square of the stereographic plane a sky map covers: texel (i, j) of a
 * level of size S shows u = (2 t - 1) E, t = ((i + 0.5)/S, (j + 0.5)/S). Equal to
 * `ocean_brdf::sky_map::SKY_MAP_EXTENT`.
 */
#define OCEAN_SKY_MAP_EXTENT 1.1

/**
 * Smallest level-0 size of a sky map (a power of two).
 */
#define OCEAN_SKY_MAP_MIN_SIZE 4

/**
 * Largest level-0 size of a sky map (a power of two).
 */
#define OCEAN_SKY_MAP_MAX_SIZE 4096

/**
 * Reflectance of water at normal incidence, R of Eq. 14 (a refractive index of 1.33).
 */
#define OCEAN_WATER_R 0.02

/**
 * The default exposure of `ocean_tone_map`: maps the default sky's zenith (radiance about
 * 0.05) to about 0.33 and the default sea's refracted light (about 0.01) to about 0.08.
 */
#define OCEAN_DEFAULT_EXPOSURE 8.0

/**
 * N_min of the paper's filter (section 7.1): a wave starts to appear in the normals (or the
 * geometry) once its wavelength spans this many pixels (or grid cells).
 */
#define OCEAN_FILTER_N_MIN 1.0

/**
 * N_max of the paper's filter: a wave is fully present from this many pixels per wavelength.
 */
#define OCEAN_FILTER_N_MAX 2.5

#if defined(OCEAN_GPU)
/**
 * Size in bytes of the exported `ocean` shader's uniform block `Frame` (binding 0, std140);
 * `ocean_surface_uniforms` writes it.
 */
#define OCEAN_SURFACE_UNIFORMS_SIZE 352
#endif

#if defined(OCEAN_GPU)
/**
 * Rows of the wave texture (binding 1 of the `ocean` shader): `ocean_surface_wave_texels`.
 */
#define OCEAN_WAVE_TEXTURE_ROWS 3
#endif

#if defined(OCEAN_GPU)
/**
 * Side of the effective Fresnel table texture (binding 6 of the `ocean` shader), texels:
 * `ocean_surface_fresnel_texels`.
 */
#define OCEAN_FRESNEL_TABLE_SIZE 33
#endif

/**
 * The smallest side of a height map, texels (a bilinear cell needs two texel centres).
 */
#define OCEAN_RELIEF_MIN_SIDE 2

/**
 * The largest side of a height map, texels (16.7 M texels; a generation at this size needs
 * about 77 bytes a texel, 1.29 GB).
 */
#define OCEAN_RELIEF_MAX_SIDE 4096

/**
 * The largest `OceanReliefConeParams::max_ratio`, texture widths per unit depth.
 */
#define OCEAN_RELIEF_MAX_RATIO_LIMIT 64.0

/**
 * The most bands a generation with a progress callback is split into: the callback is called
 * at most `OCEAN_RELIEF_PROGRESS_BANDS + 1` times.
 */
#define OCEAN_RELIEF_PROGRESS_BANDS 64

#if defined(OCEAN_GPU)
/**
 * Size in bytes of the exported `relief` shader's uniform block `Relief` (binding 0, std140);
 * `ocean_relief_uniforms` writes it.
 */
#define OCEAN_RELIEF_UNIFORMS_SIZE 448
#endif

/**
 * Array layers of a quad-directional cone map: one per closed quadrant of the ray's horizontal
 * direction, layer k = x_neg + 2 y_neg (`OCEAN_RELIEF_QUAD_X_NEG`, `_Y_NEG`).
 */
#define OCEAN_RELIEF_QUAD_LAYERS 4

/**
 * Layer bit of the quadrant of rays with dir_x < 0 (dir_x = 0 uses the other side).
 */
#define OCEAN_RELIEF_QUAD_X_NEG 1

/**
 * Layer bit of the quadrant of rays with dir_y < 0 (dir_y = 0 uses the other side).
 */
#define OCEAN_RELIEF_QUAD_Y_NEG 2

/**
 * The largest step count of each phase (`steps`, `binary`).
 */
#define OCEAN_RELIEF_MAX_STEPS 4096

/**
 * The camera-space z that `ocean_sao_view_z` stores for background pixels (depth at the far
 * end of the range): -1e9 m, a finite stand-in for infinity.
 */
#define OCEAN_SAO_SKY_Z -1.0e9

/**
 * The largest input width or height accepted, in pixels.
 */
#define OCEAN_SAO_MAX_SIDE 16384

#if defined(OCEAN_GPU)
/**
 * Size in bytes of the uniform block `Params` that every `sao_*` shader reads at binding 0
 * (std140); `ocean_sao_uniforms` writes it.
 */
#define OCEAN_SAO_UNIFORMS_SIZE 304
#endif

#if defined(OCEAN_GPU)
/**
 * `OceanShaderBinding::glsl_binding` when the binding has no GLSL binding number: a sampler
 * (combined with its texture in GLSL), a GLSL 3.30 export (assign the number by name), or a
 * non-GLSL export.
 */
#define OCEAN_NO_GLSL_BINDING UINT32_MAX
#endif

/**
 * Major version of the library this header belongs to (the `ocean-ffi` crate version).
 */
#define OCEAN_VERSION_MAJOR 0

/**
 * Minor version of the library this header belongs to.
 */
#define OCEAN_VERSION_MINOR 1

/**
 * Patch version of the library this header belongs to.
 */
#define OCEAN_VERSION_PATCH 0

/**
 * The header's version as one number, (MAJOR << 16) | (MINOR << 8) | PATCH, for
 * `ocean_check_version(OCEAN_VERSION)` and for comparisons in the preprocessor.
 */
#define OCEAN_VERSION (((OCEAN_VERSION_MAJOR << 16) | (OCEAN_VERSION_MINOR << 8)) | OCEAN_VERSION_PATCH)

/**
 * Result of every fallible `ocean_*` function.
 *
 * `OCEAN_STATUS_OK` (0) is success; any other value is a failure, after which no output
 * parameter has been written and `ocean_last_error_message()` describes what went wrong.
 * The numeric values are stable: new codes are only ever appended.
 */
enum OceanStatus
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  /**
   * Success.
   */
  OCEAN_STATUS_OK = 0,
  /**
   * A required pointer argument was NULL.
   */
  OCEAN_STATUS_NULL_POINTER = 1,
  /**
   * A pointer argument was not aligned for its type.
   */
  OCEAN_STATUS_MISALIGNED_POINTER = 2,
  /**
   * An argument is out of its documented range (zero direction, depth <= 0, wavelength <= 0,
   * negative amplitude, grid spacing <= 0, overlapping buffers, ...).
   */
  OCEAN_STATUS_INVALID_ARGUMENT = 3,
  /**
   * A floating-point argument (time, a wave parameter, a position) was NaN or infinite where
   * a finite value is required.
   */
  OCEAN_STATUS_NON_FINITE = 4,
  /**
   * A count was zero (no waves, no points, an empty grid).
   */
  OCEAN_STATUS_EMPTY = 5,
  /**
   * A count is so large that its size in bytes would exceed `PTRDIFF_MAX` (`isize::MAX`), or
   * a grid's point count overflows `size_t`.
   */
  OCEAN_STATUS_LENGTH_OVERFLOW = 6,
  /**
   * A wave's steepness k*A exceeds 1, where the trochoid would loop over itself.
   */
  OCEAN_STATUS_TOO_STEEP = 7,
  /**
   * The library panicked (a bug in ocean); the panic was caught at the boundary. Output
   * buffers of an evaluation may then hold partial results.
   */
  OCEAN_STATUS_PANIC = 8,
  /**
   * A handle's member named by the caller does not exist (a wave train box id that was
   * removed, never issued, or belongs to another scene).
   */
  OCEAN_STATUS_NOT_FOUND = 9,
  /**
   * A wave train box cannot touch the water grid: its rectangle at full fetch lies wholly
   * outside the grid's rectangle, so it could never move a single point.
   */
  OCEAN_STATUS_OUTSIDE_GRID = 10,
  /**
   * No usable GPU adapter: none was found for the backends `WGPU_BACKEND` selects (all when
   * unset), or the one found lacks compute shaders or WebGPU's downlevel limits, or refused
   * to create a device. The message says what to install (Mesa's lavapipe, or llvmpipe
   * through `WGPU_BACKEND=gl`).
   */
  OCEAN_STATUS_NO_ADAPTER = 11,
  /**
   * The GPU backend failed: the device reported a validation, out-of-memory or device-lost
   * error, reading an image back failed, or naga could not translate a shader. The message
   * carries the backend's text.
   */
  OCEAN_STATUS_GPU_FAILURE = 12,
  /**
   * A buffer's length (`len`, `n`, `*_len`) is not the exact length the call needs: the
   * function's documentation says how to know it beforehand (from the call's own arguments,
   * a constant such as `OCEAN_SAO_UNIFORMS_SIZE`, or a named size query). Nothing was read
   * or written through the buffer.
   */
  OCEAN_STATUS_LENGTH_MISMATCH = 13,
  /**
   * The caller's progress callback asked to stop (returned nonzero); nothing was written.
   */
  OCEAN_STATUS_CANCELLED = 14,
  /**
   * A call answers for what the last evaluation drew, and there is none: the scene was
   * never evaluated, or changed since (a box, the terrain, the effects, the budget or the
   * train filter). Evaluate it again first.
   */
  OCEAN_STATUS_NOT_EVALUATED = 15,
  /**
   * A handle argument is not a live handle of its kind: it is of another kind (an
   * `OceanSpectrum *` passed as an `OceanLighting *`), was destroyed, or is a value no
   * function of this library returned (zeroed or freed memory). Nothing was read through
   * it. A destroy function given such a handle frees nothing and sets this message.
   */
  OCEAN_STATUS_INVALID_HANDLE = 16,
  /**
   * `ocean_check_version`: the program was compiled against a header whose ABI this library
   * does not provide (another major version, another minor version before 1.0, or a newer
   * header than the library).
   */
  OCEAN_STATUS_VERSION_MISMATCH = 17,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanStatus OceanStatus;
#else
typedef uint32_t OceanStatus;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

/**
 * Depth convention of a projection matrix: the range of NDC depth (clip z / clip w) and which
 * end is near.
 */
enum OceanDepthConvention
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  /**
   * Depth in [0, 1], near at 0: wgpu, Vulkan, D3D, Metal (GLM with
   * GLM_FORCE_DEPTH_ZERO_TO_ONE).
   */
  OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE = 0,
  /**
   * Depth in [0, 1], near at 1 (reversed Z).
   */
  OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE_REVERSED = 1,
  /**
   * Depth in [-1, 1], near at -1: OpenGL and GLM's default.
   */
  OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE = 2,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanDepthConvention OceanDepthConvention;
#else
typedef uint32_t OceanDepthConvention;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

/**
 * `OceanReliefConeParams::kind`: which cones are made.
 */
enum OceanReliefConeKind
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  /**
   * Relaxed cones (section 18.4): a ray may enter the relief inside a cone but never leave
   * it. For `OCEAN_RELIEF_TRACER_RELAXED`.
   */
  OCEAN_RELIEF_CONE_KIND_RELAXED = 0,
  /**
   * Conservative cones (Dummer 2006): the cone holds no solid. For
   * `OCEAN_RELIEF_TRACER_CONE_STEP`.
   */
  OCEAN_RELIEF_CONE_KIND_CONSERVATIVE = 1,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanReliefConeKind OceanReliefConeKind;
#else
typedef uint32_t OceanReliefConeKind;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

/**
 * `OceanReliefMethod::method`: the tracer.
 */
enum OceanReliefTracer
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  /**
   * Linear search (Policarpo et al. 2005): `steps` equal depth steps, then `binary`
   * bisections of the step that first went inside. Reads only the depth.
   */
  OCEAN_RELIEF_TRACER_LINEAR = 0,
  /**
   * Cone step mapping (Dummer 2006): `steps` conservative cone steps, no refinement
   * (`binary` is not read). Needs conservative cones.
   */
  OCEAN_RELIEF_TRACER_CONE_STEP = 1,
  /**
   * Relaxed cone stepping (Listing 18-3): `steps` relaxed cone steps, then `binary`
   * bisections as `search` says. Needs relaxed cones.
   */
  OCEAN_RELIEF_TRACER_RELAXED = 2,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanReliefTracer OceanReliefTracer;
#else
typedef uint32_t OceanReliefTracer;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

/**
 * `OceanReliefMethod::search`: how relaxed cone stepping refines its hit.
 */
enum OceanReliefSearch
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  /**
   * Bisect the last cone step (from the last point above the surface to the stop point)
   * `binary` times (default).
   */
  OCEAN_RELIEF_SEARCH_LAST_STEP = 0,
  /**
   * Listing 18-3's search, `binary` probes starting halfway from the entry point to the stop
   * point (kept for comparison: less accurate).
   */
  OCEAN_RELIEF_SEARCH_BOOK = 1,
  /**
   * One budget of `steps + binary` fetches: cone steps while the ray is above the surface,
   * then bisections of the last step with every fetch left.
   */
  OCEAN_RELIEF_SEARCH_SHARED = 2,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanReliefSearch OceanReliefSearch;
#else
typedef uint32_t OceanReliefSearch;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

/**
 * `OceanSaoParams::mip_filter`: how a MIP level of z is made from the one below.
 */
enum OceanSaoMipFilter
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  /**
   * Rotated grid subsampling (Table 1), the paper's choice: every MIP texel is one of its
   * children, a true scene value.
   */
  OCEAN_SAO_MIP_FILTER_ROTATED_GRID = 0,
  /**
   * The arithmetic mean of the 2x2 children.
   */
  OCEAN_SAO_MIP_FILTER_ARITHMETIC_MEAN = 1,
  /**
   * The harmonic mean of the 2x2 children (Table 1 misprints it as a sixteenth of that;
   * ocean-sao implements the mean).
   */
  OCEAN_SAO_MIP_FILTER_HARMONIC_MEAN = 2,
  /**
   * The minimum z of the children (the farthest).
   */
  OCEAN_SAO_MIP_FILTER_MIN = 3,
  /**
   * The maximum z of the children (the nearest).
   */
  OCEAN_SAO_MIP_FILTER_MAX = 4,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanSaoMipFilter OceanSaoMipFilter;
#else
typedef uint32_t OceanSaoMipFilter;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

/**
 * `OceanSaoParams::estimator`: the obscurance estimator.
 */
enum OceanSaoEstimator
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  /**
   * The updated falloff of the paper's appendix,
   * A = max(0, 1 - (5 intensity / (r^6 n)) sum max(r^2 - v.v, 0)^3 max((v.n - beta)/(v.v + eps), 0)).
   */
  OCEAN_SAO_ESTIMATOR_FALLOFF = 0,
  /**
   * AlchemyAO's estimator, the paper's Eq. 1,
   * A = max(0, 1 - (2 sigma / n) sum max(0, v.n + z_C beta)/(v.v + eps))^k.
   */
  OCEAN_SAO_ESTIMATOR_ALCHEMY = 1,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanSaoEstimator OceanSaoEstimator;
#else
typedef uint32_t OceanSaoEstimator;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

/**
 * `OceanSaoParams::normals`: how each pixel's normal is reconstructed from depth.
 */
enum OceanSaoNormals
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  /**
   * The paper's Eq. 4, differences within each pixel's 2x2 quad (a silhouette pixel whose
   * quad partner is on the background gets a normal across the edge).
   */
  OCEAN_SAO_NORMALS_QUAD = 0,
  /**
   * The default: along each axis, the difference to whichever adjacent pixel is nearer in
   * depth, so silhouette pixels keep their own surface's normal.
   */
  OCEAN_SAO_NORMALS_NEAREST = 1,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanSaoNormals OceanSaoNormals;
#else
typedef uint32_t OceanSaoNormals;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

/**
 * `OceanSaoBlurParams::weight`: what a blur tap's depth key is compared with.
 */
enum OceanSaoBlurWeight
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  /**
   * The paper's: the centre's key (taps on surfaces sloped to the view are rejected and the
   * sampling pattern stays visible there).
   */
  OCEAN_SAO_BLUR_WEIGHT_DEPTH = 0,
  /**
   * The default: the key the plane through the centre pixel predicts there, its slope from
   * the adjacent pixel nearer in depth.
   */
  OCEAN_SAO_BLUR_WEIGHT_PLANE = 1,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanSaoBlurWeight OceanSaoBlurWeight;
#else
typedef uint32_t OceanSaoBlurWeight;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

#if defined(OCEAN_GPU)
/**
 * The stage of an exported file.
 */
enum OceanShaderStage
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
#if defined(OCEAN_GPU)
  /**
   * The file holds every entry point of the pass (HLSL, MSL, SPIR-V).
   */
  OCEAN_SHADER_STAGE_MODULE = 0,
#endif
#if defined(OCEAN_GPU)
  /**
   * A vertex shader (GLSL, GLSL ES).
   */
  OCEAN_SHADER_STAGE_VERTEX = 1,
#endif
#if defined(OCEAN_GPU)
  /**
   * A fragment shader (GLSL, GLSL ES).
   */
  OCEAN_SHADER_STAGE_FRAGMENT = 2,
#endif
#if defined(OCEAN_GPU)
  /**
   * A compute shader (GLSL, GLSL ES).
   */
  OCEAN_SHADER_STAGE_COMPUTE = 3,
#endif
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanShaderStage OceanShaderStage;
#else
typedef uint32_t OceanShaderStage;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus
#endif

#if defined(OCEAN_GPU)
/**
 * What kind of resource a binding is.
 */
enum OceanBindingKind
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
#if defined(OCEAN_GPU)
  /**
   * A uniform buffer (a GLSL uniform block).
   */
  OCEAN_BINDING_KIND_UNIFORM = 0,
#endif
#if defined(OCEAN_GPU)
  /**
   * A read-only storage buffer (a GLSL shader storage block).
   */
  OCEAN_BINDING_KIND_STORAGE_READ = 1,
#endif
#if defined(OCEAN_GPU)
  /**
   * A read-write storage buffer.
   */
  OCEAN_BINDING_KIND_STORAGE_READ_WRITE = 2,
#endif
#if defined(OCEAN_GPU)
  /**
   * A sampled texture (in GLSL a sampler combined with the binding's sampler).
   */
  OCEAN_BINDING_KIND_TEXTURE = 3,
#endif
#if defined(OCEAN_GPU)
  /**
   * A read-only storage texture (a GLSL image).
   */
  OCEAN_BINDING_KIND_STORAGE_TEXTURE_READ = 4,
#endif
#if defined(OCEAN_GPU)
  /**
   * A write-only storage texture.
   */
  OCEAN_BINDING_KIND_STORAGE_TEXTURE_WRITE = 5,
#endif
#if defined(OCEAN_GPU)
  /**
   * A read-write storage texture.
   */
  OCEAN_BINDING_KIND_STORAGE_TEXTURE_READ_WRITE = 6,
#endif
#if defined(OCEAN_GPU)
  /**
   * A filtering or non-filtering sampler (folded into the textures it samples in GLSL).
   */
  OCEAN_BINDING_KIND_SAMPLER = 7,
#endif
#if defined(OCEAN_GPU)
  /**
   * A comparison sampler.
   */
  OCEAN_BINDING_KIND_SAMPLER_COMPARISON = 8,
#endif
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanBindingKind OceanBindingKind;
#else
typedef uint32_t OceanBindingKind;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus
#endif

/**
 * Depth refraction (paper section 2.1), for `OceanEffects::refraction`.
 */
enum OceanRefraction
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  /**
   * No depth-dependent phase.
   */
  OCEAN_REFRACTION_OFF = 0,
  /**
   * The paper's default: a depth-dependent phase lag accumulated along each wave ray, so
   * fronts bend towards shallow water while the frequency never changes (Fig. 6).
   */
  OCEAN_REFRACTION_PHASE_SHIFT = 1,
  /**
   * Each point runs at its depth's frequency from the dispersion relation (Eq. 4): waves
   * slow down and queue up towards land as time passes (Fig. 7). Offered for comparison.
   */
  OCEAN_REFRACTION_DISPERSION = 2,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanRefraction OceanRefraction;
#else
typedef uint32_t OceanRefraction;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

#if defined(OCEAN_GPU)
/**
 * Target language of `ocean_shader_export`.
 */
enum OceanShaderLanguage
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
#if defined(OCEAN_GPU)
  /**
   * Desktop GLSL, one file per entry point: `#version 330 core` for draw passes (vertex and
   * fragment), `#version 430 core` for compute passes. Clip space is OpenGL's (y flipped and
   * depth remapped to [-1, 1] in the vertex stage, as wgpu's GL backend does).
   */
  OCEAN_SHADER_LANGUAGE_GLSL = 0,
#endif
#if defined(OCEAN_GPU)
  /**
   * GLSL ES 3.10 (`#version 310 es`), one file per entry point.
   */
  OCEAN_SHADER_LANGUAGE_GLSL_ES = 1,
#endif
#if defined(OCEAN_GPU)
  /**
   * HLSL, Shader Model 5.1, one file with every entry point.
   */
  OCEAN_SHADER_LANGUAGE_HLSL = 2,
#endif
#if defined(OCEAN_GPU)
  /**
   * Metal Shading Language 2.0, one file with every entry point.
   */
  OCEAN_SHADER_LANGUAGE_MSL = 3,
#endif
#if defined(OCEAN_GPU)
  /**
   * SPIR-V 1.0, one binary module with every entry point (little-endian 32-bit words).
   */
  OCEAN_SHADER_LANGUAGE_SPIRV = 4,
#endif
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanShaderLanguage OceanShaderLanguage;
#else
typedef uint32_t OceanShaderLanguage;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus
#endif

/**
 * What a depth buffer holds (`ocean_sao_create`'s `depth_source`, a `uint32_t` parameter).
 */
enum OceanSaoDepth
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  /**
   * Window depth, the value a depth texture stores (`glDepthRange(0, 1)`), always in
   * [0, 1]: `(ndc + 1)/2` under `OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE`, NDC depth itself
   * under the [0, 1] conventions. This is what `glReadPixels(..., GL_DEPTH_COMPONENT,
   * GL_FLOAT, ...)` and a sampled depth texture give.
   */
  OCEAN_SAO_DEPTH_WINDOW = 0,
  /**
   * NDC depth (clip z / clip w), in the convention's range: [-1, 1] under
   * `OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE`, [0, 1] otherwise (where it equals window depth).
   */
  OCEAN_SAO_DEPTH_NDC = 1,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanSaoDepth OceanSaoDepth;
#else
typedef uint32_t OceanSaoDepth;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

/**
 * How texel indices outside the map are read (the `edge` parameter, a `uint32_t`).
 */
enum OceanReliefEdge
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  /**
   * The texture tiles (sampler addressing *repeat*).
   */
  OCEAN_RELIEF_EDGE_WRAP = 0,
  /**
   * Texel indices clamp to the border (sampler addressing *clamp-to-edge*).
   */
  OCEAN_RELIEF_EDGE_CLAMP = 1,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanReliefEdge OceanReliefEdge;
#else
typedef uint32_t OceanReliefEdge;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

#if defined(OCEAN_GPU)
/**
 * The camera a scene's frames are seen from (`OceanSceneOptions::camera`, a `uint32_t`).
 */
enum OceanSceneCamera
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
#if defined(OCEAN_GPU)
  /**
   * The description's `[camera]` section.
   */
  OCEAN_SCENE_CAMERA_DESCRIPTION = 0,
#endif
#if defined(OCEAN_GPU)
  /**
   * 6 m above the water, looking 8 degrees down.
   */
  OCEAN_SCENE_CAMERA_SHORE = 1,
#endif
#if defined(OCEAN_GPU)
  /**
   * 4 m above the water, looking at the horizon.
   */
  OCEAN_SCENE_CAMERA_HORIZON = 2,
#endif
#if defined(OCEAN_GPU)
  /**
   * 120 m up, looking 30 degrees down.
   */
  OCEAN_SCENE_CAMERA_HIGH = 3,
#endif
#if defined(OCEAN_GPU)
  /**
   * 10 m up, circling the point 40 m ahead once a minute of scene time, looking at it.
   */
  OCEAN_SCENE_CAMERA_ORBIT = 4,
#endif
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanSceneCamera OceanSceneCamera;
#else
typedef uint32_t OceanSceneCamera;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus
#endif

/**
 * What `ocean_relief_map_create_f32` does with heights outside [0, 1] (its `range` parameter,
 * a `uint32_t`).
 */
enum OceanReliefRange
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  /**
   * A height outside [0, 1] is refused (`OCEAN_STATUS_INVALID_ARGUMENT`, the message names
   * the first such texel).
   */
  OCEAN_RELIEF_RANGE_REFUSE = 0,
  /**
   * The smallest height becomes 0 and the largest 1 (affinely; a constant map becomes a flat
   * map at height 1, the polygon surface).
   */
  OCEAN_RELIEF_RANGE_NORMALIZE = 1,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanReliefRange OceanReliefRange;
#else
typedef uint32_t OceanReliefRange;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

/**
 * How cone values are stored (the `encoding` parameter, a `uint32_t`).
 */
enum OceanReliefEncoding
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  /**
   * 8-bit unorm (`uint8_t`), clamped to 1.0: code k = floor(255 min(r, 1)), read back as
   * k / 255 (a GPU's `R8Unorm` conversion).
   */
  OCEAN_RELIEF_ENCODING_UNORM8 = 0,
  /**
   * 8-bit unorm of the square root (`uint8_t`), clamped to 1.0: read back as (k / 255)^2.
   */
  OCEAN_RELIEF_ENCODING_UNORM8_SQRT = 1,
  /**
   * IEEE binary16 bit patterns (`uint16_t`), unclamped (up to 65504), rounded toward zero.
   */
  OCEAN_RELIEF_ENCODING_F16 = 2,
  /**
   * `float`, the generator's values as they are.
   */
  OCEAN_RELIEF_ENCODING_F32 = 3,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanReliefEncoding OceanReliefEncoding;
#else
typedef uint32_t OceanReliefEncoding;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

/**
 * How `ocean_relief_mips_create` makes a coarse texel (its `rule` parameter, a `uint32_t`).
 */
enum OceanReliefMip
#if defined(__cplusplus) || __STDC_VERSION__ >= 202311L
  : uint32_t
#endif // defined(__cplusplus) || __STDC_VERSION__ >= 202311L
 {
  /**
   * The minimum of a 4x4 window of the finer level (its 2x2 group and a one-texel ring):
   * valid under bilinear sampling.
   */
  OCEAN_RELIEF_MIP_WINDOW = 0,
  /**
   * The book's 2x2 group minimum, valid under nearest sampling only.
   */
  OCEAN_RELIEF_MIP_GROUP = 1,
};
#ifndef __cplusplus
#if __STDC_VERSION__ >= 202311L
typedef enum OceanReliefMip OceanReliefMip;
#else
typedef uint32_t OceanReliefMip;
#endif // __STDC_VERSION__ >= 202311L
#endif // __cplusplus

#if defined(OCEAN_GPU)
/**
 * A headless GPU device and queue that the library created (opaque). Create with
 * `ocean_gpu_context_create`, free with `ocean_gpu_context_destroy`. A
 * `const OceanGpuContext *` may be used by any number of threads at once.
 */
typedef struct OceanGpuContext OceanGpuContext;
#endif

/**
 * The Sun, the sky and the sea, validated, with their derived radiances (opaque). Create with
 * `ocean_lighting_create`, free with `ocean_lighting_destroy`. Immutable: a
 * `const OceanLighting *` may be used by any number of threads at once.
 */
typedef struct OceanLighting OceanLighting;

/**
 * A cone map together with the height map it was made for: what the CPU tracers read
 * (opaque). Create with `ocean_relief_cones_create` (or `ocean_relief_cones_quantize`), free
 * with `ocean_relief_cones_destroy`. Immutable and shareable between threads.
 */
typedef struct OceanReliefCones OceanReliefCones;

/**
 * A square height map with its edge mode (opaque). Create with one of
 * `ocean_relief_map_create_f32` / `_u8` / `_u16`, free with `ocean_relief_map_destroy`.
 * Immutable: a `const OceanReliefMap *` may be used by any number of threads at once.
 */
typedef struct OceanReliefMap OceanReliefMap;

/**
 * A mip chain of a cone map, level 0 (the cone map) down to 1x1 (opaque). Create with
 * `ocean_relief_mips_create`, free with `ocean_relief_mips_destroy`. Immutable and shareable.
 */
typedef struct OceanReliefMips OceanReliefMips;

/**
 * A quad-directional cone map together with the height map it was made for: what the CPU
 * quadrant tracer reads (opaque). Create with `ocean_relief_quad_cones_create`, free with
 * `ocean_relief_quad_cones_destroy`. Immutable and shareable between threads.
 */
typedef struct OceanReliefQuadCones OceanReliefQuadCones;

#if defined(OCEAN_GPU)
/**
 * The GPU ocean renderer (opaque): a projected screen-space grid displaced by the filtered
 * trochoids of a spectrum (Eq. 2), per-pixel filtered normals and slope variances (Eq. 3, 4)
 * lit by the Sun, the sky and the sea (Algorithm 5.1), tone-mapped, over a sky background.
 *
 * Create with `ocean_renderer_create` on a context, give it a spectrum
 * (`ocean_renderer_set_spectrum`) and a lighting (`ocean_renderer_set_lighting`), then render
 * frames with `ocean_renderer_render_rgba8`. Free with `ocean_renderer_destroy`. It works
 * only with the context it was created on. Every call locks the renderer, so any thread may
 * use it, but calls on one renderer run one at a time.
 */
typedef struct OceanRenderer OceanRenderer;
#endif

/**
 * A validated SAO set-up (opaque): image sizes, guard band, camera and parameters. Create with
 * `ocean_sao_create`, free with `ocean_sao_destroy`. Immutable: a `const OceanSao *` may run
 * on any number of threads at once.
 */
typedef struct OceanSao OceanSao;

#if defined(OCEAN_GPU)
/**
 * The GPU ambient obscurance passes (opaque), with the textures they keep for the last image
 * size they ran at. Create with `ocean_sao_gpu_create` on a context, run with
 * `ocean_sao_gpu_run`, free with `ocean_sao_gpu_destroy`. It works only with the context it
 * was created on. Every call locks it, so any thread may use it, but calls on one handle run
 * one at a time.
 */
typedef struct OceanSaoGpu OceanSaoGpu;
#endif

#if defined(OCEAN_GPU)
/**
 * A scene built on a GPU context (opaque): every renderer, texture and wave train box of a
 * scene description, made once. Create with `ocean_scene_create`, render frames with
 * `ocean_scene_render_rgba8`, free with `ocean_scene_destroy`. It works only with the context
 * it was created on. Every call locks the scene, so any thread may use it, but calls on one
 * scene run one at a time.
 */
typedef struct OceanScene OceanScene;
#endif

#if defined(OCEAN_GPU)
/**
 * A shader translated to one language (opaque): its files and binding layout. Create with
 * `ocean_shader_export`, free with `ocean_shader_export_destroy`. Immutable: a
 * `const OceanShaderExport *` may be used by any number of threads at once.
 */
typedef struct OceanShaderExport OceanShaderExport;
#endif

/**
 * A mip-mapped sky map of one lighting (opaque): the sky's radiance in the stereographic
 * parameterisation (paper section 5.2), level 0 of size N, each coarser level the 2x2 mean of
 * the one above, down to 1x1. Create with `ocean_lighting_sky_map_create`, free with
 * `ocean_sky_map_destroy`. Immutable and shareable between threads.
 */
typedef struct OceanSkyMap OceanSkyMap;

/**
 * A sampled wave spectrum (opaque): its trochoids and statistics. Create with
 * `ocean_spectrum_create`, free with `ocean_spectrum_destroy`. Immutable: a
 * `const OceanSpectrum *` may be used by any number of threads at once.
 */
typedef struct OceanSpectrum OceanSpectrum;

/**
 * An immutable set of trochoid waves (opaque). Create with `ocean_waves_create`, free with
 * `ocean_waves_destroy`. A `const OceanWaves *` may be evaluated and queried from any number
 * of threads at once; destroying it must not race with any other use.
 */
typedef struct OceanWaves OceanWaves;

/**
 * A Wave Train Boxes scene (opaque): water grid, terrain, boxes, effects and budget. Create
 * with `ocean_wtb_scene_create`, free with `ocean_wtb_scene_destroy`.
 *
 * Every function taking an `OceanWtbScene *` may be called from several threads at once on the
 * same scene: a lock inside the scene serialises them (they do not run concurrently with each
 * other; evaluations and height queries spread their own work over the library's worker
 * threads). Destroying must not race with any other use.
 */
typedef struct OceanWtbScene OceanWtbScene;

/**
 * The head of an extension struct: the link to the next extension and the type of this one.
 * An extension struct starts with this member, so a pointer to it is a pointer to its head.
 */
typedef struct OceanChain {
  /**
   * The next extension of the same parameter struct, or NULL.
   */
  const struct OceanChain *next;
  /**
   * Which extension struct this head begins (an `OCEAN_S_TYPE_*` value; this version of
   * the library defines none and refuses every value).
   */
  uint32_t s_type;
  /**
   * Set to 0.
   */
  uint32_t reserved;
} OceanChain;

/**
 * The type of the `next` member of a parameter struct, `const OceanChain *`: NULL, or a
 * pointer to the head of an extension struct.
 */
typedef const struct OceanChain *OceanNext;

#if defined(OCEAN_GPU)
/**
 * How an `OceanRenderer` draws. `ocean_renderer_options_default` fills in the library's
 * defaults. Colour is fixed to 8-bit RGBA (sRGB-encoded, tone-mapped) and the renderer draws
 * with a 32-bit float depth buffer of its own.
 */
typedef struct OceanRendererOptions {
  /**
   * Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
   * function sets NULL.
   */
  OceanNext next;
  /**
   * Screen-space size of a projected-grid cell, pixels, in [1, 256] (the paper: 8). Smaller
   * cells resolve shorter waves in the geometry and cost more vertices.
   */
  double cell_px;
  /**
   * How far the grid extends beyond the viewport on every side, as a fraction of the
   * viewport's width (left and right) and height (top and bottom), in [0, 2]: large waves
   * pull the grid's edges inwards, and the margin keeps them off screen.
   */
  double margin;
  /**
   * Distance cap of the rays' sea-plane hits, metres, in (0, 1e7]: rays above the horizon,
   * or meeting the sea farther, stop there.
   */
  double max_distance;
  /**
   * Exposure of the tone mapping 1 - exp(-exposure * L), in (0, 1e6]
   * (`OCEAN_DEFAULT_EXPOSURE` by default).
   */
  double exposure;
  /**
   * Level-0 size of the sky map texture, a power of two in [`OCEAN_SKY_MAP_MIN_SIZE`,
   * `OCEAN_SKY_MAP_MAX_SIZE`] (and at most the device's largest texture).
   */
  uint32_t sky_map_size;
  /**
   * 1: draw the sky background (the sky map's radiance towards each pixel and the Sun's
   * disc) behind the sea; 0: leave those pixels black (alpha 255). Other values are refused.
   */
  uint32_t draw_sky;
} OceanRendererOptions;
#endif

/**
 * A camera, as every entry point that needs one takes it: the view and projection matrices a
 * renderer draws with, and the depth convention the projection was built for.
 *
 * Matrices are column-major, 16 doubles, element [4 * column + row]: GLM's layout
 * (`glm::value_ptr` of a `glm::dmat4`; convert a `glm::mat4` with `glm::dmat4(m)`). Column
 * vectors: clip = projection * view * world. The view matrix maps world space (right-handed,
 * y up) to view space, right-handed with the camera looking down its -z axis; every element
 * finite and the matrix invertible.
 *
 * Accepted projections:
 * - a symmetric perspective, bottom row (0, 0, -1, 0): `glm::perspective`,
 *   `glm::infinitePerspective`, and their [0, 1] and reversed-Z forms. Off-centre frusta
 *   (`projection[8]`, `[9]`, `[12]`, `[13]` non-zero, as in a TAA-jittered matrix) are refused:
 *   pass the unjittered matrix and jitter after;
 * - an orthographic box, bottom row (0, 0, 0, 1), centred or not (`glm::ortho`).
 *
 * Both need a positive x scale `projection[0]` and y scale `projection[5]` (no mirrored or
 * y-flipped matrix) and zero skew (`projection[1]`, `[2]`, `[4]`, `[6]`). The near and far
 * planes are read from the depth row (`projection[10]`, `[14]`) under `depth_convention`, and
 * must come out as 0 < near < far (perspective; far may be infinite: `projection[10]` = -1, or
 * 0 reversed) or near < far (orthographic). A matrix read under the wrong direction of depth
 * (a forward-Z matrix declared `OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE_REVERSED`, or the reverse)
 * fails that test and is refused.
 *
 * The depth row alone cannot tell `OCEAN_DEPTH_CONVENTION_ZERO_TO_ONE` from
 * `OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE` for a forward-Z perspective: a `glm::perspective`
 * matrix (GLM's default, [-1, 1]) read as [0, 1] gives a near plane at about twice its
 * distance, without any error. Pass the convention the matrix was built for (GLM: [-1, 1]
 * unless `GLM_FORCE_DEPTH_ZERO_TO_ONE`); `ocean_sao_describe` reports the planes read.
 */
typedef struct OceanCamera {
  /**
   * World-to-view matrix, column-major.
   */
  double view[16];
  /**
   * View-to-clip (projection) matrix, column-major.
   */
  double projection[16];
  /**
   * The convention of `projection` (other values are refused).
   */
  OceanDepthConvention depth_convention;
  /**
   * Must be 0: room for a later member, and no padding the caller cannot see.
   */
  uint32_t reserved;
} OceanCamera;

/**
 * A 3D vector in double precision. World-space vectors are right-handed with y up; the BRDF
 * functions take tangent-frame vectors (x along the wind, y across it, z along the normal), as
 * each function says.
 *
 * The layout (three doubles, 24 bytes, 8-aligned) is that of GLM's `glm::dvec3` and
 * `double[3]`: an array of `glm::dvec3` may be passed where an `OceanDVec3` array is taken.
 */
typedef struct OceanDVec3 {
  /**
   * x.
   */
  double x;
  /**
   * y (up).
   */
  double y;
  /**
   * z.
   */
  double z;
} OceanDVec3;

/**
 * A linear RGB triple in double precision (radiance, irradiance or reflectance, as documented
 * where it is used).
 */
typedef struct OceanRgb {
  /**
   * Red.
   */
  double r;
  /**
   * Green.
   */
  double g;
  /**
   * Blue.
   */
  double b;
} OceanRgb;

/**
 * The coefficients of a CIE standard sky type (ISO 15469 / CIE S 011): the gradation
 * phi(theta) = 1 + a exp(b / cos theta) (theta the zenith angle of the sky element) and the
 * indicatrix f(gamma) = 1 + c (exp(d gamma) - exp(d pi/2)) + e cos^2 gamma (gamma its angle
 * from the Sun). Each in [-1000, 1000], b and d in [-1000, 0] (as in every CIE standard type:
 * with b > 0 the gradation grows without bound towards the horizon); the sky's relative
 * radiance must stay positive at the zenith and non-negative elsewhere. The default (`ocean_sky_params_default`) is type 12,
 * "standard clear sky, low turbidity": a = -1, b = -0.32, c = 10, d = -3, e = 0.45.
 */
typedef struct OceanCieSky {
  /**
   * Gradation a.
   */
  double a;
  /**
   * Gradation b, in [-1000, 0] (negative: the sky brightens towards the horizon).
   */
  double b;
  /**
   * Indicatrix c (the circumsolar brightening).
   */
  double c;
  /**
   * Indicatrix d, in [-1000, 0].
   */
  double d;
  /**
   * Indicatrix e (the forward-scattering term).
   */
  double e;
} OceanCieSky;

/**
 * The Sun and the sky (paper section 5.1, 5.2). `ocean_sky_params_default` fills in a clear
 * afternoon.
 */
typedef struct OceanSkyParams {
  /**
   * Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
   * function sets NULL.
   */
  OceanNext next;
  /**
   * Unit vector towards the Sun, world space (y up); its length must be within 1e-6 of 1
   * and its elevation in [0, 90] degrees (y >= 0): the model has no twilight.
   */
  struct OceanDVec3 sun_direction;
  /**
   * The Sun's irradiance on a surface facing it, linear RGB, each channel in [0, 1e30].
   */
  struct OceanRgb sun_irradiance;
  /**
   * The sky's radiance at the zenith, linear RGB, each channel in [0, 1e30].
   */
  struct OceanRgb zenith_radiance;
  /**
   * The sky's relative radiance distribution.
   */
  struct OceanCieSky cie;
  /**
   * The Sun's angular radius, radians, in [1e-5, 0.25] (default: the real Sun's, 4.653e-3).
   * It sets the Sun's solid angle (Eq. 15) and the least slope variance of its reflection
   * (rho^2 / 16, section 5.1).
   */
  double sun_angular_radius;
} OceanSkyParams;

/**
 * The water body under the surface (paper section 5.3). `ocean_sea_params_default` fills in a
 * deep blue open ocean.
 */
typedef struct OceanSeaParams {
  /**
   * Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
   * function sets NULL.
   */
  OceanNext next;
  /**
   * Diffuse reflectance of the water body, linear RGB, each channel in [0, 1]: the light
   * scattered back up is L_sea = albedo (E_sun sin(elevation) + E_sky) / pi.
   */
  struct OceanRgb albedo;
  /**
   * Fresnel reflectance at normal incidence, R of Eq. 14, in [0, 1] (water: 0.02,
   * `OCEAN_WATER_R`).
   */
  double fresnel_r;
} OceanSeaParams;

/**
 * The environment's irradiance on a surface of any orientation, E(n) = sum_i `k[i]` Y_i(n)
 * (order-2 real spherical harmonics, world space, y up), the nine Y_i in the order
 * 1; x, y, z; xy, yz, 3y^2 - 1, xz, x^2 - z^2 with their orthonormal normalisations; linear
 * RGB per coefficient. All zero: no environment light.
 */
typedef struct OceanIrradiance {
  /**
   * `k[i] = A_l L_i`: the environment's projection on `Y_i` times the clamped cosine's
   * factor (pi, 2 pi / 3, pi / 4 for orders 0, 1, 2).
   */
  struct OceanRgb k[9];
} OceanIrradiance;

/**
 * A point on the sea plane y = 0 in double precision: world x and z in metres. World positions
 * cross the C ABI in double precision (a float resolves only 7.8 mm at 100 km).
 *
 * The layout (two doubles, 16 bytes, 8-aligned) is that of GLM's `glm::dvec2` and `double[2]`;
 * the second member holds z, not y.
 */
typedef struct OceanDVec2 {
  /**
   * x, metres.
   */
  double x;
  /**
   * z, metres.
   */
  double z;
} OceanDVec2;

/**
 * The three terms of the sea's radiance towards the viewer (Algorithm 5.1), linear RGB in the
 * unit of the lighting's radiances; their sum is the pixel's colour before tone mapping.
 */
typedef struct OceanSeaLight {
  /**
   * I_sun, the Sun's reflection (Eq. 15), with the slope variances raised to the solar
   * disc's.
   */
  struct OceanRgb sun;
  /**
   * I_sky = F_bar L_bar, the sky's reflection (Eq. 21, 26, 27).
   */
  struct OceanRgb sky;
  /**
   * I_sea = L_sea (1 - F_bar), the light refracted out of the water (Eq. 28).
   */
  struct OceanRgb sea;
} OceanSeaLight;

/**
 * One input of `ocean_sea_color_batch`: the arguments of `ocean_sea_color`.
 */
typedef struct OceanSeaColorInput {
  /**
   * Unit vector from the surface point towards the viewer, world space (y up).
   */
  struct OceanDVec3 v;
  /**
   * The filtered unit surface normal (Eq. 3), world space.
   */
  struct OceanDVec3 n;
  /**
   * The horizontal wind direction (x, z) along which `sigma_x2` is measured; any finite,
   * non-zero length.
   */
  struct OceanDVec2 wind;
  /**
   * Slope variance of the unresolved waves along the wind (Eq. 4), finite and >= 0.
   */
  double sigma_x2;
  /**
   * Slope variance across the wind, finite and >= 0.
   */
  double sigma_y2;
} OceanSeaColorInput;

/**
 * What to sample (paper section 3.1, 7.1). `ocean_spectrum_params_default` fills in 60 waves
 * from 2 cm to 30 m under a 10 m/s wind along +x.
 *
 * The `wave_count` wavelengths form a geometric progression from `min_wavelength` to
 * `max_wavelength`. Wave i (shortest first) stands for the band of angular frequencies around
 * its own omega_i = sqrt(g k_i), k_i = 2 pi / lambda_i, reaching halfway in log(omega) to its
 * neighbours, d_omega_i = omega_i (q - 1/q) with q = (lambda_max/lambda_min)^(1/(4 (n - 1)))
 * (0 for a single wave), and takes that band's energy: A_i = sqrt(2 S(omega_i) d_omega_i),
 * with S the Pierson-Moskowitz spectrum of Eq. 1,
 * S(omega) = 8.1e-3 g^2 / omega^5 exp(-0.74 (g / (V omega))^4), g = 9.81 m/s^2; then clamped
 * to k_i A_i <= `max_steepness`. Directions are drawn from Hasselmann's cos^2s(theta/2)
 * spreading around the wind (s >= 2), phases uniformly, from a PCG32 stream seeded by `seed`:
 * the same parameters give the same waves on every platform.
 */
typedef struct OceanSpectrumParams {
  /**
   * Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
   * function sets NULL.
   */
  OceanNext next;
  /**
   * Wind speed 20 m above the sea, m/s (V_20 of Eq. 1), in [1e-3, 200].
   */
  double wind_speed;
  /**
   * x component of the direction the wind blows towards, on the sea plane; with
   * `wind_direction_z` any finite, non-zero vector (it is normalised).
   */
  double wind_direction_x;
  /**
   * z component of the wind direction.
   */
  double wind_direction_z;
  /**
   * Number of trochoids, 1 to 1024 (the paper uses 60).
   */
  size_t wave_count;
  /**
   * Shortest wavelength, metres, in [1e-4, 1e5].
   */
  double min_wavelength;
  /**
   * Longest wavelength, metres, in [min_wavelength, 1e5]; strictly longer when
   * `wave_count` > 1.
   */
  double max_wavelength;
  /**
   * Largest steepness k*A of any one wave, in [0, 1]: longer amplitudes are clamped to it
   * (a trochoid with k*A > 1 loops over itself).
   */
  double max_steepness;
  /**
   * Seed of the directions and phases.
   */
  uint64_t seed;
} OceanSpectrumParams;

/**
 * One trochoid (Gerstner) wave train, as the caller describes it (Yrjola & Larsson Eq. 6, 7).
 *
 * Every member must be finite, except `depth`, which may be `INFINITY` for deep water.
 * NaN anywhere, or an infinite amplitude, wavelength, direction, phase or a depth of
 * `-INFINITY`, gives `OCEAN_STATUS_NON_FINITE`.
 */
typedef struct OceanWaveDesc {
  /**
   * Amplitude A in metres (half the crest-to-trough height), >= 0. The steepness k*A with
   * k = 2*pi/wavelength must be <= 1 (else `OCEAN_STATUS_TOO_STEEP`): A <= wavelength/(2*pi).
   */
  double amplitude;
  /**
   * Wavelength in metres, > 0.
   */
  double wavelength;
  /**
   * x component of the direction of travel on the sea plane; with `direction_z` any finite,
   * non-zero vector (it is normalised).
   */
  double direction_x;
  /**
   * z component of the direction of travel.
   */
  double direction_z;
  /**
   * Phase shift in radians, finite.
   */
  double phase;
  /**
   * Water depth in metres, > 0, which sets the angular frequency by the dispersion relation
   * omega = sqrt(g*k*tanh(k*depth)) (Eq. 4, g = 9.81 m/s^2); or `INFINITY` for deep water,
   * omega = sqrt(g*k) (Eq. 5).
   */
  double depth;
} OceanWaveDesc;

/**
 * Slope variances of a Gaussian slope distribution (Eq. 4), dimensionless: along the wind and
 * across it (the x and y axes of the BRDF's tangent frame).
 */
typedef struct OceanSlopeVariance {
  /**
   * sigma_x^2, along the wind, >= 0.
   */
  double sigma_x2;
  /**
   * sigma_y^2, across the wind, >= 0.
   */
  double sigma_y2;
} OceanSlopeVariance;

#if defined(OCEAN_GPU)
/**
 * How the exported `ocean` shader draws: the parts of the uniform block that do not come from
 * the camera, the spectrum or the lighting. `ocean_surface_draw_params_default` fills in the
 * library's defaults (those of `ocean_renderer_options_default`, the paper's filter).
 */
typedef struct OceanSurfaceDrawParams {
  /**
   * Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
   * function sets NULL.
   */
  OceanNext next;
  /**
   * N_min of the filter (paper section 7.1): a wave enters a pixel's normal once its
   * wavelength spans this many pixels (a grid vertex's position: grid cells). > 0.
   */
  double n_min;
  /**
   * N_max of the filter: fully present from this many. In (n_min, 1e6].
   */
  double n_max;
  /**
   * Projected grid (`ocean_vs`): cell size, pixels, in [1, 256]. Unused by the mesh.
   */
  double cell_px;
  /**
   * Projected grid: margin beyond the viewport, a fraction of its size, in [0, 2]. Unused by
   * the mesh.
   */
  double margin;
  /**
   * Distance cap of the view rays' hits on the sea plane, metres, in (0, 1e7]: pixel
   * footprints (hence the filtering) are measured on the sea plane, and rays above the
   * horizon stop there.
   */
  double max_distance;
  /**
   * Exposure of the tone mapping 1 - exp(-exposure * L), in (0, 1e6].
   */
  double exposure;
  /**
   * Level-0 size of the sky map texture the engine uploads (`ocean_lighting_sky_map_create`
   * with this size), a power of two in [`OCEAN_SKY_MAP_MIN_SIZE`, `OCEAN_SKY_MAP_MAX_SIZE`].
   */
  uint32_t sky_map_size;
  /**
   * 1: the shader sRGB-encodes its colour (for a linear `GL_RGBA8` target); 0: it writes
   * linear colour (for an sRGB target with `GL_FRAMEBUFFER_SRGB`). Other values are refused.
   */
  uint32_t srgb_encode;
} OceanSurfaceDrawParams;
#endif

/**
 * The water grid of a scene: `nx * nz` points, point (i, j) resting at world
 * (origin_x + i*spacing, 0, origin_z + j*spacing), stored row-major at j*nx + i. The spacing is
 * the same along x and z (a box's internal frame steps by it along both of its axes).
 */
typedef struct OceanWaterGridDesc {
  /**
   * World x of point (0, 0), metres, finite, |origin_x| <= 1e9.
   */
  double origin_x;
  /**
   * World z of point (0, 0), metres, finite, |origin_z| <= 1e9.
   */
  double origin_z;
  /**
   * Distance between neighbouring points along x and z, metres, in [1e-3, 1e4].
   */
  double spacing;
  /**
   * Columns (along x), 2 to 4096.
   */
  size_t nx;
  /**
   * Rows (along z), 2 to 4096.
   */
  size_t nz;
} OceanWaterGridDesc;

/**
 * How the cones are made. Start from `ocean_relief_cone_params_default`.
 */
typedef struct OceanReliefConeParams {
  /**
   * Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
   * function sets NULL.
   */
  OceanNext next;
  /**
   * `OCEAN_RELIEF_CONE_KIND_RELAXED` (default) or `OCEAN_RELIEF_CONE_KIND_CONSERVATIVE`;
   * other values are refused.
   */
  OceanReliefConeKind kind;
  /**
   * Cap on the cone ratios (texture widths per unit depth) and the clearances (texture
   * widths), in (0, `OCEAN_RELIEF_MAX_RATIO_LIMIT`]. Default 1.0, the book's, for 8-bit
   * storage (which clamps at 1.0 anyway); a larger cap keeps wider cones for f16 / f32.
   */
  float max_ratio;
} OceanReliefConeParams;

/**
 * A progress callback: `done` of `total` units of work are finished (rows of bilinear cells:
 * `total` is N in wrap mode and N + 1 in clamp mode). Return 0 to go on, nonzero to cancel:
 * the function then returns `OCEAN_STATUS_CANCELLED` and writes nothing.
 *
 * It is called on the thread that called the generating function, never concurrently with
 * itself: once with `done` = 0 before any work, then after each band of rows (at most
 * `OCEAN_RELIEF_PROGRESS_BANDS`), the last time with `done` = `total`. `user` is passed through
 * untouched. The callback must not unwind (C++ exceptions, `longjmp`) out of the call.
 */
typedef int (*OceanReliefProgress)(void *user, size_t done, size_t total);

/**
 * A tracer and its step counts.
 */
typedef struct OceanReliefMethod {
  /**
   * Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
   * function sets NULL.
   */
  OceanNext next;
  /**
   * `OCEAN_RELIEF_TRACER_LINEAR`, `_CONE_STEP` or `_RELAXED`; other values are refused.
   */
  OceanReliefTracer method;
  /**
   * Linear steps, cone steps, or relaxed cone steps: 1 to `OCEAN_RELIEF_MAX_STEPS` (the
   * book: 15 relaxed steps).
   */
  uint32_t steps;
  /**
   * Bisections, 0 to `OCEAN_RELIEF_MAX_STEPS` (the book: 6). Not read by cone step mapping.
   */
  uint32_t binary;
  /**
   * `OCEAN_RELIEF_SEARCH_*`: read only by relaxed cone stepping, but checked whatever the
   * tracer (other values are refused).
   */
  OceanReliefSearch search;
} OceanReliefMethod;

#if defined(OCEAN_GPU)
/**
 * A relief-mapped polygon, how it is traced and how it is lit.
 *
 * The quad is the rectangle with a corner at `origin` (texture coordinates (0, 0)) and edges
 * `edge_u` (along the texture's u) and `edge_v` (along v, the rows), spanning `tiles_u` and
 * `tiles_v` texture widths. Tangent space is the tracers': x along u, y along v, z =
 * edge_u x edge_v out of the polygon, towards its front; the relief lies `depth` world units
 * under it. The edges must be orthogonal and a texture width must have one world length along
 * both (relative tolerance 1e-6), so the relief is not sheared.
 *
 * What is drawn is the convex polygon `corners` in the quad's plane: the whole quad, or a
 * triangle or quadrilateral of a mesh (its texture then continues beyond the quad's edges).
 */
typedef struct OceanReliefScene {
  /**
   * Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
   * function sets NULL.
   */
  OceanNext next;
  /**
   * World position of the corner at texture coordinates (0, 0), metres.
   */
  struct OceanDVec3 origin;
  /**
   * World vector from `origin` along u to the next corner.
   */
  struct OceanDVec3 edge_u;
  /**
   * World vector from `origin` along v to the next corner.
   */
  struct OceanDVec3 edge_v;
  /**
   * Texture widths across `edge_u` (> 0).
   */
  double tiles_u;
  /**
   * Texture widths across `edge_v` (> 0).
   */
  double tiles_v;
  /**
   * Depth of the relief below the polygon, world units (>= 0).
   */
  double depth;
  /**
   * The tracer of the viewing ray and of the light ray.
   */
  struct OceanReliefMethod method;
  /**
   * 1: trace the light ray for self-shadowing; 0: do not. Other values are refused.
   */
  uint32_t shadows;
  /**
   * How far (depth units) above a point the light ray must stop to shadow it, in [0, 1].
   */
  float shadow_bias;
  /**
   * World direction towards the (directional) light; any length but zero.
   */
  struct OceanDVec3 light_dir;
  /**
   * Light intensity (>= 0).
   */
  float light_intensity;
  /**
   * The light's linear colour, red, green, blue, multiplying `light_intensity` (each >= 0;
   * the default: white, 1, 1, 1).
   */
  float light_color[3];
  /**
   * Linear albedo, red, green, blue (each >= 0).
   */
  float albedo[3];
  /**
   * Light that reaches every point whatever the light and shadows (>= 0).
   */
  float ambient;
  /**
   * The environment's irradiance E (`ocean_lighting_irradiance`), or all zero for none: the
   * ambient term gains albedo E(n) / pi, a Lambertian surface's radiance under it, n the
   * relief's normal at the hit in world space. `light_intensity` and `ambient` must then be
   * in the same radiance units.
   */
  struct OceanIrradiance sky;
  /**
   * The polygon drawn: corners `{s, t}`, the points `origin + s edge_u + t edge_v`,
   * counter-clockwise seen from the front, convex, enclosing an area, each coordinate within
   * 1e6; a triangle repeats its last corner. The default, `{0, 0}, {1, 0}, {1, 1}, {0, 1}`,
   * is the whole quad; all zero (a zeroed struct) is refused.
   */
  double corners[4][2];
} OceanReliefScene;
#endif

/**
 * A ray into the relief (section 18.2): it enters at texture coordinates (start_u, start_v)
 * at depth 0 and moves by (dir_x, dir_y) texture widths per dir_z of depth. Only the ratios
 * matter (the tracers divide by dir_z, as the book's `ray_dir /= ray_dir.z`), and they must
 * stay finite: a dir_z so small beside dir_x, dir_y that the run per unit depth overflows a
 * float is refused, and so is a ray whose |start| plus run to full depth exceeds 1e30 texture
 * widths (`ocean_relief::MAX_TEXCOORD`). `ocean_relief_ray_from_view` makes one from a
 * tangent-space view vector.
 */
typedef struct OceanReliefRay {
  /**
   * Entry point, texture coordinate u.
   */
  float start_u;
  /**
   * Entry point, texture coordinate v.
   */
  float start_v;
  /**
   * Direction along u.
   */
  float dir_x;
  /**
   * Direction along v.
   */
  float dir_y;
  /**
   * Direction in depth: positive (into the relief).
   */
  float dir_z;
} OceanReliefRay;

/**
 * A point of the relief: texture coordinates and normalised depth (0 at the polygon, 1 at the
 * bottom of the relief).
 */
typedef struct OceanReliefPoint {
  /**
   * Texture coordinate u (texture widths; texel i's centre is at (i + 0.5)/N).
   */
  float u;
  /**
   * Texture coordinate v.
   */
  float v;
  /**
   * Depth, 0 at the polygon surface, 1 at the bottom.
   */
  float depth;
} OceanReliefPoint;

/**
 * Where a tracer stopped.
 */
typedef struct OceanReliefHit {
  /**
   * The hit (the midpoint of the final bracket; for cone step mapping, and for a shared
   * budget spent before the ray got inside, the last point known to be above the surface).
   */
  struct OceanReliefPoint pos;
  /**
   * Texture fetches spent on the ray.
   */
  uint32_t fetches;
} OceanReliefHit;

/**
 * The bilateral reconstruction (paper section 2.4): a horizontal then a vertical pass of `taps`
 * taps `stride` pixels apart, weighted by exp(-t^2 / (2 sigma^2)) for tap t (counted in taps)
 * times max(0, 1 - depth_scale |key_t - key_ref|), with key = z / z_min and key_ref the
 * centre's key (`OCEAN_SAO_BLUR_WEIGHT_DEPTH`) or its plane's prediction
 * (`OCEAN_SAO_BLUR_WEIGHT_PLANE`, which also fades taps with their distance in metres).
 * Background pixels neither change nor contribute.
 */
typedef struct OceanSaoBlurParams {
  /**
   * Tap count, odd, 1 to 63 (default 13; the paper: 7; its released shader: 9). 1 disables
   * the blur.
   */
  uint32_t taps;
  /**
   * Pixels between taps, 1 to 64 (default 1; the paper: 3; its released shader: 2).
   */
  uint32_t stride;
  /**
   * Depth-difference scale, in [0, 1e9] (the paper: 2^11 = 2048): with z_min = -200 m,
   * pixels more than 200/2048 m (about 0.1 m) apart in depth do not mix.
   */
  float depth_scale;
  /**
   * Gaussian standard deviation in taps, in [1e-3, 1e3] (default 3: the outermost of 13
   * taps weighs e^-2 of the centre; the paper's 7 taps: 1.5).
   */
  float sigma;
  /**
   * `OCEAN_SAO_BLUR_WEIGHT_PLANE` (default) or `OCEAN_SAO_BLUR_WEIGHT_DEPTH` (the paper's);
   * other values are refused.
   */
  OceanSaoBlurWeight weight;
  /**
   * With the plane weight: the distance from the centre pixel, as a fraction of `radius`,
   * at which a tap's weight fades to 0, in [0, 1e3] (default 0.5; 0: no fade).
   */
  float world_extent;
} OceanSaoBlurParams;

/**
 * Every parameter of the passes. Start from `ocean_sao_params_default` and change what you
 * need. Lengths are metres; the default is the paper's set-up for human-scale scenes.
 */
typedef struct OceanSaoParams {
  /**
   * Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
   * function sets NULL.
   */
  OceanNext next;
  /**
   * World-space radius r of the obscurance ball, metres, in [1e-4, 1e4] (default 1).
   */
  float radius;
  /**
   * Samples per pixel, 1 to 64 (default 9, the paper's).
   */
  uint32_t samples;
  /**
   * Turns of the sample spiral (Eq. 6-7), in [1e-3, 1e3] (default 7, the paper's value for
   * 9 samples). It does not follow `samples`: when changing the sample count, set it too.
   * ocean-sao's convention is the integer nearest 7 * samples / 9 that is coprime with the
   * sample count (ties to the smaller), so every sample direction differs.
   */
  float spiral_turns;
  /**
   * log2 of q' in Eq. 9, 0 to 8 (default 3): a sample h pixels from the centre reads MIP
   * level floor(log2(h)) - mip_switch_log2, clamped to [0, max_mip].
   */
  uint32_t mip_switch_log2;
  /**
   * Highest MIP level read, 0 to 13 (default 5); 0 reads every sample from full resolution.
   */
  uint32_t max_mip;
  /**
   * How a MIP level is made from the one below: an `OCEAN_SAO_MIP_FILTER_*` value (default
   * `OCEAN_SAO_MIP_FILTER_ROTATED_GRID`); other values are refused.
   */
  OceanSaoMipFilter mip_filter;
  /**
   * `OCEAN_SAO_ESTIMATOR_FALLOFF` (default) or `OCEAN_SAO_ESTIMATOR_ALCHEMY`; other values
   * are refused. Only the chosen estimator's constants below are read and checked.
   */
  OceanSaoEstimator estimator;
  /**
   * Falloff: bias beta, metres, in [0, 1e3] (default 0.01: 1 cm).
   */
  float falloff_beta;
  /**
   * Falloff: intensity multiplier, in [0, 1e3] (default 1, the appendix's formula).
   */
  float falloff_intensity;
  /**
   * Eq. 1: intensity sigma, metres, in [0, 1e4] (default 0.25).
   */
  float alchemy_sigma;
  /**
   * Eq. 1: depth-proportional bias beta, in [0, 1] (default 1e-3: 1 cm at 10 m).
   */
  float alchemy_beta;
  /**
   * Eq. 1: contrast exponent k, in [1e-2, 16] (default 1).
   */
  float alchemy_k;
  /**
   * epsilon of both estimators, square metres, in [1e-12, 1e4] (default 0.01).
   */
  float epsilon;
  /**
   * 1: the 2x2 quad bilateral of section 2.3 (default); 0: off. Other values are refused.
   */
  uint32_t quad_filter;
  /**
   * The quad bilateral averages two neighbours when their z differ by less than this many
   * metres, in [0, 1e6] (default 0.02). Read only when `quad_filter` is 1.
   */
  float quad_depth_threshold;
  /**
   * `OCEAN_SAO_NORMALS_NEAREST` (default) or `OCEAN_SAO_NORMALS_QUAD` (the paper's Eq. 4);
   * other values are refused.
   */
  OceanSaoNormals normals;
  /**
   * 1: treat pixels whose reconstructed normal is unreliable (a depth edge inside their 2x2
   * quad) as unoccluded; 0: the paper's behaviour (default). Other values are refused.
   */
  uint32_t normal_rejection;
  /**
   * The rejection's largest apparent incidence angle, radians, in [1e-3, pi/2 - 1e-3]
   * (default 85 degrees, 1.4835 rad). Read only when `normal_rejection` is 1.
   */
  float normal_max_incidence;
  /**
   * z_min of the depth key the blur compares (section 2.3), metres, negative, in
   * [-1e8, -1e-4] (default -200): the farthest view depth at which sharp AO edges matter.
   */
  float z_min;
  /**
   * The blur passes.
   */
  struct OceanSaoBlurParams blur;
  /**
   * Set to 0 (fills the struct to a multiple of 8 bytes, the alignment of `next`).
   */
  uint32_t reserved;
} OceanSaoParams;

/**
 * What an `OceanSao` was made of, as `ocean_sao_describe` reports it: the sizes, the planes read
 * from the projection matrix, and the constants of the passes (the values a GPU shader that
 * follows ocean-sao needs).
 */
typedef struct OceanSaoInfo {
  /**
   * Width of the depth buffer, pixels.
   */
  uint32_t input_width;
  /**
   * Height of the depth buffer, pixels.
   */
  uint32_t input_height;
  /**
   * Guard band on every side, pixels.
   */
  uint32_t guard;
  /**
   * Width of the AO image: input_width - 2 guard.
   */
  uint32_t output_width;
  /**
   * Height of the AO image: input_height - 2 guard.
   */
  uint32_t output_height;
  /**
   * 1 for an orthographic projection, 0 for a perspective.
   */
  uint32_t orthographic;
  /**
   * Near-plane distance read from the matrix, metres (in front of the camera; an
   * orthographic box may start at or behind it: <= 0).
   */
  double near;
  /**
   * Far-plane distance read from the matrix, metres; `INFINITY` for an infinite perspective.
   */
  double far;
  /**
   * Eq. 2 with ocean-sao's fourth constant: the view-space z (negative in front) of a depth
   * d is (`c[0]` + `c[3]` d) / (`c[1]` d + `c[2]`), in float arithmetic (`c[3]` = 0 for a
   * perspective, `c[1]` = 0 for an orthographic box), for every depth but `far_depth`.
   */
  float z_constants[4];
  /**
   * The depth value of the near plane (0, -1 for NDC depth under [-1, 1], or 1 reversed).
   */
  float near_depth;
  /**
   * The depth value of the far plane, or of infinity: the clear value, read as background.
   */
  float far_depth;
  /**
   * Eq. 5's S' = input_height P11 / 2: pixels per metre at 1 m in front of a perspective
   * camera, pixels per metre everywhere for an orthographic one.
   */
  float pixels_per_metre;
  /**
   * Written as 0: room for a later member, and no padding the caller cannot see.
   */
  uint32_t reserved;
} OceanSaoInfo;

#if defined(OCEAN_GPU)
/**
 * How `ocean_scene_create` builds a scene: overrides of the description's `[render]` and
 * `[camera]` sections. `ocean_scene_options_default` keeps the description's everywhere.
 */
typedef struct OceanSceneOptions {
  /**
   * Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
   * function sets NULL.
   */
  OceanNext next;
  /**
   * Frame width in pixels; 0: the description's `[render] width`. The description's limits
   * apply (1 to 8192).
   */
  uint32_t width;
  /**
   * Frame height in pixels; 0: the description's `[render] height` (1 to 8192).
   */
  uint32_t height;
  /**
   * Samples per pixel, 1 or 4; 0: the description's `[render] samples`. Where the device
   * cannot draw multisampled targets (OpenGL), one.
   */
  uint32_t samples;
  /**
   * An `OceanSceneCamera`.
   */
  uint32_t camera;
} OceanSceneOptions;
#endif

#if defined(OCEAN_GPU)
/**
 * One resource binding of an exported shader. The strings are NUL-terminated UTF-8, owned by
 * the export, and valid until it is destroyed.
 */
typedef struct OceanShaderBinding {
  /**
   * WGSL `@group` (the descriptor set in SPIR-V, the register space in HLSL).
   */
  uint32_t group;
  /**
   * WGSL `@binding`.
   */
  uint32_t binding;
  /**
   * What kind of resource it is.
   */
  OceanBindingKind kind;
  /**
   * Byte size of the bound type, or of one element of a runtime-sized array; 0 for textures
   * and samplers.
   */
  uint32_t size;
  /**
   * GLSL exports: the binding number in GLSL, which has no groups (`layout(binding = n)` in
   * GLSL 4.30 and ES 3.10; what `glBindBufferBase`, `glActiveTexture` and `glBindImageTexture`
   * take). Each GLSL namespace counts from 0 on its own, in (group, binding) order: uniform
   * blocks, shader storage blocks, texture units and image units; so the first resource of
   * each kind in a pass has number 0. `OCEAN_NO_GLSL_BINDING` where there is none (see
   * there).
   */
  uint32_t glsl_binding;
  /**
   * Written as 0: room for a later member, and no padding the caller cannot see.
   */
  uint32_t reserved;
  /**
   * The variable's name in the WGSL source.
   */
  const char *name;
  /**
   * Its WGSL type, e.g. `Frame` or `texture_2d<f32>`.
   */
  const char *wgsl_type;
  /**
   * GLSL exports: the name of the uniform block, storage block or sampler naga wrote for it
   * (set its binding number by this name under GLSL 3.30); "" when no exported entry point
   * uses it, or for non-GLSL exports. Never NULL.
   */
  const char *glsl_name;
} OceanShaderBinding;
#endif

/**
 * A 3D vector (metres for positions; unit length for normals), right-handed, y up.
 *
 * The layout (three packed floats, 12 bytes) is that of GLM's `glm::vec3` and `float[3]` in
 * GLM's default configuration: an array of `glm::vec3` may be passed where an `OceanVec3` array
 * is taken (not with `GLM_FORCE_DEFAULT_ALIGNED_GENTYPES`, which pads it to 16 bytes).
 */
typedef struct OceanVec3 {
  /**
   * x, metres.
   */
  float x;
  /**
   * y (up), metres.
   */
  float y;
  /**
   * z, metres.
   */
  float z;
} OceanVec3;

/**
 * A regular grid of rest positions on the sea plane: point (i, j), for i < nx and j < nz, rests
 * at world (origin_x + i*spacing_x, origin_z + j*spacing_z). Outputs are row-major: point (i, j)
 * is element j*nx + i.
 */
typedef struct OceanGrid {
  /**
   * World x of point (0, 0), metres, finite.
   */
  double origin_x;
  /**
   * World z of point (0, 0), metres, finite.
   */
  double origin_z;
  /**
   * Distance between columns along x, metres, finite and > 0.
   */
  double spacing_x;
  /**
   * Distance between rows along z, metres, finite and > 0.
   */
  double spacing_z;
  /**
   * Number of columns (along x), 1 to 2^24.
   */
  size_t nx;
  /**
   * Number of rows (along z), 1 to 2^24.
   */
  size_t nz;
} OceanGrid;

/**
 * A wind, which creates one wave train box (paper section 2).
 *
 * The box is the rectangle origin + a*u + b*v, a in [0, length], b in [0, width], with u the
 * unit wind direction and v = (-u.z, u.x) (u turned 90 degrees clockwise seen from above, so
 * for u = +x, v = +z): `origin` is the rear corner on the left when looking along the wind.
 * Its length grows from 0 to `fetch` during the build-up. Fully developed, the trains reach a
 * crest-to-trough height H = 0.21 speed^2 / 9.81 (Eq. 1): their amplitudes sum to H/2.
 *
 * Lifecycle, with age = time - start: build-up for age in [0, build_up) (length and amplitude
 * grow linearly from 0), sustain for `sustain` seconds at full size, then decay for `decay`
 * seconds (amplitude falls linearly to 0); before `start` and after the decay the box does not
 * exist.
 */
typedef struct OceanWindDesc {
  /**
   * Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
   * function sets NULL.
   */
  OceanNext next;
  /**
   * Wind speed, m/s, in (0, 100]. A zero wind is refused.
   */
  double speed;
  /**
   * x component of the direction the wind blows towards; with `direction_z` a finite,
   * non-zero vector (normalised here).
   */
  double direction_x;
  /**
   * z component of the wind direction.
   */
  double direction_z;
  /**
   * World x of the box's origin corner, metres, |origin_x| <= 1e9.
   */
  double origin_x;
  /**
   * World z of the box's origin corner, metres, |origin_z| <= 1e9.
   */
  double origin_z;
  /**
   * Width across the wind, metres, in (0, 1e7] and at most 2^24 grid spacings.
   */
  double width;
  /**
   * Fetch: the full length along the wind, metres, in (0, 1e7] and at most 2^24 grid
   * spacings.
   */
  double fetch;
  /**
   * Time the wind starts, seconds, finite.
   */
  double start;
  /**
   * Build-up duration, seconds, finite and >= 0.
   */
  double build_up;
  /**
   * Sustain duration, seconds, >= 0; `INFINITY` for a wind that never dies.
   */
  double sustain;
  /**
   * Decay duration, seconds, finite and >= 0.
   */
  double decay;
  /**
   * Seed of the documented wind-to-trains mapping (PCG32); the same seed gives the same
   * trains on every platform.
   */
  uint64_t seed;
  /**
   * Number of wave trains the wind raises, 1 to 8 (ignored when explicit trains are given).
   */
  uint32_t trains;
  /**
   * Must be 0: room for a later member (the `_default` functions set it), and no padding
   * the caller cannot see.
   */
  uint32_t reserved;
} OceanWindDesc;

/**
 * A wave train box: its wind and its local parameters.
 */
typedef struct OceanBoxDesc {
  /**
   * Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
   * function sets NULL.
   */
  OceanNext next;
  /**
   * The wind that raises the box.
   */
  struct OceanWindDesc wind;
  /**
   * Width of the smoothing area along the box's edges, metres, finite and >= 0: the
   * amplitude rises linearly from 0 on an edge to full at this distance inside (Fig. 4);
   * 0 gives hard edges.
   */
  double smoothing;
  /**
   * 1: `recovery` is used; 0: the recovery distance is the default, two peak wavelengths.
   * Other values are refused.
   */
  uint32_t has_recovery;
  /**
   * Must be 0: room for a later member (the `_default` functions set it), and no padding
   * the caller cannot see.
   */
  uint32_t reserved;
  /**
   * Distance behind land over which the amplitude recovers linearly to full, metres, finite
   * and >= 0 (0: at once). Read only when `has_recovery` is 1.
   */
  double recovery;
} OceanBoxDesc;

/**
 * Irregular height along the box's width (Eq. 8):
 * A' = A (1 - scale sin(envelope_wavenumber (a - envelope_speed t)) sin(frequency b)), with
 * (a, b) the box's internal coordinates.
 */
typedef struct OceanIrregular {
  /**
   * 1: on; 0: off (the other members are then ignored). Other values are refused.
   */
  uint32_t enabled;
  /**
   * Must be 0: room for a later member (the `_default` functions set it), and no padding
   * the caller cannot see.
   */
  uint32_t reserved;
  /**
   * Share of the amplitude, in [0, 1].
   */
  double scale;
  /**
   * Radians per metre across the box, finite and >= 0.
   */
  double frequency;
  /**
   * Wavenumber of the envelope along the box, radians per metre, finite and >= 0.
   */
  double envelope_wavenumber;
  /**
   * Speed of the envelope along the box, m/s, finite.
   */
  double envelope_speed;
} OceanIrregular;

/**
 * Capillary noise on every grid point, inside boxes or not (Eq. 9): y' = y + amplitude
 * sin(r t), with a rate r in [0, 1) hashed from the seed and the point's index, so it is
 * deterministic and independent of threads.
 */
typedef struct OceanNoise {
  /**
   * 1: on; 0: off (the other members are then ignored). Other values are refused.
   */
  uint32_t enabled;
  /**
   * Must be 0: room for a later member (the `_default` functions set it), and no padding
   * the caller cannot see.
   */
  uint32_t reserved;
  /**
   * Amplitude, metres, finite and >= 0.
   */
  double amplitude;
  /**
   * Seed of the per-point rates.
   */
  uint64_t seed;
} OceanNoise;

/**
 * Beach adjustments (end of paper section 2): the summed amplitude is capped at a share of
 * the local depth so troughs stay above the sea floor, and the water level rises near the
 * shore.
 */
typedef struct OceanBeach {
  /**
   * 1: on; 0: off (the other members are then ignored). Other values are refused.
   */
  uint32_t enabled;
  /**
   * Must be 0: room for a later member (the `_default` functions set it), and no padding
   * the caller cannot see.
   */
  uint32_t reserved;
  /**
   * Largest share of the local depth the summed amplitude may take, in (0, 1].
   */
  double max_depth_share;
  /**
   * Extra water level at the shoreline, metres, finite and >= 0.
   */
  double run_up;
  /**
   * Depth at which the run-up has faded out, metres, finite and >= 0.
   */
  double run_up_depth;
} OceanBeach;

/**
 * The switchable effects of paper section 2.1. `ocean_wtb_effects_default` fills in the library's
 * defaults (phase-shift refraction and shoaling on, everything else off).
 */
typedef struct OceanEffects {
  /**
   * Extensions: NULL, or the first extension struct (see `OceanChain`); the `_default`
   * function sets NULL.
   */
  OceanNext next;
  /**
   * Depth refraction (other values are refused).
   */
  OceanRefraction refraction;
  /**
   * 1: shoaling on (Green's law: the amplitude grows as (D_ref/D)^(1/4) in water shallower
   * than half a wavelength, at most 1.5 times); 0: off. Other values are refused.
   */
  uint32_t shoaling;
  /**
   * 1: round waves on (Eq. 10: fronts curve forward around the middle of each box); 0: off.
   * Other values are refused.
   */
  uint32_t round_waves;
  /**
   * Must be 0: room for a later member (the `_default` functions set it), and no padding
   * the caller cannot see.
   */
  uint32_t reserved;
  /**
   * Irregular height (Eq. 8).
   */
  struct OceanIrregular irregular;
  /**
   * Capillary noise (Eq. 9).
   */
  struct OceanNoise noise;
  /**
   * Beach adjustments.
   */
  struct OceanBeach beach;
} OceanEffects;

/**
 * What one evaluation ran.
 */
typedef struct OceanFrameStats {
  /**
   * Boxes alive at the frame's time.
   */
  size_t alive;
  /**
   * Of those, culled by the view frustum.
   */
  size_t culled;
  /**
   * Boxes whose static modulation (land, shoaling, refraction along the rays) was recomputed
   * this frame because they are new, moved, grew, or the terrain or effects changed.
   */
  size_t rebuilt;
  /**
   * Wave trains evaluated, over all boxes.
   */
  size_t trains;
  /**
   * The budget's choice: at most this many trains per box (its largest); `SIZE_MAX` for all.
   */
  size_t max_trains;
  /**
   * The budget's choice: the effects that ran (a subset of those enabled).
   */
  struct OceanEffects effects;
  /**
   * The cost model's estimate of the frame's work, seconds of one core.
   */
  double estimated_seconds;
  /**
   * Trains weighted down in the geometry by the scene's train filter (they span too few
   * grid cells to be drawn whole; see `ocean_wtb_scene_set_train_filter`), those left out
   * included.
   */
  size_t filtered_trains;
  /**
   * Of those, the trains left out entirely (shorter than the filter's `min_cells`).
   */
  size_t removed_trains;
  /**
   * The slope variance the geometry leaves out, sum over the filtered trains of
   * ((1 - w_p) k A)^2 / 2: add it to the BRDF's roughness (where a box's modulation is at
   * most 1, the variance of the missing slopes is at most this).
   */
  double filtered_slope_variance;
} OceanFrameStats;

/**
 * The answer of a drawn height query at world (x, z): the triangle of the evaluated grid's
 * mesh that lies over it.
 */
typedef struct OceanDrawnSample {
  /**
   * Height of the triangle over the query, metres above the sea at rest; 0 where no
   * triangle lies over it (`covered` is 0).
   */
  double height;
  /**
   * The triangle's unit normal, on its upper side (+y where `covered` is 0).
   */
  struct OceanDVec3 normal;
  /**
   * The vertex normals of the triangle blended by the barycentric weights and normalised:
   * what a renderer interpolating the grid's normals shades the point with.
   */
  struct OceanDVec3 shading_normal;
  /**
   * World (x, z) of the rest position the mesh carries to the query (the triangle's rest
   * vertices blended by the same weights); the query itself where `covered` is 0.
   */
  struct OceanDVec2 rest;
  /**
   * Barycentric weights of the query on the triangle's three vertices, in the order given
   * by `upper` (each in [0, 1] up to rounding, summing to 1).
   */
  double weights[3];
  /**
   * The cell's first grid point: column i and row j.
   */
  uint32_t cell_i;
  /**
   * See `cell_i`.
   */
  uint32_t cell_j;
  /**
   * 0: the lower triangle (i, j), (i+1, j), (i, j+1); 1: the upper triangle (i+1, j),
   * (i+1, j+1), (i, j+1).
   */
  uint32_t upper;
  /**
   * 1 where a triangle lies over the query, 0 over the sea at rest (off the mesh).
   */
  uint32_t covered;
} OceanDrawnSample;

/**
 * The answer of a continuous height query at world (x, z).
 */
typedef struct OceanHeightSample {
  /**
   * Water height there, metres above the sea at rest.
   */
  double height;
  /**
   * Unit surface normal there.
   */
  struct OceanDVec3 normal;
  /**
   * World (x, z) of the rest position whose displaced point lies over the query.
   */
  struct OceanDVec2 rest;
  /**
   * Horizontal distance between that displaced point and the query, metres: the query
   * iterates until it is at most the library's tolerance (10 micrometres) or 16 Newton
   * steps have run.
   */
  double residual;
} OceanHeightSample;

#ifdef __cplusplus
extern "C" {
#endif // __cplusplus

#if defined(OCEAN_GPU)
/**
 * Creates a headless GPU device and stores a new context in `*out`.
 *
 * The adapter is chosen from the environment: `WGPU_BACKEND` selects the backends (`vulkan`,
 * `gl`, `metal`, `dx12`, or a comma-separated list; all compiled in when unset),
 * `WGPU_POWER_PREF` (`low`, `high`) and `WGPU_ADAPTER_NAME` (a substring of the adapter's name)
 * narrow the choice. Software adapters are accepted: Mesa's lavapipe (Vulkan) and llvmpipe
 * (OpenGL through EGL, `WGPU_BACKEND=gl`). The device asks only for WebGPU's downlevel limits.
 * Creating a device takes from milliseconds to a second or so: create one context and keep it.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
 * `OCEAN_STATUS_NO_ADAPTER` when no usable adapter exists (the message says what to install),
 * `OCEAN_STATUS_GPU_FAILURE` for another device error. On failure `*out` is unchanged. Free
 * the context with `ocean_gpu_context_destroy`.
 *
 * # Safety
 *
 * `out` must point to a writable pointer.
 */
OceanStatus ocean_gpu_context_create(struct OceanGpuContext **out);
#endif

#if defined(OCEAN_GPU)
/**
 * Frees a context. NULL does nothing; a handle of another kind or already destroyed frees nothing
 * and sets the last-error message (see the header's notes on handles). Renderers created on it
 * keep the device alive until they are destroyed, but can no longer be used (every renderer call
 * needs the context).
 */
void ocean_gpu_context_destroy(struct OceanGpuContext *ctx);
#endif

#if defined(OCEAN_GPU)
/**
 * Stores in `*out` a one-line, NUL-terminated UTF-8 description of the context's adapter
 * (name, backend, device type, driver), for logs and bug reports. The text is owned by the
 * context, fixed for its life and valid until it is destroyed, as the texts of an
 * `OceanShaderExport` are.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `ctx` or `out`, which
 * is then left unchanged.
 *
 * # Safety
 *
 * `out` must be writable and untouched by other threads during the call.
 */
OceanStatus ocean_gpu_context_describe(const struct OceanGpuContext *ctx, const char **out);
#endif

#if defined(OCEAN_GPU)
/**
 * Stores the default renderer options in `*out`: 8-pixel cells, a 10 % margin, a 50 km
 * distance cap, exposure `OCEAN_DEFAULT_EXPOSURE`, a 512 x 512 sky map, sky drawn.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
 * then left unchanged.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_renderer_options_default(struct OceanRendererOptions *out);
#endif

#if defined(OCEAN_GPU)
/**
 * Compiles the renderer's shaders and creates its buffers and textures on `ctx`'s device, and
 * stores a new renderer in `*out`. It draws nothing until it has a spectrum and a lighting.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite option, `OCEAN_STATUS_INVALID_ARGUMENT` for
 * an option outside its documented range (the message names it), `OCEAN_STATUS_GPU_FAILURE` if
 * the device refuses an object. On failure `*out` is unchanged. Free the renderer with
 * `ocean_renderer_destroy`.
 *
 * # Safety
 *
 * `options` point to a readable `OceanRendererOptions` and `out`
 * to a writable pointer; `options` is not retained.
 */
OceanStatus ocean_renderer_create(const struct OceanGpuContext *ctx,
                                  const struct OceanRendererOptions *options,
                                  struct OceanRenderer **out);
#endif

#if defined(OCEAN_GPU)
/**
 * Frees a renderer and its GPU resources. NULL does nothing; a handle of another kind or already
 * destroyed frees nothing and sets the last-error message (see the header's notes on handles). It
 * may outlive its context.
 */
void ocean_renderer_destroy(struct OceanRenderer *renderer);
#endif

#if defined(OCEAN_GPU)
/**
 * Gives the renderer the waves of `spectrum`, filtered with the thresholds `n_min` and
 * `n_max` (paper section 7.1: a wave enters the geometry once its wavelength spans n_min grid
 * cells and is fully present from n_max, and likewise in the normals per pixel; the rest goes
 * into the BRDF's slope variance). `OCEAN_FILTER_N_MIN` and `OCEAN_FILTER_N_MAX` are the
 * paper's. The waves are copied: the spectrum may be destroyed afterwards.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite threshold, `OCEAN_STATUS_INVALID_ARGUMENT`
 * unless 0 < n_min < n_max <= 1e6, for more waves than the device's largest texture is wide,
 * or for a context other than the renderer's; `OCEAN_STATUS_GPU_FAILURE` for a device error.
 * On failure the renderer keeps its previous spectrum.
 */
OceanStatus ocean_renderer_set_spectrum(struct OceanRenderer *renderer,
                                        const struct OceanGpuContext *ctx,
                                        const struct OceanSpectrum *spectrum,
                                        double n_min,
                                        double n_max);
#endif

#if defined(OCEAN_GPU)
/**
 * Gives the renderer the Sun, the sky and the sea of `lighting`: renders its sky map at
 * `options->sky_map_size` with every mip level (as `ocean_lighting_sky_map_create`) and
 * uploads it, and keeps the Sun's and the sea's radiances. The lighting is copied: it may be
 * destroyed afterwards.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_ARGUMENT` for a context other than the renderer's or a radiance beyond
 * binary16's range (65504: scale the radiance unit down), `OCEAN_STATUS_GPU_FAILURE` for a
 * device error. On failure the renderer keeps its previous lighting.
 */
OceanStatus ocean_renderer_set_lighting(struct OceanRenderer *renderer,
                                        const struct OceanGpuContext *ctx,
                                        const struct OceanLighting *lighting);
#endif

#if defined(OCEAN_GPU)
/**
 * Renders the sea and the sky seen by `camera` at `time` (seconds) into a `width` x `height`
 * image on the GPU, waits for it and copies it into `out`.
 *
 * Format: `len` = width * height * 4 bytes exactly; rows from the top of the image, each
 * `width` pixels of R, G, B, A bytes from left to right, tightly packed (no row padding).
 * Colours are tone-mapped (1 - exp(-exposure * L)) and sRGB-encoded: display-ready bytes for
 * an `SRGB8_ALPHA8` texture or a plain image file. Alpha is 255. `camera` is an `OceanCamera`
 * above the sea (world space right-handed with y up, the sea at rest on y = 0), in any depth
 * convention (the image does not depend on it, but for the depth range the renderer folds it
 * into); its projection's aspect P11/P00 should be width / height for undistorted pixels.
 *
 * The sky is drawn where the sea is not (`options->draw_sky`); the grid covers the viewport
 * plus the margin. Each call allocates its targets and waits for the GPU: a one-off, not a
 * frame loop at full speed.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_EMPTY` if `width` or `height` is 0, `OCEAN_STATUS_LENGTH_MISMATCH` if `len`
 * is not width * height * 4, `OCEAN_STATUS_INVALID_ARGUMENT` if a side exceeds the device's
 * largest texture, the camera is out of its documented ranges or not above the sea
 * (eye y <= 0), the context is not the renderer's, or the renderer has no spectrum or no
 * lighting yet; `OCEAN_STATUS_LENGTH_OVERFLOW` if
 * width * height * 4 overflows; `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `time` or
 * camera member; `OCEAN_STATUS_INVALID_ARGUMENT` for a `time` whose phase leaves the domain
 * of `ocean_waves_evaluate` (|omega t| of the fastest wave above 1e15 rad);
 * `OCEAN_STATUS_GPU_FAILURE` for a device error. Nothing is written to `out` on failure.
 *
 * # Safety
 *
 * `camera` readable, and `out` point to `len`
 * writable bytes that no other thread touches during the call.
 */
OceanStatus ocean_renderer_render_rgba8(const struct OceanRenderer *renderer,
                                        const struct OceanGpuContext *ctx,
                                        const struct OceanCamera *camera,
                                        double time,
                                        uint32_t width,
                                        uint32_t height,
                                        uint8_t *out,
                                        size_t len);
#endif

/**
 * Stores the default Sun and sky in `*out`: a clear afternoon with the Sun 25 degrees above
 * the horizon towards -z, sun_direction = (0, sin 25deg, -cos 25deg), a slightly warm Sun of
 * irradiance (1, 0.96, 0.90), a blue zenith of radiance (0.025, 0.045, 0.09) and the CIE clear
 * sky (type 12).
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
 * then left unchanged.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_sky_params_default(struct OceanSkyParams *out);

/**
 * Stores the default water body in `*out`: albedo (10, 40, 120)/255 * 0.1 (deep blue open
 * ocean) and R = 0.02.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
 * then left unchanged.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_sea_params_default(struct OceanSeaParams *out);

/**
 * Validates the Sun, the sky and the sea and stores a new lighting in `*out`.
 *
 * It derives the sky's irradiance E_sky on the horizontal sea (by quadrature of the CIE
 * radiance over the upper hemisphere), the water's radiance
 * L_sea = albedo (E_sun sin(elevation) + E_sky) / pi (paper section 5.3) and the radiance
 * shown below the horizon (the sky's mean radiance E_sky/pi times Schlick's reflectance
 * averaged over a cosine-weighted hemisphere, R + (1 - R)/21, plus L_sea times the rest).
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite member (the message names it),
 * `OCEAN_STATUS_INVALID_ARGUMENT` for a member out of its documented range (a Sun direction
 * that is not a unit vector or lies below the horizon, a negative irradiance or radiance, an
 * albedo or R outside [0, 1], a CIE type outside [-1000, 1000] or giving negative radiance).
 * On failure `*out` is unchanged. Free the handle with `ocean_lighting_destroy`.
 *
 * # Safety
 *
 * `sky` and `sea` must point to readable structs and `out` to a writable pointer; none is
 * retained.
 */
OceanStatus ocean_lighting_create(const struct OceanSkyParams *sky,
                                  const struct OceanSeaParams *sea,
                                  struct OceanLighting **out);

/**
 * Frees a lighting. NULL does nothing; a handle of another kind or already destroyed frees nothing
 * and sets the last-error message (see the header's notes on handles). Sky maps made from it stay
 * valid.
 */
void ocean_lighting_destroy(struct OceanLighting *lighting);

/**
 * Stores the sky's irradiance on the horizontal sea, E_sky = integral of L_sky cos(theta)
 * over the upper hemisphere (the Sun's disc excluded), linear RGB, in `*out`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_lighting_sky_irradiance(const struct OceanLighting *lighting,
                                          struct OceanRgb *out);

/**
 * Stores the irradiance of the lighting's environment (the sky above the horizon without the
 * Sun's disc, the sea's below-horizon radiance below it) on every orientation in `*out`: the
 * ambient light of solids lit by the same sky as the sea (`OceanReliefScene::sky`). Within
 * 3.1 % of the upward irradiance of a brute-force integration for every normal on the default
 * sky and sea, the worst facing the horizon.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_lighting_irradiance(const struct OceanLighting *lighting,
                                      struct OceanIrradiance *out);

/**
 * Stores L_sea = albedo (E_sun sin(elevation) + E_sky) / pi, the diffuse radiance leaving the
 * water body (paper section 5.3), linear RGB, in `*out`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_lighting_sea_radiance(const struct OceanLighting *lighting, struct OceanRgb *out);

/**
 * Stores the radiance the environment shows at and below the horizon (paper section 6,
 * multiple reflections; see `ocean_lighting_create`), linear RGB, in `*out`: the value of the
 * sky map outside the horizon circle.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_lighting_below_horizon_radiance(const struct OceanLighting *lighting,
                                                  struct OceanRgb *out);

/**
 * Stores the Sun's radiance L_sun = E_sun / Omega_sun (Eq. 15), uniform over its disc, linear
 * RGB, in `*out`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_lighting_sun_radiance(const struct OceanLighting *lighting, struct OceanRgb *out);

/**
 * Stores the Sun's solid angle Omega_sun = 2 pi (1 - cos rho), steradians, with rho = 4.653e-3
 * rad its mean angular radius, in `*out`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_lighting_sun_solid_angle(const struct OceanLighting *lighting, double *out);

/**
 * Stores the environment's radiance towards the unit direction `dir` (world space, y up),
 * linear RGB, in `*out`: the CIE sky above the horizon (the Sun's disc excluded, as Eq. 15
 * handles it), the below-horizon radiance (`ocean_lighting_below_horizon_radiance`) at and
 * below it. This is what level 0 of a sky map samples, before its binary16 rounding.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite component of `dir`,
 * `OCEAN_STATUS_INVALID_ARGUMENT` if its length is not within 1e-6 of 1. `*out` is written only
 * on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_lighting_environment_radiance(const struct OceanLighting *lighting,
                                                struct OceanDVec3 dir,
                                                struct OceanRgb *out);

/**
 * The Ross BRDF (Eq. 13) with Schlick's Fresnel factor (Eq. 14), 1/steradian, stored in
 * `*out`:
 *
 * brdf = p(zeta_h) F(v.h) / (4 h_z^4 cos(theta_v) cos(theta_l) (1 + Lambda(a_v) + Lambda(a_l)))
 *
 * with h = normalize(v + l), zeta_h = -(h_x, h_y)/h_z, p the Gaussian slope density of Eq. 7,
 * Lambda(a) = (exp(-a^2) - a sqrt(pi) erfc(a)) / (2 a sqrt(pi)) (Eq. 8) and Smith's
 * a = d_z / sqrt(2 (sigma_x2 d_x^2 + sigma_y2 d_y^2)) (Eq. 9 with the tan^2 the normalisation of
 * Eq. 11 requires; the transcription's tan is a misprint). 0 when `v` or `l` is on or below
 * the horizon (z <= 0). Symmetric in `v` and `l`.
 *
 * - `v`, `l`: unit vectors towards the viewer and the light, **tangent frame** (x along the
 *   wind, y across it, z along the normal), lengths within 1e-6 of 1;
 * - `sigma_x2`, `sigma_y2`: slope variances along x and y, in [DBL_MIN, DBL_MAX] (a zero
 *   variance has no density);
 * - `r`: reflectance at normal incidence, in [0, 1] (water: `OCEAN_WATER_R`).
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite argument, `OCEAN_STATUS_INVALID_ARGUMENT` for
 * one out of its range. `*out` is written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_ross_brdf(struct OceanDVec3 v,
                            struct OceanDVec3 l,
                            double sigma_x2,
                            double sigma_y2,
                            double r,
                            double *out);

/**
 * The Sun's reflected radiance I_sun of Eq. 15, stored in `*out`:
 * `l_sun * omega_sun * brdf(v, l) * l_z` with `brdf` as in `ocean_ross_brdf` (the BRDF taken as
 * constant over the solar disc), in the unit of `l_sun`.
 *
 * To show the Sun as a disc on a flat sea rather than a point, raise the variances to at
 * least rho^2 / 16 (rho = 4.653e-3 rad, the Sun's angular radius) first, as `ocean_sea_color`
 * does.
 *
 * - `v`, `l`, `sigma_x2`, `sigma_y2`, `r`: as in `ocean_ross_brdf` (tangent frame);
 * - `l_sun`: the Sun's radiance, finite and >= 0;
 * - `omega_sun`: its solid angle, steradians, in [0, 2 pi].
 *
 * Returns as `ocean_ross_brdf`. `*out` is written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_sun_radiance(struct OceanDVec3 v,
                               struct OceanDVec3 l,
                               double sigma_x2,
                               double sigma_y2,
                               double l_sun,
                               double omega_sun,
                               double r,
                               double *out);

/**
 * Schlick's Fresnel factor, Eq. 14: F = r + (1 - r) (1 - c)^5 with c = `cos_theta` clamped to
 * [0, 1] (a back-facing cosine gives 1), stored in `*out`. F(1) = r, F(0) = 1.
 *
 * `cos_theta`: the cosine between the direction and the facet normal, finite; `r`: the
 * reflectance at normal incidence, in [0, 1].
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite argument, `OCEAN_STATUS_INVALID_ARGUMENT` for
 * `r` outside [0, 1]. `*out` is written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_schlick(double cos_theta, double r, double *out);

/**
 * The paper's fit of the effective Fresnel reflectance of rough water, Eq. 26, stored in
 * `*out`:
 *
 * F_bar = r + (1 - r) (1 - cos_theta_v)^(5 exp(-2.69 sigma_v)) / (1 + 22.7 sigma_v^1.5)
 *
 * equal to `ocean_schlick(cos_theta_v, r)` bit for bit at sigma_v = 0. Fitted for slope
 * deviations below 0.5.
 *
 * - `cos_theta_v`: cosine of the view's angle to the mean normal, in [0, 1];
 * - `sigma_v`: the slope **standard deviation** in the view's azimuth,
 *   sqrt(sigma_x2 cos^2 phi_v + sigma_y2 sin^2 phi_v) (Eq. 25, phi_v measured from the wind),
 *   finite and >= 0;
 * - `r`: reflectance at normal incidence, in [0, 1].
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite argument, `OCEAN_STATUS_INVALID_ARGUMENT` for
 * one out of its range. `*out` is written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_effective_fresnel_fit(double cos_theta_v, double sigma_v, double r, double *out);

/**
 * The effective Fresnel reflectance of Eq. 24 from its table, what the sea colour
 * (`ocean_sea_color`) and the GPU renderer use, stored in `*out`:
 *
 * F_bar = r + (1 - r) ((1 - cos_theta_v)^5 + D(cos_theta_v, sigma_v))
 *
 * with D the tabulated roughness correction (33 x 33 nodes over sqrt(cos_theta_v) and
 * sqrt(sigma_v), bilinear; sigma_v above 1 clamps to 1). Within about 0.02 of
 * `ocean_effective_fresnel_integral` for slope deviations below 0.5 (the fit: about 0.045), and
 * Schlick's value for sigma_v = 0. Arguments and statuses as `ocean_effective_fresnel_fit`.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_effective_fresnel_table(double cos_theta_v,
                                          double sigma_v,
                                          double r,
                                          double *out);

/**
 * The effective Fresnel reflectance of Eq. 24 by numerical integration (the reference Eq. 26
 * fits), stored in `*out`:
 *
 * F_bar(v) = r + (1 - r) integral of q^e_vn(zeta, v) (1 - v.f(zeta))^5 d^2 zeta
 *
 * over the visible facets (Eq. 10), by a deterministic Gauss-Legendre rule (accurate to about
 * 1e-9 for sigma_x, sigma_y <= 1). About 16 000 integrand evaluations per call: for per-pixel
 * use take `ocean_effective_fresnel_fit`.
 *
 * - `v`: unit vector towards the viewer, **tangent frame** (x along the wind, y across it, z
 *   along the normal), with v_z >= 0;
 * - `sigma_x2`, `sigma_y2`: slope variances, finite and >= 0 (both 0: Schlick's F(v_z));
 * - `r`: reflectance at normal incidence, in [0, 1].
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite argument, `OCEAN_STATUS_INVALID_ARGUMENT` for
 * one out of its range (v not a unit vector, v_z < 0, ...). `*out` is written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_effective_fresnel_integral(struct OceanDVec3 v,
                                             double sigma_x2,
                                             double sigma_y2,
                                             double r,
                                             double *out);

/**
 * Exponential tone mapping, 1 - exp(-exposure * L) per channel (negative radiance maps to 0,
 * the result is in [0, 1]), stored in `*out` as linear values; encode them for display with
 * `ocean_linear_to_srgb`. The GPU renderer uses the same curve.
 *
 * `radiance`: linear RGB, every channel finite; `exposure`: finite and >= 0 (the default is
 * `OCEAN_DEFAULT_EXPOSURE`).
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite argument, `OCEAN_STATUS_INVALID_ARGUMENT` for
 * a negative exposure. `*out` is written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_tone_map(struct OceanRgb radiance, double exposure, struct OceanRgb *out);

/**
 * The sRGB transfer function (IEC 61966-2-1) from a linear value to an encoded one, both in
 * [0, 1] (the input is clamped to [0, 1] first), stored in `*out`: 12.92 c up to 0.0031308,
 * 1.055 c^(1/2.4) - 0.055 above.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `linear`. `*out` is written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_linear_to_srgb(double linear, double *out);

/**
 * The sea's colour for one pixel: Algorithm 5.1 (paper Fig. 9), the three terms of the
 * radiance towards the viewer, stored in `*out`.
 *
 * - `v`: unit vector from the surface point towards the viewer, world space (y up);
 * - `n`: the filtered unit normal of Eq. 3, world space (a normal facing away from `v` is
 *   reflected about the plane normal to `v`, paper section 3.2);
 * - `wind`: the horizontal wind direction (x, z), any finite non-zero length; the tangent
 *   frame is t_x = the wind projected on the surface, t_y = n x t_x (for n = +y and wind +x,
 *   t_y = -z);
 * - `sigma_x2`, `sigma_y2`: the slope variances of the unresolved waves along t_x and t_y
 *   (Eq. 4, from `ocean_spectrum_slope_variance`), finite and >= 0 (0: a mirror);
 * - `sky_map`: a map made from this `lighting` (any size).
 *
 * The Sun's term uses the variances raised to at least rho^2/16 (the solar disc, rho = 4.653e-3
 * rad), the sky's term the effective Fresnel fit F_bar of Eq. 26 times the sky map filtered
 * over the slopes' Gaussian (Eq. 27, a 9-sample trilinear rule), the sea's term
 * L_sea (1 - F_bar) (Eq. 28). Deterministic: the same bits on every platform.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite input, `OCEAN_STATUS_INVALID_ARGUMENT` if `v`
 * or `n` is not a unit vector (length within 1e-6 of 1), the wind is zero, a variance is
 * negative, or `sky_map` was made from a lighting with other parameters. `*out` is written only
 * on success.
 *
 * # Safety
 *
 * `out` writable.
 */
OceanStatus ocean_sea_color(const struct OceanLighting *lighting,
                            const struct OceanSkyMap *sky_map,
                            struct OceanDVec3 v,
                            struct OceanDVec3 n,
                            struct OceanDVec2 wind,
                            double sigma_x2,
                            double sigma_y2,
                            struct OceanSeaLight *out);

/**
 * `ocean_sea_color` for `n` pixels: `out[i]` receives the colour of `inputs[i]`, bit-identical
 * to `ocean_sea_color` with the same arguments.
 *
 * Every input is validated before anything is written: on failure the message names the
 * first bad one (`inputs[i].member`) and `out` is untouched.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (8-byte
 * alignment), `OCEAN_STATUS_EMPTY` if `n` is 0, `OCEAN_STATUS_LENGTH_OVERFLOW` if
 * `n * sizeof(OceanSeaColorInput)` exceeds `PTRDIFF_MAX`, `OCEAN_STATUS_INVALID_ARGUMENT` if the
 * two arrays overlap, and the statuses of `ocean_sea_color` for a bad input.
 *
 * # Safety
 *
 * `inputs` point to `n` readable
 * `OceanSeaColorInput`s and `out` to `n` writable `OceanSeaLight`s, none modified by another
 * thread during the call.
 */
OceanStatus ocean_sea_color_batch(const struct OceanLighting *lighting,
                                  const struct OceanSkyMap *sky_map,
                                  const struct OceanSeaColorInput *inputs,
                                  size_t n,
                                  struct OceanSeaLight *out);

/**
 * Renders the sky map of `lighting`, `size` x `size` texels at level 0, and stores a new
 * handle in `*out`.
 *
 * Texel (i, j) of level 0 (row-major: element j*size + i) holds the environment's radiance
 * (`ocean_lighting_environment_radiance`) towards the direction whose stereographic projection
 * is u = (2 t - 1) E, with t = ((i + 0.5)/size, (j + 0.5)/size) and E = `OCEAN_SKY_MAP_EXTENT`:
 * the direction r = (2 u_x, 1 - |u|^2, 2 u_y) / (1 + |u|^2) (so u = (r_x, r_z)/(1 + r_y); the
 * zenith is at the centre, the horizon on the circle |u| = 1), and the below-horizon radiance
 * outside that circle. Each coarser level is the 2x2 mean of the one above, down to 1x1. Every
 * channel is rounded to binary16 (the precision of the GPU's `rgba16float` texture), stored as
 * float; alpha is 1.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_ARGUMENT` if `size` is not a power of two in
 * [`OCEAN_SKY_MAP_MIN_SIZE`, `OCEAN_SKY_MAP_MAX_SIZE`] or a radiance exceeds binary16's range
 * (65504: scale the radiance unit down). On failure `*out` is unchanged. Free the map with
 * `ocean_sky_map_destroy`.
 *
 * # Safety
 *
 * `out` must point to a writable pointer.
 */
OceanStatus ocean_lighting_sky_map_create(const struct OceanLighting *lighting,
                                          uint32_t size,
                                          struct OceanSkyMap **out);

/**
 * Frees a sky map. NULL does nothing; a handle of another kind or already destroyed frees nothing
 * and sets the last-error message (see the header's notes on handles).
 */
void ocean_sky_map_destroy(struct OceanSkyMap *sky_map);

/**
 * Stores the number of mip levels of the map, log2(size) + 1, in `*out_count`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out_count`
 * is written only on success.
 *
 * # Safety
 *
 * `out_count` must be writable.
 */
OceanStatus ocean_sky_map_level_count(const struct OceanSkyMap *sky_map, uint32_t *out_count);

/**
 * Stores the side of mip `level` in texels, max(size >> level, 1), in `*out_size`: the level
 * holds out_size * out_size RGBA texels.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_ARGUMENT` if `level` >= the level count. `*out_size` is written only on
 * success.
 *
 * # Safety
 *
 * `out_size` must be writable.
 */
OceanStatus ocean_sky_map_level_info(const struct OceanSkyMap *sky_map,
                                     uint32_t level,
                                     uint32_t *out_size);

/**
 * Copies mip `level` into `rgba`: side * side texels (side from `ocean_sky_map_level_info`),
 * row-major from texture coordinate (0, 0) (texel (i, j) at element j*side + i), 4 floats
 * each (R, G, B, A = 1), the layout an `RGBA32F` or (after conversion) `RGBA16F` texture
 * upload expects. `len` counts floats and must be exactly side * side * 4.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (4-byte
 * alignment for `rgba`), `OCEAN_STATUS_INVALID_ARGUMENT` if `level` does not exist,
 * `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not side * side * 4,
 * `OCEAN_STATUS_LENGTH_OVERFLOW` if `len * sizeof(float)` exceeds
 * `PTRDIFF_MAX`. Nothing is written on failure.
 *
 * # Safety
 *
 * `rgba` must point to `len` writable floats that no other
 * thread touches during the call.
 */
OceanStatus ocean_sky_map_copy_level(const struct OceanSkyMap *sky_map,
                                     uint32_t level,
                                     float *rgba,
                                     size_t len);

/**
 * Stores the default spectrum parameters in `*out`: wind 10 m/s along +x, 60 waves from
 * 0.02 m to 30 m, steepness at most 0.5, seed 0.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
 * then left unchanged.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_spectrum_params_default(struct OceanSpectrumParams *out);

/**
 * Samples a spectrum and stores a new handle in `*out` (see `OceanSpectrumParams` for the
 * sampling).
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_EMPTY` if `wave_count` is 0, `OCEAN_STATUS_NON_FINITE` for a NaN or infinite
 * member (the message names it), `OCEAN_STATUS_INVALID_ARGUMENT` for a member out of its
 * documented range (a zero wind direction included). On failure `*out` is unchanged. Free the
 * handle with `ocean_spectrum_destroy`.
 *
 * # Safety
 *
 * `params` must point to a readable `OceanSpectrumParams` and `out` to a writable pointer;
 * neither is retained.
 */
OceanStatus ocean_spectrum_create(const struct OceanSpectrumParams *params,
                                  struct OceanSpectrum **out);

/**
 * Frees a spectrum. NULL does nothing; a handle of another kind or already destroyed frees nothing
 * and sets the last-error message (see the header's notes on handles).
 */
void ocean_spectrum_destroy(struct OceanSpectrum *spectrum);

/**
 * Stores the number of waves (`params->wave_count`) in `*out`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_spectrum_wave_count(const struct OceanSpectrum *spectrum, size_t *out);

/**
 * Copies the waves into `out[0..n]`, shortest first, as `OceanWaveDesc`s that
 * `ocean_waves_create` accepts as they are: unit directions, phases in [0, 2 pi), deep water
 * (`depth` = `INFINITY`). `n` must equal the wave count exactly.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (8-byte
 * alignment), `OCEAN_STATUS_LENGTH_MISMATCH` if `n` is not the wave count,
 * `OCEAN_STATUS_LENGTH_OVERFLOW` if `n * sizeof(OceanWaveDesc)` exceeds `PTRDIFF_MAX`. Nothing
 * is written on failure.
 *
 * # Safety
 *
 * `out` must point to `n` writable `OceanWaveDesc`s that no
 * other thread touches during the call.
 */
OceanStatus ocean_spectrum_waves(const struct OceanSpectrum *spectrum,
                                 struct OceanWaveDesc *out,
                                 size_t n);

/**
 * Stores the unit wind direction (x, z) in `*out`: the x axis of the slope variances.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_spectrum_wind_direction(const struct OceanSpectrum *spectrum,
                                          struct OceanDVec2 *out);

/**
 * Stores the number of waves whose amplitude `params->max_steepness` clamped in `*out`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_spectrum_clamped_count(const struct OceanSpectrum *spectrum, size_t *out);

/**
 * Stores the sum of the amplitudes, metres, in `*out`: the largest height (and horizontal
 * displacement) the sum of the waves can reach, for bounds and culling margins.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_spectrum_max_amplitude(const struct OceanSpectrum *spectrum, double *out);

/**
 * Stores the steepness sum, sum of k*A (dimensionless), in `*out`: below 1 the surface cannot
 * fold over itself, whatever the phases.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_spectrum_steepness_sum(const struct OceanSpectrum *spectrum, double *out);

/**
 * Stores the mean height of the surface, metres (<= 0), in `*out`: a trochoid's mean height
 * over x is -k A^2 / 2 (its crests are sharper than its troughs), so the sea's mean level sits
 * sum(k A^2 / 2) below y = 0.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_spectrum_mean_height_shift(const struct OceanSpectrum *spectrum, double *out);

/**
 * Stores the variance of the height about its mean, m^2, in `*out`:
 * sum(A^2 / 2 - (k A^2 / 2)^2) over the (independent) waves.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_spectrum_height_variance(const struct OceanSpectrum *spectrum, double *out);

/**
 * Stores the slope variance of all the waves (Eq. 4 with w_r = 1) in `*out`: each wave of
 * steepness kA adds 1 - sqrt(1 - k^2 A^2) (Appendix A), shared between the axes as
 * cos^2 and sin^2 of its angle to the wind.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_spectrum_total_slope_variance(const struct OceanSpectrum *spectrum,
                                                struct OceanSlopeVariance *out);

/**
 * Stores the slope variance of the waves a pixel does not resolve (Eq. 4) in `*out`.
 *
 * Eq. 4 summed over every wave: a wave of wavenumber k, amplitude A and angle theta to the
 * wind adds (cos^2 theta, sin^2 theta) (1 - sqrt(1 - k^2 w_r^2 A^2)): the weight
 * w_r = 1 - w(n_min, n_max, lambda / l) scales the wave's amplitude inside the square root,
 * not its variance. l = `pixel_footprint` (metres, the pixel's size on the sea, from
 * `ocean_pixel_footprint`) and w(a, b, x) = 3 t^2 - 2 t^3, t = clamp((x - a)/(b - a), 0, 1):
 * waves shorter than n_min pixels are wholly in the BRDF, waves longer than n_max pixels
 * wholly in the normals. A footprint of 0 resolves every wave: the result is exactly (0, 0)
 * (each term is summed, not the total minus the resolved part, which leaves rounding). The
 * paper's thresholds are `OCEAN_FILTER_N_MIN` and `OCEAN_FILTER_N_MAX`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite argument, `OCEAN_STATUS_INVALID_ARGUMENT`
 * unless 0 < n_min < n_max <= 1e6 and `pixel_footprint` >= 0. `*out` is written only on
 * success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_spectrum_slope_variance(const struct OceanSpectrum *spectrum,
                                          double n_min,
                                          double n_max,
                                          double pixel_footprint,
                                          struct OceanSlopeVariance *out);

/**
 * Stores the footprint of a pixel on the sea at rest (y = 0), metres, in `*out`: the `l` of
 * Eq. 3 and 4 (pass it to `ocean_spectrum_slope_variance`).
 *
 * The pixel at (`px`, `py`) (pixel units of a `width` x `height` viewport, origin at the
 * top-left corner, y down, pixel centres at half-integers: the centre of the top-left pixel is
 * (0.5, 0.5)) projects on the sea as an ellipse elongated towards the viewer; the footprint is
 * its longer axis: the larger of the distances between the sea hits of the rays through the
 * pixel's opposite edge midpoints, (px +- 0.5, py) and (px, py +- 0.5). Rays that go up, run
 * along the horizon or would meet the sea beyond `max_distance` metres (measured along the
 * ray from the near plane) are stopped there and projected onto the sea, so pixels at and
 * above the horizon get a large but finite footprint.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_EMPTY` if `width` or `height` is 0, `OCEAN_STATUS_NON_FINITE` for a NaN or
 * infinite argument or camera member (the message names it), `OCEAN_STATUS_INVALID_ARGUMENT`
 * for a camera out of its documented ranges (see `OceanCamera`), `max_distance` outside
 * (0, 1e12], or a
 * pixel whose rays do not start above the sea (the camera at or below y = 0). `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `camera` must point to a readable `OceanCamera` and `out` be writable.
 */
OceanStatus ocean_pixel_footprint(const struct OceanCamera *camera,
                                  uint32_t width,
                                  uint32_t height,
                                  double px,
                                  double py,
                                  double max_distance,
                                  double *out);

#if defined(OCEAN_GPU)
/**
 * Stores the default draw parameters in `*out`: the paper's filter (`OCEAN_FILTER_N_MIN`,
 * `OCEAN_FILTER_N_MAX`), 8-pixel grid cells, a 10 % margin, a 50 km distance cap, exposure
 * `OCEAN_DEFAULT_EXPOSURE`, a 512 x 512 sky map, sRGB encoding by the shader.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
 * then left unchanged.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_surface_draw_params_default(struct OceanSurfaceDrawParams *out);
#endif

#if defined(OCEAN_GPU)
/**
 * Writes the uniform block of the exported `ocean` draw shader for one frame of `width` x
 * `height` pixels seen by `camera` at `time` seconds into `out` (the
 * `OCEAN_SURFACE_UNIFORMS_SIZE` bytes of `Frame`, std140, in the machine's byte order: upload
 * them as they are with `glBufferSubData`): the spectrum's waves filtered by `params->n_min`
 * and `n_max` (their texture: `ocean_surface_wave_texels` for the same camera and time), the
 * Sun, sky and sea of `lighting`, and, when `mesh` is not NULL, the water mesh that `mesh_vs`
 * draws (a wave train box scene's grid: pass the `OceanWaterGridDesc` it was created with).
 * `camera` is an `OceanCamera` above the sea (eye y > 0); its projection's aspect P11/P00
 * should be width / height. Positions in the block are relative to the camera's eye
 * (subtracted here in double precision, with the waves' phases reduced per frame), so a sea
 * far from the world origin does not jitter.
 *
 * To draw a mesh with its ambient light obscured (`ocean_shader_export` of `ocean`, GLSL 3.30
 * core; assign bindings by the names in its binding table: `glUniformBlockBinding` for the
 * blocks `Frame_block_0Vertex` and `Frame_block_0Fragment`, `glUniform1i` texture units for
 * the samplers `_group_0_binding_<b>_vs` / `_fs`):
 * - binding 0: this block, a uniform buffer;
 * - binding 1: the wave texture, `GL_RGBA32F`, wave count x `OCEAN_WAVE_TEXTURE_ROWS`, one
 *   level, the texels of `ocean_surface_wave_texels` (refreshed every frame);
 * - bindings 2 and 3: the sky map, `GL_RGBA16F` (or `GL_RGBA32F`), `params->sky_map_size`
 *   square with every level of `ocean_sky_map_copy_level`, sampled with linear min, mag and
 *   mip filtering and clamp-to-edge (the sampler of binding 3 is folded into binding 2's);
 * - binding 6: the effective Fresnel table, `GL_R32F`, `OCEAN_FRESNEL_TABLE_SIZE` square, the
 *   texels of `ocean_surface_fresnel_texels`;
 * - bindings 7 and 8: local waves, never read when none are set (as here): any complete
 *   `GL_RG32F` 2D array texture and `GL_RGBA32F` 2D texture;
 * - pass 1, `mesh_vs` + `mesh_fs`: attribute 0 the positions and attribute 1 the normals that
 *   `ocean_wtb_scene_evaluate` writes (3 floats each, point (i, j) at vertex j * nx + i), drawn as
 *   indexed `GL_TRIANGLES` over the grid's cells, depth test `GL_LESS` (`GL_GREATER`
 *   reversed) with writes, no culling, into two colour targets of linear radiance: location 0
 *   the Sun's reflection, location 1 the sky's reflection plus the refracted light, both
 *   `GL_RGBA32F` cleared to 0 (alpha 1 marks the pixels the mesh covers);
 * - an ambient obscurance over pass 1's depth (the exported `sao_*` shaders,
 *   `ocean_sao_uniforms`; the depth buffer holds window depth, `OCEAN_SAO_DEPTH_WINDOW`), with
 *   no guard band, so that its output covers the viewport pixel for pixel;
 * - pass 2, `sky_vs` + `compose_fs`: 3 vertices, no vertex buffer, no depth test, with
 *   bindings 9 and 10 the two targets of pass 1 and binding 11 the obscurance (`GL_R32F`, 1
 *   unoccluded): each pixel becomes the tone-mapped Sun term plus the obscured ambient terms
 *   where the mesh drew, the sky elsewhere.
 *
 * The projected grid (`ocean_vs` + `ocean_fs`, the `OceanRenderer`'s sea) and the sky alone
 * (`sky_vs` + `sky_fs`) draw from the same block. The exported GLSL's clip space is OpenGL's
 * with y flipped (naga's convention, as wgpu's GL backend): image row 0 is the top row, so an
 * image read back with `glReadPixels` is upright, and a frame shown in a window is blitted
 * with its rows reversed.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (`mesh` may be
 * NULL), `OCEAN_STATUS_EMPTY` if `width` or `height` is 0 or the mesh has a side of 0,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `time`, parameter, camera or mesh member,
 * `OCEAN_STATUS_INVALID_ARGUMENT` for a parameter, camera or mesh outside its documented
 * ranges (the message names it) or a camera not above the sea,
 * `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not `OCEAN_SURFACE_UNIFORMS_SIZE`,
 * `OCEAN_STATUS_LENGTH_OVERFLOW` if `len` exceeds `PTRDIFF_MAX`. A `time` whose phase leaves
 * the domain of `ocean_waves_evaluate` (|omega t| of the fastest wave above 1e15 rad) is
 * `OCEAN_STATUS_INVALID_ARGUMENT`.
 *
 * # Safety
 *
 * `camera`, `params` and `mesh` (unless NULL) must be readable, and `out` point to `len`
 * writable bytes that no other thread touches during the call.
 */
OceanStatus ocean_surface_uniforms(const struct OceanCamera *camera,
                                   const struct OceanSpectrum *spectrum,
                                   const struct OceanLighting *lighting,
                                   const struct OceanSurfaceDrawParams *params,
                                   const struct OceanWaterGridDesc *mesh,
                                   double time,
                                   uint32_t width,
                                   uint32_t height,
                                   uint8_t *out,
                                   size_t len);
#endif

#if defined(OCEAN_GPU)
/**
 * Writes the wave texture of the exported `ocean` shader (binding 1) for one frame seen by
 * `camera` at `time` seconds into `out`: `OCEAN_WAVE_TEXTURE_ROWS` rows of wave count
 * (`ocean_spectrum_wave_count`) RGBA float texels, row 0 first, one column per wave, longest
 * first; `len` counts floats and must be exactly 12 * wave count. Upload it as a `GL_RGBA32F`
 * texture of wave count x 3 texels every frame, with the block of `ocean_surface_uniforms` for
 * the same camera and time.
 *
 * Row 0 holds (wavelength, k_x, k_z, phase at the eye's horizontal position o, k.o - omega t +
 * phi reduced modulo 2 pi in double precision); row 1 (A, A k_x/|k|, A k_z/|k|, 0); row 2
 * (k A, the squared cosine of the wave's angle to the wind, and the slope variances along and
 * across the wind of this wave and every shorter one, Eq. 4 with w_r = 1, summed in double
 * precision). Only row 0 changes between frames. The texels do not depend on the filter.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (4-byte
 * alignment for `out`), `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `time` or camera
 * member, `OCEAN_STATUS_INVALID_ARGUMENT` for a camera outside its documented ranges,
 * `OCEAN_STATUS_LENGTH_MISMATCH` for a `len` other than 12 * wave count,
 * `OCEAN_STATUS_LENGTH_OVERFLOW` if `len * sizeof(float)`
 * exceeds `PTRDIFF_MAX`. A `time` whose phase
 * leaves the domain of `ocean_waves_evaluate` (|omega t| of the fastest wave above 1e15 rad)
 * is `OCEAN_STATUS_INVALID_ARGUMENT`. Nothing is written on failure.
 *
 * # Safety
 *
 * `camera` must be readable, `spectrum` a live handle, and `out` point to `len` writable
 * floats that no other thread touches during the call.
 */
OceanStatus ocean_surface_wave_texels(const struct OceanCamera *camera,
                                      const struct OceanSpectrum *spectrum,
                                      double time,
                                      float *out,
                                      size_t len);
#endif

#if defined(OCEAN_GPU)
/**
 * Writes the effective Fresnel table texture of the exported `ocean` shader (binding 6) into
 * `out`: `OCEAN_FRESNEL_TABLE_SIZE` rows of as many floats, `len` exactly 33 * 33. Element
 * 33 i + j (texel (j, i): column j, row i) holds the roughness correction
 * D = M - (1 - cos theta_v)^5 of Eq. 24 at cos theta_v = (i/32)^2 and sigma_v = (j/32)^2, the
 * table behind `ocean_effective_fresnel_table`, rounded to float. Upload it as a `GL_R32F`
 * texture of 33 x 33 texels once.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
 * `OCEAN_STATUS_LENGTH_MISMATCH` for a `len` other than 33 * 33. Nothing is written on
 * failure.
 *
 * # Safety
 *
 * `out` must point to `len` writable floats that no other thread touches during the call.
 */
OceanStatus ocean_surface_fresnel_texels(float *out, size_t len);
#endif

/**
 * Creates a height map from `len` = width * height floats, row-major (texel (i, j) at element
 * j * width + i), each a **height** (1 = the polygon surface, 0 = the bottom), and stores the
 * handle in `*out`.
 *
 * `edge`: `OCEAN_RELIEF_EDGE_WRAP` or `_CLAMP`. `range`: `OCEAN_RELIEF_RANGE_REFUSE` (heights
 * must lie in [0, 1]) or `OCEAN_RELIEF_RANGE_NORMALIZE` (the smallest becomes 0, the largest 1).
 * The heights are copied.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (4-byte
 * alignment for `heights`), `OCEAN_STATUS_EMPTY` if `width` or `height` is 0,
 * `OCEAN_STATUS_INVALID_ARGUMENT` if a side is outside 2 to `OCEAN_RELIEF_MAX_SIDE`, the map is
 * not square, `len` is not width * height, `edge` or `range` is unknown, or (with `_REFUSE`) a
 * height lies outside [0, 1], `OCEAN_STATUS_NON_FINITE` for a NaN or infinite height (the
 * message names the first bad texel). `*out` is written only on success.
 *
 * # Safety
 *
 * `heights` must point to `len` readable floats and `out` to a writable pointer.
 */
OceanStatus ocean_relief_map_create_f32(const float *heights,
                                        size_t len,
                                        uint32_t width,
                                        uint32_t height,
                                        uint32_t edge,
                                        uint32_t range,
                                        struct OceanReliefMap **out);

/**
 * Creates a height map from `len` = width * height 8-bit heights (height v / 255, depth
 * (255 - v) / 255), row-major, and stores the handle in `*out`. Statuses as
 * `ocean_relief_map_create_f32` (every 8-bit value is in range).
 *
 * # Safety
 *
 * `heights` must point to `len` readable bytes and `out` to a writable pointer.
 */
OceanStatus ocean_relief_map_create_u8(const uint8_t *heights,
                                       size_t len,
                                       uint32_t width,
                                       uint32_t height,
                                       uint32_t edge,
                                       struct OceanReliefMap **out);

/**
 * Creates a height map from `len` = width * height 16-bit heights (height v / 65535, depth
 * (65535 - v) / 65535), row-major, and stores the handle in `*out`. Statuses as
 * `ocean_relief_map_create_f32` (2-byte alignment for `heights`).
 *
 * # Safety
 *
 * `heights` must point to `len` readable `uint16_t` and `out` to a writable pointer.
 */
OceanStatus ocean_relief_map_create_u16(const uint16_t *heights,
                                        size_t len,
                                        uint32_t width,
                                        uint32_t height,
                                        uint32_t edge,
                                        struct OceanReliefMap **out);

/**
 * Frees a height map. NULL does nothing; a handle of another kind or already destroyed frees
 * nothing and sets the last-error message (see the header's notes on handles).
 */
void ocean_relief_map_destroy(struct OceanReliefMap *map);

/**
 * Stores the side N of the map, texels, in `*out_size`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out_size`
 * is written only on success.
 *
 * # Safety
 *
 * `out_size` must be writable.
 */
OceanStatus ocean_relief_map_size(const struct OceanReliefMap *map, uint32_t *out_size);

/**
 * Copies the map's depths (1 - height, after normalisation if asked for; in [0, 1]) into
 * `depths`: `len` = N * N floats, row-major. These are the depths the cones are valid for:
 * upload them as the depth channel of the relief texture.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not N * N. Nothing is written on failure.
 *
 * # Safety
 *
 * `depths` must point to `len` writable floats that no other thread
 * touches during the call.
 */
OceanStatus ocean_relief_map_depths(const struct OceanReliefMap *map, float *depths, size_t len);

/**
 * Computes the tangent-space normal map of `map` for a relief `depth` texel widths deep (the
 * full depth range spans that many texel widths) by central differences, and stores it in
 * `xyz`: `len` = 3 N * N floats, row-major, (x, y, z) per texel, unit length, z out of the
 * polygon, x along the texture's u, y along v; neighbours follow the map's edge mode.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `depth`, `OCEAN_STATUS_INVALID_ARGUMENT` if
 * `depth` is outside [0, 1e6], `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not 3 N * N.
 * Nothing is written on failure.
 *
 * # Safety
 *
 * `xyz` must point to `len` writable floats that no other thread
 * touches during the call.
 */
OceanStatus ocean_relief_normals(const struct OceanReliefMap *map,
                                 float depth,
                                 float *xyz,
                                 size_t len);

/**
 * Stores the default cone parameters in `*out`: relaxed cones, capped at 1.0 (the book's).
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
 * then left unchanged.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_relief_cone_params_default(struct OceanReliefConeParams *out);

/**
 * Generates the cone map of `map` (see `OceanReliefConeParams`) and stores a handle that holds
 * it and a copy of the map in `*out`: what `ocean_relief_trace` and `ocean_relief_shadow` read.
 *
 * Every texel gets three channels, each rounded down to float and capped at
 * `params->max_ratio`: the cone ratio c (texture widths per unit depth, the book's cone map),
 * the clearance D (texture widths) and the near cap E (per unit depth); a ray h above the
 * surface may use the cone max(c, min(D/h, E)). The cones are valid for the bilinear surface
 * of the map's depths, read bilinearly or nearest. The result is bit-identical to
 * `ocean_relief::ConeMap::generate` on every thread count, with or without `progress`.
 *
 * `progress` (may be NULL) is called as `OceanReliefProgress` describes, with `user`; a nonzero
 * return cancels. Rows of the map are computed on all the threads of the library's pool.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `max_ratio`, `OCEAN_STATUS_INVALID_ARGUMENT`
 * for an unknown kind or a `max_ratio` outside (0, `OCEAN_RELIEF_MAX_RATIO_LIMIT`],
 * `OCEAN_STATUS_CANCELLED` when the callback returned nonzero (the arguments are checked before
 * the first call). `*out` is written only on success.
 *
 * # Safety
 *
 * `params` readable, `out` writable; `progress`, if not NULL,
 * must be safe to call with `user` from this thread.
 */
OceanStatus ocean_relief_cones_create(const struct OceanReliefMap *map,
                                      const struct OceanReliefConeParams *params,
                                      OceanReliefProgress progress,
                                      void *user,
                                      struct OceanReliefCones **out);

/**
 * Frees a cone map. NULL does nothing; a handle of another kind or already destroyed frees nothing
 * and sets the last-error message (see the header's notes on handles).
 */
void ocean_relief_cones_destroy(struct OceanReliefCones *cones);

/**
 * Stores the side N of the cone map (that of its height map), texels, in `*out_size`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out_size`
 * is written only on success.
 *
 * # Safety
 *
 * `out_size` must be writable.
 */
OceanStatus ocean_relief_cones_size(const struct OceanReliefCones *cones, uint32_t *out_size);

/**
 * Copies the relief texture into `rgba`: `len` = 4 N * N floats, row-major, `[depth, c, D, E]`
 * per texel (the depth of the map and the three cone channels), the layout of an `RGBA32F`
 * texture and exactly what the CPU tracers read.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not 4 N * N. Nothing is written on failure.
 *
 * # Safety
 *
 * `rgba` must point to `len` writable floats that no other thread
 * touches during the call.
 */
OceanStatus ocean_relief_cones_texels(const struct OceanReliefCones *cones,
                                      float *rgba,
                                      size_t len);

/**
 * Encodes the three cone channels for storage and copies them into `out`: `len` = 3 N * N
 * elements of the encoding's type (`uint8_t` for `OCEAN_RELIEF_ENCODING_UNORM8` and
 * `_UNORM8_SQRT`, `uint16_t` binary16 bit patterns for `_F16`, `float` for `_F32`), row-major,
 * `[c, D, E]` per texel. Every value is rounded **down** (a stored cone is never wider than
 * the exact one, so it stays valid); the 8-bit encodings clamp at 1.0. The depth channel is
 * not included: take it from `ocean_relief_map_depths` (the cones are valid for those depths).
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (aligned for
 * the element type), `OCEAN_STATUS_INVALID_ARGUMENT` for an unknown encoding,
 * `OCEAN_STATUS_LENGTH_MISMATCH` for a `len` that is not 3 N * N. Nothing is written on failure.
 *
 * # Safety
 *
 * `out` must point to `len` writable elements of the encoding's
 * type that no other thread touches during the call.
 */
OceanStatus ocean_relief_cones_encode(const struct OceanReliefCones *cones,
                                      uint32_t encoding,
                                      void *out,
                                      size_t len);

/**
 * Stores in `*out` a new handle whose cones are those of `cones` after a round trip through
 * `encoding` (each channel encoded, rounding down, and decoded): what a tracer reading the
 * stored texture sees. Trace it to measure what a storage format costs.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_ARGUMENT` for an unknown encoding. `*out` is written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_relief_cones_quantize(const struct OceanReliefCones *cones,
                                        uint32_t encoding,
                                        struct OceanReliefCones **out);

/**
 * Generates the cone map of `map` straight into `rgba` (no handle): `len` = 4 N * N floats,
 * `[depth, c, D, E]` per texel, as `ocean_relief_cones_texels` writes them. Arguments,
 * callback and statuses as `ocean_relief_cones_create`, with `OCEAN_STATUS_LENGTH_MISMATCH`
 * for a `len` that is not 4 N * N (checked before any work). `rgba` is written only on
 * success, and then wholly.
 *
 * # Safety
 *
 * `params` readable, `rgba` point to `len` writable floats that
 * no other thread touches during the call; `progress`, if not NULL, must be safe to call with
 * `user` from this thread.
 */
OceanStatus ocean_relief_generate_texels(const struct OceanReliefMap *map,
                                         const struct OceanReliefConeParams *params,
                                         OceanReliefProgress progress,
                                         void *user,
                                         float *rgba,
                                         size_t len);

/**
 * Generates the cone map of `map` and encodes its three channels straight into `out` (no
 * handle): `len` = 3 N * N elements of the encoding's type, `[c, D, E]` per texel, as
 * `ocean_relief_cones_encode` writes them. Arguments, callback and statuses as
 * `ocean_relief_cones_create` and `ocean_relief_cones_encode` (the encoding, the pointer and
 * `len` are checked before any work). `out` is written only on success, and then wholly.
 *
 * # Safety
 *
 * `params` readable, `out` point to `len` writable elements of
 * the encoding's type that no other thread touches during the call; `progress`, if not NULL,
 * must be safe to call with `user` from this thread.
 */
OceanStatus ocean_relief_generate_encoded(const struct OceanReliefMap *map,
                                          const struct OceanReliefConeParams *params,
                                          OceanReliefProgress progress,
                                          void *user,
                                          uint32_t encoding,
                                          void *out,
                                          size_t len);

#if defined(OCEAN_GPU)
/**
 * Stores the default scene in `*out`: a unit quad in the xz plane facing +y (u along +x, v
 * along -z), all of it drawn, one tile, 0.1 deep; relaxed cone stepping with 15 cone steps and 6 bisections of
 * the last step; self-shadowing with a bias of 0.02; a white light from (1, 2, 1), grey albedo
 * 0.8, ambient 0.2, no sky.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
 * then left unchanged.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_relief_scene_default(struct OceanReliefScene *out);
#endif

#if defined(OCEAN_GPU)
/**
 * Writes the uniform block of the exported `relief` draw shader for one draw of `scene` seen
 * by `camera` into `out` (the `OCEAN_RELIEF_UNIFORMS_SIZE` bytes of `Relief`, std140, in the
 * machine's byte order: upload them as they are with `glBufferSubData`), for a relief texture
 * of side `size` (2 to `OCEAN_RELIEF_MAX_SIDE`), edge mode `edge` (`OCEAN_RELIEF_EDGE_WRAP` or
 * `_CLAMP`, as the cones were generated) and `levels` mip levels (1 to log2 `size` for a
 * power-of-two side, else 1; see binding 1 below). With `srgb_encode` = 1
 * the shader writes sRGB-encoded colour (for a linear `GL_RGBA8` target); with 0 it writes
 * linear colour (for an sRGB target with `GL_FRAMEBUFFER_SRGB`).
 *
 * Positions in the block are relative to the camera's eye (the subtraction happens here, in
 * double precision), so quads far from the world origin do not jitter.
 *
 * To draw (`ocean_shader_export` of `relief`, entry points `relief_vs` and `relief_fs`, with
 * its binding table):
 * - binding 0: this block, a uniform buffer;
 * - binding 1: the relief texture, `GL_RGBA32F`, `size` x `size`, the texels of
 *   `ocean_relief_cones_texels` (`[depth, c, D, E]`, row v = 0 first). The shader reads it with
 *   `texelFetch` and filters by hand (bilinear, with the edge mode), so no sampler state
 *   matters. With `levels` = 1 it reads level 0 only. With more, the texture is the atlas of
 *   `ocean_relief_mip_atlas_size` (one texture level, (`size` + `size` / 2) x `size`): level l
 *   (side `size` >> l, placed at `ocean_relief_mip_atlas_origin`) holds the texels of the map
 *   `ocean_relief_map_downsample` made l times from level 0's, with its own cones
 *   (`ocean_relief_cones_create` on that map: cones of level 0 do not fit a coarser surface),
 *   and each fragment reads the one level `ocean_relief_mip_level` picks from its texture
 *   coordinates' screen derivatives, chosen once before the tracer's loops;
 * - for a quad-directional cone map (`ocean_relief_quad_cones_create`), export `relief_quad`
 *   instead: the same block (this function, unchanged), and binding 1 is a
 *   `GL_TEXTURE_2D_ARRAY`, `GL_RGBA32F`, `size` x `size` x 4 layers, the texels of
 *   `ocean_relief_quad_cones_texels`; each ray reads the layer of its direction's quadrant.
 *   With `levels` > 1 every layer is an atlas as above, of that layer's texels at each level;
 * - draw 6 vertices as `GL_TRIANGLES` with no vertex buffer (an empty vertex array object);
 * - depth test `GL_LESS` (`GL_GREATER` for a reversed-Z camera) with depth writes: the fragment
 *   stage writes the hit point's depth to `gl_FragDepth`, so the relief occludes and is
 *   occluded correctly. Cull nothing or the back faces (the front faces `edge_u x edge_v`).
 *
 * The exported GLSL's clip space is OpenGL's (naga flips y and maps z to [-1, 1]); the depth
 * it writes is the window depth for `glDepthRange(0, 1)`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite member, `OCEAN_STATUS_INVALID_ARGUMENT` for
 * a camera, scene, method, size or edge the description above refuses (the message names
 * it), `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not `OCEAN_RELIEF_UNIFORMS_SIZE`,
 * `OCEAN_STATUS_LENGTH_OVERFLOW` if `len` exceeds `PTRDIFF_MAX`.
 *
 * # Safety
 *
 * `camera` and `scene` must be readable, and `out` point to `len` writable bytes that no
 * other thread touches during the call.
 */
OceanStatus ocean_relief_uniforms(const struct OceanCamera *camera,
                                  const struct OceanReliefScene *scene,
                                  uint32_t size,
                                  uint32_t edge,
                                  uint32_t levels,
                                  uint32_t srgb_encode,
                                  uint8_t *out,
                                  size_t len);
#endif

/**
 * Makes the next mip level of `map`: side N / 2, each depth the mean ((a + b) + (c + d)) / 4
 * of its 2x2 group (row above first, left texel first), the same edge mode; stores the handle
 * in `*out`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_ARGUMENT` if the side is not a power of two or below 4. `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_relief_map_downsample(const struct OceanReliefMap *map,
                                        struct OceanReliefMap **out);

/**
 * Stores the width and height of the relief texture that holds `levels` levels of side `size`
 * for the `relief` shaders: `size` x `size` for one level, (`size` + `size` / 2) x `size` for
 * more (level 0 on the left, the others in a column to its right; see
 * `ocean_relief_mip_atlas_origin`).
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_ARGUMENT` for a `size` or `levels` `ocean_relief_mip_level` refuses.
 * Nothing is written on failure.
 *
 * # Safety
 *
 * `out_width` and `out_height` must be writable.
 */
OceanStatus ocean_relief_mip_atlas_size(uint32_t size,
                                        uint32_t levels,
                                        uint32_t *out_width,
                                        uint32_t *out_height);

/**
 * Stores where level `level` (side `size` >> `level`) starts in the relief texture of
 * `ocean_relief_mip_atlas_size`, in texels from its first row's first texel: (0, 0) for level
 * 0, (`size`, `size` - (`size` >> (`level` - 1))) for the others. Copy the level's texels
 * (`ocean_relief_cones_texels` of its own cones) there, row by row.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_ARGUMENT` for a `size` `ocean_relief_mip_level` refuses or a `level`
 * at or beyond log2 `size`. Nothing is written on failure.
 *
 * # Safety
 *
 * `out_x` and `out_y` must be writable.
 */
OceanStatus ocean_relief_mip_atlas_origin(uint32_t size,
                                          uint32_t level,
                                          uint32_t *out_x,
                                          uint32_t *out_y);

/**
 * Stores in `*out_level` the mip level a fragment of the `relief` shader reads for the screen
 * derivatives (du_x, du_y) = dFdx(uv) and (dv_x, dv_y) = dFdy(uv) of its texture coordinates
 * (texture widths per pixel), for a texture of side `size` with `levels` levels: with
 * rho^2 = max(|du|^2, |dv|^2) size^2, the largest l < `levels` with rho^2 >= 2^(2l - 1) (rho >=
 * 2^(l - 1/2)), or 0. A NaN footprint reads level 0, an infinite one the last level. The shader
 * rounds the same operations, so this is its CPU twin.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_ARGUMENT` if `size` is outside 2 to `OCEAN_RELIEF_MAX_SIDE` or `levels`
 * outside 1 to log2 `size` (1 for a side that is not a power of two). `*out_level` is written
 * only on success.
 *
 * # Safety
 *
 * `out_level` must be writable.
 */
OceanStatus ocean_relief_mip_level(float du_x,
                                   float du_y,
                                   float dv_x,
                                   float dv_y,
                                   uint32_t size,
                                   uint32_t levels,
                                   uint32_t *out_level);

/**
 * Builds the mip chain of the cone map of `cones`, level 0 (the cone map) down to 1x1, and
 * stores a handle in `*out`. `rule`: `OCEAN_RELIEF_MIP_WINDOW` (the 4x4-window minimum, valid
 * under bilinear sampling; use it) or `OCEAN_RELIEF_MIP_GROUP` (the book's 2x2 minimum, valid
 * under nearest sampling only). Every channel takes the same minimum.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_ARGUMENT` for an unknown rule or a side that is not a power of two.
 * `*out` is written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_relief_mips_create(const struct OceanReliefCones *cones,
                                     uint32_t rule,
                                     struct OceanReliefMips **out);

/**
 * Frees a mip chain. NULL does nothing; a handle of another kind or already destroyed frees
 * nothing and sets the last-error message (see the header's notes on handles).
 */
void ocean_relief_mips_destroy(struct OceanReliefMips *mips);

/**
 * Stores the number of levels, log2(N) + 1, in `*out_count`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out_count`
 * is written only on success.
 *
 * # Safety
 *
 * `out_count` must be writable.
 */
OceanStatus ocean_relief_mips_level_count(const struct OceanReliefMips *mips, uint32_t *out_count);

/**
 * Stores the side of mip `level`, N >> level texels, in `*out_size`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_ARGUMENT` if `level` >= the level count. `*out_size` is written only on
 * success.
 *
 * # Safety
 *
 * `out_size` must be writable.
 */
OceanStatus ocean_relief_mips_level_size(const struct OceanReliefMips *mips,
                                         uint32_t level,
                                         uint32_t *out_size);

/**
 * Encodes mip `level` and copies it into `out`: `len` = 3 side * side elements (side from
 * `ocean_relief_mips_level_size`) of the encoding's type, `[c, D, E]` per texel, row-major,
 * rounded down, as `ocean_relief_cones_encode` writes level 0.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_ARGUMENT` for an unknown encoding or a level that does not exist,
 * `OCEAN_STATUS_LENGTH_MISMATCH` for a `len` that is not 3 side * side. Nothing is written
 * on failure.
 *
 * # Safety
 *
 * `out` must point to `len` writable elements of the encoding's
 * type that no other thread touches during the call.
 */
OceanStatus ocean_relief_mips_copy_level(const struct OceanReliefMips *mips,
                                         uint32_t level,
                                         uint32_t encoding,
                                         void *out,
                                         size_t len);

/**
 * Generates the quad-directional cone map of `map` (one relaxed or conservative cone map per
 * quadrant of the ray's direction, see `OceanReliefConeParams`) and stores a handle that holds
 * it and a copy of the map in `*out`: what `ocean_relief_quad_trace` and
 * `ocean_relief_quad_shadow` read.
 *
 * Each layer has the three channels of `ocean_relief_cones_create` (c, D, E, rounded down to
 * float, capped at `params->max_ratio`), valid for the rays of its quadrant through the
 * bilinear surface; every layer's cone is at least the isotropic one. The result is
 * bit-identical to `ocean_relief::QuadConeMap::generate` on every thread count, with or
 * without `progress`. It costs about four isotropic generations.
 *
 * `progress` (may be NULL) is called as `OceanReliefProgress` describes, with `user`, except
 * that the work is four layers of rows: `total` is 4 N in wrap mode and 4 (N + 1) in clamp
 * mode, and there are still at most `OCEAN_RELIEF_PROGRESS_BANDS + 1` calls (each layer in
 * at most a quarter of the bands). A nonzero return cancels.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `max_ratio`, `OCEAN_STATUS_INVALID_ARGUMENT`
 * for an unknown kind or a `max_ratio` outside (0, `OCEAN_RELIEF_MAX_RATIO_LIMIT`],
 * `OCEAN_STATUS_CANCELLED` when the callback returned nonzero (the arguments are checked before
 * the first call). `*out` is written only on success.
 *
 * # Safety
 *
 * `params` readable, `out` writable; `progress`, if not NULL,
 * must be safe to call with `user` from this thread.
 */
OceanStatus ocean_relief_quad_cones_create(const struct OceanReliefMap *map,
                                           const struct OceanReliefConeParams *params,
                                           OceanReliefProgress progress,
                                           void *user,
                                           struct OceanReliefQuadCones **out);

/**
 * Frees a quad-directional cone map. NULL does nothing; a handle of another kind or already
 * destroyed frees nothing and sets the last-error message (see the header's notes on handles).
 */
void ocean_relief_quad_cones_destroy(struct OceanReliefQuadCones *cones);

/**
 * Stores the side N of the quad-directional cone map (that of its height map), texels, in
 * `*out_size`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out_size`
 * is written only on success.
 *
 * # Safety
 *
 * `out_size` must be writable.
 */
OceanStatus ocean_relief_quad_cones_size(const struct OceanReliefQuadCones *cones,
                                         uint32_t *out_size);

/**
 * Copies the quadrant relief texture into `rgba`: `len` = 16 N * N floats, the 4 layers of an
 * `RGBA32F` 2D texture array one after the other (layer k = x_neg + 2 y_neg, its N * N texels
 * row-major, `[depth, c_k, D_k, E_k]` per texel): upload with one `glTexSubImage3D` of depth
 * 4 into a `GL_TEXTURE_2D_ARRAY` and draw with the `relief_quad` shader. Exactly what the CPU
 * quadrant tracer reads.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not 16 N * N. Nothing is written on failure.
 *
 * # Safety
 *
 * `rgba` must point to `len` writable floats that no other thread
 * touches during the call.
 */
OceanStatus ocean_relief_quad_cones_texels(const struct OceanReliefQuadCones *cones,
                                           float *rgba,
                                           size_t len);

/**
 * Generates the quad-directional cone map of `map` straight into `rgba` (no handle): `len` =
 * 16 N * N floats, as `ocean_relief_quad_cones_texels` writes them. Arguments, callback and
 * statuses as `ocean_relief_quad_cones_create`, with `OCEAN_STATUS_LENGTH_MISMATCH` for a
 * `len` that is not 16 N * N (checked before any work). `rgba` is written only on success,
 * and then wholly.
 *
 * # Safety
 *
 * `params` readable, `rgba` point to `len` writable floats that
 * no other thread touches during the call; `progress`, if not NULL, must be safe to call with
 * `user` from this thread.
 */
OceanStatus ocean_relief_quad_generate_texels(const struct OceanReliefMap *map,
                                              const struct OceanReliefConeParams *params,
                                              OceanReliefProgress progress,
                                              void *user,
                                              float *rgba,
                                              size_t len);

/**
 * Traces `count` rays through the quad-directional cone map `cones` with `method` and stores
 * where each stopped in `hits[i]`: each ray reads the layer of its direction's quadrant (the
 * module documentation), chosen once, then runs `ocean_relief_trace`'s tracer on it (with
 * conservative quadrant cones, cone step mapping is QDCSM, section 18.1). Each result is
 * bit-identical to `ocean_relief::QuadReliefTexture::trace` and to the `relief_quad` shader's
 * tracer on the texels of `ocean_relief_quad_cones_texels`.
 *
 * Arguments, checks and statuses as `ocean_relief_trace`. `hits` is written only on success,
 * and then wholly.
 *
 * # Safety
 *
 * `method` readable, `rays` point to `count` readable rays and
 * `hits` to `count` writable hits, neither touched by another thread during the call.
 */
OceanStatus ocean_relief_quad_trace(const struct OceanReliefQuadCones *cones,
                                    const struct OceanReliefMethod *method,
                                    const struct OceanReliefRay *rays,
                                    size_t count,
                                    struct OceanReliefHit *hits);

/**
 * `ocean_relief_shadow` through the quad-directional cone map `cones`: the light ray towards
 * each point reads the layer of its own direction's quadrant. Arguments, checks and statuses
 * as `ocean_relief_shadow`; each answer equals `ocean_relief::QuadReliefTexture::in_shadow`'s.
 * `in_shadow` is written only on success, and then wholly.
 *
 * # Safety
 *
 * `method` readable, `points` point to `count` readable points
 * and `in_shadow` to `count` writable bytes, neither touched by another thread during the
 * call.
 */
OceanStatus ocean_relief_quad_shadow(const struct OceanReliefQuadCones *cones,
                                     const struct OceanReliefMethod *method,
                                     const struct OceanReliefPoint *points,
                                     size_t count,
                                     float light_x,
                                     float light_y,
                                     float light_z,
                                     float depth_scale,
                                     float bias,
                                     uint8_t *in_shadow);

/**
 * Stores the tracer that `ocean_relief_scene_default` draws with in `*out`: relaxed cone
 * stepping (Listing 18-3) with the book's 15 cone steps and 6 bisections, refining the last
 * step (`OCEAN_RELIEF_SEARCH_LAST_STEP`). Trace with a relaxed cone map.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
 * then left unchanged.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_relief_method_default(struct OceanReliefMethod *out);

/**
 * Stores in `*out` the ray of the tangent-space view vector (view_x, view_y, view_z) (x along
 * u, y along v, z out of the polygon; view_z < 0 looking at it; any length) entering at
 * (start_u, start_v), for a relief `depth` texture widths deep: the direction
 * (depth view_x / -view_z, depth view_y / -view_z, 1). Rescaling the depth changes the ray,
 * never the cones (section 18.5).
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite argument, `OCEAN_STATUS_INVALID_ARGUMENT` if
 * view_z >= 0 or depth < 0. `*out` is written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_relief_ray_from_view(float start_u,
                                       float start_v,
                                       float view_x,
                                       float view_y,
                                       float view_z,
                                       float depth,
                                       struct OceanReliefRay *out);

/**
 * Traces `count` rays through `cones` with `method` and stores where each stopped in
 * `hits[i]`. Rays are traced in parallel on the library's threads; each result is
 * bit-identical to `ocean_relief::Method::trace` for that ray.
 *
 * Cone step mapping assumes conservative cones and relaxed cone stepping relaxed ones (see
 * `OceanReliefConeParams::kind`); the other pairing runs but loses the guarantee that no
 * feature is stepped over. Linear search reads only the depths.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (4-byte
 * alignment for the arrays), `OCEAN_STATUS_EMPTY` if `count` is 0,
 * `OCEAN_STATUS_LENGTH_OVERFLOW` if an array's byte size exceeds `PTRDIFF_MAX`,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite ray member, `OCEAN_STATUS_INVALID_ARGUMENT`
 * for an unknown method or search, a step count out of range, a ray with dir_z <= 0 (the
 * message names the first bad ray) or overlapping arrays. `hits` is written only on success,
 * and then wholly.
 *
 * # Safety
 *
 * `method` readable, `rays` point to `count` readable rays and
 * `hits` to `count` writable hits, neither touched by another thread during the call.
 */
OceanStatus ocean_relief_trace(const struct OceanReliefCones *cones,
                               const struct OceanReliefMethod *method,
                               const struct OceanReliefRay *rays,
                               size_t count,
                               struct OceanReliefHit *hits);

/**
 * For each of `count` surface points, whether the light from the tangent-space direction
 * (light_x, light_y, light_z) (towards the light; light_z > 0 above the polygon; any length)
 * is blocked before it reaches the point, for a relief `depth_scale` texture widths deep:
 * the light ray is traced from where it enters the relief towards the point with `method`,
 * and the point is in shadow (1 in `in_shadow[i]`, else 0) when the ray stops more than `bias`
 * (depth units, in [0, 1]) above it; the bias absorbs the tracer's final bracket, or a point
 * shadows itself (a few times the last step over 2^binary works). A light at or below the
 * polygon's plane (light_z <= 0) leaves every point in shadow, and so does a light so close
 * above it (light_z = FLT_TRUE_MIN beside a unit light_x) that its run per unit depth
 * overflows a float. Points are processed in
 * parallel; each answer equals `ocean_relief::shadow::in_shadow`'s.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_EMPTY` if `count` is 0, `OCEAN_STATUS_LENGTH_OVERFLOW` for an array whose byte
 * size exceeds `PTRDIFF_MAX`, `OCEAN_STATUS_NON_FINITE` for a NaN or infinite light, depth
 * scale, bias or point member, `OCEAN_STATUS_INVALID_ARGUMENT` for a bad method, a negative
 * `depth_scale`, a `bias` outside [0, 1], or overlapping arrays. `in_shadow` is written only
 * on success, and then wholly.
 *
 * # Safety
 *
 * `method` readable, `points` point to `count` readable points
 * and `in_shadow` to `count` writable bytes, neither touched by another thread during the
 * call.
 */
OceanStatus ocean_relief_shadow(const struct OceanReliefCones *cones,
                                const struct OceanReliefMethod *method,
                                const struct OceanReliefPoint *points,
                                size_t count,
                                float light_x,
                                float light_y,
                                float light_z,
                                float depth_scale,
                                float bias,
                                uint8_t *in_shadow);

/**
 * Stores ocean-sao's default parameters in `*out` (the paper's set-up: r = 1 m, 9 samples,
 * 7 spiral turns, MIP levels 0 to 5 by rotated grid subsampling from q' = 8, the appendix's
 * falloff with beta = 1 cm, the 2x2 quad filter at 2 cm, no normal rejection, z_min = -200 m;
 * beyond it: nearest-neighbour normals and a blur of 13 adjacent taps, sigma 3, weighed by the
 * plane through the centre, depth scale 2048, world extent 0.5. The paper's blur is taps 7,
 * stride 3, sigma 1.5, `OCEAN_SAO_BLUR_WEIGHT_DEPTH`). The members of the estimator not
 * chosen hold that estimator's defaults too.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
 * then left unchanged.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_sao_params_default(struct OceanSaoParams *out);

/**
 * Creates an SAO set-up for depth buffers of `input_width` x `input_height` pixels with a
 * guard band of `guard` pixels on every side, and stores the handle in `*out`.
 *
 * The paper renders depth larger than the screen so that geometry just outside the frame can
 * still occlude: the AO image is the input inset by `guard` on every side,
 * (input_width - 2 guard) x (input_height - 2 guard) pixels. Any guard band is accepted and
 * gives the interior an aligned one gives: the z MIP levels are anchored at guard modulo
 * 2^max_mip (the uniform block of `ocean_sao_uniforms` carries the anchor to the GPU passes).
 * `camera` is the camera that rendered the whole input, guard band included (see
 * `OceanCamera`): SAO works in view space and reads only its projection, whose aspect
 * P11/P00 is that of the input's pixels (it need not equal width/height: non-square pixels are
 * allowed). Mirrored or y-flipped projections are refused: image rows already run top-down
 * (see `ocean_sao_run`). `depth_source` says what the depth buffer holds:
 * `OCEAN_SAO_DEPTH_WINDOW` or `OCEAN_SAO_DEPTH_NDC`. `params` are the passes (see
 * `OceanSaoParams`). Both structs are copied; neither is retained.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_EMPTY` if `input_width` or `input_height` is 0, `OCEAN_STATUS_NON_FINITE` for
 * a NaN or infinite matrix element or parameter (the message names it),
 * `OCEAN_STATUS_INVALID_ARGUMENT` for a side outside 2 to `OCEAN_SAO_MAX_SIDE`, a guard band
 * that leaves no output pixel (2 guard must be below both sides), an unknown enumeration
 * value or flag, a matrix that is not a supported projection for its depth convention or whose
 * constants degenerate in float, and a parameter out of its documented range. `*out` is
 * written only on success. Free the handle with `ocean_sao_destroy`.
 *
 * # Safety
 *
 * `camera` and `params` must point to readable structs and `out` to a writable pointer.
 */
OceanStatus ocean_sao_create(uint32_t input_width,
                             uint32_t input_height,
                             uint32_t guard,
                             const struct OceanCamera *camera,
                             uint32_t depth_source,
                             const struct OceanSaoParams *params,
                             struct OceanSao **out);

/**
 * Frees an SAO set-up. NULL does nothing; a handle of another kind or already destroyed frees
 * nothing and sets the last-error message (see the header's notes on handles).
 */
void ocean_sao_destroy(struct OceanSao *sao);

/**
 * Stores what `sao` was made of in `*out` (see `OceanSaoInfo`): the sizes, the near and far
 * planes read from the projection matrix (compare them with yours: a matrix passed with the
 * wrong depth convention shows here) and the constants of the passes.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `sao` or `out`;
 * `*out` is written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_sao_describe(const struct OceanSao *sao, struct OceanSaoInfo *out);

/**
 * Computes ambient obscurance (visibility) from a depth buffer: every pass of the paper, in
 * ocean-sao's arithmetic, with its result bit-identical to `ocean_sao::Sao::run` on every
 * platform and thread count.
 *
 * `depth`: `depth_len` = input_width * input_height floats, row-major, **row 0 at the top** of
 * the image (the layout of a wgpu, Vulkan, D3D or Metal texture read back; OpenGL's
 * `glReadPixels` returns rows bottom-up: flip them first). Each value must be finite and
 * within the range of the camera's depth source and convention: [0, 1] for window depth
 * (`OCEAN_SAO_DEPTH_WINDOW`) and for the [0, 1] conventions, [-1, 1] for NDC depth under
 * `OCEAN_DEPTH_CONVENTION_NEG_ONE_TO_ONE`. The far end of the range (`far_depth` of
 * `ocean_sao_describe`: 1, or 0 with reversed Z; the value a depth buffer is cleared to) is
 * background, at any far plane.
 *
 * `ao`: `ao_len` = output_width * output_height floats (see `ocean_sao_create`), row-major,
 * row 0 at the top: `ao[y * output_width + x]` is the visibility A of input pixel
 * (x + guard, y + guard), in [0, 1]: 1 is unoccluded, 0 fully occluded; multiply ambient light
 * by it. Background pixels, and pixels whose normal is rejected, get 1.
 *
 * The passes: view-space z from depth (Eq. 2), its MIP levels (Table 1), the spiral samples
 * (Eq. 6-10) with the chosen estimator, the 2x2 quad bilateral, A packed to 8 bits with a
 * 16-bit depth key (section 2.3), and the horizontal and vertical bilateral blur (section 2.4).
 * The result is computed in a buffer of the library's and copied to `ao` at the end.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (4-byte
 * alignment for the floats), `OCEAN_STATUS_LENGTH_MISMATCH` if `depth_len` or `ao_len` is not
 * exactly the size above, `OCEAN_STATUS_INVALID_ARGUMENT` if the buffers overlap or a depth
 * value is outside the range (the
 * message gives the first one, in row-major order, with its pixel), `OCEAN_STATUS_NON_FINITE`
 * for a NaN or infinite depth value (likewise), `OCEAN_STATUS_LENGTH_OVERFLOW` if a length in
 * bytes exceeds `PTRDIFF_MAX`. `ao` is written only on success, and then wholly.
 *
 * # Safety
 *
 * `depth` point to `depth_len` readable floats and `ao` to
 * `ao_len` writable floats, neither touched by another thread during the call.
 */
OceanStatus ocean_sao_run(const struct OceanSao *sao,
                          const float *depth,
                          size_t depth_len,
                          float *ao,
                          size_t ao_len);

/**
 * Stores the view-space z of every depth value in `z` (the first pass of `ocean_sao_run`,
 * Eq. 2): `z_len` = input_width * input_height floats, the layout of `depth`, metres, negative
 * in front of the camera; `OCEAN_SAO_SKY_Z` (-1e9 m) for background (depth at the far end),
 * and never below it. Useful to linearise a depth buffer with exactly SAO's arithmetic, or to
 * check a shader's reconstruction.
 *
 * `depth` as for `ocean_sao_run`. Returns the same statuses, with `z_len` in place of
 * `ao_len`; `z` is written only on success, and then wholly.
 *
 * # Safety
 *
 * `depth` point to `depth_len` readable floats and `z` to `z_len`
 * writable floats, neither touched by another thread during the call.
 */
OceanStatus ocean_sao_view_z(const struct OceanSao *sao,
                             const float *depth,
                             size_t depth_len,
                             float *z,
                             size_t z_len);

#if defined(OCEAN_GPU)
/**
 * Creates the GPU ambient obscurance passes on `ctx` and stores a new handle in `*out`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_GPU_FAILURE` if the device cannot build the pipelines. On failure `*out` is
 * unchanged. Free the handle with `ocean_sao_gpu_destroy`.
 *
 * # Safety
 *
 * `ctx` must be a live context and `out` point to a writable pointer.
 */
OceanStatus ocean_sao_gpu_create(const struct OceanGpuContext *ctx, struct OceanSaoGpu **out);
#endif

#if defined(OCEAN_GPU)
/**
 * Frees the handle. NULL does nothing; a handle of another kind or already destroyed frees nothing
 * and sets the last-error message (see the header's notes on handles).
 */
void ocean_sao_gpu_destroy(struct OceanSaoGpu *sao_gpu);
#endif

#if defined(OCEAN_GPU)
/**
 * Computes the obscurance of `depth` as `ocean_sao_run` does, on the GPU of `ctx`: the depth
 * buffer is uploaded, the five passes run (view-space z, Eq. 2; its MIP levels, Table 1; the
 * spiral samples, Eq. 6-10; the horizontal and vertical bilateral blurs, section 2.4) and the
 * obscurance is read back. `sao` gives the sizes, camera and parameters; `depth` and `ao` are
 * laid out and checked exactly as for `ocean_sao_run`. The result matches the CPU's within
 * 2/255 on at least 99.9% of the pixels (the library's parity tests).
 *
 * Returns the statuses of `ocean_sao_run`, and `OCEAN_STATUS_INVALID_ARGUMENT` for a context
 * other than the one the handle was created on or an image larger than the device's largest
 * texture, `OCEAN_STATUS_GPU_FAILURE` for a device error. `ao` is written only on success, and
 * then wholly.
 *
 * # Safety
 *
 * `depth` point to `depth_len` readable
 * floats and `ao` to `ao_len` writable floats, neither touched by another thread during the
 * call.
 */
OceanStatus ocean_sao_gpu_run(const struct OceanSaoGpu *sao_gpu,
                              const struct OceanGpuContext *ctx,
                              const struct OceanSao *sao,
                              const float *depth,
                              size_t depth_len,
                              float *ao,
                              size_t ao_len);
#endif

#if defined(OCEAN_GPU)
/**
 * Writes the uniform block of the exported `sao_*` shaders for `sao` into `out` (the
 * `OCEAN_SAO_UNIFORMS_SIZE` bytes of `Params`, std140, in the machine's byte order: upload
 * them as they are with `glBufferSubData`) and the number of z levels the passes build into
 * `*levels` (1 to 14).
 *
 * For engines that run the passes in their own OpenGL 4.3 pipeline (`ocean_shader_export`
 * of `sao_z`, `sao_mip`, `sao_ao` and `sao_blur`, with their binding tables), every dispatch
 * in 8 x 8 workgroups over its output:
 * 1. `sao_z` `z_pass`: the depth texture (input size) to z level 0, an `r32f` texture of the
 *    input size.
 * 2. `sao_mip` `downsample`, for each level l = 1 to levels - 1: level l - 1 to level l
 *    (`r32f`, each side halved, rounded down, at least 1), one texture per level.
 * 3. `sao_ao` `ao`: the levels to the packed A and key (`r32ui`, output size).
 * 4. `sao_blur` `blur_horizontal`, then `blur_vertical`: packed to packed, the last one also
 *    writing A (`r32f`, output size), with a memory barrier between the dispatches.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_LENGTH_MISMATCH` if `len` is not `OCEAN_SAO_UNIFORMS_SIZE`,
 * `OCEAN_STATUS_LENGTH_OVERFLOW` if `len` exceeds `PTRDIFF_MAX`. Nothing is written on
 * failure.
 *
 * # Safety
 *
 * `out` must point to `len` writable bytes and `levels` to a writable value, none touched by
 * another thread during the call.
 */
OceanStatus ocean_sao_uniforms(const struct OceanSao *sao,
                               uint8_t *out,
                               size_t len,
                               uint32_t *levels);
#endif

#if defined(OCEAN_GPU)
/**
 * Stores in `*out` the built-in scene description: NUL-terminated UTF-8 TOML, owned by the
 * library and valid for the life of the process. It is the reference of the format (every key
 * commented) and what `ocean render` draws without `--scene`; pass it to `ocean_scene_create`
 * with `strlen` as its length, or edit a copy.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`, which is then
 * left unchanged.
 *
 * # Safety
 *
 * `out` must be writable and untouched by other threads during the call.
 */
OceanStatus ocean_scene_builtin_description(const char **out);
#endif

#if defined(OCEAN_GPU)
/**
 * Stores the default scene options in `*out`: every member 0 (the description's size, samples
 * and camera), `next` NULL.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
 * then left unchanged.
 *
 * # Safety
 *
 * `out` must be writable and untouched by other threads during the call.
 */
OceanStatus ocean_scene_options_default(struct OceanSceneOptions *out);
#endif

#if defined(OCEAN_GPU)
/**
 * Parses the scene description `text` (`len` bytes of UTF-8 TOML, no NUL needed), builds
 * everything its frames are drawn with on `ctx` (spectrum and filtering, sky map, island and
 * wave train boxes, terrain, rocks and pier with their cone maps, obscurance, targets) and
 * stores the scene in `*out`. Cone maps are read from and written to the cache of
 * `ocean render` (`$OCEAN_CACHE_DIR`, else `$XDG_CACHE_HOME/ocean`, else
 * `$HOME/.cache/ocean`) when there is one; a cache that cannot be written costs only time.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_HANDLE` for a bad `ctx`, `OCEAN_STATUS_EMPTY` if `len` is 0,
 * `OCEAN_STATUS_INVALID_ARGUMENT` for text that is not UTF-8, a description that does not
 * parse or is out of range (the message names the line and the key), an option out of range,
 * or a piece that cannot be built from it (the message names it); `OCEAN_STATUS_NO_ADAPTER` /
 * `_GPU_FAILURE` for a device error. On failure `*out` is unchanged. Building takes from a
 * fraction of a second to seconds (cone maps not in the cache).
 *
 * # Safety
 *
 * `text` must point to `len` readable bytes, `options` to a readable `OceanSceneOptions` and
 * `out` to a writable pointer; neither `text` nor `options` is retained.
 */
OceanStatus ocean_scene_create(const struct OceanGpuContext *ctx,
                               const char *text,
                               size_t len,
                               const struct OceanSceneOptions *options,
                               struct OceanScene **out);
#endif

#if defined(OCEAN_GPU)
/**
 * Frees a scene and its GPU resources. NULL does nothing; a handle of another kind or already
 * destroyed frees nothing and sets the last-error message (see the header's notes on handles).
 * It may outlive its context.
 */
void ocean_scene_destroy(struct OceanScene *scene);
#endif

#if defined(OCEAN_GPU)
/**
 * Stores the size of the scene's frames in pixels in `*width` and `*height`: the description's
 * `[render]` size, or the options' overrides.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_HANDLE` for a bad `scene`. On failure nothing is written.
 *
 * # Safety
 *
 * `width` and `height` must be writable and untouched by other threads during the call.
 */
OceanStatus ocean_scene_size(const struct OceanScene *scene, uint32_t *width, uint32_t *height);
#endif

#if defined(OCEAN_GPU)
/**
 * Renders the scene's frame at scene `time` (seconds) on the GPU: the wave train boxes
 * marched to `time` on the CPU, then the sea, the island, the rocks and the pier, their
 * ambient obscurance and the composition, as `ocean render` draws the same description; waits
 * for it and copies it into `out`.
 *
 * Format: `len` = width * height * 4 bytes exactly (`ocean_scene_size`); rows from the top of
 * the image, each `width` pixels of R, G, B, A bytes from left to right, tightly packed.
 * Colours are tone-mapped and sRGB-encoded (display-ready bytes for an `SRGB8_ALPHA8` texture
 * or an image file); alpha is 255.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
 * `OCEAN_STATUS_INVALID_HANDLE` for a bad `scene` or `ctx`, `OCEAN_STATUS_LENGTH_MISMATCH` if
 * `len` is not width * height * 4, `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `time`,
 * `OCEAN_STATUS_INVALID_ARGUMENT` for a context other than the scene's or a `time` at which
 * the camera or the wave trains cannot be evaluated, `OCEAN_STATUS_GPU_FAILURE` for a device
 * error. Nothing is written to `out` on failure.
 *
 * # Safety
 *
 * `out` must point to `len` writable bytes that no other thread touches during the call.
 */
OceanStatus ocean_scene_render_rgba8(const struct OceanScene *scene,
                                     const struct OceanGpuContext *ctx,
                                     double time,
                                     uint8_t *out,
                                     size_t len);
#endif

#if defined(OCEAN_GPU)
/**
 * Returns the number of registered shaders (passes), at least 1. Never fails; leaves the
 * last-error message alone.
 */
size_t ocean_shader_count(void);
#endif

#if defined(OCEAN_GPU)
/**
 * Stores the name of registered shader `index` (0 to `ocean_shader_count()` - 1) in `*out`:
 * a static NUL-terminated string such as "ocean" (the renderer's draw pass) or "trochoid",
 * valid for the life of the program. Pass it to `ocean_shader_export`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad `out`,
 * `OCEAN_STATUS_INVALID_ARGUMENT` if `index` >= the count. `*out` is written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_shader_name(size_t index, const char **out);
#endif

#if defined(OCEAN_GPU)
/**
 * Translates the registered shader `name` to `language` (an `OceanShaderLanguage` value) with
 * naga and stores a new export in `*out`: its files (`ocean_shader_export_file`) and its
 * resource bindings (`ocean_shader_export_binding`, `ocean_shader_export_bindings`).
 *
 * GLSL and GLSL ES give one file per entry point, named `<pass>.<entry>.<vert|frag|comp>.glsl`
 * (`.es.glsl` for ES), in the order the WGSL declares them; the draw pass "ocean" has the vertex
 * and fragment stages of the sea (`ocean_vs`, `ocean_fs`), of the sky (`sky_vs`, `sky_fs`), of
 * a caller's water mesh (`mesh_vs`, `mesh_fs`) and of the full-screen pass composing that
 * mesh's light with an ambient obscurance (`sky_vs`, `compose_fs`).
 * HLSL (`<pass>.hlsl`), MSL (`<pass>.metal`) and SPIR-V (`<pass>.spv`) give one file with every
 * entry point. The translation is deterministic: the same library gives the same bytes.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_ARGUMENT` for a `language` that is not an `OceanShaderLanguage` or a
 * `name` that is not UTF-8, `OCEAN_STATUS_NOT_FOUND` for an unknown name (the message lists
 * the registered ones), `OCEAN_STATUS_GPU_FAILURE` if naga cannot translate the pass. On
 * failure `*out` is unchanged. Free the export with `ocean_shader_export_destroy`.
 *
 * # Safety
 *
 * `name` must be NULL or a NUL-terminated string, and `out` point to a writable pointer;
 * `name` is not retained.
 */
OceanStatus ocean_shader_export(const char *name,
                                uint32_t language,
                                struct OceanShaderExport **out);
#endif

#if defined(OCEAN_GPU)
/**
 * Frees an export; every pointer it handed out becomes invalid. NULL does nothing; a handle of
 * another kind or already destroyed frees nothing and sets the last-error message (see the
 * header's notes on handles).
 */
void ocean_shader_export_destroy(struct OceanShaderExport *shader_export);
#endif

#if defined(OCEAN_GPU)
/**
 * Stores the number of files of the export (>= 1) in `*out`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_shader_export_file_count(const struct OceanShaderExport *shader_export,
                                           size_t *out);
#endif

#if defined(OCEAN_GPU)
/**
 * Stores file `index` (0 to the file count - 1) of the export: its suggested file name in
 * `*file_name` (NUL-terminated, e.g. "ocean.ocean_vs.vert.glsl"), its bytes in `*data` and
 * their number in `*len`.
 *
 * The data is the shader's text (UTF-8) or, for SPIR-V, its binary module (little-endian
 * 32-bit words); `len` counts its bytes without any terminator. It is 4-byte aligned (cast it
 * to `const uint32_t *` for `vkCreateShaderModule`) and followed by at least one NUL byte,
 * so text can be passed as a C string (`glShaderSource` with a NULL length). The pointers stay
 * valid until the export is destroyed.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_ARGUMENT` if `index` >= the file count. Nothing is written on failure.
 *
 * # Safety
 *
 * The three out-pointers must be writable.
 */
OceanStatus ocean_shader_export_file(const struct OceanShaderExport *shader_export,
                                     size_t index,
                                     const char **file_name,
                                     const uint8_t **data,
                                     size_t *len);
#endif

#if defined(OCEAN_GPU)
/**
 * Stores the stage of file `index` in `*stage` (an `OceanShaderStage` value:
 * `OCEAN_SHADER_STAGE_MODULE` for a file with every entry point) and the name of its entry
 * point in `*entry_point` (NUL-terminated, e.g. "ocean_fs"; "" for a module), valid until the
 * export is destroyed.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_ARGUMENT` if `index` >= the file count. Nothing is written on failure.
 *
 * # Safety
 *
 * Both out-pointers must be writable.
 */
OceanStatus ocean_shader_export_file_stage(const struct OceanShaderExport *shader_export,
                                           size_t index,
                                           OceanShaderStage *stage,
                                           const char **entry_point);
#endif

#if defined(OCEAN_GPU)
/**
 * Stores the export's binding layout as text in `*table`: NUL-terminated UTF-8 owned by the
 * export, valid until it is destroyed. A header line starting with `#`, then one line per
 * binding in (group, binding) order, `group binding name kind type (size N)` plus
 * ` glsl_name=NAME` and ` glsl_binding=N` where they apply, each followed by the members of a
 * buffer's struct, one per line: `    +OFFSET name: type`. The same text as the
 * `<pass>.bindings.txt` of `ocean shaders`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*table` is
 * written only on success.
 *
 * # Safety
 *
 * `table` must be writable.
 */
OceanStatus ocean_shader_export_bindings(const struct OceanShaderExport *shader_export,
                                         const char **table);
#endif

#if defined(OCEAN_GPU)
/**
 * Stores the number of resource bindings of the exported pass in `*out` (the same for every
 * language; 0 for a pass without resources).
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer; `*out` is
 * written only on success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_shader_export_binding_count(const struct OceanShaderExport *shader_export,
                                              size_t *out);
#endif

#if defined(OCEAN_GPU)
/**
 * Stores binding `index` (0 to the binding count - 1, in (group, binding) order) in `*out`;
 * its strings are owned by the export and valid until it is destroyed.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer,
 * `OCEAN_STATUS_INVALID_ARGUMENT` if `index` >= the binding count. `*out` is written only on
 * success.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_shader_export_binding(const struct OceanShaderExport *shader_export,
                                        size_t index,
                                        struct OceanShaderBinding *out);
#endif

/**
 * A static, NUL-terminated English description of a status code.
 *
 * `status` is taken as a plain integer so that any value is safe to pass; values that are not an
 * `OceanStatus` give "unknown status". Never NULL, never fails, any thread. The detailed message
 * of the last failure is `ocean_last_error_message()`.
 */
const char *ocean_status_message(uint32_t status);

/**
 * The detailed message of the most recent failed `ocean_*` call on the calling thread, as a
 * NUL-terminated UTF-8 string, or "" when the most recent fallible call succeeded (or there was
 * none).
 *
 * The message is thread-local: a failure on one thread never changes another thread's message.
 * Every function that returns an `OceanStatus` replaces it (clearing it on success); the
 * functions that do not return a status (`ocean_version`, `ocean_status_message`,
 * `ocean_last_error_message`, `ocean_waves_destroy`) leave it alone. The returned pointer is
 * owned by the library and stays valid until the next call of a status-returning function on
 * the same thread, or until the thread exits; copy the text to keep it longer. Never NULL.
 */
const char *ocean_last_error_message(void);

/**
 * The version of the linked library as a static NUL-terminated string "MAJOR.MINOR.PATCH".
 *
 * Compare it with the `OCEAN_VERSION_*` macros to detect a header/library mismatch. Never NULL,
 * never fails, safe to call from any thread.
 */
const char *ocean_version(void);

/**
 * The linked library's version as one number, (MAJOR << 16) | (MINOR << 8) | PATCH: the
 * `OCEAN_VERSION` of the header it was built with. Never fails, safe from any thread.
 */
uint32_t ocean_version_number(void);

/**
 * Whether the linked library provides the ABI of the header a program was compiled against:
 * call `ocean_check_version(OCEAN_VERSION)` once at start-up, before anything else (a program
 * linked against a shared library of another version would otherwise misread structs).
 *
 * Compatible: the same major version, and before 1.0 the same minor version too (a minor
 * version may change the ABI until then, as the shared library's SONAME `libocean.so.0.MINOR`
 * says), and a library at least as new as the header (a newer header may declare what an
 * older library lacks).
 *
 * Returns `OCEAN_STATUS_OK`, or `OCEAN_STATUS_VERSION_MISMATCH` with both versions in the
 * last-error message.
 */
OceanStatus ocean_check_version(uint32_t header_version);

/**
 * Builds a wave set from `n` wave descriptions and stores a new handle in `*out`.
 *
 * The waves are summed as trochoids (Gerstner waves, Yrjola & Larsson Eq. 6, 7); see
 * `ocean_waves_evaluate` for the formula. Each description is validated: the last-error message
 * names the first bad one (`descs[i]`) and its bad member.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` if `descs` or `out` is NULL, `OCEAN_STATUS_EMPTY` if
 * `n` is 0, `OCEAN_STATUS_LENGTH_OVERFLOW` if `n * sizeof(OceanWaveDesc)` exceeds
 * `PTRDIFF_MAX`, `OCEAN_STATUS_NON_FINITE` for NaN or infinite members (see `OceanWaveDesc`),
 * `OCEAN_STATUS_TOO_STEEP` if a wave has k*A > 1, `OCEAN_STATUS_INVALID_ARGUMENT` for other
 * out-of-range members (amplitude < 0, wavelength <= 0, zero direction, depth <= 0) and for
 * amplitudes that add up past 1e30 m (a displaced float position could overflow). On any
 * failure `*out` is left unchanged. Free the handle with `ocean_waves_destroy`.
 *
 * # Safety
 *
 * `descs` must point to `n` readable `OceanWaveDesc`s and `out` to a writable pointer; neither
 * is retained after the call.
 */
OceanStatus ocean_waves_create(const struct OceanWaveDesc *descs,
                               size_t n,
                               struct OceanWaves **out);

/**
 * Frees a wave set (see `ocean_wtb_scene_destroy` for the rules every destroy function follows).
 */
void ocean_waves_destroy(struct OceanWaves *waves);

/**
 * Evaluates the wave set at `n` rest points at `time` seconds.
 *
 * For rest point p0 = (`xz[i].x`, 0, `xz[i].z`) (world metres) writes the displaced surface point
 * to `out_pos[i]` and the unit surface normal to `out_normal[i]` (right-handed, y up):
 *
 * ```text
 * theta_w    = k_w . p0 - omega_w * time + phase_w
 * out_pos    = p0 + sum_w (-khat_w.x A_w sin(theta_w), A_w cos(theta_w), -khat_w.z A_w sin(theta_w))
 * out_normal = normalize(d out_pos/dz x d out_pos/dx)
 * ```
 *
 * with k_w = (2*pi/wavelength) * khat_w, khat_w the normalised direction and omega_w from the
 * dispersion relation (see `OceanWaveDesc`). Rest positions and outputs are world coordinates
 * in double precision: each point is evaluated relative to the corner of its 64 m lattice cell
 * (a float offset below 64 m, resolved to 4 µm) with the phases formed in double precision
 * (`ocean_core::WaveSet::evaluate_world`, the same evaluation for Rust callers),
 * so the answer is as precise 100 km from the origin as at it, and a point gives the same bits
 * in any batch. Large `time` values (10^6 s) do not jitter either. The arithmetic is
 * bit-identical on every platform and thread count; large batches are split over a global
 * worker pool.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` if any pointer is NULL, `OCEAN_STATUS_MISALIGNED_POINTER`
 * if one is not aligned to its type (8 bytes for `xz` and `out_pos`, 4 for `out_normal`),
 * `OCEAN_STATUS_EMPTY` if `n` is 0, `OCEAN_STATUS_LENGTH_OVERFLOW` if
 * `n * sizeof(OceanDVec3)` exceeds `PTRDIFF_MAX`,
 * `OCEAN_STATUS_INVALID_ARGUMENT` if any two of the three arrays overlap,
 * `OCEAN_STATUS_NON_FINITE` if `time` or a coordinate of `xz` is NaN or infinite (the message
 * gives the first bad index), `OCEAN_STATUS_INVALID_ARGUMENT` if a phase leaves the domain
 * where double precision resolves it: |omega * time| of the fastest wave or |k * x| (or
 * |k * z|) of the shortest wave above 1e15 rad (far beyond it the results would be NaN).
 * Nothing is written on failure.
 *
 * # Safety
 *
 * `xz` must point to `n` readable `OceanDVec2`s, `out_pos` to `n` writable `OceanDVec3`s and
 * `out_normal` to `n` writable `OceanVec3`s, none of them modified by another thread during
 * the call.
 */
OceanStatus ocean_waves_evaluate(const struct OceanWaves *waves,
                                 const struct OceanDVec2 *xz,
                                 size_t n,
                                 double time,
                                 struct OceanDVec3 *out_pos,
                                 struct OceanVec3 *out_normal);

/**
 * Evaluates the wave set on every point of `grid` at `time` seconds, on a global worker pool.
 *
 * Writes `grid->nx * grid->nz` positions and unit normals, row-major (point (i, j) at index
 * j*nx + i), by the formula of `ocean_waves_evaluate`. The positions are relative to the grid
 * origin: `out_pos[j*nx + i]` is the displaced point minus (origin_x, 0, origin_z), about
 * (i*spacing_x, y, j*spacing_z). The origin stays in double precision, so a grid 100 km from
 * the world origin is as precise as one at it; add the origin back in double precision, or put
 * it in the model matrix (camera-relative rendering). The result is bit-identical for every
 * thread count and platform.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` if any pointer is NULL,
 * `OCEAN_STATUS_MISALIGNED_POINTER` if one is misaligned, `OCEAN_STATUS_EMPTY` if `nx` or `nz`
 * is 0, `OCEAN_STATUS_LENGTH_OVERFLOW` if `nx * nz` overflows or `nx * nz * sizeof(OceanVec3)`
 * exceeds `PTRDIFF_MAX`, `OCEAN_STATUS_INVALID_ARGUMENT` if the output arrays overlap, a
 * spacing is <= 0, `nx` or `nz` exceeds 2^24, the grid's extent does not fit in a float, or
 * a phase leaves 1e15 rad (as in `ocean_waves_evaluate`, for `time` and the grid's farthest
 * corner), `OCEAN_STATUS_NON_FINITE` if `time`, the origin or a spacing is NaN or infinite.
 * Nothing is written on failure.
 *
 * # Safety
 *
 * `grid` must point to a readable `OceanGrid`, and `out_pos` and
 * `out_normal` to `nx * nz` writable `OceanVec3`s each, untouched by other threads during the
 * call.
 */
OceanStatus ocean_waves_evaluate_grid(const struct OceanWaves *waves,
                                      const struct OceanGrid *grid,
                                      double time,
                                      struct OceanVec3 *out_pos,
                                      struct OceanVec3 *out_normal);

/**
 * Stores the number of waves in the set (>= 1) in `*out_count`.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `waves` or
 * `out_count`; `*out_count` is written only on success.
 *
 * # Safety
 *
 * `out_count` must be writable.
 */
OceanStatus ocean_waves_count(const struct OceanWaves *waves, size_t *out_count);

/**
 * Stores the steepness sum, sum over the waves of k*A (dimensionless), in `*out_steepness`.
 *
 * While it is <= 1 the summed surface can never fold over itself; above 1 crests may fold where
 * the waves align (allowed, since each wave alone is at most a cusp). Returns
 * `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad argument; the output is
 * written only on success.
 *
 * # Safety
 *
 * `out_steepness` must be writable.
 */
OceanStatus ocean_waves_steepness_sum(const struct OceanWaves *waves, double *out_steepness);

/**
 * Stores the sum of the amplitudes, in metres, in `*out_amplitude`: the largest height above
 * (and depth below) y = 0 and the largest horizontal displacement any point can reach; use it
 * for bounding volumes and culling margins. Returns `OCEAN_STATUS_NULL_POINTER` (or
 * `_MISALIGNED_POINTER`) for a bad argument; the output is written only on success.
 *
 * # Safety
 *
 * `out_amplitude` must be writable.
 */
OceanStatus ocean_waves_max_amplitude(const struct OceanWaves *waves, double *out_amplitude);

/**
 * Creates a scene: a water grid over a terrain, no boxes yet, the default effects
 * (`ocean_wtb_effects_default`) and no budget limit. Stores the new handle in `*out`.
 *
 * `terrain_heights` holds one height per grid point, row-major (point (i, j) at j*nx + i):
 * the ground's height above the sea at rest, metres. A height < 0 is sea floor at depth
 * -height; a height >= 0 is land, where the water stays at rest. Pass NULL and 0 for an open
 * sea of infinite depth. Outside the grid the sea is deep. The heights are copied.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` if `grid` or `out` is NULL, or `terrain_heights` is NULL
 * with `terrain_len` != 0; `OCEAN_STATUS_MISALIGNED_POINTER`; `OCEAN_STATUS_EMPTY` if `nx` or
 * `nz` is 0; `OCEAN_STATUS_LENGTH_OVERFLOW` if `nx * nz` overflows; `OCEAN_STATUS_NON_FINITE`
 * for a NaN or infinite origin, spacing or height; `OCEAN_STATUS_INVALID_ARGUMENT` for a side
 * outside 2 to 4096, a spacing outside [1e-3, 1e4] m or an origin beyond 1e9 m;
 * `OCEAN_STATUS_LENGTH_MISMATCH` if `terrain_len` != nx * nz. On failure `*out` is
 * unchanged. Free the scene with `ocean_wtb_scene_destroy`.
 *
 * # Safety
 *
 * `grid` must point to a readable `OceanWaterGridDesc`, `terrain_heights` be NULL or point to
 * `terrain_len` readable floats, and `out` point to a writable pointer; none is retained.
 */
OceanStatus ocean_wtb_scene_create(const struct OceanWaterGridDesc *grid,
                                   const float *terrain_heights,
                                   size_t terrain_len,
                                   struct OceanWtbScene **out);

/**
 * Frees a scene and its boxes. Every destroy function follows the same rules: NULL does
 * nothing; a handle of another kind, one already destroyed or a value this library never
 * returned frees nothing and sets the last-error message (`OCEAN_STATUS_INVALID_HANDLE`'s
 * text); a live handle is unregistered at once (later calls with it are refused) and freed when
 * the last call using it on another thread returns. A successful destroy leaves the last-error
 * message alone.
 */
void ocean_wtb_scene_destroy(struct OceanWtbScene *scene);

/**
 * Replaces the scene's terrain (same format as in `ocean_wtb_scene_create`; NULL and 0 for a deep
 * sea). Every box's land, depth and refraction along its rays is recomputed at the next
 * evaluation.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (or NULL with
 * a length), `OCEAN_STATUS_LENGTH_MISMATCH` if `terrain_len` != nx * nz,
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite height (the message gives its index). On
 * failure the scene keeps its terrain.
 *
 * # Safety
 *
 * `terrain_heights` must be NULL or point to `terrain_len` readable floats.
 */
OceanStatus ocean_wtb_scene_set_terrain(struct OceanWtbScene *scene,
                                        const float *terrain_heights,
                                        size_t terrain_len);

/**
 * Adds a wave train box raised by `desc->wind`, and stores its id in `*out_id`. Ids are never
 * reused within a scene.
 *
 * The trains: with `n_trains` = 0 (`trains` is then ignored and may be NULL) the wind raises
 * `desc->wind.trains` trains by the library's seeded mapping (peak wavelength from the
 * Pierson-Moskowitz spectrum, the others spread within 30 degrees, amplitudes summing to H/2);
 * otherwise exactly the `n_trains` (at most 64) given trains are used, at full amplitude while
 * the wind is sustained (the wind then sets only the box and its lifecycle; each train's depth
 * sets its frequency, +INFINITY for deep water, and the terrain's depth effects apply on top).
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (`trains` is
 * checked only when `n_trains` > 0), `OCEAN_STATUS_NON_FINITE` for a NaN or infinite member
 * (`sustain` may be +INFINITY, a train's `depth` too), `OCEAN_STATUS_INVALID_ARGUMENT` for a
 * member out of range (zero wind speed, zero direction, width or fetch <= 0, negative
 * durations, `trains` outside 1 to 8, negative smoothing or recovery, `has_recovery` not 0 or
 * 1, more than 64 explicit trains, a box longer or wider than 2^24 grid spacings),
 * `OCEAN_STATUS_TOO_STEEP` if explicit trains have k*A > 1 each or a summed k*A above 1,
 * `OCEAN_STATUS_LENGTH_OVERFLOW` for an absurd `n_trains`, `OCEAN_STATUS_OUTSIDE_GRID` when
 * the box's rectangle at full fetch lies wholly outside the water grid. On failure nothing is
 * added and `*out_id` is unchanged.
 *
 * # Safety
 *
 * `desc` readable, `trains` NULL or `n_trains` readable
 * descriptions, `out_id` writable; nothing is retained.
 */
OceanStatus ocean_wtb_scene_add_box(struct OceanWtbScene *scene,
                                    const struct OceanBoxDesc *desc,
                                    const struct OceanWaveDesc *trains,
                                    size_t n_trains,
                                    uint32_t *out_id);

/**
 * Replaces box `id`'s description (same arguments as `ocean_wtb_scene_add_box`): move or turn it
 * (a boat's wake), change its wind or trains. A moved box's action points along its rays are
 * recomputed at the next evaluation.
 *
 * Returns `OCEAN_STATUS_NOT_FOUND` for an id that is not in the scene (removed, never issued)
 * and otherwise as `ocean_wtb_scene_add_box`. On failure the box is unchanged.
 *
 * # Safety
 *
 * As `ocean_wtb_scene_add_box`.
 */
OceanStatus ocean_wtb_scene_update_box(struct OceanWtbScene *scene,
                                       uint32_t id,
                                       const struct OceanBoxDesc *desc,
                                       const struct OceanWaveDesc *trains,
                                       size_t n_trains);

/**
 * Removes box `id`. Returns `OCEAN_STATUS_NOT_FOUND` for an id not in the scene (also when
 * it was removed already).
 */
OceanStatus ocean_wtb_scene_remove_box(struct OceanWtbScene *scene, uint32_t id);

/**
 * Stores the number of boxes in the scene (alive at any time or not) in `*out_count`.
 *
 * # Safety
 *
 * `out_count` must be writable.
 */
OceanStatus ocean_wtb_scene_box_count(const struct OceanWtbScene *scene, size_t *out_count);

/**
 * Enables and parameterises the effects (a budget may run fewer of them).
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER`, `OCEAN_STATUS_NON_FINITE` for a
 * NaN or infinite parameter of an enabled effect, `OCEAN_STATUS_INVALID_ARGUMENT` for an
 * unknown refraction, a flag other than 0 or 1, or a parameter out of its range (see
 * `OceanEffects`). On failure the scene keeps its effects.
 *
 * # Safety
 *
 * `effects` must be readable.
 */
OceanStatus ocean_wtb_scene_set_effects(struct OceanWtbScene *scene,
                                        const struct OceanEffects *effects);

/**
 * Removes any budget limit: every enabled train and effect runs (the default).
 */
OceanStatus ocean_wtb_scene_set_budget_unlimited(struct OceanWtbScene *scene);

/**
 * Limits each evaluation to about `seconds` of estimated work (paper section 2.3): culling
 * first, then trains rank by rank (every visible box's largest train, then its second, ...),
 * then the effects in the order refraction, shoaling, round waves, irregular height, beach,
 * and the noise last, each admitted while the estimate fits. `OceanFrameStats` reports the
 * choice.
 *
 * Returns `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `seconds`,
 * `OCEAN_STATUS_INVALID_ARGUMENT` for a negative one; the budget is then unchanged.
 */
OceanStatus ocean_wtb_scene_set_budget_seconds(struct OceanWtbScene *scene, double seconds);

/**
 * Fixes each evaluation's work explicitly: at most `max_trains` trains per box (its largest;
 * `SIZE_MAX` for all, 0 for none) and exactly the effects in `*effects` (validated as in
 * `ocean_wtb_scene_set_effects`), whatever the effects enabled with `ocean_wtb_scene_set_effects`.
 *
 * # Safety
 *
 * `effects` must be readable.
 */
OceanStatus ocean_wtb_scene_set_budget_explicit(struct OceanWtbScene *scene,
                                                size_t max_trains,
                                                const struct OceanEffects *effects);

/**
 * Evaluates the whole water grid at `time` seconds into the caller's buffers.
 *
 * For grid point (i, j), element j*nx + i of `out_pos` receives its displaced position
 * **relative to the grid origin** (rest position (i*spacing, 0, j*spacing), so float precision
 * does not degrade far from the world origin; add (origin_x, 0, origin_z) for world space),
 * and `out_normal` the unit surface normal (right-handed, y up). Each frame is recomputed from
 * the rest state (the paper's frame independence): any time may be evaluated in any order.
 * Boxes that are alive at `time` add their trains, modulated by land (zero on land, recovering
 * behind it), depth (shoaling, refraction), the side smoothing and the enabled effects; grid
 * points on land stay exactly at rest.
 *
 * `camera`: NULL for no culling, or the camera the frame is drawn with (`OceanCamera`). A box
 * whose bounding box (raised by the maximum heights of all boxes that overlap it) lies wholly
 * outside its frustum is skipped: its
 * points stay at rest in this frame. Height queries never cull.
 *
 * `n` must equal nx * nz. `out_stats`, when not NULL, receives what ran.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` for a bad pointer (4-byte
 * alignment for OceanVec3, 8 for the camera and stats), `OCEAN_STATUS_EMPTY` if `n`
 * is 0, `OCEAN_STATUS_LENGTH_OVERFLOW` if `n * sizeof(OceanVec3)` exceeds `PTRDIFF_MAX`,
 * `OCEAN_STATUS_LENGTH_MISMATCH` if `n` != nx * nz, `OCEAN_STATUS_INVALID_ARGUMENT` if the
 * outputs overlap or the camera is not one `OceanCamera` accepts, `OCEAN_STATUS_NON_FINITE`
 * for a NaN or infinite `time` or matrix element. Nothing is written on failure.
 *
 * # Safety
 *
 * `camera` NULL or a readable `OceanCamera`, `out_pos` and
 * `out_normal` `n` writable `OceanVec3`s each, `out_stats` NULL or writable; no other thread
 * may touch the buffers during the call.
 */
OceanStatus ocean_wtb_scene_evaluate(struct OceanWtbScene *scene,
                                     double time,
                                     const struct OceanCamera *camera,
                                     struct OceanVec3 *out_pos,
                                     struct OceanVec3 *out_normal,
                                     size_t n,
                                     struct OceanFrameStats *out_stats);

/**
 * `ocean_wtb_scene_evaluate` for buffers kept from frame to frame (an engine's vertex buffers):
 * only the part of the grid that the visible boxes cover now, or covered at the previous call,
 * is written, with exactly the values `ocean_wtb_scene_evaluate` would write; the rest of the
 * buffers already holds the sea at rest. A frame in which no box is visible, after one with
 * none either, writes nothing.
 *
 * Pass the same two buffers to every call. The first call after `ocean_wtb_scene_create` or
 * `ocean_wtb_scene_reset_coverage` writes the whole grid. With noise or run-up enabled the whole
 * grid changes and is written every time. Arguments, statuses and safety as for
 * `ocean_wtb_scene_evaluate`.
 *
 * # Safety
 *
 * As `ocean_wtb_scene_evaluate`.
 */
OceanStatus ocean_wtb_scene_evaluate_incremental(struct OceanWtbScene *scene,
                                                 double time,
                                                 const struct OceanCamera *camera,
                                                 struct OceanVec3 *out_pos,
                                                 struct OceanVec3 *out_normal,
                                                 size_t n,
                                                 struct OceanFrameStats *out_stats);

/**
 * Forgets what `ocean_wtb_scene_evaluate_incremental` wrote: its next call writes the whole grid.
 * Call it before passing other buffers.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` or `OCEAN_STATUS_MISALIGNED_POINTER` for a bad handle.
 */
OceanStatus ocean_wtb_scene_reset_coverage(struct OceanWtbScene *scene);

/**
 * Stores the library's default effects in `*out`: refraction `OCEAN_REFRACTION_PHASE_SHIFT`,
 * shoaling on, round waves, irregular height, noise and beach off (as a new scene has them).
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
 * then left unchanged.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_wtb_effects_default(struct OceanEffects *out);

/**
 * Stores a valid wind in `*out`: 10 m/s (H = 2.14 m fully developed, Eq. 1) towards +x from
 * the origin, a box 100 m wide with a fetch of 200 m, full from time 0 and never dying
 * (`sustain` = `INFINITY`), seed 0, 3 trains. Set at least the origin, direction and extent
 * for your grid.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
 * then left unchanged.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_wtb_wind_desc_default(struct OceanWindDesc *out);

/**
 * Stores a valid box in `*out`: the wind of `ocean_wtb_wind_desc_default`, edges smoothed
 * over 10 m (Fig. 4), and the default recovery behind land (two peak wavelengths:
 * `has_recovery` = 0).
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` (or `_MISALIGNED_POINTER`) for a bad `out`, which is
 * then left unchanged.
 *
 * # Safety
 *
 * `out` must be writable.
 */
OceanStatus ocean_wtb_box_desc_default(struct OceanBoxDesc *out);

/**
 * Answers `n` height queries at world (x, z) = `xz[k]` on the **drawn** surface, into
 * `out[k]`: the triangles of the grid that the last `ocean_wtb_scene_evaluate` or
 * `ocean_wtb_scene_evaluate_incremental` wrote, culling included (a culled box's water is drawn at
 * rest, and answered at rest). This is the surface to float objects on where the grid is what
 * is drawn.
 *
 * The mesh: each cell (i, j)-(i+1, j+1) of the grid is split along the diagonal from
 * (i+1, j) to (i, j+1) into the lower triangle (i, j), (i+1, j), (i, j+1) and the upper
 * triangle (i+1, j), (i+1, j+1), (i, j+1), counter-clockwise seen from above, over the
 * evaluated positions (index j*nx + i, relative to the grid origin). The answer is the height
 * of the triangle over (x, z), exact to double rounding of those float vertices (the library's
 * tests compare it with an independent intersection of the same triangles: within 1e-14 m).
 * Where the mesh folds over itself (crests steeper than the trochoid's limit) the highest
 * triangle is taken. Where no triangle lies over the point (beyond the grid, or past an edge
 * the waves pull inwards) the sea is at rest: height 0, normal +y, `covered` 0.
 *
 * The vertices are recomputed around the queries with the evaluation's own kernel, bit for bit
 * what it wrote; the caller's buffers are not read. A batch spread over the whole grid costs
 * about one evaluation of the grid; it is spread over the library's worker threads, and the
 * answers do not depend on their number.
 *
 * Returns `OCEAN_STATUS_NULL_POINTER` / `_MISALIGNED_POINTER` (8-byte alignment),
 * `OCEAN_STATUS_EMPTY` if `n` is 0, `OCEAN_STATUS_LENGTH_OVERFLOW` if
 * `n * sizeof(OceanDrawnSample)` exceeds `PTRDIFF_MAX`, `OCEAN_STATUS_INVALID_ARGUMENT` if `xz`
 * and `out` overlap, `OCEAN_STATUS_NON_FINITE` for a NaN or infinite coordinate (the message
 * gives the first bad index), `OCEAN_STATUS_NOT_EVALUATED` if the scene was never evaluated or
 * changed since its last evaluation (evaluate it again). Nothing is written on failure.
 *
 * # Safety
 *
 * `xz` `n` readable `OceanDVec2`s and `out` `n` writable
 * `OceanDrawnSample`s, untouched by other threads during the call.
 */
OceanStatus ocean_wtb_scene_heights_drawn(const struct OceanWtbScene *scene,
                                          const struct OceanDVec2 *xz,
                                          size_t n,
                                          struct OceanDrawnSample *out);

/**
 * Answers `n` height queries at world (x, z) = `xz[k]` and `time` seconds on the
 * **continuous** surface, into `out[k]`: the model between grid points (the same boxes, depth,
 * land, effects, budget and train filter as `ocean_wtb_scene_evaluate`, but never culled), the
 * limit of an ever finer grid, and what a renderer evaluating the trains per vertex of a
 * view-dependent grid approaches. The modulation and the height field are bilinear between
 * grid points; the surface is the image of the grid's rectangle, beyond which (and where an
 * edge is pulled inwards) the sea is at rest. Any time may be asked, evaluated or not: the
 * model needs no evaluation.
 *
 * Against the drawn mesh it differs inside cells by the triangles' linear interpolation of the
 * trains, about A (1 - cos(pi s / lambda)) for a train of amplitude A and wavelength lambda on
 * a grid of spacing s (a few millimetres for the paper's scenarios; the train filter keeps
 * trains shorter than a few cells out of both). Gerstner waves move points sideways, so the
 * rest position whose displaced point lies over the query is found by Newton's method to a
 * horizontal residual of at most 10 micrometres or for at most 16 steps (see
 * `OceanHeightSample::residual`), then the height and normal are taken there. The library's
 * tests hold it within 5 micrometres of a forward double-precision evaluation of the model.
 *
 * Statuses as `ocean_wtb_scene_heights_drawn`, without `OCEAN_STATUS_NOT_EVALUATED`, plus
 * `OCEAN_STATUS_NON_FINITE` for a NaN or infinite `time`. Nothing is written on failure.
 *
 * # Safety
 *
 * `xz` `n` readable `OceanDVec2`s and `out` `n` writable
 * `OceanHeightSample`s, untouched by other threads during the call.
 */
OceanStatus ocean_wtb_scene_heights_continuous(const struct OceanWtbScene *scene,
                                               double time,
                                               const struct OceanDVec2 *xz,
                                               size_t n,
                                               struct OceanHeightSample *out);

/**
 * Sets which trains the grid's geometry carries: each train's amplitude is weighted by
 * w = smoothstep((lambda / spacing - min_cells) / (max_cells - min_cells)), 0 below
 * `min_cells` grid cells per wavelength (the train is left out), 1 above `max_cells`, as the
 * lighting paper filters its waves on a grid cell (Bruneton et al. section 3.2). What the
 * geometry loses is reported by `OceanFrameStats` (`filtered_trains`, `removed_trains`,
 * `filtered_slope_variance`) for the BRDF's roughness. The default is 2 and 4 cells: below 2
 * (Nyquist) a mesh aliases a train, at 4 it still cuts 29 % off its crests between vertices.
 * Pass 0 and 0 to keep every train whole. Both height queries see the same filtered trains.
 *
 * Returns `OCEAN_STATUS_NON_FINITE` for a NaN or infinite threshold,
 * `OCEAN_STATUS_INVALID_ARGUMENT` unless 0 <= `min_cells` < `max_cells` <= 1e6 (or both 0);
 * nothing changes then.
 */
OceanStatus ocean_wtb_scene_set_train_filter(struct OceanWtbScene *scene,
                                             double min_cells,
                                             double max_cells);

#ifdef __cplusplus
}  // extern "C"
#endif  // __cplusplus

#endif  /* OCEAN_H */
