// `ocean render`'s last pass: the frame's colour times the ambient obscurance of Scalable
// Ambient Obscurance (McGuire, Mara & Luebke 2012) computed over its depth buffer.
//
// The renderers write display values (tone mapped, sRGB encoded); the obscurance is applied to
// the tone-mapped linear value, 1 − strength·(1 − A), then encoded again. A full-screen
// triangle of 3 vertices, no vertex buffer.

struct Params {
    // x: strength in [0, 1]; y: 1 when the colour is sRGB encoded; zw: unused.
    strength: vec4<f32>,
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var color: texture_2d<f32>;
// SAO's A (r32float), 1 for no obscurance.
@group(0) @binding(2) var ao: texture_2d<f32>;

@vertex
fn composite_vs(@builtin(vertex_index) index: u32) -> @builtin(position) vec4<f32> {
    let uv = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    return vec4<f32>(uv * 2.0 - vec2<f32>(1.0), 0.0, 1.0);
}

fn srgb_to_linear(c: vec3<f32>) -> vec3<f32> {
    let lo = c / 12.92;
    let hi = pow((c + vec3<f32>(0.055)) / 1.055, vec3<f32>(2.4));
    return select(hi, lo, c <= vec3<f32>(0.04045));
}

fn linear_to_srgb(c: vec3<f32>) -> vec3<f32> {
    let x = clamp(c, vec3<f32>(0.0), vec3<f32>(1.0));
    let hi = 1.055 * pow(max(x, vec3<f32>(0.0031308)), vec3<f32>(1.0 / 2.4)) - vec3<f32>(0.055);
    return select(hi, 12.92 * x, x <= vec3<f32>(0.0031308));
}

@fragment
fn composite_fs(@builtin(position) p: vec4<f32>) -> @location(0) vec4<f32> {
    let q = vec2<i32>(p.xy);
    let c = textureLoad(color, q, 0).rgb;
    let a = clamp(textureLoad(ao, q, 0).x, 0.0, 1.0);
    let k = 1.0 - params.strength.x * (1.0 - a);
    let encoded = params.strength.y > 0.5;
    let linear = select(c, srgb_to_linear(c), encoded) * k;
    return vec4<f32>(select(linear, linear_to_srgb(linear), encoded), 1.0);
}
