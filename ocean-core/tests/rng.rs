//! PCG32 tests: reference outputs, ranges, statistics with stated bounds, determinism.

use ocean_core::rng::{Pcg32, RngError};

/// `pcg32-demo` of pcg-c-basic (seed 42, stream 54), "Round 1, 32bit" line.
const REFERENCE_42_54: [u32; 6] = [
    0xa15c02b7, 0x7b47f409, 0xba1d3330, 0x83d2f293, 0xbfa4784b, 0xcbed606e,
];

#[test]
fn reproduces_the_pcg_c_reference_outputs() {
    let mut rng = Pcg32::new(42, 54);
    let got: Vec<u32> = (0..6).map(|_| rng.next_u32()).collect();
    assert_eq!(got, REFERENCE_42_54);
}

#[test]
fn next_u64_is_two_outputs_high_first() {
    let mut rng = Pcg32::new(42, 54);
    assert_eq!(rng.next_u64(), 0xa15c02b7_7b47f409);
    assert_eq!(rng.next_u64(), 0xba1d3330_83d2f293);
}

#[test]
fn same_seed_same_sequence_and_streams_differ() {
    let a: Vec<u32> = {
        let mut r = Pcg32::new(7, 3);
        (0..1000).map(|_| r.next_u32()).collect()
    };
    let b: Vec<u32> = {
        let mut r = Pcg32::new(7, 3);
        (0..1000).map(|_| r.next_u32()).collect()
    };
    assert_eq!(a, b);
    // Another stream (or seed) gives another sequence: with 1000 independent 32-bit values the
    // chance of even 10 positional matches is negligible (expected 1000/2^32).
    for other in [Pcg32::new(7, 4), Pcg32::new(8, 3)] {
        let mut r = other;
        let same = a.iter().filter(|&&x| x == r.next_u32()).count();
        assert!(same < 10, "{same} matches");
    }
    // A copy continues identically, floats included.
    let mut r = Pcg32::new(1, 1);
    r.next_u32();
    let mut c = r;
    for _ in 0..100 {
        assert_eq!(r.next_f64().to_bits(), c.next_f64().to_bits());
        assert_eq!(r.standard_normal().to_bits(), c.standard_normal().to_bits());
    }
}

#[test]
fn advance_jumps_forward_and_back() {
    let mut stepped = Pcg32::new(42, 54);
    for _ in 0..12345 {
        stepped.next_u32();
    }
    let mut jumped = Pcg32::new(42, 54);
    jumped.advance(12345);
    assert_eq!(jumped, stepped);
    // Back by 12343 steps (2^64 - 12343 forward) leaves us after the first two outputs.
    jumped.advance(12343u64.wrapping_neg());
    assert_eq!(jumped.next_u32(), REFERENCE_42_54[2]);
}

#[test]
fn floats_are_in_zero_one_and_have_the_uniform_mean_and_variance() {
    let mut rng = Pcg32::new(123, 456);
    const N: usize = 1_000_000;
    let (mut sum32, mut sum64, mut sq64) = (0.0f64, 0.0f64, 0.0f64);
    for _ in 0..N {
        let x = rng.next_f32();
        assert!((0.0..1.0).contains(&x), "next_f32 = {x}");
        // A multiple of 2^-24: x·2^24 is an integer.
        assert_eq!((x * 16_777_216.0).fract(), 0.0);
        sum32 += x as f64;
        let y = rng.next_f64();
        assert!((0.0..1.0).contains(&y), "next_f64 = {y}");
        sum64 += y;
        sq64 += (y - 0.5) * (y - 0.5);
    }
    let n = N as f64;
    // Uniform [0,1): mean 1/2 with standard error √(1/12/N) = 2.9e-4; allow 5σ = 1.5e-3.
    assert!((sum32 / n - 0.5).abs() < 1.5e-3, "f32 mean {}", sum32 / n);
    assert!((sum64 / n - 0.5).abs() < 1.5e-3, "f64 mean {}", sum64 / n);
    // Variance 1/12; (y - 1/2)² has standard deviation √(1/80 - 1/144) = 0.0745, so the standard
    // error of the variance estimate is 7.5e-5; allow 5σ = 3.7e-4.
    assert!(
        (sq64 / n - 1.0 / 12.0).abs() < 3.7e-4,
        "variance {}",
        sq64 / n
    );
}

#[test]
fn bounded_integers_pass_chi_square() {
    // 100 000 draws of below_u32(10): chi-square with 9 degrees of freedom; the 0.1% critical
    // value is 27.88 (a fair generator exceeds it once in a thousand seeds; the seed is fixed).
    let mut rng = Pcg32::new(99, 1);
    let mut counts = [0u32; 10];
    const N: u32 = 100_000;
    for _ in 0..N {
        counts[rng.below_u32(10).unwrap() as usize] += 1;
    }
    let e = N as f64 / 10.0;
    let chi2: f64 = counts.iter().map(|&c| (c as f64 - e).powi(2) / e).sum();
    assert!(chi2 < 27.88, "chi2 = {chi2}, counts {counts:?}");
}

#[test]
fn bounded_integers_are_unbiased_for_large_bounds() {
    // bound = 3·2^30: a plain `x % bound` would return values below 2^30 with probability 1/2
    // (both x and x - bound land there), instead of 1/3. Lemire's rejection must give 1/3:
    // 100 000 draws, standard error √(2/9/N) = 1.5e-3, allow 0.01.
    let bound = 3u32 << 30;
    let mut rng = Pcg32::new(5, 5);
    let n = 100_000;
    let low = (0..n)
        .filter(|_| rng.below_u32(bound).unwrap() < (1 << 30))
        .count();
    let frac = low as f64 / n as f64;
    assert!(
        (frac - 1.0 / 3.0).abs() < 0.01,
        "fraction below 2^30: {frac}"
    );
    // The same for 64 bits with bound 3·2^62.
    let bound = 3u64 << 62;
    let low = (0..n)
        .filter(|_| rng.below_u64(bound).unwrap() < (1 << 62))
        .count();
    let frac = low as f64 / n as f64;
    assert!(
        (frac - 1.0 / 3.0).abs() < 0.01,
        "fraction below 2^62: {frac}"
    );
}

#[test]
fn ranges_cover_exactly_their_half_open_interval() {
    let mut rng = Pcg32::new(3, 9);
    let mut seen = [false; 10];
    for _ in 0..10_000 {
        let x = rng.range_i32(-5, 5).unwrap();
        assert!((-5..5).contains(&x));
        seen[(x + 5) as usize] = true;
        let y = rng.range_i64(i64::MIN, i64::MAX).unwrap();
        assert!(y < i64::MAX);
        let u = rng.uniform_f64(-2.5, 7.0).unwrap();
        assert!((-2.5..7.0).contains(&u));
        let v = rng.uniform_f32(10.0, 10.5).unwrap();
        assert!((10.0..10.5).contains(&v));
    }
    // With 10 000 draws each of the 10 values appears (missing one has probability ~1e-457).
    assert!(seen.iter().all(|&s| s), "{seen:?}");
    // A range one ulp wide has a single value, the low end, which must never round to high.
    let lo = 1.0f64;
    for _ in 0..1000 {
        assert_eq!(rng.uniform_f64(lo, lo.next_up()).unwrap(), lo);
        assert_eq!(rng.uniform_f32(1.0, 1.0f32.next_up()).unwrap(), 1.0);
    }
    assert_eq!(rng.range_i32(i32::MIN, i32::MIN + 1).unwrap(), i32::MIN);
}

#[test]
fn bad_arguments_are_errors() {
    let mut rng = Pcg32::new(0, 0);
    assert!(matches!(rng.below_u32(0), Err(RngError::EmptyRange { .. })));
    assert!(matches!(rng.below_u64(0), Err(RngError::EmptyRange { .. })));
    assert_eq!(
        rng.range_i32(3, 3),
        Err(RngError::EmptyRange {
            low: 3.0,
            high: 3.0
        })
    );
    assert!(matches!(
        rng.range_i64(5, -5),
        Err(RngError::EmptyRange { .. })
    ));
    assert_eq!(
        rng.uniform_f64(1.0, 0.5),
        Err(RngError::EmptyRange {
            low: 1.0,
            high: 0.5
        })
    );
    assert_eq!(
        rng.uniform_f64(f64::NAN, 1.0),
        Err(RngError::NotFinite("low"))
    );
    assert_eq!(
        rng.uniform_f64(0.0, f64::INFINITY),
        Err(RngError::NotFinite("high"))
    );
    assert_eq!(
        rng.uniform_f64(-f64::MAX, f64::MAX),
        Err(RngError::NotFinite("high - low"))
    );
    assert_eq!(
        rng.uniform_f32(0.0, f32::NAN),
        Err(RngError::NotFinite("high"))
    );
    assert_eq!(rng.normal(0.0, -1.0), Err(RngError::NegativeStdDev(-1.0)));
    assert_eq!(rng.normal(f64::NAN, 1.0), Err(RngError::NotFinite("mean")));
}

#[test]
fn normals_have_the_standard_moments() {
    let mut rng = Pcg32::new(2718, 28);
    const N: usize = 200_000;
    let xs: Vec<f64> = (0..N / 2)
        .flat_map(|_| {
            let (a, b) = rng.normal_pair();
            [a, b]
        })
        .collect();
    let n = N as f64;
    let mean = xs.iter().sum::<f64>() / n;
    let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
    let within1 = xs.iter().filter(|x| x.abs() < 1.0).count() as f64 / n;
    let kurt = xs.iter().map(|x| x.powi(4)).sum::<f64>() / n;
    // Standard errors: mean 1/√N = 2.2e-3, variance √(2/N) = 3.2e-3, P(|x|<1) = 0.6827 with
    // √(p(1-p)/N) = 1.0e-3, E[x⁴] = 3 with √(96/N) = 0.022. All bounds are 5σ.
    assert!(mean.abs() < 0.011, "mean {mean}");
    assert!((var - 1.0).abs() < 0.016, "variance {var}");
    assert!(
        (within1 - 0.682_689_5).abs() < 0.005,
        "P(|x| < 1) = {within1}"
    );
    assert!((kurt - 3.0).abs() < 0.11, "E[x^4] = {kurt}");
    // Scaled normals: mean 10, sd 2 ⇒ sample mean within 5·2/√N.
    let m: f64 = (0..N).map(|_| rng.normal(10.0, 2.0).unwrap()).sum::<f64>() / n;
    assert!((m - 10.0).abs() < 0.023, "scaled mean {m}");
    // A zero standard deviation is allowed and returns the mean.
    assert_eq!(rng.normal(4.0, 0.0), Ok(4.0));
}
