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
//! centres, cell edges and the clamp-mode border strips included) and a fan of directions, so
//! it can only overestimate `W`: a generated cone above it is invalid at a sampled line
//! ([`crate::check`] finds it), one below it is narrower than allowed by at least that much.
//!
//! [`width`] compares a cone map with it: the mean of `generated / W`, the mean weighted by the
//! texel's depth (a cone's reach from the top of the relief is its ratio times that depth, so
//! a narrow cone on a high texel costs little) and the worst texel.

use alloc::vec;
use alloc::vec::Vec;
use core::f64::consts::TAU;

use crate::bound::ConeKind;
use crate::check::{conservative_limit, relaxed_limit};
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
}

impl Default for WidestParams {
    fn default() -> Self {
        Self {
            apexes: 2,
            directions: 64,
        }
    }
}

/// `W` per texel, row-major, in texture widths per unit depth (the cone map's unit), capped at
/// `cap` ([`crate::ConeParams::max_ratio`]): see the module documentation.
///
/// # Errors
///
/// [`ReliefError::OutOfRange`] / [`ReliefError::NotFinite`] for `cap` outside
/// `(0, MAX_RATIO_LIMIT]`, zero or too many apexes (at most 16) or directions (at most 4096).
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
    let mut limits = vec![0.0f64; side * side];
    for_rows(&mut limits, side, |row, out| {
        let py = origin as f64 + row as f64 / s as f64;
        for (col, out) in out.iter_mut().enumerate() {
            let px = origin as f64 + col as f64 / s as f64;
            let sp = map.surface_f64(px, py);
            let mut best = cap_texels;
            for &(ux, uy) in &dirs {
                // Farther exits cannot beat `best`: their value is at least s/S(p).
                let reach = best * sp + 1.0;
                let limit = match kind {
                    ConeKind::Relaxed => relaxed_limit(map, px, py, ux, uy, reach, f64::INFINITY),
                    ConeKind::Conservative => {
                        conservative_limit(map, px, py, ux, uy, reach, f64::INFINITY)
                    }
                };
                best = best.min(limit);
            }
            *out = best;
        }
    });
    // Texel (i, j)'s footprint: spatial [i − 1, i + 1] × [j − 1, j + 1], sample indices
    // (i − 1 − origin)·s ..= (i + 1 − origin)·s, wrapped in wrap mode.
    let at = |x: i64, y: i64| -> f64 {
        let (x, y) = match map.edge() {
            Edge::Wrap => {
                let p = (n * s) as i64;
                (x.rem_euclid(p) as usize, y.rem_euclid(p) as usize)
            }
            Edge::Clamp => (x as usize, y as usize),
        };
        limits[y * side + x]
    };
    let mut w = vec![0.0f64; n * n];
    let si = s as i64;
    for (k, out) in w.iter_mut().enumerate() {
        let (i, j) = ((k % n) as i64, (k / n) as i64);
        let mut m = f64::INFINITY;
        for y in (j - 1 - origin) * si..=(j + 1 - origin) * si {
            for x in (i - 1 - origin) * si..=(i + 1 - origin) * si {
                m = m.min(at(x, y));
            }
        }
        *out = m / nf;
    }
    Ok(w)
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
