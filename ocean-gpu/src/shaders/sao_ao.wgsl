// SAO pass 3 (§2.3): the distributed AO sample pass, the 2×2 quad bilateral and the packing
// of A and z, over the output rectangle. The twin of ocean_sao::sample::sample_pixel, then
// ocean_sao::sample::quad_bilateral and ocean_sao::pack::pack_pass.
//
// Each invocation is one output pixel (x, y) at input pixel (x + guard, y + guard):
//
// 1. C from level-0 z (Eq. 3), the face normal from 2×2 quad differences (Eq. 4), the screen
//    radius r' (Eq. 5), the rotation φ (Eq. 8, reduced modulo 2π in integer-sized steps);
// 2. for each of the s spiral samples (Eq. 6–7): the tap pixel (each offset truncated toward
//    zero), skipped outside the input; its MIP level (Eq. 9: the highest set bit of the radius
//    in pixels, never log2 of a fraction); z from that level (Eq. 10); Q at the position the
//    texel stands for (the rotated grid's source pixel, else the footprint's centre); the
//    estimator's term (Eq. 1 or the appendix) inside the ball;
// 3. the quad bilateral: horizontal pairs, then vertical pairs, through workgroup memory (a
//    workgroup is 8 × 8 pixels at even coordinates, so every quad lies inside one);
// 4. A and the 16-bit depth key packed into one r32uint word.
//
// The z levels are separate textures (see sao_mip.wgsl); levels beyond the hierarchy built are
// bound to its last level and never read (Eq. 9 clamps to params.max_mip).

@group(0) @binding(1) var z0: texture_2d<f32>;
@group(0) @binding(2) var z1: texture_2d<f32>;
@group(0) @binding(3) var z2: texture_2d<f32>;
@group(0) @binding(4) var z3: texture_2d<f32>;
@group(0) @binding(5) var z4: texture_2d<f32>;
@group(0) @binding(6) var z5: texture_2d<f32>;
@group(0) @binding(7) var z6: texture_2d<f32>;
@group(0) @binding(8) var z7: texture_2d<f32>;
@group(0) @binding(9) var z8: texture_2d<f32>;
@group(0) @binding(10) var z9: texture_2d<f32>;
@group(0) @binding(11) var z10: texture_2d<f32>;
@group(0) @binding(12) var z11: texture_2d<f32>;
@group(0) @binding(13) var z12: texture_2d<f32>;
@group(0) @binding(14) var z13: texture_2d<f32>;
@group(0) @binding(15) var packed_out: texture_storage_2d<r32uint, write>;
// Written by the ao_stages entry point only (parity tests and debugging).
@group(0) @binding(16) var raw_out: texture_storage_2d<r32float, write>;
@group(0) @binding(17) var quad_out: texture_storage_2d<r32float, write>;

const ESTIMATOR_ALCHEMY: u32 = 0u;
const FILTER_ROTATED_GRID: u32 = 0u;

// ocean_sao::spiral::HASH_BYTE_TURNS: 2^(8k) mod 2π for k = 0..4, and 2π, 1/2π as f32.
const HASH_BYTE_TURN_0: f32 = 1.0;
const HASH_BYTE_TURN_1: f32 = 4.672588;
const HASH_BYTE_TURN_2: f32 = 2.3772461;
const HASH_BYTE_TURN_3: f32 = 5.3892164;
const TWO_PI: f32 = 6.2831855;
const INV_TWO_PI: f32 = 0.15915494;

// ocean_core::sincos's constants: 2/π, π/2 in three parts, Cephes' minimax coefficients.
const FRAC_2_PI: f32 = 0.63661975;
const PIO2_HI: f32 = 1.5703125;
const PIO2_MID: f32 = 4.837513e-4;
const PIO2_LO: f32 = 7.54979e-8;
const S1: f32 = -1.6666655e-1;
const S2: f32 = 8.332161e-3;
const S3: f32 = -1.9515296e-4;
const C1: f32 = 4.1666646e-2;
const C2: f32 = -1.3887316e-3;
const C3: f32 = 2.4433157e-5;

// The largest screen radius, pixels (ocean_sao::ProjectionInfo::screen_radius): keeps the i32
// conversions of the tap offsets defined.
const MAX_SCREEN_RADIUS: f32 = 16777216.0;

var<workgroup> tile_a: array<f32, 64>;
var<workgroup> tile_z: array<f32, 64>;

// z at texel p of level m (Eq. 10's z^m).
fn load_z(m: u32, p: vec2<i32>) -> f32 {
    switch (m) {
        case 0u: {
            return textureLoad(z0, p, 0).x;
        }
        case 1u: {
            return textureLoad(z1, p, 0).x;
        }
        case 2u: {
            return textureLoad(z2, p, 0).x;
        }
        case 3u: {
            return textureLoad(z3, p, 0).x;
        }
        case 4u: {
            return textureLoad(z4, p, 0).x;
        }
        case 5u: {
            return textureLoad(z5, p, 0).x;
        }
        case 6u: {
            return textureLoad(z6, p, 0).x;
        }
        case 7u: {
            return textureLoad(z7, p, 0).x;
        }
        case 8u: {
            return textureLoad(z8, p, 0).x;
        }
        case 9u: {
            return textureLoad(z9, p, 0).x;
        }
        case 10u: {
            return textureLoad(z10, p, 0).x;
        }
        case 11u: {
            return textureLoad(z11, p, 0).x;
        }
        case 12u: {
            return textureLoad(z12, p, 0).x;
        }
        default: {
            return textureLoad(z13, p, 0).x;
        }
    }
}

// Size of level m: max(1, size >> m), the sizes of ocean_sao::ZHierarchy (and of a MIP chain).
fn level_size(m: u32) -> vec2<i32> {
    return max(vec2<i32>(params.input_size >> vec2<u32>(m, m)), vec2<i32>(1, 1));
}

// glam's Vec3::dot and Vec3::cross, in the same order (no builtin whose order is unspecified).
// Sums of more than two terms are accumulated in a `var`, one statement per term, so that a
// GLSL compiler cannot rebalance them (see sao_mip.wgsl).
fn dot3(a: vec3<f32>, b: vec3<f32>) -> f32 {
    var s = a.x * b.x + a.y * b.y;
    s += a.z * b.z;
    return s;
}

fn cross3(a: vec3<f32>, b: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y);
}

// Finite (not ±∞, not NaN), from the bits: a comparison could be folded away by a compiler
// that assumes finite arithmetic.
fn is_finite(v: f32) -> bool {
    return (bitcast<u32>(v) & 0x7f800000u) != 0x7f800000u;
}

// Eq. 3 at the continuous input position (u, v) (ProjectionInfo::position_at).
fn position_at(u: f32, v: f32, z: f32) -> vec3<f32> {
    var m = 1.0;
    if (params.perspective != 0u) {
        m = z;
    }
    return vec3<f32>(
        (params.scale.x * u + params.offset.x) * m,
        (params.scale.y * v + params.offset.y) * m,
        z,
    );
}

// Eq. 3 at the centre of input pixel (x, y) (ProjectionInfo::position).
fn position(p: vec2<i32>, z: f32) -> vec3<f32> {
    return position_at(f32(p.x) + 0.5, f32(p.y) + 0.5, z);
}

// Eq. 5 (ProjectionInfo::screen_radius): r' = r·S'/(−z), clamped to [0, 2^24].
fn screen_radius(z: f32) -> f32 {
    var r = params.radius_pixels;
    if (params.perspective != 0u) {
        r = params.radius_pixels / -z;
    }
    if (r > 0.0) {
        return min(r, MAX_SCREEN_RADIUS);
    }
    return 0.0;
}

// The quad partner of output coordinate o along an axis of `len` input pixels
// (ocean_sao::reconstruct::face_normal, NormalEstimate::Quad): o ^ 1, or o − 1 when o ^ 1 falls
// outside the input. Returned as an input coordinate.
fn partner(o: u32, len: u32) -> i32 {
    let p = o ^ 1u;
    if (p + params.guard < len) {
        return i32(p + params.guard);
    }
    return i32(o - 1u + params.guard);
}

// The adjacent input coordinate nearer in z to z_c along an axis (NormalEstimate::Nearest):
// i − 1 when it is inside and strictly nearer than i + 1, or when i + 1 is outside.
fn nearest(i: i32, len: i32, z_c: f32, z_lo: f32, z_hi: f32) -> i32 {
    if (i + 1 >= len) {
        return i - 1;
    }
    if (i == 0) {
        return i + 1;
    }
    if (abs(z_lo - z_c) < abs(z_hi - z_c)) {
        return i - 1;
    }
    return i + 1;
}

// Eq. 4 (ocean_sao::reconstruct::face_normal): normalize(∂C/∂y' × ∂C/∂x') from differences of
// level-0 z to the quad partners or the nearer neighbours, with the optional rejection at depth
// edges. w = 1 for a valid normal, 0 for an undefined or rejected one.
fn face_normal(o: vec2<u32>, pc: vec2<i32>, c: vec3<f32>) -> vec4<f32> {
    var px = vec2<i32>(partner(o.x, params.input_size.x), pc.y);
    var py = vec2<i32>(pc.x, partner(o.y, params.input_size.y));
    if (params.normals_nearest != 0u) {
        let size = vec2<i32>(params.input_size);
        let last = size - vec2<i32>(1, 1);
        // Loads clamped into the input; a clamped value is never chosen (nearest checks the
        // bounds first).
        let zl = textureLoad(z0, vec2<i32>(max(pc.x - 1, 0), pc.y), 0).x;
        let zr = textureLoad(z0, vec2<i32>(min(pc.x + 1, last.x), pc.y), 0).x;
        let zu = textureLoad(z0, vec2<i32>(pc.x, max(pc.y - 1, 0)), 0).x;
        let zd = textureLoad(z0, vec2<i32>(pc.x, min(pc.y + 1, last.y)), 0).x;
        px = vec2<i32>(nearest(pc.x, size.x, c.z, zl, zr), pc.y);
        py = vec2<i32>(pc.x, nearest(pc.y, size.y, c.z, zu, zd));
    }
    let cx = position(px, textureLoad(z0, px, 0).x);
    let cy = position(py, textureLoad(z0, py, 0).x);
    var dx = c - cx;
    if (px.x > pc.x) {
        dx = cx - c;
    }
    var dy = c - cy;
    if (py.y > pc.y) {
        dy = cy - c;
    }
    let n = cross3(dy, dx);
    let len = sqrt(dot3(n, n));
    if (len == 0.0 || !is_finite(len)) {
        return vec4<f32>(0.0);
    }
    if (params.normal_rejection != 0u) {
        var m = 1.0;
        if (params.perspective != 0u) {
            m = c.z;
        }
        let footprint = abs(params.scale.x * params.scale.y) * (m * m);
        if (len > params.normal_limit * footprint) {
            return vec4<f32>(0.0);
        }
    }
    return vec4<f32>(n.x / len, n.y / len, n.z / len, 1.0);
}

// Eq. 8 (ocean_sao::spiral::hash_angle): the hash (30x) ^ (y + 10xy) in u32 (C's precedence;
// WGSL needs the parentheses), reduced modulo 2π byte by byte so that no intermediate exceeds
// ~6500 (sin and cos of the raw hash, up to ~1e9 at 4K, would differ between CPU and GPU).
fn hash_angle(x: u32, y: u32) -> f32 {
    let h = (30u * x) ^ (y + 10u * x * y);
    let b0 = f32(h & 255u);
    let b1 = f32((h >> 8u) & 255u);
    let b2 = f32((h >> 16u) & 255u);
    let b3 = f32((h >> 24u) & 255u);
    var s = b0 * HASH_BYTE_TURN_0 + b1 * HASH_BYTE_TURN_1;
    s += b2 * HASH_BYTE_TURN_2;
    s += b3 * HASH_BYTE_TURN_3;
    return s - TWO_PI * floor(s * INV_TWO_PI);
}

// ocean_core::sincos::sincos: (sin x, cos x) by Cody–Waite reduction by π/2 and Cephes'
// polynomials, the CPU's operations in order. The quadrant comes from round() (ties to even,
// as the CPU's magic-number rounding) rather than from adding and subtracting 1.5·2^23, which a
// shader compiler may fold away.
fn sincos(x: f32) -> vec2<f32> {
    let q = round(x * FRAC_2_PI);
    let r = ((x - q * PIO2_HI) - q * PIO2_MID) - q * PIO2_LO;
    let z = r * r;
    let s = ((S3 * z + S2) * z + S1) * z * r + r;
    let c = ((C3 * z + C2) * z + C1) * z * z - 0.5 * z + 1.0;
    let qi = i32(q);
    let odd = (qi & 1) != 0;
    var sn = select(s, c, odd);
    var cs = select(c, s, odd);
    if ((qi & 2) != 0) {
        sn = -sn;
    }
    if (((qi + 1) & 2) != 0) {
        cs = -cs;
    }
    return vec2<f32>(sn, cs);
}

// Eq. 9 (ocean_sao::spiral::mip_level): clamp(msb(u32(h)) − log2 q', 0, max_mip), with the
// highest set bit of the truncated radius in pixels.
fn mip_level(h: f32) -> u32 {
    let hi = u32(h);
    if (hi == 0u) {
        return 0u;
    }
    let msb = firstLeadingBit(hi);
    if (msb <= params.mip_switch_log2) {
        return 0u;
    }
    return min(msb - params.mip_switch_log2, params.max_mip);
}

// Eq. 10 (ocean_sao::ZHierarchy::sample): z of texel ((x − o) >> m, (y − o) >> m) of level m
// (o the MIP origin for m ≥ 1, 0 for level 0), clamped to the level, and the input position
// (u, v) Eq. 3 reconstructs it at: for the rotated grid the level-0 pixel the value was copied
// from (descending the filter's choices), else the centre of the texel's footprint. Returns
// (z, u, v).
fn sample_level(m: u32, x: i32, y: i32) -> vec3<f32> {
    let size = level_size(m);
    var o = 0;
    if (m > 0u) {
        o = i32(params.mip_origin);
    }
    let t = clamp(vec2<i32>((x - o) >> m, (y - o) >> m), vec2<i32>(0, 0), size - vec2<i32>(1, 1));
    let z = load_z(m, t);
    if (params.mip_filter == FILTER_ROTATED_GRID) {
        var sx = t.x;
        var sy = t.y;
        for (var l = i32(m) - 1; l >= 0; l--) {
            let below = level_size(u32(l));
            var ol = 0;
            if (l == 0) {
                ol = o;
            }
            let cx = min(ol + 2 * sx + ((sy & 1) ^ 1), below.x - 1);
            let cy = min(ol + 2 * sy + ((sx & 1) ^ 1), below.y - 1);
            sx = cx;
            sy = cy;
        }
        return vec3<f32>(z, f32(sx) + 0.5, f32(sy) + 0.5);
    }
    let size_px = f32(1 << m);
    return vec3<f32>(z, f32(o + (t.x << m)) + size_px * 0.5, f32(o + (t.y << m)) + size_px * 0.5);
}

// One sample's contribution, zero outside the ball (ocean_sao::sample's term).
fn term(v: vec3<f32>, n: vec3<f32>, z_c: f32) -> f32 {
    let vv = dot3(v, v);
    // Written so that NaN is outside.
    if (!(vv < params.radius2)) {
        return 0.0;
    }
    let vn = dot3(v, n);
    if (params.estimator == ESTIMATOR_ALCHEMY) {
        // Eq. 1's summand.
        return max(vn + z_c * params.beta, 0.0) / (vv + params.epsilon);
    }
    // The appendix's summand, (r² − v·v)³/r⁶ as (max(r² − v·v, 0)·(1/r²))³.
    let f = max(params.radius2 - vv, 0.0) * params.inv_radius2;
    return f * f * f * max((vn - params.beta) / (vv + params.epsilon), 0.0);
}

// The raw obscurance of output pixel o with level-0 z `z_c` (ocean_sao::sample::sample_pixel):
// 1 for sky and for pixels without a valid normal; the sum is normalised by the number of
// samples that fell inside the input.
fn raw_obscurance(o: vec2<u32>, z_c: f32) -> f32 {
    if (z_c == SKY_Z) {
        return 1.0;
    }
    let pc = vec2<i32>(o + vec2<u32>(params.guard, params.guard));
    let c = position(pc, z_c);
    let nv = face_normal(o, pc, c);
    if (nv.w == 0.0) {
        return 1.0;
    }
    let n = nv.xyz;
    let r_px = screen_radius(z_c);
    let phi = hash_angle(o.x, o.y);
    let size = vec2<i32>(params.input_size);
    var sum = 0.0;
    var count = 0u;
    for (var i = 0u; i < params.samples; i++) {
        // Eq. 6–7 (ocean_sao::spiral::Spiral::tap).
        let alpha = (f32(i) + 0.5) * params.inv_samples;
        let theta = alpha * params.two_pi_turns + phi;
        // û = (cos θ, sin θ), x right, y down (input rows).
        let u = sincos(theta).yx;
        let hp = r_px * alpha;
        let p = pc + vec2<i32>(i32(hp * u.x), i32(hp * u.y));
        if (any(p < vec2<i32>(0, 0)) || any(p >= size)) {
            continue;
        }
        count += 1u;
        let q = sample_level(mip_level(hp), p.x, p.y);
        let v = position_at(q.y, q.z, q.x) - c;
        sum += term(v, n, z_c);
    }
    if (count == 0u) {
        return 1.0;
    }
    let a = max(1.0 - params.strength * sum / f32(count), 0.0);
    if (params.estimator == ESTIMATOR_ALCHEMY && params.k != 1.0) {
        // Eq. 1's exponent; pow(0, k) is left undefined by WGSL, max(0, ·)^k is 0 there.
        if (a == 0.0) {
            return 0.0;
        }
        return pow(a, params.k);
    }
    return a;
}

// ocean_sao::pack::encode_key: the 16-bit depth key of z, SKY_KEY for the sky.
fn encode_key(z: f32) -> u32 {
    if (z == SKY_Z) {
        return SKY_KEY;
    }
    let key = z * params.inv_z_min;
    // Written so that NaN goes to 0.
    var k = 0.0;
    if (key > 0.0) {
        k = min(key, 1.0);
    }
    return min(u32(k * 65535.0 + 0.5), MAX_KEY);
}

// The sample pass and the quad bilateral at output pixel `id` (local index `lid` in its
// workgroup): (raw A, filtered A, level-0 z). Every invocation of the workgroup calls it, those
// outside the output too, so the barriers are reached in uniform control flow.
fn obscurance(id: vec2<u32>, lid: vec2<u32>) -> vec3<f32> {
    let inside = all(id < params.output_size);
    var z_c = 0.0;
    var a = 1.0;
    if (inside) {
        z_c = textureLoad(z0, vec2<i32>(id + vec2<u32>(params.guard, params.guard)), 0).x;
        a = raw_obscurance(id, z_c);
    }
    let me = lid.y * TILE + lid.x;
    tile_a[me] = a;
    tile_z[me] = z_c;
    workgroupBarrier();
    // ocean_sao::sample::quad_bilateral: each horizontal pair (x ^ 1) is replaced by its mean
    // when their z differ by less than the threshold, then each vertical pair (y ^ 1) of the
    // result. A partner outside the output leaves the pixel as it is.
    let quad_on = params.quad_filter != 0u;
    var h = a;
    if (inside && quad_on && (id.x ^ 1u) < params.output_size.x) {
        let other = me ^ 1u;
        if (abs(z_c - tile_z[other]) < params.quad_threshold) {
            h = (a + tile_a[other]) * 0.5;
        }
    }
    workgroupBarrier();
    tile_a[me] = h;
    workgroupBarrier();
    var q = h;
    if (inside && quad_on && (id.y ^ 1u) < params.output_size.y) {
        let other = me ^ TILE;
        if (abs(z_c - tile_z[other]) < params.quad_threshold) {
            q = (h + tile_a[other]) * 0.5;
        }
    }
    return vec3<f32>(a, q, z_c);
}

@compute @workgroup_size(8, 8)
fn ao(@builtin(global_invocation_id) id: vec3<u32>, @builtin(local_invocation_id) lid: vec3<u32>) {
    let r = obscurance(id.xy, lid.xy);
    if (all(id.xy < params.output_size)) {
        textureStore(packed_out, vec2<i32>(id.xy), vec4<u32>(pack_texel(r.y, encode_key(r.z)), 0u, 0u, 0u));
    }
}

// ao, also writing the raw and the quad-filtered A (for the parity tests).
@compute @workgroup_size(8, 8)
fn ao_stages(@builtin(global_invocation_id) id: vec3<u32>, @builtin(local_invocation_id) lid: vec3<u32>) {
    let r = obscurance(id.xy, lid.xy);
    if (all(id.xy < params.output_size)) {
        let p = vec2<i32>(id.xy);
        textureStore(packed_out, p, vec4<u32>(pack_texel(r.y, encode_key(r.z)), 0u, 0u, 0u));
        textureStore(raw_out, p, vec4<f32>(r.x, 0.0, 0.0, 0.0));
        textureStore(quad_out, p, vec4<f32>(r.y, 0.0, 0.0, 0.0));
    }
}
