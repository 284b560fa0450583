// SAO passes 4 and 5 (§2.4): the separable bilateral reconstruction over the packed texels,
// horizontal (packed in, packed out) then vertical (packed in, the final A out). The twin of
// ocean_sao::blur::BlurConstants::blur_pixel.
//
// At output pixel c with key k_c, tap t = −R..=R (in that order: the sums are formed in the
// CPU's order) reads the texel p = stride·t pixels away along the axis and weighs its A by
// gauss[|t|] · max(0, 1 − depth_scale·|k_t − k_ref|), k_ref being k_c (the paper) or, with
// params.blur_plane, the key the plane through the centre predicts at the tap (see
// ocean_sao::blur: u = 1/k affine in perspective, k in orthographic; the slope from the gentler
// of the two adjacent pixels, one key step of slope error per pixel allowed). Taps outside the output and sky taps are skipped; a sky centre
// passes through unchanged (the paper's reverse depth test).

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

// ocean_sao::blur's MIN_PLANE_KEY: half a key step.
const MIN_PLANE_KEY: f32 = 7.629511e-6;

// The packed texel at q, or SKY_KEY's texel where q is outside the output.
fn load_texel(q: vec2<i32>) -> u32 {
    if (any(q < vec2<i32>(0, 0)) || any(q >= vec2<i32>(params.output_size))) {
        return 0xffffff00u;
    }
    return textureLoad(packed_in, q, 0).x;
}

// BlurConstants::plane_u.
fn plane_u(k: f32) -> f32 {
    if (params.perspective != 0u) {
        return 1.0 / max(k, MIN_PLANE_KEY);
    }
    return k;
}

// BlurConstants::plane_key; f32::MAX (no weight unless depth_scale is 0) where a perspective plane has no point.
fn plane_key(uc: f32, s: f32, p: f32) -> f32 {
    let u = uc + p * s;
    if (params.perspective == 0u) {
        return u;
    }
    if (u > 0.0) {
        return 1.0 / u;
    }
    return 3.4028235e38;
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
    var uc = 0.0;
    var slope = 0.0;
    let plane = params.blur_plane != 0u;
    if (plane) {
        uc = plane_u(kc);
        let lq = texel_key(load_texel(p - axis));
        let rq = texel_key(load_texel(p + axis));
        let l = uc - plane_u(decode_key(lq));
        let rs = plane_u(decode_key(rq)) - uc;
        if (lq != SKY_KEY && rq != SKY_KEY) {
            slope = select(l, rs, abs(rs) < abs(l));
        } else if (lq != SKY_KEY) {
            slope = l;
        } else if (rq != SKY_KEY) {
            slope = rs;
        }
    }
    // The plane weight's fade with world distance (BlurConstants::blur_pixel).
    var fp = abs(params.scale.x);
    if (axis.y != 0) {
        fp = abs(params.scale.y);
    }
    let zc = kc * params.z_min;
    var lateral = fp;
    if (params.perspective != 0u) {
        lateral = fp * abs(zc);
    }
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
        // The centre compares with itself exactly; a plane prediction is allowed one key step
        // of slope error per pixel of distance.
        var deviation = abs(decode_key(tq) - kc);
        if (plane && t != 0) {
            let k_ref = plane_key(uc, slope, f32(t * stride));
            deviation = max(abs(decode_key(tq) - k_ref) - f32(abs(t * stride)) / 65535.0, 0.0);
        }
        var w = gauss(u32(abs(t))) * max(1.0 - params.depth_scale * deviation, 0.0);
        if (plane && params.inv_blur_extent > 0.0) {
            let dz = decode_key(tq) * params.z_min - zc;
            let dl = f32(t * stride) * lateral;
            let d = sqrt(dl * dl + dz * dz);
            w *= max(1.0 - d * params.inv_blur_extent, 0.0);
        }
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
