//! Deterministic quadrature shared by the reference integrals (effective Fresnel, filtered sky).
//!
//! Fixed rules, no adaptivity and no allocation: the same inputs give the same bits on every
//! platform, which the snapshot tests rely on.

/// The standard normal density `φ(x) = exp(-x²/2)/√(2π)`.
#[inline]
pub(crate) fn standard_normal(x: f64) -> f64 {
    // 1/√(2π) to the nearest f64.
    const FRAC_1_SQRT_2PI: f64 = 0.398_942_280_401_432_7;
    FRAC_1_SQRT_2PI * libm::exp(-0.5 * x * x)
}

/// Fills `out` with composite Gauss–Legendre nodes and weights `(x, w)` on `[a, b]`: panels of
/// width at most `panel_width`, at most `out.len() / N` of them; returns how many nodes were
/// written. An empty or reversed interval (or a NaN bound) writes none.
pub(crate) fn composite_nodes<const N: usize>(
    gl: &([f64; N], [f64; N]),
    a: f64,
    b: f64,
    panel_width: f64,
    out: &mut [(f64, f64)],
) -> usize {
    if b.partial_cmp(&a) != Some(core::cmp::Ordering::Greater) {
        return 0;
    }
    let max_panels = (out.len() / N).max(1);
    let panels = libm::ceil((b - a) / panel_width).clamp(1.0, max_panels as f64) as usize;
    let h = (b - a) / panels as f64;
    let mut k = 0;
    for p in 0..panels {
        let mid = a + (p as f64 + 0.5) * h;
        for (x, w) in gl.0.iter().zip(gl.1.iter()) {
            out[k] = (mid + 0.5 * h * x, 0.5 * h * w);
            k += 1;
        }
    }
    k
}

/// Gauss–Legendre nodes and weights on `[-1, 1]` by Newton's method on the Legendre
/// recurrence (converged to f64 precision; cheap next to the integrand evaluations).
pub(crate) fn gauss_legendre<const N: usize>() -> ([f64; N], [f64; N]) {
    let mut x = [0.0; N];
    let mut w = [0.0; N];
    let n = N as f64;
    for i in 0..N.div_ceil(2) {
        // Tricomi's initial guess for the i-th root, then Newton.
        let mut z = libm::cos(core::f64::consts::PI * (i as f64 + 0.75) / (n + 0.5));
        let mut dp = 1.0;
        for _ in 0..100 {
            let (p, d) = legendre(N, z);
            dp = d;
            let dz = p / d;
            z -= dz;
            if dz.abs() <= 1e-16 {
                break;
            }
        }
        let (_, d) = legendre(N, z);
        if d != 0.0 {
            dp = d;
        }
        let weight = 2.0 / ((1.0 - z * z) * dp * dp);
        x[i] = -z;
        x[N - 1 - i] = z;
        w[i] = weight;
        w[N - 1 - i] = weight;
    }
    (x, w)
}

/// `(P_n(z), P_n'(z))` by the three-term recurrence.
fn legendre(n: usize, z: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0, z);
    for k in 2..=n {
        let k = k as f64;
        let p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
    }
    let d = n as f64 * (z * p1 - p0) / (z * z - 1.0);
    (p1, d)
}
