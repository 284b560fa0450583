// SAO pass 1 (§2.2): camera-space z of every input pixel from the depth buffer (Eq. 2), into
// level 0 of the z hierarchy. The twin of ocean_sao::ZConstants::z (the host checks an uploaded
// depth slice as ZConstants::z_pass does; a caller's depth texture is trusted to hold values
// of the convention's range, as a rasteriser writes them).

// The caller's depth: a Depth32Float / Depth24Plus / Depth16Unorm texture (its depth aspect)
// or an R32Float texture, read unfiltered.
@group(0) @binding(1) var depth_in: texture_2d<f32>;
@group(0) @binding(2) var z_out: texture_storage_2d<r32float, write>;

// Eq. 2 in the general form (c.x + c.w * d) / (c.y * d + c.z) (c.w = 0 for every perspective:
// exactly the paper's c0 / (d * c1 + c2)); the far end of the range is sky, and nothing goes
// below SKY_Z.
fn z_of_depth(d: f32) -> f32 {
    if (d == params.far_depth) {
        return SKY_Z;
    }
    let c = params.z_c;
    return max((c.x + c.w * d) / (c.y * d + c.z), SKY_Z);
}

@compute @workgroup_size(8, 8)
fn z_pass(@builtin(global_invocation_id) id: vec3<u32>) {
    if (any(id.xy >= params.input_size)) {
        return;
    }
    let p = vec2<i32>(id.xy);
    let d = textureLoad(depth_in, p, 0).x;
    textureStore(z_out, p, vec4<f32>(z_of_depth(d), 0.0, 0.0, 0.0));
}
