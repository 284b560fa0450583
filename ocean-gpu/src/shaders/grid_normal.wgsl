// Shared by the grid passes, prepended to their sources: the end of every grid kernel, the twin
// of ocean-core's `Acc::finish` (same operations, same order).

// Rust's f32::MIN_POSITIVE, the smallest normal f32 (2^-126): below it the normal is degenerate.
const F32_MIN_POSITIVE: f32 = 1.17549435e-38;

// The unit normal ∂p/∂z × ∂p/∂x with ∂p/∂x = (J_xx, s_x, J_xz) and ∂p/∂z = (J_xz, s_z, J_zz),
// from the summed horizontal Jacobian and height gradient; its y component is det J. Where |n|²
// falls below the smallest normal f32 (next to a cusp, where the cross product has no meaningful
// direction) the normal is +y, as on the CPU.
fn unit_normal(jxx: f32, jxz: f32, jzz: f32, sx: f32, sz: f32) -> vec3<f32> {
    let na = sz * jxz - jzz * sx;
    let nb = jzz * jxx - jxz * jxz;
    let nc = jxz * sx - sz * jxx;
    let len2 = na * na + nb * nb + nc * nc;
    let degenerate = len2 < F32_MIN_POSITIVE;
    let inv = 1.0 / sqrt(select(len2, 1.0, degenerate));
    return select(vec3<f32>(na * inv, nb * inv, nc * inv), vec3<f32>(0.0, 1.0, 0.0), degenerate);
}

