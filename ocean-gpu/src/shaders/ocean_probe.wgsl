// Probes of the ocean renderer: compute entry points that run the renderer's own functions
// (ocean_common.wgsl, ocean_light.wgsl) on a list of inputs and write what they return, so the
// parity tests compare exactly what the vertex and fragment stages compute with the CPU twins.
// Assembled after grid_normal.wgsl, ocean_common.wgsl and ocean_light.wgsl; driven by
// `OceanRenderer::probe_surface` and `OceanRenderer::probe_sea_color`.
//
// One invocation per item, 64 per workgroup, item index global_invocation_id.x; frame.probe.x
// items.

@group(0) @binding(4) var<storage, read> inputs: array<vec4<f32>>;
@group(0) @binding(5) var<storage, read_write> outputs: array<vec4<f32>>;

// Item k: inputs[k] = (pixel x, pixel y, 0, 0). Writes five vec4 at outputs[5k..5k + 5]:
//   0: the vertex stage's displaced position (x, world y, z; x, z relative to o), waves summed;
//   1: its rest position (x, z relative to o), its cell footprint L, the fragment footprint l;
//   2: the fragment stage's normal (Eq. 3), waves summed;
//   3: its slope variances σ_x², σ_y² (Eq. 4), its normal-only variances;
//   4: its geometry normal, 0.
// The fragment stage's quantities are `grid_light`'s: footprints l and cell_px · l.
@compute @workgroup_size(64)
fn probe_surface(@builtin(global_invocation_id) id: vec3<u32>) {
    let k = id.x;
    if k >= frame.probe.x {
        return;
    }
    let pixel = inputs[k].xy;
    let g = grid_point(pixel);
    let l = pixel_footprint(pixel);
    let s = pixel_surface(g.rest, l, frame.grid.x * l);
    outputs[5u * k] = vec4<f32>(g.position, f32(g.count));
    outputs[5u * k + 1u] = vec4<f32>(g.rest, g.cell, l);
    outputs[5u * k + 2u] = vec4<f32>(s.normal, f32(s.count));
    outputs[5u * k + 3u] = vec4<f32>(s.variance, s.normal_only);
    outputs[5u * k + 4u] = vec4<f32>(s.geometry_normal, 0.0);
}

// Item k: inputs[5k..5k + 5] = (v, 0), (n, 0), (wind x, wind z, σ_x², σ_y²), (n_geo, 0),
// (normal-only σ_x², σ_y², 0, 0). Writes the three terms of Algorithm 5.1 for the masking-aware
// normal (`visible_normal`, as the fragment stages call it) at outputs[3k..3k + 3]: (I_sun, 0),
// (I_sky, 0), (I_sea, 0).
@compute @workgroup_size(64)
fn probe_sea_color(@builtin(global_invocation_id) id: vec3<u32>) {
    let k = id.x;
    if k >= frame.probe.x {
        return;
    }
    let v = inputs[5u * k].xyz;
    let n = inputs[5u * k + 1u].xyz;
    let w = inputs[5u * k + 2u];
    let n_geo = inputs[5u * k + 3u].xyz;
    let normal_only = inputs[5u * k + 4u].xy;
    let light = sea_color(v, visible_normal(v, n, n_geo, w.xy, normal_only, w.zw), w.xy, w.zw);
    outputs[3u * k] = vec4<f32>(light.sun, 0.0);
    outputs[3u * k + 1u] = vec4<f32>(light.sky, 0.0);
    outputs[3u * k + 2u] = vec4<f32>(light.sea, 0.0);
}
