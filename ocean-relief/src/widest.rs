//! The widest valid cones, measured: the oracle that says how much of the allowed width a cone
//! map uses.
//!
//! The tracer reads texel `k`'s cone at every point of its bilinear footprint, the four cells
//! around its centre (a point within one texel of the centre along each axis), so the widest
//! plain cone the texel may hold is
//!
//! `W(k) = min(cap, inf over p in the footprint, over directions u, of c*(p, u))`,
//!
//! `c*` the exact directional limit of [`crate::check`] (Lemma 1 of [`crate::bound`]). A map of
//! `W` values is itself valid: a bilinear blend at `p` mixes four texels whose footprints all
//! contain `p`, each `≤ c*(p)`. [`widest`] samples the infimum on a sub-grid of points (texel
//! centres, cell edges and the clamp-mode border strips included) and a fan of directions, then
//! (with [`WidestParams::refine`]) walks downhill from each cell's smallest sample: a pattern
//! search over the point (inside the closed cell) and the direction, halving its steps. Every
//! value it takes is `c*` of some line, so it can only overestimate `W`: a generated cone above
//! it is invalid on that line, one below it is narrower than allowed by at least that much.
//! The sampled infimum alone misses the minima between samples, most where the limiting line
//! grazes the top of a pin or a box's corner. Measured on the family at 64² with the default
//! generator: its mean share of the sampled `W` is 0.889, of a 16 times denser sampling (4×4
//! points a cell, 256 directions) 0.904, and of the refined `W` from the default sampling
//! 0.908, at about the cost of the samples.
//!
//! [`width`] compares a cone map with it: the mean of `generated / W`, the mean weighted by the
//! texel's depth (a cone's reach from the top of the relief is its ratio times that depth, so
//! a narrow cone on a high texel costs little) and the worst texel.

use alloc::vec;
use alloc::vec::Vec;
use core::f64::consts::TAU;

use crate::bound::ConeKind;
use crate::check::{conservative_limit_at, relaxed_limit_at};
use crate::map::{Edge, HeightMap};
use crate::quadrant::Quadrant;
use crate::{ReliefError, for_rows};

/// How densely [`widest`] samples.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WidestParams {
    /// Points per cell along each axis (positions `k/apexes`: texel centres and cell edges
    /// included).
    pub apexes: usize,
    /// Directions per point, evenly spaced from angle 0 (axes and diagonals included when a
    /// multiple of 8).
    pub directions: usize,
    /// Step halvings of the local search from each cell's smallest sample (0: the samples
    /// alone). It starts at half the sample spacing for the point, and for the pivot at half the
    /// angle between directions (as an arc at the exit's distance).
    pub refine: u32,
}

impl Default for WidestParams {
    fn default() -> Self {
        Self {
            apexes: 2,
            directions: 64,
            refine: 10,
        }
    }
}

/// Moves the local search may make at one step size before it halves the step.
const MOVES_PER_STEP: usize = 8;

/// `W` per texel, row-major, in texture widths per unit depth (the cone map's unit), capped at
/// `cap` ([`crate::ConeParams::max_ratio`]): see the module documentation.
///
/// # Errors
///
/// [`ReliefError::OutOfRange`] / [`ReliefError::NotFinite`] for `cap` outside
/// `(0, MAX_RATIO_LIMIT]`, zero or too many apexes (at most 16) or directions (at most 4096),
/// more than 40 halvings of the local search.
pub fn widest(
    map: &HeightMap,
    kind: ConeKind,
    cap: f32,
    params: WidestParams,
) -> Result<Vec<f64>, ReliefError> {
    widest_in(map, kind, cap, params, None)
}

/// [`widest`] for one layer of a quadrant cone map ([`crate::quad`]): the limit over the sampled
/// directions of the closed quadrant `quadrant` only (both of its axes included when
/// `directions` is a multiple of 4), the widest cone that layer may hold.
///
/// # Errors
///
/// As [`widest`].
pub fn widest_quadrant(
    map: &HeightMap,
    kind: ConeKind,
    cap: f32,
    params: WidestParams,
    quadrant: Quadrant,
) -> Result<Vec<f64>, ReliefError> {
    widest_in(map, kind, cap, params, Some(quadrant))
}

fn widest_in(
    map: &HeightMap,
    kind: ConeKind,
    cap: f32,
    params: WidestParams,
    sector: Option<Quadrant>,
) -> Result<Vec<f64>, ReliefError> {
    crate::check_range(
        "cap",
        f64::from(cap),
        f64::MIN_POSITIVE,
        f64::from(crate::MAX_RATIO_LIMIT),
    )?;
    crate::check_range("apexes", params.apexes as f64, 1.0, 16.0)?;
    crate::check_range("directions", params.directions as f64, 1.0, 4096.0)?;
    crate::check_range("refine", f64::from(params.refine), 0.0, 40.0)?;
    let n = map.size();
    let nf = n as f64;
    let s = params.apexes;
    let cap_texels = f64::from(cap) * nf;
    let dirs: Vec<(f64, f64)> = (0..params.directions)
        .map(|k| {
            let a = TAU * k as f64 / params.directions as f64;
            // cos(π/2) is 6e-17, not 0: the axes are snapped so that both quadrants that share
            // an axis take it (as `check::check_quadrant`).
            let snap = |c: f64| if c.abs() < 1.0e-12 { 0.0 } else { c };
            (snap(libm::cos(a)), snap(libm::sin(a)))
        })
        .filter(|&(ux, uy)| sector.is_none_or(|q| q.contains(ux, uy)))
        .collect();
    // Sample points: spatial positions origin + k/s for k in 0..=nc·s (both ends: in wrap mode
    // the last equals the first a period on; in clamp mode it is the far border strip).
    let (nc, origin) = match map.edge() {
        Edge::Wrap => (n, 0i64),
        Edge::Clamp => (n + 1, -1i64),
    };
    let side = nc * s + 1;
    // The exact limit along one line (texels per unit depth) and the distance of the exit that
    // sets it, searched only as far as it can still come below `below`: farther exits cannot,
    // their value being at least s/S(p).
    let limit = |px: f64, py: f64, ux: f64, uy: f64, below: f64| -> (f64, f64) {
        let reach = below * map.surface_f64(px, py) + 1.0;
        match kind {
            ConeKind::Relaxed => relaxed_limit_at(map, px, py, ux, uy, reach, f64::INFINITY),
            ConeKind::Conservative => {
                conservative_limit_at(map, px, py, ux, uy, reach, f64::INFINITY)
            }
        }
    };
    // Per sample: the smallest limit over the directions, with the exit that sets it.
    let mut limits = vec![Line::NONE; side * side];
    for_rows(&mut limits, side, |row, out| {
        let py = origin as f64 + row as f64 / s as f64;
        for (col, out) in out.iter_mut().enumerate() {
            let px = origin as f64 + col as f64 / s as f64;
            let mut best = Line {
                value: cap_texels,
                ..Line::NONE
            };
            for &(ux, uy) in &dirs {
                let (value, at) = limit(px, py, ux, uy, best.value);
                if value < best.value {
                    best = Line {
                        value,
                        p: (px, py),
                        exit: (px + at * ux, py + at * uy),
                    };
                }
            }
            *out = best;
        }
    });
    // Per cell (spatial [origin + ci, origin + ci + 1] × likewise): its smallest sample, then
    // the local search from there.
    let spacing = 1.0 / s as f64;
    let half_angle = TAU / (2 * params.directions) as f64;
    let mut cells = vec![0.0f64; nc * nc];
    for_rows(&mut cells, nc, |cj, out| {
        for (ci, out) in out.iter_mut().enumerate() {
            let mut start = Line::NONE;
            for y in cj * s..=(cj + 1) * s {
                for x in ci * s..=(ci + 1) * s {
                    if limits[y * side + x].value < start.value {
                        start = limits[y * side + x];
                    }
                }
            }
            *out = if start.value >= cap_texels || params.refine == 0 {
                start.value.min(cap_texels)
            } else {
                let (x0, y0) = (origin as f64 + ci as f64, origin as f64 + cj as f64);
                let length = libm::hypot(start.exit.0 - start.p.0, start.exit.1 - start.p.1);
                descend(
                    start,
                    [x0, x0 + 1.0, y0, y0 + 1.0],
                    (0.5 * spacing, (length * half_angle).max(0.5 * spacing)),
                    params.refine,
                    |p, toward, below| {
                        let (dx, dy) = (toward.0 - p.0, toward.1 - p.1);
                        let len = libm::hypot(dx, dy);
                        let (ux, uy) = (dx / len, dy / len);
                        if len <= 0.0 || !sector.is_none_or(|q| q.contains(ux, uy)) {
                            return None;
                        }
                        let (value, at) = limit(p.0, p.1, ux, uy, below);
                        Some(Line {
                            value,
                            p,
                            exit: (p.0 + at * ux, p.1 + at * uy),
                        })
                    },
                )
            };
        }
    });
    let cell = |x: i64, y: i64| -> f64 {
        let (x, y) = match map.edge() {
            Edge::Wrap => (
                x.rem_euclid(n as i64) as usize,
                y.rem_euclid(n as i64) as usize,
            ),
            Edge::Clamp => ((x - origin) as usize, (y - origin) as usize),
        };
        cells[y * nc + x]
    };
    // Texel (i, j)'s footprint: the four cells of spatial [i − 1, i + 1] × [j − 1, j + 1].
    let mut w = vec![0.0f64; n * n];
    for (k, out) in w.iter_mut().enumerate() {
        let (i, j) = ((k % n) as i64, (k / n) as i64);
        let m = cell(i - 1, j - 1)
            .min(cell(i, j - 1))
            .min(cell(i - 1, j))
            .min(cell(i, j));
        *out = m / nf;
    }
    Ok(w)
}

/// A line from a sample point: its limit and the exit that sets it.
#[derive(Clone, Copy, Debug)]
struct Line {
    value: f64,
    p: (f64, f64),
    exit: (f64, f64),
}

impl Line {
    const NONE: Line = Line {
        value: f64::INFINITY,
        p: (0.0, 0.0),
        exit: (0.0, 0.0),
    };
}

/// Pattern search for a line with a smaller limit, from `start`: each move shifts either the
/// point `p` (inside the closed box `rect`) with the line kept through the exit that limits it,
/// so the line pivots on the feature that sets the value, or that pivot with `p` kept; `f(p,
/// toward, below)` evaluates the line from `p` through `toward` (`None`: a direction the sector
/// excludes). At each step size `(dp, db)` it takes the best of the eight moves that is lower,
/// up to [`MOVES_PER_STEP`] times, then halves both steps, `halvings` times. Returns the
/// smallest value seen. (Moving the point and the direction separately, a search stalls in the
/// valley of the lines through one feature: both have to change together.)
fn descend(
    start: Line,
    rect: [f64; 4],
    step: (f64, f64),
    halvings: u32,
    f: impl Fn((f64, f64), (f64, f64), f64) -> Option<Line>,
) -> f64 {
    let mut line = start;
    let (mut dp, mut db) = step;
    for _ in 0..halvings {
        for _ in 0..MOVES_PER_STEP {
            let mut best: Option<Line> = None;
            let (p, b) = (line.p, line.exit);
            let shifts = [(-1.0, 0.0), (1.0, 0.0), (0.0, -1.0), (0.0, 1.0)];
            for (sx, sy) in shifts {
                let moved = (
                    (p.0 + sx * dp).clamp(rect[0], rect[1]),
                    (p.1 + sy * dp).clamp(rect[2], rect[3]),
                );
                let turned = (b.0 + sx * db, b.1 + sy * db);
                for (from, toward) in [(moved, b), (p, turned)] {
                    if let Some(l) = f(from, toward, line.value)
                        && l.value < best.map_or(line.value, |b| b.value)
                    {
                        best = Some(l);
                    }
                }
            }
            match best {
                Some(l) => line = l,
                None => break,
            }
        }
        dp *= 0.5;
        db *= 0.5;
    }
    line.value
}

/// The worst texel of a [`width`] comparison.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WorstTexel {
    /// Texel column.
    pub i: usize,
    /// Texel row.
    pub j: usize,
    /// Its depth in `[0, 1]`.
    pub depth: f32,
    /// The generated ratio (texture widths per unit depth).
    pub generated: f64,
    /// `W` there.
    pub widest: f64,
}

/// How wide a cone map is against [`widest`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Width {
    /// Mean over texels of `generated / W` (a texel with `W = 0` counts 1; a valid map has every
    /// ratio at most 1).
    pub mean: f64,
    /// The same mean weighted by each texel's depth (texels at depth 0 weigh nothing).
    pub depth_weighted: f64,
    /// The texel with the smallest `generated / W`.
    pub worst: WorstTexel,
}

/// Compares `ratios` (a cone map's plain ratios) with `widest` (from [`widest`] for the same
/// map and cap).
///
/// # Errors
///
/// [`ReliefError::BufferSize`] when either slice is not `size²` long.
pub fn width(map: &HeightMap, ratios: &[f32], widest: &[f64]) -> Result<Width, ReliefError> {
    let n = map.size();
    crate::map::check_len("ratios", n * n, ratios.len())?;
    crate::map::check_len("widest", n * n, widest.len())?;
    let (mut sum, mut wsum, mut weight) = (0.0f64, 0.0f64, 0.0f64);
    let mut worst = WorstTexel {
        i: 0,
        j: 0,
        depth: 0.0,
        generated: 0.0,
        widest: 0.0,
    };
    let mut worst_use = f64::INFINITY;
    for (k, (&r, &w)) in ratios.iter().zip(widest).enumerate() {
        let (i, j) = (k % n, k / n);
        // Above 1 only where the map is invalid at a sampled line.
        let u = if w > 0.0 { f64::from(r) / w } else { 1.0 };
        let depth = map.depth(i as i64, j as i64);
        sum += u;
        wsum += u * f64::from(depth);
        weight += f64::from(depth);
        if u < worst_use {
            worst_use = u;
            worst = WorstTexel {
                i,
                j,
                depth,
                generated: f64::from(r),
                widest: w,
            };
        }
    }
    Ok(Width {
        mean: sum / (n * n) as f64,
        depth_weighted: if weight > 0.0 { wsum / weight } else { 1.0 },
        worst,
    })
}
