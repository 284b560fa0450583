//! Accuracy of the tracers against the exact first hit ([`crate::truth`]): per map, relief depth,
//! view angle and method, the share of rays more than one texel from the true hit, the mean error
//! in texels, and how many rays overshot: ended more than a texel from the true hit and deeper
//! than where the ray first leaves the solid after it, i.e. went through the feature they should
//! have stopped at ([`truth::exit_after`]).
//!
//! Errors are 3D distances in texels: the horizontal error times `N`, the depth error times the
//! relief depth in texels (`depth·N`). Rays start at uniformly random points of the tile with
//! uniformly random azimuths (PCG32, fixed seed); every method traces the same rays.
//!
//! Quadrant cone maps ([`crate::quad`]) are traced through the layer of each ray's quadrant
//! ([`Textures`]); the book's four-ratio layout (`Cones::QuadPlain`) reads the depth from a second
//! texture, so its fetch count counts sample positions, two texture reads each.
//!
//! [`table`] is what the tests print and the benchmark will print; [`Table`]'s `Display` is the
//! text table.

use alloc::string::String;
use alloc::vec;
use alloc::vec::Vec;
use core::fmt;

use glam::{Vec2, Vec3};
use ocean_core::rng::Pcg32;

use crate::cone::{ConeMap, ConeParams};
use crate::map::HeightMap;
use crate::quad::{QuadConeMap, QuadReliefTexture};
use crate::relief::ReliefTexture;
use crate::trace::{Method, Ray};
use crate::{ReliefError, check_range, for_rows, truth};

/// Which cone map a method reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Cones {
    /// Relaxed cones with their clearances.
    Relaxed,
    /// Relaxed cones, plain channel only (the book's one-channel map).
    RelaxedPlain,
    /// Conservative cones, plain (Dummer's map).
    Conservative,
    /// Relaxed quadrant cones with their clearances ([`crate::quad`]: a 4-layer texture array,
    /// one RGBA fetch per step).
    Quad,
    /// Relaxed quadrant cones, plain channel only (the book's four-ratio RGBA texel, Fig. 18-8b,
    /// with the depth in a second texture: two texture reads per fetch position).
    QuadPlain,
    /// Conservative quadrant cones, plain: QDCSM (§18.1).
    QuadConservative,
}

/// A method as the table lists it: a name, the tracer, its cone map, and an optional
/// angle-adaptive budget.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// Name in the table.
    pub name: String,
    /// The tracer (for an adaptive entry, the step counts at normal incidence).
    pub method: Method,
    /// The cone map it reads (ignored by the linear search).
    pub cones: Cones,
    /// Scale the relaxed cone steps with the view angle ([`adaptive_cone_steps`]).
    pub adaptive: bool,
}

impl Entry {
    /// A fixed-budget entry.
    pub fn new(name: &str, method: Method, cones: Cones) -> Self {
        Self {
            name: name.into(),
            method,
            cones,
            adaptive: false,
        }
    }
}

/// What to measure.
#[derive(Clone, Debug, PartialEq)]
pub struct Config {
    /// Named height maps.
    pub maps: Vec<(String, HeightMap)>,
    /// Relief depths, in texture widths (0.1 on a 256² map is 25.6 texels).
    pub depths: Vec<f32>,
    /// View angles from the normal, degrees, in `[0, 89]`.
    pub angles: Vec<f32>,
    /// Rays per (map, depth, angle).
    pub rays: usize,
    /// Methods.
    pub entries: Vec<Entry>,
    /// Cone cap for the cone maps ([`ConeParams::max_ratio`]).
    pub max_ratio: f32,
    /// Seed of the ray generator.
    pub seed: u64,
}

impl Config {
    /// The benchmark's configuration on `n × n` maps: smooth and rough value noise, boxes, round
    /// bumps, thin walls and pins ([`crate::maps`]), relief depths of 0.1 and 0.2 texture widths,
    /// view angles 0–80°, [`Config::standard_entries`], cones capped at 4 texture widths per unit
    /// depth.
    ///
    /// # Errors
    ///
    /// The map size errors.
    pub fn standard(n: usize, rays: usize) -> Result<Self, ReliefError> {
        use crate::map::Edge;
        use crate::maps::{boxes, bumps, pins, thin_walls, to_map, value_noise};
        let lattice = (n / 16).max(2);
        let maps = [
            ("smooth noise", value_noise(n, lattice / 2, 2, 1)),
            ("fBm noise", value_noise(n, lattice, 5, 1)),
            ("boxes", boxes(n, n * n / 400, 2)),
            ("bumps", bumps(n, n * n / 550, n as f64 / 12.8, 3)),
            ("thin walls", thin_walls(n, (n / 8).max(4))),
            ("pins", pins(n, 40, 4)),
        ];
        Ok(Self {
            maps: maps
                .into_iter()
                .map(|(name, h)| Ok((String::from(name), to_map(n, &h, Edge::Wrap)?)))
                .collect::<Result<_, ReliefError>>()?,
            depths: vec![0.1, 0.2],
            angles: vec![0.0, 30.0, 45.0, 60.0, 70.0, 80.0],
            rays,
            entries: Self::standard_entries(),
            max_ratio: 4.0,
            seed: 7,
        })
    }

    /// The comparison at 21 fetches: linear 15 + 6, cone step mapping 21, relaxed 15 + 6 with
    /// banded cones, with the plain (book) cone channel, and with the book's bisection, and
    /// banded relaxed with an angle-adaptive budget; then the quadrant maps ([`crate::quad`]):
    /// QDCSM 21 (§18.1), relaxed quadrant cones with a shared budget of 21, with the plain
    /// channel alone, and with the angle-adaptive budget.
    pub fn standard_entries() -> Vec<Entry> {
        use crate::trace::BinarySearch::{Book, LastStep, Shared};
        let relaxed = |search| Method::Relaxed {
            cone: 15,
            binary: 6,
            search,
        };
        vec![
            Entry::new(
                "linear 15+6",
                Method::Linear {
                    linear: 15,
                    binary: 6,
                },
                Cones::Relaxed,
            ),
            Entry::new(
                "cone step 21",
                Method::ConeStep { steps: 21 },
                Cones::Conservative,
            ),
            Entry::new("relaxed 15+6 book", relaxed(Book), Cones::RelaxedPlain),
            Entry::new("relaxed 15+6 plain", relaxed(LastStep), Cones::RelaxedPlain),
            Entry::new("relaxed 15+6", relaxed(LastStep), Cones::Relaxed),
            Entry::new("relaxed 21 shared", relaxed(Shared), Cones::Relaxed),
            Entry {
                name: "relaxed adaptive".into(),
                method: relaxed(Shared),
                cones: Cones::Relaxed,
                adaptive: true,
            },
            Entry::new(
                "quad cone step 21",
                Method::ConeStep { steps: 21 },
                Cones::QuadConservative,
            ),
            Entry::new("quad 21 shared", relaxed(Shared), Cones::Quad),
            Entry::new("quad 21 plain", relaxed(Shared), Cones::QuadPlain),
            Entry {
                name: "quad adaptive".into(),
                method: relaxed(Shared),
                cones: Cones::Quad,
                adaptive: true,
            },
        ]
    }
}

/// Cone steps for a view angle: `base / cos θ`, rounded up, capped at `8·base`. A grazing ray
/// advances about `cone·height` per step while it must cross `tan θ` times the relief depth,
/// so the steps it needs grow like `1/cos θ` (80° gets 5.8× the steps of normal incidence).
pub fn adaptive_cone_steps(base: u32, angle_deg: f32) -> u32 {
    let c = libm::cosf(angle_deg.to_radians()).max(1.0e-3);
    let s = libm::ceilf(base as f32 / c);
    (s as u32).clamp(base, 8 * base)
}

/// One line of the table.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// Map name.
    pub map: String,
    /// Relief depth in texels.
    pub depth_texels: f32,
    /// View angle, degrees.
    pub angle: f32,
    /// Method name.
    pub method: String,
    /// Fetches per ray (mean over the rays for adaptive budgets).
    pub fetches: f64,
    /// Share of rays more than one texel from the true hit.
    pub over_one: f64,
    /// Mean error, texels.
    pub mean: f64,
    /// Rays that went through the feature they first hit (and ended more than a texel off).
    pub overshoots: u64,
    /// Rays traced.
    pub rays: u64,
}

/// The measured table.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Table {
    /// Its rows, in (map, depth, angle, method) order.
    pub rows: Vec<Row>,
}

impl Table {
    /// The row of `method` at `(map, angle)` and relief depth `depth_texels`.
    pub fn find(&self, map: &str, depth_texels: f32, angle: f32, method: &str) -> Option<&Row> {
        self.rows.iter().find(|r| {
            r.map == map && r.depth_texels == depth_texels && r.angle == angle && r.method == method
        })
    }
}

impl fmt::Display for Table {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "{:<14} {:>7} {:>5}  {:<20} {:>7} {:>9} {:>10} {:>6}",
            "map", "depth", "angle", "method", "fetches", ">1 texel", "mean (tx)", "over"
        )?;
        for r in &self.rows {
            writeln!(
                f,
                "{:<14} {:>7.1} {:>5.0}  {:<20} {:>7.1} {:>8.2}% {:>10.4} {:>6}",
                r.map,
                r.depth_texels,
                r.angle,
                r.method,
                r.fetches,
                100.0 * r.over_one,
                r.mean,
                r.overshoots
            )?;
        }
        Ok(())
    }
}

/// Measures every (map, depth, angle, method) of `config`.
///
/// # Errors
///
/// [`ReliefError::OutOfRange`] for an angle outside `[0, 89]`, a depth outside `(0, 100]` or no
/// rays; the cone generator's errors for `max_ratio`; the tracers' errors for bad step counts.
pub fn table(config: &Config) -> Result<Table, ReliefError> {
    check_range("rays", config.rays as f64, 1.0, 1.0e8)?;
    for &a in &config.angles {
        check_range("angle", f64::from(a), 0.0, 89.0)?;
    }
    for &d in &config.depths {
        check_range("depth", f64::from(d), 1.0e-6, 100.0)?;
    }
    let mut table = Table::default();
    for (name, map) in &config.maps {
        let textures = Textures::new(map, config.max_ratio, &config.entries)?;
        let n = map.size() as f64;
        for &depth in &config.depths {
            for &angle in &config.angles {
                let rays = rays(config.rays, angle, depth, config.seed)?;
                let truth: Vec<(glam::DVec3, f64)> = rays
                    .iter()
                    .map(|r| {
                        let hit = truth::first_hit(map, r)?;
                        Ok((hit, truth::exit_after(map, r, hit.z)?))
                    })
                    .collect::<Result<_, ReliefError>>()?;
                for entry in &config.entries {
                    let mut method = entry.method;
                    if entry.adaptive
                        && let Method::Relaxed { cone, .. } = &mut method
                    {
                        *cone = adaptive_cone_steps(*cone, angle);
                    }
                    // Step counts are checked once; the rays are valid by construction.
                    textures.trace(entry.cones, &method, &rays[0])?;
                    // Per-ray (error, overshoot) in parallel; summed in ray order.
                    let mut errs = vec![(0.0f64, false); rays.len()];
                    const CHUNK: usize = 256;
                    for_rows(&mut errs, CHUNK, |c, part| {
                        for (k, e) in part.iter_mut().enumerate() {
                            let i = c * CHUNK + k;
                            *e = match textures.trace(entry.cones, &method, &rays[i]) {
                                Ok(hit) => error(hit.pos, truth[i].0, truth[i].1, n, depth),
                                Err(_) => (f64::INFINITY, false),
                            };
                        }
                    });
                    let total = errs.len() as f64;
                    table.rows.push(Row {
                        map: name.clone(),
                        depth_texels: (f64::from(depth) * n) as f32,
                        angle,
                        method: entry.name.clone(),
                        fetches: f64::from(method.fetches()),
                        over_one: errs.iter().filter(|e| e.0 > 1.0).count() as f64 / total,
                        mean: errs.iter().map(|e| e.0).sum::<f64>() / total,
                        overshoots: errs.iter().filter(|e| e.1).count() as u64,
                        rays: errs.len() as u64,
                    });
                }
            }
        }
    }
    Ok(table)
}

/// The textures the entries of a table read on one map, each built only if some entry uses it.
#[derive(Clone, Debug, PartialEq)]
pub struct Textures {
    relaxed: ReliefTexture,
    relaxed_plain: ReliefTexture,
    conservative: ReliefTexture,
    quad: Option<QuadReliefTexture>,
    quad_plain: Option<QuadReliefTexture>,
    quad_conservative: Option<QuadReliefTexture>,
}

impl Textures {
    /// The cone maps of `map` capped at `max_ratio` that `entries` read: the isotropic relaxed
    /// (banded and plain) and conservative (plain) maps always, the quadrant maps
    /// ([`crate::quad`]) when an entry uses them.
    ///
    /// # Errors
    ///
    /// The cone generator's errors for `max_ratio`.
    pub fn new(map: &HeightMap, max_ratio: f32, entries: &[Entry]) -> Result<Self, ReliefError> {
        let uses = |c: Cones| entries.iter().any(|e| e.cones == c);
        let plain = |c: &ConeMap| ConeMap::from_ratios(c.size(), c.edge(), c.ratios().to_vec());
        let banded = ConeMap::generate(map, ConeParams::relaxed(max_ratio))?;
        let conservative = ConeMap::generate(map, ConeParams::conservative(max_ratio))?;
        let quad = if uses(Cones::Quad) || uses(Cones::QuadPlain) {
            Some(QuadConeMap::generate(map, ConeParams::relaxed(max_ratio))?)
        } else {
            None
        };
        let quad_texture = |c: Option<&QuadConeMap>, plain: bool| match c {
            Some(c) if plain => QuadReliefTexture::new(map, &c.plain()?).map(Some),
            Some(c) => QuadReliefTexture::new(map, c).map(Some),
            None => Ok(None),
        };
        let quad_conservative = if uses(Cones::QuadConservative) {
            Some(QuadConeMap::generate(
                map,
                ConeParams::conservative(max_ratio),
            )?)
        } else {
            None
        };
        Ok(Self {
            relaxed: ReliefTexture::new(map, &banded)?,
            relaxed_plain: ReliefTexture::new(map, &plain(&banded)?)?,
            conservative: ReliefTexture::new(map, &plain(&conservative)?)?,
            quad: quad_texture(quad.as_ref().filter(|_| uses(Cones::Quad)), false)?,
            quad_plain: quad_texture(quad.as_ref().filter(|_| uses(Cones::QuadPlain)), true)?,
            quad_conservative: quad_texture(quad_conservative.as_ref(), true)?,
        })
    }

    /// Traces `ray` with `method` on the texture of `cones`.
    ///
    /// # Errors
    ///
    /// The tracer's errors; [`ReliefError::Mismatch`] for quadrant cones that no entry given to
    /// [`Textures::new`] used (they were not built).
    pub fn trace(
        &self,
        cones: Cones,
        method: &Method,
        ray: &Ray,
    ) -> Result<crate::trace::Hit, ReliefError> {
        let quad = match cones {
            Cones::Relaxed => return method.trace(&self.relaxed, ray),
            Cones::RelaxedPlain => return method.trace(&self.relaxed_plain, ray),
            Cones::Conservative => return method.trace(&self.conservative, ray),
            Cones::Quad => &self.quad,
            Cones::QuadPlain => &self.quad_plain,
            Cones::QuadConservative => &self.quad_conservative,
        };
        quad.as_ref()
            .ok_or(ReliefError::Mismatch("quadrant cones not built"))?
            .trace(method, ray)
    }
}

/// `count` rays at `angle` degrees from the normal for a relief `depth` texture widths deep.
fn rays(count: usize, angle: f32, depth: f32, seed: u64) -> Result<Vec<Ray>, ReliefError> {
    let mut rng = Pcg32::new(
        seed,
        u64::from(angle.to_bits()) ^ (u64::from(depth.to_bits()) << 32),
    );
    let (st, ct) = libm::sincosf(angle.to_radians());
    (0..count)
        .map(|_| {
            let start = Vec2::new(rng.next_f32(), rng.next_f32());
            let phi = core::f32::consts::TAU * rng.next_f32();
            let (sp, cp) = libm::sincosf(phi);
            Ray::from_view(start, Vec3::new(st * cp, st * sp, -ct), depth)
        })
        .collect()
}

/// 3D error in texels, and whether the hit lies beyond `exit`, where the ray leaves the
/// feature it first hits (it went through that feature), by more than a texel from the true hit
/// (rays that graze a feature over a sliver of depth far below a texel can end past its exit by
/// rounding alone).
fn error(hit: Vec3, truth: glam::DVec3, exit: f64, n: f64, depth: f32) -> (f64, bool) {
    let dz_scale = f64::from(depth) * n;
    let du = (f64::from(hit.x) - truth.x) * n;
    let dv = (f64::from(hit.y) - truth.y) * n;
    let dz = (f64::from(hit.z) - truth.z) * dz_scale;
    let e = libm::sqrt(du * du + dv * dv + dz * dz);
    (e, e > 1.0 && f64::from(hit.z) > exit)
}
