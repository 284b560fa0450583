//! The paper's benchmark scenes (§3, Fig. 11 and 13) and an island, at any grid size: for
//! tests, benchmarks, examples and GPU parity. Grids have 1 m spacing; at 64 × 64 points the
//! scenes are exactly those of this crate's snapshot tests, and other sizes scale every
//! position and extent by n / 64.

use alloc::vec::Vec;

use glam::DVec2;
use ocean_core::math;

use crate::effects::{Effects, Refraction};
use crate::error::WtbError;
use crate::grid::WaterGrid;
use crate::scene::{BoxSpec, Scene};
use crate::terrain::Terrain;
use crate::wind::{TrainSource, Wind};

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
    let grid = WaterGrid::new(DVec2::ZERO, 1.0, n, n)?;
    let far = (n - 1) as f64;
    let terrain = Terrain::from_fn(&grid, |p| -(30.0 - 29.0 * p.x / far) as f32)?;
    Ok((grid, terrain))
}

/// The paper's scenario 1: two boxes covering most of the grid, one with one train and one
/// with two, basic Gerstner waves and depth refraction by phase shift, on [`sloping`].
pub fn scenario_1(n: usize) -> Result<Scene, WtbError> {
    let (grid, terrain) = sloping(n)?;
    let s = n as f64 / 64.0;
    let mut scene = Scene::new(grid, terrain)?;
    scene.set_effects(Effects {
        refraction: Refraction::PhaseShift,
        shoaling: false,
        ..Effects::default()
    })?;
    scene.add_box(spec(steady_wind(
        7.0,
        DVec2::new(1.0, 0.15),
        DVec2::new(-2.0, -4.0) * s,
        66.0 * s,
        70.0 * s,
        1,
        11,
    )))?;
    scene.add_box(spec(steady_wind(
        5.0,
        DVec2::new(0.7, 1.0),
        DVec2::new(30.0, -30.0) * s,
        60.0 * s,
        90.0 * s,
        2,
        12,
    )))?;
    Ok(scene)
}

/// The paper's scenario 2: seven boxes with one train each, spread over the grid (Fig. 13),
/// refraction by phase shift on [`sloping`].
pub fn scenario_2(n: usize) -> Result<Scene, WtbError> {
    let (grid, terrain) = sloping(n)?;
    let s = n as f64 / 64.0;
    let mut scene = Scene::new(grid, terrain)?;
    scene.set_effects(Effects {
        refraction: Refraction::PhaseShift,
        shoaling: false,
        ..Effects::default()
    })?;
    let boxes: Vec<(f64, f64, f64, f64)> = (0..7)
        .map(|k| {
            let a = 0.9 * k as f64;
            // Origins on a ring, winds turning with them, 24 m × 30 m boxes at 64².
            (
                a,
                32.0 + 18.0 * math::cos(a) - 12.0,
                32.0 + 18.0 * math::sin(a) - 12.0,
                5.0 + 0.5 * k as f64,
            )
        })
        .collect();
    for (k, (a, x, z, speed)) in boxes.into_iter().enumerate() {
        scene.add_box(spec(steady_wind(
            speed,
            DVec2::new(math::cos(a + 0.5), math::sin(a + 0.5)),
            DVec2::new(x, z) * s,
            24.0 * s,
            30.0 * s,
            1,
            20 + k as u64,
        )))?;
    }
    Ok(scene)
}

/// An island: land 4 m in radius (× n/64) at the grid's centre rising 2 m above the sea, its
/// shore sloping to 12 m deep; one box with one train blowing along +x across it, the
/// default effects (refraction by phase shift, shoaling), recovery behind land over 20 m.
pub fn island(n: usize) -> Result<Scene, WtbError> {
    let s = n as f64 / 64.0;
    let grid = WaterGrid::new(DVec2::ZERO, 1.0, n, n)?;
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
