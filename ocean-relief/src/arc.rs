//! Sets of horizontal directions (arcs of the unit circle) for the direction-consistent near-cell
//! bound of [`crate::bound`]: the directions from an apex cell to a candidate cell along which
//! the candidate can fall, and the largest rate at which the path can rise along them.
//!
//! Directions are compared by their *pseudo-angle*, a monotone map of the angle onto `[0, 4)`
//! (the "diamond angle": 0 = +x, 1 = +y, 2 = −x, 3 = −y) that needs no transcendental function
//! and shifts by exactly 1 under a quarter turn, so the arcs are computed without rounding in the
//! angles themselves. Arcs are closed and carry their end vectors.

use crate::quadrant::Quadrant;
use crate::round::up32;

/// Pseudo-angle of a non-zero vector, in `[0, 4)`.
#[inline]
pub(crate) fn pseudo(x: f64, y: f64) -> f64 {
    if y >= 0.0 {
        if x >= 0.0 {
            y / (x + y)
        } else {
            1.0 - x / (-x + y)
        }
    } else if x < 0.0 {
        2.0 - y / (-x - y)
    } else {
        let a = 3.0 + x / (x - y);
        if a >= 4.0 { 0.0 } else { a }
    }
}

/// `a − b` wrapped into `[0, 4)`.
#[inline]
fn ahead(a: f64, b: f64) -> f64 {
    let d = a - b;
    if d < 0.0 { d + 4.0 } else { d }
}

/// The closed arc from `start` counter-clockwise to `end`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Arc {
    pub start: (f64, f64),
    pub end: (f64, f64),
    /// Pseudo-angle of `start`.
    pub p0: f64,
    /// Pseudo-angular length, `[0, 4]`.
    pub len: f64,
}

impl Arc {
    fn new(start: (f64, f64), end: (f64, f64), len: f64) -> Self {
        Self {
            start,
            end,
            p0: pseudo(start.0, start.1),
            len,
        }
    }

    /// Whether the direction of `(x, y)` lies on the arc.
    #[inline]
    pub fn contains(&self, x: f64, y: f64) -> bool {
        ahead(pseudo(x, y), self.p0) <= self.len
    }
}

/// Corners of the box `[x0, x1] × [y0, y1]`.
#[inline]
fn corners(b: [f64; 4]) -> [(f64, f64); 4] {
    [(b[0], b[2]), (b[1], b[2]), (b[0], b[3]), (b[1], b[3])]
}

/// The directions of the vectors of a box that does not contain the origin: the arc between
/// its angularly extreme corners (less than a half turn). `None` when the box contains the
/// origin (every direction).
pub(crate) fn box_directions(b: [f64; 4]) -> Option<Arc> {
    if b[0] <= 0.0 && 0.0 <= b[1] && b[2] <= 0.0 && 0.0 <= b[3] {
        return None;
    }
    let c = corners(b);
    // The start is the corner from which every other lies counter-clockwise (cross ≥ 0); a box
    // off the origin spans less than a half turn, so exactly one corner direction qualifies
    // (several equal corners are interchangeable).
    let cross = |a: (f64, f64), b: (f64, f64)| a.0 * b.1 - a.1 * b.0;
    let nonzero = |v: &(f64, f64)| v.0 != 0.0 || v.1 != 0.0;
    let start = *c
        .iter()
        .filter(|a| nonzero(a))
        .find(|&&a| c.iter().filter(|b| nonzero(b)).all(|&b| cross(a, b) >= 0.0))?;
    let end = *c
        .iter()
        .filter(|a| nonzero(a))
        .find(|&&a| c.iter().filter(|b| nonzero(b)).all(|&b| cross(b, a) >= 0.0))?;
    let p0 = pseudo(start.0, start.1);
    Some(Arc::new(start, end, ahead(pseudo(end.0, end.1), p0)))
}

/// The closed quarter turn of the directions of quadrant `q`, counter-clockwise from its first
/// axis to its second.
pub(crate) fn quadrant_arc(q: Quadrant) -> Arc {
    let (sx, sy) = q.signs();
    // Counter-clockwise, the quadrant (sx, sy) starts on the x axis when sx·sy > 0, else on the
    // y axis.
    let (start, end) = if sx * sy > 0.0 {
        ((sx, 0.0), (0.0, sy))
    } else {
        ((0.0, sy), (sx, 0.0))
    };
    Arc::new(start, end, 1.0)
}

/// The closed arc of directions `u` with `g·u ≤ 0` for every `g` in the gradient box `g`; `None`
/// when it is empty (the box contains the origin, so some gradient is 0 and nothing is excluded).
fn non_growing(g: [f64; 4]) -> Option<Arc> {
    let span = box_directions(g)?;
    // u must be at least a quarter turn from every direction of the box: from end + ¼ turn to
    // start + ¾ turn.
    let (sx, sy) = span.start;
    let (ex, ey) = span.end;
    let start = (-ey, ex); // end rotated by +90°
    let end = (sy, -sx); // start rotated by +270°
    Some(Arc::new(start, end, 2.0 - span.len))
}

/// Up to two arcs: `d` (or the whole circle) minus the closed arc `x`, as closures.
fn subtract(d: Option<Arc>, x: Option<Arc>) -> ([Option<Arc>; 2], bool) {
    let Some(x) = x else {
        return ([d, None], d.is_none());
    };
    // The complement of x: from x's end round to x's start.
    let rest = Arc::new(x.end, x.start, 4.0 - x.len);
    let Some(d) = d else {
        return ([Some(rest), None], false);
    };
    // Intersect the arcs d = [0, d.len] and rest = [a, a + rest.len] relative to d's start.
    let a = ahead(rest.p0, d.p0);
    let mut out = [None, None];
    let mut k = 0;
    for shift in [0.0, -4.0] {
        let lo = a + shift;
        let hi = lo + rest.len;
        if hi < 0.0 || lo > d.len {
            continue;
        }
        let (s, sp) = if lo > 0.0 {
            (rest.start, lo)
        } else {
            (d.start, 0.0)
        };
        let (e, ep) = if hi < d.len {
            (rest.end, hi)
        } else {
            (d.end, d.len)
        };
        out[k] = Some(Arc::new(s, e, ep - sp));
        k += 1;
    }
    (out, false)
}

/// The largest rate at which the depth can *decrease* (the path rises) along a direction `u`
/// that points from the apex box into the candidate (`w`, a box of vectors) and along which the
/// candidate's gradient box `gc` allows growth (`max_{g ∈ gc} g·u ≥ 0`), given the box `gp` of
/// gradients over the path. `sup` over those `u` of `max_{g ∈ gp} (−g·u)`; 0 when no direction
/// qualifies or none rises. Rounded up. With a quadrant (`w` then lies in it), a box that holds
/// the origin has its directions in the quadrant's closed arc, not on the whole circle.
pub(crate) fn max_rise(w: [f64; 4], gc: [f64; 4], gp: [f64; 4], sector: Option<Quadrant>) -> f64 {
    let directions = box_directions(w).or_else(|| sector.map(quadrant_arc));
    let (arcs, full) = subtract(directions, non_growing(gc));
    // Support of −gp: its corners e.
    let e = corners([-gp[1], -gp[0], -gp[3], -gp[2]]);
    let mut best = 0.0f64;
    for (ex, ey) in e {
        let norm = libm::sqrt(ex * ex + ey * ey);
        if norm == 0.0 {
            continue;
        }
        if full {
            best = best.max(norm);
            continue;
        }
        for arc in arcs.iter().flatten() {
            if arc.contains(ex, ey) {
                best = best.max(norm);
            }
            for (ux, uy) in [arc.start, arc.end] {
                let l = libm::sqrt(ux * ux + uy * uy);
                if l > 0.0 {
                    best = best.max((ex * ux + ey * uy) / l);
                }
            }
        }
    }
    // Above the few roundings of the norms and quotients.
    f64::from(up32(best * (1.0 + 1.0e-9)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pseudo-angle is monotone in the angle and a quarter turn adds exactly 1.
    #[test]
    fn pseudo_angle() {
        let mut last = -1.0;
        for k in 0..4096 {
            let a = core::f64::consts::TAU * k as f64 / 4096.0;
            let p = pseudo(libm::cos(a), libm::sin(a));
            assert!(p > last && p < 4.0, "{k}: {p} after {last}");
            last = p;
        }
        for (x, y) in [(3.0, 1.0), (-2.0, 5.0), (-1.0, -7.0), (4.0, -0.5)] {
            let q = (pseudo(-y, x) - pseudo(x, y) + 4.0) % 4.0;
            assert_eq!(q, 1.0, "({x}, {y})");
        }
    }

    /// A plane (one gradient everywhere) has no peak: no direction both rises and falls.
    #[test]
    fn plane_never_rises_where_it_falls() {
        let g = [0.3, 0.3, -0.1, -0.1];
        // Every box of vectors, including ones containing the origin.
        for w in [
            [0.0, 2.0, -1.0, 1.0],
            [-1.0, 1.0, -1.0, 1.0],
            [1.0, 3.0, 2.0, 4.0],
            [-3.0, -1.0, 0.0, 2.0],
        ] {
            assert_eq!(max_rise(w, g, g, None), 0.0, "{w:?}");
        }
    }

    /// A ridge: the path rises along +x at rate 0.5 and the candidate falls along +x: the full
    /// rate is available when +x is a direction of the vector box, and nothing when the box
    /// only holds directions where the candidate rises.
    #[test]
    fn ridge_rate() {
        let gc = [0.2, 0.2, 0.0, 0.0];
        let gp = [-0.5, 0.2, 0.0, 0.0];
        let r = max_rise([1.0, 3.0, -1.0, 1.0], gc, gp, None);
        assert!((r - 0.5).abs() < 1e-6, "{r}");
        assert_eq!(max_rise([-3.0, -1.0, -1.0, 1.0], gc, gp, None), 0.0);
    }

    /// A quadrant's arc is its closed quarter turn: both axes on it, the other quadrants' interior
    /// directions off it.
    #[test]
    fn quadrant_arcs() {
        for q in Quadrant::ALL {
            let (sx, sy) = q.signs();
            let arc = quadrant_arc(q);
            assert!(arc.contains(sx, 0.0) && arc.contains(0.0, sy), "{q:?}");
            assert!(arc.contains(sx, 0.5 * sy), "{q:?}");
            for (x, y) in [(-sx, sy), (sx, -sy), (-sx, -sy)] {
                assert!(!arc.contains(x, 0.5 * y), "{q:?} ({x}, {y})");
            }
        }
    }

    /// A ridge seen from inside the apex cell: the path rises along +x at 0.5 and along −x at
    /// 0.25; the box of vectors holds the origin. Over every direction the rise is 0.5; restricted
    /// to the quadrants of −x it is 0.25.
    #[test]
    fn quadrant_limits_the_rise() {
        let gc = [-0.2, 0.2, 0.0, 0.0];
        let gp = [-0.5, 0.25, 0.0, 0.0];
        let r = max_rise([-1.0, 1.0, -1.0, 1.0], gc, gp, None);
        assert!((r - 0.5).abs() < 1e-6, "{r}");
        let q = Quadrant::of(-1.0, 1.0);
        let w = [-1.0, 0.0, 0.0, 1.0];
        let r = max_rise(w, gc, gp, Some(q));
        assert!((r - 0.25).abs() < 1e-6, "{r}");
    }
}
