//! One prepared instant of a scene ([`Frame`], made by [`crate::scene::Scene::frame`]): the
//! visible boxes' layers, the height field and the counters, which the evaluation, the GPU twin
//! and the height queries ([`crate::continuous`], [`crate::drawn`]) read.

use alloc::vec::Vec;

use glam::{DVec2, Vec3};
use ocean_core::layers::{GridRect, Layer, evaluate_layers};
use ocean_core::{Modulation, TimedWaves, WaveSet};

use crate::budget::Selection;
use crate::error::WtbError;
use crate::grid::WaterGrid;

/// Counters of one frame.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FrameStats {
    /// Boxes alive at the frame's time.
    pub alive: usize,
    /// Of those, culled by the frustum.
    pub culled: usize,
    /// Boxes whose static modulation was recomputed this frame (moved, grown, new terrain).
    pub rebuilt: usize,
    /// Trains evaluated, over all boxes.
    pub trains: usize,
    /// The work chosen by the budget.
    pub selection: Option<Selection>,
    /// The cost model's estimate for it, nanoseconds.
    pub estimated_ns: f64,
    /// Trains of the visible boxes weighted down in the geometry by the scene's
    /// [`TrainFilter`](crate::filter::TrainFilter) (w_p < 1), those left out included.
    pub filtered_trains: usize,
    /// Of those, the trains left out entirely (w_p = 0: shorter than the filter's N_min).
    pub removed_trains: usize,
    /// Σ ((1 − w_p)·k·A)²/2 over the filtered trains of the visible boxes (at their build-up
    /// envelope): the slope variance the geometry leaves out, at most, where every box's
    /// |μ| ≤ 1, for the BRDF's roughness (see [`crate::filter`]).
    pub filtered_slope_variance: f64,
}

/// One box's contribution to a frame.
#[derive(Clone, Debug)]
pub(crate) struct FrameLayer<'a> {
    pub(crate) waves: WaveSet,
    /// `waves` at the frame's time, for the height queries.
    pub(crate) timed: TimedWaves,
    /// This frame's modulation, when time-dependent effects change the cached one.
    pub(crate) mu: Option<Modulation>,
    pub(crate) cache: &'a Modulation,
}

impl FrameLayer<'_> {
    pub(crate) fn modulation(&self) -> &Modulation {
        self.mu.as_ref().unwrap_or(self.cache)
    }

    pub(crate) fn rect(&self) -> GridRect {
        self.cache.rect()
    }

    /// The trains' amplitudes A, metres.
    pub(crate) fn amplitudes(&self) -> impl Iterator<Item = f32> + '_ {
        self.waves.coeffs().iter().map(|c| c.a)
    }
}

/// Where a grid's buffers may differ from the sea at rest, carried between calls of
/// [`Frame::evaluate_incremental`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Coverage {
    rect: Option<GridRect>,
}

impl Coverage {
    /// Nothing is known of the buffers: the next incremental evaluation writes the whole grid.
    pub fn everything(grid: &WaterGrid) -> Self {
        Self {
            rect: Some(GridRect {
                i0: 0,
                j0: 0,
                nx: grid.nx(),
                nz: grid.nz(),
            }),
        }
    }

    /// The rectangle that may differ from rest, if any.
    pub fn rect(&self) -> Option<GridRect> {
        self.rect
    }
}

/// The smallest rectangle holding `a` (if any) and `b`.
#[cfg(feature = "std")]
fn union(a: Option<GridRect>, b: GridRect) -> GridRect {
    let Some(a) = a else { return b };
    let (i0, j0) = (a.i0.min(b.i0), a.j0.min(b.j0));
    let (i1, j1) = (
        (a.i0 + a.nx).max(b.i0 + b.nx),
        (a.j0 + a.nz).max(b.j0 + b.nz),
    );
    GridRect {
        i0,
        j0,
        nx: i1 - i0,
        nz: j1 - j0,
    }
}

/// One prepared instant of a [`Scene`](crate::scene::Scene) (see
/// [`Scene::frame`](crate::scene::Scene::frame)).
#[derive(Clone, Debug)]
pub struct Frame<'a> {
    pub(crate) grid: &'a WaterGrid,
    pub(crate) inv_spacing: f64,
    /// The grid's last point in grid units, (nx − 1, nz − 1).
    pub(crate) last_point: DVec2,
    /// The last cell's first point, (nx − 2, nz − 2).
    pub(crate) last_cell: (u32, u32),
    pub(crate) t: f64,
    pub(crate) layers: Vec<FrameLayer<'a>>,
    pub(crate) height: Option<Vec<f32>>,
    pub(crate) stats: FrameStats,
}

impl Frame<'_> {
    /// The largest horizontal displacement of any point of the surface, metres: Σ over layers of the
    /// modulation's bound times the layer's Σ A, rounded up.
    pub(crate) fn displacement_bound(&self) -> f64 {
        let d: f64 = self
            .layers
            .iter()
            .map(|l| {
                let a: f64 = l.amplitudes().map(|a| f64::from(a).abs()).sum();
                f64::from(l.modulation().magnitude_bound()) * a
            })
            .sum();
        // The kernel's f32 sums of up to a few hundred terms round by well under 10⁻⁴ of
        // their size; a micrometre covers the rest.
        d * (1.0 + 1e-4) + 1e-6
    }

    /// What this frame runs.
    pub fn stats(&self) -> &FrameStats {
        &self.stats
    }

    /// The frame's time, seconds.
    pub fn time(&self) -> f64 {
        self.t
    }

    /// The water grid.
    pub fn grid(&self) -> &WaterGrid {
        self.grid
    }

    /// The additive height field (noise, run-up), one value per grid point, if any effect
    /// produces one.
    pub fn height_field(&self) -> Option<&[f32]> {
        self.height.as_deref()
    }

    /// The visible boxes as `ocean_core` layers: everything [`Frame::evaluate`] sums, for the
    /// GPU twin (`ocean_gpu::LayersPass`) or any other evaluator.
    pub fn layers(&self) -> Vec<Layer<'_>> {
        self.core_layers()
    }

    pub(crate) fn core_layers(&self) -> Vec<Layer<'_>> {
        self.layers
            .iter()
            .map(|l| Layer {
                waves: &l.waves,
                modulation: l.modulation(),
            })
            .collect()
    }

    /// Evaluates every grid point: positions relative to the grid origin and unit normals,
    /// row-major, into the caller's buffers (the paper's frame-independent recomputation from
    /// the rest state).
    ///
    /// # Errors
    ///
    /// [`WtbError::Eval`] for buffers of the wrong length; nothing is written then.
    pub fn evaluate(&self, out_pos: &mut [Vec3], out_nrm: &mut [Vec3]) -> Result<(), WtbError> {
        evaluate_layers(
            self.grid.grid(),
            self.t,
            &self.core_layers(),
            self.height.as_deref(),
            out_pos,
            out_nrm,
        )
        .map_err(WtbError::Eval)
    }

    /// [`Frame::evaluate`] on the current rayon thread pool; bit-identical to it.
    ///
    /// # Errors
    ///
    /// As [`Frame::evaluate`].
    #[cfg(feature = "std")]
    pub fn evaluate_par(&self, out_pos: &mut [Vec3], out_nrm: &mut [Vec3]) -> Result<(), WtbError> {
        ocean_core::evaluate_layers_par(
            self.grid.grid(),
            self.t,
            &self.core_layers(),
            self.height.as_deref(),
            out_pos,
            out_nrm,
        )
        .map_err(WtbError::Eval)
    }

    /// [`Frame::evaluate_par`] for callers that keep their buffers from frame to frame (an
    /// engine's vertex buffers): only the grid rectangle that the visible boxes cover now or
    /// covered at the previous call (to return it to rest) is written, with exactly the values
    /// of a full evaluation; everything else is already at rest in the buffers. A frame in
    /// which no box is visible, after one that had none either, writes nothing.
    ///
    /// `coverage` carries the covered rectangle from call to call: start from
    /// [`Coverage::everything`] (or after a full [`Frame::evaluate`]), and pass the same value
    /// and the same buffers every frame. With a height field (noise, run-up) the whole grid
    /// changes and is written.
    ///
    /// # Errors
    ///
    /// As [`Frame::evaluate`]; `coverage` is unchanged then.
    #[cfg(feature = "std")]
    pub fn evaluate_incremental(
        &self,
        coverage: &mut Coverage,
        out_pos: &mut [Vec3],
        out_nrm: &mut [Vec3],
    ) -> Result<(), WtbError> {
        let now = self
            .layers
            .iter()
            .map(|l| l.rect())
            .fold(None, |acc: Option<GridRect>, r| Some(union(acc, r)));
        let whole = GridRect {
            i0: 0,
            j0: 0,
            nx: self.grid.nx(),
            nz: self.grid.nz(),
        };
        let region = if self.height.is_some() {
            Some(whole)
        } else {
            match (coverage.rect, now) {
                (Some(a), Some(b)) => Some(union(Some(a), b)),
                (a, b) => a.or(b),
            }
        };
        let empty = GridRect {
            i0: 0,
            j0: 0,
            nx: 0,
            nz: 0,
        };
        ocean_core::evaluate_layers_region_par(
            self.grid.grid(),
            self.t,
            &self.core_layers(),
            self.height.as_deref(),
            region.unwrap_or(empty),
            out_pos,
            out_nrm,
        )
        .map_err(WtbError::Eval)?;
        coverage.rect = if self.height.is_some() {
            Some(whole)
        } else {
            now
        };
        Ok(())
    }
}
