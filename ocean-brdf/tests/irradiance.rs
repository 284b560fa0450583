//! The order-2 irradiance of the environment (`ocean_brdf::irradiance`).

use std::f64::consts::PI;

use glam::DVec3;
use ocean_brdf::irradiance::sh_basis;
use ocean_brdf::{Irradiance, Lighting, SeaParams, SkyParams};

/// Unit normals over the sphere: 12 elevations from −90° to 90° × 16 azimuths.
fn normals() -> Vec<DVec3> {
    let mut out = Vec::new();
    for i in 0..=12 {
        let el = (-90.0 + 15.0 * i as f64).to_radians();
        for j in 0..16 {
            let az = (22.5 * j as f64).to_radians();
            out.push(DVec3::new(
                el.cos() * az.cos(),
                el.sin(),
                el.cos() * az.sin(),
            ));
        }
    }
    out
}

/// `∫ L(ω) max(0, n·ω) dω` by a fine midpoint rule in (cos θ about n, φ): the reference.
fn brute_force(radiance: impl Fn(DVec3) -> DVec3, n: DVec3) -> DVec3 {
    let (rings, azimuths) = (400, 400);
    let t = if n.y.abs() < 0.9 { DVec3::Y } else { DVec3::X };
    let u = n.cross(t).normalize();
    let v = n.cross(u);
    let mut sum = DVec3::ZERO;
    for i in 0..rings {
        let mu = (i as f64 + 0.5) / rings as f64;
        let s = (1.0 - mu * mu).sqrt();
        for j in 0..azimuths {
            let phi = (j as f64 + 0.5) / azimuths as f64 * std::f64::consts::TAU;
            let d = n * mu + u * (s * phi.cos()) + v * (s * phi.sin());
            sum += radiance(d) * mu;
        }
    }
    sum * (std::f64::consts::TAU / (rings * azimuths) as f64)
}

/// The basis is orthonormal over the sphere (to the quadrature's precision): a constant
/// radiance 1 projects onto `Y₀₀` alone and gives `E = π` for every normal, and a radiance
/// `1 + a·ω` (degree 1) gives `E(n) = π + (2π/3) a·n` exactly (Ramamoorthi & Hanrahan's
/// `Â₀ = π`, `Â₁ = 2π/3`).
#[test]
fn low_degree_radiance_is_exact() {
    let one = Irradiance::from_radiance(|_| DVec3::ONE);
    let a = DVec3::new(0.3, -0.5, 0.2);
    let linear = Irradiance::from_radiance(|d| DVec3::splat(1.0 + a.dot(d)));
    for n in normals() {
        let e = one.at(n);
        assert!(
            (e - DVec3::splat(PI)).abs().max_element() < 1e-9,
            "{n}: {e}"
        );
        let want = PI + 2.0 * PI / 3.0 * a.dot(n);
        let e = linear.at(n);
        assert!((e.x - want).abs() < 1e-9, "{n}: {e} vs {want}");
    }
    // A degree-2 radiance ω_y² is exact at order 2 too: against the brute force.
    let square = Irradiance::from_radiance(|d| DVec3::splat(d.y * d.y));
    for n in normals() {
        let want = brute_force(|d| DVec3::splat(d.y * d.y), n).x;
        assert!(
            (square.at(n).x - want).abs() < 1e-4,
            "{n}: {} vs {want}",
            square.at(n).x
        );
    }
    let y = sh_basis(DVec3::Y);
    assert!((y[0] - 0.5 / PI.sqrt()).abs() < 1e-15);
}

/// On the default clear sky over the default sea, against the brute-force integral of the same
/// environment for normals over the whole sphere: the order-2 series within 4% of the
/// irradiance facing up (measured 3.1%: the worst normals face the horizon, where the
/// environment jumps from sky to sea), and the ambient it gives a facet facing up equals the sky's
/// irradiance on the horizontal sea (`Sky::sky_irradiance`) to the series' accuracy.
#[test]
fn clear_sky_irradiance_matches_the_integral() {
    let lighting = Lighting::new(SkyParams::default(), SeaParams::default()).unwrap();
    let e = Irradiance::new(&lighting);
    let env = |d: DVec3| lighting.environment_radiance(d);
    let up = brute_force(env, DVec3::Y);
    let scale = up.max_element();
    let mut worst = 0.0f64;
    for n in normals() {
        let want = brute_force(env, n);
        let err = (e.at(n) - want).abs().max_element() / scale;
        worst = worst.max(err);
    }
    println!(
        "worst |E_sh − E| / E(up) over {} normals: {:.4}; E(up) = {up}, sky_irradiance = {}",
        normals().len(),
        worst,
        lighting.sky().sky_irradiance()
    );
    assert!(worst < 0.04, "{worst}");
    let sky = lighting.sky().sky_irradiance();
    assert!(
        ((up - sky).abs() / sky).max_element() < 1e-3,
        "{up} vs {sky}"
    );
}
