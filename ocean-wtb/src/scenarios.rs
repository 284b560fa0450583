//! The paper's benchmark scenes (§3, Fig. 11 and 13) and an island, at any grid size: the one
//! source of them for tests, benchmarks (`ocean bench wtb`), examples and GPU parity. Grids
//! have 1 m spacing; every position and extent scales with the grid's side n (from the layout
//! size each function names).

use alloc::vec;
use alloc::vec::Vec;

use glam::DVec2;

use crate::effects::{Effects, Refraction};
use crate::error::WtbError;
use crate::grid::WaterGrid;
use crate::scene::{BoxId, BoxSpec, Scene};
use crate::terrain::Terrain;
use crate::wind::{TrainSource, Wind};

/// The grid spacing of every scene here, metres.
pub const SPACING: f64 = 1.0;

/// A wind fully developed from before t = 0 that never dies.
pub fn steady_wind(
    speed: f64,
    direction: DVec2,
    origin: DVec2,
    width: f64,
    fetch: f64,
    trains: u32,
    seed: u64,
) -> Wind {
    Wind {
        speed,
        direction,
        origin,
        width,
        fetch,
        start: -1.0,
        build_up: 0.0,
        sustain: f64::INFINITY,
        decay: 0.0,
        seed,
        trains,
    }
}

/// A box raised by `wind` with the wind's own trains and 4 m of side smoothing.
pub fn spec(wind: Wind) -> BoxSpec {
    BoxSpec {
        wind,
        trains: TrainSource::FromWind,
        smoothing: 4.0,
        recovery: None,
    }
}

/// `n × n` points 1 m apart from the origin, over a sea floor sloping from 30 m deep at
/// x = 0 to 1 m deep at the far side.
pub fn sloping(n: usize) -> Result<(WaterGrid, Terrain), WtbError> {
    let grid = WaterGrid::new(DVec2::ZERO, SPACING, n, n)?;
    let far = (n - 1) as f64 * SPACING;
    let terrain = Terrain::from_fn(&grid, |p| -(30.0 - 29.0 * p.x / far) as f32)?;
    Ok((grid, terrain))
}

/// Basic Gerstner waves and depth refraction by phase shift: the effects of the paper's
/// benchmarks (§3).
pub fn paper_effects() -> Effects {
    Effects {
        refraction: Refraction::PhaseShift,
        shoaling: false,
        ..Effects::default()
    }
}

/// A scene over [`sloping`] with `effects` and one box per spec, with the boxes' ids in the
/// order of `specs`.
pub fn build(
    n: usize,
    effects: Effects,
    specs: &[BoxSpec],
) -> Result<(Scene, Vec<BoxId>), WtbError> {
    let (grid, terrain) = sloping(n)?;
    let mut scene = Scene::new(grid, terrain)?;
    scene.set_effects(effects)?;
    let ids = specs
        .iter()
        .map(|s| scene.add_box(s.clone()))
        .collect::<Result<_, _>>()?;
    Ok((scene, ids))
}

/// The boxes of the paper's scenario 1 (§3, Fig. 11) on `n × n`: two boxes covering most of
/// the grid, one with one train and one with two (laid out on 64², scaled by n / 64).
pub fn scenario_1_boxes(n: usize) -> Vec<BoxSpec> {
    let s = n as f64 / 64.0;
    vec![
        spec(steady_wind(
            7.0,
            DVec2::new(1.0, 0.15),
            DVec2::new(-2.0, -4.0) * s,
            66.0 * s,
            70.0 * s,
            1,
            11,
        )),
        spec(steady_wind(
            5.0,
            DVec2::new(0.7, 1.0),
            DVec2::new(30.0, -30.0) * s,
            60.0 * s,
            90.0 * s,
            2,
            12,
        )),
    ]
}

/// The paper's scenario 1: [`scenario_1_boxes`] with [`paper_effects`] on [`sloping`].
pub fn scenario_1(n: usize) -> Result<Scene, WtbError> {
    Ok(build(n, paper_effects(), &scenario_1_boxes(n))?.0)
}

/// The boxes of the paper's scenario 2 (§3, Fig. 13) on `n × n`: seven boxes with one train
/// each, 50–120 m a side at 256² (the paper's grid for it), in several directions, spread over
/// the grid and overlapping in places, so that culling one saves more or less depending on its
/// size, as the paper reports (laid out on 256², scaled by n / 256).
pub fn scenario_2_boxes(n: usize) -> Vec<BoxSpec> {
    let s = n as f64 / 256.0;
    // Speed, direction, origin, (width, fetch) and seed at 256².
    let w = |speed, (dx, dz): (f64, f64), (x, z): (f64, f64), (width, fetch): (f64, f64), seed| {
        spec(steady_wind(
            speed,
            DVec2::new(dx, dz),
            DVec2::new(x, z) * s,
            width * s,
            fetch * s,
            1,
            seed,
        ))
    };
    vec![
        w(6.0, (1.0, 0.1), (5.0, 5.0), (100.0, 110.0), 21),
        w(5.0, (1.0, -0.1), (140.0, 15.0), (90.0, 100.0), 22),
        w(7.0, (1.0, 0.3), (10.0, 115.0), (70.0, 90.0), 23),
        w(5.5, (1.0, 0.0), (125.0, 110.0), (60.0, 120.0), 24),
        w(4.5, (1.0, -0.2), (20.0, 195.0), (50.0, 80.0), 25),
        w(6.5, (1.0, 0.15), (130.0, 175.0), (70.0, 110.0), 26),
        w(8.0, (0.6, 1.0), (120.0, 40.0), (80.0, 120.0), 27),
    ]
}

/// The paper's scenario 2: [`scenario_2_boxes`] with [`paper_effects`] on [`sloping`].
pub fn scenario_2(n: usize) -> Result<Scene, WtbError> {
    Ok(build(n, paper_effects(), &scenario_2_boxes(n))?.0)
}

/// An island: land 4 m in radius (× n/64) at the grid's centre rising 2 m above the sea, its
/// shore sloping to 12 m deep; one box with one train blowing along +x across it, the
/// default effects (refraction by phase shift, shoaling), recovery behind land over 20 m.
pub fn island(n: usize) -> Result<Scene, WtbError> {
    let s = n as f64 / 64.0;
    let grid = WaterGrid::new(DVec2::ZERO, SPACING, n, n)?;
    let centre = DVec2::splat(32.0 * s);
    let terrain = Terrain::from_fn(&grid, |p| {
        let r = p.distance(centre) / s;
        if r < 4.0 {
            2.0
        } else {
            -((r - 4.0) * 0.8).min(12.0) as f32
        }
    })?;
    let mut scene = Scene::new(grid, terrain)?;
    scene.set_effects(Effects::default())?;
    scene.add_box(BoxSpec {
        recovery: Some(20.0 * s),
        ..spec(steady_wind(
            6.0,
            DVec2::X,
            DVec2::ZERO,
            64.0 * s,
            64.0 * s,
            1,
            5,
        ))
    })?;
    Ok(scene)
}
