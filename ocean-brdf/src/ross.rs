//! The Ross BRDF (§4).
//!
//! Ross, Dion and Potvin's BRDF for a rough surface whose heights and slopes follow
//! uncorrelated Gaussian distributions: a facet of slopes `ζ` is seen with the probability
//! `q_vn` of Eq. 5 (Smith shadowing, normalised), and the BRDF of Eq. 13 is the probability to see
//! the facet whose normal is the half vector, times the Fresnel factor.
//!
//! Every function works in the surface's tangent frame: x along the wind, y across it, z along
//! the (average) normal. `v` (towards the viewer) and `l` (towards the light) are unit vectors
//! in that frame; `sigma_x2`, `sigma_y2` are the slope variances along x and y (Eq. 4).
//!
//! The checked functions (`visible_slope_pdf`, `q_vn`, `brdf`, `sun_radiance`) validate their
//! inputs and never return NaN for valid input, grazing angles and extreme variances included;
//! each has an `_unchecked` twin for inner loops whose inputs are known to be valid.
//!
//! Two misprints of the transcription are corrected here (both found by testing the printed
//! formula against an identity the paper states, see `tests/ross.rs`):
//! - Eq. 9 prints `a = (2 σ_φ² tan θ)^(-1/2)`; the normalisation of Eq. 11 holds only with
//!   Smith's `a = (2 σ_φ² tan² θ)^(-1/2)`, which [`smith_a`] implements.
//! - Eq. 12 prints `d²ζ = d²ω_l / (4 h_z² v·h)`; the Jacobian is `4 h_z³ v·h` (slopes to half
//!   vectors `h_z³`, half vectors to light directions `4 v·h`), which is what Eq. 13's
//!   `4 h_z³ cos θ_l v·h` already uses. [`brdf`] follows Eq. 13; the tests check that its albedo
//!   integrated over light directions equals `q_vn` integrated over slopes.

use glam::{DVec2, DVec3};

use crate::error::{BrdfError, check, check_direction};
use crate::fresnel::schlick;

/// √π (to the nearest f64).
const SQRT_PI: f64 = 1.772_453_850_905_516;
/// √(2π) (to the nearest f64).
const SQRT_2PI: f64 = 2.506_628_274_631_000_7;

/// Below this `a`, [`lambda`] uses Eq. 8 as printed; above, a continued fraction without the
/// cancellation between `exp(-a²)` and `a √π erfc(a)` (which costs about `log10(2a²)` digits:
/// one at 2, four at 26).
const LAMBDA_SWITCH: f64 = 2.0;

/// The Gaussian slope distribution `p(ζ)`, Eq. 7.
///
/// Requires `sigma_x2 > 0` and `sigma_y2 > 0` (with a zero variance the distribution is a
/// Dirac and has no density).
#[inline]
pub fn slope_pdf(zeta: DVec2, sigma_x2: f64, sigma_y2: f64) -> f64 {
    let e = zeta.x * zeta.x / sigma_x2 + zeta.y * zeta.y / sigma_y2;
    // σ_x σ_y as a product of square roots: σ_x² σ_y² could underflow or overflow where σ_x σ_y
    // does not.
    let norm = 2.0 * core::f64::consts::PI * libm::sqrt(sigma_x2) * libm::sqrt(sigma_y2);
    libm::exp(-0.5 * e) / norm
}

/// The unit normal `f(ζ)` of the facet of slopes `ζ`, Eq. 6: `(-ζ_x, -ζ_y, 1) / √(1 + |ζ|²)`.
///
/// Scaled before normalising, so huge slopes give a horizontal unit normal instead of an
/// overflow.
#[inline]
pub fn facet_normal(zeta: DVec2) -> DVec3 {
    let m = zeta.x.abs().max(zeta.y.abs()).max(1.0);
    let n = DVec3::new(-zeta.x / m, -zeta.y / m, 1.0 / m);
    n / libm::sqrt(n.dot(n))
}

/// Smith's `Λ(a)` for Gaussian slopes, Eq. 8:
/// `Λ(a) = (exp(-a²) - a √π erfc(a)) / (2 a √π)`.
///
/// - `a = +∞` (normal incidence, or no slope variance along the direction): `Λ = 0`, no
///   shadowing.
/// - `a → 0+` (grazing): `Λ ~ 1/(2a√π) → +∞`; `a ≤ 0` (a direction on or below the mean
///   plane, see [`smith_a`]) returns `+∞`: every facet is shadowed.
/// - NaN returns NaN.
///
/// Accuracy: relative error below 1e-14 where `Λ(a)` is a normal f64 (`a` up to about 26.3;
/// beyond, `Λ` underflows through the subnormals to 0, as it should: `Λ(30) ≈ 7e-397`).
/// Below `a = 2` the printed formula is used with `libm::erfc`; above it, where the two terms
/// of the numerator cancel, `Λ = exp(-a²)/(2a√π) · K/(a + K)` with Laplace's continued fraction
/// `√π exp(a²) erfc(a) = 1/(a + K)`, `K = (1/2)/(a + 1/(a + (3/2)/(a + 2/(a + …))))`, which has
/// no cancellation.
pub fn lambda(a: f64) -> f64 {
    if a.is_nan() {
        return f64::NAN;
    }
    if a <= 0.0 {
        return f64::INFINITY;
    }
    if a == f64::INFINITY {
        return 0.0;
    }
    if a < LAMBDA_SWITCH {
        return (libm::exp(-a * a) - a * SQRT_PI * libm::erfc(a)) / (2.0 * a * SQRT_PI);
    }
    let k = laplace_tail(a);
    // Scale first and multiply by exp(-a²) last, so a result in the subnormal range is rounded
    // once.
    let scale = k / ((a + k) * 2.0 * a * SQRT_PI);
    exp_neg_square(a) * scale
}

/// `K(a)` of Laplace's continued fraction for `erfc` (see [`lambda`]), evaluated bottom-up with
/// enough levels for full f64 precision at `a ≥ 2` (checked against 40-digit references: 96
/// levels reach 2e-21 at a = 2, 48 levels 9e-21 at a = 3, 24 levels 4e-23 at a = 6).
fn laplace_tail(a: f64) -> f64 {
    let levels: u32 = if a < 3.0 {
        96
    } else if a < 6.0 {
        48
    } else {
        24
    };
    let mut t = 0.0;
    for n in (2..=levels).rev() {
        t = (0.5 * f64::from(n)) / (a + t);
    }
    0.5 / (a + t)
}

/// `exp(-a²)` with `a²` split exactly into `hi + lo` (`fma`), so the rounding of `a²` (an
/// absolute error up to `a² · 1.1e-16`, i.e. a relative error of `exp` of 8e-14 at a = 26) does
/// not reach the result.
fn exp_neg_square(a: f64) -> f64 {
    let hi = a * a;
    if hi > 746.0 {
        // Below half the smallest subnormal (and a² may have overflowed, which fma would turn
        // into inf · 0).
        return 0.0;
    }
    let lo = libm::fma(a, a, -hi);
    libm::exp(-hi) * (1.0 - lo)
}

/// `a_i` of Eq. 9 for a unit direction `dir` (`v` or `l`):
/// `a = cot θ / (√2 σ_φ)`, `σ_φ² = σ_x² cos² φ + σ_y² sin² φ`.
///
/// Computed without angles as `a = dir_z / √(2 (σ_x² dir_x² + σ_y² dir_y²))` (since
/// `σ_φ² sin² θ = σ_x² dir_x² + σ_y² dir_y²`): `+∞` at normal incidence, 0 at grazing, negative
/// below the horizon (where [`lambda`] gives `+∞`). Returns NaN only for a horizontal `dir`
/// with no slope variance along it, a case the checked functions exclude.
///
/// Misprint: the transcription prints `a = (2 σ_φ² tan θ)^(-1/2)`. Smith's shadowing for
/// Gaussian slopes has `tan² θ` inside, i.e. `a = 1 / (√2 σ_φ tan θ)`, and only that form makes
/// `(1 + Λ(a)) cos θ_v` equal to `∫ p(ζ) max(v·f, 0) / f_z d²ζ`, which is what Eq. 11 states.
/// With the printed form `∬ q^e_vn d²ζ` is `(1 + Λ(a_Smith)) / (1 + Λ(a_printed))` instead of 1:
/// 1.26 at σ = 0.3, θ_v = 80°; 2.73 at σ = 0.1, θ_v = 89°; 22.8 at σ = (0.5, 1), θ_v = 89.9°
/// (it is right only where `tan θ = 1` or `Λ` is negligible). With `tan² θ` the numerical
/// integral is 1 within 1e-12 over the test's whole sweep (tests/ross.rs).
#[inline]
pub fn smith_a(dir: DVec3, sigma_x2: f64, sigma_y2: f64) -> f64 {
    dir.z / (core::f64::consts::SQRT_2 * projected_deviation(dir, sigma_x2, sigma_y2))
}

/// `σ_φ sin θ = √(σ_x² dir_x² + σ_y² dir_y²)`: the slope standard deviation along `dir`'s
/// azimuth times `sin θ` (a `hypot`, so huge variances do not overflow).
#[inline]
pub(crate) fn projected_deviation(dir: DVec3, sigma_x2: f64, sigma_y2: f64) -> f64 {
    libm::hypot(libm::sqrt(sigma_x2) * dir.x, libm::sqrt(sigma_y2) * dir.y)
}

/// `Λ(a) cos θ` for a unit direction above or on the horizon (`dir.z ≥ 0`), finite at grazing.
///
/// At grazing `Λ → ∞` and `cos θ → 0`, but their product tends to `σ_φ sin θ / √(2π)`. With
/// `c = σ_φ sin θ` and `a = cos θ / (√2 c)`, Eq. 8 times `cos θ` is
/// `c exp(-a²)/√(2π) - cos θ erfc(a)/2`, used below `a = 1` (no 0·∞, no cancellation worse
/// than a factor 4); above, `cos θ · Λ(a)` directly.
pub(crate) fn lambda_cos(dir: DVec3, sigma_x2: f64, sigma_y2: f64) -> f64 {
    let c = projected_deviation(dir, sigma_x2, sigma_y2);
    let z = dir.z.max(0.0);
    if c == 0.0 {
        // No slope variance along the view: nothing is shadowed (Λ(+∞) = 0).
        return 0.0;
    }
    let a = z / (core::f64::consts::SQRT_2 * c);
    if a < 1.0 {
        c * libm::exp(-a * a) / SQRT_2PI - 0.5 * z * libm::erfc(a)
    } else {
        z * lambda(a)
    }
}

/// `(1 + Λ(a)) cos θ`, the normaliser of Eq. 10 (the projected area of the rough surface per
/// unit area of its mean plane, seen from `dir`), finite and positive at grazing whenever
/// there is slope variance along `dir`'s azimuth.
#[inline]
pub(crate) fn smith_normaliser(dir: DVec3, sigma_x2: f64, sigma_y2: f64) -> f64 {
    dir.z.max(0.0) + lambda_cos(dir, sigma_x2, sigma_y2)
}

/// `max(v·f, 0) / f_z = max(v_z - ζ·v_xy, 0)`: the projected area of the facet `ζ` seen from
/// `v`, per unit area of the mean plane (exact, and free of the square root of Eq. 6).
#[inline]
fn facet_projected_area(zeta: DVec2, v: DVec3) -> f64 {
    (v.z - zeta.x * v.x - zeta.y * v.y).max(0.0)
}

/// `q^e_vn(ζ, v)` of Eq. 10, per `d²ζ`: the probability density that the facet of slopes `ζ`
/// is the one seen from `v`, with no light source (only masking).
///
/// `v` must be a unit vector with `v.z ≥ 0`; `sigma_x2`, `sigma_y2` in
/// `[f64::MIN_POSITIVE, f64::MAX]`. Integrates to 1 over the slope plane (Eq. 11).
pub fn visible_slope_pdf(
    zeta: DVec2,
    v: DVec3,
    sigma_x2: f64,
    sigma_y2: f64,
) -> Result<f64, BrdfError> {
    check_finite2("zeta", zeta)?;
    let v = check_direction("v", v)?;
    check("v.z", v.z, 0.0, 1.0)?;
    check_variances(sigma_x2, sigma_y2)?;
    Ok(visible_slope_pdf_unchecked(zeta, v, sigma_x2, sigma_y2))
}

/// [`visible_slope_pdf`] without validation.
#[inline]
pub fn visible_slope_pdf_unchecked(zeta: DVec2, v: DVec3, sigma_x2: f64, sigma_y2: f64) -> f64 {
    let area = facet_projected_area(zeta, v);
    if area == 0.0 {
        return 0.0;
    }
    // Eq. 10: p max(v·f, 0) / ((1 + Λ(a_v)) f_z cos θ_v), with max(v·f, 0)/f_z written exactly
    // and (1 + Λ) cos θ_v computed so that it stays finite at grazing.
    slope_pdf(zeta, sigma_x2, sigma_y2) * area / smith_normaliser(v, sigma_x2, sigma_y2)
}

/// `q_vn(ζ, v, l)` of Eq. 5, per `d²ζ`: the probability density that the facet of slopes `ζ`
/// is seen from `v` and lit from `l` (Smith masking and shadowing).
///
/// `v` must be a unit vector with `v.z ≥ 0`, `l` a unit vector; a light on or below the
/// horizon (`l.z ≤ 0`) shadows every facet (`Λ(a_l) = +∞`) and gives 0. Variances as in
/// [`visible_slope_pdf`].
pub fn q_vn(
    zeta: DVec2,
    v: DVec3,
    l: DVec3,
    sigma_x2: f64,
    sigma_y2: f64,
) -> Result<f64, BrdfError> {
    check_finite2("zeta", zeta)?;
    let v = check_direction("v", v)?;
    let l = check_direction("l", l)?;
    check("v.z", v.z, 0.0, 1.0)?;
    check_variances(sigma_x2, sigma_y2)?;
    Ok(q_vn_unchecked(zeta, v, l, sigma_x2, sigma_y2))
}

/// [`q_vn`] without validation.
pub fn q_vn_unchecked(zeta: DVec2, v: DVec3, l: DVec3, sigma_x2: f64, sigma_y2: f64) -> f64 {
    if l.z <= 0.0 {
        return 0.0;
    }
    let area = facet_projected_area(zeta, v);
    // H(l·f), with l·f of the same sign as l_z - ζ·l_xy.
    if area == 0.0 || l.z - zeta.x * l.x - zeta.y * l.y <= 0.0 {
        return 0.0;
    }
    // (1 + Λ_v + Λ_l) cos θ_v = (1 + Λ_v) cos θ_v + (Λ_l cos θ_l) cos θ_v / cos θ_l.
    let denom =
        smith_normaliser(v, sigma_x2, sigma_y2) + lambda_cos(l, sigma_x2, sigma_y2) * v.z / l.z;
    slope_pdf(zeta, sigma_x2, sigma_y2) * area / denom
}

/// The Ross BRDF, Eq. 13, with Schlick's Fresnel factor of Eq. 14 at `v·h`,
/// `h = normalize(v + l)`:
///
/// `brdf = p(ζ_h) F(v·h) / (4 h_z⁴ cos θ_v cos θ_l (1 + Λ(a_v) + Λ(a_l)))`
///
/// (Eq. 13 with Eq. 5 at `ζ_h`, where `max(v·h, 0) H(l·h) = v·h` and `f_z = h_z`). Zero when
/// `v` or `l` is on or below the horizon. Symmetric in `v` and `l` bit for bit.
///
/// `v`, `l` unit vectors; `sigma_x2`, `sigma_y2` in `[f64::MIN_POSITIVE, f64::MAX]`; the
/// reflectance at normal incidence `fresnel_r` in `[0, 1]` (water: [`crate::fresnel::WATER_R`]).
pub fn brdf(
    v: DVec3,
    l: DVec3,
    sigma_x2: f64,
    sigma_y2: f64,
    fresnel_r: f64,
) -> Result<f64, BrdfError> {
    let v = check_direction("v", v)?;
    let l = check_direction("l", l)?;
    check_variances(sigma_x2, sigma_y2)?;
    check("fresnel_r", fresnel_r, 0.0, 1.0)?;
    Ok(brdf_unchecked(v, l, sigma_x2, sigma_y2, fresnel_r))
}

/// [`brdf`] without validation.
pub fn brdf_unchecked(v: DVec3, l: DVec3, sigma_x2: f64, sigma_y2: f64, fresnel_r: f64) -> f64 {
    if v.z <= 0.0 || l.z <= 0.0 {
        return 0.0;
    }
    let sum = v + l;
    let len = libm::sqrt(sum.dot(sum));
    let h = sum / len;
    // v·h = (1 + v·l)/|v + l| = |v + l|/2 for unit v and l: symmetric in v and l, and never
    // negative.
    let v_dot_h = 0.5 * len;
    let zeta_h = DVec2::new(-h.x / h.z, -h.y / h.z);
    let p = slope_pdf(zeta_h, sigma_x2, sigma_y2);
    let f = schlick(v_dot_h, fresnel_r);
    // cos θ_v cos θ_l (1 + Λ_v + Λ_l), written symmetrically and finite at grazing.
    let shadowing = v.z * l.z
        + (l.z * lambda_cos(v, sigma_x2, sigma_y2) + v.z * lambda_cos(l, sigma_x2, sigma_y2));
    let hz2 = h.z * h.z;
    ratio(p * f, 4.0 * hz2 * hz2 * shadowing)
}

/// The reflected Sun radiance `I_sun` of Eq. 15:
///
/// `I_sun ≈ L_sun Ω_sun p(ζ_h) F(v·h) / (4 h_z⁴ cos θ_v (1 + Λ(a_v) + Λ(a_l)))`,
///
/// i.e. `L_sun Ω_sun brdf(v, l) cos θ_l` with the BRDF taken as constant over the solar disc.
/// The paper clamps the slope variances to a minimum here so that a flat sea still shows a
/// disc rather than a point: that is the caller's choice of `sigma_x2`, `sigma_y2`.
///
/// `l_sun ≥ 0` (the Sun's radiance, any unit), `omega_sun` in `[0, 2π]` (its solid angle in
/// steradians), the other inputs as in [`brdf`].
pub fn sun_radiance(
    v: DVec3,
    l: DVec3,
    sigma_x2: f64,
    sigma_y2: f64,
    l_sun: f64,
    omega_sun: f64,
    r: f64,
) -> Result<f64, BrdfError> {
    check("l_sun", l_sun, 0.0, f64::MAX)?;
    check("omega_sun", omega_sun, 0.0, core::f64::consts::TAU)?;
    let v = check_direction("v", v)?;
    let l = check_direction("l", l)?;
    check_variances(sigma_x2, sigma_y2)?;
    check("r", r, 0.0, 1.0)?;
    Ok(sun_radiance_unchecked(
        v, l, sigma_x2, sigma_y2, l_sun, omega_sun, r,
    ))
}

/// [`sun_radiance`] without validation.
pub fn sun_radiance_unchecked(
    v: DVec3,
    l: DVec3,
    sigma_x2: f64,
    sigma_y2: f64,
    l_sun: f64,
    omega_sun: f64,
    r: f64,
) -> f64 {
    let b = brdf_unchecked(v, l, sigma_x2, sigma_y2, r);
    // L_sun Ω brdf cos θ_l, where a zero factor wins over a BRDF that overflowed (a
    // mirror-like sea seen exactly at the Sun's reflection).
    let light = l_sun * omega_sun * l.z.max(0.0);
    if light == 0.0 || b == 0.0 {
        0.0
    } else {
        light * b
    }
}

/// `num / den` with `0 / x = 0` for every `x` (0/0 included): a zero density or zero light
/// is zero whatever the denominator did in the extreme ranges.
#[inline]
fn ratio(num: f64, den: f64) -> f64 {
    if num == 0.0 { 0.0 } else { num / den }
}

/// Validates a pair of slope variances for the functions that need a density `p(ζ)`:
/// positive (a zero variance makes `p` a Dirac) and finite.
pub(crate) fn check_variances(sigma_x2: f64, sigma_y2: f64) -> Result<(), BrdfError> {
    check("sigma_x2", sigma_x2, f64::MIN_POSITIVE, f64::MAX)?;
    check("sigma_y2", sigma_y2, f64::MIN_POSITIVE, f64::MAX)?;
    Ok(())
}

fn check_finite2(name: &'static str, z: DVec2) -> Result<(), BrdfError> {
    if z.is_finite() {
        Ok(())
    } else {
        Err(BrdfError::NotFinite(name))
    }
}
