//! The brute-force oracle: [`crate::bound`]'s minimum by visiting every (apex cell, candidate
//! cell) pair, `Θ(N⁴)`. The fast generator must return the same bits.
//!
//! In wrap mode the candidates are the copies of every cell at tile offsets
//! `|a|, |b| ≤ ⌈max_ratio⌉`: a copy at offset `a` lies at least `(|a| − 1)·N` texels away, so
//! its value is at least that and cannot go below the cap `max_ratio·N` beyond that range.

use crate::ConeParams;
use crate::bound::{Grid, candidate};
use crate::map::Edge;
use crate::quadrant::Quadrant;
use crate::search::{CHANNELS, NEAR_DISTANCE};

/// `w(q)`, `D(q)` and `E(q)` of apex cell `(qi, qj)` (spatial position), for every direction
/// or one quadrant's ([`crate::quad`]), by visiting every candidate.
pub(crate) fn cell_cone(
    grid: &Grid<'_>,
    qi: i64,
    qj: i64,
    sector: Option<Quadrant>,
    params: ConeParams,
) -> [f64; CHANNELS] {
    let kind = params.kind;
    let cap = f64::from(params.max_ratio) * grid.n as f64;
    let q = grid.apex(qi, qj);
    let q = match sector {
        Some(s) => q.within(s),
        None => q,
    };
    let mut best = [cap; CHANNELS];
    let reach = match grid.edge {
        Edge::Wrap => libm::ceil(f64::from(params.max_ratio)) as i64,
        Edge::Clamp => 0,
    };
    let n = grid.n as i64;
    for b in -reach..=reach {
        for a in -reach..=reach {
            for y in 0..grid.nc {
                for x in 0..grid.nc {
                    let (ci, cj) = (
                        grid.origin + x as i64 + a * n,
                        grid.origin + y as i64 + b * n,
                    );
                    if let Some(c) = candidate(
                        &q,
                        &grid.cells[y * grid.nc + x],
                        ci,
                        cj,
                        kind,
                        grid.lip_global,
                    ) {
                        crate::refine::refine(
                            grid,
                            &q,
                            &grid.cells[y * grid.nc + x],
                            ci,
                            cj,
                            kind,
                            c.value(),
                            params.parts,
                            &mut best[0],
                        );
                        if c.dist < NEAR_DISTANCE {
                            best[2] = best[2].min(c.value());
                        } else {
                            best[1] = best[1].min(c.dist);
                        }
                    }
                }
            }
        }
    }
    // As `search.rs`: with the plain cone at the cap, the clearance and near cap are the cap.
    if best[0] >= cap {
        best[1] = cap;
        best[2] = cap;
    }
    best
}
