//! Tests of Algorithm 5.1 (`ocean_brdf::sea`): analytic cases, energy, the finite-difference
//! footprint, extreme inputs and a snapshot of the three terms.

use glam::{DVec2, DVec3};
use ocean_brdf::fresnel::{WATER_R, schlick};
use ocean_brdf::sea::{
    SLOPE_EPSILON, reflected_u, sea_color, sea_color_unchecked, sky_footprint, tangent_frame,
};
use ocean_brdf::sky::{CieSky, Sky, SkyParams};
use ocean_brdf::{BrdfError, Lighting, SeaParams, SkyMap, SlopeVariance};

const UNIFORM: CieSky = CieSky {
    a: 0.0,
    b: -1.0,
    c: 0.0,
    d: -1.0,
    e: 0.0,
};

fn default_lighting() -> (Lighting, SkyMap) {
    let lighting = Lighting::new(SkyParams::default(), SeaParams::default()).unwrap();
    let map = lighting.sky_map(256).unwrap();
    (lighting, map)
}

/// A world-space view direction at `elevation_deg` above the horizon, looking from azimuth
/// `azimuth_deg` (0: the viewer is towards +z of the point).
fn view(elevation_deg: f64, azimuth_deg: f64) -> DVec3 {
    let (se, ce) = elevation_deg.to_radians().sin_cos();
    let (sa, ca) = azimuth_deg.to_radians().sin_cos();
    DVec3::new(ce * sa, se, ce * ca)
}

/// Analytic case: a flat sea (σ = 0) under a uniform sky of radiance L reflects `F(cos θ_v) L`
/// (Schlick's F, Eq. 26 at σ_v = 0) and transmits `L_sea (1 − F)` with
/// `L_sea = albedo (E_sun sin α + π L)/π`.
#[test]
fn flat_sea_under_a_uniform_sky_is_schlick() {
    let l = DVec3::new(0.125, 0.25, 0.5);
    let sky = SkyParams {
        zenith_radiance: l,
        cie: UNIFORM,
        ..SkyParams::default()
    };
    let sea = SeaParams::default();
    let lighting = Lighting::new(sky, sea).unwrap();
    let map = lighting.sky_map(128).unwrap();
    let sun_h = sky.sun_irradiance * sky.sun_direction.y;
    let l_sea = sea.albedo * (sun_h + l * std::f64::consts::PI) / std::f64::consts::PI;
    assert!((lighting.sea_radiance() - l_sea).abs().max_element() < 1e-12);
    for elevation in [15.0, 30.0, 60.0, 89.0] {
        // Away from the Sun's reflection (the Sun is at azimuth 180°, so its glint is at 0°).
        let v = view(elevation, 90.0);
        let out = sea_color(
            &lighting,
            &map,
            v,
            DVec3::Y,
            DVec2::X,
            SlopeVariance::default(),
        )
        .unwrap();
        let f = schlick(v.y, WATER_R);
        assert!((out.sky - l * f).abs().max_element() < 1e-12, "{elevation}");
        assert!((out.sea - l_sea * (1.0 - f)).abs().max_element() < 1e-12);
        assert!(out.sun.max_element() < 1e-30, "{}", out.sun);
    }
}

/// Energy: the Sun's light reflected by a slightly rough flat sea, integrated over every view
/// direction with the projected solid angle, is the Fresnel-weighted solar irradiance
/// `F(cos θ_l) E_sun cos θ_l` (Eq. 13–15 with negligible shadowing: σ² = 10⁻³ and the Sun 25°
/// high give a ≈ 10 in Eq. 9, so Λ < 10⁻⁴⁰).
#[test]
fn reflected_sun_energy_is_fresnel_times_irradiance() {
    let (lighting, map) = default_lighting();
    let sky = lighting.sky();
    let l = sky.sun_direction();
    let mirror = DVec3::new(-l.x, l.y, -l.z);
    let theta_m = mirror.y.acos();
    let phi_m = mirror.x.atan2(mirror.z);
    for variance in [
        SlopeVariance { x: 1e-3, y: 1e-3 },
        SlopeVariance { x: 2e-3, y: 5e-4 },
    ] {
        // Midpoint rule over ±0.4 rad (more than 6 lobe widths) around the mirror direction.
        let n = 500;
        let half = 0.4;
        let mut e = DVec3::ZERO;
        for i in 0..n {
            let theta = theta_m - half + (i as f64 + 0.5) / n as f64 * 2.0 * half;
            for j in 0..n {
                let phi = phi_m - half + (j as f64 + 0.5) / n as f64 * 2.0 * half;
                let v = DVec3::new(
                    theta.sin() * phi.sin(),
                    theta.cos(),
                    theta.sin() * phi.cos(),
                );
                let out = sea_color_unchecked(&lighting, &map, v, DVec3::Y, DVec2::X, variance);
                e += out.sun * (v.y * theta.sin());
            }
        }
        e *= (2.0 * half / n as f64).powi(2);
        let expected = sky.sun_irradiance_horizontal() * schlick(l.y, WATER_R);
        let rel = ((e - expected) / expected).abs().max_element();
        assert!(rel < 0.01, "{variance:?}: {e} against {expected}, {rel}");
    }
}

/// §3.2: a back-facing normal gives the same light as its reflection about the plane normal
/// to v.
#[test]
fn back_facing_normals_are_reflected() {
    let (lighting, map) = default_lighting();
    let v = view(5.0, 30.0);
    let n = DVec3::new(-0.3, 0.2, -0.93).normalize();
    assert!(n.dot(v) < 0.0);
    let reflected = n - v * (2.0 * n.dot(v));
    let var = SlopeVariance { x: 0.01, y: 0.005 };
    let a = sea_color(&lighting, &map, v, n, DVec2::Y, var).unwrap();
    let b = sea_color(&lighting, &map, v, reflected, DVec2::Y, var).unwrap();
    assert!((a.total() - b.total()).abs().max_element() < 1e-14);
}

/// Fig. 9: "using finite differences is ... precise enough with ε = 10⁻³". Against central
/// differences with a 10⁻⁶ step, the footprint's axes differ by at most 2e-3 of their length
/// (measured: 1.1e-3) for σ = 0.1 over views from 1° to 90° and normals tilted up to 30°.
#[test]
fn finite_difference_footprint_is_precise_enough() {
    let var = SlopeVariance { x: 0.01, y: 0.01 };
    let mut worst: f64 = 0.0;
    for elevation in [1.0, 3.0, 10.0, 30.0, 60.0, 90.0] {
        for azimuth in [0.0, 45.0, 120.0] {
            for tilt in [0.0f64, 15.0, 30.0] {
                let v = view(elevation, azimuth);
                let (st, ct) = tilt.to_radians().sin_cos();
                let n = DVec3::new(st, ct, 0.0);
                if n.dot(v) <= 0.05 {
                    continue;
                }
                let (tx, ty) = tangent_frame(n, DVec2::new(1.0, 0.5));
                let fp = sky_footprint(v, n, tx, ty, var);
                let h = 1e-6;
                let central = |d: DVec2| {
                    (reflected_u(v, n, tx, ty, d * h) - reflected_u(v, n, tx, ty, -d * h))
                        / (2.0 * h)
                };
                let ex = central(DVec2::X) * (2.0 * 0.1);
                let ey = central(DVec2::Y) * (2.0 * 0.1);
                worst = worst.max((fp.du_x - ex).length() / ex.length());
                worst = worst.max((fp.du_y - ey).length() / ey.length());
            }
        }
    }
    println!("ε = {SLOPE_EPSILON}: worst relative error of the footprint axes {worst:.2e}");
    assert!(worst < 2e-3, "{worst}");
}

/// Extreme but valid inputs never give NaN or negative light: grazing and below-horizon views,
/// horizontal normals, zero and huge variances.
#[test]
fn extreme_inputs_give_finite_non_negative_light() {
    let (lighting, map) = default_lighting();
    let mut n_checked = 0;
    for elevation in [-30.0, -1.0, 0.0, 1e-6, 0.5, 45.0, 90.0] {
        for azimuth in [0.0, 90.0, 180.0] {
            for normal in [
                DVec3::Y,
                DVec3::X,
                DVec3::new(0.0, 1e-9, 1.0).normalize(),
                DVec3::new(0.2, 0.9, -0.3).normalize(),
                -DVec3::Y,
            ] {
                for s in [0.0, 1e-12, 0.01, 1.0, 1e6, f64::MAX] {
                    let v = view(elevation, azimuth);
                    let var = SlopeVariance { x: s, y: s * 0.5 };
                    let out = sea_color(&lighting, &map, v, normal, DVec2::X, var).unwrap();
                    for c in [out.sun, out.sky, out.sea] {
                        assert!(
                            c.is_finite() && c.min_element() >= 0.0,
                            "{v} {normal} {s}: {out:?}"
                        );
                    }
                    n_checked += 1;
                }
            }
        }
    }
    assert_eq!(n_checked, 7 * 3 * 5 * 6);
}

#[test]
fn bad_inputs_are_refused() {
    let (lighting, map) = default_lighting();
    let ok = SlopeVariance { x: 0.01, y: 0.01 };
    let call = |v: DVec3, n: DVec3, w: DVec2, s: SlopeVariance| {
        sea_color(&lighting, &map, v, n, w, s).unwrap_err()
    };
    assert_eq!(
        call(DVec3::NAN, DVec3::Y, DVec2::X, ok),
        BrdfError::NotFinite("v")
    );
    assert_eq!(
        call(DVec3::Y * 2.0, DVec3::Y, DVec2::X, ok),
        BrdfError::NotUnit("v")
    );
    assert_eq!(
        call(DVec3::Y, DVec3::ZERO, DVec2::X, ok),
        BrdfError::NotUnit("n")
    );
    assert_eq!(
        call(DVec3::Y, DVec3::Y, DVec2::ZERO, ok),
        BrdfError::NotUnit("wind")
    );
    assert!(matches!(
        call(
            DVec3::Y,
            DVec3::Y,
            DVec2::X,
            SlopeVariance { x: -1.0, y: 0.0 }
        ),
        BrdfError::OutOfRange { .. }
    ));
    assert!(matches!(
        Lighting::new(
            SkyParams::default(),
            SeaParams {
                albedo: DVec3::new(0.1, 2.0, 0.1),
                ..SeaParams::default()
            }
        )
        .unwrap_err(),
        BrdfError::OutOfRange { .. }
    ));
}

/// The three terms for a table of views, normals and variances on the default environment,
/// rounded to 6 significant digits (the table the GPU's parity test also evaluates).
#[test]
fn sea_color_table_snapshot() {
    let (lighting, map) = default_lighting();
    let mut out = String::new();
    let sky = Sky::new(SkyParams::default()).unwrap();
    out += &format!(
        "L_sun {:.6e} Ω {:.6e} E_sky {:.6e} L_sea {:.6e} below {:.6e}\n",
        sky.sun_radiance().x,
        sky.sun_solid_angle(),
        sky.sky_irradiance().x,
        lighting.sea_radiance().z,
        lighting.below_horizon_radiance().z
    );
    for (elevation, azimuth) in [(2.0, 0.0), (10.0, 0.0), (25.0, 0.0), (40.0, 90.0)] {
        for n in [DVec3::Y, DVec3::new(0.1, 0.99, -0.1).normalize()] {
            for (sx, sy) in [(0.0, 0.0), (0.004, 0.002), (0.04, 0.02)] {
                let v = view(elevation, azimuth);
                let r = sea_color(
                    &lighting,
                    &map,
                    v,
                    n,
                    DVec2::new(0.0, -1.0),
                    SlopeVariance { x: sx, y: sy },
                )
                .unwrap();
                let fmt = |c: DVec3| format!("{:.5e} {:.5e} {:.5e}", c.x, c.y, c.z);
                out += &format!(
                    "v({elevation},{azimuth}) n.y={:.3} σ²=({sx},{sy}): sun {} | sky {} | sea {}\n",
                    n.y,
                    fmt(r.sun),
                    fmt(r.sky),
                    fmt(r.sea)
                );
            }
        }
    }
    insta::assert_snapshot!(out);
}

/// `visible_normal` gives the slopes that only the normals resolve the first two moments of
/// their visible density (Eq. 10 for the sum of those slopes and the BRDF's), computed here by
/// brute force: a 2D midpoint rule over (ζ_n, ζ_r) along the view's azimuth of
/// `p_n p_r (v_z − (ζ_n + ζ_r) v_x)⁺`; and leaves the normal alone where nothing is unmasked.
#[test]
fn visible_normal_moves_the_normal_only_slopes_to_their_visible_moments() {
    use ocean_brdf::ross::facet_normal;
    use ocean_brdf::sea::visible_normal;
    let wind = DVec2::X;
    let n_geo = DVec3::Y;
    let (tx, ty) = tangent_frame(n_geo, wind);
    let world = |f: DVec3| tx * f.x + ty * f.y + n_geo * f.z;
    let (sn2, sr2) = (0.012, 0.008);
    let (normal_only, brdf) = (
        SlopeVariance {
            x: sn2,
            y: 0.5 * sn2,
        },
        SlopeVariance {
            x: sr2,
            y: 0.5 * sr2,
        },
    );
    for elevation in [3.0f64, 10.0, 30.0] {
        // The viewer along the wind (t_x), `elevation` above the geometry's plane.
        let e = elevation.to_radians();
        let v = world(DVec3::new(libm::cos(e), 0.0, libm::sin(e)));
        let (vx, vz) = (libm::cos(e), libm::sin(e));
        // Brute force: visible mean and variance of ζ_n along x.
        let (sn, sr) = (libm::sqrt(sn2), libm::sqrt(sr2));
        let (mut m0, mut m1, mut m2) = (0.0, 0.0, 0.0);
        let k = 1200;
        for i in 0..k {
            let a = -8.0 + 16.0 * (i as f64 + 0.5) / k as f64;
            for j in 0..k {
                let b = -8.0 + 16.0 * (j as f64 + 0.5) / k as f64;
                let w = libm::exp(-0.5 * (a * a + b * b)) * (vz - (sn * a + sr * b) * vx).max(0.0);
                m0 += w;
                m1 += w * sn * a;
                m2 += w * sn * a * sn * a;
            }
        }
        let (mean, var) = (m1 / m0, m2 / m0 - (m1 / m0) * (m1 / m0));
        // The map over Gauss–Hermite-like nodes of ζ_n along x: its weighted moments.
        let (mut w0, mut w1, mut w2) = (0.0, 0.0, 0.0);
        for i in 0..400 {
            let a = -8.0 + 16.0 * (i as f64 + 0.5) / 400.0;
            let w = libm::exp(-0.5 * a * a);
            let n = world(facet_normal(DVec2::new(sn * a, 0.0)));
            let m = visible_normal(v, n, n_geo, wind, normal_only, brdf);
            let zeta = -m.dot(tx) / m.dot(n_geo);
            assert!(m.dot(ty).abs() < 1e-12, "no slope appears across the view");
            w0 += w;
            w1 += w * zeta;
            w2 += w * zeta * zeta;
        }
        let (got_mean, got_var) = (w1 / w0, w2 / w0 - (w1 / w0) * (w1 / w0));
        assert!(
            (got_mean - mean).abs() < 1e-4 * sn && (got_var / var - 1.0).abs() < 1e-3,
            "elevation {elevation}: mean {got_mean} vs {mean}, variance {got_var} vs {var}"
        );
        // Facets turn towards the viewer (−ζ·v_xy > 0), the more so the more grazing the view.
        assert!(mean < 0.0, "{mean}");
    }
    // Nothing to unmask: the normal is returned as it is.
    let n = world(facet_normal(DVec2::new(0.1, -0.05)));
    let v = world(DVec3::new(0.9, 0.0, libm::sqrt(1.0 - 0.81)));
    assert_eq!(
        visible_normal(v, n, n_geo, wind, SlopeVariance::default(), brdf),
        n
    );
    // A normal view has no masking either.
    let m = visible_normal(n_geo, n, n_geo, wind, normal_only, brdf);
    assert!((m - n).length() < 1e-12);
}
