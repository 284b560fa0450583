//! The wave model of §2: boxes over a water grid and terrain, evaluated frame by frame.
//!
//! A [`Scene`] holds the water grid, the terrain and the wave train boxes. [`Scene::frame`]
//! prepares one instant, in the paper's layered order (§2.3):
//!
//! 1. **culling**: a box is skipped when its oriented bounding box, extruded by the summed
//!    maximum heights of every box overlapping it (§2.2), is outside the view frustum;
//! 2. **basic trains**: each visible box contributes its trains, the largest first when a
//!    [`Budget`] limits them;
//! 3. **effects**: the per-point factors and phases of [`crate::effects`];
//! 4. **noise** last.
//!
//! Each box's static modulation is computed by marching its wave rays in order (§2, Fig. 2):
//! along a ray the amplitude drops to zero on land, recovers linearly over a distance behind it
//! (Fig. 5), grows by Green's law as the water shoals, is capped on beaches, and the phase lag
//! of depth refraction accumulates. The ray events (land starts and ends, depth bands) are kept
//! as action points. The land factor (zero on land, the recovery behind it) is then smoothed
//! across the grid over a width in metres proportional to the box's amplitude
//! ([`crate::shore`]), so that neither a cliff nor the side of a shadow folds the displaced
//! surface, whatever the grid spacing. The result is cached until the box moves, grows, or the terrain or the
//! static effects change, so a still box costs nothing per frame beyond evaluating its trains.
//!
//! The [`Frame`] then evaluates the grid with `ocean_core::evaluate_layers` (every box a layer
//! with its complex amplitude m·e^{iφ}) and answers height queries on the same surface.

use alloc::vec;
use alloc::vec::Vec;

use glam::DVec2;
use ocean_core::frustum::{Containment, Frustum};
use ocean_core::layers::GridRect;
use ocean_core::{Modulation, Wave, WaveDesc, WaveSet};

use crate::box_frame::BoxFrame;
use crate::budget::{BoxLoad, Budget, CostModel, Selection, select, train_order};
use crate::effects::{
    self, Effects, MAX_EFFECT_DEPTH, MAX_EFFECT_HEIGHT, MAX_EFFECT_SPEED, MAX_EFFECT_WAVENUMBER,
    StaticKey,
};
use crate::error::WtbError;
use crate::filter::TrainFilter;
use crate::frame::FrameLayer;
pub use crate::frame::{Coverage, Frame, FrameStats};
use crate::grid::{WaterGrid, ceil_i64, check_range, floor_i64};
use crate::march::{self, MarchBox, Plan, PlannedBox};
pub use crate::march::{ActionKind, ActionPoint, BoxId};
use crate::shore;
use crate::terrain::Terrain;
use crate::wind::{TrainSource, Wind};

/// How a box is made: its wind (placement, size, lifecycle, trains) and its local parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct BoxSpec {
    /// The wind raising the box (§2).
    pub wind: Wind,
    /// Where the trains come from: the wind's seeded mapping or explicit trains.
    pub trains: TrainSource,
    /// Width of the smoothing area along the box's edges, metres (Fig. 4).
    pub smoothing: f64,
    /// Distance behind land over which the amplitude recovers to full, metres (Fig. 5);
    /// `None` for two peak wavelengths.
    pub recovery: Option<f64>,
}

/// A box's static modulation over its grid rectangle.
#[derive(Clone, Debug)]
struct Cache {
    frame: BoxFrame,
    terrain_version: u64,
    key: StaticKey,
    /// `None` when the box covers no grid point.
    mu: Option<Modulation>,
    actions: Vec<ActionPoint>,
}

#[derive(Clone, Debug)]
struct Slot {
    id: BoxId,
    spec: BoxSpec,
    trains: Vec<WaveDesc>,
    /// Σ A of the trains.
    amplitude: f64,
    /// Wavenumber and length of the largest train: the box's reference for depth effects.
    peak_k: f64,
    peak_wavelength: f64,
    cache: Option<Cache>,
}

/// Water grid, terrain and wave train boxes (see the module documentation).
#[derive(Clone, Debug)]
pub struct Scene {
    grid: WaterGrid,
    terrain: Terrain,
    terrain_version: u64,
    boxes: Vec<Slot>,
    next_id: u32,
    effects: Effects,
    budget: Budget,
    cost: CostModel,
    filter: Option<TrainFilter>,
    /// Counts the changes of the description (see [`Scene::revision`]).
    revision: u64,
}

/// Largest number of boxes in a scene.
pub const MAX_BOXES: usize = 4096;

impl Scene {
    /// A scene on `grid` over `terrain` (which must be sampled on the same grid), with the
    /// default effects and no budget limit.
    ///
    /// # Errors
    ///
    /// [`WtbError::TerrainSize`] when the terrain belongs to another grid.
    pub fn new(grid: WaterGrid, terrain: Terrain) -> Result<Self, WtbError> {
        check_terrain(&grid, &terrain)?;
        Ok(Self {
            grid,
            terrain,
            terrain_version: 0,
            boxes: Vec::new(),
            next_id: 0,
            effects: Effects::default(),
            budget: Budget::Unlimited,
            cost: CostModel::default(),
            filter: Some(TrainFilter::DEFAULT),
            revision: 0,
        })
    }

    /// A number that changes whenever the scene's description does (terrain, effects, budget,
    /// cost model, boxes added, replaced or removed), and only then: a frame prepared at the
    /// same time and view, under the same revision, draws the same grid. Callers that keep
    /// what they drew (a C engine's last evaluation) compare it to know whether that is still
    /// the scene's frame.
    pub fn revision(&self) -> u64 {
        self.revision
    }

    /// The water grid.
    pub fn grid(&self) -> &WaterGrid {
        &self.grid
    }

    /// The terrain.
    pub fn terrain(&self) -> &Terrain {
        &self.terrain
    }

    /// Replaces the terrain; every box's static modulation is recomputed at the next frame.
    ///
    /// # Errors
    ///
    /// [`WtbError::TerrainSize`] when the terrain belongs to another grid.
    pub fn set_terrain(&mut self, terrain: Terrain) -> Result<(), WtbError> {
        check_terrain(&self.grid, &terrain)?;
        self.terrain = terrain;
        self.terrain_version += 1;
        self.revision += 1;
        Ok(())
    }

    /// The effects enabled (the budget may run fewer).
    pub fn effects(&self) -> &Effects {
        &self.effects
    }

    /// Enables and parameterises the effects.
    ///
    /// # Errors
    ///
    /// [`WtbError::NotFinite`] or [`WtbError::OutOfRange`] for a bad parameter.
    pub fn set_effects(&mut self, effects: Effects) -> Result<(), WtbError> {
        check_effects(&effects)?;
        self.effects = effects;
        self.revision += 1;
        Ok(())
    }

    /// Sets the frame budget (§2.3).
    ///
    /// # Errors
    ///
    /// [`WtbError::OutOfRange`] for a negative or non-finite time.
    pub fn set_budget(&mut self, budget: Budget) -> Result<(), WtbError> {
        if let Budget::Seconds(s) = budget
            && !(s.is_finite() && s >= 0.0)
        {
            return Err(WtbError::OutOfRange {
                name: "budget seconds",
                value: s,
                min: 0.0,
                max: f64::MAX,
            });
        }
        if let Budget::Explicit(sel) = budget {
            check_effects(&sel.effects)?;
        }
        self.budget = budget;
        self.revision += 1;
        Ok(())
    }

    /// The per-train geometry filter (see [`crate::filter`]); [`TrainFilter::DEFAULT`] unless
    /// set.
    pub fn train_filter(&self) -> Option<TrainFilter> {
        self.filter
    }

    /// Sets the per-train geometry filter, or `None` to keep every train whole whatever its
    /// length in grid cells (a renderer that filters the trains itself on its own footprints).
    pub fn set_train_filter(&mut self, filter: Option<TrainFilter>) {
        self.filter = filter;
        self.revision += 1;
    }

    /// The cost model the budget uses; refine it with measured frame times.
    pub fn cost_model_mut(&mut self) -> &mut CostModel {
        self.revision += 1;
        &mut self.cost
    }

    /// Adds a box.
    ///
    /// # Errors
    ///
    /// Any error of the wind, its trains or the smoothing and recovery distances;
    /// [`WtbError::OutsideGrid`] for a box that cannot touch the grid even at its full fetch;
    /// too many boxes.
    pub fn add_box(&mut self, spec: BoxSpec) -> Result<BoxId, WtbError> {
        if self.boxes.len() >= MAX_BOXES {
            return Err(WtbError::OutOfRange {
                name: "box count",
                value: (self.boxes.len() + 1) as f64,
                min: 0.0,
                max: MAX_BOXES as f64,
            });
        }
        let id = BoxId(self.next_id);
        let slot = self.make_slot(id, spec)?;
        self.next_id += 1;
        self.boxes.push(slot);
        self.revision += 1;
        Ok(id)
    }

    /// Replaces a box's description: moving its origin or turning it (a boat's wake, the
    /// paper's future work) recomputes its action points at the next frame.
    ///
    /// # Errors
    ///
    /// [`WtbError::UnknownBox`] for a removed or foreign id; as [`Scene::add_box`].
    pub fn update_box(&mut self, id: BoxId, spec: BoxSpec) -> Result<(), WtbError> {
        let k = self.position(id)?;
        self.boxes[k] = self.make_slot(id, spec)?;
        self.revision += 1;
        Ok(())
    }

    /// Removes a box.
    ///
    /// # Errors
    ///
    /// [`WtbError::UnknownBox`] for a removed or foreign id.
    pub fn remove_box(&mut self, id: BoxId) -> Result<(), WtbError> {
        let k = self.position(id)?;
        self.boxes.remove(k);
        self.revision += 1;
        Ok(())
    }

    /// The boxes, in creation order.
    pub fn box_ids(&self) -> impl Iterator<Item = BoxId> + '_ {
        self.boxes.iter().map(|s| s.id)
    }

    /// The action points of a box as last computed (empty before its first frame).
    ///
    /// # Errors
    ///
    /// [`WtbError::UnknownBox`] for a removed or foreign id.
    pub fn action_points(&self, id: BoxId) -> Result<&[ActionPoint], WtbError> {
        let k = self.position(id)?;
        Ok(self.boxes[k].cache.as_ref().map_or(&[][..], |c| &c.actions))
    }

    fn position(&self, id: BoxId) -> Result<usize, WtbError> {
        self.boxes
            .iter()
            .position(|s| s.id == id)
            .ok_or(WtbError::UnknownBox(id.0))
    }

    fn make_slot(&self, id: BoxId, spec: BoxSpec) -> Result<Slot, WtbError> {
        spec.wind.validate()?;
        finite_at_least("smoothing", spec.smoothing, 0.0)?;
        if let Some(r) = spec.recovery {
            finite_at_least("recovery", r, 0.0)?;
        }
        // A box that cannot reach the grid even fully grown is a mistake, not an empty box.
        let w = &spec.wind;
        let full = BoxFrame::new(w.origin, w.direction, w.fetch, w.width, self.grid.spacing())?;
        let s = self.grid.spacing();
        let extent = DVec2::new(
            (self.grid.nx() - 1) as f64 * s,
            (self.grid.nz() - 1) as f64 * s,
        );
        let whole = BoxFrame::new(self.grid.origin(), DVec2::X, extent.x, extent.y, s)?;
        if !rectangles_overlap(&full, &whole) {
            return Err(WtbError::OutsideGrid);
        }
        let trains = spec.trains.resolve(&spec.wind)?;
        let amplitude = trains.iter().map(|d| d.amplitude).sum();
        let peak = trains
            .iter()
            .max_by(|a, b| a.amplitude.total_cmp(&b.amplitude))
            .ok_or(WtbError::OutOfRange {
                name: "trains",
                value: 0.0,
                min: 1.0,
                max: f64::MAX,
            })?;
        Ok(Slot {
            id,
            spec,
            peak_k: effects::wavenumber(peak.wavelength),
            peak_wavelength: peak.wavelength,
            trains,
            amplitude,
            cache: None,
        })
    }

    /// Prepares the instant `t` (seconds): culls boxes outside `view` (none when `None`),
    /// chooses the work within the budget, refreshes the static modulation of boxes that moved
    /// or grew, and computes the time-dependent effects. Evaluate the grid and answer height
    /// queries on the returned [`Frame`].
    ///
    /// # Errors
    ///
    /// [`WtbError::NotFinite`] for a non-finite time.
    pub fn frame(&mut self, t: f64, view: Option<&Frustum>) -> Result<Frame<'_>, WtbError> {
        let (mut stats, selection, visible) = self.visible(t, view)?;
        let choice = TrainChoice {
            max_trains: selection.max_trains,
            filter: self.filter,
            spacing: self.grid.spacing(),
        };
        let key = StaticKey::of(&selection.effects);
        // Refresh the caches that are stale.
        for (k, frame, _) in &visible {
            let fresh = self.boxes[*k].cache.as_ref().is_some_and(|c| {
                c.frame == *frame && c.terrain_version == self.terrain_version && c.key == key
            });
            if !fresh {
                let rect = box_rect(&self.grid, frame);
                let march = MarchBox::new(&self.grid, &self.boxes[*k], frame, key, rect);
                let cache = build_cache(&self.grid, &self.terrain, &march, self.terrain_version)?;
                self.boxes[*k].cache = Some(cache);
                stats.rebuilt += 1;
            }
        }
        // Per-frame layers.
        let mut layers = Vec::new();
        for (k, frame, env) in &visible {
            let slot = &self.boxes[*k];
            let cache = slot.cache.as_ref().expect("refreshed above");
            let Some(static_mu) = &cache.mu else {
                continue;
            };
            let Some(waves) = frame_waves(slot, *env, choice, &mut stats)? else {
                continue;
            };
            stats.trains += waves.coeffs().len();
            let mu = march::time_modulation(
                &self.grid,
                &self.terrain,
                frame,
                slot.peak_k,
                static_mu,
                &selection.effects,
                t,
            )?;
            let timed = waves.at_time(t).map_err(WtbError::Eval)?;
            layers.push(FrameLayer {
                waves,
                timed,
                mu,
                cache: static_mu,
            });
        }
        let height = height_field(&self.grid, &self.terrain, &selection.effects, t);
        Ok(Frame {
            grid: &self.grid,
            inv_spacing: 1.0 / self.grid.spacing(),
            last_point: DVec2::new((self.grid.nx() - 1) as f64, (self.grid.nz() - 1) as f64),
            // The grid's cap (MAX_SIDE) keeps these in u32.
            last_cell: ((self.grid.nx() - 2) as u32, (self.grid.nz() - 2) as u32),
            t,
            layers,
            height,
            stats,
        })
    }

    /// Steps 1 and 2 of a frame (§2.3): the boxes alive at `t`, culled against `view`, and the
    /// budget's selection for them, as `(slot index, frame, envelope)`.
    #[allow(clippy::type_complexity)]
    fn visible(
        &self,
        t: f64,
        view: Option<&Frustum>,
    ) -> Result<(FrameStats, Selection, Vec<(usize, BoxFrame, f64)>), WtbError> {
        if !t.is_finite() {
            return Err(WtbError::NotFinite("time"));
        }
        let spacing = self.grid.spacing();
        let mut stats = FrameStats::default();
        // 1. Alive boxes and their frames at t.
        let mut alive: Vec<(usize, BoxFrame, f64)> = Vec::new();
        for (k, slot) in self.boxes.iter().enumerate() {
            let Some(state) = slot.spec.wind.state(t) else {
                continue;
            };
            if let Some(frame) = slot.spec.wind.frame(t, spacing)?
                && frame.length() > 0.0
                && state.envelope > 0.0
            {
                alive.push((k, frame, state.envelope));
            }
        }
        stats.alive = alive.len();
        // Culling (§2.2): each OBB is extruded by the maximum heights of all overlapping boxes.
        let noise = self.effects.noise.map_or(0.0, |n| n.amplitude.abs());
        let heights: Vec<f64> = alive
            .iter()
            .map(|(k, _, env)| self.boxes[*k].amplitude * env * effects::MAX_SHOALING)
            .collect();
        let mut visible = Vec::new();
        for (n, (k, frame, env)) in alive.iter().enumerate() {
            let mut h = noise;
            for (m, (_, other, _)) in alive.iter().enumerate() {
                if m == n || rectangles_overlap(frame, other) {
                    h += heights[m];
                }
            }
            let keep = match view {
                None => true,
                Some(f) => f.test_obb(&frame.obb(h.max(1e-3))?) != Containment::Outside,
            };
            if keep {
                visible.push((*k, *frame, *env));
            } else {
                stats.culled += 1;
            }
        }
        // 2.–4. The budget's choice.
        let loads: Vec<BoxLoad> = visible
            .iter()
            .map(|(k, frame, _)| BoxLoad {
                points: covered_points(frame, spacing),
                trains: self.boxes[*k].trains.len(),
            })
            .collect();
        let selection = select(
            &self.budget,
            &self.cost,
            self.grid.len(),
            &loads,
            &self.effects,
        );
        stats.selection = Some(selection);
        stats.estimated_ns = self.cost.estimate(self.grid.len(), &loads, &selection);
        Ok((stats, selection, visible))
    }

    /// A frame's plan without its CPU ray march: the visible boxes with their waves and what
    /// their march reads, for a GPU twin (`ocean_gpu::WtbMarchPass`) that marches the rays
    /// itself. The boxes are those, in the order, of [`Frame::layers`] at the same `t` and
    /// `view`, and [`MarchBox::march`]'s result is what the CPU frame evaluates.
    ///
    /// # Errors
    ///
    /// As [`Scene::frame`].
    pub fn plan(&self, t: f64, view: Option<&Frustum>) -> Result<Plan, WtbError> {
        let (mut stats, selection, visible) = self.visible(t, view)?;
        let choice = TrainChoice {
            max_trains: selection.max_trains,
            filter: self.filter,
            spacing: self.grid.spacing(),
        };
        let key = StaticKey::of(&selection.effects);
        let mut boxes = Vec::new();
        for (k, frame, env) in &visible {
            let slot = &self.boxes[*k];
            let rect = box_rect(&self.grid, frame);
            if rect.is_empty() {
                continue;
            }
            let Some(waves) = frame_waves(slot, *env, choice, &mut stats)? else {
                continue;
            };
            stats.trains += waves.coeffs().len();
            boxes.push(PlannedBox {
                id: slot.id,
                waves,
                march: MarchBox::new(&self.grid, slot, frame, key, rect),
            });
        }
        Ok(Plan {
            t,
            effects: selection.effects,
            boxes,
            stats,
        })
    }
}

fn check_terrain(grid: &WaterGrid, terrain: &Terrain) -> Result<(), WtbError> {
    if terrain.grid() != grid {
        return Err(WtbError::TerrainSize {
            expected: grid.len(),
            got: terrain.grid().len(),
        });
    }
    Ok(())
}

fn finite_at_least(name: &'static str, v: f64, min: f64) -> Result<(), WtbError> {
    if !v.is_finite() {
        return Err(WtbError::NotFinite(name));
    }
    if v < min {
        return Err(WtbError::OutOfRange {
            name,
            value: v,
            min,
            max: f64::MAX,
        });
    }
    Ok(())
}

fn check_effects(e: &Effects) -> Result<(), WtbError> {
    if let Some(n) = e.noise {
        check_range("noise amplitude", n.amplitude, 0.0, MAX_EFFECT_HEIGHT)?;
    }
    if let Some(p) = e.irregular {
        check_range("irregular scale", p.scale, 0.0, 1.0)?;
        check_range(
            "irregular frequency",
            p.frequency,
            0.0,
            MAX_EFFECT_WAVENUMBER,
        )?;
        check_range(
            "irregular envelope wavenumber",
            p.envelope_wavenumber,
            0.0,
            MAX_EFFECT_WAVENUMBER,
        )?;
        check_range(
            "irregular envelope speed",
            p.envelope_speed,
            -MAX_EFFECT_SPEED,
            MAX_EFFECT_SPEED,
        )?;
    }
    if let Some(b) = e.beach {
        check_range("beach run-up", b.run_up, 0.0, MAX_EFFECT_HEIGHT)?;
        check_range("beach run-up depth", b.run_up_depth, 0.0, MAX_EFFECT_DEPTH)?;
        if !(b.max_depth_share > 0.0 && b.max_depth_share <= 1.0) {
            return Err(WtbError::OutOfRange {
                name: "beach max depth share",
                value: b.max_depth_share,
                min: 0.0,
                max: 1.0,
            });
        }
    }
    Ok(())
}

/// Whether two boxes' rectangles overlap (separating-axis test on their four edge normals).
pub fn rectangles_overlap(a: &BoxFrame, b: &BoxFrame) -> bool {
    let corners = |f: &BoxFrame| {
        let (o, u, v) = (f.origin(), f.u() * f.length(), f.v() * f.width());
        [o, o + u, o + u + v, o + v]
    };
    let (ca, cb) = (corners(a), corners(b));
    for axis in [a.u(), a.v(), b.u(), b.v()] {
        let span = |c: &[DVec2; 4]| {
            c.iter()
                .map(|p| p.dot(axis))
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
                    (lo.min(x), hi.max(x))
                })
        };
        let ((a0, a1), (b0, b1)) = (span(&ca), span(&cb));
        if a1 < b0 || b1 < a0 {
            return false;
        }
    }
    true
}

/// Grid points a box covers, estimated from its area (for the budget).
fn covered_points(frame: &BoxFrame, spacing: f64) -> usize {
    (frame.length() * frame.width() / (spacing * spacing)) as usize
}

/// The grid rectangle that holds every grid point of the box (its corners' bounding box,
/// clipped to the grid).
fn box_rect(grid: &WaterGrid, frame: &BoxFrame) -> GridRect {
    let (o, u, v) = (
        frame.origin(),
        frame.u() * frame.length(),
        frame.v() * frame.width(),
    );
    let corners = [o, o + u, o + u + v, o + v];
    let (mut lo, mut hi) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
    for c in corners {
        // Fractional grid coordinates (to_local already divides by the spacing).
        let l = grid.to_local(c);
        lo = lo.min(l);
        hi = hi.max(l);
    }
    let (nx, nz) = (grid.nx() as f64, grid.nz() as f64);
    // Corners may lie far outside the grid (up to 2²⁴ cells): clamp before converting.
    let clamp = |v: f64, n: f64| v.clamp(-1.0, n + 1.0);
    let (nxi, nzi) = (grid.nx() as i64, grid.nz() as i64);
    let i0 = (floor_i64(clamp(lo.x, nx)) - 1).clamp(0, nxi) as usize;
    let j0 = (floor_i64(clamp(lo.y, nz)) - 1).clamp(0, nzi) as usize;
    let i1 = (ceil_i64(clamp(hi.x, nx)) + 2).clamp(0, nxi) as usize;
    let j1 = (ceil_i64(clamp(hi.y, nz)) + 2).clamp(0, nzi) as usize;
    GridRect {
        i0,
        j0,
        nx: i1.saturating_sub(i0),
        nz: j1.saturating_sub(j0),
    }
}

/// What a frame's boxes draw their trains with: the budget's train count, the geometry
/// filter and the grid's spacing.
#[derive(Clone, Copy)]
struct TrainChoice {
    max_trains: usize,
    filter: Option<TrainFilter>,
    spacing: f64,
}

/// A box's trains at envelope `env`: its largest `max_trains` (§2.3), each weighted by the
/// geometry filter's w_p (the trains it leaves out are not built); `None` when none is left.
/// The filtered trains are counted in `stats`.
fn frame_waves(
    slot: &Slot,
    env: f64,
    choice: TrainChoice,
    stats: &mut FrameStats,
) -> Result<Option<WaveSet>, WtbError> {
    let order = train_order(&slot.trains.iter().map(|d| d.amplitude).collect::<Vec<_>>());
    let take = order.len().min(choice.max_trains);
    let mut waves: Vec<Wave> = Vec::with_capacity(take);
    for &i in &order[..take] {
        let d = &slot.trains[i];
        let w = choice
            .filter
            .map_or(1.0, |f| f.weight(d.wavelength, choice.spacing));
        if w < 1.0 {
            stats.filtered_trains += 1;
            let lost = (1.0 - w) * effects::wavenumber(d.wavelength) * d.amplitude * env;
            stats.filtered_slope_variance += 0.5 * lost * lost;
        }
        if w == 0.0 {
            stats.removed_trains += 1;
            continue;
        }
        let wave = d
            .build()
            .and_then(|w| w.scaled(env))
            .and_then(|wave| if w < 1.0 { wave.scaled(w) } else { Ok(wave) })
            .map_err(|source| WtbError::Wave { index: i, source })?;
        waves.push(wave);
    }
    if waves.is_empty() {
        return Ok(None);
    }
    WaveSet::new(&waves)
        .map(Some)
        .map_err(|source| WtbError::Wave { index: 0, source })
}

impl MarchBox {
    /// What `slot`'s march reads with `frame` over `rect`, under the static effects `key`.
    fn new(
        grid: &WaterGrid,
        slot: &Slot,
        frame: &BoxFrame,
        key: StaticKey,
        rect: GridRect,
    ) -> Self {
        Self {
            frame: *frame,
            rect,
            smoothing: slot.spec.smoothing,
            recovery: slot.spec.recovery.unwrap_or(2.0 * slot.peak_wavelength),
            amplitude: slot.amplitude,
            peak_k: slot.peak_k,
            shallow_depth: effects::shoaling_reference(slot.peak_wavelength),
            refraction: key.refraction,
            shoaling: key.shoaling,
            round_waves: key.round_waves,
            beach: key.beach,
            shore_radius: shore::radius(slot.amplitude, grid.spacing()),
        }
    }
}

/// Marches the box's rays (see [`MarchBox::march`]) into a cache.
fn build_cache(
    grid: &WaterGrid,
    terrain: &Terrain,
    march: &MarchBox,
    terrain_version: u64,
) -> Result<Cache, WtbError> {
    let (mu, actions) = march.march(grid, terrain)?;
    Ok(Cache {
        frame: march.frame,
        terrain_version,
        key: march.key(),
        mu,
        actions,
    })
}

use ocean_core::parallel::for_rows;

/// Height-only terms: capillary noise on every grid point (Eq. 9) and the beach run-up.
fn height_field(grid: &WaterGrid, terrain: &Terrain, e: &Effects, t: f64) -> Option<Vec<f32>> {
    if e.noise.is_none() && e.beach.is_none_or(|b| b.run_up == 0.0) {
        return None;
    }
    let mut h = vec![0.0f32; grid.len()];
    let nx = grid.nx();
    for_rows(&mut h, nx, |j, row| {
        for (i, v) in row.iter_mut().enumerate() {
            let mut y = 0.0;
            if let Some(n) = &e.noise {
                y += effects::noise_height(n, (j * nx + i) as u64, t);
            }
            if let Some(b) = &e.beach
                && !terrain.is_land(i, j)
            {
                y += effects::run_up(b, terrain.depth(i, j));
            }
            *v = y as f32;
        }
    });
    Some(h)
}

pub use crate::continuous::{HeightSample, QUERY_MAX_ITERATIONS, QUERY_TOLERANCE};
pub use crate::drawn::{DrawnMesh, DrawnSample, DrawnTriangle};
