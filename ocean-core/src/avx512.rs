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

use core::arch::x86_64::{__m512, __m512i};

use glam::Vec3;
use pulp::x86::V4;

use crate::kernel::{LANES, WaveCoeffs};
use crate::layers::{ActiveLayer, LayerRow};
use crate::trochoid::{ColumnSinCos, GridRow, LANE_INDEX};

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
    let end = layer.first + layer.modulation.len();
    if first_col >= layer.first && first_col + LANES <= end {
        let run = &layer.modulation[first_col - layer.first..][..LANES];
        // 16 pairs are two vectors of 16 floats.
        let halves: &[[f32; LANES]] = bytemuck::cast_slice(run);
        let (lo, hi) = (v(halves[0]), v(halves[1]));
        (
            f._mm512_permutex2var_ps(lo, vi(EVEN), hi),
            f._mm512_permutex2var_ps(lo, vi(ODD), hi),
        )
    } else {
        partial_modulation(layer, first_col, end)
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

/// [`modulation`] for a chunk that the span covers in part (at most two a layer and row).
#[inline(never)]
fn partial_modulation(layer: &ActiveLayer<'_>, first_col: usize, end: usize) -> (__m512, __m512) {
    let mut re = [0.0f32; LANES];
    let mut im = [0.0f32; LANES];
    for l in 0..LANES {
        let i = first_col + l;
        if i >= layer.first && i < end {
            [re[l], im[l]] = layer.modulation[i - layer.first];
        }
    }
    (v(re), v(im))
}

/// The eight running sums of a chunk ([`Acc`](crate::kernel::Acc)'s fields), one vector each.
#[derive(Clone, Copy)]
struct Sums {
    dx: __m512,
    y: __m512,
    dz: __m512,
    jxx: __m512,
    jxz: __m512,
    jzz: __m512,
    sx: __m512,
    sz: __m512,
}

impl Sums {
    /// `Acc::new`: zero displacement, identity Jacobian, zero slope.
    #[inline(always)]
    fn new(simd: V4) -> Self {
        let f = simd.avx512f;
        let (zero, one) = (f._mm512_setzero_ps(), f._mm512_set1_ps(1.0));
        Self {
            dx: zero,
            y: zero,
            dz: zero,
            jxx: one,
            jxz: zero,
            jzz: one,
            sx: zero,
            sz: zero,
        }
    }

    /// `Acc::add_sin_cos`: one wave, given its sine and cosine on every lane.
    #[inline(always)]
    fn add(&mut self, simd: V4, k: &WaveCoeffs, s: __m512, co: __m512) {
        let f = simd.avx512f;
        let b = |x: f32| f._mm512_set1_ps(x);
        let (add, sub, mul) = (
            |a, b| f._mm512_add_ps(a, b),
            |a, b| f._mm512_sub_ps(a, b),
            |a, b| f._mm512_mul_ps(a, b),
        );
        self.dx = sub(self.dx, mul(b(k.ahx), s));
        self.dz = sub(self.dz, mul(b(k.ahz), s));
        self.y = add(self.y, mul(b(k.a), co));
        self.jxx = sub(self.jxx, mul(b(k.cxx), co));
        self.jxz = sub(self.jxz, mul(b(k.cxz), co));
        self.jzz = sub(self.jzz, mul(b(k.czz), co));
        self.sx = sub(self.sx, mul(b(k.gx), s));
        self.sz = sub(self.sz, mul(b(k.gz), s));
    }

    /// `Acc::finish` and its interleaved stores: the chunk from grid column `first_col` of
    /// a row at `z`, columns `dx` apart, into the first `pos.len()` (at most 16) points.
    #[inline(always)]
    fn finish(
        self,
        simd: V4,
        first_col: usize,
        dx: f32,
        z: f32,
        pos: &mut [Vec3],
        nrm: &mut [Vec3],
    ) {
        let f = simd.avx512f;
        let (add, sub, mul) = (
            |a, b| f._mm512_add_ps(a, b),
            |a, b| f._mm512_sub_ps(a, b),
            |a, b| f._mm512_mul_ps(a, b),
        );
        let (zero, one) = (f._mm512_setzero_ps(), f._mm512_set1_ps(1.0));
        let Sums {
            dx: sdx,
            y,
            dz: sdz,
            jxx,
            jxz,
            jzz,
            sx,
            sz,
        } = self;
        let x = mul(
            add(f._mm512_set1_ps(first_col as f32), v(LANE_INDEX)),
            f._mm512_set1_ps(dx),
        );
        let px = add(x, sdx);
        let pz = add(f._mm512_set1_ps(z), sdz);
        let a = sub(mul(sz, jxz), mul(jzz, sx));
        let b = sub(mul(jzz, jxx), mul(jxz, jxz));
        let c = sub(mul(jxz, sx), mul(sz, jxx));
        let len2 = add(add(mul(a, a), mul(b, b)), mul(c, c));
        let degenerate = f._mm512_cmp_ps_mask::<{ core::arch::x86_64::_CMP_LT_OQ }>(
            len2,
            f._mm512_set1_ps(f32::MIN_POSITIVE),
        );
        let inv = f._mm512_div_ps(
            one,
            f._mm512_sqrt_ps(f._mm512_mask_blend_ps(degenerate, len2, one)),
        );
        let nx = f._mm512_mask_blend_ps(degenerate, mul(a, inv), zero);
        let ny = f._mm512_mask_blend_ps(degenerate, mul(b, inv), one);
        let nz = f._mm512_mask_blend_ps(degenerate, mul(c, inv), zero);
        store(interleave(simd, px, y, pz), pos);
        store(interleave(simd, nx, ny, nz), nrm);
    }
}

/// sin θ and cos θ of every lane of one wave from its row's (`rs`, `rc`) and its column
/// table's values, by angle addition: the grid kernels' four products and two sums.
#[inline(always)]
fn angle_sum(simd: V4, rs: f32, rc: f32, col: &ColumnSinCos) -> (__m512, __m512) {
    let f = simd.avx512f;
    let (add, sub, mul) = (
        |a, b| f._mm512_add_ps(a, b),
        |a, b| f._mm512_sub_ps(a, b),
        |a, b| f._mm512_mul_ps(a, b),
    );
    let (cs, cc) = (v(col.sin), v(col.cos));
    let (rs, rc) = (f._mm512_set1_ps(rs), f._mm512_set1_ps(rc));
    (add(mul(rs, cc), mul(rc, cs)), sub(mul(rc, cc), mul(rs, cs)))
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
    let (add, sub, mul) = (
        |a, b| f._mm512_add_ps(a, b),
        |a, b| f._mm512_sub_ps(a, b),
        |a, b| f._mm512_mul_ps(a, b),
    );
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
            let end = layer.first + layer.modulation.len();
            if end <= first_col || layer.first >= first_col + LANES {
                continue;
            }
            prefetch(simd, layer, first_col);
            let (mr, mi) = modulation(simd, layer, first_col);
            // Skip a layer whose μ is zero on every lane (land): it would add ±0.
            let bits = f._mm512_or_si512(bytemuck::cast(mr), bytemuck::cast(mi));
            if f._mm512_test_epi32_mask(bits, magnitude) == 0 {
                continue;
            }
            let waves = layer.coeffs.len();
            let table = &layer.cols[c * waves..(c + 1) * waves];
            let rows = &rows[layer.rows.clone()];
            for ((k, &[rs, rc]), col) in layer.coeffs.iter().zip(rows).zip(table) {
                let (sin, cos) = angle_sum(simd, rs, rc, col);
                let s = add(mul(sin, mr), mul(cos, mi));
                let co = sub(mul(cos, mr), mul(sin, mi));
                sums.add(simd, k, s, co);
            }
        }
        if let Some(h) = height {
            let len = pos.len().min(LANES);
            let mut add_h = [0.0f32; LANES];
            add_h[..len].copy_from_slice(&h[first_col..first_col + len]);
            sums.y = add(sums.y, v(add_h));
        }
        sums.finish(simd, first_col, dx, z, pos, nrm);
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
                let (s, co) = angle_sum(simd, rs, rc, col);
                sums.add(simd, k, s, co);
            }
            sums.finish(simd, c * LANES, dx, z, pos, nrm);
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
