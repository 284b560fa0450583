//! Winds (§2): Eq. 1, the lifecycle of a box and the seeded mapping to wave trains.

use std::f64::consts::{PI, TAU};
use std::fmt::Write;

use glam::DVec2;
use ocean_core::{Depth, WaveDesc};
use ocean_wtb::WtbError;
use ocean_wtb::wind::{
    LifePhase, MAX_TOTAL_STEEPNESS, MAX_TRAIN_STEEPNESS, SPREAD, TrainSource, Wind, crest_height,
    fully_developed_height, limit_steepness, peak_wavelength, steepness, total_steepness,
};

fn wind() -> Wind {
    Wind {
        speed: 10.0,
        direction: DVec2::new(3.0, 4.0),
        origin: DVec2::new(-50.0, 20.0),
        width: 200.0,
        fetch: 1000.0,
        start: 100.0,
        build_up: 10.0,
        sustain: 20.0,
        decay: 5.0,
        seed: 7,
        trains: 3,
    }
}

#[test]
fn eq1_fully_developed_height() {
    // H = 0.21 h²/g with g = 9.81: 10 m/s → 21/9.81 = 2.140673 m; 20 m/s → 4× that; 5 m/s → ¼.
    assert!((fully_developed_height(10.0) - 2.140_672_782_874_6).abs() < 1e-12);
    assert!((fully_developed_height(20.0) - 8.562_691_131_498_5).abs() < 1e-12);
    assert!((fully_developed_height(5.0) - 0.535_168_195_718_65).abs() < 1e-12);
    assert_eq!(wind().height(), fully_developed_height(10.0));
    // Pierson–Moskowitz peak: ω_p = 0.877·9.81/10 = 0.860337 rad/s, λ_p = 2πg/ω_p² = 83.2744 m.
    assert!((peak_wavelength(10.0) - 83.274_431_063_84).abs() < 1e-9);
    // λ_p grows as h²: 20 m/s → 333.0977 m.
    assert!((peak_wavelength(20.0) - 333.097_724_255_36).abs() < 1e-8);
}

#[test]
fn lifecycle_phases() {
    let w = wind(); // start 100 s, build-up 10 s, sustain 20 s, decay 5 s, fetch 1000 m
    assert_eq!(w.state(99.999), None);
    assert_eq!(w.state(f64::NAN), None);
    let s = w.state(100.0).unwrap();
    assert_eq!(
        (s.phase, s.length, s.envelope),
        (LifePhase::BuildUp, 0.0, 0.0)
    );
    // Half-way through build-up: half the fetch, half the amplitude.
    let s = w.state(105.0).unwrap();
    assert_eq!(
        (s.phase, s.length, s.envelope, s.age),
        (LifePhase::BuildUp, 500.0, 0.5, 5.0)
    );
    let s = w.state(110.0).unwrap();
    assert_eq!(
        (s.phase, s.length, s.envelope),
        (LifePhase::Sustain, 1000.0, 1.0)
    );
    let s = w.state(130.0).unwrap();
    assert_eq!(
        (s.phase, s.length, s.envelope),
        (LifePhase::Sustain, 1000.0, 1.0)
    );
    // Decay: full length, the envelope falls to 0 at 135 s.
    let s = w.state(132.5).unwrap();
    assert_eq!(
        (s.phase, s.length, s.envelope),
        (LifePhase::Decay, 1000.0, 0.5)
    );
    let s = w.state(135.0).unwrap();
    assert_eq!((s.phase, s.envelope), (LifePhase::Decay, 0.0));
    assert_eq!(w.state(135.001), None);
    assert_eq!(w.lifetime(), 35.0);
}

#[test]
fn lifecycle_is_continuous() {
    // Length changes at most fetch/B = 100 m/s and the envelope at most 1/min(B, D) = 0.2 /s:
    // over a step of 1 ms no jump may exceed 0.1 m or 2e-4 (with rounding slack), also across
    // the phase boundaries at 110 s and 130 s.
    let w = wind();
    let dt = 1e-3;
    let mut prev = w.state(100.0).unwrap();
    let mut n = 1;
    while n <= 35_000 {
        let t = 100.0 + n as f64 * dt;
        let s = w.state(t).unwrap_or_else(|| panic!("box exists at {t}"));
        assert!(
            (s.length - prev.length).abs() <= 100.0 * dt * (1.0 + 1e-6),
            "length at {t}"
        );
        assert!(
            (s.envelope - prev.envelope).abs() <= 0.2 * dt * (1.0 + 1e-6),
            "envelope at {t}"
        );
        prev = s;
        n += 1;
    }
    // Either side of each boundary, 1 ns apart, the values agree within 1e-6.
    for tb in [110.0, 130.0] {
        let a = w.state(tb - 1e-9).unwrap();
        let b = w.state(tb + 1e-9).unwrap();
        assert!((a.length - b.length).abs() < 1e-6 && (a.envelope - b.envelope).abs() < 1e-6);
    }
}

#[test]
fn instant_build_up_and_endless_wind() {
    // B = 0: the box appears at full size; S = ∞: it never dies.
    let w = Wind {
        build_up: 0.0,
        sustain: f64::INFINITY,
        ..wind()
    };
    w.validate().unwrap();
    let s = w.state(100.0).unwrap();
    assert_eq!(
        (s.phase, s.length, s.envelope),
        (LifePhase::Sustain, 1000.0, 1.0)
    );
    assert!(w.state(1e12).is_some());
    // D = 0: it vanishes at full amplitude after B + S.
    let w = Wind {
        decay: 0.0,
        ..wind()
    };
    assert_eq!(w.state(130.0).unwrap().envelope, 1.0);
    assert_eq!(w.state(130.000_001), None);
}

#[test]
fn frame_follows_the_wind() {
    let w = wind();
    // At 105 s the box is 500 m long, 200 m wide, along (0.6, 0.8), with corner at the origin.
    let f = w.frame(105.0, 2.0).unwrap().unwrap();
    assert_eq!(f.length(), 500.0);
    assert_eq!(f.width(), 200.0);
    assert_eq!(f.origin(), DVec2::new(-50.0, 20.0));
    assert!((f.u() - DVec2::new(0.6, 0.8)).length() < 1e-15);
    assert_eq!(f.spacing(), 2.0);
    assert_eq!(w.frame(99.0, 2.0), Ok(None));
    assert!(w.frame(105.0, 0.0).is_err());
}

#[test]
fn seeded_trains_are_deterministic() {
    let w = wind();
    let a = w.trains().unwrap();
    assert_eq!(a.len(), 3);
    assert_eq!(a, w.trains().unwrap(), "same seed, same trains");
    let b = Wind { seed: 8, ..w }.trains().unwrap();
    assert_ne!(a, b, "another seed, other trains");
    // Train 0 is the peak: λ_p along the wind; the rest within [0.5, 1.5)·λ_p and ±30°.
    let lp = peak_wavelength(10.0);
    let u = DVec2::new(0.6, 0.8);
    assert_eq!(a[0].wavelength, lp);
    assert!((a[0].direction - u).length() < 1e-15);
    for seed in 0..200u64 {
        for n in 1..=8u32 {
            let t = Wind {
                seed,
                trains: n,
                ..w
            }
            .trains()
            .unwrap();
            assert_eq!(t.len(), n as usize);
            for d in &t {
                assert!(d.wavelength >= 0.5 * lp && d.wavelength < 1.5 * lp);
                let cos = d.direction.normalize().dot(u);
                assert!(cos >= SPREAD.cos() - 1e-12, "direction outside ±30°");
                assert!((0.0..TAU).contains(&d.phase));
                assert_eq!(d.depth, Depth::Deep);
                assert!(d.amplitude > 0.0);
            }
            // Amplitudes sum to H/2 = 1.0703 m (no clamping: see the next test).
            assert!((crest_height(&t) - 0.5 * w.height()).abs() < 1e-12);
            for d in &t {
                d.build().unwrap();
            }
        }
    }
    // Only the seed matters, not the wind's other fields: trains are a function of
    // (speed, direction, seed, count).
    let moved = Wind {
        origin: DVec2::new(1e6, 0.0),
        start: -5.0,
        ..w
    };
    assert_eq!(moved.trains().unwrap(), a);
}

#[test]
fn wind_trains_are_never_steep() {
    // A fully developed PM peak has k·H/2 = 0.877²·0.21/2 = 0.0808 at every speed; with the
    // shortest trains at half the peak wavelength the summed steepness stays below 2·0.0808.
    for speed in [0.5, 3.0, 10.0, 25.0, 60.0, 100.0] {
        for seed in 0..100u64 {
            let t = Wind {
                speed,
                seed,
                trains: 8,
                ..wind()
            }
            .trains()
            .unwrap();
            let total = total_steepness(&t);
            assert!(
                total <= 2.0 * 0.081,
                "speed {speed} seed {seed}: Σ kA = {total}"
            );
            assert!(t.iter().all(|d| steepness(d) <= MAX_TRAIN_STEEPNESS));
            assert!(
                (crest_height(&t) - 0.5 * fully_developed_height(speed)).abs()
                    < 1e-12 * fully_developed_height(speed)
            );
        }
        // A single train is the peak with k_p·H/2 = 0.080759 exactly as the PM figures give.
        let one = Wind {
            speed,
            trains: 1,
            ..wind()
        }
        .trains()
        .unwrap();
        assert!((steepness(&one[0]) - 0.080_758_545).abs() < 1e-9);
    }
}

#[test]
fn steepness_limits() {
    // Three trains of λ = 10 m, A = 5 m (k·A = π): each is clamped to k·A = 0.5 (A = 5/2π m),
    // the sum 1.5 is then scaled by 2/3 to 1.
    let d = WaveDesc {
        amplitude: 5.0,
        wavelength: 10.0,
        direction: DVec2::X,
        phase: 0.0,
        depth: Depth::Deep,
    };
    let mut t = vec![d; 3];
    let f = limit_steepness(&mut t, MAX_TRAIN_STEEPNESS, MAX_TOTAL_STEEPNESS);
    assert!((f - 2.0 / 3.0).abs() < 1e-15);
    for x in &t {
        assert!((x.amplitude - (10.0 / (2.0 * PI)) * 0.5 * (2.0 / 3.0)).abs() < 1e-14);
    }
    assert!(total_steepness(&t) <= 1.0 + 4.0 * f64::EPSILON);
    // Gentle trains are left alone.
    let gentle = WaveDesc {
        amplitude: 0.1,
        ..d
    };
    let mut g = vec![gentle; 2];
    assert_eq!(limit_steepness(&mut g, 0.5, 1.0), 1.0);
    assert_eq!(g, vec![gentle; 2]);
}

#[test]
fn explicit_trains() {
    let w = wind();
    let d = WaveDesc {
        amplitude: 0.5,
        wavelength: 20.0,
        direction: DVec2::new(1.0, 1.0),
        phase: 1.0,
        depth: Depth::Deep,
    };
    // Passed through unchanged.
    assert_eq!(TrainSource::Explicit(vec![d]).resolve(&w).unwrap(), vec![d]);
    assert_eq!(
        TrainSource::FromWind.resolve(&w).unwrap(),
        w.trains().unwrap()
    );
    // Two trains of k·A = 0.6 each sum to 1.2 > 1: the box could fold.
    let steep = WaveDesc {
        amplitude: 0.6 * 20.0 / TAU,
        ..d
    };
    match TrainSource::Explicit(vec![steep, steep]).resolve(&w) {
        Err(WtbError::TooSteep { total, max }) => {
            assert!((total - 1.2).abs() < 1e-12);
            assert_eq!(max, 1.0);
        }
        other => panic!("expected TooSteep, got {other:?}"),
    }
    assert!(matches!(
        TrainSource::Explicit(vec![
            d,
            WaveDesc {
                wavelength: f64::NAN,
                ..d
            }
        ])
        .resolve(&w),
        Err(WtbError::Wave { index: 1, .. })
    ));
    assert!(matches!(
        TrainSource::Explicit(vec![]).resolve(&w),
        Err(WtbError::OutOfRange { .. })
    ));
}

#[test]
fn rejects_bad_winds() {
    let ok = wind();
    ok.validate().unwrap();
    let bad = [
        Wind { speed: 0.0, ..ok },
        Wind { speed: -3.0, ..ok },
        Wind {
            speed: f64::NAN,
            ..ok
        },
        Wind { speed: 101.0, ..ok },
        Wind {
            direction: DVec2::ZERO,
            ..ok
        },
        Wind {
            direction: DVec2::new(f64::INFINITY, 0.0),
            ..ok
        },
        Wind {
            origin: DVec2::new(f64::NAN, 0.0),
            ..ok
        },
        Wind { width: 0.0, ..ok },
        Wind {
            fetch: f64::NAN,
            ..ok
        },
        Wind { fetch: -1.0, ..ok },
        Wind {
            start: f64::INFINITY,
            ..ok
        },
        Wind {
            build_up: -1.0,
            ..ok
        },
        Wind {
            sustain: f64::NAN,
            ..ok
        },
        Wind {
            decay: f64::INFINITY,
            ..ok
        },
        Wind { trains: 0, ..ok },
        Wind { trains: 9, ..ok },
    ];
    for (n, w) in bad.iter().enumerate() {
        assert!(w.validate().is_err(), "case {n}");
        assert!(w.trains().is_err(), "case {n}");
        assert!(w.frame(105.0, 1.0).is_err(), "case {n}");
    }
    assert!(matches!(
        Wind {
            direction: DVec2::ZERO,
            ..ok
        }
        .validate(),
        Err(WtbError::ZeroDirection(_))
    ));
}

#[test]
fn trains_snapshot() {
    // The mapping is part of the contract (networked games replay winds from their seeds):
    // any change to it shows here.
    let mut out = String::new();
    for (speed, seed, n) in [(10.0, 7u64, 3u32), (4.0, 1, 1), (18.0, 12345, 8)] {
        let w = Wind {
            speed,
            seed,
            trains: n,
            ..wind()
        };
        writeln!(out, "speed {speed} seed {seed}:").unwrap();
        for d in w.trains().unwrap() {
            writeln!(
                out,
                "  A={:.6} λ={:.6} dir=({:.6}, {:.6}) Φ={:.6}",
                d.amplitude, d.wavelength, d.direction.x, d.direction.y, d.phase
            )
            .unwrap();
        }
    }
    insta::assert_snapshot!(out);
}

#[test]
fn winds_too_weak_to_raise_gravity_waves_are_refused() {
    // The slowest wind accepted, 0.1 m/s, peaks at λ_p = 2π·0.1²/(0.877²·9.81) = 8.33 mm,
    // the capillary limit; 5e-324 m/s would give λ_p = 0 and infinite wavenumbers.
    use ocean_wtb::wind::MIN_WIND_SPEED;
    assert!((peak_wavelength(MIN_WIND_SPEED) - 0.008_327_443_106_384).abs() < 1e-12);
    for speed in [5e-324, 1e-3, MIN_WIND_SPEED * (1.0 - 1e-15)] {
        let w = Wind { speed, ..wind() };
        let e = w.validate().unwrap_err();
        assert!(
            matches!(e, WtbError::OutOfRange { name: "speed", .. }),
            "{e}"
        );
    }
    // The message prints 5e-324 as such, not as 324 digits.
    let e = Wind {
        speed: 5e-324,
        ..wind()
    }
    .validate()
    .unwrap_err();
    assert_eq!(e.to_string(), "`speed` = 5e-324 is outside [0.1, 100]");
    let w = Wind {
        speed: MIN_WIND_SPEED,
        ..wind()
    };
    w.validate().unwrap();
    // Its trains are finite and built.
    for train in w.trains().unwrap() {
        let built = train.build().unwrap();
        assert!(built.wavenumber().is_finite() && built.angular_frequency().is_finite());
    }
}
