//! Modulated layers against the plain trochoid sum: the identities that define them.

use core::f64::consts::TAU;

use glam::{DVec2, Vec3};
use ocean_core::{
    Depth, EvalError, Grid, GridRect, Layer, Modulation, Wave, WaveDesc, WaveSet, evaluate_layers,
    evaluate_layers_par, evaluate_layers_region, evaluate_layers_region_par,
};

fn waves(seed: f64) -> WaveSet {
    let descs: Vec<WaveDesc> = (0..3)
        .map(|i| {
            let lambda = 4.0 + 7.0 * i as f64 + seed;
            let a = 0.4 * i as f64 + seed;
            WaveDesc {
                amplitude: 0.3 * lambda / TAU,
                wavelength: lambda,
                direction: DVec2::new(a.cos(), a.sin()),
                phase: seed + i as f64,
                depth: Depth::Deep,
            }
        })
        .collect();
    WaveSet::from_descs(&descs).unwrap()
}

/// 45 × 23: not a multiple of the 16-lane chunk, far from the origin.
fn grid() -> Grid {
    Grid {
        origin: DVec2::new(-3.0e4, 1.2e4),
        spacing: DVec2::splat(0.7),
        size: (45, 23),
    }
}

fn full(grid: &Grid) -> GridRect {
    GridRect {
        i0: 0,
        j0: 0,
        nx: grid.size.0,
        nz: grid.size.1,
    }
}

fn modulation(rect: GridRect, values: &[[f32; 2]]) -> Modulation {
    Modulation::new(rect, values.to_vec()).unwrap()
}

fn run(grid: &Grid, t: f64, layers: &[Layer], height: Option<&[f32]>) -> (Vec<Vec3>, Vec<Vec3>) {
    let n = grid.size.0 * grid.size.1;
    let (mut p, mut q) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    evaluate_layers(grid, t, layers, height, &mut p, &mut q).unwrap();
    (p, q)
}

fn max_diff(a: &[Vec3], b: &[Vec3]) -> f32 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (*x - *y).abs().max_element())
        .fold(0.0, f32::max)
}

#[test]
fn unit_modulation_is_the_plain_sum_bit_for_bit() {
    // μ = [1, 0]: sin θ·1 + cos θ·0 = sin θ and cos θ·1 − sin θ·0 = cos θ exactly in IEEE
    // arithmetic, so the layer reproduces WaveSet::evaluate_grid to the bit.
    let g = grid();
    let set = waves(0.0);
    let m = vec![[1.0f32, 0.0]; g.size.0 * g.size.1];
    let (p, q) = run(
        &g,
        77.5,
        &[Layer {
            waves: &set,
            modulation: &modulation(full(&g), &m),
        }],
        None,
    );
    let n = p.len();
    let (mut pe, mut qe) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    set.evaluate_grid(&g, 77.5, &mut pe, &mut qe).unwrap();
    assert_eq!(p, pe);
    assert_eq!(q, qe);
}

#[test]
fn constant_modulation_scales_amplitude_and_shifts_phase() {
    // μ = m e^{iφ} everywhere equals the same waves with amplitude m·A and phase Φ + φ
    // (Eq. 6, 7), up to f32 rounding of the modulated products (≤ a few 1e-7 · A).
    let g = grid();
    let set = waves(0.5);
    let (m, phi) = (0.6f64, 1.1f64);
    let mu = vec![[(m * phi.cos()) as f32, (m * phi.sin()) as f32]; g.size.0 * g.size.1];
    let (p, q) = run(
        &g,
        3.0e5,
        &[Layer {
            waves: &set,
            modulation: &modulation(full(&g), &mu),
        }],
        None,
    );
    let shifted: Vec<Wave> = set
        .waves()
        .iter()
        .map(|w| {
            Wave::from_parts(
                m * w.amplitude(),
                w.wave_vector(),
                w.angular_frequency(),
                w.phase() + phi,
            )
            .unwrap()
        })
        .collect();
    let expect = WaveSet::new(&shifted).unwrap();
    let n = p.len();
    let (mut pe, mut qe) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    expect.evaluate_grid(&g, 3.0e5, &mut pe, &mut qe).unwrap();
    assert!(max_diff(&p, &pe) < 5e-6, "positions {}", max_diff(&p, &pe));
    assert!(max_diff(&q, &qe) < 5e-6, "normals {}", max_diff(&q, &qe));
}

#[test]
fn overlapping_layers_add_and_rectangles_bound_them() {
    // Two layers over two overlapping rectangles: inside both the result is the sum of both
    // wave sets; inside one only, that set alone; outside both, the rest position with +y.
    let g = grid();
    let (a, b) = (waves(0.0), waves(1.3));
    let ra = GridRect {
        i0: 3,
        j0: 2,
        nx: 30,
        nz: 15,
    };
    let rb = GridRect {
        i0: 20,
        j0: 9,
        nx: 25,
        nz: 14,
    };
    let ma = vec![[1.0f32, 0.0]; ra.len()];
    let mb = vec![[1.0f32, 0.0]; rb.len()];
    let t = 12.0;
    let (p, q) = run(
        &g,
        t,
        &[
            Layer {
                waves: &a,
                modulation: &modulation(ra, &ma),
            },
            Layer {
                waves: &b,
                modulation: &modulation(rb, &mb),
            },
        ],
        None,
    );
    let both: Vec<Wave> = a.waves().iter().chain(b.waves()).copied().collect();
    let both = WaveSet::new(&both).unwrap();
    let n = p.len();
    let eval = |s: &WaveSet| {
        let (mut pe, mut qe) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
        s.evaluate_grid(&g, t, &mut pe, &mut qe).unwrap();
        (pe, qe)
    };
    let (pab, qab) = eval(&both);
    let (pa, qa) = eval(&a);
    let (pb, qb) = eval(&b);
    let (nx, nz) = g.size;
    let mut counts = [0usize; 4];
    for j in 0..nz {
        for i in 0..nx {
            let k = j * nx + i;
            let (ina, inb) = (ra.index(i, j).is_some(), rb.index(i, j).is_some());
            let (lx, lz) = g.local(i, j);
            let (ep, eq) = match (ina, inb) {
                (true, true) => (pab[k], qab[k]),
                (true, false) => (pa[k], qa[k]),
                (false, true) => (pb[k], qb[k]),
                (false, false) => (Vec3::new(lx, 0.0, lz), Vec3::Y),
            };
            counts[usize::from(ina) * 2 + usize::from(inb)] += 1;
            // Summation order differs between one set of six waves and two layers of three.
            assert!(
                (p[k] - ep).abs().max_element() < 2e-6,
                "({i},{j}) {:?} vs {ep:?}",
                p[k]
            );
            assert!((q[k] - eq).abs().max_element() < 2e-6, "({i},{j}) normal");
        }
    }
    assert!(
        counts.iter().all(|&c| c > 0),
        "every region exercised: {counts:?}"
    );
}

#[test]
fn height_field_adds_to_heights_only() {
    let g = grid();
    let set = waves(0.2);
    let m = vec![[0.8f32, -0.3]; g.size.0 * g.size.1];
    let h: Vec<f32> = (0..m.len()).map(|k| 0.01 * (k % 7) as f32 - 0.02).collect();
    let layer = [Layer {
        waves: &set,
        modulation: &modulation(full(&g), &m),
    }];
    let (p0, q0) = run(&g, 5.0, &layer, None);
    let (p1, q1) = run(&g, 5.0, &layer, Some(&h));
    for k in 0..p0.len() {
        assert_eq!(p1[k].x, p0[k].x);
        assert_eq!(p1[k].z, p0[k].z);
        assert!((p1[k].y - (p0[k].y + h[k])).abs() <= 1e-6);
    }
    assert_eq!(q0, q1);
}

#[test]
fn threads_give_identical_bits() {
    let g = Grid {
        size: (333, 97),
        ..grid()
    };
    let (a, b) = (waves(0.0), waves(2.0));
    let ra = GridRect {
        i0: 0,
        j0: 0,
        nx: 200,
        nz: 97,
    };
    let rb = GridRect {
        i0: 150,
        j0: 10,
        nx: 183,
        nz: 80,
    };
    let ma: Vec<[f32; 2]> = (0..ra.len())
        .map(|k| [(k % 13) as f32 / 13.0, 0.1])
        .collect();
    let mb: Vec<[f32; 2]> = (0..rb.len()).map(|k| [0.5, (k % 5) as f32 / 9.0]).collect();
    let layers = [
        Layer {
            waves: &a,
            modulation: &modulation(ra, &ma),
        },
        Layer {
            waves: &b,
            modulation: &modulation(rb, &mb),
        },
    ];
    let (p1, q1) = run(&g, 1.5e4, &layers, None);
    for threads in [1, 2, 8] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let n = p1.len();
        let (mut p, mut q) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
        pool.install(|| evaluate_layers_par(&g, 1.5e4, &layers, None, &mut p, &mut q))
            .unwrap();
        assert!(p == p1 && q == q1, "{threads} threads differ");
    }
}

#[test]
fn bad_layers_are_refused_without_writing() {
    let g = grid();
    let set = waves(0.0);
    let n = g.size.0 * g.size.1;
    let sentinel = Vec3::splat(9.0);
    let (mut p, mut q) = (vec![sentinel; n], vec![sentinel; n]);
    let m = vec![[1.0f32, 0.0]; n];
    let outside = GridRect {
        i0: 40,
        j0: 0,
        nx: 10,
        nz: 5,
    };
    let bad_h = vec![0.0f32; n - 1];
    let nan_h = vec![f32::NAN; n];
    let outside = modulation(outside, &m[..50]);
    let fine = modulation(full(&g), &m);
    // (layer modulation, height field, time): each invalid in one way.
    let cases: [(&Modulation, Option<&[f32]>, f64); 4] = [
        (&outside, None, 0.0),
        (&fine, Some(&bad_h), 0.0),
        (&fine, Some(&nan_h), 0.0),
        (&fine, None, f64::NAN),
    ];
    for (m, h, t) in cases {
        let layers = [Layer {
            waves: &set,
            modulation: m,
        }];
        assert!(evaluate_layers(&g, t, &layers, h, &mut p, &mut q).is_err());
        assert!(evaluate_layers_par(&g, t, &layers, h, &mut p, &mut q).is_err());
    }
    assert!(matches!(
        evaluate_layers(&g, 0.0, &[], None, &mut p[..3], &mut q),
        Err(EvalError::OutputLength { .. })
    ));
    assert!(p.iter().chain(&q).all(|v| *v == sentinel));
    // Modulations themselves are checked when built.
    assert!(Modulation::new(full(&g), vec![[1.0, 0.0]; 10]).is_err());
    assert!(Modulation::new(full(&g), vec![[f32::NAN, 0.0]; n]).is_err());
}

#[test]
fn f64_point_sums_agree_with_the_layer_kernel() {
    // WaveSet::add_sums_f64 with a point's μ is the f64 twin of the layers kernel: at every
    // grid point it must give the same position and normal, to f32 rounding (positions up to
    // 30 m: a few µm; normals 1e-6).
    let g = grid();
    let (a, b) = (waves(0.0), waves(0.9));
    let ra = full(&g);
    let rb = GridRect {
        i0: 10,
        j0: 4,
        nx: 30,
        nz: 15,
    };
    let ma: Vec<[f32; 2]> = (0..ra.len())
        .map(|k| [0.9 - (k % 11) as f32 * 0.05, 0.2])
        .collect();
    let mb: Vec<[f32; 2]> = (0..rb.len())
        .map(|k| [0.3, -0.4 + (k % 3) as f32 * 0.1])
        .collect();
    let t = 4.0e4;
    let (p, q) = run(
        &g,
        t,
        &[
            Layer {
                waves: &a,
                modulation: &modulation(ra, &ma),
            },
            Layer {
                waves: &b,
                modulation: &modulation(rb, &mb),
            },
        ],
        None,
    );
    let (nx, nz) = g.size;
    for j in 0..nz {
        for i in 0..nx {
            let rest = g.origin + DVec2::new(i as f64 * g.spacing.x, j as f64 * g.spacing.y);
            let mut sums = ocean_core::PointSums::REST;
            let mu = |m: [f32; 2]| [f64::from(m[0]), f64::from(m[1])];
            a.add_sums_f64(rest, t, mu(ma[ra.index(i, j).unwrap()]), &mut sums)
                .unwrap();
            if let Some(k) = rb.index(i, j) {
                b.add_sums_f64(rest, t, mu(mb[k]), &mut sums).unwrap();
            }
            let k = j * nx + i;
            let (lx, lz) = g.local(i, j);
            let expect = glam::DVec3::new(f64::from(lx), 0.0, f64::from(lz)) + sums.displacement();
            assert!((p[k].as_dvec3() - expect).length() < 1e-5, "({i},{j})");
            assert!(
                (q[k].as_dvec3() - sums.normal()).length() < 1e-5,
                "({i},{j}) normal"
            );
        }
    }
}

#[test]
fn every_non_finite_value_is_found_with_its_index() {
    // The finiteness checks are vectorised (x·0 sums); an infinity or NaN anywhere, in the
    // unrolled part or the remainder, on either component, must still be reported exactly:
    // by Modulation::new for a modulation, by the evaluation for a height field.
    let g = Grid {
        size: (333, 211),
        ..grid()
    };
    let set = waves(0.0);
    let n = 333 * 211;
    let (mut p, mut q) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    let full = GridRect {
        i0: 0,
        j0: 0,
        nx: 333,
        nz: 211,
    };
    let fine = modulation(full, &vec![[0.5f32, -0.25]; n]);
    for (index, bad) in [
        (0, f32::INFINITY),
        (37, f32::NEG_INFINITY),
        (n - 1, f32::NAN),
        (n / 2, f32::INFINITY),
    ] {
        for component in 0..2 {
            let mut m = vec![[0.5f32, -0.25]; n];
            m[index][component] = bad;
            assert_eq!(Modulation::new(full, m), Err(EvalError::Position { index }));
        }
        let mut h = vec![0.01f32; n];
        h[index] = bad;
        let layer = [Layer {
            waves: &set,
            modulation: &fine,
        }];
        assert_eq!(
            evaluate_layers(&g, 1.0, &layer, Some(&h), &mut p, &mut q),
            Err(EvalError::Position { index })
        );
        assert_eq!(
            evaluate_layers_par(&g, 1.0, &layer, Some(&h), &mut p, &mut q),
            Err(EvalError::Position { index })
        );
    }
}

#[test]
fn zero_modulation_outside_a_rotated_box_leaves_rest_and_skips_nothing_inside() {
    // A diamond (a box rotated 45°) inside its bounding rectangle: μ = [1, 0] inside, 0 outside,
    // so each row's non-zero span starts and ends mid-chunk. Inside, the bits of the plain
    // trochoid sum (unit modulation, see the first test); outside, the rest position and +y.
    let g = Grid {
        size: (131, 77),
        ..grid()
    };
    let set = waves(0.7);
    let rect = GridRect {
        i0: 9,
        j0: 4,
        nx: 117,
        nz: 69,
    };
    let (ci, cj) = (rect.i0 as f64 + 58.0, rect.j0 as f64 + 34.0);
    let inside =
        |i: usize, j: usize| (i as f64 - ci).abs() / 58.0 + (j as f64 - cj).abs() / 34.0 <= 1.0;
    let mut m = vec![[0.0f32; 2]; rect.len()];
    for j in 0..rect.nz {
        for i in 0..rect.nx {
            if inside(rect.i0 + i, rect.j0 + j) {
                m[j * rect.nx + i] = [1.0, 0.0];
            }
        }
    }
    let m = modulation(rect, &m);
    let layers = [Layer {
        waves: &set,
        modulation: &m,
    }];
    let t = 640.0;
    let (p, q) = run(&g, t, &layers, None);
    let n = p.len();
    let (mut pe, mut qe) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    set.evaluate_grid(&g, t, &mut pe, &mut qe).unwrap();
    let (mut pp, mut qp) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    evaluate_layers_par(&g, t, &layers, None, &mut pp, &mut qp).unwrap();
    assert!(pp == p && qp == q, "threads");
    let (nx, nz) = g.size;
    let mut counted = [0usize; 2];
    for j in 0..nz {
        for i in 0..nx {
            let k = j * nx + i;
            if inside(i, j) {
                assert!(p[k] == pe[k] && q[k] == qe[k], "({i},{j}) inside");
                counted[0] += 1;
            } else {
                let (lx, lz) = g.local(i, j);
                assert_eq!((p[k], q[k]), (Vec3::new(lx, 0.0, lz), Vec3::Y), "({i},{j})");
                counted[1] += 1;
            }
        }
    }
    assert!(counted[0] > 3000 && counted[1] > 3000, "{counted:?}");
}

#[test]
fn region_evaluation_writes_the_full_result_inside_and_nothing_outside() {
    // Inside the region every point gets the bits evaluate_layers gives it; outside the region's
    // rows and 16-column chunks nothing is written (sentinels survive).
    let g = Grid {
        size: (101, 37),
        ..grid()
    };
    let set = waves(0.3);
    let rect = GridRect {
        i0: 5,
        j0: 3,
        nx: 90,
        nz: 30,
    };
    let m: Vec<[f32; 2]> = (0..rect.len())
        .map(|k| [0.7, (k % 9) as f32 * 0.03])
        .collect();
    let h: Vec<f32> = (0..101 * 37).map(|k| (k % 5) as f32 * 0.01).collect();
    let m = modulation(rect, &m);
    let layers = [Layer {
        waves: &set,
        modulation: &m,
    }];
    let (full_p, full_q) = run(&g, 21.0, &layers, Some(&h));
    let sentinel = Vec3::splat(-9.0);
    for region in [
        GridRect {
            i0: 0,
            j0: 0,
            nx: 101,
            nz: 37,
        },
        GridRect {
            i0: 17,
            j0: 4,
            nx: 30,
            nz: 9,
        },
        GridRect {
            i0: 99,
            j0: 36,
            nx: 2,
            nz: 1,
        },
        GridRect {
            i0: 40,
            j0: 10,
            nx: 0,
            nz: 5,
        },
    ] {
        for parallel in [false, true] {
            let (mut p, mut q) = (vec![sentinel; 101 * 37], vec![sentinel; 101 * 37]);
            if parallel {
                evaluate_layers_region_par(&g, 21.0, &layers, Some(&h), region, &mut p, &mut q)
                    .unwrap();
            } else {
                evaluate_layers_region(&g, 21.0, &layers, Some(&h), region, &mut p, &mut q)
                    .unwrap();
            }
            let (c0, c1) = (
                region.i0 / 16 * 16,
                (region.i0 + region.nx).div_ceil(16) * 16,
            );
            for j in 0..37 {
                for i in 0..101 {
                    let k = j * 101 + i;
                    if region.index(i, j).is_some() {
                        assert!(
                            p[k] == full_p[k] && q[k] == full_q[k],
                            "{region:?} ({i},{j})"
                        );
                    } else if j < region.j0
                        || j >= region.j0 + region.nz
                        || i < c0
                        || i >= c1
                        || region.is_empty()
                    {
                        assert!(
                            p[k] == sentinel && q[k] == sentinel,
                            "{region:?} wrote ({i},{j})"
                        );
                    } else {
                        // Same chunk as the region: written with the full result, or untouched.
                        assert!(p[k] == full_p[k] || p[k] == sentinel);
                    }
                }
            }
        }
    }
    let outside = GridRect {
        i0: 95,
        j0: 0,
        nx: 10,
        nz: 1,
    };
    let (mut p, mut q) = (vec![sentinel; 101 * 37], vec![sentinel; 101 * 37]);
    assert!(evaluate_layers_region(&g, 21.0, &layers, None, outside, &mut p, &mut q).is_err());
}
