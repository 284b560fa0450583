//! A box's internal frame and its traversal along wave rays (paper §2, Fig. 2).
//!
//! # The frame
//!
//! A wave train box covers the rectangle
//!
//! ```text
//! origin + a·u + b·v,   a ∈ [0, length],  b ∈ [0, width]
//! ```
//!
//! where `u` is the unit direction of the wind (the direction the waves travel) and
//! `v = (−u.z, u.x)` (in glam's `DVec2` terms `(−u.y, u.x)`). In our right-handed, y-up world, an
//! observer standing on the sea and facing `u` has `v` on their **right** (seen from above, v is u
//! turned 90° clockwise; for `u = +x`, `v = +z`). So `origin` is the paper's "lower left corner
//! when looking along u" (Fig. 2): the rear (upwind) corner on the left-hand side, and the box
//! extends forwards along `u` and to the right along `v`. The internal coordinates of a world
//! point `p` are `(a, b) = ((p − origin)·u, (p − origin)·v)`, metres, and the internal grid steps
//! by the water grid's spacing `s` along both `u` and `v` (§2).
//!
//! # Wave rays and the quadrant scan
//!
//! The box has one **wave ray** per internal column: ray `r` owns the strip
//! `b ∈ ((r − 1)·s, r·s]`, for `r = 0 ..= ⌈width/s⌉`, and along a ray, **step** `k` owns
//! `a ∈ ((k − 1)·s, k·s]`, for `k = 0 ..= ⌈length/s⌉`. The cell of step `k` of ray `r` is the
//! half-open square "behind and to the left" of internal grid point `(k·s, r·s)` — the pink
//! quadrant of Fig. 2 (behind: smaller a; left: smaller b). Cells tile the plane, so:
//!
//! - **Inside rule.** A water grid point is inside the box when `0 ≤ a ≤ length` and
//!   `0 ≤ b ≤ width` (closed on every side).
//! - **Ownership rule.** An inside point belongs to the cell `(k, r) = (⌈a/s⌉, ⌈b/s⌉)`. Every
//!   inside point thus belongs to exactly one (ray, step): no holes, no doubles.
//!
//! Both rules are evaluated **exactly** (see [`Traversal::classify`]) in integer arithmetic on
//! constants quantised to 1/[`FIXED_ONE`] = 2⁻³⁶ cells: in units of the spacing,
//! `a/s = cₐ + i·uₓ + j·u_z` for grid point (i, j), where `cₐ = ((g − o)·u)/s` (grid origin g,
//! box origin o), `u`, and likewise `c_b`, the length and the width are rounded once, when the
//! traversal is built, to multiples of 2⁻³⁶ (a rotation below 3·10⁻¹¹ rad, a shift below 10⁻¹¹
//! cells). Every sum is then an exact `i64` ([`FixedTraversal`]), its ceiling an exact integer
//! division, and the partition an exact tiling of the plane by squares whatever the orientation,
//! including exact multiples of 90° where grid points lie on cell edges. The same integers drive
//! the GPU's ray march (`ocean_gpu::WtbMarchPass`), which therefore finds exactly the CPU's
//! cells.
//!
//! # At most two points per cell
//!
//! The paper states that a scan finds zero, one or two points (§2). Proof for our half-open
//! cells: in grid units a cell is a square of side `1/|u| ≤ 1` (the quantised u has `|u| ≥ 1`
//! exactly: its larger component is raised by a unit of 2⁻³⁶ until it does). Three collinear lattice points span at
//! least 2 > √2, more than the square's diagonal. Three non-collinear lattice points form a
//! triangle of area ≥ ½ (Pick's theorem), but a triangle inside a square of side ≤ 1 has area
//! ≤ ½, with equality only when the side is 1 and two of the triangle's vertices are adjacent
//! corners of the square (the maximal inscribed triangles of a square). A half-open cell
//! `(k − 1, k] × (r − 1, r]` contains only one of its corners, so it holds at most two lattice
//! points. The traversal's buffer holds the ≤ 4 candidates a cell's bounding box can contain
//! (its width is at most √2 cells, so at most 2 integers per axis), so it never overflows even if
//! this argument were wrong; the tests check the bound of 2 over thousands of boxes.
//!
//! # Traversal
//!
//! [`BoxFrame::traversal`] binds a frame to a [`WaterGrid`]. The traversal visits rays in
//! increasing `r`, and along each ray the steps in increasing `k` (increasing `a`), calling back
//! with the grid points of each cell (0, 1 or 2; in increasing `a`). Rays and steps whose cells
//! cannot contain a grid point (outside the grid, the box hanging over its edges) are skipped;
//! every other cell of the box is visited, empty or not, so the number of visited cells is about
//! the area of the box's overlap with the grid divided by `s²`. Nothing is allocated.

use core::ops::Range;

use glam::{DVec2, DVec3};
use ocean_core::frustum::Obb;
use ocean_core::math::sqrt;

use crate::error::WtbError;
use crate::grid::{WaterGrid, ceil_i64, check_position, floor_i64};

/// Largest length or width of a box, in units of its spacing (2²⁴ cells: 4096 × 4096 grids need
/// at most 5793).
pub const MAX_CELLS: f64 = (1u64 << 24) as f64;

/// The traversal's fixed-point unit: its constants are integers counting 2⁻³⁶ cells.
pub const FIXED_ONE: i64 = 1 << 36;

/// A box whose constants exceed this (in cells) cannot reach a grid of ≤ 4096 points per side
/// (whose points are within 4096·√2 < 2¹³ cells of its origin), since its extents are at most
/// [`MAX_CELLS`] = 2²⁴.
const FAR: f64 = (1u64 << 25) as f64;

/// The internal frame of a wave train box (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoxFrame {
    origin: DVec2,
    u: DVec2,
    length: f64,
    width: f64,
    spacing: f64,
}

impl BoxFrame {
    /// A frame with its lower-left corner at `origin` (world x, z), `u` along `direction`
    /// (normalised here), extents `length` along u and `width` along v (metres, ≥ 0; a box may be
    /// empty while it builds up) and internal grid `spacing` (metres; the water grid's).
    ///
    /// # Errors
    ///
    /// [`WtbError::NotFinite`] or [`WtbError::OutOfRange`] for the origin (within ±10⁹ m), the
    /// spacing (as the water grid's), a negative length or width, or one above
    /// [`MAX_CELLS`]·spacing; [`WtbError::ZeroDirection`] for a zero or non-finite direction.
    pub fn new(
        origin: DVec2,
        direction: DVec2,
        length: f64,
        width: f64,
        spacing: f64,
    ) -> Result<Self, WtbError> {
        check_position("origin", origin)?;
        let spacing = crate::grid::check_range(
            "spacing",
            spacing,
            crate::grid::MIN_SPACING,
            crate::grid::MAX_SPACING,
        )?;
        let u = unit_direction("direction", direction)?;
        let max = MAX_CELLS * spacing;
        let length = crate::grid::check_range("length", length, 0.0, max)?;
        let width = crate::grid::check_range("width", width, 0.0, max)?;
        Ok(Self {
            origin,
            u,
            length,
            width,
            spacing,
        })
    }

    /// The same frame with another length (the box grows during build-up, §2).
    ///
    /// # Errors
    ///
    /// As [`BoxFrame::new`] for the length.
    pub fn with_length(&self, length: f64) -> Result<Self, WtbError> {
        let max = MAX_CELLS * self.spacing;
        let length = crate::grid::check_range("length", length, 0.0, max)?;
        Ok(Self { length, ..*self })
    }

    /// The lower-left corner (world x, z).
    #[inline]
    pub fn origin(&self) -> DVec2 {
        self.origin
    }
    /// Unit direction along the box (the wind), `u`.
    #[inline]
    pub fn u(&self) -> DVec2 {
        self.u
    }
    /// Unit direction across the box, `v = (−u.y, u.x)`: to the right of `u` for an observer on
    /// the sea facing `u`.
    #[inline]
    pub fn v(&self) -> DVec2 {
        DVec2::new(-self.u.y, self.u.x)
    }
    /// Extent along u, metres.
    #[inline]
    pub fn length(&self) -> f64 {
        self.length
    }
    /// Extent along v, metres.
    #[inline]
    pub fn width(&self) -> f64 {
        self.width
    }
    /// Internal grid spacing, metres.
    #[inline]
    pub fn spacing(&self) -> f64 {
        self.spacing
    }

    /// Number of wave rays, `⌈width/s⌉ + 1` (rays `0 ..= ⌈width/s⌉`).
    #[inline]
    pub fn ray_count(&self) -> u32 {
        ceil_i64(self.width / self.spacing) as u32 + 1
    }

    /// Number of steps along each ray, `⌈length/s⌉ + 1` (steps `0 ..= ⌈length/s⌉`).
    #[inline]
    pub fn step_count(&self) -> u32 {
        ceil_i64(self.length / self.spacing) as u32 + 1
    }

    /// Internal coordinates `(a, b) = ((p − origin)·u, (p − origin)·v)` of world (x, z), metres.
    #[inline]
    pub fn internal(&self, p: DVec2) -> DVec2 {
        let d = p - self.origin;
        DVec2::new(d.dot(self.u), d.dot(self.v()))
    }

    /// World (x, z) of internal coordinates (a, b): `origin + a·u + b·v`.
    #[inline]
    pub fn world(&self, ab: DVec2) -> DVec2 {
        self.origin + self.u * ab.x + self.v() * ab.y
    }

    /// Whether world (x, z) lies in the closed rectangle `a ∈ [0, length]`, `b ∈ [0, width]`,
    /// evaluated in plain `f64` (the traversal's exact test of grid points,
    /// [`Traversal::classify`], can differ only within about 10⁻¹² of the box's size from its
    /// edges).
    #[inline]
    pub fn contains(&self, p: DVec2) -> bool {
        let ab = self.internal(p);
        ab.x >= 0.0 && ab.x <= self.length && ab.y >= 0.0 && ab.y <= self.width
    }

    /// The box's rectangle extruded to `y ∈ [−height, height]`, as an oriented bounding box for
    /// frustum culling (§2.2): axes `(u, y, v)` with half extents `(length/2, height, width/2)`.
    /// `height` should be the sum of the maximum heights of the trains of every box overlapping
    /// this one (§2.2).
    ///
    /// # Errors
    ///
    /// [`WtbError::NotFinite`] or [`WtbError::OutOfRange`] for a NaN, infinite or negative height.
    pub fn obb(&self, height: f64) -> Result<Obb, WtbError> {
        let height = crate::grid::check_range("height", height, 0.0, f64::MAX)?;
        let c = self.world(DVec2::new(0.5 * self.length, 0.5 * self.width));
        let (u, v) = (self.u, self.v());
        Obb::new(
            DVec3::new(c.x, 0.0, c.y),
            [
                DVec3::new(u.x, 0.0, u.y),
                DVec3::Y,
                DVec3::new(v.x, 0.0, v.y),
            ],
            DVec3::new(0.5 * self.length, height, 0.5 * self.width),
        )
        .map_err(|_| WtbError::NotFinite("obb"))
    }

    /// Binds the frame to a water grid for the quadrant scan (see the module documentation). A box
    /// wholly outside the grid gives a traversal that visits nothing
    /// ([`Traversal::is_empty`]); whether that is an error is the caller's choice.
    ///
    /// # Errors
    ///
    /// [`WtbError::SpacingMismatch`] when the frame's spacing is not exactly the grid's.
    pub fn traversal(&self, grid: &WaterGrid) -> Result<Traversal, WtbError> {
        let s = grid.spacing();
        if self.spacing != s {
            return Err(WtbError::SpacingMismatch {
                frame: self.spacing,
                grid: s,
            });
        }
        let (qx, qz) = lattice_direction(self.u);
        let one = FIXED_ONE as f64;
        let lu = DVec2::new(qx as f64 / one, qz as f64 / one);
        let d = (grid.origin() - self.origin) / s;
        let ca = d.x * lu.x + d.y * lu.y;
        let cb = -d.x * lu.y + d.y * lu.x;
        // Constants past FAR give an empty traversal below; clamping first keeps the
        // conversions to i64 in range.
        let fixed = |v: f64| round_i64(v.clamp(-2.0 * FAR, 2.0 * FAR) * one);
        let q = FixedTraversal {
            ca: fixed(ca),
            cb: fixed(cb),
            ux: qx,
            uz: qz,
            length: fixed(self.length / s),
            width: fixed(self.width / s),
        };
        let (ca, cb) = (q.ca as f64 / one, q.cb as f64 / one);
        let steps_max = ceil_div(q.length) as u32;
        let rays_max = ceil_div(q.width) as u32;
        let mut t = Traversal {
            frame: *self,
            nx: grid.nx() as u32,
            nz: grid.nz() as u32,
            ux: lu.x,
            uz: lu.y,
            norm2: lu.x * lu.x + lu.y * lu.y,
            ca,
            cb,
            fixed: q,
            steps_max,
            rays: 0..0,
        };
        if ca.abs() <= FAR && cb.abs() <= FAR {
            // Rays whose centre line b = r − ½ crosses the grid's rectangle grown by one cell
            // (a cell holding a grid point has its centre within √2/2 of it on each axis).
            let (nx, nz) = (t.nx as f64, t.nz as f64);
            let mut lo = f64::INFINITY;
            let mut hi = f64::NEG_INFINITY;
            for (i, j) in [(-1.0, -1.0), (nx, -1.0), (-1.0, nz), (nx, nz)] {
                let b = cb - i * t.uz + j * t.ux;
                lo = lo.min(b);
                hi = hi.max(b);
            }
            let first = ceil_i64(lo + 0.5).max(0);
            let last = floor_i64(hi + 0.5).min(rays_max as i64);
            if first <= last {
                // Trim the rays that cross the grid only beyond the box's ends. The rays with
                // steps form one interval (the box and the grown grid rectangle are convex), and
                // at most about 2·4096·√2 rays cross the grid, so this loop is short.
                let (mut first, mut last) = (first as u32, last as u32);
                while first <= last && t.step_range(first).is_empty() {
                    first += 1;
                }
                while last > first && t.step_range(last).is_empty() {
                    last -= 1;
                }
                if first <= last {
                    t.rays = first..last + 1;
                }
            }
        }
        Ok(t)
    }
}

/// Normalises a direction, refusing zero and non-finite vectors.
pub(crate) fn unit_direction(name: &'static str, d: DVec2) -> Result<DVec2, WtbError> {
    if !d.is_finite() {
        return Err(WtbError::ZeroDirection(name));
    }
    // Scale first so that tiny or huge vectors neither underflow nor overflow when squared.
    let m = d.x.abs().max(d.y.abs());
    if m == 0.0 {
        return Err(WtbError::ZeroDirection(name));
    }
    let d = d / m;
    let len = sqrt(d.x * d.x + d.y * d.y);
    Ok(d / len)
}

/// The frame's u as the traversal uses it, in units of 2⁻³⁶: each component rounded to the
/// nearest unit, then the larger one raised by a unit until `|u|² ≥ 1` holds exactly, which
/// makes a cell at most one grid spacing wide (see "At most two points per cell"). The
/// rounding rotates u by less than 2⁻³⁶ rad; at most two raises are ever needed (the rounded
/// norm² is within 2·2⁻³⁶ of 1 and each raise adds more than 2⁻³⁶·√2).
fn lattice_direction(u: DVec2) -> (i64, i64) {
    let one = FIXED_ONE as f64;
    let (mut x, mut z) = (round_i64(u.x * one), round_i64(u.y * one));
    let target = i128::from(FIXED_ONE) * i128::from(FIXED_ONE);
    while i128::from(x) * i128::from(x) + i128::from(z) * i128::from(z) < target {
        if x.abs() >= z.abs() {
            x += x.signum();
        } else {
            z += z.signum();
        }
    }
    (x, z)
}

/// `round(v)` as an integer, for `|v| < 2⁶²`.
#[inline]
fn round_i64(v: f64) -> i64 {
    let r = floor_i64(v);
    if v - r as f64 >= 0.5 { r + 1 } else { r }
}

/// `⌈x / 2³⁶⌉` for a fixed-point value `x`.
#[inline]
fn ceil_div(x: i64) -> i64 {
    // Arithmetic shift floors; adding one unit less than 2³⁶ makes it a ceiling.
    (x + (FIXED_ONE - 1)) >> 36
}

/// The exact constants of a [`Traversal`], integers in units of 2⁻³⁶ cells ([`FIXED_ONE`]):
/// grid point (i, j) has the internal coordinates, in cells,
///
/// ```text
/// A = ca + i·ux + j·uz,   B = cb + j·ux − i·uz      (divided by FIXED_ONE)
/// ```
///
/// It is inside the box when `0 ≤ A ≤ length` and `0 ≤ B ≤ width`, and then belongs to step
/// `⌈A / FIXED_ONE⌉` of ray `⌈B / FIXED_ONE⌉`. Every product and sum fits an `i64` with room
/// to spare (|i·ux| < 2¹²·2³⁷, |ca| ≤ 2⁶²), which is what a GPU twin emulates.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FixedTraversal {
    /// `a/s` of grid point (0, 0).
    pub ca: i64,
    /// `b/s` of grid point (0, 0).
    pub cb: i64,
    /// u's x component (|u| ≥ 1 exactly).
    pub ux: i64,
    /// u's z component.
    pub uz: i64,
    /// The box's length in cells.
    pub length: i64,
    /// The box's width in cells.
    pub width: i64,
}

impl FixedTraversal {
    /// A and B of grid point (i, j).
    #[inline]
    pub fn internal(&self, i: u32, j: u32) -> (i64, i64) {
        let (i, j) = (i64::from(i), i64::from(j));
        (
            self.ca + i * self.ux + j * self.uz,
            self.cb + j * self.ux - i * self.uz,
        )
    }

    /// The step (of A) or ray (of B) owning a coordinate `x` when `0 ≤ x ≤ max`.
    #[inline]
    pub fn cell(x: i64, max: i64) -> Option<u32> {
        (0..=max).contains(&x).then(|| ceil_div(x) as u32)
    }
}

/// A water grid point found in a cell by the quadrant scan.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GridPoint {
    /// Column (along x).
    pub i: u32,
    /// Row (along z).
    pub j: u32,
    /// Row-major index `j·nx + i`.
    pub index: usize,
    /// Internal coordinate along u, metres (rounded; its cell was decided exactly).
    pub a: f64,
    /// Internal coordinate along v, metres.
    pub b: f64,
}

/// One wave ray of a traversal.
#[derive(Clone, Debug, PartialEq)]
pub struct RayInfo {
    /// The ray's index r: it owns `b ∈ ((r − 1)·s, r·s]`.
    pub ray: u32,
    /// World (x, z) of the ray's internal grid point at `a = 0`: `origin + r·s·v`.
    pub start: DVec2,
    /// Unit direction of travel along the ray (the frame's u).
    pub direction: DVec2,
    /// The steps visited: those whose cells may hold grid points (a sub-range of
    /// `0 .. step_count`), empty when the ray misses the grid.
    pub steps: Range<u32>,
}

/// A box frame bound to a water grid: the quadrant scan of Fig. 2 (see the module documentation).
/// Cheap to copy and `Send + Sync`, so rays can be scanned in parallel.
#[derive(Clone, Debug, PartialEq)]
pub struct Traversal {
    frame: BoxFrame,
    nx: u32,
    nz: u32,
    /// u as used by the lattice arithmetic ([`lattice_direction`]).
    ux: f64,
    uz: f64,
    norm2: f64,
    /// a/s and b/s of grid point (0, 0) (the fixed-point values, rounded).
    ca: f64,
    cb: f64,
    fixed: FixedTraversal,
    steps_max: u32,
    rays: Range<u32>,
}

impl Traversal {
    /// The frame.
    #[inline]
    pub fn frame(&self) -> &BoxFrame {
        &self.frame
    }

    /// The rays visited, in order: those whose strips may hold grid points (a sub-range of
    /// `0 .. frame.ray_count()`).
    #[inline]
    pub fn rays(&self) -> Range<u32> {
        self.rays.clone()
    }

    /// Whether no cell is visited. This holds for every box that stays more than one cell away
    /// from the grid's rectangle; a box closer to it, or one smaller than a cell that falls between
    /// grid points, may visit only empty cells.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.rays.is_empty()
    }

    /// Ray `r` with its world start and the range of steps visited (empty when `r` is not in
    /// [`Traversal::rays`]).
    pub fn ray(&self, r: u32) -> RayInfo {
        let f = &self.frame;
        RayInfo {
            ray: r,
            start: f.origin + f.v() * (r as f64 * f.spacing),
            direction: f.u,
            steps: if self.rays.contains(&r) {
                self.step_range(r)
            } else {
                0..0
            },
        }
    }

    /// The steps of ray `r` whose cells' centres lie within one cell of the grid's rectangle.
    fn step_range(&self, r: u32) -> Range<u32> {
        // Centre line of the ray in grid units: (i, j)(A) = P0 + A·(ux, uz)/|u|², A = a/s.
        let beta = r as f64 - 0.5 - self.cb;
        let i0 = (-self.ux * self.ca - self.uz * beta) / self.norm2;
        let j0 = (-self.uz * self.ca + self.ux * beta) / self.norm2;
        let (di, dj) = (self.ux / self.norm2, self.uz / self.norm2);
        let mut lo = f64::NEG_INFINITY;
        let mut hi = f64::INFINITY;
        for (p0, dp, n) in [(i0, di, self.nx as f64), (j0, dj, self.nz as f64)] {
            if dp == 0.0 {
                if !(-1.0..=n).contains(&p0) {
                    return 0..0;
                }
            } else {
                let t0 = (-1.0 - p0) / dp;
                let t1 = (n - p0) / dp;
                lo = lo.max(t0.min(t1));
                hi = hi.min(t0.max(t1));
            }
        }
        // Step k has its centre at A = k − ½.
        let kmax = self.steps_max as f64;
        let lo = (lo + 0.5).clamp(-1.0, kmax + 1.0);
        let hi = (hi + 0.5).clamp(-1.0, kmax + 1.0);
        let first = ceil_i64(lo).max(0);
        let last = floor_i64(hi).min(self.steps_max as i64);
        if first <= last {
            first as u32..last as u32 + 1
        } else {
            0..0
        }
    }

    /// The owner `(ray, step)` of grid point (i, j) by the exact inside and ownership rules, or
    /// `None` when the point is outside the box or the grid.
    pub fn classify(&self, i: u32, j: u32) -> Option<(u32, u32)> {
        if i >= self.nx || j >= self.nz || self.is_empty() {
            return None;
        }
        let f = &self.fixed;
        let (a, b) = f.internal(i, j);
        let k = FixedTraversal::cell(a, f.length)?;
        let r = FixedTraversal::cell(b, f.width)?;
        Some((r, k))
    }

    /// The exact constants (see [`FixedTraversal`]).
    #[inline]
    pub fn fixed(&self) -> &FixedTraversal {
        &self.fixed
    }

    /// The centre of the cell of step `k` of ray `r`, in grid units (fractional column, row).
    /// It moves by [`Traversal::centre_step`] per step.
    pub fn cell_centre(&self, r: u32, k: u32) -> DVec2 {
        let beta = r as f64 - 0.5 - self.cb;
        let alpha = k as f64 - 0.5 - self.ca;
        DVec2::new(
            (self.ux * alpha - self.uz * beta) / self.norm2,
            (self.uz * alpha + self.ux * beta) / self.norm2,
        )
    }

    /// How far a cell's centre moves per step, grid units: `u/|u|²`.
    #[inline]
    pub fn centre_step(&self) -> DVec2 {
        DVec2::new(self.ux, self.uz) / self.norm2
    }

    /// Half the side of a cell's axis-aligned bounding box, grid units: every grid point of a
    /// cell lies within this of its centre on each axis. At most √2/2, so a window of this
    /// half-width plus a margin under 0.29 holds at most two integers per axis.
    #[inline]
    pub fn cell_half_extent(&self) -> f64 {
        0.5 * (self.ux.abs() + self.uz.abs()) / self.norm2
    }

    /// Scans the cells of ray `r` in increasing step `k` (increasing a), calling
    /// `f(k, points)` with the 0, 1 or 2 grid points of each cell, in increasing a. Visits nothing
    /// when `r` is not in [`Traversal::rays`].
    pub fn for_each_cell_in_ray(&self, r: u32, mut f: impl FnMut(u32, &[GridPoint])) {
        if !self.rays.contains(&r) {
            return;
        }
        let s = self.frame.spacing;
        let q = &self.fixed;
        let one = FIXED_ONE as f64;
        // Candidates: the cell's bounding box around its (rounded) centre, plus a margin far
        // above the centre's rounding: < 1 in all, so at most 2 candidates per axis.
        let half = self.cell_half_extent() + 1e-4;
        let (nx, nz) = (self.nx as i64, self.nz as i64);
        let mut buf = [(0i64, GridPoint::default()); 4];
        let mut pts = [GridPoint::default(); 4];
        for k in self.step_range(r) {
            let c = self.cell_centre(r, k);
            let i_lo = ceil_i64(c.x - half).max(0);
            let i_hi = floor_i64(c.x + half).min(nx - 1);
            let j_lo = ceil_i64(c.y - half).max(0);
            let j_hi = floor_i64(c.y + half).min(nz - 1);
            let mut n = 0;
            for j in j_lo..=j_hi {
                for i in i_lo..=i_hi {
                    let (a, b) = q.internal(i as u32, j as u32);
                    if FixedTraversal::cell(a, q.length) != Some(k)
                        || FixedTraversal::cell(b, q.width) != Some(r)
                        || n == buf.len()
                    {
                        continue;
                    }
                    buf[n] = (
                        a,
                        GridPoint {
                            i: i as u32,
                            j: j as u32,
                            index: (j * nx + i) as usize,
                            a: a as f64 / one * s,
                            b: b as f64 / one * s,
                        },
                    );
                    n += 1;
                }
            }
            let cell = &mut buf[..n];
            // Increasing exact a (insertion sort of at most 4).
            for x in 1..cell.len() {
                let mut y = x;
                while y > 0 && cell[y - 1].0 > cell[y].0 {
                    cell.swap(y - 1, y);
                    y -= 1;
                }
            }
            for (p, (_, g)) in pts.iter_mut().zip(cell.iter()) {
                *p = *g;
            }
            f(k, &pts[..n]);
        }
    }

    /// Scans every visited cell: rays in increasing r, and along each ray steps in increasing k,
    /// calling `f(&ray, k, points)` (see [`Traversal::for_each_cell_in_ray`]).
    pub fn for_each_cell(&self, mut f: impl FnMut(&RayInfo, u32, &[GridPoint])) {
        for r in self.rays() {
            let ray = self.ray(r);
            self.for_each_cell_in_ray(r, |k, pts| f(&ray, k, pts));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lattice_direction_has_norm_at_least_one() {
        for deg in 0..3600 {
            let t = deg as f64 * core::f64::consts::PI / 1800.0;
            let u = unit_direction(
                "d",
                DVec2::new(ocean_core::math::cos(t), ocean_core::math::sin(t)),
            )
            .unwrap();
            let (x, z) = lattice_direction(u);
            let norm2 = i128::from(x) * i128::from(x) + i128::from(z) * i128::from(z);
            let one = i128::from(FIXED_ONE);
            assert!(norm2 >= one * one, "{deg}");
            // At most two raises of a unit above the rounded vector.
            assert!(norm2 < one * one + 8 * one, "{deg}");
            let l = DVec2::new(x as f64, z as f64) / FIXED_ONE as f64;
            assert!((l - u).length() < 3.0 / FIXED_ONE as f64, "{deg}");
        }
    }
}
