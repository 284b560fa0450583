// SAO pass 2 (§2.2, Table 1): z MIP level m + 1 from level m, one dispatch per level. The twin
// of ocean_sao::hierarchy::ZLevel::downsample: texel (x', y') filters the 2×2 children
// (o + 2x' + i, o + 2y' + j) of level m, each child clamped to the level's last column or row,
// with o = params.mip_origin when level m is level 0 and 0 above (ocean_sao::hierarchy's
// origin, which keeps the texel grid aligned with the output whatever the guard band).
//
// Every level is a texture of its own (one level each), so a dispatch reads one texture and
// writes another: one storage texture per dispatch, and no texture is ever sampled and written
// at two levels at once (OpenGL ignores image stores to a level outside the range of a
// texture's sampled view).

@group(0) @binding(1) var z_src: texture_2d<f32>;
@group(0) @binding(2) var z_dst: texture_storage_2d<r32float, write>;

const FILTER_ROTATED_GRID: u32 = 0u;
const FILTER_ARITHMETIC_MEAN: u32 = 1u;
const FILTER_HARMONIC_MEAN: u32 = 2u;
const FILTER_MIN: u32 = 3u;

// ZLevel::fetch: z at texel (x, y) clamped to the level.
fn fetch(x: i32, y: i32, size: vec2<i32>) -> f32 {
    let c = clamp(vec2<i32>(x, y), vec2<i32>(0, 0), size - vec2<i32>(1, 1));
    return textureLoad(z_src, c, 0).x;
}

// ZLevel::filter_texel.
fn filter_texel(x: i32, y: i32, size: vec2<i32>) -> f32 {
    // Level 0 is the only level of the input's size (level 1 has at most half of a side ≥ 2).
    var o = 0;
    if (all(size == vec2<i32>(params.input_size))) {
        o = i32(params.mip_origin);
    }
    let x2 = o + 2 * x;
    let y2 = o + 2 * y;
    if (params.mip_filter == FILTER_ROTATED_GRID) {
        // Table 1: z^m(2x' + ((y' & 1) ^ 1), 2y' + ((x' & 1) ^ 1)); WGSL needs the parentheses
        // around ^.
        return fetch(x2 + ((y & 1) ^ 1), y2 + ((x & 1) ^ 1), size);
    }
    let a = fetch(x2, y2, size);
    let b = fetch(x2 + 1, y2, size);
    let c = fetch(x2, y2 + 1, size);
    let d = fetch(x2 + 1, y2 + 1, size);
    // The sums are accumulated in a `var`, one statement per term: Mesa's GLSL compiler
    // rebalances a single expression ((a + b) + c) + d into (a + b) + (c + d), which rounds
    // differently (measured: 22.6% of 10⁵ random quadruples differ by an ulp on llvmpipe through
    // wgpu's GL backend; the statement form matched the CPU on all of them).
    var sum = a + b;
    sum += c;
    sum += d;
    let mean = sum * 0.25;
    switch (params.mip_filter) {
        case FILTER_ARITHMETIC_MEAN: {
            return mean;
        }
        case FILTER_HARMONIC_MEAN: {
            // The true harmonic mean (Table 1 prints a sixteenth of it), defined for values of
            // one sign: the arithmetic mean otherwise.
            if (a < 0.0 && b < 0.0 && c < 0.0 && d < 0.0) {
                var inv = 1.0 / a + 1.0 / b;
                inv += 1.0 / c;
                inv += 1.0 / d;
                return 4.0 / inv;
            }
            return mean;
        }
        case FILTER_MIN: {
            return min(min(min(a, b), c), d);
        }
        default: {
            return max(max(max(a, b), c), d);
        }
    }
}

@compute @workgroup_size(8, 8)
fn downsample(@builtin(global_invocation_id) id: vec3<u32>) {
    if (any(id.xy >= textureDimensions(z_dst))) {
        return;
    }
    let size = vec2<i32>(textureDimensions(z_src));
    let z = filter_texel(i32(id.x), i32(id.y), size);
    textureStore(z_dst, vec2<i32>(id.xy), vec4<f32>(z, 0.0, 0.0, 0.0));
}
