//! Sharper cell bounds by subdivision: the plain cone of an apex cell as the minimum of the
//! [`crate::bound`] bound over pairs of **parts** of the apex cell and of each candidate cell.
//!
//! The cell bound loses width in three places, all from treating each cell as one box: the
//! distance from apex box to candidate box is short of the distance from the apex `p` to the
//! exit `b` by up to the two boxes' diagonals; `Smax(q) − m_C` exceeds `S(p) − M` by the depth
//! range of both cells; and the falling test and the near-cell rise see every gradient of the
//! candidate and every direction between the boxes. On a pin, a sphere's rim or a box edge these
//! cost a texel of distance or most of a cell's depth range, which is what separates the cell
//! bound from the widest valid cone ([`crate::widest`]).
//!
//! ## The refined bound, and why it is valid
//!
//! The theorem of [`crate::bound`] uses three facts about the apex box `q` and candidate box `C`:
//! `Smax(q) ≥ S(p)` for every `p ∈ q`; the surface on `C` is one bilinear patch, so `m_C`
//! bounds its depth from below and the gradient box `G_C` contains every gradient on the closed
//! box; and the path from `p` to the exit lies in the bounding box of the two **cells**, which
//! the Lipschitz ring and the near-cell path boxes cover. All three hold for any sub-rectangle
//! `q'` of the apex cell (with `Smax(q')` an upper bound of the depth over `q'`) and any
//! sub-rectangle `C'` of a candidate cell (with its own `m`, a lower bound over `C'`, and its own
//! gradient box), while the Lipschitz ring and the twist stay those of the cells. The near-cell
//! rule's path box `G_P` needs only to hold every gradient on the segments from `p ∈ q'` to
//! `b ∈ C'`; they lie in the bounding box of `q' ∪ C'`, so `G_P` is the union, over the cells
//! that box overlaps, of each cell's gradient box on its part of it (`Pair::path`), much
//! smaller than the cells' when the parts are. (Beside the apex, where the parts touch and
//! `A` is 0, that rule alone sets the value: on fBm at 64² with 2 halvings the cells' path box
//! gave 0.741 of the widest cones on average, this one 0.771, both against the widest cones
//! refined by an earlier search over point and angle.)
//! So the bound `v(q', C')` of the pair of parts is a valid lower bound of
//! `s/(S(p) − M)` for every exit `b ∈ C'` seen from every `p ∈ q'`, and a pair of parts that is
//! not a candidate holds no exit.
//!
//! Every exit that the cell pair `(q, C)` covers lies in some pair of parts, so
//! `R(q, C) = min over pairs of parts of v(q', C')` bounds the pair's exits, and
//! `min(cap, min over C of R(q, C))` bounds `inf over p ∈ q of c*(p)` as the cell bound does.
//! Parts are made by halving, [`crate::ConeParams::parts`] times, alternately the candidate and the apex part
//! (both axes; not along an axis where the box is a clamp-mode border strip, which stands for
//! the whole strip and must keep the cell's extent). A part's value is taken as the larger of its
//! own bound and its parent's: the parent's bound already holds for every exit in the part, so
//! the maximum is valid too, and it makes values grow monotonically down the subdivision. That
//! makes pruning exact: a pair whose value is not below the best cone found so far cannot lower
//! it at any finer level, and a pair that is not a candidate has no candidate parts. The result
//! is therefore the same minimum in whatever order apexes and candidates are visited, so the
//! branch-and-bound and the brute force still agree bit for bit.
//!
//! ## Floating point
//!
//! Part depths are bilinear values at dyadic points, computed in `f64` and padded outwards by
//! `2⁻⁴⁶` (far above the few roundings of a value in `[0, 1]`), then clamped to the cell's own
//! range (the exact bounds). Gradient bounds along a part are linear in the other coordinate;
//! where the two edge differences are equal (no twist along that axis) the bound is the exact
//! difference, as in the cell bound, so planar ramps keep their exact level directions;
//! elsewhere the two end values are padded by `2⁻⁵⁰` of the edge differences' magnitude. Every
//! padded bound is then intersected with the cell's stored box, which contains the exact one.

use crate::bound::{Apex, ApexPart, BIG, Cell, ConeKind, Grid, Region, candidate_in};

/// Padding of part depths (a depth is a sum of a few products of values in `[0, 1]`).
const DEPTH_PAD: f64 = 1.0 / (1u64 << 46) as f64;
/// Relative padding of interior gradient bounds.
const GRADIENT_PAD: f64 = 1.0 / (1u64 << 50) as f64;
/// Largest number of cells plus one along each axis of a path box: the near-cell rule reaches
/// [`crate::bound::K_LIP`] cells from the apex cell, so a box spans at most `K_LIP + 2` cells.
const SPAN: usize = crate::bound::K_LIP + 3;

/// The bilinear patch with corners `c = [d00, d10, d01, d11]` at local `(x, y) ∈ [0, 1]²`.
#[inline(always)]
fn bilinear(c: [f64; 4], x: f64, y: f64) -> f64 {
    let top = c[0] + (c[1] - c[0]) * x;
    let bottom = c[2] + (c[3] - c[2]) * x;
    top + (bottom - top) * y
}

/// The range of `e0·(1 − t) + e1·t` over `t ∈ [t0, t1]`, bounded outwards (see the module
/// documentation), intersected with the stored `[lo, hi]`.
#[inline(always)]
fn edge_range(e0: f64, e1: f64, t0: f64, t1: f64, stored: [f64; 2]) -> [f64; 2] {
    let (lo, hi) = if e0 == e1 {
        (e0, e0)
    } else {
        let a = e0 + (e1 - e0) * t0;
        let b = e0 + (e1 - e0) * t1;
        let pad = (e0.abs() + e1.abs()) * GRADIENT_PAD;
        (a.min(b) - pad, a.max(b) + pad)
    };
    [lo.max(stored[0]), hi.min(stored[1])]
}

/// The gradient box `[gx0, gx1, gy0, gy1]` of the bilinear patch with corners `c` over its part
/// `[x0, x1, y0, y1]` (local coordinates), within the cell's stored box: `∂S/∂x` runs from
/// `d10 − d00` (y = 0) to `d11 − d01` (y = 1), `∂S/∂y` likewise along x.
#[inline(always)]
fn gradients(c: [f64; 4], cell: &Cell, part: [f64; 4]) -> [f64; 4] {
    let [x0, x1, y0, y1] = part;
    let gx = edge_range(
        c[1] - c[0],
        c[3] - c[2],
        y0,
        y1,
        [f64::from(cell.gx[0]), f64::from(cell.gx[1])],
    );
    let gy = edge_range(
        c[2] - c[0],
        c[3] - c[1],
        x0,
        x1,
        [f64::from(cell.gy[0]), f64::from(cell.gy[1])],
    );
    [gx[0], gx[1], gy[0], gy[1]]
}

/// A part of a cell in local coordinates `[x0, x1, y0, y1] ⊂ [0, 1]²`, and whether each axis
/// may be halved.
#[derive(Clone, Copy, Debug)]
struct Part {
    local: [f64; 4],
    split: [bool; 2],
}

impl Part {
    /// The (up to four) halves of the part.
    fn halves(&self, out: &mut [Part; 4]) -> usize {
        let [x0, x1, y0, y1] = self.local;
        let xs: &[[f64; 2]] = if self.split[0] {
            &[[x0, 0.5 * (x0 + x1)], [0.5 * (x0 + x1), x1]]
        } else {
            &[[x0, x1]]
        };
        let ys: &[[f64; 2]] = if self.split[1] {
            &[[y0, 0.5 * (y0 + y1)], [0.5 * (y0 + y1), y1]]
        } else {
            &[[y0, y1]]
        };
        let mut k = 0;
        for y in ys {
            for x in xs {
                out[k] = Part {
                    local: [x[0], x[1], y[0], y[1]],
                    split: self.split,
                };
                k += 1;
            }
        }
        k
    }
}

/// One refinement: the apex cell and one candidate cell.
struct Pair<'a> {
    grid: &'a Grid<'a>,
    q: &'a Apex,
    cell: &'a Cell,
    ci: i64,
    cj: i64,
    kind: ConeKind,
    lip_global: f64,
    /// Corner depths of the apex cell and of the candidate cell.
    qc: [f64; 4],
    cc: [f64; 4],
    /// Halvings.
    levels: u32,
}

impl Pair<'_> {
    fn apex_part(&self, p: &Part) -> ApexPart {
        let [x0, x1, y0, y1] = p.local;
        let r = self.q.rect;
        let (qi, qj) = (self.q.qi as f64, self.q.qj as f64);
        // Border strips (±BIG) keep their extent; a strip's depth does not vary along it.
        let rect = [
            if r[0] == -BIG { r[0] } else { qi + x0 },
            if r[1] == BIG { r[1] } else { qi + x1 },
            if r[2] == -BIG { r[2] } else { qj + y0 },
            if r[3] == BIG { r[3] } else { qj + y1 },
        ];
        let c = self.qc;
        let top = bilinear(c, x0, y0)
            .max(bilinear(c, x1, y0))
            .max(bilinear(c, x0, y1))
            .max(bilinear(c, x1, y1));
        ApexPart {
            rect,
            smax: (top + DEPTH_PAD).min(self.q.smax),
        }
    }

    fn region(&self, p: &Part) -> Region {
        let [x0, x1, y0, y1] = p.local;
        let c = self.cc;
        let low = bilinear(c, x0, y0)
            .min(bilinear(c, x1, y0))
            .min(bilinear(c, x0, y1))
            .min(bilinear(c, x1, y1));
        let g = gradients(c, self.cell, p.local);
        Region {
            rect: [
                self.ci as f64 + x0,
                self.ci as f64 + x1,
                self.cj as f64 + y0,
                self.cj as f64 + y1,
            ],
            m: (low - DEPTH_PAD).max(f64::from(self.cell.m)),
            g,
        }
    }

    /// The union of the gradient boxes over the bounding box of apex part `a` and candidate
    /// part `c` (spatial rectangles), each cell contributing the box of its own sub-rectangle
    /// there: every gradient that a segment from `a` to `c` meets, moving inside that box (the
    /// near-cell rule's `G_P`, module documentation). `None` for a clamp-mode border strip,
    /// whose extent is not a rectangle of cells; the cells' path box serves there.
    fn path(&self, a: [f64; 4], c: [f64; 4]) -> Option<[f64; 4]> {
        let r = [
            a[0].min(c[0]),
            a[1].max(c[1]),
            a[2].min(c[2]),
            a[3].max(c[3]),
        ];
        if r[0] == -BIG || r[1] == BIG || r[2] == -BIG || r[3] == BIG {
            return None;
        }
        // Cells that a segment in the closed box moves through: those overlapping its interior;
        // along a degenerate axis (a segment on a cell edge), the cells on both sides.
        let span = |lo: f64, hi: f64| -> (i64, i64) {
            let (a, b) = (libm::floor(lo) as i64, libm::ceil(hi) as i64 - 1);
            if b < a { (a - 1, a) } else { (a, b) }
        };
        let (xs, ys) = (span(r[0], r[1]), span(r[2], r[3]));
        let (wx, wy) = ((xs.1 - xs.0 + 1) as usize, (ys.1 - ys.0 + 1) as usize);
        if wx >= SPAN || wy >= SPAN {
            return None;
        }
        let g = self.grid;
        // Texel indices of the cells' edges along each axis, and the cells' indices (none for
        // a clamp-mode cell outside the grid), resolved once for the whole box.
        let mut tx = [0usize; SPAN];
        let mut ty = [0usize; SPAN];
        for (k, t) in tx.iter_mut().enumerate().take(wx + 1) {
            *t = g.edge.resolve(xs.0 + k as i64, g.n);
        }
        for (k, t) in ty.iter_mut().enumerate().take(wy + 1) {
            *t = g.edge.resolve(ys.0 + k as i64, g.n);
        }
        let cell_index = |c: i64, resolved: usize| -> Option<usize> {
            match g.edge {
                crate::Edge::Wrap => Some(resolved),
                crate::Edge::Clamp => {
                    let k = c - g.origin;
                    (0..g.nc as i64).contains(&k).then_some(k as usize)
                }
            }
        };
        let mut out = [
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for b in 0..wy {
            let cj = ys.0 + b as i64;
            let Some(row) = cell_index(cj, ty[b]) else {
                continue;
            };
            for a in 0..wx {
                let ci = xs.0 + a as i64;
                let Some(col) = cell_index(ci, tx[a]) else {
                    continue;
                };
                let cell = &g.cells[row * g.nc + col];
                let d = |i: usize, j: usize| f64::from(g.depth[ty[j] * g.n + tx[i]]);
                let c = [d(a, b), d(a + 1, b), d(a, b + 1), d(a + 1, b + 1)];
                let local = |v: f64, at: i64| (v - at as f64).clamp(0.0, 1.0);
                let part = [
                    local(r[0], ci),
                    local(r[1], ci),
                    local(r[2], cj),
                    local(r[3], cj),
                ];
                let g = gradients(c, cell, part);
                out = [
                    out[0].min(g[0]),
                    out[1].max(g[1]),
                    out[2].min(g[2]),
                    out[3].max(g[3]),
                ];
            }
        }
        Some(out)
    }

    /// Lowers `best` to the smallest value of a pair of finest parts below it (module
    /// documentation); `value` is the pair `(qp, cp)`'s own, `qa` and `cr` what the bound needs
    /// of each part.
    #[allow(clippy::too_many_arguments)]
    fn descend(
        &self,
        qp: &Part,
        qa: ApexPart,
        cp: &Part,
        cr: &Region,
        value: f64,
        level: u32,
        best: &mut f64,
    ) {
        if level == self.levels {
            *best = best.min(value);
            return;
        }
        let mut halves = [*qp; 4];
        // Even levels halve the candidate part, odd ones the apex part.
        let on_candidate = level.is_multiple_of(2);
        let count = if on_candidate {
            cp.halves(&mut halves)
        } else {
            qp.halves(&mut halves)
        };
        // Every half's value first, then the lowest first: the smallest value found early
        // prunes the other halves' subtrees sooner.
        let mut kids: [(f64, Part, ApexPart, Part, Region); 4] =
            [(f64::INFINITY, *qp, qa, *cp, *cr); 4];
        let mut found = 0;
        for h in &halves[..count] {
            let (q2, qa2, c2, cr2) = if on_candidate {
                (*qp, qa, *h, self.region(h))
            } else {
                (*h, self.apex_part(h), *cp, *cr)
            };
            if let Some(v) = candidate_in(
                self.q,
                qa2,
                &cr2,
                self.cell.twist,
                self.ci,
                self.cj,
                self.kind,
                self.lip_global,
                *best,
                || self.path(qa2.rect, cr2.rect),
            ) {
                let v = v.value().max(value);
                if v < *best {
                    kids[found] = (v, q2, qa2, c2, cr2);
                    found += 1;
                }
            }
        }
        let kids = &mut kids[..found];
        kids.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
        for (v, q2, qa2, c2, cr2) in kids.iter() {
            if *v < *best {
                self.descend(q2, *qa2, c2, cr2, *v, level + 1, best);
            }
        }
    }
}

/// Lowers `best` to `R(q, C)` for candidate cell `cell` at spatial position `(ci, cj)` when that
/// is below it; `coarse` is the cell pair's own bound ([`crate::bound::candidate`]).
#[allow(clippy::too_many_arguments)]
pub(crate) fn refine(
    grid: &Grid<'_>,
    q: &Apex,
    cell: &Cell,
    ci: i64,
    cj: i64,
    kind: ConeKind,
    coarse: f64,
    levels: u32,
    best: &mut f64,
) {
    if levels == 0 {
        *best = best.min(coarse);
        return;
    }
    if coarse >= *best {
        return;
    }
    let pair = Pair {
        grid,
        q,
        cell,
        ci,
        cj,
        kind,
        lip_global: grid.lip_global,
        qc: grid.corners(q.qi, q.qj),
        cc: grid.corners(ci, cj),
        levels,
    };
    let whole = [0.0, 1.0, 0.0, 1.0];
    let apex = Part {
        local: whole,
        split: [
            q.rect[0] != -BIG && q.rect[1] != BIG,
            q.rect[2] != -BIG && q.rect[3] != BIG,
        ],
    };
    // A clamp-mode border cell stands for its strip along the axis where it is constant.
    let strip = |c: i64| grid.edge == crate::Edge::Clamp && (c == -1 || c == grid.n as i64 - 1);
    let candidate = Part {
        local: whole,
        split: [!strip(ci), !strip(cj)],
    };
    let whole_apex = ApexPart {
        rect: q.rect,
        smax: q.smax,
    };
    let whole_candidate = Region::cell(cell, ci, cj);
    pair.descend(
        &apex,
        whole_apex,
        &candidate,
        &whole_candidate,
        coarse,
        0,
        best,
    );
}
