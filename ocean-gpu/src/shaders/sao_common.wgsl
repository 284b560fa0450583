// Shared by the Scalable Ambient Obscurance passes (McGuire, Mara & Luebke 2012), prepended to
// each of them: the parameter block and the constants the CPU reference (crate ocean-sao) uses.
// Every pass follows the CPU's arithmetic operation by operation; the comments name the CPU
// function each piece mirrors.

// Byte for byte ocean_sao::gpu_params::SaoUniforms (304 bytes, std140 rows).
struct Params {
    // Eq. 2: z(d) = (c.x + c.w * d) / (c.y * d + c.z).
    z_c: vec4<f32>,
    // Eq. 3: C = ((scale.x * u + offset.x) * m, (scale.y * v + offset.y) * m, z).
    scale: vec2<f32>,
    offset: vec2<f32>,
    input_size: vec2<u32>,
    output_size: vec2<u32>,
    guard: u32,
    perspective: u32,
    far_depth: f32,
    mip_origin: u32,
    radius_pixels: f32,
    radius2: f32,
    inv_radius2: f32,
    epsilon: f32,
    samples: u32,
    inv_samples: f32,
    two_pi_turns: f32,
    mip_switch_log2: u32,
    max_mip: u32,
    mip_filter: u32,
    estimator: u32,
    strength: f32,
    beta: f32,
    k: f32,
    normal_limit: f32,
    quad_threshold: f32,
    normal_rejection: u32,
    quad_filter: u32,
    inv_z_min: f32,
    blur_radius: u32,
    blur_stride: u32,
    depth_scale: f32,
    blur_plane: u32,
    normals_nearest: u32,
    inv_blur_extent: f32,
    z_min: f32,
    _pad0: u32,
    _pad1: u32,
    gauss: array<vec4<f32>, 8>,
}

@group(0) @binding(0) var<uniform> params: Params;

// ocean_sao::SKY_Z: camera-space z of background pixels (finite, so the MIP filters and the
// cross products of Eq. 4 stay finite).
const SKY_Z: f32 = -1.0e9;

// ocean_sao::pack::SKY_KEY and MAX_KEY: the 16-bit depth keys of the packing.
const SKY_KEY: u32 = 65535u;
const MAX_KEY: u32 = 65534u;

// Each pass runs 8 × 8 invocations per workgroup over its image; the sample pass relies on the
// workgroups starting at even coordinates (its 2×2 quads never straddle two workgroups).
const TILE: u32 = 8u;

// ocean_sao::pack::quantise_ao: round(clamp(A, 0, 1) * 255) (written so that NaN goes to 0).
fn quantise_ao(a: f32) -> u32 {
    var c = 0.0;
    if (a > 0.0) {
        c = min(a, 1.0);
    }
    return u32(c * 255.0 + 0.5);
}

// A packed texel is ocean_sao::pack::Texel [A, key >> 8, key & 255, 255] as one little-endian
// r32uint word: the bytes an RGBA8 texel would hold, read and written without any float
// conversion.

// ocean_sao::pack::dequantise_ao of the texel's A byte.
fn texel_ao(t: u32) -> f32 {
    return f32(t & 255u) / 255.0;
}

// ocean_sao::pack::texel_key.
fn texel_key(t: u32) -> u32 {
    return (((t >> 8u) & 255u) << 8u) | ((t >> 16u) & 255u);
}

// ocean_sao::pack::pack.
fn pack_texel(a: f32, key: u32) -> u32 {
    return quantise_ao(a) | ((key >> 8u) << 8u) | ((key & 255u) << 16u) | (255u << 24u);
}
