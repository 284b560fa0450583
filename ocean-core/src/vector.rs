//! What the hand-written kernels (`avx2.rs`, `avx512.rs`) share: the per-lane arithmetic of
//! [`Acc`](crate::kernel::Acc), written once over any vector type.
//!
//! Each operation is one IEEE operation per lane, in the portable kernel's order, with no
//! fused multiply-add; so every implementation of [`Vector`] gives the portable kernel's bits.

use crate::kernel::WaveCoeffs;

/// One instruction set's `f32` vectors and the operations the kernels use.
pub(crate) trait Vector: Copy {
    /// A vector of `f32` lanes.
    type V: Copy;
    /// A per-lane condition.
    type Mask: Copy;
    fn splat(self, x: f32) -> Self::V;
    fn add(self, a: Self::V, b: Self::V) -> Self::V;
    fn sub(self, a: Self::V, b: Self::V) -> Self::V;
    fn mul(self, a: Self::V, b: Self::V) -> Self::V;
    fn div(self, a: Self::V, b: Self::V) -> Self::V;
    fn sqrt(self, a: Self::V) -> Self::V;
    /// a < b, false where either is NaN (Rust's `<`).
    fn less(self, a: Self::V, b: Self::V) -> Self::Mask;
    /// `if m { t } else { f }` per lane.
    fn select(self, m: Self::Mask, t: Self::V, f: Self::V) -> Self::V;
}

/// The eight running sums of [`Acc`](crate::kernel::Acc), one vector each.
#[derive(Clone, Copy)]
pub(crate) struct Sums<V> {
    pub(crate) dx: V,
    pub(crate) y: V,
    pub(crate) dz: V,
    pub(crate) jxx: V,
    pub(crate) jxz: V,
    pub(crate) jzz: V,
    pub(crate) sx: V,
    pub(crate) sz: V,
}

impl<V: Copy> Sums<V> {
    /// `Acc::new`: zero displacement, identity Jacobian, zero slope.
    #[inline(always)]
    pub(crate) fn new<S: Vector<V = V>>(s: S) -> Self {
        let (zero, one) = (s.splat(0.0), s.splat(1.0));
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
    pub(crate) fn add<S: Vector<V = V>>(&mut self, s: S, k: &WaveCoeffs, sin: V, cos: V) {
        let term = |c: f32, x: V| s.mul(s.splat(c), x);
        self.dx = s.sub(self.dx, term(k.ahx, sin));
        self.dz = s.sub(self.dz, term(k.ahz, sin));
        self.y = s.add(self.y, term(k.a, cos));
        self.jxx = s.sub(self.jxx, term(k.cxx, cos));
        self.jxz = s.sub(self.jxz, term(k.cxz, cos));
        self.jzz = s.sub(self.jzz, term(k.czz, cos));
        self.sx = s.sub(self.sx, term(k.gx, sin));
        self.sz = s.sub(self.sz, term(k.gz, sin));
    }

    /// `Acc::finish` before its stores: positions `(x + dx, y, z + dz)` and unit normals, as
    /// (`[x, y, z]`, `[nx, ny, nz]`).
    #[inline(always)]
    pub(crate) fn finish<S: Vector<V = V>>(self, s: S, x: V, z: f32) -> ([V; 3], [V; 3]) {
        let Sums {
            dx,
            y,
            dz,
            jxx,
            jxz,
            jzz,
            sx,
            sz,
        } = self;
        let (zero, one) = (s.splat(0.0), s.splat(1.0));
        let px = s.add(x, dx);
        let pz = s.add(s.splat(z), dz);
        let a = s.sub(s.mul(sz, jxz), s.mul(jzz, sx));
        let b = s.sub(s.mul(jzz, jxx), s.mul(jxz, jxz));
        let c = s.sub(s.mul(jxz, sx), s.mul(sz, jxx));
        let len2 = s.add(s.add(s.mul(a, a), s.mul(b, b)), s.mul(c, c));
        let degenerate = s.less(len2, s.splat(f32::MIN_POSITIVE));
        let inv = s.div(one, s.sqrt(s.select(degenerate, one, len2)));
        let nx = s.select(degenerate, zero, s.mul(a, inv));
        let ny = s.select(degenerate, one, s.mul(b, inv));
        let nz = s.select(degenerate, zero, s.mul(c, inv));
        ([px, y, pz], [nx, ny, nz])
    }
}

/// sin θ and cos θ of a wave from its row's sine and cosine (`rs`, `rc`) and its column
/// table's (`cs`, `cc`), by angle addition: the grid kernels' four products and two sums.
#[inline(always)]
pub(crate) fn angle_sum<S: Vector>(s: S, rs: f32, rc: f32, cs: S::V, cc: S::V) -> (S::V, S::V) {
    let (rs, rc) = (s.splat(rs), s.splat(rc));
    (
        s.add(s.mul(rs, cc), s.mul(rc, cs)),
        s.sub(s.mul(rc, cc), s.mul(rs, cs)),
    )
}

/// m sin(θ + φ) and m cos(θ + φ) from sin θ, cos θ and μ = (m cos φ, m sin φ) (the layers
/// kernel's modulation).
#[inline(always)]
pub(crate) fn modulate<S: Vector>(s: S, sin: S::V, cos: S::V, mr: S::V, mi: S::V) -> (S::V, S::V) {
    (
        s.add(s.mul(sin, mr), s.mul(cos, mi)),
        s.sub(s.mul(cos, mr), s.mul(sin, mi)),
    )
}
