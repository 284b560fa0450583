// The relief texture of a quad-directional cone map (with relief_common.wgsl; GPU Gems 3
// section 18.1's four cones per texel, ocean_relief::quad): an rgba32float N x N texture array
// of 4 layers, layer k texel (i, j) = [depth, c_k, D_k, E_k], the cones of the closed quadrant
// k = x_neg + 2 y_neg of the ray's horizontal direction (ocean_relief::QuadReliefTexture), and
// its mip levels (ocean_relief::QuadReliefMips) packed into one atlas per layer
// (relief_common.wgsl).
// relief_common.wgsl reads the texture only through these two functions.

@group(0) @binding(1) var relief_map: texture_2d_array<f32>;

// The layer of the ray whose direction scaled to z = 1 is (dx, dy), chosen once per ray
// (Quadrant::of): a negative component picks the negative side, 0 and -0 the positive one,
// whose closed quadrant holds it.
fn relief_layer(dx: f32, dy: f32) -> i32 {
    return select(0, 1, dx < 0.0) + select(0, 2, dy < 0.0);
}

// Texel (i, j) (indices resolved inside the level) of the layer, at the fragment's level.
fn relief_texel(layer: i32, i: i32, j: i32) -> vec4<f32> {
    return textureLoad(relief_map, relief_origin + vec2<i32>(i, j), layer, 0);
}

// The texture's width in texels (the side N, or 3N/2 for an atlas of levels), known only
// when the shader runs (relief_ctl).
fn relief_side() -> u32 {
    return textureDimensions(relief_map).x;
}
