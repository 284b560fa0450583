
// ---- time (shared by wtb_march.wgsl and wtb_height.wgsl) ----

// fract(ν·t) for t = x·2^24 + y·2^12 + z + w (params.time): ν is split into two halves of 12
// significant bits, so that each product with the whole numbers x, y and z (below 2^12) is
// exact in f32 whatever the compiler fuses, and only the final sums round: the phase has the
// precision of ν, not of ν·t, and moves smoothly at any t below 2^36 s.
fn turns(nu: f32, t: vec4<f32>) -> f32 {
    let hi = bitcast<f32>(bitcast<u32>(nu) & 0xfffff000u);
    let lo = nu - hi;
    var f = fract(hi * t.x * 16777216.0) + fract(lo * t.x * 16777216.0);
    f += fract(hi * t.y * 4096.0) + fract(lo * t.y * 4096.0);
    f += fract(hi * t.z) + fract(lo * t.z);
    f += fract(nu * t.w);
    return fract(f);
}
