//! Tests of the filtered surface (Eq. 2–4) and its footprints (`ocean_brdf::surface`).

use glam::{DVec2, DVec3};
use ocean_brdf::surface::{pixel_footprint, pixel_ray, sea_plane_hit};
use ocean_brdf::{Filter, FilteredSurface, Spectrum, SpectrumParams};
use ocean_core::{Camera, DepthConvention, Far, Projection};

fn surface() -> FilteredSurface {
    FilteredSurface::new(
        &Spectrum::new(SpectrumParams::default()).unwrap(),
        Filter::PAPER,
    )
    .unwrap()
}

#[test]
fn waves_are_sorted_longest_first_and_resolved_waves_are_a_prefix() {
    let s = surface();
    assert!(s.wavelengths().windows(2).all(|w| w[0] >= w[1]));
    // λ/L ≥ N_max = 2.5 gives weight 1, λ/L ≤ N_min = 1 weight 0.
    for size in [1e-3, 0.01, 0.1, 1.0, 10.0, 100.0] {
        let n = s.resolved_count(size);
        let expected = s.wavelengths().iter().filter(|&&l| l > size).count();
        assert_eq!(n, expected, "{size}");
    }
}

/// Footprints far below the shortest wave resolve every wave: Eq. 2–3 are the plain trochoid
/// sum. Footprints beyond the longest wave resolve none: the sea at rest, flat.
#[test]
fn extreme_footprints_give_the_full_sum_or_the_rest_plane() {
    let s = surface();
    let rest = DVec2::new(13.0, -7.5);
    let t = 4.25;
    let full = s.wave_set().sample_f64(rest, t).unwrap();
    let p = s.position(rest, t, 1e-4).unwrap();
    let expected = DVec3::new(rest.x, 0.0, rest.y) + full.displacement;
    assert!((p - expected).length() < 1e-12);
    let n = s.normal(rest, t, 1e-4).unwrap();
    assert!((n - full.normal).length() < 1e-12);
    assert_eq!(
        s.position(rest, t, 1e3).unwrap(),
        DVec3::new(rest.x, 0.0, rest.y)
    );
    assert_eq!(s.normal(rest, t, 1e3).unwrap(), DVec3::Y);
    // Eq. 4: what the normals lose, the variance gains.
    let total = s.variance_table().total();
    assert_eq!(s.variance(1e3), total);
    let v = s.variance(1e-4);
    assert!(v.x.abs() < 1e-15 && v.y.abs() < 1e-15, "{v:?}");
    assert!(s.position(rest, t, 0.0).is_err());
    assert!(s.normal(rest, f64::NAN, 1.0).is_err());
}

#[test]
fn sea_plane_hits_and_the_distance_cap() {
    let eye = DVec3::new(1.0, 4.0, 2.0);
    let d = DVec3::new(0.0, -1.0, -1.0).normalize();
    let h = sea_plane_hit(eye, d, 1e4).unwrap();
    assert!((h - DVec2::new(1.0, -2.0)).length() < 1e-12);
    // Up, along the horizon, or beyond the cap: stopped at the cap.
    for dir in [
        DVec3::new(0.0, 0.1, -1.0),
        DVec3::NEG_Z,
        DVec3::new(0.0, -1e-5, -1.0),
    ] {
        let dir = dir.normalize();
        let h = sea_plane_hit(eye, dir, 100.0).unwrap();
        let e = DVec2::new(eye.x, eye.z) + DVec2::new(dir.x, dir.z) * 100.0;
        assert!((h - e).length() < 1e-9, "{dir}");
    }
    assert!(sea_plane_hit(DVec3::new(0.0, -1.0, 0.0), d, 1e4).is_none());
    assert!(sea_plane_hit(eye, DVec3::NAN, 1e4).is_none());
}

/// Analytic case: a camera looking straight down from height h sees a pixel of size
/// `2 h tan(fov/2) / height` on the sea, in both directions.
#[test]
fn pixel_footprint_looking_down_is_the_pinhole_size() {
    let h = 10.0;
    let fov = 60f64.to_radians();
    let (w, ht) = (320.0, 240.0);
    for depth in [
        DepthConvention::ZERO_TO_ONE,
        DepthConvention::NEG_ONE_TO_ONE,
    ] {
        for far in [Far::Finite(1000.0), Far::Infinite] {
            let cam = Camera::look_at(
                DVec3::new(0.0, h, 0.0),
                DVec3::ZERO,
                DVec3::NEG_Z,
                Projection::Perspective {
                    fov_y: fov,
                    aspect: w / ht,
                    near: 0.1,
                    far,
                },
                depth,
            )
            .unwrap();
            let centre = DVec2::new(w / 2.0, ht / 2.0);
            let (_, dir) = pixel_ray(&cam, w, ht, centre).unwrap();
            assert!((dir - DVec3::NEG_Y).length() < 1e-9);
            let l = pixel_footprint(&cam, w, ht, centre, 1e5).unwrap();
            let expected = 2.0 * h * (fov / 2.0).tan() / ht;
            assert!((l - expected).abs() < 1e-9 * expected, "{l} {expected}");
        }
    }
}

/// Towards the horizon the footprint grows, and it is bounded by the distance cap.
#[test]
fn pixel_footprint_grows_towards_the_horizon() {
    let cam = Camera::look_at(
        DVec3::new(0.0, 4.0, 0.0),
        DVec3::new(0.0, 4.0, -100.0),
        DVec3::Y,
        Projection::Perspective {
            fov_y: 40f64.to_radians(),
            aspect: 2.0,
            near: 0.1,
            far: Far::Infinite,
        },
        DepthConvention::ZERO_TO_ONE,
    )
    .unwrap();
    let (w, h) = (256.0, 128.0);
    let mut last = 0.0;
    // From the bottom row up to the row just below the horizon (the middle of the screen).
    for row in (65..128).rev() {
        let l = pixel_footprint(&cam, w, h, DVec2::new(128.5, row as f64 + 0.5), 5e4).unwrap();
        assert!(l.is_finite() && l > last, "{row}: {l} after {last}");
        last = l;
    }
    // Above the horizon every hit is at the cap: a footprint of at most 2 × cap × pixel angle.
    let l = pixel_footprint(&cam, w, h, DVec2::new(128.5, 20.5), 5e4).unwrap();
    assert!(l < 2.0 * 5e4 * (40f64.to_radians() / 128.0), "{l}");
}

/// §6, local waves: an open sea with local trains on it lights the same as one surface made of
/// both wave sets (normals by adding Eq. 3's sums, variances by adding Eq. 4), and a local
/// scale of 0 leaves the open sea alone.
#[test]
fn local_waves_add_their_normals_and_variances() {
    let open = surface();
    let local_descs = [
        ocean_core::WaveDesc {
            amplitude: 0.05,
            wavelength: 2.0,
            direction: DVec2::new(0.6, 0.8),
            phase: 0.4,
            depth: ocean_core::Depth::Deep,
        },
        ocean_core::WaveDesc {
            amplitude: 0.01,
            wavelength: 0.3,
            direction: DVec2::new(-0.2, 1.0),
            phase: 2.0,
            depth: ocean_core::Depth::Deep,
        },
    ];
    let local = FilteredSurface::from_waves(&local_descs, open.wind(), Filter::PAPER).unwrap();
    let mut all: Vec<_> = Spectrum::new(SpectrumParams::default())
        .unwrap()
        .waves()
        .to_vec();
    all.extend_from_slice(&local_descs);
    let both = FilteredSurface::from_waves(&all, open.wind(), Filter::PAPER).unwrap();
    let rest = DVec2::new(3.0, 8.0);
    let t = 2.5;
    for pixel in [0.01, 0.2, 1.0, 5.0] {
        let mut sums = ocean_core::PointSums::REST;
        open.add_normal_sums(rest, t, pixel, 1.0, &mut sums)
            .unwrap();
        local
            .add_normal_sums(rest, t, pixel, 1.0, &mut sums)
            .unwrap();
        let n = both.normal(rest, t, pixel).unwrap();
        assert!((sums.normal() - n).length() < 1e-12, "{pixel}");
        let v = open.variance(pixel).plus(local.local_variance(pixel, 1.0));
        let w = both.variance(pixel);
        assert!(
            (v.x - w.x).abs() < 1e-12 && (v.y - w.y).abs() < 1e-12,
            "{pixel}"
        );
        // Scale 0: the open sea alone.
        let mut only = ocean_core::PointSums::REST;
        open.add_normal_sums(rest, t, pixel, 1.0, &mut only)
            .unwrap();
        local
            .add_normal_sums(rest, t, pixel, 0.0, &mut only)
            .unwrap();
        assert_eq!(only.normal(), open.normal(rest, t, pixel).unwrap());
        assert_eq!(local.local_variance(pixel, 0.0), Default::default());
    }
    let mut sums = ocean_core::PointSums::REST;
    assert!(local.add_normal_sums(rest, t, 1.0, 1.5, &mut sums).is_err());
}

/// `FilteredSurface::pixel` (the fragment stage's twin) is its parts: Eq. 3 and 4 for the pixel
/// footprint, the geometry normal for the cell (Eq. 2's waves), the normal-only variance of
/// both; `sea::pixel_color` lights its masking-aware normal with Eq. 4's variance. Where the
/// cell resolves every wave the pixel does, nothing is unmasked and the normal is kept; with a
/// cell that resolves none the normal-only slopes are every resolved wave's.
#[test]
fn a_pixel_is_its_normal_geometry_and_variances() {
    use ocean_brdf::sea::{pixel_color, sea_color_unchecked, visible_normal};
    use ocean_brdf::{Lighting, SeaParams, SkyParams};
    let s = surface();
    let rest = DVec2::new(-3.0, 11.0);
    let t = 7.5;
    let (pixel, cell) = (0.05, 0.4);
    let px = s.pixel(rest, t, pixel, cell).unwrap();
    assert_eq!(px.normal, s.normal(rest, t, pixel).unwrap());
    assert_eq!(px.geometry_normal, s.normal(rest, t, cell).unwrap());
    assert_eq!(px.variance, s.variance(pixel));
    assert_eq!(px.normal_only, s.normal_only_variance(pixel, cell));
    assert!(px.normal_only.x > 0.0 && px.normal_only.y > 0.0);
    let lighting = Lighting::new(SkyParams::default(), SeaParams::default()).unwrap();
    let map = lighting.sky_map(64).unwrap();
    let v = DVec3::new(0.0, 0.05, 1.0).normalize();
    let n = visible_normal(
        v,
        px.normal,
        px.geometry_normal,
        s.wind(),
        px.normal_only,
        px.variance,
    );
    assert_eq!(px.visible_normal(v, s.wind()), n);
    assert!(n.angle_between(px.normal) > 1e-3, "a grazing view moves it");
    assert_eq!(
        pixel_color(&lighting, &map, v, &px, s.wind()),
        sea_color_unchecked(&lighting, &map, v, n, s.wind(), px.variance)
    );
    // The same footprint for both: no normal-only slopes, the normal as it is.
    let same = s.pixel(rest, t, pixel, pixel).unwrap();
    assert_eq!(same.normal_only, ocean_brdf::SlopeVariance::default());
    assert_eq!(same.visible_normal(v, s.wind()), same.normal);
    // No geometry at all: every resolved wave's variance.
    let none = s.pixel(rest, t, pixel, 1e6).unwrap();
    assert_eq!(none.geometry_normal, DVec3::Y);
    let resolved = s.variance_table().total();
    let left = s.variance(pixel);
    assert!(none.normal_only.x > 0.0 && none.normal_only.x < resolved.x - left.x + 1e-12);
    assert!(s.pixel(rest, f64::NAN, pixel, cell).is_err());
}
