// SAO passes 4 and 5 (§2.4): the separable bilateral reconstruction over the packed texels,
// horizontal (packed in, packed out) then vertical (packed in, the final A out). The twin of
// ocean_sao::blur::BlurConstants::blur_pixel.
//
// At output pixel c with key k_c, tap t = −R..=R (in that order: the sums are formed in the
// CPU's order) reads the texel stride·t pixels away along the axis and weighs its A by
// gauss[|t|] · max(0, 1 − depth_scale·|k_t − k_c|). Taps outside the output and sky taps are
// skipped; a sky centre passes through unchanged (the paper's reverse depth test).

@group(0) @binding(1) var packed_in: texture_2d<u32>;
// blur_horizontal writes packed texels (A re-quantised to 8 bits, the key unchanged).
@group(0) @binding(2) var packed_out: texture_storage_2d<r32uint, write>;
// blur_vertical writes the final A.
@group(0) @binding(3) var ao_out: texture_storage_2d<r32float, write>;

// ocean_sao::pack::decode_key: q / 65535.
fn decode_key(q: u32) -> f32 {
    return f32(q) / 65535.0;
}

// Gaussian weight of tap |t| (unnormalised: the blur divides by the sum of the weights used).
fn gauss(t: u32) -> f32 {
    return params.gauss[t >> 2u][t & 3u];
}

fn blur_pixel(p: vec2<i32>, axis: vec2<i32>) -> f32 {
    let centre = textureLoad(packed_in, p, 0).x;
    let kq = texel_key(centre);
    if (kq == SKY_KEY) {
        return texel_ao(centre);
    }
    let kc = decode_key(kq);
    let r = i32(params.blur_radius);
    let stride = i32(params.blur_stride);
    let size = vec2<i32>(params.output_size);
    var sum = 0.0;
    var wsum = 0.0;
    for (var t = -r; t <= r; t++) {
        let q = p + axis * (t * stride);
        if (any(q < vec2<i32>(0, 0)) || any(q >= size)) {
            continue;
        }
        let tap = textureLoad(packed_in, q, 0).x;
        let tq = texel_key(tap);
        if (tq == SKY_KEY) {
            continue;
        }
        let w = gauss(u32(abs(t))) * max(1.0 - params.depth_scale * abs(decode_key(tq) - kc), 0.0);
        sum += w * texel_ao(tap);
        wsum += w;
    }
    // The centre tap always weighs gauss[0] > 0: wsum is never 0.
    return sum / wsum;
}

@compute @workgroup_size(8, 8)
fn blur_horizontal(@builtin(global_invocation_id) id: vec3<u32>) {
    if (any(id.xy >= params.output_size)) {
        return;
    }
    let p = vec2<i32>(id.xy);
    let a = blur_pixel(p, vec2<i32>(1, 0));
    let key = texel_key(textureLoad(packed_in, p, 0).x);
    textureStore(packed_out, p, vec4<u32>(pack_texel(a, key), 0u, 0u, 0u));
}

@compute @workgroup_size(8, 8)
fn blur_vertical(@builtin(global_invocation_id) id: vec3<u32>) {
    if (any(id.xy >= params.output_size)) {
        return;
    }
    let p = vec2<i32>(id.xy);
    textureStore(ao_out, p, vec4<f32>(blur_pixel(p, vec2<i32>(0, 1)), 0.0, 0.0, 0.0));
}
