// Shared by the grid passes (trochoid.wgsl, layers.wgsl), prepended to their sources after
// grid_normal.wgsl: an invocation's point and the sums of its wave terms, the twin of
// ocean-core's `Acc` (same operations, same order).

// One wave's coefficients (ocean-core's `WaveCoeffs`, 32 bytes).
struct WaveCoeffs {
    a: f32,    // A
    ahx: f32,  // A k_x/|k|
    ahz: f32,  // A k_z/|k|
    cxx: f32,  // A k_x²/|k|
    cxz: f32,  // A k_x k_z/|k|
    czz: f32,  // A k_z²/|k|
    gx: f32,   // A k_x
    gz: f32,   // A k_z
}

// The linear point index of an invocation, 64 per workgroup: grids with more than 65535
// workgroups fold into the dispatch's second dimension, `groups_x` workgroups wide.
fn grid_index(group: vec3<u32>, local: u32, groups_x: u32) -> u32 {
    return (group.y * groups_x + group.x) * 64u + local;
}

// The sums over a point's waves: the displacement (dx, y, dz), the horizontal Jacobian
// (jxx, jxz, jzz) and the height gradient (sx, sz).
struct GridSums {
    dx: f32,
    y: f32,
    dz: f32,
    jxx: f32,
    jxz: f32,
    jzz: f32,
    sx: f32,
    sz: f32,
}

// No wave yet: no displacement, the identity Jacobian, a flat surface.
fn no_waves() -> GridSums {
    return GridSums(0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0);
}

// Adds the terms of a wave with coefficients c at the sine s and cosine co of its phase.
fn add_wave(sums: ptr<function, GridSums>, c: WaveCoeffs, s: f32, co: f32) {
    (*sums).dx -= c.ahx * s;
    (*sums).dz -= c.ahz * s;
    (*sums).y += c.a * co;
    (*sums).jxx -= c.cxx * co;
    (*sums).jxz -= c.cxz * co;
    (*sums).jzz -= c.czz * co;
    (*sums).sx -= c.gx * s;
    (*sums).sz -= c.gz * s;
}
