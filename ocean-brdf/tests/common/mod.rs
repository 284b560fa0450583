//! Test helpers shared by the BRDF and Fresnel tests: directions and a composite
//! Gauss–Legendre rule written here, independent of the library's own quadrature, so the
//! library is checked against a second implementation.

use glam::DVec3;

/// The unit vector at zenith `theta_deg` and azimuth `phi_deg` (degrees) in the tangent frame.
pub fn dir(theta_deg: f64, phi_deg: f64) -> DVec3 {
    let (st, ct) = theta_deg.to_radians().sin_cos();
    let (sp, cp) = phi_deg.to_radians().sin_cos();
    DVec3::new(st * cp, st * sp, ct)
}

/// Gauss–Legendre nodes and weights on [-1, 1] (Newton on the Legendre recurrence).
pub fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    let mut out = vec![(0.0, 0.0); n];
    for i in 0..n.div_ceil(2) {
        let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        for _ in 0..100 {
            let (p, d) = legendre(n, z);
            let dz = p / d;
            z -= dz;
            if dz.abs() < 1e-16 {
                break;
            }
        }
        let (_, d) = legendre(n, z);
        let w = 2.0 / ((1.0 - z * z) * d * d);
        out[i] = (-z, w);
        out[n - 1 - i] = (z, w);
    }
    out
}

fn legendre(n: usize, z: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0, z);
    for k in 2..=n {
        let k = k as f64;
        let p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
    }
    (p1, n as f64 * (z * p1 - p0) / (z * z - 1.0))
}

/// Composite Gauss–Legendre rule on [a, b]: `panels` panels of `gl.len()` nodes.
pub fn composite(gl: &[(f64, f64)], a: f64, b: f64, panels: usize) -> Vec<(f64, f64)> {
    if b <= a {
        return Vec::new();
    }
    let h = (b - a) / panels as f64;
    let mut out = Vec::with_capacity(panels * gl.len());
    for p in 0..panels {
        let mid = a + (p as f64 + 0.5) * h;
        out.extend(gl.iter().map(|&(x, w)| (mid + 0.5 * h * x, 0.5 * h * w)));
    }
    out
}
