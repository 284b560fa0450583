//! The trochoid sum (Yrjölä & Larsson Eq. 6, 7) against closed forms and the f64 reference.

use core::f64::consts::{PI, TAU};

use glam::{DVec2, DVec3, Vec2, Vec3};
use ocean_core::{Depth, EvalError, Grid, Wave, WaveDesc, WaveError, WaveSet};

/// Three waves of different lengths and directions, the steepest at k·A = 0.6.
fn three_waves() -> WaveSet {
    WaveSet::from_descs(&[
        WaveDesc {
            amplitude: 0.8,
            wavelength: 40.0,
            direction: DVec2::new(1.0, 0.2),
            phase: 0.3,
            depth: Depth::Deep,
        },
        WaveDesc {
            amplitude: 0.3,
            wavelength: 11.0,
            direction: DVec2::new(0.6, -0.8),
            phase: 2.0,
            depth: Depth::Finite(6.0),
        },
        WaveDesc {
            amplitude: 0.6 * 3.0 / TAU,
            wavelength: 3.0,
            direction: DVec2::new(-0.3, 1.0),
            phase: -1.0,
            depth: Depth::Deep,
        },
    ])
    .unwrap()
}

/// Closed form of a single trochoid at phase θ: displacement (−k̂ A sin θ, A cos θ) and the
/// normal ∝ (kA sin θ k̂ₓ, 1 − kA cos θ, kA sin θ k̂_z), derived from ∂p/∂z × ∂p/∂x.
fn single_closed_form(w: &Wave, rest: DVec2, t: f64) -> (DVec3, DVec3) {
    let theta = w.wave_vector().dot(rest) - w.angular_frequency() * t + w.phase();
    let d = w.direction();
    let a = w.amplitude();
    let q = w.steepness();
    let disp = DVec3::new(
        -d.x * a * theta.sin(),
        a * theta.cos(),
        -d.y * a * theta.sin(),
    );
    let n = DVec3::new(
        q * theta.sin() * d.x,
        1.0 - q * theta.cos(),
        q * theta.sin() * d.y,
    );
    (disp, n.normalize())
}

#[test]
fn single_wave_equals_closed_form() {
    let w = Wave::deep(0.9, 17.0, DVec2::new(0.8, 0.6), 0.7).unwrap();
    let set = WaveSet::new(&[w]).unwrap();
    let grid = Grid {
        origin: DVec2::new(-5.0, 3.0),
        spacing: DVec2::new(0.7, 1.3),
        size: (29, 11),
    };
    let n = 29 * 11;
    let (mut pos, mut nrm) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    let t = 12.25;
    set.evaluate_grid(&grid, t, &mut pos, &mut nrm).unwrap();
    for j in 0..11 {
        for i in 0..29 {
            let local = DVec2::new(i as f64 * 0.7, j as f64 * 1.3);
            let (disp, normal) = single_closed_form(&w, grid.origin + local, t);
            let expected = DVec3::new(local.x, 0.0, local.y) + disp;
            // f32 rounding of positions up to ~30 m (2 µm) plus the f32 sincos (1.5e-7 · A).
            let e = (pos[j * 29 + i].as_dvec3() - expected).length();
            assert!(e < 1e-5, "position ({i},{j}) off by {e:e} m");
            let en = (nrm[j * 29 + i].as_dvec3() - normal).length();
            assert!(en < 1e-6, "normal ({i},{j}) off by {en:e}");
            // The f64 reference path agrees with the closed form to double rounding.
            let r = set.sample_f64(grid.origin + local, t).unwrap();
            assert!((r.displacement - disp).length() < 1e-12);
            assert!((r.normal - normal).length() < 1e-12);
        }
    }
}

#[test]
fn steepness_one_gives_a_cusp() {
    // k·A = 1: the trochoid is a cycloid. At the crest (θ = 0) the tangent ∂p/∂x vanishes and
    // the surface has a cusp: chord slopes to neighbours grow like 3/ε, and normals on either
    // side turn horizontal, pointing away from the crest.
    let lambda = 8.0;
    let k = TAU / lambda;
    let w = Wave::from_parts(1.0 / k, DVec2::new(k, 0.0), 1.0, 0.0).unwrap();
    let set = WaveSet::new(&[w]).unwrap();
    let crest = set.sample(DVec2::ZERO, 0.0).unwrap();
    assert!((crest.displacement.y - 1.0 / k as f32).abs() < 1e-6);
    // The normal at the cusp itself is undefined; the kernel documents +y there.
    assert_eq!(crest.normal, Vec3::Y);
    for eps in [1e-1, 3e-2, 1e-2] {
        let x = eps / k;
        let right = set.sample_f64(DVec2::new(x, 0.0), 0.0).unwrap();
        let left = set.sample_f64(DVec2::new(-x, 0.0), 0.0).unwrap();
        // Δx = (ε − sin ε)/k ≈ ε³/6k, Δy = (cos ε − 1)/k ≈ −ε²/2k: slope ≈ −3/ε.
        let dx = x + right.displacement.x;
        let dy = right.displacement.y - 1.0 / k;
        let slope = dy / dx;
        assert!((slope * eps + 3.0).abs() < 0.01, "eps {eps}: slope {slope}");
        // Normal ∝ (sin ε, 1 − cos ε): nearly horizontal, opposite on the two sides.
        assert!(right.normal.y < eps && right.normal.x > 0.99);
        assert!(left.normal.y < eps && left.normal.x < -0.99);
    }
    // And the surface never loops: x positions increase monotonically along the wave.
    let mut last = f64::NEG_INFINITY;
    for i in 0..=2000 {
        let x0 = -lambda + 2.0 * lambda * i as f64 / 2000.0;
        let x = x0
            + set
                .sample_f64(DVec2::new(x0, 0.0), 0.0)
                .unwrap()
                .displacement
                .x;
        assert!(x >= last - 1e-12, "fold at x0 = {x0}");
        last = x;
    }
    // A hair steeper is refused.
    assert!(matches!(
        Wave::from_parts(1.0001 / k, DVec2::new(k, 0.0), 1.0, 0.0),
        Err(WaveError::TooSteep(_))
    ));
}

#[test]
fn grid_snapshot() {
    let set = three_waves();
    let grid = Grid {
        origin: DVec2::new(10.0, -4.0),
        spacing: DVec2::new(2.5, 3.0),
        size: (4, 3),
    };
    let (mut pos, mut nrm) = (vec![Vec3::ZERO; 12], vec![Vec3::ZERO; 12]);
    set.evaluate_grid(&grid, 1.5, &mut pos, &mut nrm).unwrap();
    let mut out = String::new();
    for (k, (p, n)) in pos.iter().zip(&nrm).enumerate() {
        out += &format!(
            "({}, {}) pos [{:.4}, {:.4}, {:.4}] n [{:.4}, {:.4}, {:.4}]\n",
            k % 4,
            k / 4,
            p.x,
            p.y,
            p.z,
            n.x,
            n.y,
            n.z
        );
    }
    insta::assert_snapshot!(out.replace("-0.0000", "0.0000"));
}

#[test]
fn bit_identical_for_1_2_and_8_threads() {
    let set = three_waves();
    // 333 columns: not a multiple of the 8-lane chunk, so the tail path runs too.
    let grid = Grid {
        origin: DVec2::new(-120.0, 45.0),
        spacing: DVec2::new(0.31, 0.47),
        size: (333, 257),
    };
    let n = 333 * 257;
    let t = 731.125;
    let (mut p1, mut n1) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    set.evaluate_grid(&grid, t, &mut p1, &mut n1).unwrap();
    let local: Vec<Vec2> = (0..n)
        .map(|k| Vec2::new((k % 333) as f32 * 0.77, (k / 333) as f32 * 0.13))
        .collect();
    let (mut lp1, mut ln1) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    set.evaluate_points(grid.origin, &local, t, &mut lp1, &mut ln1)
        .unwrap();
    let bits = |v: &[Vec3]| -> Vec<[u32; 3]> {
        v.iter()
            .map(|a| [a.x.to_bits(), a.y.to_bits(), a.z.to_bits()])
            .collect()
    };
    for threads in [1, 2, 8] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let (mut p, mut nr) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
        pool.install(|| set.evaluate_grid_par(&grid, t, &mut p, &mut nr))
            .unwrap();
        assert!(
            bits(&p) == bits(&p1),
            "grid positions differ with {threads} threads"
        );
        assert!(
            bits(&nr) == bits(&n1),
            "grid normals differ with {threads} threads"
        );
        let (mut lp, mut ln) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
        pool.install(|| set.evaluate_points_par(grid.origin, &local, t, &mut lp, &mut ln))
            .unwrap();
        assert!(
            bits(&lp) == bits(&lp1),
            "point positions differ with {threads} threads"
        );
        assert!(
            bits(&ln) == bits(&ln1),
            "point normals differ with {threads} threads"
        );
    }
}

/// Waves down to 0.5 m long, so k·x reaches 1.3·10⁶ rad at 100 km and ω·t 1.1·10⁷ rad at 10⁶ s.
fn far_field_waves() -> WaveSet {
    let descs: Vec<WaveDesc> = (0..8)
        .map(|i| {
            let lambda = 0.5 * 1.9f64.powi(i);
            let angle = 0.7 * i as f64;
            WaveDesc {
                amplitude: 0.12 * lambda / TAU,
                wavelength: lambda,
                direction: DVec2::new(angle.cos(), angle.sin()),
                phase: i as f64,
                depth: Depth::Deep,
            }
        })
        .collect();
    WaveSet::from_descs(&descs).unwrap()
}

#[test]
fn f32_path_within_1_mm_at_100_km_and_1e6_s() {
    let set = far_field_waves();
    let t = 1.0e6;
    let grid = Grid {
        origin: DVec2::new(100_000.0 * (PI / 5.0).cos(), 100_000.0 * (PI / 5.0).sin()),
        spacing: DVec2::splat(0.173),
        size: (64, 64),
    };
    let n = 64 * 64;
    let (mut pos, mut nrm) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    set.evaluate_grid(&grid, t, &mut pos, &mut nrm).unwrap();
    let local: Vec<Vec2> = (0..n)
        .map(|k| Vec2::new((k % 64) as f32 * 0.173, (k / 64) as f32 * 0.173))
        .collect();
    let (mut lpos, mut lnrm) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    set.evaluate_points(grid.origin, &local, t, &mut lpos, &mut lnrm)
        .unwrap();
    let (mut worst_p, mut worst_n) = (0.0f64, 0.0f64);
    for k in 0..n {
        let (i, j) = (k % 64, k / 64);
        let l = DVec2::new(i as f64 * 0.173, j as f64 * 0.173);
        let r = set.sample_f64(grid.origin + l, t).unwrap();
        let expected = DVec3::new(l.x, 0.0, l.y) + r.displacement;
        for (p, nn) in [(pos[k], nrm[k]), (lpos[k], lnrm[k])] {
            worst_p = worst_p.max((p.as_dvec3() - expected).length());
            worst_n = worst_n.max(p_angle(nn.as_dvec3(), r.normal));
        }
    }
    println!(
        "100 km, 1e6 s: worst position error {worst_p:e} m, worst normal error {worst_n:e} rad"
    );
    assert!(worst_p < 1e-3, "position error {worst_p} m");
    assert!(worst_n < 1e-4, "normal error {worst_n} rad");
}

fn p_angle(a: DVec3, b: DVec3) -> f64 {
    a.normalize().dot(b).clamp(-1.0, 1.0).acos()
}

#[test]
fn bad_input_is_refused_and_outputs_untouched() {
    let set = three_waves();
    let grid = Grid {
        origin: DVec2::ZERO,
        spacing: DVec2::ONE,
        size: (4, 4),
    };
    let sentinel = Vec3::splat(7.0);
    let (mut p, mut n) = (vec![sentinel; 16], vec![sentinel; 16]);
    assert!(matches!(
        set.evaluate_grid(&grid, f64::NAN, &mut p, &mut n),
        Err(EvalError::Time(t)) if t.is_nan()
    ));
    assert!(matches!(
        set.evaluate_grid(&grid, f64::INFINITY, &mut p, &mut n),
        Err(EvalError::Time(_))
    ));
    let (mut short, mut n15) = (vec![sentinel; 15], vec![sentinel; 16]);
    assert!(matches!(
        set.evaluate_grid(&grid, 0.0, &mut short, &mut n15),
        Err(EvalError::OutputLength {
            expected: 16,
            positions: 15,
            normals: 16
        })
    ));
    for bad in [
        Grid {
            size: (0, 4),
            ..grid
        },
        Grid {
            spacing: DVec2::new(0.0, 1.0),
            ..grid
        },
        Grid {
            spacing: DVec2::new(1.0, f64::NAN),
            ..grid
        },
        Grid {
            origin: DVec2::new(f64::INFINITY, 0.0),
            ..grid
        },
        Grid {
            size: (usize::MAX, 2),
            ..grid
        },
    ] {
        assert!(
            set.evaluate_grid(&bad, 0.0, &mut p, &mut n).is_err(),
            "{bad:?}"
        );
    }
    assert_eq!(
        set.evaluate_points(DVec2::ZERO, &[], 0.0, &mut [], &mut []),
        Err(EvalError::Empty)
    );
    let pts = [Vec2::ZERO, Vec2::new(f32::NAN, 0.0)];
    assert_eq!(
        set.evaluate_points(DVec2::ZERO, &pts, 0.0, &mut p[..2], &mut n[..2]),
        Err(EvalError::Position { index: 1 })
    );
    assert!(set.sample(DVec2::new(0.0, f64::NAN), 0.0).is_err());
    assert!(set.sample_f64(DVec2::ZERO, f64::NEG_INFINITY).is_err());
    assert!(
        p.iter().chain(&n).all(|v| *v == sentinel),
        "outputs were written"
    );
    assert_eq!(WaveSet::new(&[]), Err(WaveError::Empty));
}

#[test]
fn statistics_of_a_set() {
    let set = three_waves();
    let expected_sum = set
        .waves()
        .iter()
        .map(|w| w.wavenumber() * w.amplitude())
        .sum::<f64>();
    assert!((set.steepness_sum() - expected_sum).abs() < 1e-15);
    assert!((set.max_amplitude() - (0.8 + 0.3 + 0.6 * 3.0 / TAU)).abs() < 1e-15);
    // No point of a dense grid rises above Σ A.
    let grid = Grid::centred(DVec2::ZERO, 0.25, 200);
    let (mut p, mut n) = (vec![Vec3::ZERO; 40_000], vec![Vec3::ZERO; 40_000]);
    set.evaluate_grid(&grid, 3.0, &mut p, &mut n).unwrap();
    let top = p.iter().map(|v| v.y).fold(f32::MIN, f32::max);
    assert!(f64::from(top) <= set.max_amplitude() + 1e-6);
}

#[test]
fn grid_sin_cos_tables_give_each_phase() {
    // Angle addition of the row and column entries must give sin and cos of the full phase
    // k·p₀ − ωt + Φ, to the f32 rounding of the two table entries (a few 1e-7).
    let set = far_field_waves();
    let grid = Grid {
        origin: DVec2::new(-3.0e4, 7.0e4),
        spacing: DVec2::new(0.37, 0.29),
        size: (19, 7),
    };
    let t = 2.5e5;
    let w = set.waves().len();
    let mut rows = vec![[0.0f32; 2]; w * 7];
    let mut cols = vec![[0.0f32; 2]; w * 19];
    set.grid_sin_cos(&grid, t, &mut rows, &mut cols).unwrap();
    let mut worst = 0.0f64;
    for (wi, wave) in set.waves().iter().enumerate() {
        for j in 0..7 {
            for i in 0..19 {
                let [rs, rc] = rows[wi * 7 + j].map(f64::from);
                let [cs, cc] = cols[wi * 19 + i].map(f64::from);
                let rest = grid.origin + DVec2::new(i as f64 * 0.37, j as f64 * 0.29);
                let theta = wave.phase_at(rest, t);
                worst = worst
                    .max((rs * cc + rc * cs - theta.sin()).abs())
                    .max((rc * cc - rs * cs - theta.cos()).abs());
            }
        }
    }
    assert!(worst < 5e-7, "worst {worst:e}");
    assert!(matches!(
        set.grid_sin_cos(&grid, t, &mut rows[1..], &mut cols),
        Err(EvalError::Grid(_))
    ));
    assert!(
        set.grid_sin_cos(&grid, f64::NAN, &mut rows, &mut cols)
            .is_err()
    );
}

/// Per-wave weights: all ones is the plain sum bit for bit; a weight w gives the wave scaled
/// by w (Bruneton et al. Eq. 2–3); zero weights, and waves past the end of the weights, are
/// skipped; bad weights (or more weights than waves) are refused and leave the sums alone.
#[test]
fn weighted_sums_scale_each_wave() {
    use ocean_core::PointSums;
    let descs = [
        WaveDesc {
            amplitude: 0.5,
            wavelength: 20.0,
            direction: DVec2::new(1.0, 0.0),
            phase: 0.3,
            depth: Depth::Deep,
        },
        WaveDesc {
            amplitude: 0.1,
            wavelength: 3.0,
            direction: DVec2::new(0.6, 0.8),
            phase: 1.1,
            depth: Depth::Deep,
        },
    ];
    let set = WaveSet::from_descs(&descs).unwrap();
    let rest = DVec2::new(12.5, -3.25);
    let t = 7.5;
    let mut plain = PointSums::REST;
    set.add_sums_f64(rest, t, [1.0, 0.0], &mut plain).unwrap();
    let mut ones = PointSums::REST;
    set.add_weighted_sums_f64(rest, t, [1.0, 1.0], &mut ones)
        .unwrap();
    assert_eq!(plain, ones);

    let mut weighted = PointSums::REST;
    set.add_weighted_sums_f64(rest, t, [0.25, 0.0], &mut weighted)
        .unwrap();
    // A prefix of the weights: the second wave is left out as if its weight were zero.
    let mut prefix = PointSums::REST;
    set.add_weighted_sums_f64(rest, t, [0.25], &mut prefix)
        .unwrap();
    assert_eq!(prefix, weighted);
    let scaled = WaveSet::from_descs(&[WaveDesc {
        amplitude: 0.125,
        ..descs[0]
    }])
    .unwrap();
    let mut expected = PointSums::REST;
    scaled
        .add_sums_f64(rest, t, [1.0, 0.0], &mut expected)
        .unwrap();
    let d = weighted.displacement() - expected.displacement();
    assert!(d.length() < 1e-15, "{d}");
    assert!((weighted.normal() - expected.normal()).length() < 1e-15);

    let mut sums = PointSums::REST;
    assert!(
        set.add_weighted_sums_f64(rest, t, [1.0, 1.0, 1.0], &mut sums)
            .is_err()
    );
    assert!(
        set.add_weighted_sums_f64(rest, t, [1.0, f64::NAN], &mut sums)
            .is_err()
    );
    assert!(
        set.add_weighted_sums_f64(rest, f64::INFINITY, [1.0, 1.0], &mut sums)
            .is_err()
    );
    assert_eq!(sums, PointSums::REST);
}
