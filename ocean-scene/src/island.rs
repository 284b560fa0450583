//! The island of `ocean render`: a procedural terrain (`[island]` in scene files) and the wave
//! train boxes that reach its shore (`[[boxes]]`, Yrjölä & Larsson), marched on the CPU each
//! frame by `ocean_wtb` (land collision, shadow zones behind land, depth refraction, shoaling)
//! and drawn on the open sea as local waves (Bruneton et al. §6, `ocean_brdf::LocalWaves`), so
//! their slope variance feeds the same lighting and near and far water look like one sea. The
//! open sea's own spectrum fades out over the shallows, where the boxes take over.

use crate::RockMesh;
use crate::SceneError;
use crate::check::{Bad, range};
use glam::{DVec2, DVec3};
use ocean_brdf::{FilteredSurface, LocalWaves};
use ocean_wtb::effects::Effects;
use ocean_wtb::scenarios::steady_wind;
use ocean_wtb::scene::{BoxSpec, Scene};
use ocean_wtb::{Terrain, TrainSource, WaterGrid};
use serde::Deserialize;

/// `[island]`: a procedural island and the grid its shore waves are computed on.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(default, deny_unknown_fields)]
pub struct IslandSection {
    /// World (x, z) of its centre, metres.
    pub centre: [f64; 2],
    /// Mean radius of its shoreline, metres.
    pub radius: f64,
    /// Height of its summit above the sea, metres.
    pub peak: f64,
    /// Depth of the sea floor away from it, metres.
    pub shelf_depth: f64,
    /// Irregularity of the coastline, a fraction of the radius in [0, 0.5].
    pub roughness: f64,
    /// Seed of the coastline and the hills.
    pub seed: u64,
    /// Points per side of the square grid (terrain and wave trains), 16 to 2048.
    pub grid_size: usize,
    /// Spacing of that grid, metres.
    pub grid_spacing: f64,
    /// Depths, metres, over which the open sea's spectrum fades in: absent above the first,
    /// full below the second.
    pub open_sea_depths: [f64; 2],
}

impl Default for IslandSection {
    fn default() -> Self {
        Self {
            centre: [40.0, -150.0],
            radius: 50.0,
            peak: 16.0,
            shelf_depth: 14.0,
            roughness: 0.2,
            seed: 7,
            grid_size: 256,
            grid_spacing: 1.2,
            open_sea_depths: [1.0, 10.0],
        }
    }
}

impl IslandSection {
    pub fn check(&self) -> Result<(), Bad> {
        for c in self.centre {
            range("island.centre", c, -1e6, 1e6)?;
        }
        range("island.radius", self.radius, 1.0, 1e4)?;
        range("island.peak", self.peak, 0.1, 1e4)?;
        range("island.shelf_depth", self.shelf_depth, 0.1, 1e4)?;
        range("island.roughness", self.roughness, 0.0, 0.5)?;
        if !(16..=2048).contains(&self.grid_size) {
            return Err((
                "island.grid_size",
                format!("= {} is outside 16 to 2048", self.grid_size),
            ));
        }
        range("island.grid_spacing", self.grid_spacing, 0.01, 100.0)?;
        let [a, b] = self.open_sea_depths;
        range("island.open_sea_depths", a, 0.0, 1e4)?;
        range("island.open_sea_depths", b, a + 1e-3, 1e4)?;
        Ok(())
    }

    /// The terrain's height at world `(x, z)` = `p`, metres above the sea at rest: a bump
    /// `(peak + shelf)/(1 + (peak/shelf) d⁴) − shelf` of the distance d from the centre in
    /// radii (0 on the mean shoreline, the summit at the centre, the shelf far away), d
    /// perturbed by value noise for an irregular coast, plus low hills on land.
    pub fn height(&self, p: DVec2) -> f64 {
        let c = DVec2::from_array(self.centre);
        let q = (p - c) / self.radius;
        let coast = fbm(q * 1.6, self.seed) - 0.5;
        let d = q.length() * (1.0 + 2.0 * self.roughness * coast);
        let (peak, shelf) = (self.peak, self.shelf_depth);
        let d2 = d * d;
        let base = (peak + shelf) / (1.0 + (peak / shelf) * d2 * d2) - shelf;
        let hills = 0.25 * peak * (fbm(q * 4.0, self.seed ^ 0x9e37) - 0.5);
        base + hills * smoothstep(0.0, 2.0, base)
    }

    /// The outermost point of the shoreline (height 0) along the unit direction `dir` from the
    /// centre: stepping inwards from three radii (beyond the coast's reach: the noise moves it
    /// at most by a factor `1 ± roughness`) by 1/256 of the radius to the first point on land,
    /// then bisecting that step to 1e-9 of the radius. `None` if the ray meets no land.
    pub fn shore(&self, dir: DVec2) -> Option<DVec2> {
        let c = DVec2::from_array(self.centre);
        let at = |r: f64| c + dir * (r * self.radius);
        let step = 1.0 / 256.0;
        let mut outside = 3.0;
        while self.height(at(outside - step)) < 0.0 {
            outside -= step;
            if outside <= step {
                return None;
            }
        }
        let mut inside = outside - step;
        while outside - inside > 1e-9 {
            let mid = 0.5 * (inside + outside);
            if self.height(at(mid)) < 0.0 {
                outside = mid;
            } else {
                inside = mid;
            }
        }
        Some(at(0.5 * (inside + outside)))
    }

    /// The water grid: `grid_size²` points around the centre.
    pub fn grid(&self) -> Result<WaterGrid, SceneError> {
        WaterGrid::centred(
            DVec2::from_array(self.centre),
            self.grid_spacing,
            self.grid_size,
        )
        .map_err(|e| SceneError::Description(format!("island grid: {e}")))
    }

    /// The open sea's amplitude factor at a point `depth` metres deep (negative on land).
    pub fn open_sea_factor(&self, depth: f64) -> f32 {
        let [a, b] = self.open_sea_depths;
        smoothstep(a, b, depth) as f32
    }
}

/// `[[boxes]]`: a wind raising a wave train box (§2) that blows for the whole render.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(default, deny_unknown_fields)]
pub struct WaveBox {
    /// World (x, z) of the box's centre, metres.
    pub centre: [f64; 2],
    /// Direction the wind blows towards, degrees from +x towards +z.
    pub direction: f64,
    /// Wind speed, m/s.
    pub speed: f64,
    /// Width across the wind and fetch along it, metres.
    pub width: f64,
    pub fetch: f64,
    /// Number of wave trains, and the seed of their mapping.
    pub trains: u32,
    pub seed: u64,
    /// Width of the smoothing band along the box's edges, metres.
    pub smoothing: f64,
}

impl Default for WaveBox {
    fn default() -> Self {
        Self {
            centre: [20.0, -90.0],
            direction: 285.0,
            speed: 8.0,
            width: 200.0,
            fetch: 150.0,
            trains: 2,
            seed: 3,
            smoothing: 8.0,
        }
    }
}

impl WaveBox {
    pub fn check(&self) -> Result<(), Bad> {
        for c in self.centre {
            range("boxes.centre", c, -1e6, 1e6)?;
        }
        range("boxes.direction", self.direction, -1e4, 1e4)?;
        range(
            "boxes.speed",
            self.speed,
            0.1,
            ocean_wtb::wind::MAX_WIND_SPEED,
        )?;
        range("boxes.width", self.width, 1.0, 1e5)?;
        range("boxes.fetch", self.fetch, 1.0, 1e5)?;
        range(
            "boxes.trains",
            f64::from(self.trains),
            1.0,
            f64::from(ocean_wtb::wind::MAX_TRAINS),
        )?;
        range("boxes.smoothing", self.smoothing, 0.0, 1e4)?;
        Ok(())
    }

    /// The box's spec: its rectangle centred on `centre` (the frame's origin is the rear
    /// left corner looking along the wind, `ocean_wtb::frame`).
    fn spec(&self) -> BoxSpec {
        let a = self.direction.to_radians();
        let u = DVec2::new(a.cos(), a.sin());
        let v = DVec2::new(-u.y, u.x);
        let origin = DVec2::from_array(self.centre) - 0.5 * self.fetch * u - 0.5 * self.width * v;
        BoxSpec {
            wind: steady_wind(
                self.speed,
                u,
                origin,
                self.width,
                self.fetch,
                self.trains,
                self.seed,
            ),
            trains: TrainSource::FromWind,
            smoothing: self.smoothing,
            recovery: None,
        }
    }
}

/// The island of a scene: its terrain heights and its wave train box scene.
pub struct Island {
    pub grid: WaterGrid,
    /// Heights at the grid points, row-major.
    pub heights: Vec<f32>,
    /// The open sea's factor at the grid points, from their depth.
    open_scale: Vec<f32>,
    scene: Scene,
}

impl Island {
    /// Builds the terrain and adds the boxes. The wave trains meet the `rocks` too: their
    /// terrain is the island's raised to the top of every rock (`RockMesh::top_at`), so the
    /// trains break on the rocks and leave shadow zones behind them; the drawn terrain is
    /// the island's alone (the rocks draw themselves).
    ///
    /// # Errors
    ///
    /// A message naming the box the wave train model refuses.
    pub fn new(
        section: &IslandSection,
        boxes: &[WaveBox],
        rocks: &[&RockMesh],
    ) -> Result<Self, SceneError> {
        let grid = section.grid()?;
        let ground = Terrain::from_fn(&grid, |p| section.height(p) as f32)
            .map_err(|e| format!("island terrain: {e}"))?;
        let heights = ground.heights().map(<[f32]>::to_vec).unwrap_or_default();
        let bounds: Vec<[DVec3; 2]> = rocks.iter().map(|r| r.bounds()).collect();
        let with_rocks = |p: DVec2| {
            let mut h = section.height(p);
            for (rock, [lo, hi]) in rocks.iter().zip(&bounds) {
                if (lo.x..=hi.x).contains(&p.x) && (lo.z..=hi.z).contains(&p.y) {
                    h = rock.top_at(p.x, p.y).map_or(h, |top| h.max(top));
                }
            }
            h as f32
        };
        let terrain = if rocks.is_empty() {
            ground
        } else {
            Terrain::from_fn(&grid, with_rocks).map_err(|e| format!("island terrain: {e}"))?
        };
        let mut scene = Scene::new(grid, terrain).map_err(|e| format!("island: {e}"))?;
        scene
            .set_effects(Effects::default())
            .map_err(|e| format!("island: {e}"))?;
        // The renderer filters every train on its own footprints (local waves, §6), so the
        // scene grid's geometry filter would take out trains the screen resolves.
        scene.set_train_filter(None);
        for (k, b) in boxes.iter().enumerate() {
            scene
                .add_box(b.spec())
                .map_err(|e| format!("box {}: {e}", k + 1))?;
        }
        let open_scale = heights
            .iter()
            .map(|&h| section.open_sea_factor(-f64::from(h)))
            .collect();
        Ok(Self {
            grid,
            heights,
            open_scale,
            scene,
        })
    }

    /// The wave trains at `time` as local waves on `sea` (its wind and filter), with the open
    /// sea's factor from the depth.
    ///
    /// # Errors
    ///
    /// A message if the wave train model or the local waves refuse the frame.
    pub fn local_waves(
        &mut self,
        sea: &FilteredSurface,
        time: f64,
    ) -> Result<LocalWaves, SceneError> {
        let g = self.grid;
        let mut local = LocalWaves::new(
            g.origin(),
            g.spacing(),
            g.nx(),
            g.nz(),
            sea.wind(),
            *sea.filter(),
        )
        .map_err(|e| format!("island: {e}"))?;
        local
            .set_open_scale(&self.open_scale)
            .map_err(|e| format!("island: {e}"))?;
        let frame = self
            .scene
            .frame(time, None)
            .map_err(|e| format!("wave trains at t = {time}: {e}"))?;
        for layer in frame.layers() {
            local
                .add_set(layer.waves, layer.modulation)
                .map_err(|e| format!("wave trains: {e}"))?;
        }
        Ok(local)
    }
}

fn smoothstep(a: f64, b: f64, x: f64) -> f64 {
    let t = ((x - a) / (b - a)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// A hash of a lattice point and a seed to [0, 1).
fn lattice(i: i64, j: i64, seed: u64) -> f64 {
    let mut h = (i as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ (j as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
        ^ seed.wrapping_mul(0x1656_67B1_9E37_79F9);
    h ^= h >> 31;
    h = h.wrapping_mul(0xBF58_476D_1CE4_E5B9);
    h ^= h >> 29;
    (h >> 11) as f64 / (1u64 << 53) as f64
}

/// Value noise at `p` (lattice spacing 1), smoothly interpolated, in [0, 1].
fn value_noise(p: DVec2, seed: u64) -> f64 {
    let (fx, fz) = (p.x.floor(), p.y.floor());
    let (i, j) = (fx as i64, fz as i64);
    let s = |t: f64| t * t * (3.0 - 2.0 * t);
    let (tx, tz) = (s(p.x - fx), s(p.y - fz));
    let a = lattice(i, j, seed) * (1.0 - tx) + lattice(i + 1, j, seed) * tx;
    let b = lattice(i, j + 1, seed) * (1.0 - tx) + lattice(i + 1, j + 1, seed) * tx;
    a * (1.0 - tz) + b * tz
}

/// Four octaves of value noise, in [0, 1].
fn fbm(p: DVec2, seed: u64) -> f64 {
    let mut sum = 0.0;
    let mut amp = 0.5;
    let mut q = p;
    for o in 0..4u64 {
        sum += amp * value_noise(q, seed.wrapping_add(o));
        q *= 2.03;
        amp *= 0.5;
    }
    sum / 0.9375
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The profile: the summit at the centre, the shelf far away, the coast near one radius
    /// (within the roughness), and the same heights for the same seed.
    #[test]
    fn the_island_has_a_summit_a_coast_and_a_shelf() {
        let s = IslandSection::default();
        let c = DVec2::from_array(s.centre);
        assert!(s.height(c) > 0.6 * s.peak);
        assert!((s.height(c + DVec2::new(10.0 * s.radius, 0.0)) + s.shelf_depth).abs() < 0.01);
        for k in 0..16 {
            let a = f64::from(k) * std::f64::consts::TAU / 16.0;
            let dir = DVec2::new(a.cos(), a.sin());
            let inside = c + dir * s.radius * (1.0 - 2.0 * s.roughness);
            let outside = c + dir * s.radius * (1.0 + 2.0 * s.roughness) * 1.2;
            assert!(s.height(inside) > 0.0, "{k}");
            assert!(s.height(outside) < 0.0, "{k}");
        }
        assert_eq!(
            s.height(c + DVec2::new(3.3, -7.1)),
            s.height(c + DVec2::new(3.3, -7.1))
        );
        assert!(s.check().is_ok());
    }

    /// The boxes reach the shore: the local waves have the default box's trains, their μ is
    /// zero on land and non-zero in open water inside the box, and the open sea is faded out on
    /// land and present far out.
    #[test]
    fn local_waves_follow_land_and_boxes() {
        let s = IslandSection {
            grid_size: 128,
            grid_spacing: 2.4,
            ..IslandSection::default()
        };
        let boxes = [WaveBox::default()];
        let mut island = Island::new(&s, &boxes, &[]).unwrap();
        let spectrum = ocean_brdf::Spectrum::new(ocean_brdf::SpectrumParams::default()).unwrap();
        let sea = FilteredSurface::new(&spectrum, ocean_brdf::Filter::PAPER).unwrap();
        let local = island.local_waves(&sea, 10.0).unwrap();
        assert_eq!(local.set_count(), 1);
        assert_eq!(local.train_count(), 2);
        let c = DVec2::from_array(s.centre);
        assert_eq!(local.modulation_at(0, c), [0.0, 0.0]);
        assert_eq!(local.open_scale_at(c), 0.0);
        // Inside the default box, 13 m deep, 60 m upwind of its centre.
        let open_water = DVec2::new(0.0, -30.0);
        let mu = local.modulation_at(0, open_water);
        assert!(mu[0].hypot(mu[1]) > 0.3, "{mu:?}");
        assert_eq!(local.open_scale_at(open_water), 1.0);

        // A rock standing there is land to the wave trains (μ = 0 on it) but not to the drawn
        // terrain, which stays the island's.
        let rock = crate::RockShape {
            size: DVec3::new(12.0, 6.0, 12.0),
            ..Default::default()
        }
        .mesh()
        .unwrap()
        .placed(DVec3::new(open_water.x, 1.0, open_water.y), 0.0);
        let mut rocky = Island::new(&s, &boxes, &[&rock]).unwrap();
        assert_eq!(rocky.heights, island.heights);
        let local = rocky.local_waves(&sea, 10.0).unwrap();
        assert_eq!(local.modulation_at(0, open_water), [0.0, 0.0]);
    }
}
