//! The cone ratio a cell can carry: the one definition that the fast generator
//! (`search.rs`) and the brute-force oracle (`brute.rs`) both compute, and its
//! proof of validity for the bilinear tracer.
//!
//! Units here: texel-centre coordinates (texel `(i, j)`'s centre is the point `(i, j)`), depth in
//! `[0, 1]`, ratios in **texels per unit depth** (the cone map divides by `N` at the end to get
//! the book's texture widths per unit depth).
//!
//! ## What a relaxed cone must guarantee (§18.4, Listing 18-3)
//!
//! The tracer stands at `P = (p, z₀)` above the surface (`z₀ < S(p)`, `S` the bilinear depth),
//! fetches the cone ratio `c` at `p`, and moves along its ray `(r, 1)` (`|r| = ρ`) by
//! `t = c·(S(p) − z₀)/(ρ + c)`: to where the ray leaves the cone of apex `(p, S(p))` that opens
//! upwards with ratio `c` (Eq. 1–4). The step is safe when the ray crosses the surface at most
//! once, inwards, inside that cone. The tracer reuses one cone for **every** `z₀` on its axis
//! and every ray slope, so the cone at `p` is valid iff no ray through the axis above the apex
//! enters and then leaves the solid inside the cone.
//!
//! **Lemma 1 (the peak rule).** Along a direction `u`, write `g(s) = S(p + s·u)` and
//! `M(s) = min over [0, s] of g`. The largest valid ratio is
//! `c*(p) = inf { s / (S(p) − M(s)) : g(s) > M(s), M(s) < S(p) }` over all `u` and `s`.
//! *Proof.* (⇐) If `c > c*(p)`, pick such an `s`; a ray through the axis at depth just below
//! `M(s)` and nearly horizontal enters the solid at the running minimum before `s` and is outside
//! again at `s`, inside the cone. (⇒) If a ray from `(p, z₀)` is inside at `s₁` and outside at
//! `s₂ > s₁` with depth `z_b < S(p)` there, then `M(s₂) ≤ z(s₁) < z_b < g(s₂)` and
//! `s₂ ≤ c·(S(p) − z_b) < c·(S(p) − M(s₂))`, so `c > c*(p)`. ∎ So a relaxed cone may not reach
//! past any point that is a local maximum of height along a line from `p` and higher than the
//! apex — including gentle hill tops that Listing 18-1 ignores because it only casts rays from
//! the top of the axis (`z₀ = 0`); see [`crate::book`] for that listing (the validity tests
//! show its cones failing this rule).
//!
//! ## The cell bound
//!
//! The tracer samples the cone map bilinearly (with the depth, one fetch), so a texel's value is
//! used for every apex `p` in the four cells around its centre. We therefore bound
//! `inf_{p ∈ q} c*(p)` for each **cell** `q` (the unit square between four texel centres) and
//! give texel `k` the minimum over its four cells ([`crate::cone`]); a bilinear blend of values
//! that are each `≤ c*(p)` is `≤ c*(p)`.
//!
//! For a candidate cell `C` (another unit square, anywhere, wrapped copies included) let
//! `m_C` be its highest corner (smallest depth), `Smax(q)` the deepest corner of `q`, `G_C` the
//! box of `C`'s bilinear gradients (`∂S/∂x` lies between `C`'s two x-edge differences, likewise
//! `y`) and `W = C − q` the box of vectors from `q` to `C`. `C` is a **candidate** for `q` when
//!
//! 1. `C` is not flat and `m_C < Smax(q)`;
//! 2. `F = max_{g ∈ G_C, w ∈ W} g·w > 0` ("falling": the depth can grow away from `q` in
//!    `C`), or `F = 0` and `C`'s twist `D` (its `x·y` coefficient) has the sign of `wₓ·w_y` for
//!    some `w ∈ W`.
//!
//! Its value is `max(A, B)` with `A = dist(q, C) / (Smax(q) − m_C)` and `B = 1/L`, `L` the
//! largest gradient magnitude bound of the cells within Chebyshev distance `cheb(q, C)` of `q`
//! when that distance is at most [`K_LIP`], of all cells otherwise (for relaxed candidates that
//! close, `B` is sharpened and the cell may drop out: "Near cells" below). The cell's cone is
//! `w(q) = min(cap, min over candidates of max(A, B))`.
//!
//! **Theorem.** For every `p ∈ q`, `c*(p) ≥ w(q)`.
//! *Proof.* Take `(u, s)` in Lemma 1's set and let `s_e ≤ s` be the left end of the interval of
//! `{g > M}` that contains `s`: `g(s_e) = M(s_e) = M(s)` and `g > M` just after `s_e`. Let
//! `b = p + s_e·u` and `C` the cell that contains `b + εu` for small `ε`. In `C`, `g` grows
//! right after `b`, so `C` is not flat and, along `u ∝ b − p ∈ W`, either `∇S_C(b)·u > 0` or it
//! is 0 and the second derivative `2·D·uₓ·u_y` is positive (condition 2: `F ≥ ∇S_C(b)·u`, and
//! `F = 0` forces `∇S_C(b)·u = 0`), and
//! `m_C ≤ S(b) = M < S(p) ≤ Smax(q)` (condition 1). Then
//! `s/(S(p) − M) ≥ |b − p|/(S(p) − M) ≥ dist(q, C)/(Smax(q) − m_C) = A`; and with `a` the point
//! of `[p, b]` where `g` reaches `M`, `S(p) − M ≤ L·|a − p| ≤ L·s` because the segment `[p, a]`
//! lies in the bounding box of `q ∪ C`, whose cells are within `cheb(q, C)` of `q`; so
//! `s/(S(p) − M) ≥ B`. Hence every element of Lemma 1's set is `≥ max(A, B) ≥ w(q)`. ∎
//!
//! ### Near cells
//!
//! Next to the apex the distance term vanishes and `B = 1/L` alone would make every relaxed cone
//! as narrow as a conservative one, since a plane's side neighbours pass condition 2 for some
//! direction. But the proof's direction `u` is one direction for the whole path: the surface
//! falls at `b` along `u`, and, since `S(b) = M < S(p)`, it rises somewhere on `[p, b]` along
//! the same `u`, at a rate at most `R(u) = max_{g ∈ G_P} (−g·u)`, `G_P` the union of the gradient
//! boxes of the cells in the bounding box of `q ∪ C`; so `S(p) − M ≤ R(u)·s`. The direction lies
//! in the directions of `W`, and not in the interior of the arc where every `g ∈ G_C` has
//! `g·u ≤ 0` (there `∇S_C(b)·u < 0`). Let `ρ` be the supremum of `R` over the closure of the
//! directions of `W` minus that arc (`arc.rs`, `max_rise`). If `ρ = 0` no exit can lie in
//! `C` and it is not a candidate; otherwise `s/(S(p) − M) ≥ 1/ρ`, and `B = max(1/ρ, 1/L)`. A
//! plane has `R(u) > 0` exactly where its cells do not fall, so its near cells drop out.
//!
//! The proof needs of `q` only an upper bound of the depth over it and of `C` only that it is one
//! bilinear patch; `refine.rs` runs the same bound over parts of both cells, which gives up
//! less width than whole cells.
//!
//! The conservative cone (Dummer 2006: the cone contains no solid at all) is bounded the same
//! way with every cell that has `m_C < Smax(q)` as a candidate, flat or not, and no falling
//! test: a point `b` higher than `p` limits it by `s/(S(p) − S(b))`, with the same `A` and `B`.
//! Near cells take the direction-consistent bound too, with no arc excluded: the surface rises
//! from `S(p)` to `S(b)` along `u` at a rate at most `R(u)`, so `s/(S(p) − S(b)) ≥ 1/ρ`, `ρ`
//! the supremum of `R` over the directions of `W`; `ρ = 0` leaves no point of `C` higher than
//! `p` along them, and `C` is not a candidate.
//!
//! **Quadrant cones** ([`crate::quad`]) run the same bound with the vectors `W` clipped to one
//! closed quadrant (`Apex::within`, `Apex::vectors`): the proof's `b − p` points along the ray's
//! horizontal direction, so for rays of that quadrant only `W ∩ Q` can hold it.
//!
//! [`Edge::Clamp`] extends the surface beyond the texel centres by constant strips; the cells
//! there are the grid's border cells (`i = −1` and `i = N − 1`), whose extrusion to infinity
//! repeats the same values. An apex cell on the border stands for its whole strip (an apex
//! outside the texture samples the border texels): its box extends to `±BIG` for the falling
//! test; distances to the strip equal distances to the border cell for every grid cell.
//!
//! ## Floating point
//!
//! Depths are `f32`; gradient bounds are stored rounded outwards to `f32` and `L` rounded up,
//! so the stored boxes contain the exact ones. Every test is evaluated in `f64` where the
//! products of an `f32` and a small integer are exact, so the sign tests are exact and the node
//! bounds of the search are never above a leaf's value (monotone rounding). The two generators
//! evaluate the same expression on the same inputs and agree bit for bit.

use alloc::vec::Vec;

use crate::map::{Edge, HeightMap};
use crate::quadrant::Quadrant;
use crate::round::{down32, up32};

/// "Infinite" extent of a clamp-mode border strip, in texels: larger than any reach a cone can
/// have (`MAX_RATIO_LIMIT·MAX_SIDE`), exact in `f64` and in products with `f32` values.
pub(crate) const BIG: f64 = 1_073_741_824.0; // 2^30

/// Chebyshev radius (cells) inside which the Lipschitz bound `B` uses local gradients.
pub const K_LIP: usize = 3;

/// Which cones to bound.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum ConeKind {
    /// Relaxed cones (§18.4): rays may enter the relief inside a cone but never leave it.
    #[default]
    Relaxed,
    /// Conservative cones (Dummer 2006, §18.3): the cone contains no solid.
    Conservative,
}

/// What the bound needs to know about one cell.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Cell {
    /// Smallest corner depth (the highest point).
    pub m: f32,
    /// Largest corner depth.
    pub smax: f32,
    /// Bounds of `∂S/∂x` over the cell, rounded outwards.
    pub gx: [f32; 2],
    /// Bounds of `∂S/∂y` over the cell, rounded outwards.
    pub gy: [f32; 2],
    /// Upper bound of `|∇S|` over the cell, rounded up.
    pub lip: f32,
    /// Sign of the twist `D = d₀₀ − d₁₀ − d₀₁ + d₁₁` (the `x·y` coefficient): along a direction
    /// `u` the surface's second derivative is `2·D·uₓ·u_y`.
    pub twist: i8,
    /// All four corners equal.
    pub flat: bool,
}

impl Cell {
    fn new(d00: f32, d10: f32, d01: f32, d11: f32) -> Self {
        let (a, b, c, d) = (
            f64::from(d00),
            f64::from(d10),
            f64::from(d01),
            f64::from(d11),
        );
        // Differences of two f32 values are exact in f64.
        let (ex0, ex1) = (b - a, d - c);
        let (ey0, ey1) = (c - a, d - b);
        let mx = ex0.abs().max(ex1.abs());
        let my = ey0.abs().max(ey1.abs());
        // |∂x| ≤ mx and |∂y| ≤ my everywhere in the cell; the factor covers the two roundings of
        // the f64 square root.
        let lip = libm::sqrt(mx * mx + my * my) * (1.0 + 1.0e-12);
        Self {
            m: d00.min(d10).min(d01).min(d11),
            smax: d00.max(d10).max(d01).max(d11),
            gx: [down32(ex0.min(ex1)), up32(ex0.max(ex1))],
            gy: [down32(ey0.min(ey1)), up32(ey0.max(ey1))],
            lip: up32(lip),
            twist: {
                let t = a - b - c + d;
                if t > 0.0 {
                    1
                } else if t < 0.0 {
                    -1
                } else {
                    0
                }
            },
            flat: d00 == d10 && d00 == d01 && d00 == d11,
        }
    }
}

/// The cells of a map: `N × N` in wrap mode, `(N + 1) × (N + 1)` in clamp mode (the border
/// strips included).
pub(crate) struct Grid<'a> {
    /// Texels per side.
    pub n: usize,
    /// Cells per side.
    pub nc: usize,
    pub edge: Edge,
    /// Spatial index of cell 0 along each axis: 0 (wrap) or −1 (clamp).
    pub origin: i64,
    pub cells: Vec<Cell>,
    /// `L` over all cells.
    pub lip_global: f64,
    /// The map's depths, row-major, `N × N` (the corners of the cells, for `crate::refine`).
    pub depth: &'a [f32],
}

impl<'a> Grid<'a> {
    pub fn new(map: &'a HeightMap) -> Self {
        let n = map.size();
        let edge = map.edge();
        let (nc, origin) = match edge {
            Edge::Wrap => (n, 0),
            Edge::Clamp => (n + 1, -1),
        };
        let mut cells = Vec::with_capacity(nc * nc);
        let mut lip_global = 0.0f64;
        for cj in 0..nc as i64 {
            for ci in 0..nc as i64 {
                let (i, j) = (ci + origin, cj + origin);
                let cell = Cell::new(
                    map.depth(i, j),
                    map.depth(i + 1, j),
                    map.depth(i, j + 1),
                    map.depth(i + 1, j + 1),
                );
                lip_global = lip_global.max(f64::from(cell.lip));
                cells.push(cell);
            }
        }
        Self {
            n,
            nc,
            edge,
            origin,
            cells,
            lip_global,
            depth: map.depths(),
        }
    }

    /// Corner depths `[d00, d10, d01, d11]` of the cell at spatial position `(ci, cj)`
    /// (unwrapped; resolved by the edge mode).
    pub fn corners(&self, ci: i64, cj: i64) -> [f64; 4] {
        let n = self.n;
        let d = |i: i64, j: i64| {
            f64::from(self.depth[self.edge.resolve(j, n) * n + self.edge.resolve(i, n)])
        };
        [d(ci, cj), d(ci + 1, cj), d(ci, cj + 1), d(ci + 1, cj + 1)]
    }

    /// Index of the cell at spatial position `(ci, cj)` (unwrapped in wrap mode), if it exists.
    #[inline(always)]
    pub fn index(&self, ci: i64, cj: i64) -> Option<usize> {
        match self.edge {
            Edge::Wrap => {
                let n = self.n as i64;
                Some(cj.rem_euclid(n) as usize * self.nc + ci.rem_euclid(n) as usize)
            }
            Edge::Clamp => {
                let (x, y) = (ci - self.origin, cj - self.origin);
                let nc = self.nc as i64;
                if (0..nc).contains(&x) && (0..nc).contains(&y) {
                    Some(y as usize * self.nc + x as usize)
                } else {
                    None
                }
            }
        }
    }

    /// The apex cell at spatial position `(qi, qj)` (`0 ≤ qi − origin < nc`).
    pub fn apex(&self, qi: i64, qj: i64) -> Apex {
        let cell = &self.cells[self.index(qi, qj).unwrap_or(0)];
        let (mut x0, mut x1) = (qi as f64, qi as f64 + 1.0);
        let (mut y0, mut y1) = (qj as f64, qj as f64 + 1.0);
        if self.edge == Edge::Clamp {
            let last = self.n as i64 - 1;
            if qi == -1 {
                x0 = -BIG;
            }
            if qi == last {
                x1 = BIG;
            }
            if qj == -1 {
                y0 = -BIG;
            }
            if qj == last {
                y1 = BIG;
            }
        }
        let mut lring = [0.0f64; K_LIP + 1];
        for (r, l) in lring.iter_mut().enumerate() {
            let r = r as i64;
            let mut max = 0.0f64;
            for dj in -r..=r {
                for di in -r..=r {
                    if let Some(k) = self.index(qi + di, qj + dj) {
                        max = max.max(f64::from(self.cells[k].lip));
                    }
                }
            }
            *l = max;
        }
        // Path boxes by dynamic programming outwards from the apex cell, one quadrant at a time:
        // the box of offsets (dx, dy) is the union of those of (dx − sx, dy), (dx, dy − sy) and
        // the cell itself.
        const EMPTY: [f64; 4] = [
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        let k = K_LIP as i64;
        let mut path = [EMPTY; NEAR * NEAR];
        let at = |dx: i64, dy: i64| ((dy + k) as usize) * NEAR + (dx + k) as usize;
        let own = |dx: i64, dy: i64| -> [f64; 4] {
            match self.index(qi + dx, qj + dy) {
                Some(i) => {
                    let c = &self.cells[i];
                    [
                        f64::from(c.gx[0]),
                        f64::from(c.gx[1]),
                        f64::from(c.gy[0]),
                        f64::from(c.gy[1]),
                    ]
                }
                None => EMPTY,
            }
        };
        let union = |a: [f64; 4], b: [f64; 4]| {
            [
                a[0].min(b[0]),
                a[1].max(b[1]),
                a[2].min(b[2]),
                a[3].max(b[3]),
            ]
        };
        for sy in [-1i64, 1] {
            for sx in [-1i64, 1] {
                for ady in 0..=k {
                    for adx in 0..=k {
                        let (dx, dy) = (sx * adx, sy * ady);
                        let mut b = own(dx, dy);
                        if adx > 0 {
                            b = union(b, path[at(dx - sx, dy)]);
                        }
                        if ady > 0 {
                            b = union(b, path[at(dx, dy - sy)]);
                        }
                        path[at(dx, dy)] = b;
                    }
                }
            }
        }
        Apex {
            qi,
            qj,
            rect: [x0, x1, y0, y1],
            clip: ALL_VECTORS,
            sector: None,
            smax: f64::from(cell.smax),
            lring,
            path,
        }
    }
}

/// An apex cell with what the bound needs about it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Apex {
    pub qi: i64,
    pub qj: i64,
    /// `[x0, x1, y0, y1]`, ±BIG for clamp-mode border strips.
    pub rect: [f64; 4],
    /// The closed box `[wx0, wx1, wy0, wy1]` of vectors `b − p` the cone serves: every vector
    /// ([`ALL_VECTORS`]) or one closed quadrant ([`crate::quad`]).
    pub clip: [f64; 4],
    /// The quadrant the cone serves, if any (`clip` is its box).
    pub sector: Option<Quadrant>,
    /// Deepest corner.
    pub smax: f64,
    /// Largest `lip` within Chebyshev distance `r` of the apex cell.
    pub lring: [f64; K_LIP + 1],
    /// For each offset `(dx, dy) ∈ [−K_LIP, K_LIP]²` (row-major), the union `[gx0, gx1, gy0, gy1]`
    /// of the gradient boxes of the cells in the bounding box of the apex cell and the cell at
    /// that offset: every gradient a segment from `q` to that cell can meet.
    pub path: [[f64; 4]; NEAR * NEAR],
}

/// Side of the near neighbourhood.
const NEAR: usize = 2 * K_LIP + 1;

/// The clip box of a cone that serves every direction.
pub(crate) const ALL_VECTORS: [f64; 4] = [
    f64::NEG_INFINITY,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::INFINITY,
];

impl Apex {
    /// The same apex for a cone that serves only the rays whose horizontal direction lies in the
    /// closed quadrant `q` ([`crate::quad`]).
    pub fn within(mut self, q: Quadrant) -> Self {
        self.clip = q.vectors();
        self.sector = Some(q);
        self
    }

    /// The box of vectors `b − p` from the apex box to `rect` that the cone serves (the plain
    /// difference box clipped to [`Apex::clip`]); `None` when it is empty. Without a quadrant the
    /// clip is `±∞` and the box is the difference box bit for bit.
    #[inline(always)]
    pub fn vectors(&self, rect: [f64; 4]) -> Option<[f64; 4]> {
        self.vectors_from(self.rect, rect)
    }

    /// [`Apex::vectors`] from a part `from` of the apex box (a sub-rectangle, `crate::refine`).
    #[inline(always)]
    pub fn vectors_from(&self, from: [f64; 4], rect: [f64; 4]) -> Option<[f64; 4]> {
        let [qx0, qx1, qy0, qy1] = from;
        let [x0, x1, y0, y1] = rect;
        let [cx0, cx1, cy0, cy1] = self.clip;
        let w = [
            (x0 - qx1).max(cx0),
            (x1 - qx0).min(cx1),
            (y0 - qy1).max(cy0),
            (y1 - qy0).min(cy1),
        ];
        (w[0] <= w[1] && w[2] <= w[3]).then_some(w)
    }
}

/// Largest product `g·w` over `g ∈ [g0, g1]`, `w ∈ [w0, w1]`.
#[inline(always)]
fn max_product(g: [f32; 2], w0: f64, w1: f64) -> f64 {
    max_product64([f64::from(g[0]), f64::from(g[1])], w0, w1)
}

/// [`max_product`] for bounds held in `f64`.
#[inline(always)]
fn max_product64(g: [f64; 2], w0: f64, w1: f64) -> f64 {
    let [g0, g1] = g;
    (g0 * w0).max(g0 * w1).max(g1 * w0).max(g1 * w1)
}

/// The largest `g·w` over gradients `gx × gy` and the vectors `w` of the box `w`.
#[inline(always)]
fn growth(w: [f64; 4], gx: [f32; 2], gy: [f32; 2]) -> f64 {
    max_product(gx, w[0], w[1]) + max_product(gy, w[2], w[3])
}

/// Condition 2 for a block of cells (a pyramid node): can the depth grow, or stay level with a
/// twisted cell curving it upwards, along some vector of `w` ([`Apex::vectors`] of the node)
/// with gradients in `gx × gy`? `twists` has bit 0 set when some cell of the block has a
/// positive twist, bit 1 when some has a negative one. A node that fails holds no cell that
/// passes [`falling_cell`]: each cell's gradient and vector boxes lie in the node's, so its
/// largest `g·w` is at most the node's (the products and the sum round monotonically), and when
/// the node's is 0 a cell can only pass through its twist, on a box of vectors inside the node's.
/// (Without the twist test, a tread of a staircase saw the whole column of risers beside it as
/// falling, level along the riser: the search then visited every node of that column.)
#[inline(always)]
pub(crate) fn falling(w: [f64; 4], gx: [f32; 2], gy: [f32; 2], twists: u8) -> bool {
    let f = growth(w, gx, gy);
    if f > 0.0 {
        return true;
    }
    if f < 0.0 {
        return false;
    }
    (twists & 1 != 0 && twist_allows(w, 1)) || (twists & 2 != 0 && twist_allows(w, -1))
}

/// A necessary condition for some cell of a block to pass [`falling_cell`], from where its cells
/// lie rather than from the block's box: `reach` holds, in spatial coordinates, the largest right
/// edge of the cells whose `∂S/∂x` can be positive, the smallest left edge of those whose
/// `∂S/∂x` can be negative, and the same along `y` (`∓∞` when there are none). A cell's largest
/// `g·w` is positive only if one of its two products is, and `gₓ·wₓ > 0` needs either
/// `gₓ > 0` and a vector with `wₓ > 0`, which [`Apex::vectors`] gives the cell only when its right
/// edge lies right of the apex box's left edge (within the clip), or the mirror case; when the
/// largest `g·w` is 0 the cell passes only through its twist, which `twists` and `w` (the block's
/// vectors, a superset of the cell's) test as in [`falling`]. The coordinates are integers, so
/// the differences are exact and monotone in the edge. (The gradient union alone cannot see
/// that, on the treads of a staircase, the risers that fall towards the apex lie behind it: a
/// node straddling the apex's column passed, and the search opened every such node out to the
/// clearance radius.)
#[inline(always)]
pub(crate) fn falling_reach(q: &Apex, w: [f64; 4], reach: [f64; 4], twists: u8) -> bool {
    let [qx0, qx1, qy0, qy1] = q.rect;
    let [cx0, cx1, cy0, cy1] = q.clip;
    (reach[0] - qx0).min(cx1) > 0.0
        || (reach[1] - qx1).max(cx0) < 0.0
        || (reach[2] - qy0).min(cy1) > 0.0
        || (reach[3] - qy1).max(cy0) < 0.0
        || (twists & 1 != 0 && twist_allows(w, 1))
        || (twists & 2 != 0 && twist_allows(w, -1))
}

/// Whether a box of vectors `w` holds a vector along which a cell of twist sign `twist` curves
/// its depth upwards (second derivative `2·D·wₓ·w_y > 0`).
#[inline(always)]
fn twist_allows(w: [f64; 4], twist: i8) -> bool {
    let [wx0, wx1, wy0, wy1] = w;
    match twist {
        1 => (wx1 > 0.0 && wy1 > 0.0) || (wx0 < 0.0 && wy0 < 0.0),
        -1 => (wx1 > 0.0 && wy0 < 0.0) || (wx0 < 0.0 && wy1 > 0.0),
        _ => false,
    }
}

/// Condition 2 for one cell (or part of one, `g` its gradient box `[gx0, gx1, gy0, gy1]`): the
/// depth can grow right after the exit point `b` along `u ∝ b − p` only if `∇S(b)·u > 0`, or
/// `∇S(b)·u = 0` and the second derivative `2·D·uₓ·u_y > 0`. When the largest `g·w` over the
/// boxes is exactly 0 (a planar ramp seen along its level direction), only a twisted cell whose
/// box of directions allows `D·wₓ·w_y > 0` can still have an exit.
#[inline(always)]
fn falling_cell(w: [f64; 4], g: [f64; 4], twist: i8) -> bool {
    let f = max_product64([g[0], g[1]], w[0], w[1]) + max_product64([g[2], g[3]], w[2], w[3]);
    if f > 0.0 {
        return true;
    }
    if f < 0.0 {
        return false;
    }
    twist_allows(w, twist)
}

/// The shortest vector of the box `w`: the Euclidean distance from the apex box to a rectangle
/// along the directions the cone serves (`w` from [`Apex::vectors`]). Without a quadrant it is
/// the plain distance between the boxes (`−(a − b)` and `b − a` are the same `f64`).
#[inline(always)]
pub(crate) fn distance(w: [f64; 4]) -> f64 {
    let [wx0, wx1, wy0, wy1] = w;
    let gx = wx0.max(-wx1).max(0.0);
    let gy = wy0.max(-wy1).max(0.0);
    libm::sqrt(gx * gx + gy * gy)
}

/// A candidate cell's parts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Candidate {
    /// `dist(q, C)`.
    pub dist: f64,
    /// `Smax(q) − m_C > 0`.
    pub depth: f64,
    /// `B`.
    pub b: f64,
}

impl Candidate {
    /// `max(A, B)`: the cell's bound on the plain cone.
    #[inline(always)]
    pub fn value(&self) -> f64 {
        (self.dist / self.depth).max(self.b)
    }
}

/// What the bound needs about a candidate region: a whole cell, or a sub-rectangle of one
/// (`crate::refine`): its box, its smallest depth (a lower bound) and its gradient box
/// `[gx0, gx1, gy0, gy1]` (containing every gradient in the closed box).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Region {
    pub rect: [f64; 4],
    pub m: f64,
    pub g: [f64; 4],
}

impl Region {
    /// The whole cell at spatial position `(ci, cj)`.
    #[inline(always)]
    pub fn cell(cell: &Cell, ci: i64, cj: i64) -> Self {
        Self {
            rect: [ci as f64, ci as f64 + 1.0, cj as f64, cj as f64 + 1.0],
            m: f64::from(cell.m),
            g: [
                f64::from(cell.gx[0]),
                f64::from(cell.gx[1]),
                f64::from(cell.gy[0]),
                f64::from(cell.gy[1]),
            ],
        }
    }
}

/// Candidate cell `cell` at spatial position `(ci, cj)` for apex `q`, or `None` when it is not
/// a candidate (module documentation).
#[inline(always)]
pub(crate) fn candidate(
    q: &Apex,
    cell: &Cell,
    ci: i64,
    cj: i64,
    kind: ConeKind,
    lip_global: f64,
) -> Option<Candidate> {
    if kind == ConeKind::Relaxed && cell.flat {
        return None;
    }
    let part = ApexPart {
        rect: q.rect,
        smax: q.smax,
    };
    candidate_in(
        q,
        part,
        &Region::cell(cell, ci, cj),
        cell.twist,
        ci,
        cj,
        kind,
        lip_global,
        f64::INFINITY,
        || None,
    )
}

/// A part of an apex cell: its box and the largest depth over it (an upper bound).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ApexPart {
    pub rect: [f64; 4],
    pub smax: f64,
}

/// The bound of the module documentation for apex part `part` of `q` and candidate region `r`
/// inside the (non-flat, for relaxed cones) cell at `(ci, cj)` with twist `twist`: the theorem
/// holds word for word for any box `q` on which `Smax(q)` bounds the depth and any box `C` on
/// which the surface is one bilinear patch, so parts of cells take it too (`crate::refine`).
/// A candidate whose value is at least `enough` may come back with a smaller value at or above
/// `enough`, or as one, where the near-cell rule would drop it (`∞`: always the exact bound).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub(crate) fn candidate_in(
    q: &Apex,
    part: ApexPart,
    r: &Region,
    twist: i8,
    ci: i64,
    cj: i64,
    kind: ConeKind,
    lip_global: f64,
    enough: f64,
    path: impl FnOnce() -> Option<[f64; 4]>,
) -> Option<Candidate> {
    let m = r.m;
    if m >= part.smax {
        return None;
    }
    let w = q.vectors_from(part.rect, r.rect)?;
    if kind == ConeKind::Relaxed && !falling_cell(w, r.g, twist) {
        return None;
    }
    let (dx, dy) = (ci - q.qi, cj - q.qj);
    let cheb = dx.unsigned_abs().max(dy.unsigned_abs()) as usize;
    let l = if cheb <= K_LIP {
        q.lring[cheb]
    } else {
        lip_global
    };
    let mut out = Candidate {
        dist: distance(w),
        depth: part.smax - m,
        b: if l > 0.0 { 1.0 / l } else { f64::INFINITY },
    };
    // The near-cell rule only raises the value or drops the candidate: a caller that discards
    // values at or above `enough` needs neither when the value is there already.
    if cheb <= K_LIP && out.value() < enough {
        // Direction-consistent bound (module documentation, "near cells"). A conservative cone
        // must clear every higher point, falling or not: no direction is excluded (a gradient
        // box around the origin excludes none).
        let k = K_LIP as i64;
        let path = path().unwrap_or_else(|| q.path[((dy + k) as usize) * NEAR + (dx + k) as usize]);
        let g = match kind {
            ConeKind::Relaxed => r.g,
            ConeKind::Conservative => [-1.0, 1.0, -1.0, 1.0],
        };
        let rise = crate::arc::max_rise(w, g, path, q.sector);
        if rise <= 0.0 {
            return None;
        }
        out.b = out.b.max(1.0 / rise);
    }
    Some(out)
}

/// The floor of every candidate's value: `1/L` over the whole map.
#[inline(always)]
pub(crate) fn floor_value(lip_global: f64) -> f64 {
    if lip_global > 0.0 {
        1.0 / lip_global
    } else {
        f64::INFINITY
    }
}
