//! The sampled spectrum: Eq. 1, its band energies, determinism, clamping and statistics.

use core::f64::consts::TAU;

use glam::DVec2;
use ocean_brdf::spectrum::{
    PM_ALPHA, PM_BETA, hasselmann_exponent, peak_frequency, pierson_moskowitz,
};
use ocean_brdf::{Spectrum, SpectrumParams};
use ocean_core::{GRAVITY, WaveSet};

#[test]
fn pierson_moskowitz_is_eq_1_and_peaks_where_stated() {
    // At ω = ω₀ = g/V: S = α g² / ω₀⁵ · e^{−β}.
    let v = 10.0;
    let w0 = GRAVITY / v;
    let expect = PM_ALPHA * GRAVITY * GRAVITY / w0.powi(5) * (-PM_BETA).exp();
    assert!((pierson_moskowitz(w0, v) - expect).abs() < 1e-14 * expect);
    // The peak: S is larger there than a hair to either side, and ω_p = 0.877 g/V.
    let wp = peak_frequency(v);
    assert!((wp * v / GRAVITY - (0.8f64 * 0.74).powf(0.25)).abs() < 1e-15);
    assert!((wp * v / GRAVITY - 0.8772).abs() < 1e-4);
    let s = |w| pierson_moskowitz(w, v);
    assert!(s(wp) > s(wp * (1.0 + 1e-4)) && s(wp) > s(wp * (1.0 - 1e-4)));
    assert_eq!(pierson_moskowitz(0.0, v), 0.0);
    assert_eq!(pierson_moskowitz(1.0, 0.0), 0.0);
}

#[test]
fn hasselmann_exponent_is_continuous_at_the_peak_and_narrowest_there() {
    // Below the peak s = 6.97 (ω/ω_p)^4.06, above 9.77 (ω/ω_p)^μ: at ω_p the published fit
    // jumps from 6.97 to 9.77 (it is two fits); both sides fall away from the peak.
    let v = 10.0;
    let wp = peak_frequency(v);
    assert!((hasselmann_exponent(wp, v) - 6.97).abs() < 1e-12);
    assert!((hasselmann_exponent(wp * 1.000001, v) - 9.77).abs() < 1e-3);
    assert!(hasselmann_exponent(0.5 * wp, v) < 6.97);
    assert!(hasselmann_exponent(4.0 * wp, v) < 9.77);
}

fn band_integral(v: f64, lambda_min: f64, lambda_max: f64, n_waves: usize) -> f64 {
    // ∫ S dω over the bands the waves stand for: from half a step (in log ω) beyond the
    // shortest wave to half a step beyond the longest, by the midpoint rule on 200 000 steps
    // in log ω (relative error far below 1e-8 for this smooth integrand).
    let ratio = (lambda_max / lambda_min).powf(1.0 / (n_waves - 1) as f64);
    let w = |l: f64| (GRAVITY * TAU / l).sqrt();
    let (lo, hi) = (
        w(lambda_max * ratio.sqrt()).ln(),
        w(lambda_min / ratio.sqrt()).ln(),
    );
    let n = 200_000;
    let h = (hi - lo) / n as f64;
    (0..n)
        .map(|i| {
            let x = lo + (i as f64 + 0.5) * h;
            let om = x.exp();
            pierson_moskowitz(om, v) * om * h
        })
        .sum()
}

/// (Σ A²/2 − ∫ S dω) / ∫ S dω for `waves` waves over 0.02–30 m at `v` m/s.
fn band_error(waves: usize, v: f64) -> f64 {
    let params = SpectrumParams {
        waves,
        wind_speed: v,
        ..SpectrumParams::default()
    };
    let s = Spectrum::new(params).unwrap();
    assert_eq!(s.clamped(), 0);
    let sum: f64 = s
        .waves()
        .iter()
        .map(|w| 0.5 * w.amplitude * w.amplitude)
        .sum();
    let expect = band_integral(v, 0.02, 30.0, waves);
    (sum - expect) / expect
}

#[test]
fn the_waves_carry_the_band_energy_of_the_spectrum() {
    // Each wave takes S(ω)·Δω for its band, a midpoint rule: its relative error is of order
    // (Δω/ω)²·p²/24 for a spectrum falling as ω^−p. With 60 waves over 0.02–30 m the bands are
    // Δω/ω = 6.3 % wide and p ≈ 5 (Eq. 1's tail): 4.1e-3. Four times as many waves make the bands
    // four times narrower and, the rule being of second order, the error about 16 times smaller
    // (at least 10 times, leaving room for the next order).
    for v in [10.0, 5.0, 20.0] {
        let (e60, e240) = (band_error(60, v), band_error(240, v));
        println!("{v} m/s: 60 waves {e60:+.2e}, 240 waves {e240:+.2e}");
        assert!(e60.abs() < 4.1e-3, "{v} m/s, 60 waves: {e60}");
        assert!(10.0 * e240.abs() < e60.abs(), "{v} m/s: {e240} vs {e60}");
    }
}

#[test]
fn waves_are_sorted_geometric_seeded_and_deterministic() {
    let p = SpectrumParams::default();
    let a = Spectrum::new(p).unwrap();
    let b = Spectrum::new(p).unwrap();
    let c = Spectrum::new(SpectrumParams { seed: 1, ..p }).unwrap();
    assert_eq!(a.waves(), b.waves(), "same seed, same bits");
    assert_ne!(
        a.waves(),
        c.waves(),
        "another seed, other directions and phases"
    );
    let w = a.waves();
    assert_eq!(w.len(), 60);
    assert!((w[0].wavelength - 0.02).abs() < 1e-15);
    assert!((w[59].wavelength - 30.0).abs() < 1e-11);
    let r = w[1].wavelength / w[0].wavelength;
    for pair in w.windows(2) {
        assert!((pair[1].wavelength / pair[0].wavelength - r).abs() < 1e-12);
    }
    // Every wave is valid for ocean-core and its phase in [0, 2π). (The spread of the
    // directions is tested on many draws in the crate's unit tests.)
    WaveSet::from_descs(w).unwrap();
    assert!(w.iter().all(|d| (0.0..TAU).contains(&d.phase)));
    // A wind along +z turns every direction by 90°, same draws.
    let z = Spectrum::new(SpectrumParams {
        wind_direction: DVec2::new(0.0, 2.0),
        ..p
    })
    .unwrap();
    for (a, z) in a.waves().iter().zip(z.waves()) {
        let (d, e) = (a.direction.normalize(), z.direction.normalize());
        assert!((e.x + d.y).abs() < 1e-12 && (e.y - d.x).abs() < 1e-12);
    }
}

#[test]
fn steepness_is_clamped_per_wave() {
    // In its saturation range the spectrum gives every wave about the same steepness,
    // kA = √(2α·Δω/ω) (S ≈ αg²ω⁻⁵, k = ω²/g): 0.032 for the default 60 bands. A limit of 0.03
    // clamps most of them; the default 0.5 none.
    let p = SpectrumParams::default();
    assert_eq!(Spectrum::new(p).unwrap().clamped(), 0);
    let s = Spectrum::new(SpectrumParams {
        max_steepness: 0.03,
        ..p
    })
    .unwrap();
    assert!(s.clamped() > 30, "{} clamped", s.clamped());
    for w in s.waves() {
        assert!(TAU / w.wavelength * w.amplitude <= 0.03 * (1.0 + 1e-12));
    }
}

#[test]
fn statistics_match_the_surface_they_describe() {
    // One trochoid: mean height over x is −kA²/2 and the variance about it A²/2 − (kA²/2)²,
    // measured on ocean-core's displaced surface with the trapezoid rule over x.
    let s = Spectrum::new(SpectrumParams {
        waves: 1,
        min_wavelength: 4.0,
        max_wavelength: 4.0,
        wind_speed: 30.0,
        max_steepness: 0.6,
        ..SpectrumParams::default()
    })
    .unwrap();
    // A lone wave stands for no band: zero energy, unless clamped. Use its own wave at the
    // clamp instead, rebuilt with a known amplitude along x.
    assert_eq!(s.waves()[0].amplitude, 0.0);
    let k = TAU / 4.0;
    let a = 0.6 / k;
    let desc = ocean_core::WaveDesc {
        amplitude: a,
        direction: DVec2::X,
        ..s.waves()[0]
    };
    let set = WaveSet::from_descs(&[desc]).unwrap();
    let n = 20_000;
    let pts: Vec<(f64, f64)> = (0..=n)
        .map(|i| {
            let x0 = 4.0 * i as f64 / n as f64;
            let p = set.sample_f64(DVec2::new(x0, 0.0), 0.0).unwrap();
            (x0 + p.displacement.x, p.displacement.y)
        })
        .collect();
    let integrate = |f: &dyn Fn(f64) -> f64| {
        pts.windows(2)
            .map(|w| 0.5 * (f(w[0].1) + f(w[1].1)) * (w[1].0 - w[0].0))
            .sum::<f64>()
            / 4.0
    };
    let mean = integrate(&|y| y);
    let var = integrate(&|y| y * y) - mean * mean;
    let m = -0.5 * k * a * a;
    assert!((mean - m).abs() < 1e-7, "mean {mean} vs {m}");
    assert!((var - (0.5 * a * a - m * m)).abs() < 1e-7, "variance {var}");
    // The spectrum's own statistics are those sums.
    let full = Spectrum::new(SpectrumParams::default()).unwrap();
    let w = full.waves();
    let amp: f64 = w.iter().map(|d| d.amplitude).sum();
    assert_eq!(full.max_amplitude(), amp);
    let shift: f64 = -w
        .iter()
        .map(|d| 0.5 * TAU / d.wavelength * d.amplitude * d.amplitude)
        .sum::<f64>();
    assert!((full.mean_height_shift() - shift).abs() < 1e-15);
    assert!(full.height_variance() > 0.0 && full.steepness_sum() > 0.0);
}

#[test]
fn bad_parameters_are_refused() {
    let p = SpectrumParams::default();
    for bad in [
        SpectrumParams {
            wind_speed: f64::NAN,
            ..p
        },
        SpectrumParams {
            wind_speed: 0.0,
            ..p
        },
        SpectrumParams {
            wind_direction: DVec2::ZERO,
            ..p
        },
        SpectrumParams {
            wind_direction: DVec2::new(f64::INFINITY, 0.0),
            ..p
        },
        SpectrumParams { waves: 0, ..p },
        SpectrumParams { waves: 5000, ..p },
        SpectrumParams {
            min_wavelength: -1.0,
            ..p
        },
        SpectrumParams {
            max_wavelength: 0.01,
            ..p
        },
        SpectrumParams {
            max_wavelength: 0.02,
            ..p
        },
        SpectrumParams {
            max_steepness: 1.5,
            ..p
        },
    ] {
        assert!(Spectrum::new(bad).is_err(), "{bad:?}");
    }
}
