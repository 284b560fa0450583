//! Fresnel reflectance (§5.1, §5.2).
//!
//! Schlick's approximation (Eq. 14), the slope variance in the view direction (Eq. 25), the
//! paper's fit of the effective Fresnel reflectance of a rough surface (Eq. 26), and the
//! integral it fits (Eq. 24), computed by deterministic quadrature as the fit's reference.
//!
//! Directions are in the surface's tangent frame (x along the wind, y across it, z along the
//! average normal), as in [`crate::ross`].

use glam::{DVec2, DVec3};

use crate::error::check_direction;
use crate::error::{BrdfError, check};
use crate::quadrature::{composite_nodes, gauss_legendre, standard_normal};

/// Reflectance of water at normal incidence, `R` of Eq. 14 (for a refractive index of 1.33,
/// `((1.33 - 1)/(1.33 + 1))² ≈ 0.02`).
pub const WATER_R: f64 = 0.02;

/// Schlick's Fresnel factor, Eq. 14: `F = R + (1 - R)(1 - cos)⁵`.
///
/// `cos` is the cosine between the direction and the facet normal (`v·h`), clamped to
/// `[0, 1]` (a back-facing cosine gives 1, total reflection, never more); `r` is the
/// reflectance at normal incidence, in `[0, 1]`. `schlick(1, r) = r`, `schlick(0, r) = 1`.
#[inline]
pub fn schlick(cos: f64, r: f64) -> f64 {
    // libm::pow(x, 5.0) rather than x*x*x*x*x: Eq. 26 with σ_v = 0 calls pow with the exponent
    // 5.0 exactly, and is then equal to this bit for bit.
    r + (1.0 - r) * libm::pow(1.0 - cos.clamp(0.0, 1.0), 5.0)
}

/// The slope variance in the view direction, Eq. 25:
/// `σ_v² = σ_x² cos² φ_v + σ_y² sin² φ_v`, `φ_v` the view azimuth from the wind direction x.
///
/// The transcription prints `σ_r² cos² φ_v + σ_v² sin² φ_v`, a misprint: the variances along
/// x and y are meant, as in Fig. 9's algorithm.
#[inline]
pub fn sigma_v2(phi_v: f64, sigma_x2: f64, sigma_y2: f64) -> f64 {
    let (s, c) = libm::sincos(phi_v);
    sigma_x2 * c * c + sigma_y2 * s * s
}

/// The paper's fit of the effective Fresnel reflectance, Eq. 26:
///
/// `F̄ ≈ R + (1 - R) (1 - cos θ_v)^(5 exp(-2.69 σ_v)) / (1 + 22.7 σ_v^1.5)`
///
/// with `σ_v = √σ_v²` of Eq. 25 (the standard deviation, as in Fig. 9). Equal to
/// [`schlick`]`(cos θ_v, R)` bit for bit at `σ_v = 0`. Fitted for `σ_x, σ_y < 0.5`; the tests
/// bound its distance to [`effective_fresnel_integral`] there.
///
/// `cos_theta_v` in `[0, 1]`, `sigma_v ≥ 0` (finite), `r` in `[0, 1]`.
pub fn effective_fresnel_fit(cos_theta_v: f64, sigma_v: f64, r: f64) -> Result<f64, BrdfError> {
    check("cos_theta_v", cos_theta_v, 0.0, 1.0)?;
    check("sigma_v", sigma_v, 0.0, f64::MAX)?;
    check("r", r, 0.0, 1.0)?;
    Ok(effective_fresnel_fit_unchecked(cos_theta_v, sigma_v, r))
}

/// [`effective_fresnel_fit`] without validation.
#[inline]
pub fn effective_fresnel_fit_unchecked(cos_theta_v: f64, sigma_v: f64, r: f64) -> f64 {
    let exponent = 5.0 * libm::exp(-2.69 * sigma_v);
    let damping = 1.0 + 22.7 * sigma_v * libm::sqrt(sigma_v);
    r + (1.0 - r) * libm::pow(1.0 - cos_theta_v, exponent) / damping
}

/// The effective Fresnel reflectance of Eq. 24, by numerical integration:
///
/// `F̄(v) ≈ R + (1 - R) ∬ q^e_vn(ζ, v) (1 - v·h)⁵ d²ζ`
///
/// where `h = f(ζ)`, the facet normal of Eq. 6: the light that the facet `ζ` reflects towards
/// `v` comes from the mirror direction `r(v, ζ) = 2 (v·f) f - v` of Eq. 18, and the half vector
/// between `v` and `r` is `(v + r)/|v + r| = f` (as `v + r = 2 (v·f) f`, with `v·f > 0` on every
/// facet that `q^e_vn` counts). This is the paper's approximation of Eq. 23 (`q_vn H ≈ q^e_vn`,
/// so the light's shadowing and the reflected rays that go below the horizon are ignored).
///
/// Quadrature (deterministic, no allocation): in whitened slopes `ζ = (σ_x u, σ_y w)` the
/// density `p(ζ) d²ζ` is the standard normal `φ(u) φ(w) du dw`, and the projected facet area
/// `max(v·f, 0)/f_z = max(v_z - ζ·v_xy, 0)` becomes `max(v_z - c s, 0)` along the unit axis `s`
/// of `(σ_x v_x, σ_y v_y)` (`c` its length, `t` the axis across it). The integrand therefore
/// has its only kink on the line `s = v_z / c`; the integral runs over `s` in
/// `[-8, min(8, v_z/c)]` and `t` in `[-8, 8]` (the standard normal's mass beyond 8 is 1e-15),
/// each with composite 8-point Gauss–Legendre on panels of width at most 1, and the result is
/// divided by the quadrature's own total mass of `q^e_vn` (Eq. 11 makes that mass 1, so the
/// normaliser `1 + Λ(a_v)` is not needed and the result is a weighted mean of values in
/// `[0, 1]`). Measured accuracy (tests/fresnel.rs, against an independent slope-space
/// quadrature of [`crate::ross::visible_slope_pdf`]): better than 1e-9 for `σ_x, σ_y ≤ 1`
/// at every view angle, grazing included.
///
/// `v` a unit vector with `v.z ≥ 0`; `sigma_x2`, `sigma_y2` in `[0, f64::MAX]` (zero gives
/// Schlick's `F(v_z)`); `r` in `[0, 1]`.
pub fn effective_fresnel_integral(
    v: DVec3,
    sigma_x2: f64,
    sigma_y2: f64,
    r: f64,
) -> Result<f64, BrdfError> {
    let v = check_direction("v", v)?;
    check("v.z", v.z, 0.0, 1.0)?;
    check("sigma_x2", sigma_x2, 0.0, f64::MAX)?;
    check("sigma_y2", sigma_y2, 0.0, f64::MAX)?;
    check("r", r, 0.0, 1.0)?;
    Ok(r + (1.0 - r) * visible_schlick_mean(v, sigma_x2, sigma_y2))
}

/// Half-width of the integration domain in standard deviations.
const HALF_WIDTH: f64 = 8.0;
/// Gauss–Legendre nodes per panel.
const NODES: usize = 8;
/// Largest panel width, in standard deviations.
const PANEL_WIDTH: f64 = 1.0;
/// Largest number of nodes along one axis: `2 HALF_WIDTH / PANEL_WIDTH` panels.
const MAX_POINTS: usize = 16 * NODES;

/// `∬ q^e_vn(ζ, v) (1 - v·f(ζ))⁵ d²ζ`, see [`effective_fresnel_integral`].
fn visible_schlick_mean(v: DVec3, sigma_x2: f64, sigma_y2: f64) -> f64 {
    let (sx, sy) = (libm::sqrt(sigma_x2), libm::sqrt(sigma_y2));
    let axis = DVec2::new(sx * v.x, sy * v.y);
    let c = libm::hypot(axis.x, axis.y);
    let (e, s_max) = if c > 0.0 {
        (axis / c, (v.z / c).min(HALF_WIDTH))
    } else {
        // No slope variance along the view's azimuth (or normal incidence): no kink.
        (DVec2::X, HALF_WIDTH)
    };
    let e_perp = DVec2::new(-e.y, e.x);

    let gl = gauss_legendre::<NODES>();
    let mut s_nodes = [(0.0, 0.0); MAX_POINTS];
    let ns = composite_nodes(&gl, -HALF_WIDTH, s_max, PANEL_WIDTH, &mut s_nodes);
    let mut t_nodes = [(0.0, 0.0); MAX_POINTS];
    let nt = composite_nodes(&gl, -HALF_WIDTH, HALF_WIDTH, PANEL_WIDTH, &mut t_nodes);

    let mut mass = 0.0;
    let mut sum = 0.0;
    for &(s, ws) in &s_nodes[..ns] {
        // Projected area v_z - c s (≥ 0 up to the kink) times the standard normal in s.
        let area = (v.z - c * s).max(0.0);
        let ws = ws * standard_normal(s) * area;
        let mut row = 0.0;
        let mut row_mass = 0.0;
        for &(t, wt) in &t_nodes[..nt] {
            let w = wt * standard_normal(t);
            let u = s * e.x + t * e_perp.x;
            let y = s * e.y + t * e_perp.y;
            let zeta = DVec2::new(sx * u, sy * y);
            // v·f = (v_z - ζ·v_xy) f_z, f_z = 1/√(1 + |ζ|²) (Eq. 6).
            let v_dot_f = area / libm::sqrt(1.0 + zeta.dot(zeta));
            let x = 1.0 - v_dot_f;
            row += w * (x * x) * (x * x) * x;
            row_mass += w;
        }
        sum += ws * row;
        mass += ws * row_mass;
    }
    if mass > 0.0 {
        sum / mass
    } else {
        // Grazing view (v_z = 0) over a surface with no slope variance along the view: the
        // Dirac limit, Schlick's (1 - v_z)⁵ = 1.
        1.0
    }
}
