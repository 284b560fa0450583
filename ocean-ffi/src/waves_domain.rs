//! Where a wave set's results are finite and meaningful, checked before anything is written.
//!
//! A trochoid's phase k·p₀ − ωt + Φ is formed and reduced in double precision. Beyond
//! [`PHASE_LIMIT`] radians a double no longer resolves the phase (its spacing there is 0.125
//! rad), and far beyond it k·p₀ or ωt overflows to infinity and every output becomes NaN. The
//! displaced positions are floats: a set whose amplitudes add up past [`AMPLITUDE_SUM_LIMIT`]
//! could displace a point to infinity. Inputs outside this domain are refused with
//! `OCEAN_STATUS_INVALID_ARGUMENT`, naming the input and the bound it breaks, instead of
//! returning non-finite results behind `OCEAN_STATUS_OK`.

use glam::DVec2;
use ocean_core::{Grid, Wave, WaveSet};

use crate::boundary::{Approx, Num};
use crate::status::{Error, OceanStatus};

/// The largest |k·p₀| or |ω·t|, radians, whose phase a double still resolves to 1/8 rad.
pub(crate) const PHASE_LIMIT: f64 = 1e15;

/// The largest sum of a set's amplitudes, metres: far enough below `FLT_MAX` (3.4e38) that no
/// float position plus the largest displacement overflows.
pub(crate) const AMPLITUDE_SUM_LIMIT: f64 = 1e30;

/// The fastest and shortest wave of a set: what bounds its phases.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Reach {
    k_max: f64,
    omega_max: f64,
}

fn invalid(message: String) -> Error {
    Error::new(OceanStatus::InvalidArgument, message)
}

impl Reach {
    /// The reach of `set`, refusing a set whose amplitudes add up past the limit.
    pub(crate) fn of(set: &WaveSet) -> Result<Self, Error> {
        Self::of_waves(set.waves().iter().copied())
    }

    /// The reach of a spectrum's waves (deep water, each well below the limits).
    #[cfg(feature = "gpu")]
    pub(crate) fn of_spectrum(spectrum: &ocean_brdf::Spectrum) -> Result<Self, Error> {
        let waves: Vec<Wave> = spectrum
            .waves()
            .iter()
            .filter_map(|d| d.build().ok())
            .collect();
        Self::of_waves(waves.into_iter())
    }

    fn of_waves(waves: impl Iterator<Item = Wave> + Clone) -> Result<Self, Error> {
        let amplitude_sum: f64 = waves.clone().map(|w| w.amplitude()).sum();
        if amplitude_sum > AMPLITUDE_SUM_LIMIT {
            return Err(invalid(format!(
                "the amplitudes add up to {} m, above {} m: a displaced position would overflow \
                 a float",
                Approx(amplitude_sum),
                Approx(AMPLITUDE_SUM_LIMIT)
            )));
        }
        Ok(Self {
            k_max: waves.clone().map(|w| w.wavenumber()).fold(0.0, f64::max),
            omega_max: waves.map(|w| w.angular_frequency()).fold(0.0, f64::max),
        })
    }

    /// Refuses a finite `time` whose phase ω·t leaves the limit for the fastest wave.
    pub(crate) fn check_time(&self, time: f64) -> Result<(), Error> {
        if (time * self.omega_max).abs() <= PHASE_LIMIT {
            return Ok(());
        }
        Err(invalid(format!(
            "`time` = {} s puts the phase of the fastest wave (omega = {} rad/s) beyond {} rad, \
             where a double no longer resolves it: |time| must be <= {} s for this set",
            Num(time),
            Approx(self.omega_max),
            Approx(PHASE_LIMIT),
            Approx(PHASE_LIMIT / self.omega_max)
        )))
    }

    /// The largest |x| or |z| whose phase k·x stays within the limit for the shortest wave.
    fn max_coordinate(&self) -> f64 {
        PHASE_LIMIT / self.k_max
    }

    /// Refuses the first world rest position `name[i]` whose phase leaves the limit. NaN and
    /// infinite coordinates pass: the evaluation refuses them with `OCEAN_STATUS_NON_FINITE`.
    pub(crate) fn check_points(&self, name: &str, points: &[DVec2]) -> Result<(), Error> {
        let most = self.max_coordinate();
        // Infinities are left to the evaluation too, which reports them as non-finite.
        let beyond = |c: f64| c.is_finite() && c.abs() > most;
        let far = points.iter().position(|p| beyond(p.x) || beyond(p.y));
        match far {
            None => Ok(()),
            Some(i) => Err(invalid(format!(
                "{name}[{i}] = ({}, {}) lies beyond {} m from the origin, where the phase k*x of \
                 the shortest wave (k = {} rad/m) passes {} rad",
                Num(points[i].x),
                Num(points[i].y),
                Approx(most),
                Approx(self.k_max),
                Approx(PHASE_LIMIT)
            ))),
        }
    }

    /// Refuses a grid whose far corner (world coordinates) leaves the phase limit, or whose
    /// extent from its origin does not fit in a float.
    pub(crate) fn check_grid(&self, name: &str, grid: &Grid) -> Result<(), Error> {
        let (nx, nz) = grid.size;
        let steps = DVec2::new(nx.saturating_sub(1) as f64, nz.saturating_sub(1) as f64);
        // The spacing itself is a float in the kernel: a 1 x 1 grid of spacing 2.6e151 has no
        // extent but gave NaN at point (0, 0) (0 times an infinite float spacing).
        let extent = (grid.spacing * steps).max(grid.spacing);
        if extent.max_element() > f64::from(f32::MAX) / 2.0 {
            return Err(invalid(format!(
                "{name}: the grid extends {} m from its origin, which a float cannot hold",
                Approx(extent.max_element())
            )));
        }
        let far = grid.origin.abs() + extent;
        if far.max_element() > self.max_coordinate() {
            return Err(invalid(format!(
                "{name}: the grid reaches {} m from the world origin, where the phase k*x of the \
                 shortest wave (k = {} rad/m) passes {} rad (the limit is {} m)",
                Approx(far.max_element()),
                Approx(self.k_max),
                Approx(PHASE_LIMIT),
                Approx(self.max_coordinate())
            )));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::status::last_error;
    use crate::waves::{
        OceanDVec2, OceanDVec3, OceanGrid, OceanVec3, OceanWaveDesc, OceanWaves,
        ocean_waves_create, ocean_waves_destroy, ocean_waves_evaluate, ocean_waves_evaluate_grid,
    };

    fn desc(amplitude: f64, wavelength: f64) -> OceanWaveDesc {
        OceanWaveDesc {
            amplitude,
            wavelength,
            direction_x: 1.0,
            direction_z: 0.0,
            phase: 0.0,
            depth: f64::INFINITY,
        }
    }

    fn create(descs: &[OceanWaveDesc]) -> Result<*mut OceanWaves, OceanStatus> {
        let mut w = core::ptr::null_mut();
        // SAFETY: `descs.len()` readable descriptions, a writable out.
        match unsafe { ocean_waves_create(descs.as_ptr(), descs.len(), &mut w) } {
            OceanStatus::Ok => Ok(w),
            s => Err(s),
        }
    }

    /// Evaluates one point; the outputs start as a sentinel and are returned with the status.
    fn evaluate(w: *const OceanWaves, x: f64, time: f64) -> (OceanStatus, OceanVec3, OceanVec3) {
        let xz = [OceanDVec2 { x, z: 0.5 }];
        let sentinel = OceanVec3 {
            x: 7.0,
            y: 7.0,
            z: 7.0,
        };
        let mut p = [OceanDVec3 {
            x: 7.0,
            y: 7.0,
            z: 7.0,
        }];
        let mut n = [sentinel];
        // SAFETY: one readable point, one writable position and normal.
        let s = unsafe {
            ocean_waves_evaluate(w, xz.as_ptr(), 1, time, p.as_mut_ptr(), n.as_mut_ptr())
        };
        // The position in float: every test here asks only whether it is finite.
        let p = OceanVec3 {
            x: p[0].x as f32,
            y: p[0].y as f32,
            z: p[0].z as f32,
        };
        (s, p, n[0])
    }

    fn finite(v: OceanVec3) -> bool {
        v.x.is_finite() && v.y.is_finite() && v.z.is_finite()
    }

    #[test]
    fn a_time_past_the_phase_limit_is_refused_and_one_within_it_is_finite() {
        // One 20 m deep-water wave: omega = sqrt(g k), k = 2 pi / 20.
        let w = create(&[desc(1.0, 20.0)]).unwrap();
        let omega = (ocean_core::GRAVITY * core::f64::consts::TAU / 20.0).sqrt();
        let limit = PHASE_LIMIT / omega;
        for time in [f64::MAX, -f64::MAX, 1e300, limit * 1.0001] {
            let (s, p, n) = evaluate(w, 1.0, time);
            assert_eq!(s, OceanStatus::InvalidArgument, "time {time}");
            assert!(last_error().contains("`time`"), "{}", last_error());
            assert_eq!((p.x, n.x), (7.0, 7.0), "written on failure");
        }
        for time in [limit * 0.9999, -limit * 0.9999, 1e6, 0.0] {
            let (s, p, n) = evaluate(w, 1.0, time);
            assert_eq!(s, OceanStatus::Ok, "time {time}: {}", last_error());
            assert!(finite(p) && finite(n), "time {time}: {p:?} {n:?}");
        }
        ocean_waves_destroy(w);
    }

    #[test]
    fn a_position_past_the_phase_limit_is_refused() {
        let w = create(&[desc(1.0, 20.0)]).unwrap();
        let k = core::f64::consts::TAU / 20.0;
        let (s, p, _) = evaluate(w, f64::from(f32::MAX), 0.0);
        assert_eq!(s, OceanStatus::InvalidArgument);
        assert!(last_error().contains("xz[0]"), "{}", last_error());
        assert_eq!(p.x, 7.0);
        let inside = PHASE_LIMIT / k * 0.999;
        let (s, p, n) = evaluate(w, inside, 0.0);
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        assert!(finite(p) && finite(n));
        ocean_waves_destroy(w);
    }

    #[test]
    fn amplitudes_that_overflow_a_float_when_aligned_are_refused() {
        // Eight aligned waves, each at most a cusp (k A <= 1), whose sum 4.6e38 m exceeds
        // FLT_MAX: their crests would add up to an infinite height.
        let each = [desc(5.7e37, 4.0e38); 8];
        assert_eq!(create(&each), Err(OceanStatus::InvalidArgument));
        assert!(
            last_error().contains("add up to 4.56e38 m"),
            "{}",
            last_error()
        );
        // At the limit the sum is finite in a float.
        let w = create(&[desc(AMPLITUDE_SUM_LIMIT / 2.0, 1e31); 2]).unwrap();
        let (s, p, n) = evaluate(w, 0.0, 0.0);
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        assert!(finite(p) && finite(n), "{p:?} {n:?}");
        ocean_waves_destroy(w);
    }

    #[test]
    fn a_grid_a_float_cannot_hold_or_beyond_the_phase_limit_is_refused() {
        let w = create(&[desc(1.0, 20.0)]).unwrap();
        let sentinel = OceanVec3 {
            x: 7.0,
            y: 7.0,
            z: 7.0,
        };
        let run = |g: OceanGrid| {
            let (mut p, mut n) = ([sentinel; 4], [sentinel; 4]);
            // SAFETY: a readable grid of 2 x 2 points, four writable outputs each.
            let s =
                unsafe { ocean_waves_evaluate_grid(w, &g, 0.0, p.as_mut_ptr(), n.as_mut_ptr()) };
            (s, p, n)
        };
        let grid = |spacing_x: f64, origin_x: f64| OceanGrid {
            origin_x,
            origin_z: 0.0,
            spacing_x,
            spacing_z: 1.0,
            nx: 2,
            nz: 2,
        };
        for (g, needle) in [
            (grid(1e300, 0.0), "float cannot hold"),
            (grid(1.0, 1e17), "the limit"),
        ] {
            let (s, p, _) = run(g);
            assert_eq!(s, OceanStatus::InvalidArgument);
            assert!(last_error().contains(needle), "{}", last_error());
            assert!(p.iter().all(|v| v.x == 7.0), "written on failure");
        }
        // A 1 x 1 grid has no extent, but its spacing is a float in the kernel too.
        let single = OceanGrid {
            nx: 1,
            nz: 1,
            ..grid(2.57e151, 0.0)
        };
        let (s, p, _) = run(single);
        assert_eq!(s, OceanStatus::InvalidArgument, "{}", last_error());
        assert_eq!(p[0].x, 7.0);
        let (s, p, n) = run(grid(1e6, 1e9));
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        assert!(p.iter().chain(&n).all(|v| finite(*v)));
        ocean_waves_destroy(w);
    }

    #[test]
    fn a_side_over_2_pow_24_is_refused_for_its_side_not_as_overlapping_outputs() {
        let w = create(&[desc(1.0, 20.0)]).unwrap();
        // Two neighbouring output arrays sized for a valid grid: their ranges for 2^24 + 1
        // points would overlap, but the side is what is wrong.
        let mut storage = [OceanVec3::default(); 8];
        let (a, b) = storage.split_at_mut(4);
        let g = OceanGrid {
            origin_x: 0.0,
            origin_z: 0.0,
            spacing_x: 1.0,
            spacing_z: 1.0,
            nx: (1 << 24) + 1,
            nz: 1,
        };
        // SAFETY: refused before any access.
        let s = unsafe { ocean_waves_evaluate_grid(w, &g, 0.0, a.as_mut_ptr(), b.as_mut_ptr()) };
        assert_eq!(s, OceanStatus::InvalidArgument);
        assert!(last_error().contains("2^24"), "{}", last_error());
        ocean_waves_destroy(w);
    }
}
