// The ray march of a wave train box (wave-train-boxes §2, Fig. 2, Fig. 5): the GPU twin of
// `ocean_wtb::march::MarchBox::march` followed by `MarchBox::time_modulation`. One invocation
// marches one wave ray; the rays are independent (their state lives along the ray).
//
// Entry points, dispatched in this order over the box's grid rectangle (nx × nz points, `q` the
// row-major index in it) or over its rays:
//   clear     (points) base = 0; factor = 0 on land, else 1.
//   march     (rays)   for every cell of the ray in increasing step, its 0-2 grid points in
//                      increasing a: the ray's state and the point's m·e^{iφ} (base) and land
//                      factor (factor).
//   erode_x, erode_z, mean_x, mean_z (points)
//                      the land factor's smoothing (ocean_wtb::shore): the minimum, then the
//                      mean, over windows of `radius` cells clipped to the rectangle, rows then
//                      columns, ping-ponging between `factor` and `tmp`.
//   combine   (points) modulation = base · factor (0 on land), times the time-dependent effects
//                      (irregular height, Eq. 8; dispersion refraction, Eq. 4).
//
// Ownership is exact and identical to the CPU's: the traversal's constants are 64-bit integers
// in units of 2^-36 cells (`ocean_wtb::FixedTraversal`), emulated here with pairs of u32
// (low word, high word; two's complement). Point (i, j) has A = ca + i·ux + j·uz and
// B = cb + j·ux − i·uz; it is inside when 0 ≤ A ≤ length and 0 ≤ B ≤ width and belongs to step
// ⌈A / 2^36⌉ of ray ⌈B / 2^36⌉. Distances along the ray (Δa, the distance behind land, the
// distances to the box's edges) are differences of these integers, exact before their final
// rounding to f32, so neither a box far from the origin nor a long ray loses precision. The
// refraction lag is kept reduced to [-π, π] at every step.

struct Params {
    grid_nx: u32,          // water grid columns
    grid_nz: u32,          // water grid rows
    i0: u32,               // the box rectangle's first column
    j0: u32,               // its first row
    nx: u32,               // its columns
    nz: u32,               // its rows
    rays: u32,             // ray descriptors in `statics`
    flags: u32,            // 1 terrain, 2 refraction, 4 shoaling, 8 round waves, 16 beach,
                           // 32 irregular, 64 dispersion
    ca: vec2<u32>,         // fixed-point traversal constants (lo, hi)
    cb: vec2<u32>,
    ux: vec2<u32>,
    uz: vec2<u32>,
    length: vec2<u32>,
    width: vec2<u32>,
    centre_step: vec2<f32>, // a cell centre's move per step, grid units
    half: f32,             // candidate window half-width, grid units
    cell: f32,             // metres per fixed-point unit: spacing · 2^-36
    smoothing: f32,        // side fade width, metres
    recovery: f32,         // recovery distance behind land, metres
    amplitude: f32,        // ΣA of the box's trains, metres
    peak_k: f32,           // peak wavenumber, rad/m
    shallow_depth: f32,    // shoaling reference depth, metres
    beach_share: f32,      // the beach's largest amplitude per metre of depth
    table_step: f32,       // shortening table step in √depth
    table_len: u32,        // its intervals (values: table_len + 1)
    table: u32,            // word offset of its values in `statics`
    radius: u32,           // smoothing radius, cells
    groups_x: u32,         // workgroups along x of the points' dispatches
    irregular_scale: f32,  // Eq. 8: a
    irregular_freq: f32,   // Eq. 8: f (rad/m)
    irregular_k: f32,      // Eq. 8: k_e (rad/m)
    irregular_phase: f32,  // k_e·c_e·t reduced to [-π, π] on the host
    origin_a: f32,         // internal a of the rectangle's first point, metres
    origin_b: f32,         // internal b of it, metres
    a_di: f32,             // a's change per column, metres
    a_dj: f32,             // a's change per row
    b_di: f32,             // b's change per column
    b_dj: f32,             // b's change per row
    omega_deep: f32,       // √(g k_p): deep-water frequency of the peak train, rad/s
    ray_groups_x: u32,     // workgroups along x of the rays' dispatch
    _pad: u32,
    time: vec4<f32>,       // t = x·2^24 + y·2^12 + z + w: x, y, z whole numbers below 2^12, w ∈ [0, 1)
}

// One wave ray: its index r, the first of `count` steps, and the first step's cell centre.
struct Ray {
    r: u32,
    first: u32,
    count: u32,
    _pad: u32,
    centre: vec2<f32>,
    _pad1: vec2<f32>,
}

@group(0) @binding(0) var<uniform> params: Params;
// Ray descriptors (8 words each) from word 0, then the shortening table's f32 values at
// `params.table`.
@group(0) @binding(1) var<storage, read> statics: array<u32>;
// The water grid's ground heights (metres above the sea at rest), row-major; unused without
// terrain (flag 1 clear: deep sea everywhere).
@group(0) @binding(2) var<storage, read> terrain: array<f32>;
// base (2 words a rectangle point), then factor (1 word), then tmp (1 word).
@group(0) @binding(3) var<storage, read_write> work: array<f32>;
// The box's modulation [m cos φ, m sin φ] per rectangle point: what the layers pass reads.
@group(0) @binding(4) var<storage, read_write> modulation: array<vec2<f32>>;

const TAU: f32 = 6.283185307179586;
const GRAVITY: f32 = 9.81;    // ocean_core::GRAVITY
const MAX_SHOALING: f32 = 1.5;

// ---- 64-bit integers as (lo, hi) ----

fn add64(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    let lo = a.x + b.x;
    let carry = select(0u, 1u, lo < a.x);
    return vec2<u32>(lo, a.y + b.y + carry);
}

fn neg64(a: vec2<u32>) -> vec2<u32> {
    return add64(vec2<u32>(~a.x, ~a.y), vec2<u32>(1u, 0u));
}

fn sub64(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    return add64(a, neg64(b));
}

fn is_negative(a: vec2<u32>) -> bool {
    return (a.y & 0x80000000u) != 0u;
}

// a < b, signed.
fn less64(a: vec2<u32>, b: vec2<u32>) -> bool {
    let ha = bitcast<i32>(a.y);
    let hb = bitcast<i32>(b.y);
    return ha < hb || (ha == hb && a.x < b.x);
}

// n · v for n < 2^16 and |v| < 2^47 (the products stay exact in 32-bit pieces).
fn mul64(n: u32, v: vec2<u32>) -> vec2<u32> {
    let neg = is_negative(v);
    var m = v;
    if neg {
        m = neg64(v);
    }
    let p0 = n * (m.x & 0xffffu);          // < 2^32
    let p1 = n * (m.x >> 16u);             // < 2^32
    let lo = p0 + (p1 << 16u);
    let carry = select(0u, 1u, lo < p0);
    let hi = n * m.y + (p1 >> 16u) + carry;
    let r = vec2<u32>(lo, hi);
    if neg {
        return neg64(r);
    }
    return r;
}

// The value as f32 (rounded).
fn to_f32(a: vec2<u32>) -> f32 {
    return f32(bitcast<i32>(a.y)) * 4294967296.0 + f32(a.x);
}

// ⌈x / 2^36⌉ when 0 ≤ x ≤ max, else 0xffffffff (no cell).
fn cell_of(x: vec2<u32>, max: vec2<u32>) -> u32 {
    if is_negative(x) || less64(max, x) {
        return 0xffffffffu;
    }
    // + (2^36 − 1), then the high word shifted by 4: x ≥ 0, so the shift is a plain one.
    let c = add64(x, vec2<u32>(0xffffffffu, 0xfu));
    return c.y >> 4u;
}

// ---- the march's per-point terms (ocean_wtb::effects) ----

fn reduce(x: f32) -> f32 {
    return x - TAU * round(x / TAU);
}

fn side_fade(distance: f32, smoothing: f32) -> f32 {
    if smoothing <= 0.0 {
        return select(0.0, 1.0, distance >= 0.0);
    }
    return clamp(distance / smoothing, 0.0, 1.0);
}

fn shoaling(depth: f32, reference: f32) -> f32 {
    if depth <= 0.0 {
        return 0.0;
    }
    if depth >= reference {
        return 1.0;
    }
    return min(sqrt(sqrt(reference / depth)), MAX_SHOALING);
}

// k(D)/k∞ − 1 solved directly (ocean_wtb::effects::shortening): Newton on ω² = g k tanh(k D)
// from the shallow-water wavenumber, with D floored at a millimetre.
fn shortening_direct(k_deep: f32, depth: f32) -> f32 {
    if depth * k_deep > 20.0 {
        return 0.0;
    }
    let d = max(depth, 1e-3);
    let w2 = GRAVITY * k_deep;
    var k = sqrt(w2 / (GRAVITY * d));
    for (var n = 0; n < 12; n++) {
        let th = tanh(k * d);
        let f = GRAVITY * k * th - w2;
        let df = GRAVITY * (th + k * d * (1.0 - th * th));
        k = k - f / df;
    }
    return k / k_deep - 1.0;
}

fn table_value(n: u32) -> f32 {
    return bitcast<f32>(statics[params.table + n]);
}

// ocean_wtb::effects::ShorteningTable::get.
fn shortening(depth: f32) -> f32 {
    let u = sqrt(max(depth, 0.0));
    let x = u / params.table_step;
    if x < 1.0 {
        return shortening_direct(params.peak_k, depth);
    }
    if x >= f32(params.table_len) {
        return 0.0;
    }
    let n = u32(x);
    let f = x - f32(n);
    let v0 = table_value(n);
    let v1 = table_value(n + 1u);
    return (v0 + (v1 - v0) * f) / u - 1.0;
}

fn has(flag: u32) -> bool {
    return (params.flags & flag) != 0u;
}

// Ground height at grid point (i, j). Only read when flag 1 says there is a terrain (without
// one the buffer is a placeholder).
fn ground(i: u32, j: u32) -> f32 {
    return terrain[j * params.grid_nx + i];
}

fn is_land(i: u32, j: u32) -> bool {
    return has(1u) && ground(i, j) >= 0.0;
}

fn linear_index(group: vec3<u32>, local: u32) -> u32 {
    return (group.y * params.groups_x + group.x) * 64u + local;
}

fn factor_at(q: u32) -> u32 {
    return 2u * params.nx * params.nz + q;
}

fn tmp_at(q: u32) -> u32 {
    return 3u * params.nx * params.nz + q;
}

@compute @workgroup_size(64)
fn clear(@builtin(workgroup_id) group: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let q = linear_index(group, local);
    if q >= params.nx * params.nz {
        return;
    }
    let i = params.i0 + q % params.nx;
    let j = params.j0 + q / params.nx;
    work[2u * q] = 0.0;
    work[2u * q + 1u] = 0.0;
    work[factor_at(q)] = select(1.0, 0.0, is_land(i, j));
}

struct Candidate {
    a: vec2<u32>,
    b: vec2<u32>,
    i: u32,
    j: u32,
}

@compute @workgroup_size(64)
fn march(@builtin(workgroup_id) group: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let n = (group.y * params.ray_groups_x + group.x) * 64u + local;
    if n >= params.rays {
        return;
    }
    let ray = Ray(
        statics[8u * n],
        statics[8u * n + 1u],
        statics[8u * n + 2u],
        0u,
        vec2<f32>(bitcast<f32>(statics[8u * n + 4u]), bitcast<f32>(statics[8u * n + 5u])),
        vec2<f32>(0.0),
    );
    let r = ray.r;
    let width_m = to_f32(params.width) * params.cell;

    // The ray's state (ocean_wtb::march): land, where land last ended, the refraction lag.
    var on_land = false;
    var land_ended = false;
    var land_end = vec2<u32>(0u, 0u);
    var has_last = false;
    var last_a = vec2<u32>(0u, 0u);
    var lag = 0.0;

    var cands: array<Candidate, 4>;
    for (var s = 0u; s < ray.count; s++) {
        let k = ray.first + s;
        let c = ray.centre + f32(s) * params.centre_step;
        let i_lo = max(i32(ceil(c.x - params.half)), 0);
        let i_hi = min(i32(floor(c.x + params.half)), i32(params.grid_nx) - 1);
        let j_lo = max(i32(ceil(c.y - params.half)), 0);
        let j_hi = min(i32(floor(c.y + params.half)), i32(params.grid_nz) - 1);
        var count = 0u;
        for (var j = j_lo; j <= j_hi; j++) {
            for (var i = i_lo; i <= i_hi; i++) {
                let ui = u32(i);
                let uj = u32(j);
                let a = add64(add64(params.ca, mul64(ui, params.ux)), mul64(uj, params.uz));
                let b = sub64(add64(params.cb, mul64(uj, params.ux)), mul64(ui, params.uz));
                if cell_of(a, params.length) != k || cell_of(b, params.width) != r || count == 4u {
                    continue;
                }
                cands[count] = Candidate(a, b, ui, uj);
                count++;
            }
        }
        // In increasing a: each time the smallest a not yet taken. (Selection by index rather
        // than a sort that swaps structs in place: naga's GLSL output does not keep a swap's
        // temporary, and llvmpipe then lost one point of each swapped pair.)
        var taken = 0u;
        for (var p = 0u; p < count; p++) {
            var best = count;
            for (var x = 0u; x < count; x++) {
                if (taken & (1u << x)) != 0u {
                    continue;
                }
                if best == count {
                    best = x;
                } else if less64(cands[x].a, cands[best].a) {
                    best = x;
                }
            }
            taken |= 1u << best;
            let cand = cands[best];
            let land = is_land(cand.i, cand.j);
            let terrain_here = has(1u);
            let depth = select(0.0, -ground(cand.i, cand.j), terrain_here);
            // Refraction: the lag of the shorter shallow-water wave along the ray.
            if has(2u) && has_last {
                var integrand = 0.0;
                if !land && terrain_here {
                    integrand = shortening(depth);
                }
                let da = to_f32(sub64(cand.a, last_a)) * params.cell;
                lag = reduce(lag + params.peak_k * integrand * da);
            }
            has_last = true;
            last_a = cand.a;
            if land != on_land {
                if !land {
                    land_ended = true;
                    land_end = cand.a;
                }
                on_land = land;
            }
            var land_factor = 1.0;
            if land {
                land_factor = 0.0;
            } else if land_ended && params.recovery > 0.0 {
                let behind = to_f32(sub64(cand.a, land_end)) * params.cell;
                land_factor = clamp(behind / params.recovery, 0.0, 1.0);
            }
            var m = 1.0;
            if has(4u) && !land && terrain_here {
                m *= shoaling(depth, params.shallow_depth);
            }
            if has(16u) && !land && terrain_here && params.amplitude > 0.0 {
                m = min(m, params.beach_share * max(depth, 0.0) / params.amplitude);
            }
            let edge_u = to_f32(select(sub64(params.length, cand.a), cand.a,
                                       less64(cand.a, sub64(params.length, cand.a)))) * params.cell;
            let edge_v = to_f32(select(sub64(params.width, cand.b), cand.b,
                                       less64(cand.b, sub64(params.width, cand.b)))) * params.cell;
            m *= side_fade(edge_v, params.smoothing) * side_fade(edge_u, params.smoothing);
            var phase = lag;
            if has(8u) && width_m > 0.0 {
                // Eq. 10 with v − V/2 = (2B − W)/2 from the integers.
                let d = to_f32(sub64(add64(cand.b, cand.b), params.width)) * 0.5 * params.cell;
                phase += params.peak_k * d * d / width_m;
            }
            phase = reduce(phase);
            let q = (cand.j - params.j0) * params.nx + (cand.i - params.i0);
            work[2u * q] = m * cos(phase);
            work[2u * q + 1u] = m * sin(phase);
            work[factor_at(q)] = land_factor;
        }
    }
}

// The smoothing's line filters: `src_at`/`dst_at` map a rectangle point to its word.
fn window(q: u32, along_x: bool) -> vec3<u32> {
    // (first, last + 1, stride) of the clipped window around q along the axis.
    let c = q % params.nx;
    let r = q / params.nx;
    let rad = params.radius;
    if along_x {
        let lo = select(c - rad, 0u, c < rad);
        let hi = min(c + rad + 1u, params.nx);
        return vec3<u32>(r * params.nx + lo, r * params.nx + hi, 1u);
    }
    let lo = select(r - rad, 0u, r < rad);
    let hi = min(r + rad + 1u, params.nz);
    return vec3<u32>(lo * params.nx + c, hi * params.nx + c, params.nx);
}

fn window_min(q: u32, along_x: bool, from_tmp: bool) -> f32 {
    let w = window(q, along_x);
    var v = 1.0;
    for (var p = w.x; p < w.y; p += w.z) {
        v = min(v, work[select(factor_at(p), tmp_at(p), from_tmp)]);
    }
    return v;
}

fn window_mean(q: u32, along_x: bool, from_tmp: bool) -> f32 {
    let w = window(q, along_x);
    var sum = 0.0;
    var n = 0u;
    for (var p = w.x; p < w.y; p += w.z) {
        sum += work[select(factor_at(p), tmp_at(p), from_tmp)];
        n++;
    }
    return sum / f32(n);
}

@compute @workgroup_size(64)
fn erode_x(@builtin(workgroup_id) group: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let q = linear_index(group, local);
    if q < params.nx * params.nz {
        work[tmp_at(q)] = window_min(q, true, false);
    }
}

@compute @workgroup_size(64)
fn erode_z(@builtin(workgroup_id) group: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let q = linear_index(group, local);
    if q < params.nx * params.nz {
        work[factor_at(q)] = window_min(q, false, true);
    }
}

@compute @workgroup_size(64)
fn mean_x(@builtin(workgroup_id) group: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let q = linear_index(group, local);
    if q < params.nx * params.nz {
        work[tmp_at(q)] = window_mean(q, true, false);
    }
}

@compute @workgroup_size(64)
fn mean_z(@builtin(workgroup_id) group: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let q = linear_index(group, local);
    if q < params.nx * params.nz {
        work[factor_at(q)] = window_mean(q, false, true);
    }
}

@compute @workgroup_size(64)
fn combine(@builtin(workgroup_id) group: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let q = linear_index(group, local);
    if q >= params.nx * params.nz {
        return;
    }
    let c = q % params.nx;
    let r = q / params.nx;
    let i = params.i0 + c;
    let j = params.j0 + r;
    var f = work[factor_at(q)];
    if is_land(i, j) {
        f = 0.0;
    }
    var mu = vec2<f32>(work[2u * q], work[2u * q + 1u]) * f;
    if (has(32u) || has(64u)) && (mu.x != 0.0 || mu.y != 0.0) {
        var m = 1.0;
        var phase = 0.0;
        if has(32u) {
            // Eq. 8 at the point's internal (u, v), the time part reduced on the host.
            let u = params.origin_a + f32(c) * params.a_di + f32(r) * params.a_dj;
            let v = params.origin_b + f32(c) * params.b_di + f32(r) * params.b_dj;
            let envelope = reduce(reduce(params.irregular_k * u) - params.irregular_phase);
            let across = reduce(params.irregular_freq * v);
            m *= 1.0 - params.irregular_scale * sin(envelope) * sin(across);
        }
        if has(64u) && has(1u) {
            // (ω∞ − ω(D)) t, reduced as turns.
            let depth = max(-ground(i, j), 1e-3);
            let omega = sqrt(GRAVITY * params.peak_k * tanh(params.peak_k * depth));
            phase = TAU * turns((params.omega_deep - omega) / TAU, params.time);
        }
        let s = m * sin(phase);
        let co = m * cos(phase);
        mu = vec2<f32>(mu.x * co - mu.y * s, mu.x * s + mu.y * co);
    }
    modulation[q] = mu;
}
