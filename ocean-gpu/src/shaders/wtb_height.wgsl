// The height-only terms of a wave-train-box frame, one invocation per water grid point: the
// capillary noise of Eq. 9 on every point, inside boxes or not, and the beach run-up; the GPU
// twin of `ocean_wtb::scene::Frame::height_field`, which the layers pass adds to the heights.
//
// A point's noise rate is SplitMix64 of (seed, index) as on the CPU, in 64-bit integer
// arithmetic on (low, high) u32 pairs, so every point gets the CPU's rate ν (an f32, turns per
// second: `ocean_wtb::effects::noise_rate`); its phase ν·t modulo one turn comes from
// `turns` (wtb_time.wgsl), exact but for the final sums at any t below 2^36 s.

struct Params {
    nx: u32,             // water grid columns
    nz: u32,             // water grid rows
    flags: u32,          // 1 noise, 2 run-up (over a terrain)
    groups_x: u32,       // workgroups along x
    seed: vec2<u32>,     // noise seed (lo, hi)
    amplitude: f32,      // noise amplitude b, metres
    step: f32,           // ocean_wtb::effects::NOISE_TURNS_STEP
    run_up: f32,         // water level raised at the shoreline, metres
    run_up_depth: f32,   // depth where the run-up has faded to 0, metres
    _pad: vec2<u32>,
    time: vec4<f32>,     // t = x·2^24 + y·2^12 + z + w: x, y, z whole numbers below 2^12, w ∈ [0, 1)
}

@group(0) @binding(0) var<uniform> params: Params;
// The water grid's ground heights (metres above the sea at rest), row-major; unused without
// run-up.
@group(0) @binding(1) var<storage, read> terrain: array<f32>;
// The height field, one value per grid point, row-major.
@group(0) @binding(2) var<storage, read_write> height: array<f32>;

const TAU: f32 = 6.283185307179586;

// a ^ (a >> s) for 0 < s < 32.
fn xor_shift(a: vec2<u32>, s: u32) -> vec2<u32> {
    return a ^ vec2<u32>((a.x >> s) | (a.y << (32u - s)), a.y >> s);
}

// The 64-bit product of two u32, from 16-bit halves.
fn wide_mul(a: u32, b: u32) -> vec2<u32> {
    let a0 = a & 0xffffu;
    let a1 = a >> 16u;
    let b0 = b & 0xffffu;
    let b1 = b >> 16u;
    let p00 = a0 * b0;
    let p01 = a0 * b1;
    let p10 = a1 * b0;
    let mid = (p00 >> 16u) + (p01 & 0xffffu) + (p10 & 0xffffu);
    return vec2<u32>((p00 & 0xffffu) | (mid << 16u), a1 * b1 + (p01 >> 16u) + (p10 >> 16u) + (mid >> 16u));
}

// a·b modulo 2^64.
fn mul64(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    let p = wide_mul(a.x, b.x);
    return vec2<u32>(p.x, p.y + a.x * b.y + a.y * b.x);
}

// ocean_wtb::effects::noise_rate: ν of grid point `index`, turns per second.
fn noise_rate(index: u32) -> f32 {
    var z = params.seed ^ mul64(vec2<u32>(index, 0u), vec2<u32>(0x7f4a7c15u, 0x9e3779b9u));
    z = mul64(xor_shift(z, 30u), vec2<u32>(0x1ce4e5b9u, 0xbf58476du));
    z = mul64(xor_shift(z, 27u), vec2<u32>(0x133111ebu, 0x94d049bbu));
    z = xor_shift(z, 31u);
    // The top 24 bits: z >> 40.
    return f32(z.y >> 8u) * params.step;
}

@compute @workgroup_size(64)
fn height_field(@builtin(workgroup_id) group: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let q = (group.y * params.groups_x + group.x) * 64u + local;
    if q >= params.nx * params.nz {
        return;
    }
    var y = 0.0;
    if (params.flags & 1u) != 0u {
        y += params.amplitude * sin(TAU * turns(noise_rate(q), params.time));
    }
    if (params.flags & 2u) != 0u {
        // ocean_wtb::effects::run_up over water (ground below the sea at rest).
        let ground = terrain[q];
        if ground < 0.0 && -ground < params.run_up_depth {
            y += params.run_up * (1.0 - max(-ground, 0.0) / params.run_up_depth);
        }
    }
    height[q] = y;
}
