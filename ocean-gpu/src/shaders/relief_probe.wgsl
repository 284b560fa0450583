// Probes of the relief tracers (after relief_common.wgsl): the draw pass's own functions run on
// a list of rays, so the parity tests compare them with the CPU tracers directly; and a copy of
// a depth texture into a buffer (the headless image's depth readback).

// Per item, five vec4s: (start u, start v, depth scale, shadow bias), (tangent-space view
// vector, 0), (the point the shadow test is made for: u, v, depth, 0), (tangent-space light
// direction, 0), (the texture coordinates' screen derivatives du.xy, dv.xy: the footprint the
// draw pass would take the level of detail from).
@group(0) @binding(2) var<storage, read> probe_in: array<vec4<f32>>;
// Per item, two vec4s: (hit u, v, depth, fetches), (1 in shadow / 0 lit, the light ray's hit
// depth, its fetches, the level read).
@group(0) @binding(3) var<storage, read_write> probe_out: array<vec4<f32>>;

@compute @workgroup_size(64)
fn probe_trace(@builtin(global_invocation_id) id: vec3<u32>) {
    let k = id.x;
    if k >= relief.steps.w {
        return;
    }
    let ray = probe_in[5u * k];
    let view = probe_in[5u * k + 1u].xyz;
    let point = probe_in[5u * k + 2u].xyz;
    let light = probe_in[5u * k + 3u].xyz;
    let footprint = probe_in[5u * k + 4u];
    // As the draw pass does, once, before the tracers' loops.
    relief_use_level(relief_lod(footprint.xy, footprint.zw));
    let hit = relief_trace(ray.xy, relief_view_ray(view, ray.z));
    let shadow = relief_shadow(point, light, ray.z, ray.w);
    probe_out[2u * k] = vec4<f32>(hit.pos, f32(hit.fetches));
    probe_out[2u * k + 1u] = vec4<f32>(shadow, f32(relief_level));
}

// The depth texture a headless render wrote (its depth aspect, bound as an unfilterable float
// texture: GLSL cannot textureLoad a depth texture), row-major into probe_out (x: the depth),
// for a width of relief.steps.w texels.
@group(0) @binding(4) var depth_in: texture_2d<f32>;

@compute @workgroup_size(8, 8)
fn copy_depth(@builtin(global_invocation_id) id: vec3<u32>) {
    let size = textureDimensions(depth_in);
    if id.x >= size.x || id.y >= size.y {
        return;
    }
    let d = textureLoad(depth_in, vec2<i32>(id.xy), 0).x;
    probe_out[id.y * relief.steps.w + id.x] = vec4<f32>(d, 0.0, 0.0, 0.0);
}
