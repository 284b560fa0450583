//! Winds and the wave trains they raise (paper §2).
//!
//! A [`Wind`] defines a wave train box: its direction, origin (the box's lower-left corner looking
//! along the wind, see [`crate::frame`]) and width set the box directly; its speed sets the height
//! of the waves (Eq. 1); its life length sets how the box builds up, is sustained and decays.
//!
//! # Height (Eq. 1)
//!
//! The fully developed crest-to-trough height is `H = α h² / g` with `α = 0.21`
//! ([`ALPHA`], Resio et al. 1999) and `g` = [`ocean_core::GRAVITY`]. The trains' amplitudes
//! (half heights) therefore sum to `H/2`, so that crests of all trains in phase reach `H/2` above
//! and troughs `H/2` below the sea at rest.
//!
//! # Lifecycle
//!
//! See [`Wind::state`]: linear build-up of length and amplitude, sustain, linear decay of the
//! amplitude at full length.
//!
//! # From a wind to its wave trains
//!
//! [`Wind::trains`] is a documented, seeded mapping (PCG32 from ocean-core, seed [`Wind::seed`],
//! stream [`TRAIN_STREAM`]), the same on every platform:
//!
//! 1. Peak wavelength from the Pierson–Moskowitz spectrum (Pierson & Moskowitz 1964; the lighting
//!    paper's Eq. 1 with ω₀ = g/V): peak angular frequency `ω_p = 0.877 g / h`, and by the
//!    deep-water dispersion relation (Eq. 5) `λ_p = 2π g / ω_p²`. For h = 10 m/s:
//!    ω_p = 0.8603 rad/s, λ_p = 83.27 m.
//! 2. For train `n = 0 .. trains`, draws in this order: phase `Φ` uniform in `[0, 2π)`; then, for
//!    `n ≥ 1` only, a wavelength factor `f` uniform in [[`MIN_FACTOR`], [`MAX_FACTOR`]), a
//!    direction offset `δ` uniform in `[−SPREAD, SPREAD)` ([`SPREAD`] = 30°, "wave trains traveling
//!    in roughly the same direction", §2) and a weight `w` uniform in [[`MIN_WEIGHT`], 1). Train 0
//!    is the peak: `f = 1`, `δ = 0`, `w = 1`.
//! 3. `λₙ = f·λ_p`, direction = the wind's turned by `δ`, amplitude `Aₙ = (H/2)·wₙ / Σw`, deep
//!    water ([`Depth::Deep`]; depth effects are applied per point by the evaluator).
//! 4. Steepness limits ([`limit_steepness`]): each `kₙAₙ ≤` [`MAX_TRAIN_STEEPNESS`], then all
//!    amplitudes scaled so that `Σ kₙAₙ ≤` [`MAX_TOTAL_STEEPNESS`] (the sum of Gerstner waves
//!    cannot fold where it holds). A fully developed Pierson–Moskowitz peak has
//!    `k_p·H/2 = 0.877²·α/2 = 0.081` at every wind speed, so with the ranges above the sum stays
//!    below 0.17 and wind-made trains are never clamped; the limits guard explicit trains.

use alloc::vec::Vec;
use core::f64::consts::{PI, TAU};

use glam::DVec2;
use ocean_core::math::{cos, sin};
use ocean_core::{Depth, GRAVITY, Pcg32, WaveDesc};

use crate::box_frame::{BoxFrame, unit_direction};
use crate::error::WtbError;
use crate::grid::{check_position, check_range};

/// α of Eq. 1 (Resio et al. 1999).
pub const ALPHA: f64 = 0.21;
/// The Pierson–Moskowitz peak: `ω_p = PM_PEAK · g / h`.
pub const PM_PEAK: f64 = 0.877;
/// Most wave trains a wind raises.
pub const MAX_TRAINS: u32 = 8;
/// Most explicit trains a box accepts.
pub const MAX_EXPLICIT_TRAINS: usize = 64;
/// Largest wind speed accepted, m/s (above the strongest gusts measured; H = 214 m there).
pub const MAX_WIND_SPEED: f64 = 100.0;
/// Smallest wind speed accepted, m/s: its peak wavelength λ_p = 2π h² / (0.877² g) is 8.3 mm,
/// at the capillary limit where gravity waves end. Slower winds would give trains so short
/// that their wavenumbers overflow (at 5e-324 m/s, λ_p underflows to 0).
pub const MIN_WIND_SPEED: f64 = 0.1;
/// Largest fetch or width of a wind, metres.
pub const MAX_EXTENT: f64 = 1e7;
/// The PCG32 stream of the wind → trains mapping.
pub const TRAIN_STREAM: u64 = 0x5754_425f_7472_6e73; // "WTB_trns"
/// Smallest wavelength factor of trains n ≥ 1.
pub const MIN_FACTOR: f64 = 0.5;
/// Largest wavelength factor (exclusive) of trains n ≥ 1.
pub const MAX_FACTOR: f64 = 1.5;
/// Half-angle of the directional spread of trains n ≥ 1 around the wind, radians (30°).
pub const SPREAD: f64 = PI / 6.0;
/// Smallest amplitude weight of trains n ≥ 1 (train 0 has weight 1).
pub const MIN_WEIGHT: f64 = 0.25;
/// Largest steepness k·A of one train.
pub const MAX_TRAIN_STEEPNESS: f64 = 0.5;
/// Largest summed steepness Σ k·A of a box's trains: at 1 the sum of trochoids reaches a cusp.
pub const MAX_TOTAL_STEEPNESS: f64 = 1.0;

/// Fully developed crest-to-trough wave height for wind speed `h` (m/s): `H = α h²/g` (Eq. 1).
#[inline]
pub fn fully_developed_height(h: f64) -> f64 {
    ALPHA * h * h / GRAVITY
}

/// Pierson–Moskowitz peak wavelength for wind speed `h`: `λ_p = 2π g / ω_p²`,
/// `ω_p = 0.877 g / h` (see the module documentation).
#[inline]
pub fn peak_wavelength(h: f64) -> f64 {
    let wp = PM_PEAK * GRAVITY / h;
    TAU * GRAVITY / (wp * wp)
}

/// A wind that creates a wave train box (§2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wind {
    /// Wind speed h, m/s, in (0, [`MAX_WIND_SPEED`]].
    pub speed: f64,
    /// Direction the wind blows towards (x, z); any finite non-zero length.
    pub direction: DVec2,
    /// World (x, z) of the box's lower-left corner looking along the wind (see
    /// [`crate::frame`]).
    pub origin: DVec2,
    /// Box width across the wind, metres, in (0, [`MAX_EXTENT`]].
    pub width: f64,
    /// Fetch: the box's full length along the wind, metres, in (0, [`MAX_EXTENT`]].
    pub fetch: f64,
    /// Time the wind starts, seconds.
    pub start: f64,
    /// Build-up duration, seconds, ≥ 0.
    pub build_up: f64,
    /// Sustain duration, seconds, ≥ 0; `f64::INFINITY` for a wind that never dies.
    pub sustain: f64,
    /// Decay duration, seconds, ≥ 0.
    pub decay: f64,
    /// Seed of the wave-train mapping.
    pub seed: u64,
    /// Number of wave trains, 1 ..= [`MAX_TRAINS`].
    pub trains: u32,
}

/// The phase of a wind's life.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LifePhase {
    /// Growing: age in `[0, build_up)`.
    BuildUp,
    /// Full: age in `[build_up, build_up + sustain]`.
    Sustain,
    /// Dying: age in `(build_up + sustain, build_up + sustain + decay]`.
    Decay,
}

/// A wind's box at one instant (see [`Wind::state`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WindState {
    /// Time since the wind started, seconds.
    pub age: f64,
    /// Which phase of its life the wind is in.
    pub phase: LifePhase,
    /// The box's current length along the wind, metres, in `[0, fetch]`.
    pub length: f64,
    /// Amplitude factor of every train, in `[0, 1]`.
    pub envelope: f64,
}

impl Wind {
    /// Checks every field.
    ///
    /// # Errors
    ///
    /// [`WtbError::NotFinite`], [`WtbError::OutOfRange`] (speed, width, fetch, durations, trains),
    /// [`WtbError::ZeroDirection`].
    pub fn validate(&self) -> Result<(), WtbError> {
        check_range("speed", self.speed, MIN_WIND_SPEED, MAX_WIND_SPEED)?;
        unit_direction("direction", self.direction)?;
        check_position("origin", self.origin)?;
        positive("width", self.width, MAX_EXTENT)?;
        positive("fetch", self.fetch, MAX_EXTENT)?;
        if !self.start.is_finite() {
            return Err(WtbError::NotFinite("start"));
        }
        check_range("build_up", self.build_up, 0.0, f64::MAX)?;
        check_range("decay", self.decay, 0.0, f64::MAX)?;
        if self.sustain != f64::INFINITY {
            check_range("sustain", self.sustain, 0.0, f64::MAX)?;
        }
        if !(1..=MAX_TRAINS).contains(&self.trains) {
            return Err(WtbError::OutOfRange {
                name: "trains",
                value: self.trains as f64,
                min: 1.0,
                max: MAX_TRAINS as f64,
            });
        }
        Ok(())
    }

    /// Fully developed crest-to-trough height `H = α h²/g` (Eq. 1), metres.
    #[inline]
    pub fn height(&self) -> f64 {
        fully_developed_height(self.speed)
    }

    /// Unit direction of the wind (u of its box); `None` for a zero or non-finite direction.
    pub fn unit_direction(&self) -> Option<DVec2> {
        unit_direction("direction", self.direction).ok()
    }

    /// Total life length `build_up + sustain + decay`, seconds (may be +∞).
    #[inline]
    pub fn lifetime(&self) -> f64 {
        self.build_up + self.sustain + self.decay
    }

    /// The box at time `t` (seconds), or `None` when it does not exist: before `start`, after
    /// `start + build_up + sustain + decay`, or for a NaN `t`. With `age = t − start`,
    /// `B = build_up`, `S = sustain`, `D = decay`:
    ///
    /// | age | phase | length | envelope |
    /// |---|---|---|---|
    /// | `[0, B)` | build-up | `fetch·age/B` | `age/B` |
    /// | `[B, B + S]` | sustain | `fetch` | 1 |
    /// | `(B + S, B + S + D]` | decay | `fetch` | `1 − (age − B − S)/D` |
    ///
    /// Length and envelope are continuous in `t` while the box exists, and the envelope is 0 at
    /// both ends of its life when `B > 0` and `D > 0`. With `B = 0` the box appears at full size
    /// and amplitude at `t = start`; with `D = 0` it vanishes at full amplitude — discontinuities
    /// the wind asks for.
    pub fn state(&self, t: f64) -> Option<WindState> {
        let age = t - self.start;
        if age.is_nan() || age < 0.0 {
            return None;
        }
        let (b, s, d) = (self.build_up, self.sustain, self.decay);
        let (phase, length, envelope) = if age < b {
            let x = age / b;
            (LifePhase::BuildUp, self.fetch * x, x)
        } else if age - b <= s {
            (LifePhase::Sustain, self.fetch, 1.0)
        } else if age - b - s <= d {
            let x = (age - b - s) / d;
            (LifePhase::Decay, self.fetch, (1.0 - x).max(0.0))
        } else {
            return None;
        };
        Some(WindState {
            age,
            phase,
            length: length.min(self.fetch),
            envelope: envelope.clamp(0.0, 1.0),
        })
    }

    /// The box frame at time `t` with the water grid's `spacing`: origin, direction and width from
    /// the wind, length from [`Wind::state`]; `Ok(None)` when the box does not exist at `t`.
    ///
    /// # Errors
    ///
    /// As [`Wind::validate`] and [`BoxFrame::new`].
    pub fn frame(&self, t: f64, spacing: f64) -> Result<Option<BoxFrame>, WtbError> {
        self.validate()?;
        let Some(state) = self.state(t) else {
            return Ok(None);
        };
        BoxFrame::new(
            self.origin,
            self.direction,
            state.length,
            self.width,
            spacing,
        )
        .map(Some)
    }

    /// The wind's wave trains by the seeded mapping of the module documentation, at full
    /// amplitude (multiply by [`WindState::envelope`] when evaluating).
    ///
    /// # Errors
    ///
    /// As [`Wind::validate`].
    pub fn trains(&self) -> Result<Vec<WaveDesc>, WtbError> {
        self.validate()?;
        let u = unit_direction("direction", self.direction)?;
        let lambda_p = peak_wavelength(self.speed);
        let mut rng = Pcg32::new(self.seed, TRAIN_STREAM);
        let mut out = Vec::with_capacity(self.trains as usize);
        let mut weights = [0.0f64; MAX_TRAINS as usize];
        for (n, weight) in weights.iter_mut().enumerate().take(self.trains as usize) {
            let phase = TAU * rng.next_f64();
            let (factor, offset, w) = if n == 0 {
                (1.0, 0.0, 1.0)
            } else {
                let f = MIN_FACTOR + (MAX_FACTOR - MIN_FACTOR) * rng.next_f64();
                let d = SPREAD * (2.0 * rng.next_f64() - 1.0);
                let w = MIN_WEIGHT + (1.0 - MIN_WEIGHT) * rng.next_f64();
                (f, d, w)
            };
            *weight = w;
            let (sn, cs) = (sin(offset), cos(offset));
            out.push(WaveDesc {
                amplitude: 0.0,
                wavelength: factor * lambda_p,
                direction: DVec2::new(cs * u.x - sn * u.y, sn * u.x + cs * u.y),
                phase,
                depth: Depth::Deep,
            });
        }
        let total_w: f64 = weights.iter().sum();
        let half_height = 0.5 * self.height();
        for (desc, w) in out.iter_mut().zip(weights) {
            desc.amplitude = half_height * w / total_w;
        }
        limit_steepness(&mut out, MAX_TRAIN_STEEPNESS, MAX_TOTAL_STEEPNESS);
        Ok(out)
    }
}

fn positive(name: &'static str, value: f64, max: f64) -> Result<f64, WtbError> {
    let v = check_range(name, value, 0.0, max)?;
    if v == 0.0 {
        return Err(WtbError::OutOfRange {
            name,
            value,
            min: f64::MIN_POSITIVE,
            max,
        });
    }
    Ok(v)
}

/// Steepness `k·A = 2π A / λ` of a train.
#[inline]
pub fn steepness(desc: &WaveDesc) -> f64 {
    TAU * desc.amplitude / desc.wavelength
}

/// Summed steepness `Σ kₙAₙ` of a set of trains.
pub fn total_steepness(trains: &[WaveDesc]) -> f64 {
    trains.iter().map(steepness).sum()
}

/// Summed amplitude `Σ Aₙ`: the highest crest the trains can build together, metres (the
/// height of a box's bounding volume, §2.2).
pub fn crest_height(trains: &[WaveDesc]) -> f64 {
    trains.iter().map(|d| d.amplitude).sum()
}

/// Clamps amplitudes so that each train's `k·A ≤ max_train`, then scales all amplitudes by one
/// factor so that `Σ k·A ≤ max_total` (within rounding: at most a few ulps above). Returns the
/// factor of the second step (1 when it did nothing). Trains with a non-positive or non-finite
/// wavelength are left alone (they are refused when built).
pub fn limit_steepness(trains: &mut [WaveDesc], max_train: f64, max_total: f64) -> f64 {
    for d in trains.iter_mut() {
        if d.wavelength > 0.0 && d.wavelength.is_finite() && steepness(d) > max_train {
            d.amplitude = max_train * d.wavelength / TAU;
        }
    }
    let total = total_steepness(trains);
    if total > max_total {
        let f = max_total / total;
        for d in trains.iter_mut() {
            d.amplitude *= f;
        }
        f
    } else {
        1.0
    }
}

/// Where a box's wave trains come from.
#[derive(Clone, Debug, PartialEq, Default)]
pub enum TrainSource {
    /// The wind's seeded mapping ([`Wind::trains`]).
    #[default]
    FromWind,
    /// Exactly these trains (for users who want full control); the wind then sets only the box
    /// and its lifecycle.
    Explicit(Vec<WaveDesc>),
}

impl TrainSource {
    /// The trains of a box raised by `wind`.
    ///
    /// # Errors
    ///
    /// As [`Wind::trains`] for [`TrainSource::FromWind`]. For explicit trains:
    /// [`WtbError::OutOfRange`] for none or more than [`MAX_EXPLICIT_TRAINS`],
    /// [`WtbError::Wave`] when ocean-core refuses a train (NaN, zero direction, `k·A > 1`, ...),
    /// [`WtbError::TooSteep`] when `Σ k·A >` [`MAX_TOTAL_STEEPNESS`] (scale them with
    /// [`limit_steepness`] first).
    pub fn resolve(&self, wind: &Wind) -> Result<Vec<WaveDesc>, WtbError> {
        match self {
            TrainSource::FromWind => wind.trains(),
            TrainSource::Explicit(trains) => {
                if trains.is_empty() || trains.len() > MAX_EXPLICIT_TRAINS {
                    return Err(WtbError::OutOfRange {
                        name: "explicit trains",
                        value: trains.len() as f64,
                        min: 1.0,
                        max: MAX_EXPLICIT_TRAINS as f64,
                    });
                }
                for (index, d) in trains.iter().enumerate() {
                    d.build()
                        .map_err(|source| WtbError::Wave { index, source })?;
                }
                let total = total_steepness(trains);
                if total > MAX_TOTAL_STEEPNESS * (1.0 + 8.0 * f64::EPSILON) {
                    return Err(WtbError::TooSteep {
                        total,
                        max: MAX_TOTAL_STEEPNESS,
                    });
                }
                Ok(trains.clone())
            }
        }
    }
}
