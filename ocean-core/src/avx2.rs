//! The layers kernel ([`crate::layers`]) and the trochoid grid kernel ([`crate::trochoid`])
//! written out in AVX2, for CPUs without AVX-512 ([`crate::avx512`] has the wide twin).
//!
//! With 16 vector registers a chunk is summed in two halves of eight lanes, each half's eight
//! sums in registers across every layer and wave, and each half is finished and stored on its
//! own. Written with intrinsics (pulp's safe wrappers) rather than left to LLVM's vectoriser:
//! for the same loops it joined the halves through the stack, hoisted the partial-span path's
//! index arithmetic into every chunk and interleaved the stores with a long chain of shuffles,
//! about 900 instructions per 16-point chunk of which 240 were the waves' arithmetic.
//!
//! **Bits.** Every lane performs exactly the IEEE operations of the portable kernel, in the
//! same order, with no fused multiply-add, so the output is bit-identical to the portable and
//! AVX-512 paths (`tests/layers_isa.rs`).

use core::arch::x86_64::{__m256, __m256d, __m256i};

use glam::Vec3;
use pulp::x86::V3;

use crate::kernel::{ActiveLayer, GridRow, HALF, LANE_INDEX, LANES, LayerRow};
use crate::vector::{Sums, Vector, angle_sum, modulate};

const _: () = assert!(HALF == 8, "one AVX2 vector per half chunk");

#[inline(always)]
fn v(a: [f32; HALF]) -> __m256 {
    bytemuck::cast(a)
}

/// Lanes `h·8 … h·8 + 7` of a chunk's array.
#[inline(always)]
fn half(a: &[f32; LANES], h: usize) -> __m256 {
    let halves: &[[f32; HALF]; 2] = bytemuck::cast_ref(a);
    v(halves[h])
}

impl Vector for V3 {
    type V = __m256;
    /// All bits set in a lane where the condition holds.
    type Mask = __m256;
    #[inline(always)]
    fn splat(self, x: f32) -> __m256 {
        self.avx._mm256_set1_ps(x)
    }
    #[inline(always)]
    fn add(self, a: __m256, b: __m256) -> __m256 {
        self.avx._mm256_add_ps(a, b)
    }
    #[inline(always)]
    fn sub(self, a: __m256, b: __m256) -> __m256 {
        self.avx._mm256_sub_ps(a, b)
    }
    #[inline(always)]
    fn mul(self, a: __m256, b: __m256) -> __m256 {
        self.avx._mm256_mul_ps(a, b)
    }
    #[inline(always)]
    fn div(self, a: __m256, b: __m256) -> __m256 {
        self.avx._mm256_div_ps(a, b)
    }
    #[inline(always)]
    fn sqrt(self, a: __m256) -> __m256 {
        self.avx._mm256_sqrt_ps(a)
    }
    #[inline(always)]
    fn less(self, a: __m256, b: __m256) -> __m256 {
        self.avx
            ._mm256_cmp_ps::<{ core::arch::x86_64::_CMP_LT_OQ }>(a, b)
    }
    #[inline(always)]
    fn select(self, m: __m256, t: __m256, f: __m256) -> __m256 {
        self.avx._mm256_blendv_ps(f, t, m)
    }
}

/// `Acc::finish` and its interleaved stores for the half chunk whose first lane is lane
/// `h·8` of the chunk from grid column `chunk_col`, into the first `pos.len()` (at most 8)
/// points.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn finish(
    simd: V3,
    sums: Sums<__m256>,
    chunk_col: usize,
    h: usize,
    dx: f32,
    z: f32,
    pos: &mut [Vec3],
    nrm: &mut [Vec3],
) {
    // (first + LANE_INDEX[l]) · dx with the chunk's first column, as the portable kernel.
    let first = simd.splat(chunk_col as f32);
    let x = simd.mul(simd.add(first, half(&LANE_INDEX, h)), simd.splat(dx));
    let ([px, py, pz], [nx, ny, nz]) = sums.finish(simd, x, z);
    store(interleave(simd, px, py, pz), pos);
    store(interleave(simd, nx, ny, nz), nrm);
}

/// Eight points' x, y, z interleaved as `xyz`: three vectors.
///
/// Each 128-bit half first interleaves its four points into A = (x0 y0 z0 x1),
/// B = (y1 z1 x2 y2), C = (z2 x3 y3 z3) (and x4 … z7 in the upper halves); the outputs then take
/// their halves from A, B, C: (A.lo, B.lo), (C.lo, A.hi), (B.hi, C.hi). Eleven shuffles.
#[inline(always)]
fn interleave(simd: V3, x: __m256, y: __m256, z: __m256) -> [__m256; 3] {
    let avx = simd.avx;
    let xy_lo = avx._mm256_unpacklo_ps(x, y); // x0 y0 x1 y1
    let xy_hi = avx._mm256_unpackhi_ps(x, y); // x2 y2 x3 y3
    let yz_lo = avx._mm256_unpacklo_ps(y, z); // y0 z0 y1 z1
    let yz_hi = avx._mm256_unpackhi_ps(y, z); // y2 z2 y3 z3
    let zx_lo = avx._mm256_shuffle_ps::<0x50>(z, x); // z0 z0 x1 x1
    let zx_hi = avx._mm256_shuffle_ps::<0xFA>(z, x); // z2 z2 x3 x3
    let a = avx._mm256_shuffle_ps::<0x84>(xy_lo, zx_lo); // x0 y0 z0 x1
    let b = avx._mm256_shuffle_ps::<0x4E>(yz_lo, xy_hi); // y1 z1 x2 y2
    let c = avx._mm256_shuffle_ps::<0xE8>(zx_hi, yz_hi); // z2 x3 y3 z3
    [
        avx._mm256_permute2f128_ps::<0x20>(a, b),
        avx._mm256_permute2f128_ps::<0x30>(c, a),
        avx._mm256_permute2f128_ps::<0x31>(b, c),
    ]
}

/// Writes the first `out.len()` (at most 8) of 8 interleaved points.
#[inline(always)]
fn store(xyz: [__m256; 3], out: &mut [Vec3]) {
    if out.len() >= HALF {
        let full: &mut [[f32; HALF]] = bytemuck::cast_slice_mut(&mut out[..HALF]);
        for (o, v) in full.iter_mut().zip(xyz) {
            *o = bytemuck::cast(v);
        }
    } else {
        let staged: [[f32; HALF]; 3] = xyz.map(bytemuck::cast);
        let flat: &[f32] = bytemuck::cast_slice(&staged);
        let n = out.len();
        bytemuck::cast_slice_mut::<Vec3, f32>(out).copy_from_slice(&flat[..3 * n]);
    }
}

/// The modulation of the eight lanes from grid column `col`, zero outside the layer's span:
/// (real parts, imaginary parts).
#[inline(always)]
fn modulation(simd: V3, layer: &ActiveLayer<'_>, col: usize) -> (__m256, __m256) {
    match layer.run(col, HALF) {
        Some(run) => {
            // Eight pairs are two vectors of eight floats.
            let pairs: &[[f32; HALF]] = bytemuck::cast_slice(run);
            let (lo, hi) = (v(pairs[0]), v(pairs[1]));
            let avx = simd.avx;
            // Even floats, then odd, in 64-bit blocks (0, 2, 1, 3) of the true order.
            let re = avx._mm256_shuffle_ps::<0x88>(lo, hi);
            let im = avx._mm256_shuffle_ps::<0xDD>(lo, hi);
            let order = |a: __m256| -> __m256 {
                let a: __m256d = bytemuck::cast(a);
                bytemuck::cast(simd.avx2._mm256_permute4x64_pd::<0xD8>(a))
            };
            (order(re), order(im))
        }
        None => {
            let (re, im) = layer.partial::<HALF>(col);
            (v(re), v(im))
        }
    }
}

/// Half chunks of modulation read ahead of the kernel (one cache line each).
const AHEAD: usize = 16;

#[inline(always)]
fn prefetch(simd: V3, layer: &ActiveLayer<'_>, col: usize) {
    let at = (col + AHEAD * HALF).wrapping_sub(layer.first);
    let p = layer.modulation.as_ptr().wrapping_add(at).cast::<i8>();
    simd.sse
        ._mm_prefetch::<{ core::arch::x86_64::_MM_HINT_T0 }>(p);
}

/// One row of [`crate::layers`] on AVX2: what [`pulp::Simd::vectorize`] runs.
pub(crate) struct Half<'a>(pub(crate) V3, pub(crate) LayerRow<'a>);

impl pulp::WithSimd for Half<'_> {
    type Output = ();
    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) {
        let Half(simd, row) = self;
        let f = simd.avx;
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
        let magnitude: __m256i = bytemuck::cast([0x7fff_ffffu32; HALF]);
        for (n, (pos, nrm)) in out_pos
            .chunks_mut(LANES)
            .zip(out_nrm.chunks_mut(LANES))
            .enumerate()
        {
            let c = first_chunk + n;
            let chunk_col = c * LANES;
            for (h, (pos, nrm)) in pos.chunks_mut(HALF).zip(nrm.chunks_mut(HALF)).enumerate() {
                let col = chunk_col + h * HALF;
                let mut sums = Sums::new(simd);
                for layer in layers {
                    if !layer.touches(col, HALF) {
                        continue;
                    }
                    prefetch(simd, layer, col);
                    let (mr, mi) = modulation(simd, layer, col);
                    // Skip a layer whose μ is zero on every lane (land): it would add ±0.
                    let bits = simd
                        .avx2
                        ._mm256_or_si256(bytemuck::cast(mr), bytemuck::cast(mi));
                    if f._mm256_testz_si256(bits, magnitude) == 1 {
                        continue;
                    }
                    let rows = &rows[layer.rows.clone()];
                    for ((k, &[rs, rc]), entry) in layer.coeffs.iter().zip(rows).zip(layer.table(c))
                    {
                        let (cs, cc) = (half(&entry.sin, h), half(&entry.cos, h));
                        let (sin, cos) = angle_sum(simd, rs, rc, cs, cc);
                        let (s, co) = modulate(simd, sin, cos, mr, mi);
                        sums.add(simd, k, s, co);
                    }
                }
                if let Some(hf) = height {
                    let len = pos.len();
                    let mut add_h = [0.0f32; HALF];
                    add_h[..len].copy_from_slice(&hf[col..col + len]);
                    sums.y = simd.add(sums.y, v(add_h));
                }
                finish(simd, sums, chunk_col, h, dx, z, pos, nrm);
            }
        }
    }
}

/// One row of [`WaveSet::evaluate_grid`](crate::WaveSet::evaluate_grid) on AVX2: the trochoid
/// grid kernel (`crate::trochoid`) with the same operations, lane for lane.
pub(crate) struct HalfGrid<'a>(pub(crate) V3, pub(crate) GridRow<'a>);

impl pulp::WithSimd for HalfGrid<'_> {
    type Output = ();
    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) {
        let HalfGrid(
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
            for (h, (pos, nrm)) in pos.chunks_mut(HALF).zip(nrm.chunks_mut(HALF)).enumerate() {
                let mut sums = Sums::new(simd);
                for ((k, &[rs, rc]), entry) in coeffs.iter().zip(rows).zip(table) {
                    let (cs, cc) = (half(&entry.sin, h), half(&entry.cos, h));
                    let (s, co) = angle_sum(simd, rs, rc, cs, cc);
                    sums.add(simd, k, s, co);
                }
                finish(simd, sums, c * LANES, h, dx, z, pos, nrm);
            }
        }
    }
}
