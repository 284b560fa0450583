//! The renderer's geometry (Eq. 2 to 4, footprints, the waves each sum visits) against
//! `ocean_brdf::surface`.

use super::*;

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
