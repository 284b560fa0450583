// The relief texture of the isotropic cone map (with relief_common.wgsl): one rgba32float
// N x N texture, texel (i, j) = [depth, cone ratio, clearance, near cap]
// (ocean_relief::ReliefTexture), and its mip levels (ocean_relief::ReliefMips) packed
// into one atlas (relief_common.wgsl). Its twin relief_texture_quad.wgsl declares the quadrant
// layers; relief_common.wgsl reads the texture only through these two functions.

@group(0) @binding(1) var relief_map: texture_2d<f32>;

// The cones serve every direction: one layer.
fn relief_layer(dx: f32, dy: f32) -> i32 {
    return 0;
}

// Texel (i, j) (indices resolved inside the level) of the layer, at the fragment's level.
fn relief_texel(layer: i32, i: i32, j: i32) -> vec4<f32> {
    return textureLoad(relief_map, relief_origin + vec2<i32>(i, j), 0);
}

// The texture's width in texels (the side N, or 3N/2 for an atlas of levels), known only
// when the shader runs (relief_ctl).
fn relief_side() -> u32 {
    return textureDimensions(relief_map).x;
}
