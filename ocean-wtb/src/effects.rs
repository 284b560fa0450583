//! The local wave effects of §2 and §2.1, as pure per-point laws.
//!
//! Every effect either scales a box's amplitude at a point (a factor m) or shifts its phase (an
//! offset φ); the evaluator multiplies the factors, adds the offsets and hands the box's trains
//! to `ocean_core::evaluate_layers` with the complex amplitude m·e^{iφ}. Height-only terms (the
//! capillary noise of Eq. 9 and the run-up) are added to the heights afterwards.
//!
//! Where the paper describes an effect only qualitatively, the law chosen here is stated with
//! its source:
//!
//! - **shoaling** ("the amplitude is increased slightly" as depth decreases, §2): Green's law
//!   A ∝ D^(−1/4), from the depth where the waves start to feel the bottom (half a wavelength),
//!   capped;
//! - **depth refraction by phase shift** (the default, §2.1, Fig. 6): the phase lag that the
//!   shorter shallow-water wavelength accumulates along each ray at a fixed frequency,
//!   φ = −∫ (k(D) − k∞) da with k(D) from Eq. 4, so fronts bend towards shallow water while the
//!   frequency, and so the animation speed, never changes (no queueing);
//! - **dispersion refraction** (Eq. 4, the option of §2.1): each point runs at its own
//!   frequency ω(D), a phase offset (ω∞ − ω(D)) t that grows with time: the queueing of Fig. 7;
//! - **round waves** (Eq. 10): Φ = (v − V/2)²/V read as a backward shift of the fronts by Φ
//!   metres, a phase k·Φ, so fronts curve forward around the middle of the box;
//! - **irregular height** (Eq. 8): A' = A − a sin(t + u) sin(v f), with the envelope written
//!   as sin(k_e (u − c_e t)) so that its speed and length are parameters;
//! - **capillary noise** (Eq. 9): y' = y + b sin(r t), r ∈ [0, 1) hashed from a seed and the
//!   grid point, so it is deterministic and independent of threads and evaluation order;
//! - **beaches** (§2, last paragraph): the trough is kept above the sea floor by capping the
//!   amplitude at a share of the depth, and the water level is raised near the shore (run-up).

use core::f64::consts::TAU;

use ocean_core::dispersion::{self, Depth};
use ocean_core::math;

/// Which depth refraction runs (§2.1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Refraction {
    /// No depth-dependent phase.
    Off,
    /// The paper's default: a depth-dependent phase shift accumulated along each ray (Fig. 6).
    PhaseShift,
    /// Frequency from the dispersion relation (Eq. 4) per point: waves slow down and queue up
    /// towards land as time passes (Fig. 7). Offered for comparison.
    Dispersion,
}

/// Capillary noise, Eq. 9.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Noise {
    /// b, metres.
    pub amplitude: f64,
    /// Seed of the per-point random rates r.
    pub seed: u64,
}

/// Irregular height along the box's width, Eq. 8.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Irregular {
    /// a, as a share of the amplitude in [0, 1].
    pub scale: f64,
    /// f, radians per metre across the box (along v).
    pub frequency: f64,
    /// Wavenumber k_e of the envelope along the box (along u), radians per metre.
    pub envelope_wavenumber: f64,
    /// Speed c_e of the envelope along u, metres per second.
    pub envelope_speed: f64,
}

/// Beach adjustments suggested at the end of §2.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Beach {
    /// Largest share of the local depth the summed amplitude may take, in (0, 1]: the trough
    /// then stays above the sea floor.
    pub max_depth_share: f64,
    /// Extra water level at the shoreline, metres, fading to 0 at `run_up_depth`.
    pub run_up: f64,
    /// Depth at which the run-up has faded out, metres.
    pub run_up_depth: f64,
}

/// The switchable effects of §2.1 and their parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Effects {
    /// Depth refraction.
    pub refraction: Refraction,
    /// Shoaling (Green's law) in shallow water.
    pub shoaling: bool,
    /// Irregular height along v (Eq. 8).
    pub irregular: Option<Irregular>,
    /// Capillary noise on every grid point (Eq. 9).
    pub noise: Option<Noise>,
    /// Round waves (Eq. 10).
    pub round_waves: bool,
    /// Beach adjustments.
    pub beach: Option<Beach>,
}

impl Default for Effects {
    /// Depth refraction by phase shift and shoaling on, as in the paper's benchmark scenarios;
    /// everything else off.
    fn default() -> Self {
        Self {
            refraction: Refraction::PhaseShift,
            shoaling: true,
            irregular: None,
            noise: None,
            round_waves: false,
            beach: None,
        }
    }
}

/// Greatest shoaling gain: Green's law grows without bound as D → 0, the paper asks for "slightly".
pub const MAX_SHOALING: f64 = 1.5;

/// Largest capillary-noise amplitude or beach run-up, metres. Far above any sea state; the
/// bound keeps every height finite in the `f32` outputs.
pub const MAX_EFFECT_HEIGHT: f64 = 1e3;
/// Largest run-up fade-out depth, metres (deeper than any ocean).
pub const MAX_EFFECT_DEPTH: f64 = 1e4;
/// Largest irregular-height frequency or envelope wavenumber, radians per metre (a 6 mm
/// period): with coordinates within [`crate::grid::MAX_COORDINATE`] (1e9 m) their phases stay
/// below 1e12 rad, where a double resolves them.
pub const MAX_EFFECT_WAVENUMBER: f64 = 1e3;
/// Largest irregular-height envelope speed, m/s.
pub const MAX_EFFECT_SPEED: f64 = 1e3;

/// Green's law shoaling factor (D_ref / D)^(1/4) for depth `depth` below the depth
/// `reference` where the waves begin to feel the bottom (half a wavelength), 1 in deeper water,
/// capped at [`MAX_SHOALING`]. `depth` ≤ 0 (land) gives 0.
pub fn shoaling(depth: f64, reference: f64) -> f64 {
    if depth <= 0.0 {
        0.0
    } else if depth >= reference {
        1.0
    } else {
        math::sqrt(math::sqrt(reference / depth)).min(MAX_SHOALING)
    }
}

/// k(D)/k∞ − 1 for a wave of deep-water wavenumber `k_deep` over `depth` (≥ 0 metres; `f64::INFINITY`
/// is deep water): how much shorter the wave is there at the same frequency (Eq. 4 against Eq. 5).
/// The integrand of the phase-shift refraction; 0 in deep water, growing as the water shoals.
pub fn shortening(k_deep: f64, depth: f64) -> f64 {
    if !(depth.is_finite()) || depth * k_deep > 20.0 {
        return 0.0;
    }
    let omega = math::sqrt(ocean_core::GRAVITY * k_deep);
    // Depth is floored at a millimetre: on the shoreline itself the amplitude is zero anyway.
    match dispersion::wavenumber(omega, Depth::Finite(depth.max(1e-3))) {
        Ok(k) => k / k_deep - 1.0,
        Err(_) => 0.0,
    }
}

/// [`shortening`] for one wavenumber, tabulated: the ray march of a box calls it at every
/// covered point, and solving the dispersion relation there each time dominated a box's
/// rebuild. In shallow water k(D)/k∞ grows like D^(−1/2) (k ≈ ω/√(gD)), so the table holds
/// h = (1 + shortening)·√D, smooth down to D → 0, at 1024 values of √D evenly spaced up to
/// where the wave no longer feels the bottom (k D = 20), interpolated linearly; the first
/// interval, where dividing by √D would magnify the error, is computed directly.
#[derive(Clone, Debug)]
pub struct ShorteningTable {
    k_deep: f64,
    step: f64,
    values: alloc::vec::Vec<f64>,
}

impl ShorteningTable {
    /// Intervals of the table (it holds one more value).
    pub const SAMPLES: usize = 1024;

    /// The spacing of the samples in √depth, √m.
    pub fn step(&self) -> f64 {
        self.step
    }

    /// The samples h(n·step) = (1 + shortening)·n·step, n = 0 ..= [`Self::SAMPLES`].
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// The table for deep-water wavenumber `k_deep` (> 0).
    pub fn new(k_deep: f64) -> Self {
        let step = math::sqrt(20.0 / k_deep) / Self::SAMPLES as f64;
        let values = (0..=Self::SAMPLES)
            .map(|n| {
                let u = n as f64 * step;
                (1.0 + shortening(k_deep, u * u)) * u
            })
            .collect();
        Self {
            k_deep,
            step,
            values,
        }
    }

    /// k(D)/k∞ − 1 at `depth`, as [`shortening`] (within 1e-4 of it, in the tests).
    pub fn get(&self, depth: f64) -> f64 {
        if !depth.is_finite() {
            return 0.0;
        }
        let u = math::sqrt(depth.max(0.0));
        let x = u / self.step;
        if x < 1.0 {
            return shortening(self.k_deep, depth);
        }
        if x >= Self::SAMPLES as f64 {
            return 0.0;
        }
        let n = x as usize;
        let f = x - n as f64;
        (self.values[n] + (self.values[n + 1] - self.values[n]) * f) / u - 1.0
    }
}

/// The dispersion option's phase offset at time `t`: (ω∞ − ω(D)) t for the deep-water
/// wavenumber `k_deep`, reduced modulo 2π in `f64`.
pub fn dispersion_phase(k_deep: f64, depth: f64, t: f64) -> f64 {
    if !depth.is_finite() {
        return 0.0;
    }
    let deep = math::sqrt(ocean_core::GRAVITY * k_deep);
    let shallow =
        dispersion::angular_frequency(k_deep, Depth::Finite(depth.max(1e-3))).unwrap_or(deep);
    ocean_core::phase::reduce_angle((deep - shallow) * t)
}

/// Round-wave phase, Eq. 10: k (v − V/2)²/V for a point `v` metres across a box `width` wide.
pub fn round_wave_phase(k: f64, v: f64, width: f64) -> f64 {
    let d = v - 0.5 * width;
    k * d * d / width
}

/// Side smoothing (Fig. 4): 0 on the box's edge, rising linearly to 1 at `smoothing` metres
/// inside. `distance` is the distance to the nearest edge (negative outside).
pub fn side_fade(distance: f64, smoothing: f64) -> f64 {
    if smoothing <= 0.0 {
        return if distance >= 0.0 { 1.0 } else { 0.0 };
    }
    (distance / smoothing).clamp(0.0, 1.0)
}

/// Irregular-height factor (Eq. 8) at internal coordinates (u, v) and time `t`:
/// 1 − a sin(k_e (u − c_e t)) sin(f v).
pub fn irregular_factor(p: &Irregular, u: f64, v: f64, t: f64) -> f64 {
    let envelope =
        ocean_core::phase::reduce_angle(p.envelope_wavenumber * (u - p.envelope_speed * t));
    let across = ocean_core::phase::reduce_angle(p.frequency * v);
    1.0 - p.scale * math::sin(envelope) * math::sin(across)
}

/// One step of the noise rates, in turns per second: 2⁻²⁴/(2π), rounded to `f32`.
pub const NOISE_TURNS_STEP: f32 = (1.0 / (16_777_216.0 * TAU)) as f32;

/// The random rate of grid point `index` for the noise seed, in turns per second: ν = n·
/// [`NOISE_TURNS_STEP`] with n the top 24 bits of SplitMix64 of the pair (Steele, Lea & Flood
/// 2014), so Eq. 9's r = 2πν is uniform on [0, 1) rad/s in steps of 2⁻²⁴. The same for a point
/// whatever the thread or order of evaluation.
///
/// The rate is an `f32` of at most 24 significant bits, counted in turns, so that a GPU forms
/// the phase ν·t modulo one turn as exactly as the CPU does in `f64` (`ocean_gpu`'s
/// `wtb_height.wgsl` splits ν and t into 12-bit parts whose products are exact).
pub fn noise_rate(seed: u64, index: u64) -> f32 {
    let mut z = seed ^ index.wrapping_mul(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^= z >> 31;
    (z >> 40) as f32 * NOISE_TURNS_STEP
}

/// Capillary noise height at grid point `index`, Eq. 9: b sin(r t) with r = 2πν
/// ([`noise_rate`]); the phase is ν·t modulo one turn, formed in `f64` (exact to 2⁻⁵³ of ν·t),
/// and its sine comes from the kernels' deterministic `sincos`.
pub fn noise_height(noise: &Noise, index: u64, t: f64) -> f64 {
    let nu = f64::from(noise_rate(noise.seed, index));
    let turns = ocean_core::phase::reduce_turns(nu * t);
    let (s, _) = ocean_core::sincos::sincos((TAU * turns) as f32);
    noise.amplitude * f64::from(s)
}

/// Largest summed amplitude the beach allows over `depth`; `f64::INFINITY` without a beach or
/// in deep water.
pub fn beach_amplitude_cap(beach: Option<&Beach>, depth: f64) -> f64 {
    match beach {
        Some(b) if depth.is_finite() => b.max_depth_share * depth.max(0.0),
        _ => f64::INFINITY,
    }
}

/// Run-up water level over `depth`: `run_up` at the shoreline, fading linearly to 0 at
/// `run_up_depth`.
pub fn run_up(beach: &Beach, depth: f64) -> f64 {
    if !depth.is_finite() || depth >= beach.run_up_depth || beach.run_up_depth <= 0.0 {
        0.0
    } else {
        beach.run_up * (1.0 - depth.max(0.0) / beach.run_up_depth)
    }
}

/// Depth at which a wave of length `wavelength` starts to feel the bottom: half its length.
pub fn shoaling_reference(wavelength: f64) -> f64 {
    0.5 * wavelength
}

/// Deep-water wavenumber of a wave of length `wavelength`.
pub fn wavenumber(wavelength: f64) -> f64 {
    TAU / wavelength
}

/// The part of the effects that the static cache depends on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct StaticKey {
    pub(crate) refraction: bool,
    pub(crate) shoaling: bool,
    pub(crate) round_waves: bool,
    pub(crate) beach: Option<Beach>,
}

impl StaticKey {
    pub(crate) fn of(e: &Effects) -> Self {
        Self {
            refraction: e.refraction == Refraction::PhaseShift,
            shoaling: e.shoaling,
            round_waves: e.round_waves,
            beach: e.beach,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec::Vec;

    #[test]
    fn greens_law() {
        // (D_ref/D)^(1/4): a sixteenth of the reference depth doubles... but the cap is 1.5,
        // reached at D = D_ref / 1.5⁴ ≈ 0.1975 D_ref.
        assert_eq!(shoaling(20.0, 10.0), 1.0);
        assert!((shoaling(10.0 / 1.6, 10.0) - 1.6f64.powf(0.25)).abs() < 1e-12);
        assert_eq!(shoaling(0.01, 10.0), MAX_SHOALING);
        assert_eq!(shoaling(0.0, 10.0), 0.0);
        assert_eq!(shoaling(-1.0, 10.0), 0.0);
    }

    #[test]
    fn shortening_follows_the_dispersion_relation() {
        // 10 s waves (k∞ = ω²/g) in 10 m of water are 92.37 m long against 156.13 m in deep
        // water (Dean & Dalrymple), so k(D)/k∞ − 1 = 156.13/92.37 − 1 = 0.690.
        let omega = TAU / 10.0;
        let k_deep = omega * omega / ocean_core::GRAVITY;
        assert!((shortening(k_deep, 10.0) - (156.13 / 92.374 - 1.0)).abs() < 2e-3);
        assert_eq!(shortening(k_deep, f64::INFINITY), 0.0);
        assert!(shortening(k_deep, 1000.0).abs() < 1e-12);
    }

    #[test]
    fn shortening_table_matches_the_direct_solution() {
        // Every depth from 1 cm to beyond k D = 20, for short and long waves.
        for lambda in [3.0, 40.0, 150.0] {
            let k = wavenumber(lambda);
            let table = ShorteningTable::new(k);
            let mut worst = 0.0f64;
            let mut d = 0.01;
            while d < 25.0 / k {
                worst = worst.max((table.get(d) - shortening(k, d)).abs());
                d *= 1.013;
            }
            assert!(worst < 1e-4, "lambda {lambda}: worst {worst:e}");
        }
    }

    #[test]
    fn dispersion_phase_grows_with_time_but_phase_shift_does_not() {
        // Fig. 7: a frequency that depends on depth gives a phase difference growing linearly in t.
        let k = wavenumber(20.0);
        let p1 = dispersion_phase(k, 2.0, 1.0);
        let p2 = dispersion_phase(k, 2.0, 2.0);
        assert!((p2 - 2.0 * p1).abs() < 1e-9 && p1 > 0.0);
        assert_eq!(dispersion_phase(k, f64::INFINITY, 100.0), 0.0);
    }

    #[test]
    fn round_waves_are_symmetric_and_zero_in_the_middle() {
        let (k, w) = (0.5, 40.0);
        assert_eq!(round_wave_phase(k, 20.0, w), 0.0);
        assert_eq!(round_wave_phase(k, 5.0, w), round_wave_phase(k, 35.0, w));
        // At the sides: k (V/2)²/V = k V/4.
        assert!((round_wave_phase(k, 0.0, w) - k * w / 4.0).abs() < 1e-12);
    }

    #[test]
    fn fades_and_factors() {
        assert_eq!(side_fade(-1.0, 5.0), 0.0);
        assert_eq!(side_fade(2.5, 5.0), 0.5);
        assert_eq!(side_fade(7.0, 5.0), 1.0);
        let p = Irregular {
            scale: 0.4,
            frequency: 0.3,
            envelope_wavenumber: 0.05,
            envelope_speed: 2.0,
        };
        // sin(f v) = 0 at v = 0: no change; extremes 1 ± a.
        assert_eq!(irregular_factor(&p, 3.0, 0.0, 1.0), 1.0);
        let mut lo = f64::MAX;
        let mut hi = f64::MIN;
        for i in 0..2000 {
            let f = irregular_factor(&p, i as f64 * 0.37, i as f64 * 0.11, 0.0);
            lo = lo.min(f);
            hi = hi.max(f);
        }
        assert!(lo >= 0.6 - 1e-12 && hi <= 1.4 + 1e-12 && lo < 0.65 && hi > 1.35);
    }

    #[test]
    fn noise_is_deterministic_and_uniform() {
        let a: Vec<f32> = (0..10_000).map(|i| noise_rate(7, i)).collect();
        let b: Vec<f32> = (0..10_000).map(|i| noise_rate(7, i)).collect();
        assert_eq!(a, b);
        assert_ne!(noise_rate(7, 3), noise_rate(8, 3));
        // r = 2πν on [0, 1) rad/s.
        let r: Vec<f64> = a.iter().map(|&nu| TAU * f64::from(nu)).collect();
        assert!(r.iter().all(|r| (0.0..1.0).contains(r)));
        // Uniform on [0, 1): mean 1/2 within 5 standard errors (σ = 1/√12/√n ≈ 0.0029).
        let mean = r.iter().sum::<f64>() / r.len() as f64;
        assert!((mean - 0.5).abs() < 5.0 * 0.0029, "mean {mean}");
        let n = Noise {
            amplitude: 0.02,
            seed: 7,
        };
        assert!(noise_height(&n, 5, 1.0e6).abs() <= 0.02);
        // The phase is ν·t: one whole period 1/ν later the height repeats (to the f64 rounding
        // of ν·t, about 10⁻¹⁶ turns here).
        let nu = f64::from(noise_rate(7, 5));
        let (h0, h1) = (
            noise_height(&n, 5, 3.0),
            noise_height(&n, 5, 3.0 + 1.0 / nu),
        );
        assert!((h0 - h1).abs() < 1e-9, "{h0} {h1}");
    }

    #[test]
    fn beach_caps_and_run_up() {
        let b = Beach {
            max_depth_share: 0.5,
            run_up: 0.3,
            run_up_depth: 2.0,
        };
        assert_eq!(beach_amplitude_cap(Some(&b), 1.0), 0.5);
        assert_eq!(beach_amplitude_cap(None, 1.0), f64::INFINITY);
        assert_eq!(run_up(&b, 0.0), 0.3);
        assert_eq!(run_up(&b, 1.0), 0.15);
        assert_eq!(run_up(&b, 3.0), 0.0);
    }
}
