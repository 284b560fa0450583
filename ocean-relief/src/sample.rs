//! The bilinear fetch every tracer uses, written as the `f32` arithmetic a WGSL port copies
//! (four `textureLoad`s and `mix`), so that CPU and GPU see the same surface.
//!
//! At texture coordinates `(u, v)` on an `N × N` texture:
//!
//! ```text
//! x = u·N − ½,  y = v·N − ½            texel-centre coordinates
//! i = floor(x), j = floor(y)           top-left tap (resolved by the edge mode)
//! fx = x − i,   fy = y − j             weights in [0, 1)
//! value = mix(mix(t(i, j), t(i+1, j), fx), mix(t(i, j+1), t(i+1, j+1), fx), fy)
//! ```
//!
//! with `mix(a, b, t) = a·(1 − t) + b·t` (WGSL's definition). Hardware linear filtering
//! computes the same weights with fewer fractional bits; the CPU twin and the WGSL port use this
//! exact form instead. Depth and cone ratio are fetched together with the same weights (the
//! book keeps them in one texel, §18.4.1), which is what the cone maps are made valid for.

/// What the surface is beyond the texture's borders (see [`crate::map`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Edge {
    /// The texture tiles: texel `i` is texel `i mod N` (sampler addressing *repeat*).
    #[default]
    Wrap,
    /// Texel indices are clamped to `0 ..= N − 1` (sampler addressing *clamp-to-edge*).
    Clamp,
}

impl Edge {
    /// Texel index `i` (any integer) resolved into `0 .. n`.
    #[inline(always)]
    pub fn resolve(self, i: i64, n: usize) -> usize {
        match self {
            // rem_euclid of a positive modulus is in 0 .. n.
            Edge::Wrap => i.rem_euclid(n as i64) as usize,
            Edge::Clamp => i.clamp(0, n as i64 - 1) as usize,
        }
    }
}

/// The four taps and weights of one bilinear fetch.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Taps {
    /// Row-major indices of the taps `(i, j)`, `(i+1, j)`, `(i, j+1)`, `(i+1, j+1)`.
    pub index: [usize; 4],
    /// Weight of the right column.
    pub fx: f32,
    /// Weight of the bottom row.
    pub fy: f32,
}

impl Taps {
    /// The taps at texture coordinates `(u, v)` of an `n × n` texture.
    #[inline(always)]
    pub fn new(n: usize, edge: Edge, u: f32, v: f32) -> Self {
        let nf = n as f32;
        let x = u * nf - 0.5;
        let y = v * nf - 0.5;
        let x0 = libm::floorf(x);
        let y0 = libm::floorf(y);
        let (fx, fy) = (x - x0, y - y0);
        // `as` saturates (and maps NaN to 0): no input can index out of bounds.
        let (i, j) = (x0 as i64, y0 as i64);
        let (i0, i1) = (edge.resolve(i, n), edge.resolve(i.saturating_add(1), n));
        let (j0, j1) = (edge.resolve(j, n), edge.resolve(j.saturating_add(1), n));
        Self {
            index: [j0 * n + i0, j0 * n + i1, j1 * n + i0, j1 * n + i1],
            fx,
            fy,
        }
    }

    /// The bilinear blend of `texel(index)` over the taps.
    #[inline(always)]
    pub fn blend(&self, texel: impl Fn(usize) -> f32) -> f32 {
        let [a, b, c, d] = self.index;
        let top = mix(texel(a), texel(b), self.fx);
        let bottom = mix(texel(c), texel(d), self.fx);
        mix(top, bottom, self.fy)
    }

    /// The blend of four channels stored together (`[depth, cone, cone₁, cone₂]`): one fetch.
    #[inline(always)]
    pub fn blend4(&self, texels: &[[f32; 4]]) -> [f32; 4] {
        let [a, b, c, d] = self.index;
        let (a, b, c, d) = (texels[a], texels[b], texels[c], texels[d]);
        let mut out = [0.0; 4];
        for (k, o) in out.iter_mut().enumerate() {
            *o = mix(mix(a[k], b[k], self.fx), mix(c[k], d[k], self.fx), self.fy);
        }
        out
    }
}

/// WGSL's `mix(a, b, t) = a·(1 − t) + b·t`.
#[inline(always)]
pub fn mix(a: f32, b: f32, t: f32) -> f32 {
    a * (1.0 - t) + b * t
}
