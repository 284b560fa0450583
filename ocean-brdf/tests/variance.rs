//! Slope variances (Eq. 4, Appendix A) against the trochoid's own geometry.

use core::f64::consts::TAU;

use glam::DVec2;
use ocean_brdf::variance::{SUN_MIN_VARIANCE, trochoid_slope_variance};
use ocean_brdf::{Filter, SlopeVariance, Spectrum, SpectrumParams, VarianceTable};
use ocean_core::{Depth, WaveDesc, WaveSet};

fn wave(amplitude: f64, wavelength: f64, direction: DVec2) -> WaveDesc {
    WaveDesc {
        amplitude,
        wavelength,
        direction,
        phase: 0.3,
        depth: Depth::Deep,
    }
}

/// The mean of the squared slope over one wavelength of the displaced surface, integrated over
/// x (not over the rest parameter) with the trapezoid rule on `n` rest points, using
/// ocean-core's own f64 trochoid: the slope is −n_x / n_y of its normal.
fn measured_slope_variance(ka: f64, n: usize) -> f64 {
    let lambda = 7.0;
    let k = TAU / lambda;
    let set = WaveSet::from_descs(&[wave(ka / k, lambda, DVec2::X)]).unwrap();
    let point = |s: f64| {
        let p = set.sample_f64(DVec2::new(s, 0.0), 0.0).unwrap();
        let slope = -p.normal.x / p.normal.y;
        (s + p.displacement.x, slope * slope)
    };
    let mut sum = 0.0;
    let mut prev = point(0.0);
    for i in 1..=n {
        let next = point(lambda * i as f64 / n as f64);
        sum += 0.5 * (prev.1 + next.1) * (next.0 - prev.0);
        prev = next;
    }
    sum / lambda
}

#[test]
fn appendix_a_matches_the_trochoid_geometry() {
    // Appendix A: the slope variance of a trochoid is 1 − √(1 − k²h²). Measured on the surface
    // ocean-core actually displaces, from gentle to nearly cusped waves. Near the cusp the
    // slope peaks sharply (at kA = 0.95 it reaches ~3), so the quadrature needs many points;
    // with 20 000 the trapezoid error is below 1e-6 relative here.
    for ka in [0.01f64, 0.1, 0.3, 0.5, 0.7, 0.9, 0.95] {
        let expect = 1.0 - (1.0 - ka * ka).sqrt();
        let got = measured_slope_variance(ka, 20_000);
        let closed = trochoid_slope_variance(ka);
        assert!(
            ((got - expect) / expect).abs() < 1e-6,
            "kA = {ka}: measured {got}, Appendix A {expect}"
        );
        assert!(((closed - expect) / expect).abs() < 1e-12, "kA = {ka}");
    }
    // Small steepness: 1 − √(1 − x) = x/2 + x²/8 + …, x = k²A²: a sine's k²A²/2, digits kept.
    let v = trochoid_slope_variance(1e-4);
    assert!((v - (0.5e-8 + 1.25e-17)).abs() < 1e-24, "{v}");
}

#[test]
fn eq4_splits_each_wave_between_the_wind_axes() {
    let along = wave(0.1, 5.0, DVec2::new(2.0, 0.0));
    let across = wave(0.1, 5.0, DVec2::new(0.0, -1.0));
    let diagonal = wave(0.1, 5.0, DVec2::new(1.0, 1.0));
    let v = trochoid_slope_variance(TAU / 5.0 * 0.1);
    let t = VarianceTable::new(&[along], DVec2::X).unwrap().total();
    assert_eq!((t.x, t.y), (v, 0.0));
    let t = VarianceTable::new(&[across], DVec2::X).unwrap().total();
    assert!(t.x.abs() < 1e-18 && (t.y - v).abs() < 1e-18);
    let t = VarianceTable::new(&[diagonal], DVec2::X).unwrap().total();
    assert!((t.x - 0.5 * v).abs() < 1e-17 && (t.y - 0.5 * v).abs() < 1e-17);
    // The wind frame follows the wind: the same wave across a wind along +z is "along".
    let t = VarianceTable::new(&[across], DVec2::new(0.0, 3.0))
        .unwrap()
        .total();
    assert!((t.x - v).abs() < 1e-18 && t.y.abs() < 1e-18);
    assert!(VarianceTable::new(&[along], DVec2::ZERO).is_err());
}

#[test]
fn total_minus_resolved_equals_the_direct_sum() {
    // §7.1: Eq. 4 as the total minus the resolved waves' share must equal Eq. 4 summed over
    // every wave, from pixels that resolve everything to pixels that resolve nothing.
    let spectrum = Spectrum::new(SpectrumParams::default()).unwrap();
    let table = spectrum.variance();
    let filter = Filter::PAPER;
    for pixel in [0.0, 1e-3, 0.01, 0.05, 0.2, 1.0, 3.0, 12.0, 40.0, 1e4] {
        let a = table.unresolved(&filter, pixel);
        let b = table.unresolved_direct(&filter, pixel);
        let scale = table.total().x + table.total().y;
        assert!(
            (a.x - b.x).abs() <= 1e-13 * scale && (a.y - b.y).abs() <= 1e-13 * scale,
            "pixel {pixel}: {a:?} vs {b:?}"
        );
    }
    // Everything resolved: nothing left for the BRDF but the rounding of total − Σ (ulps of
    // the total). Nothing resolved: all of it, untouched.
    let total = table.total();
    let none = table.unresolved(&filter, 0.0);
    assert!(
        none.x <= 1e-15 * total.x && none.y <= 1e-15 * total.y,
        "{none:?}"
    );
    assert_eq!(table.unresolved(&filter, 1e4), total);
}

#[test]
fn unresolved_variance_grows_with_the_pixel() {
    let spectrum = Spectrum::new(SpectrumParams::default()).unwrap();
    let table = spectrum.variance();
    let mut last = -1.0;
    for i in 0..60 {
        let pixel = 1e-3 * 1.2f64.powi(i);
        let v = table.unresolved(&Filter::PAPER, pixel);
        let s = v.x + v.y;
        assert!(s >= last, "pixel {pixel}: {s} < {last}");
        last = s;
    }
}

#[test]
fn the_sun_minimum_is_the_disc_matched_variance() {
    // ρ = 4.653e-3 rad: (ρ/2)²/4 = ρ²/16 = 1.3532e-6.
    assert!((SUN_MIN_VARIANCE - 1.3532e-6).abs() < 1e-10);
    let v = SlopeVariance { x: 0.0, y: 0.2 }.at_least(SUN_MIN_VARIANCE);
    assert_eq!((v.x, v.y), (SUN_MIN_VARIANCE, 0.2));
}
