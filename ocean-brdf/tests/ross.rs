//! Tests of the Ross BRDF (§4 of the paper, `ocean_brdf::ross`).
//!
//! Quadratures here are deterministic composite Gauss–Legendre rules from `tests/common`,
//! independent of the crate's own (tests/fresnel.rs checks that one).

use glam::{DVec2, DVec3};
use ocean_brdf::BrdfError;
use ocean_brdf::ross::{
    brdf, brdf_unchecked, facet_normal, lambda, q_vn, slope_pdf, smith_a, sun_radiance,
    visible_slope_pdf, visible_slope_pdf_unchecked,
};

mod common;
use common::{composite, dir, gauss_legendre};

// ---------------------------------------------------------------------------------------------
// Helpers.

/// `∬ g(ζ) d²ζ` over the facets visible from `v` (`v_z - ζ·v_xy > 0`), on the box of ±10
/// standard deviations, in slope space. The inner variable is the one with the larger
/// `σ_i |v_i|` (so that, in units of standard deviations, the visibility line is closer to
/// perpendicular to it than to the outer one, and the inner integrals vary smoothly with the
/// outer variable), and its range is cut exactly at the visibility line, so that the kink of
/// `max(v·f, 0)` lies on a panel boundary and the rule converges spectrally.
fn integrate_visible(
    v: DVec3,
    sigma_x2: f64,
    sigma_y2: f64,
    panels: usize,
    nodes: usize,
    g: impl Fn(DVec2) -> f64,
) -> f64 {
    integrate_visible_cut(v, sigma_x2, sigma_y2, panels, nodes, false, g)
}

/// [`integrate_visible`], optionally (`lit`) also restricted to the facets whose mirror
/// direction `r(v, ζ)` of Eq. 18 is above the horizon. `r_z = 2 (v·f) f_z - v_z > 0` is
/// `|ζ + v_xy/v_z| < 1/v_z`, a disc, whose chord on each inner line is cut exactly too.
fn integrate_visible_cut(
    v: DVec3,
    sigma_x2: f64,
    sigma_y2: f64,
    panels: usize,
    nodes: usize,
    lit: bool,
    g: impl Fn(DVec2) -> f64,
) -> f64 {
    let gl = gauss_legendre(nodes);
    let (sx, sy) = (sigma_x2.sqrt(), sigma_y2.sqrt());
    let swap = sy * v.y.abs() > sx * v.x.abs();
    // (inner, outer) half widths and view components.
    let (si, so, vi, vo) = if swap {
        (sy, sx, v.y, v.x)
    } else {
        (sx, sy, v.x, v.y)
    };
    let to_zeta = |inner: f64, outer: f64| {
        if swap {
            DVec2::new(outer, inner)
        } else {
            DVec2::new(inner, outer)
        }
    };
    let (lo, hi) = (-10.0 * si, 10.0 * si);
    let mut total = 0.0;
    for (outer, wo) in composite(&gl, -10.0 * so, 10.0 * so, panels) {
        // Visible side: inner * vi < v_z - outer * vo.
        let (mut a, mut b) = if vi == 0.0 {
            (lo, hi)
        } else {
            let kink = (v.z - outer * vo) / vi;
            if vi > 0.0 {
                (lo, kink.min(hi))
            } else {
                (kink.max(lo), hi)
            }
        };
        if lit && v.z > 0.0 {
            // Disc of centre -v_xy/v_z and radius 1/v_z, in (inner, outer) coordinates.
            let (ci, co) = (-vi / v.z, -vo / v.z);
            let disc = 1.0 / (v.z * v.z) - (outer - co) * (outer - co);
            if disc <= 0.0 {
                continue;
            }
            a = a.max(ci - disc.sqrt());
            b = b.min(ci + disc.sqrt());
        }
        let row: f64 = composite(&gl, a, b, panels)
            .into_iter()
            .map(|(inner, wi)| wi * g(to_zeta(inner, outer)))
            .sum();
        total += wo * row;
    }
    total
}

/// The mirror direction of `v` about the facet normal `f` (Eq. 18).
fn reflect(v: DVec3, f: DVec3) -> DVec3 {
    2.0 * v.dot(f) * f - v
}

// ---------------------------------------------------------------------------------------------
// Eq. 8: erfc and Λ against high-precision references.

/// `(a, erfc(a), Λ(a))` at the exact f64 values of `a`, to 21 significant digits, computed
/// with Python's `decimal` at 120 digits of working precision:
///
/// ```python
/// # erfc(a) = 1 - erf(a), erf(a) = 2/sqrt(pi) exp(-a^2) sum_n 2^n a^(2n+1)/(1*3*...*(2n+1))  (a < 5;
/// #           all terms positive, the 1 - erf cancellation costs < 12 of the 120 digits)
/// # erfc(a) = exp(-a^2)/sqrt(pi) / (a + (1/2)/(a + 1/(a + (3/2)/(a + ...))))  (a >= 5, Laplace's
/// #           continued fraction, 4000 levels bottom-up)
/// # Lambda(a) = (exp(-a^2) - a sqrt(pi) erfc(a)) / (2 a sqrt(pi))  (Eq. 8), same precision;
/// # pi by Machin's formula.  Cross-checked against mpmath at 60 digits: max rel. diff 1.7e-58.
/// ```
///
/// From a ≈ 26.55 on, `erfc(a)` and `Λ(a)` fall below f64's normal range (`Λ(30) ≈ 7e-397` is
/// not representable at all).
#[allow(clippy::excessive_precision)] // the references keep the digits they were computed with
const ERFC_LAMBDA_REFS: [(f64, f64, f64); 31] = [
    (0.001, 9.98871621209030763597e-1, 2.81595073868622895691e2),
    (0.01, 9.88716584444150382849e-1, 2.77123000782906942119e1),
    (0.05, 9.43628022202983373045e-1, 5.15599470102860394134e0),
    (0.1, 8.87537083981715101595e-1, 2.34911047498148464892e0),
    (0.25, 7.23673609831763067015e-1, 6.98177324460232709990e-1),
    (0.5, 4.79500122186953462317e-1, 1.99641228374245665888e-1),
    (0.75, 2.88844366346484868401e-1, 6.98881732251600088173e-2),
    (1.0, 1.57299207050285130659e-1, 2.51272708300061105057e-2),
    (1.25, 7.70998717435417698635e-2, 8.75428861768727251226e-3),
    (1.5, 3.38948535246892729330e-2, 2.87428810826025878866e-3),
    (1.75, 1.33283287808175562278e-2, 8.75120742469846837947e-4),
    (1.99, 4.88858680038300295268e-3, 2.57750581223216964087e-4),
    (2.0, 4.67773498104726583793e-3, 2.44505678737873813168e-4),
    (2.5, 4.06952017444958939564e-4, 1.43524143127915022566e-5),
    (2.99, 2.35256030806401953003e-5, 5.99171211883402497783e-7),
    (3.0, 2.20904969985854413728e-5, 5.59172496269600471147e-7),
    (4.0, 1.54172579002800188522e-8, 2.27767719776589491639e-10),
    (5.0, 1.53745979442803485019e-12, 1.48134293368493403180e-14),
    (5.99, 2.43004551273213460811e-17, 1.64896901081190903207e-19),
    (6.0, 2.15197367124989131166e-17, 1.45553473955813563445e-19),
    (8.0, 1.12242971729829270800e-29, 4.31851536834872716561e-32),
    (10.0, 2.08848758376254475700e-45, 5.17026595733184402139e-48),
    (12.0, 1.35626116920590421278e-64, 2.33854537596539650838e-67),
    (
        15.0,
        7.21299417245120666657e-100,
        7.97920764604284839112e-103,
    ),
    (
        20.0,
        5.39586561160790092893e-176,
        3.36403717954761179446e-179,
    ),
    (
        25.0,
        8.30017257119652275204e-274,
        3.31477804163535514765e-277,
    ),
    (
        26.0,
        5.66319240885614284648e-296,
        2.09128909718775003506e-299,
    ),
    (
        26.5,
        2.21090766426373427593e-307,
        7.85963151891318206947e-311,
    ),
    (
        27.0,
        5.23704892378925568502e-319,
        1.79351493658668397613e-322,
    ),
    (
        28.0,
        6.56321584032878415238e-343,
        2.09020119929914991860e-346,
    ),
    (
        30.0,
        2.56465620375611160003e-393,
        7.11615130274153823662e-397,
    ),
];

/// Relative error of `got` against `want`, or, where `want` is below f64's normal range, the
/// absolute error in units of the smallest subnormal (where relative precision does not exist).
fn error_vs_ref(got: f64, want: f64) -> (f64, bool) {
    if want >= f64::MIN_POSITIVE {
        ((got - want).abs() / want, true)
    } else {
        ((got - want).abs() / f64::from_bits(1), false)
    }
}

#[test]
fn erfc_matches_high_precision_references() {
    // libm's erfc (FreeBSD's, documented < 1 ulp): relative error within 1e-15 in the normal
    // range, within one subnormal step beyond.
    let mut worst = (0.0, 0.0);
    for &(a, want, _) in &ERFC_LAMBDA_REFS {
        let (err, normal) = error_vs_ref(libm::erfc(a), want);
        if normal {
            assert!(err <= 1e-15, "erfc({a}): rel. error {err:e}");
            if err > worst.0 {
                worst = (err, a);
            }
        } else {
            assert!(err <= 1.0, "erfc({a}): {err} subnormal steps off");
        }
    }
    println!(
        "erfc: worst relative error {:.2e} at a = {}",
        worst.0, worst.1
    );
}

#[test]
fn lambda_matches_high_precision_references() {
    // Λ (Eq. 8): relative error within 1e-14 wherever Λ is a normal f64 (a ≤ 26), from
    // a = 1e-3 (Λ = 281.6) through the switch to the continued fraction at a = 2 and on to
    // a = 26 (Λ = 2.1e-299); within one subnormal step beyond (a = 26.5, 27) and exactly 0 where
    // the true value is below half the smallest subnormal (a = 28, 30).
    let mut worst = (0.0, 0.0);
    for &(a, _, want) in &ERFC_LAMBDA_REFS {
        let got = lambda(a);
        let (err, normal) = error_vs_ref(got, want);
        if normal {
            assert!(
                err <= 1e-14,
                "Λ({a}) = {got:e}, want {want:e}: rel. error {err:e}"
            );
            if err > worst.0 {
                worst = (err, a);
            }
        } else {
            assert!(
                err <= 1.0,
                "Λ({a}) = {got:e}, want {want:e}: {err} subnormal steps off"
            );
        }
    }
    println!("Λ: worst relative error {:.2e} at a = {}", worst.0, worst.1);
}

#[test]
fn lambda_limits() {
    // a = +∞ is normal incidence: no shadowing. a → 0+ is grazing: Λ ~ 1/(2a√π) - 1/2 → +∞.
    assert_eq!(lambda(f64::INFINITY), 0.0);
    assert_eq!(lambda(0.0), f64::INFINITY);
    assert_eq!(lambda(-1.0), f64::INFINITY);
    assert!(lambda(f64::NAN).is_nan());
    let a: f64 = 1e-8;
    let asymptote = 1.0 / (2.0 * a * std::f64::consts::PI.sqrt()) - 0.5;
    assert!((lambda(a) / asymptote - 1.0).abs() < 1e-14);
    // Λ decreases strictly (fewer facets shadowed as the direction rises), across the switch
    // between the two formulas at a = 2 included, until it reaches the subnormals (a ≈ 26.3),
    // where neighbouring values may round to the same number.
    let mut prev = f64::INFINITY;
    for i in 1..=4000 {
        let a = i as f64 * 0.0075;
        let l = lambda(a);
        assert!(
            l < prev || l < f64::MIN_POSITIVE,
            "Λ({a}) = {l:e} ≥ Λ(previous) = {prev:e}"
        );
        prev = l;
    }
}

// ---------------------------------------------------------------------------------------------
// Eq. 7, Eq. 6, Eq. 9.

#[test]
fn slope_pdf_integrates_to_one() {
    // ∬ p(ζ) d²ζ = 1 for a normalised Gaussian; the composite rule on ±10σ integrates it to
    // within rounding (the mass beyond 10σ is 1.5e-23).
    for &(sx2, sy2) in &[
        (1e-4, 1e-4),
        (0.01, 0.0025),
        (0.09, 0.25),
        (1.0, 0.04),
        (4.0, 9.0),
    ] {
        let gl = gauss_legendre(8);
        let (sx, sy) = (f64::sqrt(sx2), f64::sqrt(sy2));
        let xs = composite(&gl, -10.0 * sx, 10.0 * sx, 20);
        let ys = composite(&gl, -10.0 * sy, 10.0 * sy, 20);
        let mut total = 0.0;
        for &(x, wx) in &xs {
            for &(y, wy) in &ys {
                total += wx * wy * slope_pdf(DVec2::new(x, y), sx2, sy2);
            }
        }
        assert!(
            (total - 1.0).abs() < 1e-13,
            "σ² = ({sx2}, {sy2}): ∬p = {total}"
        );
    }
}

#[test]
fn facet_normal_is_eq_6() {
    // f(0) is the mean normal; f(ζ) is unit and has slopes ζ (-f_x/f_z = ζ_x, -f_y/f_z = ζ_y).
    assert_eq!(facet_normal(DVec2::ZERO), DVec3::Z);
    for &z in &[
        DVec2::new(0.3, -0.2),
        DVec2::new(-4.0, 7.0),
        DVec2::new(1e-9, 0.0),
    ] {
        let f = facet_normal(z);
        assert!((f.length() - 1.0).abs() < 1e-15);
        assert!((-f.x / f.z - z.x).abs() <= 1e-15 * z.x.abs().max(1.0));
        assert!((-f.y / f.z - z.y).abs() <= 1e-15 * z.y.abs().max(1.0));
    }
    // Huge slopes: a horizontal unit normal, not an overflow.
    let f = facet_normal(DVec2::new(1e300, -1e300));
    assert!((f.length() - 1.0).abs() < 1e-15 && f.z >= 0.0);
}

#[test]
fn smith_a_is_cot_over_sqrt2_sigma() {
    // a = cot θ / (√2 σ_φ), σ_φ² = σ_x² cos² φ + σ_y² sin² φ (Eq. 9 with tan² θ, see below).
    let (sx2, sy2) = (0.04, 0.01);
    for &(t, p) in &[(30.0, 0.0), (60.0, 40.0), (85.0, 90.0), (10.0, 200.0)] {
        let (tr, pr) = (f64::to_radians(t), f64::to_radians(p));
        let sigma_phi2 = sx2 * pr.cos().powi(2) + sy2 * pr.sin().powi(2);
        let want = 1.0 / (std::f64::consts::SQRT_2 * sigma_phi2.sqrt() * tr.tan());
        let got = smith_a(dir(t, p), sx2, sy2);
        assert!(
            (got / want - 1.0).abs() < 1e-13,
            "θ = {t}, φ = {p}: {got} vs {want}"
        );
    }
    assert_eq!(smith_a(DVec3::Z, sx2, sy2), f64::INFINITY);
    assert_eq!(smith_a(DVec3::X, sx2, sy2), 0.0);
}

// ---------------------------------------------------------------------------------------------
// Eq. 10 and 11: the normalisation that decides Eq. 9.

/// The slope-variance pairs of the Eq. 11 sweep: every pair of σ in {0.01, 0.1, 0.3, 0.5, 1}
/// (isotropic and up to 100:1 anisotropic) in release builds; σ in {0.01, 0.3, 1} in debug
/// builds, to keep `cargo test` fast.
fn sigma_pairs() -> Vec<(f64, f64)> {
    let s: &[f64] = if cfg!(debug_assertions) {
        &[0.01, 0.3, 1.0]
    } else {
        &[0.01, 0.1, 0.3, 0.5, 1.0]
    };
    let mut out = Vec::new();
    for &a in s {
        for &b in s {
            out.push((a * a, b * b));
        }
    }
    out
}

/// View zenith angles of the sweep, grazing included (degrees).
const THETAS: [f64; 7] = [0.0, 30.0, 60.0, 80.0, 88.0, 89.5, 89.9];
/// View azimuths of the sweep (degrees).
const PHIS: [f64; 4] = [0.0, 30.0, 90.0, 135.0];

#[test]
fn visible_slope_pdf_is_normalised_eq_11() {
    // ∬ q^e_vn(ζ, v) d²ζ = 1 (Eq. 11) for every σ pair, view angle and azimuth of the sweep.
    // The quadrature (12 panels × 8 nodes on ±10σ per axis, cut at the visibility line) has a
    // worst error of 9.5e-13 over the release sweep (2e-11 with 10 panels, 3.6e-14 with 16):
    // tolerance 2e-12. The worst deviation measured is printed.
    let mut worst = (0.0, (0.0, 0.0, 0.0, 0.0));
    for (sx2, sy2) in sigma_pairs() {
        for &t in &THETAS {
            for &p in &PHIS {
                let v = dir(t, p);
                let total = integrate_visible(v, sx2, sy2, 12, 8, |z| {
                    visible_slope_pdf_unchecked(z, v, sx2, sy2)
                });
                let dev = (total - 1.0).abs();
                assert!(
                    dev < 2e-12,
                    "σ² = ({sx2}, {sy2}), θ = {t}, φ = {p}: ∬q^e = {total}"
                );
                if dev > worst.0 {
                    worst = (dev, (sx2.sqrt(), sy2.sqrt(), t, p));
                }
            }
        }
    }
    let (s, (sx, sy, t, p)) = worst;
    println!("Eq. 11: worst |∬q^e - 1| = {s:.2e} at σ = ({sx}, {sy}), θ_v = {t}°, φ_v = {p}°");
}

#[test]
fn eq_9_needs_tan_squared() {
    // Eq. 11 says ∬ p(ζ) max(v·f, 0)/f_z d²ζ = (1 + Λ(a_v)) cos θ_v. The left side is computed
    // here from p alone (no Λ), so each candidate form of a_v is tested on its own:
    // - Smith's a = cot θ/(√2 σ_φ) (tan² θ inside Eq. 9's bracket, what `smith_a` returns)
    //   satisfies it to quadrature precision (< 2e-12 over the sweep);
    // - the transcription's a = (2 σ_φ² tan θ)^(-1/2) fails it: the ratio is off by more than
    //   50% somewhere on the sweep (it agrees only where tan θ = 1 or Λ is negligible).
    let mut worst_smith: f64 = 0.0;
    let mut worst_printed = (0.0, 1.0, (0.0, 0.0, 0.0, 0.0));
    for (sx2, sy2) in sigma_pairs() {
        for &t in &THETAS[1..] {
            for &p in &PHIS {
                let v = dir(t, p);
                let projected = integrate_visible(v, sx2, sy2, 12, 8, |z| {
                    slope_pdf(z, sx2, sy2) * (v.z - z.dot(v.truncate())).max(0.0)
                });
                let smith = projected / ((1.0 + lambda(smith_a(v, sx2, sy2))) * v.z);
                worst_smith = worst_smith.max((smith - 1.0).abs());
                let sigma_phi2 = (sx2 * v.x * v.x + sy2 * v.y * v.y) / (v.x * v.x + v.y * v.y);
                let tan = (v.x * v.x + v.y * v.y).sqrt() / v.z;
                let a_printed = 1.0 / (2.0 * sigma_phi2 * tan).sqrt();
                let printed = projected / ((1.0 + lambda(a_printed)) * v.z);
                if (printed - 1.0).abs() > worst_printed.0 {
                    worst_printed = (
                        (printed - 1.0).abs(),
                        printed,
                        (sx2.sqrt(), sy2.sqrt(), t, p),
                    );
                }
            }
        }
    }
    let (dev, value, (sx, sy, t, p)) = worst_printed;
    println!(
        "Eq. 11 with Smith's tan² θ: worst deviation {worst_smith:.2e}; with the printed tan θ: \
         {dev:.3} (∬q^e = {value:.4}) at σ = ({sx}, {sy}), θ_v = {t}°, φ_v = {p}°"
    );
    assert!(worst_smith < 2e-12);
    assert!(dev > 0.5);
}

#[test]
fn q_vn_is_at_most_q_e_and_zero_when_unlit() {
    // Eq. 5 adds the light's shadowing to Eq. 10: q_vn ≤ q^e_vn pointwise, equal when the
    // light is at the zenith only if Λ(a_l) = 0 (a = +∞), zero for facets facing away from l
    // or a light below the horizon.
    let (sx2, sy2) = (0.09, 0.04);
    let v = dir(70.0, 20.0);
    for &z in &[DVec2::new(0.1, 0.05), DVec2::new(-0.3, 0.1), DVec2::ZERO] {
        let qe = visible_slope_pdf(z, v, sx2, sy2).unwrap();
        assert_eq!(q_vn(z, v, DVec3::Z, sx2, sy2).unwrap(), qe);
        for &(t, p) in &[(30.0, 180.0), (80.0, 90.0)] {
            let q = q_vn(z, v, dir(t, p), sx2, sy2).unwrap();
            assert!(q < qe && q > 0.0, "ζ = {z}: q_vn = {q}, q^e = {qe}");
        }
        assert_eq!(q_vn(z, v, dir(95.0, 0.0), sx2, sy2).unwrap(), 0.0);
    }
    // The facet ζ = (3, 0) faces away from l = dir(60, 0) (l·f < 0): H(l·f) = 0.
    let z = DVec2::new(3.0, 0.0);
    assert!(visible_slope_pdf(z, dir(60.0, 180.0), sx2, sy2).unwrap() > 0.0);
    assert_eq!(
        q_vn(z, dir(60.0, 180.0), dir(60.0, 0.0), sx2, sy2).unwrap(),
        0.0
    );
}

// ---------------------------------------------------------------------------------------------
// Eq. 13: reciprocity, the change of variables, energy.

#[test]
fn brdf_is_reciprocal() {
    // Eq. 13 is symmetric in v and l (h, ζ_h, v·h = l·h, cos θ_v cos θ_l and Λ_v + Λ_l are);
    // the implementation is symmetric bit for bit.
    let dirs: Vec<DVec3> = [0.0, 10.0, 45.0, 75.0, 89.0, 89.999]
        .iter()
        .flat_map(|&t| [0.0, 37.0, 90.0, 200.0, 333.0].map(move |p| dir(t, p)))
        .collect();
    for &(sx2, sy2) in &[(1e-6, 1e-6), (0.01, 0.04), (0.3, 0.05), (1.0, 1.0)] {
        for &v in &dirs {
            for &l in &dirs {
                let a = brdf(v, l, sx2, sy2, 0.02).unwrap();
                let b = brdf(l, v, sx2, sy2, 0.02).unwrap();
                assert_eq!(a.to_bits(), b.to_bits(), "v = {v}, l = {l}: {a} vs {b}");
            }
        }
    }
}

/// The light direction of slope `ζ` seen from `v` (`r(v, ζ)` of Eq. 18) and the solid angle
/// per unit slope area `|∂r/∂ζ_x × ∂r/∂ζ_y|`, by central differences (step 1e-6: relative
/// error about 1e-9, far below what the tests compare).
fn mirror_and_jacobian(v: DVec3, z: DVec2) -> (DVec3, f64) {
    let h = 1e-6;
    let r = |z: DVec2| reflect(v, facet_normal(z));
    let dx = (r(z + DVec2::new(h, 0.0)) - r(z - DVec2::new(h, 0.0))) / (2.0 * h);
    let dy = (r(z + DVec2::new(0.0, h)) - r(z - DVec2::new(0.0, h))) / (2.0 * h);
    (r(z), dx.cross(dy).length())
}

#[test]
fn brdf_times_cos_dl_is_q_vn_d_zeta() {
    // Eq. 13 is built so that brdf(v, l) cos θ_l d²ω_l = q_vn(ζ_h, v, l) F d²ζ. Checked
    // pointwise with the Jacobian d²ω_l/d²ζ measured by finite differences of ζ ↦ r(v, ζ):
    // agreement within 1e-7 relative. It equals 4 h_z³ v·h (the printed Eq. 12 has h_z², which
    // would put the ratio off by h_z, 0.83 at ζ = (0.5, -0.4)).
    let (sx2, sy2) = (0.09, 0.04);
    for &(t, p) in &[(0.0, 0.0), (40.0, 10.0), (75.0, 120.0), (88.0, 300.0)] {
        let v = dir(t, p);
        for &z in &[
            DVec2::new(0.05, 0.02),
            DVec2::new(0.5, -0.4),
            DVec2::new(-0.2, 0.3),
        ] {
            let (l, jac) = mirror_and_jacobian(v, z);
            if l.z <= 0.0 || facet_normal(z).dot(v) <= 0.0 {
                continue;
            }
            let lhs = brdf(v, l, sx2, sy2, 1.0).unwrap() * l.z * jac;
            let rhs = q_vn(z, v, l, sx2, sy2).unwrap();
            assert!(
                (lhs / rhs - 1.0).abs() < 1e-7,
                "v = {v}, ζ = {z}: {lhs} vs {rhs}"
            );
            let h = facet_normal(z);
            let eq12 = 4.0 * h.z.powi(3) * v.dot(h);
            assert!(
                (jac / eq12 - 1.0).abs() < 1e-7,
                "Jacobian {jac} vs 4 h_z³ v·h = {eq12}"
            );
        }
    }
}

/// Directional albedo `∫ brdf(v, l) cos θ_l d²ω_l` over the upper hemisphere, directly over
/// `l`: composite Gauss–Legendre in `θ_l` on [0, π/2] (`panels` panels of 8 nodes,
/// `d²ω_l = sin θ_l dθ_l dφ_l`) and the trapezoid rule in `φ_l` (`n_phi` points, spectrally
/// accurate for a periodic integrand). Good away from grazing views only: there the lobe
/// in `l` narrows with `v·h` (0.07 rad wide at σ = 0.1, θ_v = 89°).
fn albedo_over_l(v: DVec3, sx2: f64, sy2: f64, panels: usize, n_phi: usize) -> f64 {
    let gl = gauss_legendre(8);
    let dphi = std::f64::consts::TAU / n_phi as f64;
    let mut total = 0.0;
    for (theta, wt) in composite(&gl, 0.0, std::f64::consts::FRAC_PI_2, panels) {
        let (st, ct) = theta.sin_cos();
        let mut ring = 0.0;
        for k in 0..n_phi {
            let (sp, cp) = (k as f64 * dphi).sin_cos();
            let l = DVec3::new(st * cp, st * sp, ct);
            ring += brdf_unchecked(v, l, sx2, sy2, 1.0) * ct;
        }
        total += wt * st * ring * dphi;
    }
    total
}

/// The same albedo with `l = r(v, ζ)` (Eq. 18) and `d²ω_l = 4 h_z³ v·h d²ζ` (the Jacobian
/// checked by finite differences in `brdf_times_cos_dl_is_q_vn_d_zeta`), over the slopes whose
/// mirror direction is above the horizon; both boundaries of that region are cut exactly, so
/// the lobe is resolved at every view angle.
fn albedo_over_slopes(v: DVec3, sx2: f64, sy2: f64, panels: usize) -> f64 {
    integrate_visible_cut(v, sx2, sy2, panels, 8, true, |z| {
        let f = facet_normal(z);
        let l = reflect(v, f);
        brdf_unchecked(v, l, sx2, sy2, 1.0) * l.z * 4.0 * f.z.powi(3) * v.dot(f)
    })
}

#[test]
fn brdf_creates_no_energy() {
    // With R = 1 (every facet a perfect mirror) the directional albedo is
    // ∬ q_vn(ζ, v, r) H(r_z) d²ζ ≤ ∬ q^e_vn d²ζ = 1: the light's shadowing and the reflections
    // into the sea remove energy; nothing may add any. Swept over σ from 0.05 to 1
    // (anisotropic included) and θ_v from 0 to 89.9°. Quadrature: 16 panels × 8 nodes per
    // axis. Against 48 panels it agrees within 1e-11 for σ ≤ 0.3 and, for σ ≥ 0.5, within
    // 4e-9 from θ_v = 80° on; below 80° the chords of the horizon disc touch it tangentially
    // inside the box and the error reaches 2e-4 (σ = 0.5, θ_v = 0), but there the albedo is
    // at least 0.16 below 1 (0.376 at σ = (1, 0.6), θ_v = 0: steep facets send much of the
    // light into the sea). Wherever the albedo comes within 0.1 of 1 the error is below
    // 4e-9, hence the bound 1 + 1e-9 is not loosened by the quadrature.
    // A near-mirror sea seen from 30° returns almost everything (> 0.999), and the albedo is
    // not monotonic in θ_v (at σ = (0.1, 0.05): 0.921 at 80°, 0.997 at 89.9°: at grazing the
    // visible facets are those tilted towards the viewer, which reflect upwards, away from the
    // shadowed horizon).
    let mut worst = (0.0, 0.0, 0.0, 0.0);
    for &(sx2, sy2) in &[
        (0.0025, 0.0025),
        (0.01, 0.0025),
        (0.09, 0.0225),
        (0.25, 0.25),
        (1.0, 0.36),
    ] {
        for &t in &[0.0, 30.0, 60.0, 80.0, 89.0, 89.9] {
            let a = albedo_over_slopes(dir(t, 30.0), sx2, sy2, 16);
            assert!(a <= 1.0 + 1e-9, "σ² = ({sx2}, {sy2}), θ = {t}: albedo {a}");
            if a > worst.0 {
                worst = (a, sx2, sy2, t);
            }
        }
    }
    let near_mirror = albedo_over_slopes(dir(30.0, 0.0), 0.0025, 0.0025, 16);
    assert!(near_mirror > 0.999, "{near_mirror}");
    println!(
        "largest albedo with R = 1: {:.12} at σ² = ({}, {}), θ_v = {}°",
        worst.0, worst.1, worst.2, worst.3
    );
}

#[test]
fn albedo_over_l_matches_albedo_over_slopes() {
    // The integral over l itself (no change of variables) agrees with the slope-space one
    // within 1e-9 where both grids resolve the lobe (σ ≤ 0.3, θ_v ≤ 60°; measured: 9e-12 at
    // most, at σ = (0.3, 0.15), θ_v = 30°).
    for &(sx2, sy2, t) in &[
        (0.01, 0.0025, 60.0),
        (0.09, 0.0225, 30.0),
        (0.09, 0.0225, 0.0),
        (0.0025, 0.0025, 30.0),
    ] {
        let v = dir(t, 30.0);
        let direct = albedo_over_l(v, sx2, sy2, 32, 512);
        let slopes = albedo_over_slopes(v, sx2, sy2, 16);
        assert!(
            (direct - slopes).abs() < 1e-9,
            "θ_v = {t}: {direct} vs {slopes}"
        );
    }
}

// ---------------------------------------------------------------------------------------------
// Eq. 15.

#[test]
fn sun_highlight_concentrates_at_the_mirror_direction() {
    // v at 60° from the zenith, the Sun at its mirror direction (60°, opposite azimuth), then
    // 5° further down in the plane of incidence: the half vector tilts by 2.5°, a slope of
    // ζ = tan 2.5° = 0.0437, so p(ζ_h) falls by exp(ζ²/(2σ²)). At σ² = 1e-4 that is 1.4e4;
    // Λ is negligible at both (a ≈ 40 and 33) and Schlick's F rises from 0.051 to 0.065 (v·h
    // from cos 60° to cos 62.5°), so the ratio is 1.4e4 / 1.27 ≈ 1.1e4: asserted > 1e4. With
    // σ² = 1e-3 the same ratio is only exp(0.95)/1.27 ≈ 2.0: the highlight concentrates as σ
    // falls. The brightest direction on a 0.1° scan of ±3° is within 0.1° of the mirror
    // direction: not exactly on it, since Schlick's F rises away from the normal and moves the
    // maximum of p(ζ_h) F by about 4σ² d(ln F)/dθ_d ≈ 4e-4 · 2.6 rad ≈ 0.06°.
    let (l_sun, omega, r) = (1.0e5, 6.8e-5, 0.02);
    let v = dir(60.0, 0.0);
    let mirror = dir(60.0, 180.0);
    let off = dir(65.0, 180.0);
    let i = |l: DVec3, s2: f64| sun_radiance(v, l, s2, s2, l_sun, omega, r).unwrap();
    let sharp = i(mirror, 1e-4) / i(off, 1e-4);
    let broad = i(mirror, 1e-3) / i(off, 1e-3);
    println!("I_sun(mirror)/I_sun(5° off): {sharp:.4e} at σ² = 1e-4, {broad:.4} at σ² = 1e-3");
    assert!(sharp > 1e4, "{sharp}");
    assert!(broad > 1.9 && broad < 2.1, "{broad}");
    let peak = (-30..=30)
        .map(|k| 60.0 + 0.1 * k as f64)
        .max_by(|&a, &b| i(dir(a, 180.0), 1e-4).total_cmp(&i(dir(b, 180.0), 1e-4)))
        .unwrap();
    assert!((peak - 60.0).abs() <= 0.1 + 1e-12, "peak at {peak}°");
    // Eq. 15 is L_sun Ω_sun brdf cos θ_l.
    let b = brdf(v, off, 1e-3, 1e-3, r).unwrap();
    let want = l_sun * omega * b * off.z;
    assert!((i(off, 1e-3) / want - 1.0).abs() < 1e-15);
}

// ---------------------------------------------------------------------------------------------
// Validation and extreme inputs.

#[test]
fn checked_functions_refuse_invalid_input() {
    let v = dir(30.0, 0.0);
    assert_eq!(
        brdf(v * 1.1, v, 0.1, 0.1, 0.02),
        Err(BrdfError::NotUnit("v"))
    );
    assert_eq!(
        brdf(v, DVec3::ZERO, 0.1, 0.1, 0.02),
        Err(BrdfError::NotUnit("l"))
    );
    assert_eq!(
        brdf(v, DVec3::new(f64::NAN, 0.0, 1.0), 0.1, 0.1, 0.02),
        Err(BrdfError::NotFinite("l"))
    );
    assert!(matches!(
        brdf(v, v, 0.0, 0.1, 0.02),
        Err(BrdfError::OutOfRange {
            name: "sigma_x2",
            ..
        })
    ));
    assert!(matches!(
        brdf(v, v, 0.1, -1.0, 0.02),
        Err(BrdfError::OutOfRange {
            name: "sigma_y2",
            ..
        })
    ));
    assert_eq!(
        brdf(v, v, f64::INFINITY, 0.1, 0.02),
        Err(BrdfError::NotFinite("sigma_x2"))
    );
    assert!(matches!(
        brdf(v, v, 0.1, 0.1, 1.5),
        Err(BrdfError::OutOfRange {
            name: "fresnel_r",
            ..
        })
    ));
    assert!(matches!(
        visible_slope_pdf(DVec2::ZERO, dir(120.0, 0.0), 0.1, 0.1),
        Err(BrdfError::OutOfRange { name: "v.z", .. })
    ));
    assert_eq!(
        visible_slope_pdf(DVec2::new(f64::NAN, 0.0), v, 0.1, 0.1),
        Err(BrdfError::NotFinite("zeta"))
    );
    assert!(matches!(
        sun_radiance(v, v, 0.1, 0.1, -1.0, 6.8e-5, 0.02),
        Err(BrdfError::OutOfRange { name: "l_sun", .. })
    ));
    assert!(matches!(
        sun_radiance(v, v, 0.1, 0.1, 1.0, 7.0, 0.02),
        Err(BrdfError::OutOfRange {
            name: "omega_sun",
            ..
        })
    ));
    // Below the horizon the BRDF is zero, not an error.
    assert_eq!(brdf(dir(100.0, 0.0), v, 0.1, 0.1, 0.02), Ok(0.0));
    assert_eq!(brdf(v, DVec3::X, 0.1, 0.1, 0.02), Ok(0.0));
}

#[test]
fn no_nan_for_valid_extreme_input() {
    // Every checked function, at every combination of extreme valid inputs (the smallest and
    // largest variances, exact and near grazing, normal incidence, huge slopes), returns a
    // non-negative number, never NaN (+∞ is possible for the BRDF of a near-mirror seen
    // exactly at the reflection, where the true value is a Dirac).
    let variances = [
        f64::MIN_POSITIVE,
        1e-300,
        1e-12,
        1e-4,
        0.25,
        1.0,
        1e4,
        1e150,
        1e300,
        f64::MAX,
    ];
    let thetas = [0.0, 1e-9, 30.0, 89.99, 90.0 - 1e-12, 90.0];
    let phis = [0.0, 45.0, 90.0, 180.0];
    let dirs: Vec<DVec3> = thetas
        .iter()
        .flat_map(|&t| phis.map(move |p| dir(t, p)))
        .collect();
    let zetas = [
        DVec2::ZERO,
        DVec2::new(1e-3, -1e-3),
        DVec2::new(-2.0, 0.5),
        DVec2::new(1e200, 1e200),
    ];
    for &sx2 in &variances {
        for &sy2 in &[f64::MIN_POSITIVE, 0.25, f64::MAX] {
            for &v in &dirs {
                for &z in &zetas {
                    let q = visible_slope_pdf(z, v, sx2, sy2).unwrap();
                    assert!(q >= 0.0, "q^e({z}, {v}, {sx2}, {sy2}) = {q}");
                }
                for &l in &dirs {
                    let b = brdf(v, l, sx2, sy2, 0.02).unwrap();
                    assert!(b >= 0.0, "brdf({v}, {l}, {sx2}, {sy2}) = {b}");
                    let s = sun_radiance(v, l, sx2, sy2, 1e5, 6.8e-5, 0.02).unwrap();
                    assert!(s >= 0.0, "I_sun({v}, {l}, {sx2}, {sy2}) = {s}");
                    let q = q_vn(zetas[2], v, l, sx2, sy2).unwrap();
                    assert!(q >= 0.0, "q_vn({v}, {l}, {sx2}, {sy2}) = {q}");
                }
            }
        }
    }
}
