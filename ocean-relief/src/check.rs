//! The validity check: does any ray through a cone's axis cross the surface twice inside the
//! cone it steps with?
//!
//! For an apex `p`, a direction `u` and a ray that passes the axis at depth `z₀ = S(p) − h`
//! (`h` above the surface), [`crate::bound`]'s Lemma 1 (with the exit level kept, as in the
//! cone module's height argument) reduces "no such ray, of any slope, enters and leaves the
//! solid inside the cone" to the exact directional limit
//!
//! `c*(p, u, h) = inf { s/(S(p) − L(s)) : g(s) > L(s), L(s) < S(p) }`, `L(s) = max(M(s), S(p) − h)`
//!
//! (`g` the surface along `u`, `M` its running minimum), which [`relaxed_limit`] computes exactly
//! on the bilinear pieces of the line ([`crate::line`]); `h = ∞` is the plain cone. A
//! conservative cone must contain no solid at the depths the ray can reach:
//! `inf { s/(S(p) − max(g(s), S(p) − h)) : g(s) < S(p) }` ([`conservative_limit`]).
//!
//! [`check`] samples apexes on a sub-grid of every cell (texel centres included, and the
//! clamp-mode border strips), reads the cone map exactly as the tracer does (bilinear, `f32`, at
//! the cone map's own resolution, so coarse mip levels are checked against the full-resolution
//! surface) and compares, along many directions and for several heights `h`, the cone the tracer
//! would use, `max(c, min(D/h, E))`, with the limit. [`check_quadrant`] does the same for one
//! layer of a quadrant cone map ([`crate::quad`]) over the sampled directions of its quadrant.

use alloc::vec;
use alloc::vec::Vec;
use core::f64::consts::TAU;

use crate::bound::ConeKind;
use crate::line::{Piece, walk};
use crate::map::{Edge, HeightMap};
use crate::quadrant::Quadrant;
use crate::sample::Taps;
use crate::{ReliefError, for_rows};

/// Relative tolerance of the comparison: the tracer's `f32` blend of four values may exceed the
/// largest by a few ulps.
pub const TOLERANCE: f64 = 1.0e-6;

/// Heights above the surface (depth units) at which [`check`] tests the height-dependent cone,
/// besides the plain cone (`h = ∞`).
pub const HEIGHTS: [f64; 5] = [0.5, 0.125, 0.03125, 0.0078125, 0.001953125];

/// How densely to sample.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CheckParams {
    /// Apexes per cell along each axis (positions `k/apexes`, so texel centres are included).
    pub apexes: usize,
    /// Directions per apex, evenly spaced from angle 0 (axes and diagonals included when a
    /// multiple of 8).
    pub directions: usize,
    /// Also measure how much of the widest valid plain cone the map uses
    /// ([`CheckReport::mean_use`]); this walks every line out to the map's largest ratio.
    pub usage: bool,
}

impl Default for CheckParams {
    fn default() -> Self {
        Self {
            apexes: 2,
            directions: 64,
            usage: false,
        }
    }
}

/// One ray that crosses the surface twice inside the cone it stepped with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Violation {
    /// Apex, texel-centre coordinates.
    pub x: f64,
    /// Apex, texel-centre coordinates.
    pub y: f64,
    /// Direction angle (rad).
    pub angle: f64,
    /// Height of the ray above the surface at the apex (`∞`: any).
    pub height: f64,
    /// The ratio the tracer uses there (texels per unit depth).
    pub stored: f64,
    /// The exact limit along that direction (texels per unit depth).
    pub limit: f64,
}

/// What [`check`] saw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CheckReport {
    /// Apex × direction × height lines examined.
    pub lines: u64,
    /// Lines whose cone is wider than the limit.
    pub violations: u64,
    /// The violation with the largest `stored/limit`, if any.
    pub worst: Option<Violation>,
    /// With [`CheckParams::usage`], the mean over apexes of `stored / min(limit over directions,
    /// cap)` for the plain cone: the share of the sampled widest valid cone the map uses (1 = as
    /// wide as allowed); NaN without.
    pub mean_use: f64,
}

/// A cone map as the check reads it: plain ratios, clearances and near caps (texture units), at
/// resolution `size`. Clearance and near cap may be all zero (the book's one-channel map).
#[derive(Clone, Copy, Debug)]
pub struct Channels<'a> {
    /// Side of the (possibly coarse) cone map.
    pub size: usize,
    /// Plain ratios `c`.
    pub ratios: &'a [f32],
    /// Clearances `D`.
    pub clearance: &'a [f32],
    /// Near caps `E`.
    pub near_cap: &'a [f32],
}

impl<'a> Channels<'a> {
    /// The channels of a full-resolution cone map.
    pub fn of(cones: &'a crate::ConeMap) -> Self {
        Self {
            size: cones.size(),
            ratios: cones.ratios(),
            clearance: cones.clearance(),
            near_cap: cones.near_cap(),
        }
    }
}

/// The first point of the piece where `g` is at or below `level`, if any.
fn dip_below(pc: &Piece, level: f64) -> Option<f64> {
    let below = |s: f64| pc.at(s) <= level;
    if below(pc.s0) {
        return Some(pc.s0);
    }
    // g's minimum on the piece: an end or, when convex, the vertex; g decreases up to it.
    let mut low = pc.s1;
    if pc.k2 > 0.0 {
        let v = pc.s0 - pc.k1 / (2.0 * pc.k2);
        if v > pc.s0 && v < pc.s1 && pc.at(v) < pc.at(low) {
            low = v;
        }
    }
    if !below(low) {
        return None;
    }
    let (mut lo, mut hi) = (pc.s0, low);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if below(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(hi)
}

/// Where `g` first rises above `level` after `from` on the piece, if it does.
fn rise_above(pc: &Piece, from: f64, level: f64) -> Option<f64> {
    let g = |s: f64| pc.at(s);
    // g's maximum on [from, s1]: at an end or, when concave, at the vertex.
    let mut end = pc.s1;
    if pc.k2 < 0.0 {
        let v = pc.s0 - pc.k1 / (2.0 * pc.k2);
        if v > from && v < pc.s1 && g(v) > level {
            end = v;
        }
    }
    if g(end) <= level {
        return None;
    }
    if g(from) > level {
        return Some(from);
    }
    let (mut lo, mut hi) = (from, end);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if g(mid) > level {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(lo)
}

/// The exact directional relaxed limit for rays `height` above the surface (`∞`: any) at
/// texel-centre point `(px, py)` along unit `(ux, uy)`, searched up to distance `reach` texels;
/// `+∞` if nothing limits the cone within it. Texels per unit depth.
pub fn relaxed_limit(
    map: &HeightMap,
    px: f64,
    py: f64,
    ux: f64,
    uy: f64,
    reach: f64,
    height: f64,
) -> f64 {
    relaxed_limit_at(map, px, py, ux, uy, reach, height).0
}

/// [`relaxed_limit`] and the distance along the line of the exit that sets it (`∞` with it).
pub(crate) fn relaxed_limit_at(
    map: &HeightMap,
    px: f64,
    py: f64,
    ux: f64,
    uy: f64,
    reach: f64,
    height: f64,
) -> (f64, f64) {
    let sp = map.surface_f64(px, py);
    let floor_level = sp - height;
    let mut m = sp;
    let mut best = (f64::INFINITY, f64::INFINITY);
    // Whether g has been at or below the floor level (an upward crossing of it is then an exit),
    // and whether that crossing has been found.
    let mut dipped = false;
    let mut crossed = false;
    const EPS: f64 = 1.0e-12;
    walk(map, px, py, ux, uy, reach, |pc| {
        // Exits at the running minimum (levels above the floor level).
        let cand = |s: f64, level: f64, best: &mut (f64, f64)| {
            if level < sp - EPS && level >= floor_level && s / (sp - level) < best.0 {
                *best = (s / (sp - level), s);
            }
        };
        if pc.k0 > m + EPS {
            cand(pc.s0, m, &mut best);
        } else if pc.k1 > EPS || (pc.k1 >= -EPS && pc.k2 > 0.0) {
            cand(pc.s0, m.min(pc.k0), &mut best);
        }
        m = m.min(pc.k0);
        let len = pc.s1 - pc.s0;
        if pc.k2 > 0.0 {
            let tv = -pc.k1 / (2.0 * pc.k2);
            if tv > 0.0 && tv < len {
                let gv = pc.at(pc.s0 + tv);
                if gv < m {
                    m = gv;
                    cand(pc.s0 + tv, gv, &mut best);
                }
            }
        }
        // Exits at the floor level: the first upward crossing of it after g has come down to it
        // (every such exit has the same denominator `height`, so the first is the smallest).
        if floor_level > f64::NEG_INFINITY && !crossed {
            let mut from = Some(pc.s0);
            if !dipped {
                from = dip_below(pc, floor_level);
                dipped = from.is_some();
            }
            if let Some(f) = from
                && let Some(s) = rise_above(pc, f, floor_level)
            {
                if s / height < best.0 {
                    best = (s / height, s);
                }
                crossed = true;
            }
        }
        m = m.min(pc.at(pc.s1));
        // Farther points cannot beat `best`: s/(S(p) − L) ≥ s/S(p).
        pc.s1 < best.0 * sp
    });
    best
}

/// The exact directional conservative limit for rays `height` above the surface (`∞`: any):
/// `inf s/(S(p) − max(g(s), S(p) − h))` over points higher than the apex, searched up to `reach`
/// texels.
pub fn conservative_limit(
    map: &HeightMap,
    px: f64,
    py: f64,
    ux: f64,
    uy: f64,
    reach: f64,
    height: f64,
) -> f64 {
    conservative_limit_at(map, px, py, ux, uy, reach, height).0
}

/// [`conservative_limit`] and the distance along the line of the point that sets it (`∞` with
/// it).
pub(crate) fn conservative_limit_at(
    map: &HeightMap,
    px: f64,
    py: f64,
    ux: f64,
    uy: f64,
    reach: f64,
    height: f64,
) -> (f64, f64) {
    let sp = map.surface_f64(px, py);
    let floor_level = sp - height;
    let mut best = (f64::INFINITY, f64::INFINITY);
    walk(map, px, py, ux, uy, reach, |pc| {
        let mut try_at = |s: f64| {
            let g = pc.at(s).max(floor_level);
            if g < sp {
                let v = if s > 0.0 { s / (sp - g) } else { 0.0 };
                if v < best.0 {
                    best = (v, s);
                }
            }
        };
        try_at(pc.s0);
        try_at(pc.s1);
        let len = pc.s1 - pc.s0;
        // Stationary points of s/(S(p) − g(s)): k2·τ² + 2·k2·s0·τ + (S(p) − k0 + s0·k1) = 0,
        // and where g crosses the floor level (the function switches to s/h there).
        let roots = |a: f64, b: f64, c: f64, try_at: &mut dyn FnMut(f64)| {
            if a != 0.0 {
                let disc = b * b - 4.0 * a * c;
                if disc >= 0.0 {
                    let r = libm::sqrt(disc);
                    for t in [(-b - r) / (2.0 * a), (-b + r) / (2.0 * a)] {
                        if t > 0.0 && t < len {
                            try_at(pc.s0 + t);
                        }
                    }
                }
            } else if b != 0.0 {
                let t = -c / b;
                if t > 0.0 && t < len {
                    try_at(pc.s0 + t);
                }
            }
        };
        roots(
            pc.k2,
            2.0 * pc.k2 * pc.s0,
            sp - pc.k0 + pc.s0 * pc.k1,
            &mut try_at,
        );
        if floor_level > f64::NEG_INFINITY {
            roots(pc.k2, pc.k1, pc.k0 - floor_level, &mut try_at);
        }
        pc.s1 < best.0 * sp
    });
    best
}

/// Checks a cone map (see the module documentation) against the exact limits of `map`.
///
/// # Errors
///
/// [`ReliefError::BufferSize`] if a channel is not `size²` long; [`ReliefError::Mismatch`] if
/// `size` does not divide the map's side; [`ReliefError::OutOfRange`] for zero or too many
/// apexes or directions.
pub fn check(
    map: &HeightMap,
    cones: Channels<'_>,
    kind: ConeKind,
    params: CheckParams,
) -> Result<CheckReport, ReliefError> {
    check_in(map, cones, kind, params, None)
}

/// [`check`] for one layer of a quadrant cone map ([`crate::quad`]): the cones serve only the
/// rays whose horizontal direction lies in the closed quadrant `quadrant`, so only the sampled
/// directions in it are checked (both of its axes included when `directions` is a multiple of
/// 4: `directions/4 + 1` of them).
///
/// # Errors
///
/// As [`check`].
pub fn check_quadrant(
    map: &HeightMap,
    cones: Channels<'_>,
    kind: ConeKind,
    params: CheckParams,
    quadrant: Quadrant,
) -> Result<CheckReport, ReliefError> {
    check_in(map, cones, kind, params, Some(quadrant))
}

fn check_in(
    map: &HeightMap,
    cones: Channels<'_>,
    kind: ConeKind,
    params: CheckParams,
    sector: Option<Quadrant>,
) -> Result<CheckReport, ReliefError> {
    let size = cones.size;
    crate::map::check_len("ratios", size * size, cones.ratios.len())?;
    crate::map::check_len("clearance", size * size, cones.clearance.len())?;
    crate::map::check_len("near_cap", size * size, cones.near_cap.len())?;
    let n = map.size();
    if size == 0 || !n.is_multiple_of(size) {
        return Err(ReliefError::Mismatch("cones"));
    }
    crate::check_range("apexes", params.apexes as f64, 1.0, 64.0)?;
    crate::check_range("directions", params.directions as f64, 1.0, 65536.0)?;
    let (nc, origin) = match map.edge() {
        Edge::Wrap => (n, 0i64),
        Edge::Clamp => (n + 1, -1i64),
    };
    let nf = n as f64;
    let cap = cones
        .ratios
        .iter()
        .fold(0.0f64, |a, &r| a.max(f64::from(r)))
        * nf;
    let dirs: Vec<(f64, f64, f64)> = (0..params.directions)
        .map(|k| {
            let a = TAU * k as f64 / params.directions as f64;
            (a, libm::cos(a), libm::sin(a))
        })
        .filter_map(|(a, ux, uy)| match sector {
            None => Some((a, ux, uy)),
            Some(q) => {
                // cos(π/2) is 6e-17, not 0: the axes are snapped so that both quadrants that
                // share an axis check it.
                let snap = |c: f64| if c.abs() < 1.0e-12 { 0.0 } else { c };
                let (ux, uy) = (snap(ux), snap(uy));
                q.contains(ux, uy).then_some((a, ux, uy))
            }
        })
        .collect();
    let s = params.apexes;
    // Per cell row: (lines, violations, worst, sum of use, apexes).
    let mut rows = vec![(0u64, 0u64, None::<Violation>, 0.0f64, 0u64); nc];
    for_rows(&mut rows, 1, |row, out| {
        let acc = &mut out[0];
        let cj = origin + row as i64;
        for ci in origin..origin + nc as i64 {
            for b in 0..s {
                for a in 0..s {
                    let px = ci as f64 + a as f64 / s as f64;
                    let py = cj as f64 + b as f64 / s as f64;
                    let (u, v) = ((px + 0.5) / nf, (py + 0.5) / nf);
                    let taps = Taps::new(size, map.edge(), u as f32, v as f32);
                    let c = f64::from(taps.blend(|k| cones.ratios[k])) * nf;
                    let d = f64::from(taps.blend(|k| cones.clearance[k])) * nf;
                    let e = f64::from(taps.blend(|k| cones.near_cap[k])) * nf;
                    let sp = map.surface_f64(px, py);
                    let mut limit_min = f64::INFINITY;
                    for &(angle, ux, uy) in &dirs {
                        for height in core::iter::once(f64::INFINITY).chain(HEIGHTS) {
                            // The cone the tracer uses for a ray `height` above the surface.
                            let stored = if height.is_finite() {
                                c.max((d / height).min(e))
                            } else {
                                c
                            };
                            // Search as far as that cone reaches (its radius at the ray's depth is
                            // stored·h); for the plain cone, as far as the cap for the usage
                            // statistic.
                            let reach = if height.is_finite() {
                                stored * sp.min(height) + 1.0
                            } else if params.usage {
                                stored.max(cap) * sp + 1.0
                            } else {
                                stored * sp + 1.0
                            };
                            let limit = match kind {
                                ConeKind::Relaxed => {
                                    relaxed_limit(map, px, py, ux, uy, reach, height)
                                }
                                ConeKind::Conservative => {
                                    conservative_limit(map, px, py, ux, uy, reach, height)
                                }
                            };
                            if !height.is_finite() {
                                limit_min = limit_min.min(limit);
                            }
                            acc.0 += 1;
                            if stored > limit * (1.0 + TOLERANCE) + 1.0e-9 {
                                acc.1 += 1;
                                let v = Violation {
                                    x: px,
                                    y: py,
                                    angle,
                                    height,
                                    stored,
                                    limit,
                                };
                                if acc
                                    .2
                                    .is_none_or(|w: Violation| stored / limit > w.stored / w.limit)
                                {
                                    acc.2 = Some(v);
                                }
                            }
                        }
                    }
                    let allowed = limit_min.min(cap);
                    if allowed > 0.0 && sp > 0.0 {
                        acc.3 += (c / allowed).min(1.0e3);
                        acc.4 += 1;
                    }
                }
            }
        }
    });
    let mut report = CheckReport {
        lines: 0,
        violations: 0,
        worst: None,
        mean_use: 0.0,
    };
    let (mut use_sum, mut use_n) = (0.0, 0u64);
    for (lines, violations, worst, u, k) in rows {
        report.lines += lines;
        report.violations += violations;
        if let Some(w) = worst
            && report
                .worst
                .is_none_or(|r| w.stored / w.limit > r.stored / r.limit)
        {
            report.worst = Some(w);
        }
        use_sum += u;
        use_n += k;
    }
    report.mean_use = if !params.usage {
        f64::NAN
    } else if use_n > 0 {
        use_sum / use_n as f64
    } else {
        1.0
    };
    Ok(report)
}
