//! Tests of the Fresnel functions (§5.1, §5.2 of the paper, `ocean_brdf::fresnel`).

use glam::{DVec2, DVec3};
use ocean_brdf::BrdfError;
use ocean_brdf::fresnel::{
    WATER_R, effective_fresnel_fit, effective_fresnel_integral, schlick, sigma_v2,
};
use ocean_brdf::ross::{facet_normal, visible_slope_pdf_unchecked};

mod common;
use common::{composite, dir, gauss_legendre};

/// Eq. 24 computed independently of the crate's quadrature: in slope space (not whitened),
/// with `ross::visible_slope_pdf` (Eq. 10, with its analytic normaliser `1 + Λ`) and
/// `ross::facet_normal` (Eq. 6), on ±10σ per axis with 24 panels × 8 nodes, the inner range
/// cut at the visibility line (inner variable: the larger `σ_i |v_i|`).
fn eq_24_reference(v: DVec3, sx2: f64, sy2: f64, r: f64) -> f64 {
    let gl = gauss_legendre(8);
    let panels = 24;
    let (sx, sy) = (sx2.sqrt(), sy2.sqrt());
    let swap = sy * v.y.abs() > sx * v.x.abs();
    let (si, so, vi, vo) = if swap {
        (sy, sx, v.y, v.x)
    } else {
        (sx, sy, v.x, v.y)
    };
    let (lo, hi) = (-10.0 * si, 10.0 * si);
    let mut total = 0.0;
    for (outer, wo) in composite(&gl, -10.0 * so, 10.0 * so, panels) {
        let (a, b) = if vi == 0.0 {
            (lo, hi)
        } else {
            let kink = (v.z - outer * vo) / vi;
            if vi > 0.0 {
                (lo, kink.min(hi))
            } else {
                (kink.max(lo), hi)
            }
        };
        let row: f64 = composite(&gl, a, b, panels)
            .into_iter()
            .map(|(inner, wi)| {
                let z = if swap {
                    DVec2::new(outer, inner)
                } else {
                    DVec2::new(inner, outer)
                };
                let x = 1.0 - v.dot(facet_normal(z));
                wi * visible_slope_pdf_unchecked(z, v, sx2, sy2) * x.powi(5)
            })
            .sum();
        total += wo * row;
    }
    r + (1.0 - r) * total
}

#[test]
fn schlick_endpoints() {
    // Eq. 14: F(1) = R (normal incidence), F(0) = 1 (grazing); a back-facing cosine is clamped
    // to grazing, never above 1.
    for &r in &[0.0, WATER_R, 0.04, 0.5, 1.0] {
        assert_eq!(schlick(1.0, r), r);
        assert!((schlick(0.0, r) - 1.0).abs() <= f64::EPSILON, "R = {r}");
        assert_eq!(schlick(-0.5, r), schlick(0.0, r));
    }
    assert_eq!(schlick(0.0, WATER_R), 1.0);
    // (1 - 0.5)⁵ = 1/32.
    assert!((schlick(0.5, WATER_R) - (0.02 + 0.98 / 32.0)).abs() < 1e-16);
}

#[test]
fn sigma_v2_is_eq_25() {
    // σ_v² = σ_x² cos² φ + σ_y² sin² φ: σ_x² along the wind, σ_y² across, the mean at 45°.
    assert_eq!(sigma_v2(0.0, 0.04, 0.01), 0.04);
    assert!((sigma_v2(std::f64::consts::FRAC_PI_2, 0.04, 0.01) - 0.01).abs() < 1e-17);
    assert!((sigma_v2(std::f64::consts::FRAC_PI_4, 0.04, 0.01) - 0.025).abs() < 1e-17);
    assert!((sigma_v2(std::f64::consts::PI, 0.04, 0.01) - 0.04).abs() < 1e-17);
}

#[test]
fn fit_is_schlick_at_sigma_zero() {
    // Eq. 26 at σ_v = 0: the exponent 5 exp(0) is exactly 5 and the damping exactly 1, so the
    // fit is Schlick's formula bit for bit.
    for i in 0..=1000 {
        let c = i as f64 / 1000.0;
        for &r in &[0.0, WATER_R, 0.3] {
            assert_eq!(
                effective_fresnel_fit(c, 0.0, r).unwrap(),
                schlick(c, r),
                "cos = {c}"
            );
        }
    }
}

#[test]
fn fit_tends_to_schlick() {
    // |Eq. 26 - Eq. 14| ≤ (1 - R) (k σ e^(kσ)/e + b σ^1.5) with k = 2.69, b = 22.7: the
    // exponent g = 5 e^(-kσ) moves by at most 5kσ and |∂x^g/∂g| = x^g |ln x| ≤ 1/(e g); the
    // damping 1/(1 + b σ^1.5) moves x^g ≤ 1 by at most b σ^1.5. Checked on a fine cos θ grid.
    for &sv in &[1e-8_f64, 1e-6, 1e-4, 1e-2] {
        let bound = (1.0 - WATER_R)
            * (2.69 * sv * (2.69 * sv).exp() / std::f64::consts::E + 22.7 * sv.powf(1.5));
        for i in 0..=1000 {
            let c = i as f64 / 1000.0;
            let d = (effective_fresnel_fit(c, sv, WATER_R).unwrap() - schlick(c, WATER_R)).abs();
            assert!(
                d <= bound * (1.0 + 1e-9) + 1e-16,
                "σ_v = {sv}, cos = {c}: {d} > {bound}"
            );
        }
    }
}

#[test]
fn integral_matches_an_independent_quadrature() {
    // effective_fresnel_integral (whitened slopes, quadrature cut at the visibility line,
    // normalised by its own mass) against Eq. 24 computed in plain slope space with
    // visible_slope_pdf (analytic 1 + Λ normaliser) and facet_normal, 24 panels: agreement
    // within 1e-9 (measured 1.2e-10, at σ = (1, 0.6), θ_v = 80°), grazing (θ_v = 90°) included.
    // Debug builds check a subset: σ = (0.05, 0.05) and (1, 0.6), θ_v in {0, 80, 90}°,
    // φ_v in {0, 30}°.
    let (pairs, thetas, phis): (&[(f64, f64)], &[f64], &[f64]) = if cfg!(debug_assertions) {
        (
            &[(0.05, 0.05), (1.0, 0.6)],
            &[0.0, 80.0, 90.0],
            &[0.0, 30.0],
        )
    } else {
        (
            &[(0.05, 0.05), (0.3, 0.1), (0.5, 0.5), (1.0, 0.6)],
            &[0.0, 45.0, 80.0, 89.0, 89.9, 90.0],
            &[0.0, 30.0, 90.0],
        )
    };
    let mut worst: f64 = 0.0;
    for &(a, b) in pairs {
        for &t in thetas {
            for &p in phis {
                let v = dir(t, p);
                let v = if t == 90.0 {
                    DVec3::new(v.x, v.y, 0.0)
                } else {
                    v
                };
                let got = effective_fresnel_integral(v, a * a, b * b, WATER_R).unwrap();
                let want = eq_24_reference(v, a * a, b * b, WATER_R);
                assert!(
                    (got - want).abs() < 1e-9,
                    "σ = ({a}, {b}), θ = {t}, φ = {p}: {got} vs {want}"
                );
                worst = worst.max((got - want).abs());
            }
        }
    }
    println!("Eq. 24 integral vs independent quadrature: worst {worst:.2e}");
}

#[test]
fn integral_tends_to_schlick() {
    // As σ → 0, q^e_vn tends to a Dirac at ζ = 0 and Eq. 24 to Schlick's F(cos θ_v). The gap
    // is largest at grazing, where the visible facets are those tilted towards the viewer:
    // there v·f is σ_v |s| on the half s < 0 of the standard normal weighted by √(2π)|s|,
    // whose mean is σ_v √(π/2), so F̄ ≈ 1 - 5 (1 - R) σ_v √(π/2): a gap of 6.27 σ_v (1 - R).
    // Asserted: gap ≤ 6.3 σ (1 - R), σ the larger deviation, at θ_v from 0 to 89.99°
    // (measured: 6.02 σ (1 - R) at most).
    // Debug builds take θ_v every 5° (plus the grazing angles).
    let step = if cfg!(debug_assertions) { 5 } else { 1 };
    let mut worst: f64 = 0.0;
    for &sg in &[1e-4, 1e-3, 1e-2] {
        for t in (0..90)
            .step_by(step)
            .map(f64::from)
            .chain([89.5, 89.9, 89.99])
        {
            for &p in &[0.0, 45.0] {
                let v = dir(t, p);
                let got = effective_fresnel_integral(v, sg * sg, 0.25 * sg * sg, WATER_R).unwrap();
                let gap = (got - schlick(v.z, WATER_R)).abs() / (sg * (1.0 - WATER_R));
                assert!(
                    gap <= 6.3,
                    "σ = {sg}, θ = {t}, φ = {p}: gap {gap} σ (1 - R)"
                );
                worst = worst.max(gap);
            }
        }
    }
    // σ = 0 exactly: Schlick.
    for t in [0.0, 45.0, 89.0] {
        let v = dir(t, 10.0);
        let got = effective_fresnel_integral(v, 0.0, 0.0, WATER_R).unwrap();
        assert!(
            (got - schlick(v.z, WATER_R)).abs() < 1e-15,
            "θ = {t}: {got}"
        );
    }
    println!("Eq. 24 vs Schlick as σ → 0: worst gap {worst:.3} σ (1 - R)");
}

#[test]
fn fit_stays_close_to_the_integral_below_sigma_half() {
    // The requirement: Eq. 26 against Eq. 24 for σ_x, σ_y < 0.5, all view angles.
    // Sweep (release): σ_x, σ_y each in {0.02, 0.1, 0.2, 0.3, 0.4, 0.49} (isotropic and
    // anisotropic up to 25:1), φ_v in {0, 30, 60, 90}°, θ_v = 0, 1, …, 89, 89.5, 89.9, 89.99°.
    // Debug builds sweep σ in {0.02, 0.1, 0.49}, φ_v in {0, 90}°, θ_v every 5° plus 81,
    // 89, 89.5, 89.9, 89.99°, which contains both worst cases below.
    // Measured (release): largest |fit - integral| = 0.0641, at σ = (0.1, 0.49), φ_v = 0,
    // θ_v = 81° (fit 0.318, integral 0.382): the fit sees only σ_v = 0.1 along the view, not
    // the rough cross-wind slopes. Isotropic worst: 0.0556 at σ = 0.02, θ_v = 89.99° (fit 0.940,
    // integral 0.884; the fit does not follow the integral's 1 - 6.27 σ (1 - R) gap at grazing).
    // Away from both (θ_v ≤ 60°) differences are far smaller.
    // Bound 0.065, just above the measurement. Fig. 7 of the paper plots both functions over
    // θ_v and σ_v² on a reflectance axis from 0 to 1 and calls the fit "very accurate": a few
    // hundredths of reflectance is the size of a gap between two curves on that plot, and the
    // paper itself says the integral only "mainly" depends on σ_v (Eq. 25).
    let (sigmas, phis, step): (&[f64], &[f64], usize) = if cfg!(debug_assertions) {
        (&[0.02, 0.1, 0.49], &[0.0, 90.0], 5)
    } else {
        (
            &[0.02, 0.1, 0.2, 0.3, 0.4, 0.49],
            &[0.0, 30.0, 60.0, 90.0],
            1,
        )
    };
    let thetas: Vec<f64> = (0..90)
        .step_by(step)
        .map(f64::from)
        .chain([81.0, 89.0, 89.5, 89.9, 89.99])
        .collect();
    let mut worst = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    for &a in sigmas {
        for &b in sigmas {
            for &p in phis {
                for &t in &thetas {
                    let v = dir(t, p);
                    let integral = effective_fresnel_integral(v, a * a, b * b, WATER_R).unwrap();
                    let sv = sigma_v2(p.to_radians(), a * a, b * b).sqrt();
                    let fit = effective_fresnel_fit(v.z, sv, WATER_R).unwrap();
                    let d = (fit - integral).abs();
                    if d > worst.0 {
                        worst = (d, a, b, p, t, fit, integral);
                    }
                }
            }
        }
    }
    let (d, a, b, p, t, fit, integral) = worst;
    println!(
        "Eq. 26 vs Eq. 24, σ < 0.5: largest |fit - integral| = {d:.4} at σ = ({a}, {b}), \
         φ_v = {p}°, θ_v = {t}° (fit {fit:.4}, integral {integral:.4})"
    );
    assert!(d < 0.065, "{d}");
}

#[test]
fn fresnel_functions_refuse_invalid_input() {
    let v = dir(30.0, 0.0);
    assert!(matches!(
        effective_fresnel_fit(1.5, 0.1, WATER_R),
        Err(BrdfError::OutOfRange {
            name: "cos_theta_v",
            ..
        })
    ));
    assert!(matches!(
        effective_fresnel_fit(0.5, -0.1, WATER_R),
        Err(BrdfError::OutOfRange {
            name: "sigma_v",
            ..
        })
    ));
    assert_eq!(
        effective_fresnel_fit(0.5, f64::NAN, WATER_R),
        Err(BrdfError::NotFinite("sigma_v"))
    );
    assert!(matches!(
        effective_fresnel_integral(dir(100.0, 0.0), 0.1, 0.1, WATER_R),
        Err(BrdfError::OutOfRange { name: "v.z", .. })
    ));
    assert_eq!(
        effective_fresnel_integral(v * 2.0, 0.1, 0.1, WATER_R),
        Err(BrdfError::NotUnit("v"))
    );
    assert!(matches!(
        effective_fresnel_integral(v, 0.1, 0.1, -0.5),
        Err(BrdfError::OutOfRange { name: "r", .. })
    ));
}

#[test]
fn fresnel_functions_stay_in_range_for_extreme_input() {
    // Valid extremes (zero, tiny and huge variances, exact grazing, normal incidence): the
    // effective reflectance is a number in [R, 1], never NaN.
    let variances = [
        0.0,
        f64::MIN_POSITIVE,
        1e-300,
        1e-8,
        1.0,
        1e8,
        1e300,
        f64::MAX,
    ];
    for &sx2 in &variances {
        for &sy2 in &[0.0, 1e-8, 1.0, f64::MAX] {
            for &t in &[0.0, 1e-9, 60.0, 89.999, 90.0] {
                for &p in &[0.0, 30.0] {
                    let v = dir(t, p);
                    let v = if t == 90.0 {
                        DVec3::new(v.x, v.y, 0.0)
                    } else {
                        v
                    };
                    let f = effective_fresnel_integral(v, sx2, sy2, WATER_R).unwrap();
                    assert!((WATER_R..=1.0).contains(&f), "{v}, ({sx2}, {sy2}): {f}");
                }
            }
        }
        let sv = sx2.sqrt();
        for &c in &[0.0, 1e-12, 0.5, 1.0] {
            let f = effective_fresnel_fit(c, sv, WATER_R).unwrap();
            assert!((WATER_R..=1.0).contains(&f), "fit({c}, {sv}) = {f}");
        }
    }
}
