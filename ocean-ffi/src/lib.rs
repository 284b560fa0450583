//! # ocean-ffi
//!
//! The C ABI of the ocean crates. `include/ocean.h` is generated from this crate by cbindgen
//! (`cbindgen.toml`); `tests/header.rs` fails when the checked-in header differs from a fresh
//! generation, and rewrites it when `OCEAN_BLESS=1`.
//!
//! The model is rustls-ffi:
//!
//! - Every fallible function returns an [`OceanStatus`] (`OCEAN_STATUS_OK` = 0) and writes its
//!   outputs through out-parameters, and only on success.
//! - A detailed message for the most recent failure on the calling thread is available from
//!   [`ocean_last_error_message`]; [`ocean_status_message`] gives a fixed text per code.
//! - Objects are opaque handles with `_create` / `_destroy` pairs: registered ids with a kind,
//!   never addresses, so a handle of another kind, a destroyed one or a second destroy is
//!   `OCEAN_STATUS_INVALID_HANDLE`, not undefined behaviour (`boundary::handle`).
//! - Every pointer is checked for NULL and alignment, every length for overflow, every float
//!   for NaN and infinity, and inputs whose results would not be finite are refused. The checks
//!   are written once, in the `boundary` module, in the order the header documents. No panic
//!   crosses the boundary: each function body runs inside `catch_unwind`, and a panic becomes
//!   `OCEAN_STATUS_PANIC`.
//!
//! `unsafe` cannot be forbidden in a C ABI crate; instead `unsafe_op_in_unsafe_fn` is denied,
//! functions that take raw pointers are `unsafe extern "C"` with a `# Safety` section (what the
//! caller must guarantee beyond what is checked), and the few `unsafe` blocks (turning checked
//! raw pointers into references and slices) each carry a `SAFETY:` comment.
#![deny(unsafe_op_in_unsafe_fn)]
#![deny(clippy::undocumented_unsafe_blocks)]
#![warn(missing_docs)]

mod boundary;
mod camera;
#[cfg(feature = "gpu")]
mod gpu;
mod lighting;
mod lighting_brdf;
mod lighting_sea;
mod lighting_sky_map;
mod lighting_spectrum;
#[doc(hidden)]
pub mod measure;
#[cfg(feature = "gpu")]
mod ocean_draw;
mod relief;
#[cfg(feature = "gpu")]
mod relief_draw;
mod relief_encode;
mod relief_enums;
mod relief_lod;
mod relief_mips;
mod relief_quad;
mod relief_trace;
mod sao;
mod sao_depth;
#[cfg(feature = "gpu")]
mod sao_gpu;
#[cfg(feature = "gpu")]
mod scene;
#[cfg(feature = "gpu")]
mod shader_export;
mod status;
mod version;
mod waves;
mod waves_domain;
mod wtb;
mod wtb_params;
mod wtb_query;

pub use boundary::{OceanChain, OceanNext};
pub use camera::{OceanCamera, OceanDepthConvention};
#[cfg(feature = "gpu")]
pub use gpu::{
    OceanGpuContext, OceanRenderer, OceanRendererOptions, ocean_gpu_context_create,
    ocean_gpu_context_describe, ocean_gpu_context_destroy, ocean_renderer_create,
    ocean_renderer_destroy, ocean_renderer_options_default, ocean_renderer_render_rgba8,
    ocean_renderer_set_lighting, ocean_renderer_set_spectrum,
};
pub use lighting::{
    OCEAN_SKY_MAP_EXTENT, OCEAN_SKY_MAP_MAX_SIZE, OCEAN_SKY_MAP_MIN_SIZE, OceanCieSky,
    OceanIrradiance, OceanLighting, OceanRgb, OceanSeaParams, OceanSkyParams,
    ocean_lighting_below_horizon_radiance, ocean_lighting_create, ocean_lighting_destroy,
    ocean_lighting_environment_radiance, ocean_lighting_irradiance, ocean_lighting_sea_radiance,
    ocean_lighting_sky_irradiance, ocean_lighting_sun_radiance, ocean_lighting_sun_solid_angle,
    ocean_sea_params_default, ocean_sky_params_default,
};
pub use lighting_brdf::{
    OCEAN_DEFAULT_EXPOSURE, OCEAN_WATER_R, ocean_effective_fresnel_fit,
    ocean_effective_fresnel_integral, ocean_effective_fresnel_table, ocean_linear_to_srgb,
    ocean_ross_brdf, ocean_schlick, ocean_sun_radiance, ocean_tone_map,
};
pub use lighting_sea::{OceanSeaColorInput, OceanSeaLight, ocean_sea_color, ocean_sea_color_batch};
pub use lighting_sky_map::{
    OceanSkyMap, ocean_lighting_sky_map_create, ocean_sky_map_copy_level, ocean_sky_map_destroy,
    ocean_sky_map_level_count, ocean_sky_map_level_info,
};
pub use lighting_spectrum::{
    OCEAN_FILTER_N_MAX, OCEAN_FILTER_N_MIN, OceanSlopeVariance, OceanSpectrum, OceanSpectrumParams,
    ocean_pixel_footprint, ocean_spectrum_clamped_count, ocean_spectrum_create,
    ocean_spectrum_destroy, ocean_spectrum_height_variance, ocean_spectrum_max_amplitude,
    ocean_spectrum_mean_height_shift, ocean_spectrum_params_default, ocean_spectrum_slope_variance,
    ocean_spectrum_steepness_sum, ocean_spectrum_total_slope_variance, ocean_spectrum_wave_count,
    ocean_spectrum_waves, ocean_spectrum_wind_direction,
};
#[cfg(feature = "gpu")]
pub use ocean_draw::{
    OCEAN_FRESNEL_TABLE_SIZE, OCEAN_SURFACE_UNIFORMS_SIZE, OCEAN_WAVE_TEXTURE_ROWS,
    OceanSurfaceDrawParams, ocean_surface_draw_params_default, ocean_surface_fresnel_texels,
    ocean_surface_uniforms, ocean_surface_wave_texels,
};
pub use relief::{
    OCEAN_RELIEF_MAX_RATIO_LIMIT, OCEAN_RELIEF_MAX_SIDE, OCEAN_RELIEF_MIN_SIDE,
    OCEAN_RELIEF_PROGRESS_BANDS, OceanReliefConeParams, OceanReliefCones, OceanReliefMap,
    OceanReliefProgress, ocean_relief_cone_params_default, ocean_relief_cones_create,
    ocean_relief_cones_destroy, ocean_relief_cones_encode, ocean_relief_cones_quantize,
    ocean_relief_cones_size, ocean_relief_cones_texels, ocean_relief_generate_encoded,
    ocean_relief_generate_texels, ocean_relief_map_create_f32, ocean_relief_map_create_u8,
    ocean_relief_map_create_u16, ocean_relief_map_depths, ocean_relief_map_destroy,
    ocean_relief_map_size, ocean_relief_normals,
};
#[cfg(feature = "gpu")]
pub use relief_draw::{
    OCEAN_RELIEF_UNIFORMS_SIZE, OceanReliefScene, ocean_relief_scene_default, ocean_relief_uniforms,
};
pub use relief_enums::{
    OceanReliefConeKind, OceanReliefEdge, OceanReliefEncoding, OceanReliefMip, OceanReliefRange,
};
pub use relief_lod::{
    ocean_relief_map_downsample, ocean_relief_mip_atlas_origin, ocean_relief_mip_atlas_size,
    ocean_relief_mip_level,
};
pub use relief_mips::{
    OceanReliefMips, ocean_relief_mips_copy_level, ocean_relief_mips_create,
    ocean_relief_mips_destroy, ocean_relief_mips_level_count, ocean_relief_mips_level_size,
};
pub use relief_quad::{
    OCEAN_RELIEF_QUAD_LAYERS, OCEAN_RELIEF_QUAD_X_NEG, OCEAN_RELIEF_QUAD_Y_NEG,
    OceanReliefQuadCones, ocean_relief_quad_cones_create, ocean_relief_quad_cones_destroy,
    ocean_relief_quad_cones_size, ocean_relief_quad_cones_texels,
    ocean_relief_quad_generate_texels, ocean_relief_quad_shadow, ocean_relief_quad_trace,
};
pub use relief_trace::{
    OCEAN_RELIEF_MAX_STEPS, OceanReliefHit, OceanReliefMethod, OceanReliefPoint, OceanReliefRay,
    OceanReliefSearch, OceanReliefTracer, ocean_relief_method_default, ocean_relief_ray_from_view,
    ocean_relief_shadow, ocean_relief_trace,
};
pub use sao::{
    OCEAN_SAO_MAX_SIDE, OCEAN_SAO_SKY_Z, OceanSao, OceanSaoBlurParams, OceanSaoBlurWeight,
    OceanSaoEstimator, OceanSaoInfo, OceanSaoMipFilter, OceanSaoNormals, OceanSaoParams,
    ocean_sao_create, ocean_sao_describe, ocean_sao_destroy, ocean_sao_params_default,
    ocean_sao_run, ocean_sao_view_z,
};
pub use sao_depth::OceanSaoDepth;
#[cfg(feature = "gpu")]
pub use sao_gpu::{
    OCEAN_SAO_UNIFORMS_SIZE, OceanSaoGpu, ocean_sao_gpu_create, ocean_sao_gpu_destroy,
    ocean_sao_gpu_run, ocean_sao_uniforms,
};
#[cfg(feature = "gpu")]
pub use scene::{
    OceanScene, OceanSceneCamera, OceanSceneOptions, ocean_scene_builtin_description,
    ocean_scene_create, ocean_scene_destroy, ocean_scene_options_default, ocean_scene_render_rgba8,
    ocean_scene_size,
};
#[cfg(feature = "gpu")]
pub use shader_export::{
    OCEAN_NO_GLSL_BINDING, OceanBindingKind, OceanShaderBinding, OceanShaderExport,
    OceanShaderLanguage, OceanShaderStage, ocean_shader_count, ocean_shader_export,
    ocean_shader_export_binding, ocean_shader_export_binding_count, ocean_shader_export_bindings,
    ocean_shader_export_destroy, ocean_shader_export_file, ocean_shader_export_file_count,
    ocean_shader_export_file_stage, ocean_shader_name,
};
pub use status::{OceanStatus, ocean_last_error_message, ocean_status_message};
pub use version::{
    OCEAN_VERSION, OCEAN_VERSION_MAJOR, OCEAN_VERSION_MINOR, OCEAN_VERSION_PATCH,
    ocean_check_version, ocean_version, ocean_version_number,
};
pub use waves::{
    OceanDVec2, OceanDVec3, OceanGrid, OceanVec3, OceanWaveDesc, OceanWaves, ocean_waves_count,
    ocean_waves_create, ocean_waves_destroy, ocean_waves_evaluate, ocean_waves_evaluate_grid,
    ocean_waves_max_amplitude, ocean_waves_steepness_sum,
};
pub use wtb::{
    OceanWtbScene, ocean_wtb_scene_add_box, ocean_wtb_scene_box_count, ocean_wtb_scene_create,
    ocean_wtb_scene_destroy, ocean_wtb_scene_evaluate, ocean_wtb_scene_evaluate_incremental,
    ocean_wtb_scene_remove_box, ocean_wtb_scene_reset_coverage,
    ocean_wtb_scene_set_budget_explicit, ocean_wtb_scene_set_budget_seconds,
    ocean_wtb_scene_set_budget_unlimited, ocean_wtb_scene_set_effects, ocean_wtb_scene_set_terrain,
    ocean_wtb_scene_update_box,
};
pub use wtb_params::{
    OceanBeach, OceanBoxDesc, OceanEffects, OceanFrameStats, OceanIrregular, OceanNoise,
    OceanRefraction, OceanWaterGridDesc, OceanWindDesc, ocean_wtb_box_desc_default,
    ocean_wtb_effects_default, ocean_wtb_wind_desc_default,
};
pub use wtb_query::{
    OceanDrawnSample, OceanHeightSample, ocean_wtb_scene_heights_continuous,
    ocean_wtb_scene_heights_drawn, ocean_wtb_scene_set_train_filter,
};
