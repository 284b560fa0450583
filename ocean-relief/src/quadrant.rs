//! The four closed quadrants of horizontal ray directions, which quad-directional cone maps
//! ([`crate::quad`]) keep one cone each for, and which the cone bounds ([`crate::bound`], and
//! its arcs of directions in `arc.rs`) restrict their vectors to.

/// A closed quadrant of horizontal directions (see [`crate::quad`]): `x_neg` for `uₓ ≤ 0`
/// (else `uₓ ≥ 0`), `y_neg` for `u_y ≤ 0` (else `u_y ≥ 0`). Layer index
/// `x_neg + 2·y_neg` ([`Quadrant::index`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Quadrant {
    /// The quadrant of `uₓ ≤ 0`.
    pub x_neg: bool,
    /// The quadrant of `u_y ≤ 0`.
    pub y_neg: bool,
}

impl Quadrant {
    /// The four quadrants in layer order.
    pub const ALL: [Quadrant; 4] = [
        Quadrant::new(false, false),
        Quadrant::new(true, false),
        Quadrant::new(false, true),
        Quadrant::new(true, true),
    ];

    /// The quadrant of `uₓ ≤ 0` (`x_neg`) or `≥ 0`, and likewise `y`.
    pub const fn new(x_neg: bool, y_neg: bool) -> Self {
        Self { x_neg, y_neg }
    }

    /// The quadrant the tracer picks for a scaled direction `(dx, dy)`: negative components pick
    /// the negative side, `0` (and `−0`) the positive one, whose closed quadrant contains it.
    pub fn of(dx: f32, dy: f32) -> Self {
        Self::new(dx < 0.0, dy < 0.0)
    }

    /// Layer index `x_neg + 2·y_neg`.
    pub const fn index(self) -> usize {
        self.x_neg as usize + 2 * self.y_neg as usize
    }

    /// `(sₓ, s_y)`, each `±1`.
    pub fn signs(self) -> (f64, f64) {
        (
            if self.x_neg { -1.0 } else { 1.0 },
            if self.y_neg { -1.0 } else { 1.0 },
        )
    }

    /// Whether the direction `(ux, uy)` lies in the closed quadrant.
    pub fn contains(self, ux: f64, uy: f64) -> bool {
        let (sx, sy) = self.signs();
        sx * ux >= 0.0 && sy * uy >= 0.0
    }

    /// The quadrant as a closed box of vectors `[wx0, wx1, wy0, wy1]`.
    pub(crate) fn vectors(self) -> [f64; 4] {
        let (lo, hi) = (f64::NEG_INFINITY, f64::INFINITY);
        let x = if self.x_neg { [lo, 0.0] } else { [0.0, hi] };
        let y = if self.y_neg { [lo, 0.0] } else { [0.0, hi] };
        [x[0], x[1], y[0], y[1]]
    }
}
