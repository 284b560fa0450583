//! The layers kernel ([`crate::layers`]) and the trochoid grid kernel ([`crate::trochoid`])
//! written out in AVX-512 for CPUs that have it.
//!
//! With 32 vector registers a whole 16-point chunk fits: the eight running sums, the chunk's
//! modulation and the wave's temporaries stay in registers across every layer and wave, where
//! the AVX2 kernel sums each half chunk on its own. Written with intrinsics (pulp's safe
//! wrappers) rather than left to LLVM's vectoriser, which for the same loops emitted scalar
//! reductions, masked partial loads and stack round trips.
//!
//! **Bits.** Every lane performs exactly the IEEE operations of the portable kernel, in the same
//! order, with no fused multiply-add: [`Acc::add_sin_cos`](crate::kernel::Acc) for each wave,
//! [`Acc::finish`](crate::kernel::Acc) for the normal. Its output is therefore bit-identical
//! to the AVX2 and portable paths (tested in `tests/layers_isa.rs`), whatever the CPU.

use core::arch::x86_64::{__m512, __m512i, __mmask16};

use glam::Vec3;
use pulp::x86::V4;

use crate::kernel::{ActiveLayer, GridRow, LANE_INDEX, LANES, LayerRow};
use crate::vector::{Sums, Vector, angle_sum, modulate};

const _: () = assert!(LANES == 16, "one AVX-512 vector per chunk");

/// One row of [`crate::layers`] on AVX-512: what [`pulp::Simd::vectorize`] runs.
pub(crate) struct Wide<'a>(pub(crate) V4, pub(crate) LayerRow<'a>);

impl pulp::WithSimd for Wide<'_> {
    type Output = ();
    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) {
        row(self.0, self.1);
    }
}

/// Even and odd floats of 32 (`permutex2var` indices: 0–15 pick from the first operand,
/// 16–31 from the second): the real and imaginary parts of 16 `[re, im]` pairs.
const EVEN: [i32; LANES] = {
    let mut v = [0i32; LANES];
    let mut l = 0;
    while l < LANES {
        v[l] = 2 * l as i32;
        l += 1;
    }
    v
};
const ODD: [i32; LANES] = {
    let mut v = [0i32; LANES];
    let mut l = 0;
    while l < LANES {
        v[l] = 2 * l as i32 + 1;
        l += 1;
    }
    v
};

/// For output vector `k` of 16 points interleaved as `xyz` (48 floats), the indices of the
/// first step (x from the first operand, y from the second; z slots left at 0) and of the
/// second (z from the second operand into the z slots, every other slot kept).
const fn interleave_indices(k: usize) -> ([i32; LANES], [i32; LANES]) {
    let mut first = [0i32; LANES];
    let mut second = [0i32; LANES];
    let mut e = 0;
    while e < LANES {
        let g = LANES * k + e;
        let (point, component) = ((g / 3) as i32, g % 3);
        first[e] = match component {
            0 => point,
            1 => LANES as i32 + point,
            _ => 0,
        };
        second[e] = if component == 2 {
            LANES as i32 + point
        } else {
            e as i32
        };
        e += 1;
    }
    (first, second)
}
const XYZ: [([i32; LANES], [i32; LANES]); 3] = [
    interleave_indices(0),
    interleave_indices(1),
    interleave_indices(2),
];

#[inline(always)]
fn v(a: [f32; LANES]) -> __m512 {
    bytemuck::cast(a)
}

#[inline(always)]
fn vi(a: [i32; LANES]) -> __m512i {
    bytemuck::cast(a)
}

/// The 48 floats of 16 points: `x`, `y`, `z` interleaved, as three vectors.
#[inline(always)]
fn interleave(simd: V4, x: __m512, y: __m512, z: __m512) -> [__m512; 3] {
    let f = simd.avx512f;
    XYZ.map(|(first, second)| {
        let xy = f._mm512_permutex2var_ps(x, vi(first), y);
        f._mm512_permutex2var_ps(xy, vi(second), z)
    })
}

/// The modulation of the chunk from grid column `first_col`, zero outside the layer's span:
/// (real parts, imaginary parts).
#[inline(always)]
fn modulation(simd: V4, layer: &ActiveLayer<'_>, first_col: usize) -> (__m512, __m512) {
    let f = simd.avx512f;
    match layer.run(first_col, LANES) {
        Some(run) => {
            // 16 pairs are two vectors of 16 floats.
            let halves: &[[f32; LANES]] = bytemuck::cast_slice(run);
            let (lo, hi) = (v(halves[0]), v(halves[1]));
            (
                f._mm512_permutex2var_ps(lo, vi(EVEN), hi),
                f._mm512_permutex2var_ps(lo, vi(ODD), hi),
            )
        }
        None => {
            let (re, im) = layer.partial::<LANES>(first_col);
            (v(re), v(im))
        }
    }
}

/// Chunks of modulation read ahead of the kernel: the hardware prefetchers lag several
/// interleaved streams (every layer's modulation and the two outputs).
const AHEAD: usize = 8;

/// Asks for the modulation [`AHEAD`] chunks on (two cache lines a chunk). A prefetch reads
/// nothing and faults on no address, so one past the end of the span is harmless.
#[inline(always)]
fn prefetch(simd: V4, layer: &ActiveLayer<'_>, first_col: usize) {
    let at = (first_col + AHEAD * LANES).wrapping_sub(layer.first);
    let p = layer.modulation.as_ptr().wrapping_add(at).cast::<i8>();
    simd.sse
        ._mm_prefetch::<{ core::arch::x86_64::_MM_HINT_T0 }>(p);
    simd.sse
        ._mm_prefetch::<{ core::arch::x86_64::_MM_HINT_T0 }>(p.wrapping_add(64));
}

impl Vector for V4 {
    type V = __m512;
    type Mask = __mmask16;
    #[inline(always)]
    fn splat(self, x: f32) -> __m512 {
        self.avx512f._mm512_set1_ps(x)
    }
    #[inline(always)]
    fn add(self, a: __m512, b: __m512) -> __m512 {
        self.avx512f._mm512_add_ps(a, b)
    }
    #[inline(always)]
    fn sub(self, a: __m512, b: __m512) -> __m512 {
        self.avx512f._mm512_sub_ps(a, b)
    }
    #[inline(always)]
    fn mul(self, a: __m512, b: __m512) -> __m512 {
        self.avx512f._mm512_mul_ps(a, b)
    }
    #[inline(always)]
    fn div(self, a: __m512, b: __m512) -> __m512 {
        self.avx512f._mm512_div_ps(a, b)
    }
    #[inline(always)]
    fn sqrt(self, a: __m512) -> __m512 {
        self.avx512f._mm512_sqrt_ps(a)
    }
    #[inline(always)]
    fn less(self, a: __m512, b: __m512) -> __mmask16 {
        self.avx512f
            ._mm512_cmp_ps_mask::<{ core::arch::x86_64::_CMP_LT_OQ }>(a, b)
    }
    #[inline(always)]
    fn select(self, m: __mmask16, t: __m512, f: __m512) -> __m512 {
        self.avx512f._mm512_mask_blend_ps(m, f, t)
    }
}

/// `Acc::finish` and its interleaved stores: the chunk from grid column `first_col` of a row
/// at `z`, columns `dx` apart, into the first `pos.len()` (at most 16) points.
#[inline(always)]
fn finish(
    simd: V4,
    sums: Sums<__m512>,
    first_col: usize,
    dx: f32,
    z: f32,
    pos: &mut [Vec3],
    nrm: &mut [Vec3],
) {
    // (first + LANE_INDEX[l]) · dx, as the portable kernel forms x.
    let x = simd.mul(
        simd.add(simd.splat(first_col as f32), v(LANE_INDEX)),
        simd.splat(dx),
    );
    let ([px, py, pz], [nx, ny, nz]) = sums.finish(simd, x, z);
    store(interleave(simd, px, py, pz), pos);
    store(interleave(simd, nx, ny, nz), nrm);
}

#[inline(always)]
fn row(simd: V4, row: LayerRow<'_>) {
    let f = simd.avx512f;
    let LayerRow {
        layers,
        rows,
        height,
        first_chunk,
        dx,
        z,
        pos: out_pos,
        nrm: out_nrm,
    } = row;
    let magnitude = f._mm512_set1_epi32(0x7fff_ffff);
    for (n, (pos, nrm)) in out_pos
        .chunks_mut(LANES)
        .zip(out_nrm.chunks_mut(LANES))
        .enumerate()
    {
        let c = first_chunk + n;
        let first_col = c * LANES;
        let mut sums = Sums::new(simd);
        for layer in layers {
            if !layer.touches(first_col, LANES) {
                continue;
            }
            prefetch(simd, layer, first_col);
            let (mr, mi) = modulation(simd, layer, first_col);
            // Skip a layer whose μ is zero on every lane (land): it would add ±0.
            let bits = f._mm512_or_si512(bytemuck::cast(mr), bytemuck::cast(mi));
            if f._mm512_test_epi32_mask(bits, magnitude) == 0 {
                continue;
            }
            let rows = &rows[layer.rows.clone()];
            for ((k, &[rs, rc]), col) in layer.coeffs.iter().zip(rows).zip(layer.table(c)) {
                let (sin, cos) = angle_sum(simd, rs, rc, v(col.sin), v(col.cos));
                let (s, co) = modulate(simd, sin, cos, mr, mi);
                sums.add(simd, k, s, co);
            }
        }
        if let Some(h) = height {
            let len = pos.len().min(LANES);
            let mut add_h = [0.0f32; LANES];
            add_h[..len].copy_from_slice(&h[first_col..first_col + len]);
            sums.y = simd.add(sums.y, v(add_h));
        }
        finish(simd, sums, first_col, dx, z, pos, nrm);
    }
}

/// One row of [`WaveSet::evaluate_grid`](crate::WaveSet::evaluate_grid) on AVX-512: the
/// trochoid grid kernel (`crate::trochoid`) with the same operations, lane for lane.
pub(crate) struct WideGrid<'a>(pub(crate) V4, pub(crate) GridRow<'a>);

impl pulp::WithSimd for WideGrid<'_> {
    type Output = ();
    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) {
        let WideGrid(
            simd,
            GridRow {
                coeffs,
                rows,
                cols,
                dx,
                z,
                pos,
                nrm,
            },
        ) = self;
        let block = coeffs.len();
        for (c, (pos, nrm)) in pos.chunks_mut(LANES).zip(nrm.chunks_mut(LANES)).enumerate() {
            let table = &cols[c * block..(c + 1) * block];
            let mut sums = Sums::new(simd);
            for ((k, &[rs, rc]), col) in coeffs.iter().zip(rows).zip(table) {
                let (s, co) = angle_sum(simd, rs, rc, v(col.sin), v(col.cos));
                sums.add(simd, k, s, co);
            }
            finish(simd, sums, c * LANES, dx, z, pos, nrm);
        }
    }
}

/// Writes the first `out.len()` (at most 16) of 16 interleaved points.
#[inline(always)]
fn store(xyz: [__m512; 3], out: &mut [Vec3]) {
    if out.len() >= LANES {
        // Three whole vectors: fixed-size stores straight from the registers.
        let full: &mut [[f32; LANES]] = bytemuck::cast_slice_mut(&mut out[..LANES]);
        for (o, v) in full.iter_mut().zip(xyz) {
            *o = bytemuck::cast(v);
        }
    } else {
        let staged: [[f32; LANES]; 3] = xyz.map(bytemuck::cast);
        let flat: &[f32] = bytemuck::cast_slice(&staged);
        let n = out.len();
        bytemuck::cast_slice_mut::<Vec3, f32>(out).copy_from_slice(&flat[..3 * n]);
    }
}
