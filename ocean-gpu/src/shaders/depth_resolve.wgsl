// The depth of a multisampled frame for passes that read one depth per pixel, such as an
// ambient obscurance: each pixel's nearest sample, written as the pixel's depth by a
// full-screen triangle (no colour target, depth compare Always). Driven by
// `ocean_gpu::DepthResolve`.
//
// The nearest, not a fixed sample: along a silhouette a fixed sample lies on the near surface
// in some pixels and on the far one in the next, and the obscurance read from that depth
// would draw the edge as a dotted line. The nearest sample gives every pixel an edge crosses
// the surface in front, whose light dominates what the obscurance scales there. Forward depth
// (near 0) takes the minimum, reversed depth (near 1) the maximum. The sample count is 4,
// WebGPU's one multisample count. The depth is bound as an unfilterable float texture (WebGPU
// allows it for depth formats): naga's GLSL writer cannot load from depth textures.

@group(0) @binding(0) var depth_ms: texture_multisampled_2d<f32>;

@vertex
fn resolve_vs(@builtin(vertex_index) index: u32) -> @builtin(position) vec4<f32> {
    // (−1, −1), (3, −1), (−1, 3): one triangle over the viewport.
    let corner = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    return vec4<f32>(2.0 * corner - vec2<f32>(1.0), 0.0, 1.0);
}

@fragment
fn nearest_forward_fs(@builtin(position) pixel: vec4<f32>) -> @builtin(frag_depth) f32 {
    let p = vec2<i32>(pixel.xy);
    var d = textureLoad(depth_ms, p, 0).x;
    for (var i = 1; i < 4; i++) {
        d = min(d, textureLoad(depth_ms, p, i).x);
    }
    return d;
}

@fragment
fn nearest_reversed_fs(@builtin(position) pixel: vec4<f32>) -> @builtin(frag_depth) f32 {
    let p = vec2<i32>(pixel.xy);
    var d = textureLoad(depth_ms, p, 0).x;
    for (var i = 1; i < 4; i++) {
        d = max(d, textureLoad(depth_ms, p, i).x);
    }
    return d;
}
