//! A box's ray march as data (§2, Fig. 2, Fig. 5): what it reads, its CPU evaluation, and a
//! frame's [`Plan`], from which a GPU twin (`ocean_gpu::WtbMarchPass`) marches the rays itself.
//!
//! Along each wave ray of a box, in increasing a, the march keeps the ray's state (on land or
//! not, where the last land ended, shallow or not, the refraction lag) and gives each grid point
//! it owns a complex amplitude m·e^{iφ} and a land factor:
//!
//! - the land factor is 0 on land and recovers linearly over `recovery` metres behind it
//!   (Fig. 5); every land point of the box's rectangle is 0 whether a ray owns it or not, every
//!   other point 1; the factor is then smoothed across the grid ([`crate::shore`]);
//! - m is Green's law shoaling ([`effects::shoaling`]), capped by the beach
//!   ([`effects::beach_amplitude_cap`] / ΣA), times the side fades along v and u (Fig. 4);
//! - φ is the refraction lag, accumulated from one point of the ray to the next as
//!   k_p·s(depth)·Δa with s from [`effects::ShorteningTable::get`] (0 over land), plus the round-wave phase of
//!   Eq. 10, reduced to [−π, π].
//!
//! The static modulation is then m·e^{iφ}·(smoothed factor) per point; the time-dependent
//! effects (irregular height, Eq. 8; dispersion refraction, Eq. 4) multiply it each frame.

use alloc::vec;
use alloc::vec::Vec;

use ocean_core::layers::GridRect;
use ocean_core::math;
use ocean_core::sincos::sincos;
use ocean_core::{Modulation, WaveSet};

use crate::box_frame::BoxFrame;
use crate::effects::StaticKey;
use crate::effects::{self, Beach, Effects, Refraction};
use crate::error::WtbError;
use crate::frame::FrameStats;
use crate::grid::WaterGrid;
use crate::shore;
use crate::terrain::Terrain;
use ocean_core::parallel::for_rows;

/// What the ray march of one box reads (see the [module documentation](self)).
#[derive(Clone, Debug, PartialEq)]
pub struct MarchBox {
    /// The box's frame at the frame's time.
    pub frame: BoxFrame,
    /// The grid rectangle holding every grid point of the box (non-empty).
    pub rect: GridRect,
    /// Side smoothing width, metres (Fig. 4).
    pub smoothing: f64,
    /// Distance behind land over which the amplitude recovers, metres (Fig. 5).
    pub recovery: f64,
    /// ΣA of the box's trains at full strength, metres (the beach cap's reference).
    pub amplitude: f64,
    /// Wavenumber of the box's largest train: the reference of the depth effects, rad/m.
    pub peak_k: f64,
    /// Depth where shoaling starts: half the peak wavelength, metres.
    pub shallow_depth: f64,
    /// Depth refraction by phase shift.
    pub refraction: bool,
    /// Green's law shoaling.
    pub shoaling: bool,
    /// Round waves (Eq. 10).
    pub round_waves: bool,
    /// The beach's amplitude cap, if any.
    pub beach: Option<Beach>,
    /// Radius of the land factor's smoothing, cells ([`shore::radius`]).
    pub shore_radius: usize,
}

/// A box's handle in a [`Scene`](crate::scene::Scene).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BoxId(pub(crate) u32);

impl BoxId {
    /// The number behind the handle (stable for the box's life).
    pub fn get(self) -> u32 {
        self.0
    }
}

/// What happens at an action point of a ray.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ActionKind {
    /// The ray reaches land: the amplitude is zero from here.
    LandStart,
    /// The ray leaves land: the amplitude recovers from here (Fig. 5).
    LandEnd,
    /// The water becomes shallower than half the peak wavelength: shoaling and refraction start.
    Shallow,
    /// The water becomes deep again.
    Deep,
}

/// A point along a wave ray where the trains' parameters change (Fig. 2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ActionPoint {
    /// The ray.
    pub ray: u32,
    /// Distance along the ray (internal coordinate a), metres.
    pub a: f64,
    /// The grid point where it happens.
    pub index: usize,
    /// What happens.
    pub kind: ActionKind,
}

/// One ray's result: (rectangle index, modulation without the land factor, land factor) per
/// covered point, and its action points.
type MarchedRay = (Vec<(usize, [f64; 2], f32)>, Vec<ActionPoint>);

impl MarchBox {
    /// The refraction integrand's table for the box's peak wavenumber.
    pub fn shortening_table(&self) -> effects::ShorteningTable {
        effects::ShorteningTable::new(self.peak_k)
    }

    pub(crate) fn key(&self) -> StaticKey {
        StaticKey {
            refraction: self.refraction,
            shoaling: self.shoaling,
            round_waves: self.round_waves,
            beach: self.beach,
        }
    }

    /// Marches every wave ray of the box over `grid` and `terrain` (§2, Fig. 2, Fig. 5): the
    /// static modulation m·e^{iφ} of each point of [`MarchBox::rect`] (`None` for an empty
    /// rectangle) and the action points of the rays.
    ///
    /// # Errors
    ///
    /// [`WtbError::SpacingMismatch`] when the frame's spacing is not the grid's.
    pub fn march(
        &self,
        grid: &WaterGrid,
        terrain: &Terrain,
    ) -> Result<(Option<Modulation>, Vec<ActionPoint>), WtbError> {
        let rect = self.rect;
        let frame = &self.frame;
        let mut mu = vec![[0.0f32; 2]; rect.len()];
        let mut actions = Vec::new();
        let traversal = frame.traversal(grid)?;
        let (length, width) = (frame.length(), frame.width());
        let smoothing = self.smoothing;
        let recovery = self.recovery;
        let k_p = self.peak_k;
        let shallow_depth = self.shallow_depth;
        let shortening = self.shortening_table();
        let march = |r: u32| {
            let mut values: Vec<(usize, [f64; 2], f32)> = Vec::new();
            let mut actions: Vec<ActionPoint> = Vec::new();
            let mut on_land = false;
            let mut land_end: Option<f64> = None;
            let mut shallow = false;
            let mut lag = 0.0f64;
            let mut last_a: Option<f64> = None;
            traversal.for_each_cell_in_ray(r, |_, points| {
                for p in points {
                    let (i, j) = (p.i as usize, p.j as usize);
                    let depth = terrain.depth(i, j);
                    let land = terrain.is_land(i, j);
                    // Refraction: the phase lag of the shorter shallow-water wave, integrated along
                    // the ray at fixed frequency (midpoint of the step's two depths' integrands).
                    if self.refraction
                        && let Some(prev) = last_a
                    {
                        let integrand = if land { 0.0 } else { shortening.get(depth) };
                        lag += k_p * integrand * (p.a - prev);
                    }
                    last_a = Some(p.a);
                    if land != on_land {
                        actions.push(ActionPoint {
                            ray: r,
                            a: p.a,
                            index: p.index,
                            kind: if land {
                                ActionKind::LandStart
                            } else {
                                ActionKind::LandEnd
                            },
                        });
                        if !land {
                            land_end = Some(p.a);
                        }
                        on_land = land;
                    }
                    let is_shallow = !land && depth < shallow_depth;
                    if is_shallow != shallow && !land {
                        actions.push(ActionPoint {
                            ray: r,
                            a: p.a,
                            index: p.index,
                            kind: if is_shallow {
                                ActionKind::Shallow
                            } else {
                                ActionKind::Deep
                            },
                        });
                        shallow = is_shallow;
                    }
                    // The land factor: zero on land, recovering behind it (Fig. 5); smoothed across
                    // the grid below (see `shore`).
                    let land_factor = if land {
                        0.0
                    } else {
                        land_end.map_or(1.0, |e| {
                            if recovery > 0.0 {
                                ((p.a - e) / recovery).clamp(0.0, 1.0)
                            } else {
                                1.0
                            }
                        })
                    };
                    let mut m = 1.0;
                    if self.shoaling && !land {
                        m *= effects::shoaling(depth, shallow_depth);
                    }
                    if !land {
                        let cap = effects::beach_amplitude_cap(self.beach.as_ref(), depth);
                        if cap.is_finite() && self.amplitude > 0.0 {
                            m = m.min(cap / self.amplitude);
                        }
                    }
                    let edge_v = p.b.min(width - p.b);
                    let edge_u = p.a.min(length - p.a);
                    m *= effects::side_fade(edge_v, smoothing)
                        * effects::side_fade(edge_u, smoothing);
                    let mut phase = lag;
                    if self.round_waves && width > 0.0 {
                        phase += effects::round_wave_phase(k_p, p.b, width);
                    }
                    let phase = ocean_core::phase::reduce_angle(phase);
                    if let Some(q) = rect.index(i, j) {
                        values.push((
                            q,
                            [m * math::cos(phase), m * math::sin(phase)],
                            land_factor as f32,
                        ));
                    }
                }
            });
            (values, actions)
        };
        // Rays are independent (their state, land recovery and refraction lag, lives along the
        // ray), so they march in parallel; results are applied in ray order, as sequentially.
        let rays: Vec<u32> = traversal.rays().collect();
        #[cfg(feature = "std")]
        let marched: Vec<MarchedRay> = {
            use rayon::prelude::*;
            rays.par_iter().map(|&r| march(r)).collect()
        };
        #[cfg(not(feature = "std"))]
        let marched: Vec<MarchedRay> = rays.iter().map(|&r| march(r)).collect();
        // The land factor of every rectangle point: land is 0 whether a ray covers it or not (a
        // shore just outside the box still ramps the water inside it), open water 1.
        let mut factor = vec![1.0f32; rect.len()];
        let mut land = vec![false; rect.len()];
        if terrain.has_land() {
            for (q, (f, l)) in factor.iter_mut().zip(&mut land).enumerate() {
                let (i, j) = (rect.i0 + q % rect.nx, rect.j0 + q / rect.nx);
                if terrain.is_land(i, j) {
                    (*f, *l) = (0.0, true);
                }
            }
        }
        let mut base = vec![[0.0f64; 2]; rect.len()];
        for (points, ray_actions) in marched {
            for (q, v, f) in points {
                base[q] = v;
                factor[q] = f;
            }
            actions.extend(ray_actions);
        }
        if factor.iter().any(|&f| f < 1.0) {
            shore::smooth(&mut factor, &land, rect.nx, rect.nz, self.shore_radius);
        }
        for ((m, b), f) in mu.iter_mut().zip(&base).zip(&factor) {
            let f = f64::from(*f);
            *m = [(b[0] * f) as f32, (b[1] * f) as f32];
        }
        // Every value is a product of finite factors; the check also records each row's span.
        let mu = if rect.is_empty() {
            None
        } else {
            Some(Modulation::new(rect, mu).map_err(WtbError::Eval)?)
        };
        Ok((mu, actions))
    }

    /// This frame's modulation from the static one `cache`: irregular height (Eq. 8) and
    /// dispersion refraction (Eq. 4) when they run, `None` when neither does.
    ///
    /// # Errors
    ///
    /// [`WtbError::Eval`] if a value is not finite (not expected: every factor is bounded).
    pub fn time_modulation(
        &self,
        grid: &WaterGrid,
        terrain: &Terrain,
        cache: &Modulation,
        effects: &Effects,
        t: f64,
    ) -> Result<Option<Modulation>, WtbError> {
        time_modulation(grid, terrain, &self.frame, self.peak_k, cache, effects, t)
    }
}

/// One visible box of a [`Plan`].
#[derive(Clone, Debug)]
pub struct PlannedBox {
    /// The box.
    pub id: BoxId,
    /// Its trains at this instant (envelope and budget applied), largest first.
    pub waves: WaveSet,
    /// What its march reads.
    pub march: MarchBox,
}

/// A frame without its CPU ray march (see [`crate::scene::Scene::plan`]).
#[derive(Clone, Debug)]
pub struct Plan {
    /// Time, seconds.
    pub t: f64,
    /// The effects the budget let run.
    pub effects: Effects,
    /// The visible boxes with grid points and trains, in the order of the CPU frame's layers.
    pub boxes: Vec<PlannedBox>,
    /// The frame's counters (`rebuilt` is 0: nothing was marched).
    pub stats: FrameStats,
}

/// The time-dependent part of a box's modulation (irregular height, Eq. 8; dispersion
/// refraction, Eq. 4), applied to the cached static one; `None` when neither runs, and the
/// cache is used as it is.
pub(crate) fn time_modulation(
    grid: &WaterGrid,
    terrain: &Terrain,
    frame: &BoxFrame,
    peak_k: f64,
    cache: &Modulation,
    e: &Effects,
    t: f64,
) -> Result<Option<Modulation>, WtbError> {
    let dispersion = e.refraction == Refraction::Dispersion;
    if e.irregular.is_none() && !dispersion {
        return Ok(None);
    }
    let r = cache.rect();
    let mut out = cache.values().to_vec();
    let row = |dj: usize, row: &mut [[f32; 2]]| {
        for (di, v) in row.iter_mut().enumerate() {
            let [re, im] = *v;
            if re == 0.0 && im == 0.0 {
                continue;
            }
            let (i, j) = (r.i0 + di, r.j0 + dj);
            let mut m = 1.0;
            let mut phase = 0.0;
            if let Some(p) = &e.irregular {
                let ab = frame.internal(grid.point(i, j));
                m *= effects::irregular_factor(p, ab.x, ab.y, t);
            }
            if dispersion {
                phase += effects::dispersion_phase(peak_k, terrain.depth(i, j), t);
            }
            let (s, c) = sincos(phase as f32);
            let (c, s) = (m * f64::from(c), m * f64::from(s));
            let (re, im) = (f64::from(re), f64::from(im));
            *v = [(re * c - im * s) as f32, (re * s + im * c) as f32];
        }
    };
    for_rows(&mut out, r.nx, row);
    Ok(Some(Modulation::new(r, out).map_err(WtbError::Eval)?))
}
