//! Every instruction set of the layers kernel gives the same bits (`ocean_core::isa`).
//!
//! The cases reach every branch of the kernels: rectangles that start and end inside a 16-lane
//! chunk (rows with partial spans), rows of zeros and zero patches inside a span (land), grids
//! whose width is not a multiple of 16 (a partial last chunk), an additive height field, steep
//! waves and far-from-origin grids. A CPU without AVX2 or AVX-512 checks the sets it has
//! (the AMD EPYC and Intel Xeon machines this project has run on have all three).

use core::f64::consts::TAU;

use glam::{DVec2, Vec3};
use ocean_core::{
    Depth, EvalError, Grid, GridRect, Isa, Layer, LayersEvaluator, Modulation, Pcg32, WaveDesc,
    WaveSet, evaluate_layers, evaluate_layers_isa,
};

fn waves(rng: &mut Pcg32, count: usize, steepness: f64) -> WaveSet {
    let descs: Vec<WaveDesc> = (0..count)
        .map(|_| {
            let lambda = 2.0 + 30.0 * rng.next_f64();
            let a = TAU * rng.next_f64();
            WaveDesc {
                amplitude: steepness * lambda / TAU / count as f64,
                wavelength: lambda,
                direction: DVec2::new(a.cos(), a.sin()),
                phase: TAU * rng.next_f64(),
                depth: Depth::Finite(1.0 + 20.0 * rng.next_f64()),
            }
        })
        .collect();
    WaveSet::from_descs(&descs).unwrap()
}

/// A modulation over `rect` whose rows vary: some all zero, some with zero runs, every value
/// otherwise a random complex amplitude of magnitude up to 1.5.
fn modulation(rng: &mut Pcg32, rect: GridRect) -> Modulation {
    let mut values = Vec::with_capacity(rect.len());
    for r in 0..rect.nz {
        let zero_row = r % 7 == 3;
        let (z0, z1) = (
            (rng.next_f64() * rect.nx as f64) as usize,
            (rng.next_f64() * rect.nx as f64) as usize,
        );
        for c in 0..rect.nx {
            let land = zero_row || (c >= z0.min(z1) && c < z0.max(z1) && r % 3 == 0);
            values.push(if land {
                [0.0, 0.0]
            } else {
                let (m, phi) = (1.5 * rng.next_f64(), TAU * rng.next_f64());
                [(m * phi.cos()) as f32, (m * phi.sin()) as f32]
            });
        }
    }
    Modulation::new(rect, values).unwrap()
}

struct Case {
    grid: Grid,
    sets: Vec<WaveSet>,
    mods: Vec<Modulation>,
    height: Option<Vec<f32>>,
    t: f64,
}

fn case(seed: u64, size: (usize, usize), layers: usize, height: bool, steepness: f64) -> Case {
    let mut rng = Pcg32::new(seed, 7);
    let grid = Grid {
        origin: DVec2::new(-4.0e4 * rng.next_f64(), 9.0e4 * rng.next_f64()),
        spacing: DVec2::splat(0.25 + 2.0 * rng.next_f64()),
        size,
    };
    let mut sets = Vec::new();
    let mut mods = Vec::new();
    for _ in 0..layers {
        let count = 1 + (rng.next_f64() * 4.0) as usize;
        sets.push(waves(&mut rng, count, steepness));
        // A rectangle with edges anywhere, so spans start and end inside chunks.
        let i0 = (rng.next_f64() * size.0 as f64 * 0.6) as usize;
        let j0 = (rng.next_f64() * size.1 as f64 * 0.6) as usize;
        let nx = 1 + (rng.next_f64() * (size.0 - i0 - 1) as f64) as usize;
        let nz = 1 + (rng.next_f64() * (size.1 - j0 - 1) as f64) as usize;
        mods.push(modulation(&mut rng, GridRect { i0, j0, nx, nz }));
    }
    let n = size.0 * size.1;
    let height = height.then(|| {
        (0..n)
            .map(|_| (0.2 * rng.next_f64() - 0.1) as f32)
            .collect()
    });
    Case {
        grid,
        sets,
        mods,
        height,
        t: 1.0e6 * rng.next_f64(),
    }
}

fn eval(c: &Case, isa: Option<Isa>) -> (Vec<Vec3>, Vec<Vec3>) {
    let layers: Vec<Layer> = c
        .sets
        .iter()
        .zip(&c.mods)
        .map(|(waves, modulation)| Layer { waves, modulation })
        .collect();
    let n = c.grid.size.0 * c.grid.size.1;
    let (mut p, mut q) = (vec![Vec3::NAN; n], vec![Vec3::NAN; n]);
    let h = c.height.as_deref();
    match isa {
        Some(isa) => evaluate_layers_isa(isa, &c.grid, c.t, &layers, h, &mut p, &mut q).unwrap(),
        None => evaluate_layers(&c.grid, c.t, &layers, h, &mut p, &mut q).unwrap(),
    }
    (p, q)
}

fn bits(v: &[Vec3]) -> Vec<[u32; 3]> {
    v.iter()
        .map(|p| [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()])
        .collect()
}

#[test]
fn every_instruction_set_gives_the_portable_bits() {
    let available: Vec<Isa> = Isa::ALL.into_iter().filter(|i| i.is_available()).collect();
    assert!(available.contains(&Isa::Portable));
    let sizes = [(45, 23), (16, 16), (1, 9), (97, 40), (128, 33), (17, 1)];
    let mut compared = 0usize;
    for (k, &size) in sizes.iter().enumerate() {
        for layers in [1, 2, 5] {
            for height in [false, true] {
                for steepness in [0.3, 0.95] {
                    let seed = (k * 100 + layers * 10) as u64 + height as u64 * 3;
                    let c = case(seed, size, layers, height, steepness);
                    let (p0, q0) = eval(&c, Some(Isa::Portable));
                    assert!(p0.iter().chain(&q0).all(|v| v.is_finite()));
                    for &isa in &available {
                        let (p, q) = eval(&c, Some(isa));
                        assert_eq!(bits(&p), bits(&p0), "{isa:?} positions, {size:?}");
                        assert_eq!(bits(&q), bits(&q0), "{isa:?} normals, {size:?}");
                        compared += p.len();
                    }
                    // The default evaluator is one of them.
                    let (p, q) = eval(&c, None);
                    assert_eq!((bits(&p), bits(&q)), (bits(&p0), bits(&q0)));
                }
            }
        }
    }
    assert!(compared > 0);
}

#[test]
fn best_is_available_and_an_unavailable_set_is_an_error() {
    assert!(Isa::best().is_available());
    let c = case(1, (20, 20), 1, false, 0.5);
    for isa in Isa::ALL {
        let layers = [Layer {
            waves: &c.sets[0],
            modulation: &c.mods[0],
        }];
        let (mut p, mut q) = (vec![Vec3::ZERO; 400], vec![Vec3::ZERO; 400]);
        let r = evaluate_layers_isa(isa, &c.grid, 1.0, &layers, None, &mut p, &mut q);
        if isa.is_available() {
            assert_eq!(r, Ok(()));
        } else {
            assert_eq!(r, Err(EvalError::Isa(isa)));
            assert!(p.iter().all(|v| *v == Vec3::ZERO), "nothing written");
        }
    }
}

/// `LayersEvaluator::evaluate_block` gives every point of a block the whole grid's bits:
/// blocks aligned to 16-column chunks, blocks that start and end inside chunks, single points,
/// blocks at the grid's far edges.
#[test]
fn blocks_have_the_whole_grid_bits() {
    for (seed, size) in [(3u64, (45usize, 23usize)), (4, (97, 40)), (5, (40, 16))] {
        let c = case(seed, size, 3, seed % 2 == 1, 0.8);
        let (p0, q0) = eval(&c, None);
        let layers: Vec<Layer> = c
            .sets
            .iter()
            .zip(&c.mods)
            .map(|(waves, modulation)| Layer { waves, modulation })
            .collect();
        let e = LayersEvaluator::new(&c.grid, c.t, &layers, c.height.as_deref()).unwrap();
        let (nx, nz) = size;
        let mut rng = Pcg32::new(seed, 11);
        let mut blocks = vec![
            GridRect {
                i0: 0,
                j0: 0,
                nx,
                nz,
            },
            GridRect {
                i0: 16,
                j0: 1,
                nx: 16.min(nx - 16),
                nz: 3,
            },
            GridRect {
                i0: nx - 1,
                j0: nz - 1,
                nx: 1,
                nz: 1,
            },
        ];
        for _ in 0..20 {
            let i0 = (rng.next_f64() * nx as f64) as usize;
            let j0 = (rng.next_f64() * nz as f64) as usize;
            let w = 1 + (rng.next_f64() * (nx - i0) as f64) as usize;
            let h = 1 + (rng.next_f64() * (nz - j0) as f64) as usize;
            blocks.push(GridRect {
                i0,
                j0,
                nx: w.min(nx - i0),
                nz: h.min(nz - j0),
            });
        }
        for b in blocks {
            let (mut p, mut q) = (vec![Vec3::NAN; b.len()], vec![Vec3::NAN; b.len()]);
            e.evaluate_block(b, &mut p, &mut q).unwrap();
            for dj in 0..b.nz {
                for di in 0..b.nx {
                    let (k, g) = (dj * b.nx + di, (b.j0 + dj) * nx + b.i0 + di);
                    assert_eq!(
                        bits(&[p[k], q[k]]),
                        bits(&[p0[g], q0[g]]),
                        "{b:?} ({di}, {dj})"
                    );
                }
            }
        }
        let outside = GridRect {
            i0: nx - 1,
            j0: 0,
            nx: 2,
            nz: 1,
        };
        let (mut p, mut q) = (vec![Vec3::NAN; 2], vec![Vec3::NAN; 2]);
        assert!(matches!(
            e.evaluate_block(outside, &mut p, &mut q),
            Err(EvalError::Grid(_))
        ));
        assert!(p.iter().all(|v| v.x.is_nan()), "nothing written on error");
        let one = GridRect {
            i0: 0,
            j0: 0,
            nx: 1,
            nz: 1,
        };
        assert!(matches!(
            e.evaluate_block(one, &mut p, &mut q),
            Err(EvalError::OutputLength { .. })
        ));
    }
}
