//! The `f32` trochoid kernel, shaped for auto-vectorisation.
//!
//! Points are processed in chunks of [`LANES`]; every operation is written element-wise over
//! `[f32; LANES]` arrays, which LLVM turns into SSE2, AVX2 or NEON instructions. Each lane sees
//! the same sequence of IEEE operations whatever the vector width, and there is no fused
//! multiply-add, so results are bit-identical across targets and thread counts.

// Lane loops index several arrays in step; that indexed shape is what LLVM vectorises.
#![allow(clippy::needless_range_loop)]

use glam::Vec3;

use crate::sincos::sincos;
use crate::wave::Wave;

/// Points per chunk of the `f32` kernel.
///
/// Sixteen lanes are two AVX2 vectors. The normalisation and the stores run on both at once,
/// so two independent dependency chains hide the latency of the square root and division,
/// which dominate when there are few waves; the grid kernel sums the waves over half chunks
/// (eight lanes) so that the running sums stay in registers.
pub const LANES: usize = 16;

/// Per-wave constants of the `f32` kernel, derived once from a [`Wave`].
///
/// With θ = k·p₀ − ωt + Φ, s = sin θ, c = cos θ, k̂ = k/|k|, the wave contributes (Eq. 6, 7):
/// displacement −k̂ A s (horizontal) and A c (vertical); horizontal Jacobian
/// ∂p/∂p₀ −= (k kᵀ/|k|) A c; height gradient ∂y/∂p₀ −= k A s.
///
/// `#[repr(C)]` and [`bytemuck::Pod`]: the GPU pass uploads this array as it is (32 bytes per
/// wave, the layout of WGSL's `WaveCoeffs`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct WaveCoeffs {
    /// A.
    pub a: f32,
    /// A k_x/|k|.
    pub ahx: f32,
    /// A k_z/|k|.
    pub ahz: f32,
    /// A k_x²/|k|.
    pub cxx: f32,
    /// A k_x k_z/|k|.
    pub cxz: f32,
    /// A k_z²/|k|.
    pub czz: f32,
    /// A k_x.
    pub gx: f32,
    /// A k_z.
    pub gz: f32,
}

impl WaveCoeffs {
    /// The kernel constants of `wave`, computed in `f64` and rounded once.
    pub fn of(wave: &Wave) -> Self {
        let a = wave.amplitude();
        let k = wave.wave_vector();
        let m = wave.wavenumber();
        Self {
            a: a as f32,
            ahx: (a * k.x / m) as f32,
            ahz: (a * k.y / m) as f32,
            cxx: (a * k.x * k.x / m) as f32,
            cxz: (a * k.x * k.y / m) as f32,
            czz: (a * k.y * k.y / m) as f32,
            gx: (a * k.x) as f32,
            gz: (a * k.y) as f32,
        }
    }
}

/// Running sums over the waves for `N` points (a chunk has [`LANES`]; the grid kernel sums half
/// chunks, see [`HALF`]).
pub(crate) struct Acc<const N: usize = LANES> {
    dx: [f32; N],
    y: [f32; N],
    dz: [f32; N],
    jxx: [f32; N],
    jxz: [f32; N],
    jzz: [f32; N],
    sx: [f32; N],
    sz: [f32; N],
}

/// Half a chunk: eight sums of eight lanes each are eight AVX2 registers, so a loop over the
/// waves keeps them all in registers; a whole chunk's sixteen would spill on every wave.
pub(crate) const HALF: usize = LANES / 2;

impl<const N: usize> Acc<N> {
    #[inline(always)]
    pub(crate) fn new() -> Self {
        Self {
            dx: [0.0; N],
            y: [0.0; N],
            dz: [0.0; N],
            jxx: [1.0; N],
            jxz: [0.0; N],
            jzz: [1.0; N],
            sx: [0.0; N],
            sz: [0.0; N],
        }
    }

    /// Adds one wave given sin θ and cos θ per lane.
    #[inline(always)]
    pub(crate) fn add_sin_cos(&mut self, c: &WaveCoeffs, s: &[f32; N], co: &[f32; N]) {
        for l in 0..N {
            let (s, co) = (s[l], co[l]);
            self.dx[l] -= c.ahx * s;
            self.dz[l] -= c.ahz * s;
            self.y[l] += c.a * co;
            self.jxx[l] -= c.cxx * co;
            self.jxz[l] -= c.cxz * co;
            self.jzz[l] -= c.czz * co;
            self.sx[l] -= c.gx * s;
            self.sz[l] -= c.gz * s;
        }
    }
}

impl Acc<LANES> {
    /// Adds `h` to the heights (an additive height field: noise, run-up).
    #[inline(always)]
    pub(crate) fn add_height(&mut self, h: &[f32; LANES]) {
        for l in 0..LANES {
            self.y[l] += h[l];
        }
    }

    /// Chunk sums from the sums of its two halves.
    #[inline(always)]
    pub(crate) fn from_halves(lo: &Acc<HALF>, hi: &Acc<HALF>) -> Self {
        let mut v = Self::new();
        for l in 0..HALF {
            v.dx[l] = lo.dx[l];
            v.y[l] = lo.y[l];
            v.dz[l] = lo.dz[l];
            v.jxx[l] = lo.jxx[l];
            v.jxz[l] = lo.jxz[l];
            v.jzz[l] = lo.jzz[l];
            v.sx[l] = lo.sx[l];
            v.sz[l] = lo.sz[l];
            v.dx[HALF + l] = hi.dx[l];
            v.y[HALF + l] = hi.y[l];
            v.dz[HALF + l] = hi.dz[l];
            v.jxx[HALF + l] = hi.jxx[l];
            v.jxz[HALF + l] = hi.jxz[l];
            v.jzz[HALF + l] = hi.jzz[l];
            v.sx[HALF + l] = hi.sx[l];
            v.sz[HALF + l] = hi.sz[l];
        }
        v
    }

    /// Adds one wave at phases `theta` (each in [-2π, 2π]).
    #[inline(always)]
    pub(crate) fn add(&mut self, c: &WaveCoeffs, theta: &[f32; LANES]) {
        let mut s = [0.0f32; LANES];
        let mut co = [0.0f32; LANES];
        for l in 0..LANES {
            (s[l], co[l]) = sincos(theta[l]);
        }
        self.add_sin_cos(c, &s, &co);
    }

    /// Writes the first `out_pos.len()` lanes: positions `(x + dx, y, z + dz)` and unit normals.
    ///
    /// The normal is ∂p/∂z × ∂p/∂x with ∂p/∂x = (J_xx, s_x, J_xz) and ∂p/∂z = (J_xz, s_z, J_zz);
    /// its y component is det J, which stays ≥ 0 while the steepness sum is ≤ 1. Where the cross
    /// product vanishes (|n|² below `f32::MIN_POSITIVE`, which happens only at a cusp,
    /// k·A = 1) the normal is taken as +y.
    #[inline(always)]
    pub(crate) fn finish(
        &self,
        x: &[f32; LANES],
        z: &[f32; LANES],
        out_pos: &mut [Vec3],
        out_nrm: &mut [Vec3],
    ) {
        let mut px = [0.0f32; LANES];
        let mut pz = [0.0f32; LANES];
        let mut nx = [0.0f32; LANES];
        let mut ny = [0.0f32; LANES];
        let mut nz = [0.0f32; LANES];
        for l in 0..LANES {
            px[l] = x[l] + self.dx[l];
            pz[l] = z[l] + self.dz[l];
            let a = self.sz[l] * self.jxz[l] - self.jzz[l] * self.sx[l];
            let b = self.jzz[l] * self.jxx[l] - self.jxz[l] * self.jxz[l];
            let c = self.jxz[l] * self.sx[l] - self.sz[l] * self.jxx[l];
            let len2 = a * a + b * b + c * c;
            // Below the smallest normal float the cross product has no meaningful direction
            // (|n| < 1.1e-19, only next to a cusp).
            let degenerate = len2 < f32::MIN_POSITIVE;
            let inv = 1.0 / crate::math::sqrtf(if degenerate { 1.0 } else { len2 });
            nx[l] = if degenerate { 0.0 } else { a * inv };
            ny[l] = if degenerate { 1.0 } else { b * inv };
            nz[l] = if degenerate { 0.0 } else { c * inv };
        }
        if out_pos.len() >= LANES && out_nrm.len() >= LANES {
            // Full chunk: interleave into xyz order here and store contiguous runs, instead
            // of six scalar stores per point.
            let mut p = [0.0f32; 3 * LANES];
            let mut q = [0.0f32; 3 * LANES];
            for l in 0..LANES {
                p[3 * l] = px[l];
                p[3 * l + 1] = self.y[l];
                p[3 * l + 2] = pz[l];
                q[3 * l] = nx[l];
                q[3 * l + 1] = ny[l];
                q[3 * l + 2] = nz[l];
            }
            bytemuck::cast_slice_mut::<Vec3, f32>(&mut out_pos[..LANES]).copy_from_slice(&p);
            bytemuck::cast_slice_mut::<Vec3, f32>(&mut out_nrm[..LANES]).copy_from_slice(&q);
        } else {
            for l in 0..out_pos.len().min(LANES) {
                out_pos[l] = Vec3::new(px[l], self.y[l], pz[l]);
                out_nrm[l] = Vec3::new(nx[l], ny[l], nz[l]);
            }
        }
    }
}

// The arguments of the row kernels, shared by the portable kernels (`trochoid`, `layers`) and
// their AVX2 and AVX-512 twins, which must not depend on the modules that dispatch to them.

/// 0, 1, …, LANES − 1 as floats.
pub(crate) const LANE_INDEX: [f32; LANES] = {
    let mut v = [0.0f32; LANES];
    let mut l = 0;
    while l < LANES {
        v[l] = l as f32;
        l += 1;
    }
    v
};

/// sin and cos of one wave's phase at the columns of one chunk.
#[derive(Clone, Copy)]
pub(crate) struct ColumnSinCos {
    pub(crate) sin: [f32; LANES],
    pub(crate) cos: [f32; LANES],
}

impl ColumnSinCos {
    pub(crate) const ZERO: Self = Self {
        sin: [0.0; LANES],
        cos: [0.0; LANES],
    };
}

/// One grid row: the arguments of `trochoid`'s grid row kernel (and of its AVX2 and AVX-512
/// twins, `crate::avx2::HalfGrid` and `crate::avx512::WideGrid`).
pub(crate) struct GridRow<'a> {
    pub(crate) coeffs: &'a [WaveCoeffs],
    pub(crate) rows: &'a [[f32; 2]],
    pub(crate) cols: &'a [ColumnSinCos],
    pub(crate) dx: f32,
    pub(crate) z: f32,
    pub(crate) pos: &'a mut [Vec3],
    pub(crate) nrm: &'a mut [Vec3],
}

/// One layer's data for one grid row.
pub(crate) struct ActiveLayer<'a> {
    pub(crate) coeffs: &'a [WaveCoeffs],
    /// Where the sin and cos of each wave's row phase lie in the row's table (`layers`'s
    /// `Scratch::rows`).
    pub(crate) rows: core::ops::Range<usize>,
    /// The layer's column table (see `trochoid`'s `GridPlan`).
    pub(crate) cols: &'a [ColumnSinCos],
    /// The grid column of `modulation[0]`.
    pub(crate) first: usize,
    /// The layer's modulation along this row, over the row's span of non-zero values: zero
    /// on either side.
    pub(crate) modulation: &'a [[f32; 2]],
}

impl ActiveLayer<'_> {
    /// The grid column past the row's span.
    #[inline(always)]
    fn end(&self) -> usize {
        self.first + self.modulation.len()
    }

    /// Whether the span reaches into the `n` columns from grid column `col`.
    #[inline(always)]
    pub(crate) fn touches(&self, col: usize, n: usize) -> bool {
        self.end() > col && self.first < col + n
    }

    /// The `n` values of μ from grid column `col`, if the span holds all of them.
    #[inline(always)]
    pub(crate) fn run(&self, col: usize, n: usize) -> Option<&[[f32; 2]]> {
        (col >= self.first && col + n <= self.end())
            .then(|| &self.modulation[col - self.first..][..n])
    }

    /// μ on the `N` lanes from grid column `col` where the span covers them in part (at most
    /// two runs a layer and row): real and imaginary parts, zero outside the span. Kept out of
    /// line so that the kernels' loops do not carry its index arithmetic.
    #[inline(never)]
    pub(crate) fn partial<const N: usize>(&self, col: usize) -> ([f32; N], [f32; N]) {
        let (mut re, mut im) = ([0.0f32; N], [0.0f32; N]);
        for l in 0..N {
            let i = col + l;
            if i >= self.first && i < self.end() {
                [re[l], im[l]] = self.modulation[i - self.first];
            }
        }
        (re, im)
    }

    /// The column table entries of chunk `c`, one a wave.
    #[inline(always)]
    pub(crate) fn table(&self, c: usize) -> &[ColumnSinCos] {
        let waves = self.coeffs.len();
        &self.cols[c * waves..(c + 1) * waves]
    }
}

/// One grid row of a layered evaluation: the arguments of `layers`'s row kernel and of its
/// AVX2 and AVX-512 twins.
pub(crate) struct LayerRow<'a> {
    pub(crate) layers: &'a [ActiveLayer<'a>],
    pub(crate) rows: &'a [[f32; 2]],
    pub(crate) height: Option<&'a [f32]>,
    /// Chunk of the row where `pos` and `nrm` start.
    pub(crate) first_chunk: usize,
    pub(crate) dx: f32,
    pub(crate) z: f32,
    pub(crate) pos: &'a mut [Vec3],
    pub(crate) nrm: &'a mut [Vec3],
}
