//! The one AVX2 sequence written by hand: interleaving three arrays into `xyz` points.
//!
//! LLVM vectorises the kernels' arithmetic well, but for the stride-3 stores of a chunk's
//! positions and normals it emits a long chain of shuffles, blends and stack round trips
//! (about a quarter of a 1024² wave train box frame's instructions). Interleaving eight
//! points takes eleven shuffles here. The bits are only moved, never computed, so the output
//! is identical to [`Portable`](crate::kernel::Portable)'s.

use core::arch::x86_64::__m256;

use pulp::x86::V3;

use crate::kernel::{HALF, Interleave};

impl Interleave for V3 {
    /// With x = (x0 … x7) and likewise y, z, each 128-bit half first interleaves its four
    /// points into three vectors A = (x0 y0 z0 x1), B = (y1 z1 x2 y2), C = (z2 x3 y3 z3) (and
    /// x4 … z7 in the upper halves); the three outputs then take their halves from A, B, C:
    /// (A.lo, B.lo), (C.lo, A.hi), (B.hi, C.hi).
    #[inline(always)]
    fn xyz(self, x: &[f32; HALF], y: &[f32; HALF], z: &[f32; HALF], out: &mut [f32]) {
        let avx = self.avx;
        let (x, y, z): (__m256, __m256, __m256) =
            (bytemuck::cast(*x), bytemuck::cast(*y), bytemuck::cast(*z));
        let xy_lo = avx._mm256_unpacklo_ps(x, y); // x0 y0 x1 y1
        let xy_hi = avx._mm256_unpackhi_ps(x, y); // x2 y2 x3 y3
        let yz_lo = avx._mm256_unpacklo_ps(y, z); // y0 z0 y1 z1
        let yz_hi = avx._mm256_unpackhi_ps(y, z); // y2 z2 y3 z3
        let zx_lo = avx._mm256_shuffle_ps::<0x50>(z, x); // z0 z0 x1 x1
        let zx_hi = avx._mm256_shuffle_ps::<0xFA>(z, x); // z2 z2 x3 x3
        let a = avx._mm256_shuffle_ps::<0x84>(xy_lo, zx_lo); // x0 y0 z0 x1
        let b = avx._mm256_shuffle_ps::<0x4E>(yz_lo, xy_hi); // y1 z1 x2 y2
        let c = avx._mm256_shuffle_ps::<0xE8>(zx_hi, yz_hi); // z2 x3 y3 z3
        let o0: [f32; HALF] = bytemuck::cast(avx._mm256_permute2f128_ps::<0x20>(a, b));
        let o1: [f32; HALF] = bytemuck::cast(avx._mm256_permute2f128_ps::<0x30>(c, a));
        let o2: [f32; HALF] = bytemuck::cast(avx._mm256_permute2f128_ps::<0x31>(b, c));
        let out = &mut out[..3 * HALF];
        out[..HALF].copy_from_slice(&o0);
        out[HALF..2 * HALF].copy_from_slice(&o1);
        out[2 * HALF..].copy_from_slice(&o2);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Portable;

    /// Every lane lands where the element-by-element interleave puts it.
    #[test]
    fn interleave_matches_the_portable_order() {
        let Some(simd) = V3::try_new() else {
            return;
        };
        let x: [f32; HALF] = core::array::from_fn(|l| l as f32);
        let y: [f32; HALF] = core::array::from_fn(|l| 100.0 + l as f32);
        let z: [f32; HALF] = core::array::from_fn(|l| 200.0 + l as f32);
        let mut want = [0.0f32; 3 * HALF];
        let mut got = [0.0f32; 3 * HALF];
        Portable.xyz(&x, &y, &z, &mut want);
        pulp::Simd::vectorize(simd, Run(simd, &x, &y, &z, &mut got));
        assert_eq!(got, want);
        for l in 0..HALF {
            assert_eq!(want[3 * l..3 * l + 3], [x[l], y[l], z[l]]);
        }
    }

    struct Run<'a>(
        V3,
        &'a [f32; HALF],
        &'a [f32; HALF],
        &'a [f32; HALF],
        &'a mut [f32],
    );

    impl pulp::WithSimd for Run<'_> {
        type Output = ();
        fn with_simd<S: pulp::Simd>(self, _: S) {
            let Run(simd, x, y, z, out) = self;
            simd.xyz(x, y, z, out);
        }
    }
}
