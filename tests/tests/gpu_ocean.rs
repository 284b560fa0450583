//! The GPU ocean renderer (`ocean_gpu::OceanRenderer`, Bruneton et al. 2010) against its CPU
//! twins in `ocean_brdf`: the sea colour of Algorithm 5.1, the projected grid's geometry (rays,
//! sea-plane hits, footprints, Eq. 2), the per-pixel normal and slope variance (Eq. 3 and 4),
//! the waves each sum visits, a stored reference image, and the error paths.
//!
//! The probes (`probe_sea_color`, `probe_surface`) run the render shaders' own WGSL functions on
//! lists of inputs, so what is compared here is what the vertex and fragment stages compute.
//!
//! Run with `OCEAN_REQUIRE_GPU=1` to turn a missing adapter into a failure (CI runs these on
//! lavapipe with `WGPU_BACKEND=vulkan` and on llvmpipe with `WGPU_BACKEND=gl`). The reference
//! image is rewritten with `OCEAN_BLESS=1`.

use std::path::PathBuf;

use glam::{DVec2, DVec3};
use ocean_brdf::sea::{sea_color_unchecked, visible_normal};
use ocean_brdf::surface::{pixel_footprint, pixel_ray, sea_plane_hit};
use ocean_brdf::{
    Filter, FilteredSurface, Lighting, SeaLight, SeaParams, SkyParams, SlopeVariance, Spectrum,
    SpectrumParams,
};
use ocean_core::{Camera, DepthConvention, Far, Projection};
use ocean_gpu::{GpuContext, GpuError, OceanOptions, OceanRenderer, SeaColorInput, wgpu};
use ocean_tests::{gpu_context_or_skip, texture_2d};

/// The default sea: 60 waves from 2 cm to 30 m under a 10 m/s wind, the paper's filter.
fn surface() -> FilteredSurface {
    let spectrum = Spectrum::new(SpectrumParams::default()).expect("default spectrum");
    FilteredSurface::new(&spectrum, Filter::PAPER).expect("default surface")
}

/// The default clear sky (Sun 25° up towards −z) over deep blue water.
fn lighting() -> Lighting {
    Lighting::new(SkyParams::default(), SeaParams::default()).expect("default lighting")
}

/// A camera at `eye` looking along `dir`, 60° vertical field of view, for a `width × height`
/// viewport.
fn camera(eye: DVec3, dir: DVec3, width: u32, height: u32, depth: DepthConvention) -> Camera {
    Camera::look_at(
        eye,
        eye + dir,
        DVec3::Y,
        Projection::Perspective {
            fov_y: 60f64.to_radians(),
            aspect: f64::from(width) / f64::from(height),
            near: 0.1,
            far: Far::Finite(100_000.0),
        },
        depth,
    )
    .expect("valid camera")
}

/// 4 m above the sea, looking at the horizon towards the Sun (−z).
fn horizon_camera(width: u32, height: u32) -> Camera {
    camera(
        DVec3::new(0.0, 4.0, 0.0),
        DVec3::new(0.0, 0.0, -1.0),
        width,
        height,
        DepthConvention::ZERO_TO_ONE,
    )
}

fn renderer(ctx: &GpuContext, options: OceanOptions) -> OceanRenderer {
    let mut r = OceanRenderer::new(ctx, options).expect("renderer");
    r.set_surface(ctx, &surface()).expect("surface");
    r.set_lighting(ctx, &lighting()).expect("lighting");
    r
}

fn unit(v: DVec3) -> DVec3 {
    v.normalize()
}

/// A unit vector `elevation` degrees above the horizon, at `azimuth` degrees from +x towards +z.
fn dir(elevation: f64, azimuth: f64) -> DVec3 {
    let (e, a) = (elevation.to_radians(), azimuth.to_radians());
    DVec3::new(e.cos() * a.cos(), e.sin(), e.cos() * a.sin())
}

/// One of the three terms of a [`SeaLight`].
type Term = fn(&SeaLight) -> DVec3;

/// The absolute floor of the sea-colour parity, relative to each term's peak over the table.
const FLOOR: f64 = 1e-9;

fn f32_round(v: DVec3) -> DVec3 {
    v.as_vec3().as_dvec3()
}

/// Algorithm 5.1 on the GPU against `sea_color_unchecked`, term by term (§7.2 validates the
/// three terms apart, Fig. 10), over a table covering grazing (0.5°) to vertical views, vertical,
/// tilted (up to 35°) and back-facing normals, calm (no unresolved variance: the Sun's disc
/// only) to rough (σ² = 0.2) seas, two winds, and the Sun's glint in (views at the mirror
/// direction of the Sun, and 1 to 4 slope deviations off it) and out; and, as the fragment
/// stages light a pixel, with the normal made masking-aware first (`visible_normal`, §3.2):
/// normals off level and tilted geometry with normal-only variances, on the CPU
/// `sea_color_unchecked` of `sea::visible_normal`.
///
/// Tolerance: each channel of each term within 1 % of the CPU's value, or within an absolute
/// floor of [`FLOOR`] times that term's largest value over the table (f32 cannot promise 1 % of
/// a value 10⁹ times below the term's peak, deep in the tails of the Sun's Gaussian, nor
/// does it matter on screen). The inputs are rounded to f32 on both sides, so only the
/// arithmetic differs.
#[test]
fn sea_color_matches_the_cpu_twin() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let r = renderer(&ctx, OceanOptions::default());
    let light = lighting();
    let sky_map = light.sky_map(r.options().sky_map_size).expect("sky map");
    let sun = light.sky().sun_direction();

    let variances = [
        (0.0, 0.0),
        (1e-5, 8e-6),
        (1e-3, 6e-4),
        (0.01, 0.007),
        (0.05, 0.03),
        (0.2, 0.1),
    ];
    let normals = [
        DVec3::Y,
        unit(DVec3::new(0.1, 1.0, 0.05)),
        unit(DVec3::new(-0.3, 1.0, 0.4)),
        unit(DVec3::new(0.0, 1.0, -0.7)),
    ];
    let winds = [DVec2::X, DVec2::new(0.6, 0.8)];
    let mut inputs = Vec::new();
    for &(vx, vy) in &variances {
        let variance = SlopeVariance { x: vx, y: vy };
        let sigma = f64::max(vx.max(vy), 1.35e-6).sqrt();
        for (ni, &n) in normals.iter().enumerate() {
            let wind = winds[ni % 2];
            let mut views = vec![
                dir(0.5, 90.0),
                dir(0.5, -80.0),
                dir(2.0, 30.0),
                dir(5.0, 95.0),
                dir(15.0, 200.0),
                dir(30.0, 60.0),
                dir(60.0, -120.0),
                dir(89.0, 10.0),
                DVec3::Y,
            ];
            // The Sun's mirror direction about n (the glint's centre), and views off it by 1, 2
            // and 4 slope deviations (a slope δ turns the reflection by 2δ).
            let mirror = n * (2.0 * n.dot(sun)) - sun;
            if mirror.y > 0.0 {
                let side = unit(mirror.cross(DVec3::Y));
                for k in [0.0, 1.0, 2.0, 4.0] {
                    views.push(unit(mirror + side * (2.0 * k * sigma)));
                }
            }
            for v in views {
                inputs.push(SeaColorInput::plain(
                    f32_round(v),
                    f32_round(n),
                    wind,
                    variance,
                ));
            }
        }
    }
    // Back-facing normals (§3.2: reflected about the plane normal to v): grazing views over
    // normals tilted away from the viewer.
    for &(vx, vy) in &variances[2..] {
        for (v, n) in [
            (dir(1.0, 90.0), unit(DVec3::new(0.0, 0.2, -1.0))),
            (dir(3.0, -90.0), unit(DVec3::new(0.3, 0.1, 1.0))),
            (dir(10.0, 0.0), unit(DVec3::new(-1.0, 0.15, 0.0))),
        ] {
            assert!(v.dot(n) < 0.0, "back-facing case");
            inputs.push(SeaColorInput::plain(
                f32_round(v),
                f32_round(n),
                DVec2::X,
                SlopeVariance { x: vx, y: vy },
            ));
        }
    }
    // The masking-aware normal (§3.2, `visible_normal`): normals tilted off the geometry's by
    // the waves only they resolve, over level and tilted geometry, grazing to steep views,
    // small to large normal-only variances (up to a quarter of the slope variance of the
    // default sea) against small to large BRDF variances, two winds.
    let normal_only = [(0.004, 0.002), (0.02, 0.012)];
    let geometry = [DVec3::Y, unit(DVec3::new(0.06, 1.0, -0.03))];
    let tilted = [
        unit(DVec3::new(0.1, 1.0, 0.05)),
        unit(DVec3::new(-0.2, 1.0, 0.3)),
    ];
    for &(vx, vy) in &variances[2..5] {
        for &(nx, ny) in &normal_only {
            for (gi, &g) in geometry.iter().enumerate() {
                for &n in &tilted {
                    for v in [
                        dir(1.0, 90.0),
                        dir(3.0, -80.0),
                        dir(10.0, 30.0),
                        dir(40.0, 200.0),
                    ] {
                        inputs.push(SeaColorInput {
                            geometry_normal: f32_round(g),
                            normal_only: SlopeVariance { x: nx, y: ny },
                            ..SeaColorInput::plain(
                                f32_round(v),
                                f32_round(n),
                                winds[gi],
                                SlopeVariance { x: vx, y: vy },
                            )
                        });
                    }
                }
            }
        }
    }

    let gpu = r.probe_sea_color(&ctx, &inputs).expect("probe");
    let cpu: Vec<SeaLight> = inputs
        .iter()
        .map(|s| {
            let f32_var = |v: SlopeVariance| SlopeVariance {
                x: f64::from(v.x as f32),
                y: f64::from(v.y as f32),
            };
            let variance = f32_var(s.variance);
            let wind = s.wind.as_vec2().as_dvec2();
            let n = visible_normal(
                s.v,
                s.n,
                s.geometry_normal,
                wind,
                f32_var(s.normal_only),
                variance,
            );
            sea_color_unchecked(&light, &sky_map, s.v, n, wind, variance)
        })
        .collect();
    assert_eq!(gpu.len(), inputs.len());

    let terms: [(&str, Term); 3] = [("sun", |l| l.sun), ("sky", |l| l.sky), ("sea", |l| l.sea)];
    let mut failures = Vec::new();
    for (name, term) in terms {
        let peak = cpu
            .iter()
            .map(|l| term(l).max_element())
            .fold(0.0, f64::max);
        assert!(peak > 0.0, "{name}: the table must light this term");
        let floor = FLOOR * peak;
        let (mut worst, mut worst_at) = (0.0f64, 0);
        let mut compared = 0;
        for (i, (g, c)) in gpu.iter().zip(&cpu).enumerate() {
            let (g, c) = (term(g), term(c));
            for ch in 0..3 {
                let (g, c) = (g[ch], c[ch]);
                assert!(g.is_finite(), "{name} #{i}: GPU gives {g}");
                let err = (g - c).abs();
                if c.abs() > floor {
                    compared += 1;
                    let rel = err / c.abs();
                    if rel > worst {
                        (worst, worst_at) = (rel, i);
                    }
                }
                if err > 0.01 * c.abs() && err > floor {
                    failures.push(format!(
                        "{name} #{i} channel {ch}: GPU {g:e}, CPU {c:e} ({:?})",
                        inputs[i]
                    ));
                }
            }
        }
        println!(
            "sea colour, {name}: worst relative difference {worst:.2e} (input #{worst_at}, {:?}) \
             over {compared} channels above the floor {floor:.2e} (peak {peak:.3e})",
            inputs[worst_at]
        );
    }
    assert!(
        failures.is_empty(),
        "{} of {} terms outside 1 %:\n{}",
        failures.len(),
        inputs.len() * 9,
        failures.join("\n")
    );
}

/// The screen points of a geometry probe: every vertex of the projected grid (margin included)
/// and a lattice of pixel centres.
fn probe_pixels(r: &OceanRenderer, width: u32, height: u32) -> Vec<DVec2> {
    let (nx, ny) = r.grid_size(width, height).expect("grid size");
    let o = r.options();
    let origin = DVec2::new(-o.margin * f64::from(width), -o.margin * f64::from(height));
    let mut pixels = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            pixels.push(origin + DVec2::new(f64::from(i), f64::from(j)) * o.cell_px);
        }
    }
    for y in (0..height).step_by(3) {
        for x in (0..width).step_by(5) {
            pixels.push(DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5));
        }
    }
    pixels
}

/// Worst differences of a geometry probe against the CPU twins.
#[derive(Debug, Default)]
struct GeometryDiff {
    /// Eq. 2 at the GPU's own rest position and L, metres.
    wave_sum: f64,
    /// Eq. 3 at the GPU's own rest position and l, degrees.
    normal_deg: f64,
    /// Eq. 4 at the GPU's own l, relative to max(σ², 10⁻⁶).
    variance_rel: f64,
    /// The fragment stage's geometry normal at the GPU's rest position and its cell footprint
    /// (cell_px · l, the vertex stage's L at the same pixel), degrees.
    geometry_normal_deg: f64,
    /// Its normal-only variance for l and cell_px · l, relative to max(σ_n², 10⁻⁶).
    normal_only_rel: f64,
    /// Rest position against `sea_plane_hit(pixel_ray(..))`, over its tolerance.
    rest_ratio: f64,
    /// Rest position against the CPU's, metres (for the report).
    rest_m: f64,
    /// Footprints l and L against `pixel_footprint`, relative.
    footprint_rel: f64,
    /// Eq. 2 at the CPU's rest position and L, metres, over its tolerance.
    position_ratio: f64,
    /// Eq. 2 at the CPU's rest position and L, metres (for the report).
    position_m: f64,
    /// Points whose wave counts differ from `resolved_count` with a weight above 10⁻⁴.
    count_mismatches: usize,
    /// Waves summed, vertex and fragment stages, over all points.
    waves_summed: (u64, u64),
    /// Points compared.
    points: usize,
    /// Points with a normal-only variance above 10⁻⁴ (so the comparison is not vacuous).
    normal_only_points: usize,
}

/// The number of waves a footprint resolves on the CPU, and whether a count `gpu` is
/// acceptable: equal, or off by one at a wave whose weight at that footprint is below 10⁻⁴
/// (the f32 and f64 ratios λ/size can fall on either side of N_min there).
fn count_ok(s: &FilteredSurface, size: f64, gpu: u32) -> bool {
    let cpu = s.resolved_count(size);
    let gpu = gpu as usize;
    if gpu == cpu {
        return true;
    }
    let boundary = gpu.min(cpu);
    gpu.abs_diff(cpu) == 1
        && s.wavelengths()
            .get(boundary)
            .is_some_and(|&l| s.filter().weight(l, size) < 1e-4)
}

/// Probes the renderer's geometry for `camera` at `t` on a `width × height` viewport and
/// compares every point with the CPU twins (see [`geometry_matches_the_cpu_twin`]).
fn geometry_diff(
    ctx: &GpuContext,
    r: &OceanRenderer,
    cam: &Camera,
    t: f64,
    width: u32,
    height: u32,
) -> GeometryDiff {
    let s = surface();
    let o = r.options();
    let pixels = probe_pixels(r, width, height);
    let gpu = r
        .probe_surface(ctx, cam, t, width, height, &pixels)
        .expect("probe");
    let (w, h) = (f64::from(width), f64::from(height));
    let eye = cam.eye();
    let mut d = GeometryDiff {
        points: pixels.len(),
        ..Default::default()
    };
    for (p, g) in pixels.iter().zip(&gpu) {
        // The vertex and fragment stages' wave sums at their own inputs: f32 phases and sums.
        let at_gpu = s
            .position(g.rest, t, g.cell_footprint)
            .expect("cpu position");
        d.wave_sum = d.wave_sum.max((g.position - at_gpu).length());
        let n = s.normal(g.rest, t, g.pixel_footprint).expect("cpu normal");
        let angle = g.normal.angle_between(n).to_degrees();
        d.normal_deg = d.normal_deg.max(angle);
        let v = s.variance(g.pixel_footprint);
        let var_rel =
            (g.variance.x - v.x).abs().max((g.variance.y - v.y).abs()) / v.x.max(v.y).max(1e-6);
        d.variance_rel = d.variance_rel.max(var_rel);
        let px = s
            .pixel(g.rest, t, g.pixel_footprint, g.cell_footprint)
            .expect("cpu pixel");
        assert_eq!(px.normal, n);
        let geo = g
            .geometry_normal
            .angle_between(px.geometry_normal)
            .to_degrees();
        d.geometry_normal_deg = d.geometry_normal_deg.max(geo);
        let (gn, cn) = (g.normal_only, px.normal_only);
        let only_rel = (gn.x - cn.x).abs().max((gn.y - cn.y).abs()) / cn.x.max(cn.y).max(1e-6);
        d.normal_only_rel = d.normal_only_rel.max(only_rel);
        if cn.x.max(cn.y) > 1e-4 {
            d.normal_only_points += 1;
        }
        if !count_ok(&s, g.cell_footprint, g.position_waves)
            || !count_ok(&s, g.pixel_footprint, g.normal_waves)
        {
            d.count_mismatches += 1;
        }
        d.waves_summed.0 += u64::from(g.position_waves);
        d.waves_summed.1 += u64::from(g.normal_waves);

        // The rays, hits and footprints against the CPU's f64 ones.
        let (origin, ray) = pixel_ray(cam, w, h, *p).expect("cpu ray");
        let rest = sea_plane_hit(origin, ray, o.max_distance).expect("cpu hit");
        let l = pixel_footprint(cam, w, h, *p, o.max_distance).expect("cpu footprint");
        // A hit at distance s along a ray δ below the horizon moves by s·dδ/tan δ for a
        // direction error dδ: the f32 ray's error (≈ 10⁻⁷ rad) is magnified at grazing angles.
        let dist = (DVec3::new(rest.x, 0.0, rest.y) - eye).length();
        let conditioning = dist * (dist / eye.y).max(1.0);
        let rest_tol = 1e-3 + 4e-7 * conditioning;
        let rest_err = (g.rest - rest).length();
        d.rest_m = d.rest_m.max(rest_err);
        d.rest_ratio = d.rest_ratio.max(rest_err / rest_tol);
        let fp_rel = ((g.pixel_footprint - l).abs() / l)
            .max((g.cell_footprint - o.cell_px * l).abs() / (o.cell_px * l));
        d.footprint_rel = d.footprint_rel.max(fp_rel);
        // End to end: Eq. 2 at the CPU's rest position and L. A rest error moves the displaced
        // point by at most (1 + Σ k·A) times as much; a relative footprint error e changes each
        // w_p by at most 1.5 N_max/(N_max − N_min) e = 2.5 e (the smoothstep's steepest slope,
        // 1.5, over x̄ = (λ/L − N_min)/(N_max − N_min), with λ/L ≤ N_max where w_p < 1).
        let cpu = s.position(rest, t, o.cell_px * l).expect("cpu position");
        let pos_err = (g.position - cpu).length();
        d.position_m = d.position_m.max(pos_err);
        let amplitude: f64 = s.wave_set().waves().iter().map(|w| w.amplitude()).sum();
        let steep = s.wave_set().steepness_sum();
        let pos_tol = 1e-3 + rest_tol * (1.0 + steep) + amplitude * 2.5 * fp_rel;
        d.position_ratio = d.position_ratio.max(pos_err / pos_tol);
    }
    d
}

/// The renderer's geometry against `ocean_brdf::surface`, on the projected grid's vertices
/// (margin included) and a lattice of pixel centres, for a camera 4 m up looking at the
/// horizon (sky rays meet the 50 km cap), one 30 m up looking down, and one 100 km from the
/// origin at t = 10⁶ s (where unreduced f32 phases would be off by whole radians).
///
/// Tolerances:
/// - Eq. 2 at the GPU's own rest position and grid-cell footprint L: 1 mm (f32 phases reduced
///   on the host, f32 sums);
/// - Eq. 3 at the GPU's rest position and pixel footprint l: 0.1°;
/// - Eq. 4 at the GPU's l: 10⁻⁴ relative to max(σ², 10⁻⁶);
/// - the fragment stage's geometry normal and normal-only variance (`FilteredSurface::pixel`
///   for l and cell_px · l, at the GPU's rest position): 0.1° and 10⁻⁴ relative to
///   max(σ_n², 10⁻⁶), as Eq. 3 and 4;
/// - waves summed: `FilteredSurface::resolved_count` of the same footprint (off by one only at
///   a weight below 10⁻⁴);
/// - rest positions against `sea_plane_hit(pixel_ray(..))`: 1 mm + 4·10⁻⁷ s·max(1, s/h), the
///   f32 ray's direction error magnified by the hit's conditioning at grazing angles (s the
///   distance, h the eye's height);
/// - footprints l and L: 10⁻³ relative;
/// - end to end, Eq. 2 at the CPU's rest position and L: 1 mm plus the rest tolerance times
///   (1 + Σ k·A) plus Σ A times 2.5 times the footprint error.
#[test]
fn geometry_matches_the_cpu_twin() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let r = renderer(&ctx, OceanOptions::default());
    let (width, height) = (64, 48);
    let cases = [
        (
            "4 m, horizon, t = 10 s",
            horizon_camera(width, height),
            10.0,
        ),
        (
            "30 m, looking 30° down, t = 100 s",
            camera(
                DVec3::new(5.0, 30.0, -3.0),
                dir(-30.0, 200.0),
                width,
                height,
                DepthConvention::ZERO_TO_ONE,
            ),
            100.0,
        ),
        (
            "6 m, 100 km from the origin, t = 10⁶ s",
            camera(
                DVec3::new(100_000.0, 6.0, -100_000.0),
                dir(-8.0, 40.0),
                width,
                height,
                DepthConvention::ZERO_TO_ONE_REVERSED,
            ),
            1e6,
        ),
    ];
    for (label, cam, t) in cases {
        let d = geometry_diff(&ctx, &r, &cam, t, width, height);
        println!("geometry, {label}: {d:?}");
        assert!(
            d.wave_sum <= 1e-3,
            "{label}: Eq. 2 differs by {} m",
            d.wave_sum
        );
        assert!(
            d.normal_deg <= 0.1,
            "{label}: Eq. 3 differs by {}°",
            d.normal_deg
        );
        assert!(
            d.variance_rel <= 1e-4,
            "{label}: Eq. 4 differs by {} (relative)",
            d.variance_rel
        );
        assert!(
            d.geometry_normal_deg <= 0.1,
            "{label}: the geometry normal differs by {}°",
            d.geometry_normal_deg
        );
        assert!(
            d.normal_only_rel <= 1e-4,
            "{label}: the normal-only variance differs by {} (relative)",
            d.normal_only_rel
        );
        assert_eq!(d.count_mismatches, 0, "{label}: waves summed");
        assert!(
            d.rest_ratio <= 1.0,
            "{label}: rest positions ({} m)",
            d.rest_m
        );
        assert!(
            d.footprint_rel <= 1e-3,
            "{label}: footprints differ by {} (relative)",
            d.footprint_rel
        );
        assert!(
            d.position_ratio <= 1.0,
            "{label}: end-to-end positions ({} m)",
            d.position_m
        );
        // Not a vacuous comparison: the waves are there.
        assert!(d.points > 300 && d.waves_summed.0 > 0 && d.waves_summed.1 > d.waves_summed.0);
        assert!(d.normal_only_points > 100, "{label}: {d:?}");
    }
}

/// The waves each sum visits are the resolved ones only: the GPU's loops stop at the first zero
/// weight (waves sorted longest first), so the count each stage reports equals
/// `FilteredSurface::resolved_count` of its footprint, and distant views visit fewer waves
/// (§7.1: "the computation time ... is proportional to the number of resolved waves").
#[test]
fn zero_weight_waves_are_skipped() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let r = renderer(&ctx, OceanOptions::default());
    let s = surface();
    let total = s.wavelengths().len() as u32;
    let (width, height) = (64, 48);
    let mut previous = f64::INFINITY;
    for altitude in [4.0, 100.0, 1000.0, 8000.0] {
        let cam = camera(
            DVec3::new(0.0, altitude, 0.0),
            dir(-20.0, -90.0),
            width,
            height,
            DepthConvention::ZERO_TO_ONE,
        );
        let pixels = probe_pixels(&r, width, height);
        let gpu = r
            .probe_surface(&ctx, &cam, 10.0, width, height, &pixels)
            .expect("probe");
        let mut sum = 0u64;
        let mut partial = 0;
        for g in &gpu {
            assert!(
                count_ok(&s, g.cell_footprint, g.position_waves),
                "{altitude} m: the vertex stage summed {} waves at L = {} m, {} resolved",
                g.position_waves,
                g.cell_footprint,
                s.resolved_count(g.cell_footprint)
            );
            assert!(
                count_ok(&s, g.pixel_footprint, g.normal_waves),
                "{altitude} m: the fragment stage summed {} waves at l = {} m, {} resolved",
                g.normal_waves,
                g.pixel_footprint,
                s.resolved_count(g.pixel_footprint)
            );
            sum += u64::from(g.normal_waves);
            if g.normal_waves < total {
                partial += 1;
            }
        }
        let mean = sum as f64 / gpu.len() as f64;
        println!("{altitude} m: {mean:.1} of {total} waves per pixel on average");
        // Every view leaves short waves out somewhere, and higher views leave out more.
        assert!(partial > 0, "{altitude} m: some pixel must skip waves");
        assert!(
            mean < previous,
            "{altitude} m: {mean} waves, {previous} lower down"
        );
        previous = mean;
    }
}

/// Where the reference image lives.
fn reference_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("data/ocean_horizon_96x64.rgba")
}

/// Mean absolute difference per channel (levels) and the share of pixels with a channel more
/// than `levels` apart.
fn image_diff(a: &[u8], b: &[u8], levels: u8) -> (f64, f64) {
    assert_eq!(a.len(), b.len());
    let sum: u64 = a
        .iter()
        .zip(b)
        .map(|(x, y)| u64::from(x.abs_diff(*y)))
        .sum();
    let pixels = a.len() / 4;
    let far = a
        .chunks_exact(4)
        .zip(b.chunks_exact(4))
        .filter(|(p, q)| p.iter().zip(q.iter()).any(|(x, y)| x.abs_diff(*y) > levels))
        .count();
    (sum as f64 / a.len() as f64, far as f64 / pixels as f64)
}

/// Mean RGB over rows `rows` of a `width`-wide RGBA8 image.
fn mean_rgb(img: &[u8], width: usize, rows: std::ops::Range<usize>) -> DVec3 {
    let mut sum = DVec3::ZERO;
    let mut n = 0.0;
    for y in rows {
        for px in img[y * width * 4..(y + 1) * width * 4].chunks_exact(4) {
            sum += DVec3::new(px[0].into(), px[1].into(), px[2].into());
            n += 1.0;
        }
    }
    sum / n
}

/// A 96 × 64 headless render (4 m up, looking at the horizon towards the Sun, the default sea
/// and sky, t = 10 s) against the stored reference `tests/data/ocean_horizon_96x64.rgba`
/// (tightly packed RGBA8, rows from the top; `OCEAN_BLESS=1` rewrites it): mean absolute
/// difference at most 1 level per channel, at most 2 % of the pixels with a channel more than
/// 8 levels apart (software rasterisers agree within a level; GPUs differ in the Sun's glint).
/// Also checks what any correct render shows: every pixel opaque and lit (NaN radiance would
/// tone-map to black), the water blue, the sky above the horizon brighter than the water, and
/// the glint under the Sun brighter than the water beside it.
#[test]
fn headless_render_matches_the_reference_image() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let (width, height) = (96, 64);
    let r = renderer(&ctx, OceanOptions::default());
    let img = r
        .render_image(&ctx, &horizon_camera(width, height), 10.0, width, height)
        .expect("render");
    assert_eq!(img.len(), 96 * 64 * 4);

    assert!(img.chunks_exact(4).all(|p| p[3] == 255), "opaque");
    let darkest = img
        .chunks_exact(4)
        .map(|p| p[0].max(p[1]).max(p[2]))
        .min()
        .unwrap_or(0);
    assert!(
        darkest >= 40,
        "a pixel is nearly black ({darkest}): NaN radiance?"
    );
    // The horizon is the middle row (the camera looks horizontally).
    let sky = mean_rgb(&img, 96, 0..30);
    let sea = mean_rgb(&img, 96, 34..64);
    println!("mean sky {sky:.1}, mean sea {sea:.1}");
    assert!(sea.z > sea.x + 30.0, "the water is blue: {sea}");
    assert!(
        sky.element_sum() > sea.element_sum() + 60.0,
        "sky {sky} vs sea {sea}"
    );
    // The glint: the columns under the Sun (x in 40..56) against the side ones, near the
    // horizon where it is widest.
    let column_mean = |x0: usize, x1: usize| {
        let mut sum = 0.0;
        for y in 34..44 {
            for x in x0..x1 {
                let p = &img[(y * 96 + x) * 4..(y * 96 + x) * 4 + 3];
                sum += f64::from(p[0]) + f64::from(p[1]) + f64::from(p[2]);
            }
        }
        sum / ((x1 - x0) * 10) as f64
    };
    let (glint, side) = (column_mean(40, 56), column_mean(0, 16));
    assert!(glint > side + 100.0, "glint {glint} vs side {side}");

    let path = reference_path();
    if std::env::var("OCEAN_BLESS").is_ok_and(|v| v.trim() == "1") {
        std::fs::create_dir_all(path.parent().expect("data dir")).expect("mkdir");
        std::fs::write(&path, &img).expect("write the reference");
        println!("blessed {}", path.display());
        return;
    }
    let reference = std::fs::read(&path).unwrap_or_else(|e| {
        panic!(
            "{}: {e} (run once with OCEAN_BLESS=1 to create it)",
            path.display()
        )
    });
    let (mean, share) = image_diff(&img, &reference, 8);
    println!(
        "reference image: mean difference {mean:.3} levels, {:.2} % of pixels > 8 levels",
        100.0 * share
    );
    assert!(mean <= 1.0, "mean difference {mean} levels");
    assert!(
        share <= 0.02,
        "{:.2} % of pixels differ by more than 8 levels",
        100.0 * share
    );
}

/// The same view through a reversed-Z camera, an OpenGL [−1, 1] camera, no depth buffer, an
/// sRGB target (where the hardware encodes instead of the shader) and a BGRA target gives the
/// same image within rounding: at most 0.5 level of mean difference and 0.5 % of pixels beyond
/// 4 levels. Without the sky background, the sea is unchanged and the sky is the clear colour.
#[test]
fn depth_conventions_and_targets_agree() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let (width, height) = (96, 64);
    let view = |depth| {
        camera(
            DVec3::new(2.0, 5.0, 1.0),
            dir(-6.0, -80.0),
            width,
            height,
            depth,
        )
    };
    let base = renderer(&ctx, OceanOptions::default())
        .render_image(
            &ctx,
            &view(DepthConvention::ZERO_TO_ONE),
            20.0,
            width,
            height,
        )
        .expect("render");
    let cases = [
        (
            "reversed Z",
            OceanOptions::default(),
            DepthConvention::ZERO_TO_ONE_REVERSED,
        ),
        (
            "OpenGL [-1, 1]",
            OceanOptions::default(),
            DepthConvention::NEG_ONE_TO_ONE,
        ),
        (
            "no depth buffer",
            OceanOptions {
                depth_format: None,
                ..OceanOptions::default()
            },
            DepthConvention::ZERO_TO_ONE,
        ),
        (
            "sRGB target",
            OceanOptions {
                color_format: wgpu::TextureFormat::Rgba8UnormSrgb,
                ..OceanOptions::default()
            },
            DepthConvention::ZERO_TO_ONE,
        ),
        (
            "BGRA target",
            OceanOptions {
                color_format: wgpu::TextureFormat::Bgra8Unorm,
                ..OceanOptions::default()
            },
            DepthConvention::ZERO_TO_ONE,
        ),
    ];
    // Without the sky the clear colour (black) shows above the horizon, and the sea is the
    // same. The horizon is 6° above the centre: row 26 of 64.
    let no_sky = renderer(
        &ctx,
        OceanOptions {
            draw_sky: false,
            ..OceanOptions::default()
        },
    )
    .render_image(
        &ctx,
        &view(DepthConvention::ZERO_TO_ONE),
        20.0,
        width,
        height,
    )
    .expect("render without sky");
    let row = |img: &[u8], y: usize| img[y * 96 * 4..(y + 1) * 96 * 4].to_vec();
    for y in 0..20 {
        assert!(
            row(&no_sky, y).chunks_exact(4).all(|p| p == [0, 0, 0, 255]),
            "row {y}"
        );
    }
    for y in 32..64 {
        assert_eq!(row(&no_sky, y), row(&base, y), "row {y}");
    }
    for (label, options, depth) in cases {
        let img = renderer(&ctx, options)
            .render_image(&ctx, &view(depth), 20.0, width, height)
            .expect(label);
        let (mean, share) = image_diff(&img, &base, 4);
        println!(
            "{label}: mean difference {mean:.3} levels, {:.2} % of pixels > 4 levels",
            100.0 * share
        );
        assert!(
            mean <= 0.5 && share <= 0.005,
            "{label}: {mean} levels, {share} share"
        );
    }
}

/// `render` draws into the caller's targets through the caller's encoder, keeping what is there
/// outside its viewport: the top-left 64 × 48 of a 80 × 60 target cleared to magenta holds the
/// same image as `render_image` at 64 × 48, and the rest stays magenta.
#[test]
fn render_into_caller_targets() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let r = renderer(&ctx, OceanOptions::default());
    let (width, height) = (64u32, 48u32);
    let cam = horizon_camera(width, height);
    let expected = r
        .render_image(&ctx, &cam, 5.0, width, height)
        .expect("image");

    let device = ctx.device();
    let texture = |format, usage| texture_2d(&ctx, (80, 60), format, usage);
    let color = texture(
        wgpu::TextureFormat::Rgba8Unorm,
        wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
    );
    let depth = texture(
        wgpu::TextureFormat::Depth32Float,
        wgpu::TextureUsages::RENDER_ATTACHMENT,
    );
    let color_view = color.create_view(&Default::default());
    let depth_view = depth.create_view(&Default::default());
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        // The caller's own clear.
        encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("caller clear"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &color_view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color {
                        r: 1.0,
                        g: 0.0,
                        b: 1.0,
                        a: 1.0,
                    }),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &depth_view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(1.0),
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: None,
            }),
            ..Default::default()
        });
    }
    r.render(
        &ctx,
        &mut encoder,
        &cam,
        5.0,
        &color_view,
        Some(&depth_view),
        (width, height),
    )
    .expect("render");
    ctx.queue().submit([encoder.finish()]);
    let data = ocean_gpu::readback::read_texture(&ctx, &color, 0)
        .expect("readback")
        .data;
    let mut inside = Vec::new();
    for y in 0..60usize {
        for x in 0..80usize {
            let p = &data[(y * 80 + x) * 4..(y * 80 + x) * 4 + 4];
            if x < 64 && y < 48 {
                inside.extend_from_slice(p);
            } else {
                assert_eq!(
                    p,
                    [255, 0, 255, 255],
                    "pixel ({x}, {y}) outside the viewport"
                );
            }
        }
    }
    let (mean, share) = image_diff(&inside, &expected, 1);
    assert!(
        mean <= 0.01 && share <= 0.001,
        "{mean} levels, {share} share"
    );
}

/// Every error path returns an error, not a panic (and nothing is drawn).
#[test]
fn bad_inputs_are_errors() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let bad_options = [
        OceanOptions {
            cell_px: 0.0,
            ..OceanOptions::default()
        },
        OceanOptions {
            cell_px: f64::NAN,
            ..OceanOptions::default()
        },
        OceanOptions {
            margin: -0.1,
            ..OceanOptions::default()
        },
        OceanOptions {
            max_distance: f64::INFINITY,
            ..OceanOptions::default()
        },
        OceanOptions {
            max_distance: 0.0,
            ..OceanOptions::default()
        },
        OceanOptions {
            sky_map_size: 100,
            ..OceanOptions::default()
        },
        OceanOptions {
            sky_map_size: 1 << 20,
            ..OceanOptions::default()
        },
        OceanOptions {
            exposure: -1.0,
            ..OceanOptions::default()
        },
        OceanOptions {
            color_format: wgpu::TextureFormat::Depth32Float,
            ..OceanOptions::default()
        },
        OceanOptions {
            depth_format: Some(wgpu::TextureFormat::Rgba8Unorm),
            ..OceanOptions::default()
        },
    ];
    for o in bad_options {
        let e = OceanRenderer::new(&ctx, o.clone()).expect_err("bad options");
        assert!(matches!(e, GpuError::InvalidInput { .. }), "{o:?}: {e}");
    }

    let (w, h) = (32, 24);
    let cam = horizon_camera(w, h);
    // Nothing set yet.
    let mut r = OceanRenderer::new(&ctx, OceanOptions::default()).expect("renderer");
    let e = r
        .render_image(&ctx, &cam, 0.0, w, h)
        .expect_err("no surface");
    assert!(matches!(e, GpuError::NotConfigured { .. }), "{e}");
    assert!(e.to_string().contains("set_surface"), "{e}");
    r.set_surface(&ctx, &surface()).expect("surface");
    let e = r
        .render_image(&ctx, &cam, 0.0, w, h)
        .expect_err("no lighting");
    assert!(e.to_string().contains("set_lighting"), "{e}");
    let one = [SeaColorInput::plain(
        DVec3::Y,
        DVec3::Y,
        DVec2::X,
        SlopeVariance::default(),
    )];
    assert!(matches!(
        r.probe_sea_color(&ctx, &one),
        Err(GpuError::NotConfigured { .. })
    ));
    // A sky beyond binary16's range cannot be mapped.
    let blinding = Lighting::new(
        SkyParams {
            zenith_radiance: DVec3::splat(1e6),
            ..SkyParams::default()
        },
        SeaParams::default(),
    )
    .expect("valid, if blinding");
    assert!(matches!(
        r.set_lighting(&ctx, &blinding),
        Err(GpuError::Brdf(_))
    ));
    r.set_lighting(&ctx, &lighting()).expect("lighting");
    r.render_image(&ctx, &cam, 0.0, w, h)
        .expect("now it renders");

    // Viewports.
    for (w, h) in [(0, 24), (32, 0), (1 << 20, 24), (32, u32::MAX)] {
        let e = r.render_image(&ctx, &cam, 0.0, w, h).expect_err("viewport");
        assert!(matches!(e, GpuError::InvalidInput { .. }), "{w} x {h}: {e}");
    }
    assert!(r.grid_size(0, 10).is_err());
    // Times.
    for t in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let e = r.render_image(&ctx, &cam, t, w, h).expect_err("time");
        assert!(matches!(e, GpuError::Eval(_)), "t = {t}: {e}");
    }
    // Cameras at or below the sea.
    for y in [0.0, -3.0] {
        let under = camera(
            DVec3::new(0.0, y, 0.0),
            DVec3::new(0.0, 0.0, -1.0),
            w,
            h,
            DepthConvention::ZERO_TO_ONE,
        );
        let e = r.render_image(&ctx, &under, 0.0, w, h).expect_err("under");
        assert!(e.to_string().contains("above the sea"), "{e}");
        assert!(
            r.probe_surface(&ctx, &under, 0.0, w, h, &[DVec2::ONE])
                .is_err()
        );
    }
    // Probes.
    assert!(r.probe_surface(&ctx, &cam, 0.0, w, h, &[]).is_err());
    assert!(
        r.probe_surface(&ctx, &cam, 0.0, w, h, &[DVec2::new(f64::NAN, 1.0)])
            .is_err()
    );
    assert!(r.probe_sea_color(&ctx, &[]).is_err());
    for bad in [
        SeaColorInput {
            v: DVec3::new(0.0, 2.0, 0.0),
            ..one[0]
        },
        SeaColorInput {
            n: DVec3::splat(f64::NAN),
            ..one[0]
        },
        SeaColorInput {
            wind: DVec2::ZERO,
            ..one[0]
        },
        SeaColorInput {
            variance: SlopeVariance { x: -1.0, y: 0.0 },
            ..one[0]
        },
        SeaColorInput {
            geometry_normal: DVec3::new(0.0, 0.5, 0.0),
            ..one[0]
        },
        SeaColorInput {
            normal_only: SlopeVariance {
                x: 0.0,
                y: f64::NAN,
            },
            ..one[0]
        },
    ] {
        let e = r.probe_sea_color(&ctx, &[bad]).expect_err("bad input");
        assert!(matches!(e, GpuError::InvalidInput { .. }), "{e}");
    }
    // render_image needs an 8-bit RGBA or BGRA format.
    let mut hdr = OceanRenderer::new(
        &ctx,
        OceanOptions {
            color_format: wgpu::TextureFormat::Rgba16Float,
            ..OceanOptions::default()
        },
    )
    .expect("hdr renderer");
    hdr.set_surface(&ctx, &surface()).expect("surface");
    hdr.set_lighting(&ctx, &lighting()).expect("lighting");
    assert!(matches!(
        hdr.render_image(&ctx, &cam, 0.0, w, h),
        Err(GpuError::InvalidInput { .. })
    ));

    // Caller targets that do not fit: wrong format, too small, a missing or an extra depth
    // view, no RENDER_ATTACHMENT usage. Nothing is recorded.
    let device = ctx.device();
    let texture = |format, width, usage| {
        device
            .create_texture(&wgpu::TextureDescriptor {
                label: Some("target"),
                size: wgpu::Extent3d {
                    width,
                    height: h,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
            .create_view(&Default::default())
    };
    let attach = wgpu::TextureUsages::RENDER_ATTACHMENT;
    let color = texture(wgpu::TextureFormat::Rgba8Unorm, w, attach);
    let depth = texture(wgpu::TextureFormat::Depth32Float, w, attach);
    let cases = [
        (
            texture(wgpu::TextureFormat::Rgba16Float, w, attach),
            Some(&depth),
        ),
        (
            texture(wgpu::TextureFormat::Rgba8Unorm, w - 1, attach),
            Some(&depth),
        ),
        (
            texture(
                wgpu::TextureFormat::Rgba8Unorm,
                w,
                wgpu::TextureUsages::TEXTURE_BINDING,
            ),
            Some(&depth),
        ),
        (color.clone(), None),
        (color.clone(), Some(&color)),
    ];
    for (i, (c, d)) in cases.iter().enumerate() {
        let mut encoder = device.create_command_encoder(&Default::default());
        let e = r
            .render(&ctx, &mut encoder, &cam, 0.0, c, *d, (w, h))
            .expect_err("bad target");
        assert!(
            matches!(e, GpuError::InvalidResource { .. }),
            "case {i}: {e}"
        );
    }
    let mut no_depth = OceanRenderer::new(
        &ctx,
        OceanOptions {
            depth_format: None,
            ..OceanOptions::default()
        },
    )
    .expect("renderer");
    no_depth.set_surface(&ctx, &surface()).expect("surface");
    no_depth.set_lighting(&ctx, &lighting()).expect("lighting");
    let mut encoder = device.create_command_encoder(&Default::default());
    assert!(matches!(
        no_depth.render(&ctx, &mut encoder, &cam, 0.0, &color, Some(&depth), (w, h)),
        Err(GpuError::InvalidResource { .. })
    ));
}

/// Issue 4's bad-input rule for views: grazing, vertical, tiny and huge altitudes, far from
/// the origin, late times, reversed and OpenGL depth, extreme wind: no pixel of any such frame
/// is left unlit (NaN radiance tone-maps to black), every pixel is opaque.
#[test]
fn extreme_views_never_give_unlit_pixels() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let (w, h) = (48, 32);
    let mut r = renderer(&ctx, OceanOptions::default());
    let views: [(&str, DVec3, DVec3, DepthConvention, f64); 9] = [
        (
            "1 cm above the sea, at the horizon",
            DVec3::new(0.0, 0.01, 0.0),
            dir(0.0, -90.0),
            DepthConvention::ZERO_TO_ONE,
            10.0,
        ),
        (
            "straight down from 2 m",
            DVec3::new(0.0, 2.0, 0.0),
            DVec3::new(1e-6, -1.0, 0.0),
            DepthConvention::ZERO_TO_ONE,
            10.0,
        ),
        (
            "straight up from 4 m",
            DVec3::new(0.0, 4.0, 0.0),
            DVec3::new(1e-6, 1.0, 0.0),
            DepthConvention::ZERO_TO_ONE,
            10.0,
        ),
        (
            "100 km up, looking down 30°",
            DVec3::new(0.0, 1e5, 0.0),
            dir(-30.0, 45.0),
            DepthConvention::ZERO_TO_ONE,
            10.0,
        ),
        (
            "grazing, 0.01° below the horizon",
            DVec3::new(0.0, 10.0, 0.0),
            dir(-0.01, -90.0),
            DepthConvention::ZERO_TO_ONE,
            10.0,
        ),
        (
            "100 km from the origin at t = 1e6 s",
            DVec3::new(1e5, 6.0, -1e5),
            dir(-5.0, 200.0),
            DepthConvention::ZERO_TO_ONE,
            1e6,
        ),
        (
            "reversed depth, at the Sun's glint",
            DVec3::new(0.0, 30.0, 0.0),
            dir(-25.0, -90.0),
            DepthConvention::ZERO_TO_ONE_REVERSED,
            10.0,
        ),
        (
            "OpenGL depth, away from the Sun",
            DVec3::new(0.0, 4.0, 0.0),
            dir(-3.0, 90.0),
            DepthConvention::NEG_ONE_TO_ONE,
            10.0,
        ),
        (
            "1000 m, looking at the horizon",
            DVec3::new(0.0, 1000.0, 0.0),
            dir(-2.0, -90.0),
            DepthConvention::ZERO_TO_ONE,
            10.0,
        ),
    ];
    let check = |r: &OceanRenderer, label: &str| {
        for &(name, eye, d, depth, t) in &views {
            let img = r
                .render_image(&ctx, &camera(eye, d, w, h, depth), t, w, h)
                .unwrap_or_else(|e| panic!("{label}, {name}: {e}"));
            assert!(
                img.chunks_exact(4).all(|p| p[3] == 255),
                "{label}, {name}: opaque"
            );
            let darkest = img
                .chunks_exact(4)
                .map(|p| p[0].max(p[1]).max(p[2]))
                .min()
                .unwrap_or(0);
            // The darkest lit water of these scenes tone-maps well above 30 (sRGB levels).
            assert!(
                darkest >= 30,
                "{label}, {name}: a pixel is unlit ({darkest})"
            );
        }
    };
    check(&r, "default sea");
    // An extreme sea: a 40 m/s wind (every wave at the steepness clamp) and a calm one.
    for wind_speed in [40.0, 0.5] {
        let spectrum = Spectrum::new(SpectrumParams {
            wind_speed,
            ..SpectrumParams::default()
        })
        .expect("spectrum");
        let s = FilteredSurface::new(&spectrum, Filter::PAPER).expect("surface");
        r.set_surface(&ctx, &s).expect("set_surface");
        check(&r, &format!("wind {wind_speed} m/s"));
    }
}
