//! The whole pipeline on the analytic scenes: unoccluded planes, monotone darkening toward
//! contacts, the brute-force references, agreement across depth conventions, determinism,
//! the guard band and snapshots.

mod common;

use common::{Render, convention_name, hex_grid, projections};
use ocean_core::{DepthConvention, DepthRange};
use ocean_sao::analytic::{AnalyticView, CameraRays, DepthFormat};
use ocean_sao::reference::{self, Comparison, ReferenceParams, compare};
use ocean_sao::{DepthSource, Estimator, NormalRejection, SaoParams};

/// Input 144 × 112 with a 16 px guard band: output 112 × 80.
const SIZE: (usize, usize, usize) = (144, 112, 16);

fn rejecting() -> SaoParams {
    SaoParams {
        normal_rejection: Some(NormalRejection {
            max_incidence: 85f32.to_radians(),
        }),
        ..SaoParams::default()
    }
}

/// A flat open plane occludes nothing: every sample is a depth-buffer point of the plane itself
/// (the rotated grid makes every MIP sample an actual pixel, see `ZHierarchy::sample`), so its
/// height above the reconstructed tangent plane, `v·n̂`, is within the depth error (≤ 0.1 mm,
/// Fig. 3) plus `|v|·` the normal error (≤ 0.03° on this plane: 0.5 mm at r = 1 m). That is below
/// the appendix's β = 1 cm and below Eq. 1's bias `|z_C|·β ≥ 1.5 mm` (every visible point is
/// at least 1.5 m away), so every term is 0 and A is exactly 1 at every pixel, raw and final,
/// for every convention, far plane, orthographic camera, depth format and both estimators.
#[test]
fn open_plane_stays_unoccluded() {
    let mut runs = 0;
    for (name, projection) in projections(SIZE.0, SIZE.1) {
        for convention in DepthConvention::ALL {
            for format in [DepthFormat::F32, DepthFormat::Unorm24] {
                let r = Render::new(
                    AnalyticView::open_plane(),
                    projection,
                    convention,
                    DepthSource::Window,
                    format,
                    SIZE,
                );
                for estimator in [Estimator::FALLOFF, Estimator::ALCHEMY] {
                    let st = r.stages(SaoParams {
                        estimator,
                        ..SaoParams::default()
                    });
                    let geometry = (0..st.ao.len()).filter(|&i| r.is_geometry(i)).count();
                    assert!(geometry > 1000, "{name}: the plane fills the view");
                    assert!(
                        st.raw.iter().all(|&a| a == 1.0),
                        "{name} {convention:?} {format:?} {estimator:?}"
                    );
                    assert!(
                        st.ao.iter().all(|&a| a == 1.0),
                        "{name} {convention:?} {format:?} {estimator:?}"
                    );
                    runs += 1;
                }
            }
        }
    }
    assert_eq!(runs, 36);
}

/// Mean final A of the pixels of `face` binned by `distance` in 0.1 m bins up to 1.6 m.
fn profile(
    r: &Render,
    ao: &[f32],
    keep: impl Fn(usize, glam::DVec3) -> Option<f64>,
) -> Vec<(f64, usize)> {
    let mut bins = vec![(0.0, 0); 16];
    for (i, &a) in ao.iter().enumerate() {
        if !r.is_geometry(i) {
            continue;
        }
        let face = r.raster.face[r.input_index(i)] as usize;
        if let Some(d) = keep(face, r.world_point(i)) {
            let b = (d / 0.1) as usize;
            if b < bins.len() {
                bins[b].0 += f64::from(a);
                bins[b].1 += 1;
            }
        }
    }
    bins.iter()
        .map(|&(s, n)| (s / n.max(1) as f64, n))
        .collect()
}

/// Asserts that a profile never gets darker away from the contact (a bin's mean A is at least
/// the previous bin's) from its `skip`-th populated bin on, that the nearest populated bin is
/// darker than `contact_max` and than every bin from the 4th on, and prints it.
fn assert_monotone(what: &str, bins: &[(f64, usize)], contact_max: f64, skip: usize) {
    let means: Vec<f64> = bins.iter().filter(|b| b.1 > 0).map(|b| b.0).collect();
    println!(
        "{what}: {}",
        means
            .iter()
            .map(|m| format!("{m:.3}"))
            .collect::<Vec<_>>()
            .join(" ")
    );
    assert!(means.len() >= 12, "{what}: {bins:?}");
    assert!(means[0] <= contact_max, "{what}: contact {}", means[0]);
    assert!(
        means[3..].iter().all(|&m| m >= means[0]),
        "{what}: {means:?}"
    );
    // The final image passes through 8-bit A between the blur passes (§2.3's packing): a bin
    // whose real obscurance is a few thousandths may come out a fraction of 1/255 below its
    // brighter neighbour from the rounding alone (measured: 1.2e-4 at 0.9 m on the crease).
    for w in means[skip..].windows(2) {
        assert!(
            w[1] >= w[0] - 0.5 / 255.0,
            "{what}: {} then {} ({means:?})",
            w[0],
            w[1]
        );
    }
}

/// The 90° crease (floor y = 0, wall z = −4, r = 1 m), with both estimators and with or
/// without the normal rejection. Floor pixels are binned by their distance to the wall (0.1 m
/// bins), wall pixels by their height.
///
/// - The sample pass's output (after the 2×2 quad filter) darkens monotonically toward the
///   contact line on both faces, from the first bin, to at least 10% obscurance at the contact
///   (A ≤ 0.9; the falloff reaches 0.02–0.34, Eq. 1 with its weaker σ = 0.25 m 0.68–0.82).
/// - The final image does too on the wall, and on the floor from its second populated bin on;
///   the floor's contact row itself (4 cm from the wall at this resolution) is lifted by the
///   §2.4 reconstruction: it lies at the same view depth as the wall 13 cm above it (the camera
///   looks down 16°), so the depth-only bilateral weighs those wall pixels fully and averages
///   them in (measured 0.33 against 0.21 in the next bin; 0.02 before the blur). A sharper depth
///   scale does not separate surfaces at equal depth; this is the paper's filter, reported, not
///   hidden. The contact bin stays at A ≤ 0.9 and darker than every bin from 0.3 m on.
/// - Beyond the radius nothing can occlude (every wall point is farther than r from a floor
///   point 1 m away, and the floor is coplanar), and the plane-weighted blur only mixes taps
///   less than `world_extent·r = 0.5 m` away: every pixel farther than 1.5 m from the crease is
///   exactly 1. (With the paper's weight, which mixes only pixels whose depth differs by less
///   than `200 m / 2¹¹ ≈ 0.1 m`, it was 1.2 m; the contact row's lift described above is gone
///   with the plane weight: measured 0.07 against 0.18 in the next bin.)
#[test]
fn crease_darkens_monotonically_toward_the_contact() {
    let r = Render::standard(AnalyticView::crease(), SIZE);
    for (name, params) in [
        ("falloff", SaoParams::default()),
        (
            "Eq. 1",
            SaoParams {
                estimator: Estimator::ALCHEMY,
                ..SaoParams::default()
            },
        ),
        ("falloff, rejection", rejecting()),
    ] {
        let st = r.stages(params);
        // Face 0 is the floor, face 1 the wall.
        let floor = |img: &[f32]| profile(&r, img, |f, p| (f == 0).then_some(p.z + 4.0));
        let wall = |img: &[f32]| profile(&r, img, |f, p| (f == 1).then_some(p.y));
        assert_monotone(
            &format!("crease floor, sample pass ({name})"),
            &floor(&st.quad),
            0.9,
            0,
        );
        assert_monotone(
            &format!("crease wall, sample pass ({name})"),
            &wall(&st.quad),
            0.9,
            0,
        );
        assert_monotone(
            &format!("crease floor, final ({name})"),
            &floor(&st.ao),
            0.9,
            1,
        );
        assert_monotone(
            &format!("crease wall, final ({name})"),
            &wall(&st.ao),
            0.9,
            0,
        );
        for (i, &a) in st.ao.iter().enumerate() {
            if !r.is_geometry(i) {
                continue;
            }
            let p = r.world_point(i);
            let d = if r.raster.face[r.input_index(i)] == 0 {
                p.z + 4.0
            } else {
                p.y
            };
            if d >= 1.5 {
                assert_eq!(a, 1.0, "{name}: pixel {i} at {d} m");
            }
        }
    }
}

/// The 1 m box on the floor of the room: floor pixels in front of and beside the box (those
/// behind it border its silhouette), at least 1.5 m from the side walls, binned by their
/// horizontal distance to the box's footprint, darken monotonically toward the contact, before
/// and after the blur. Beyond `r` plus the blur's reach (0.1 m in depth, and sideways at most
/// 9 px ≈ 0.4 m at this distance) every pixel is exactly 1: from 1.5 m on.
#[test]
fn box_in_room_darkens_monotonically_toward_the_contact() {
    let r = Render::standard(AnalyticView::box_in_room(), SIZE);
    for (name, params) in [
        ("falloff", SaoParams::default()),
        ("falloff, rejection", rejecting()),
    ] {
        let st = r.stages(params);
        let distance = |p: glam::DVec3| {
            let dx = (-0.2 - p.x).max(p.x - 0.8).max(0.0);
            let dz = (-3.6 - p.z).max(p.z + 2.6).max(0.0);
            (dx * dx + dz * dz).sqrt()
        };
        // Face 2 is the room's floor.
        let near_side = |f: usize, p: glam::DVec3| {
            (f == 2 && p.z >= -3.6 && p.x.abs() <= 2.5).then(|| distance(p))
        };
        let sample = profile(&r, &st.quad, near_side);
        assert_monotone(
            &format!("box contact, sample pass ({name})"),
            &sample,
            0.6,
            0,
        );
        let bins = profile(&r, &st.ao, near_side);
        assert_monotone(&format!("box contact, final ({name})"), &bins, 0.6, 0);
        for (i, &a) in st.ao.iter().enumerate() {
            if r.is_geometry(i) {
                let face = r.raster.face[r.input_index(i)] as usize;
                if let Some(d) = near_side(face, r.world_point(i))
                    && d >= 1.5
                {
                    assert_eq!(a, 1.0, "{name}: pixel {i} at {d} m");
                }
            }
        }
    }
}

fn report(what: &str, c: &Comparison) {
    println!(
        "  {what:<28} MSE {:.4}  correlation {:.3}  (means {:.3} vs {:.3}, {} px)",
        c.mse, c.correlation, c.mean_a, c.mean_b, c.pixels
    );
}

/// Against the brute-force obscurance (`reference`): the same falloff (appendix, r = 1 m,
/// β = 1 cm, ε = 0.01 m²) with 256 rays per pixel from the exact visible point over the ball
/// (exact 3D visibility), and with 256 exact-depth samples over Eq. 5's disk (the estimator's
/// own limit), on the crease, the box in the room and the spheres. Background pixels excluded.
///
/// Measured (112 × 80 output; printed), with the paper's normals and blur: against the disk
/// limit MSE 0.0046–0.0081 and correlation 0.87–0.96; against exact visibility over the ball
/// MSE 0.025–0.053 and correlation 0.83–0.95. With the defaults (nearest-neighbour normals,
/// plane-weighted blur): against the disk limit MSE 0.0046 / 0.0056 / 0.0040 (crease, box,
/// spheres; the paper's 0.0046 / 0.0081 / 0.0058) and correlation 0.93–0.96; against the ball
/// MSE 0.028–0.060, correlation 0.80–0.92. The disk limit is what a reconstruction filter can
/// reach (the estimator's own answer without sampling noise); the ball differs from it by the
/// estimator's bias: it sees only the visible surface (no occluder behind it) and weighs
/// occluders by screen area rather than solid angle, so it is systematically lighter (mean A
/// 0.93–0.95 against 0.85–0.89), and on the spheres the wider blur correlates less with it.
///
/// Bounds: 1.25× the worst measured MSE and 0.03 below the worst correlation; the defaults'
/// MSE against the disk limit at most 1% above the paper's on any view and 10% below it over
/// the three; and a floor that does not depend
/// on the measurements: the passes must be at least 3× (disk limit) and 1.5× (ball) closer in
/// MSE than the trivial answer "no obscurance" (A ≡ 1) is. A wrong sign, scale, radius or MIP
/// level breaks both.
#[test]
fn brute_force_references() {
    let views = [
        AnalyticView::crease(),
        AnalyticView::box_in_room(),
        AnalyticView::spheres(),
    ];
    let mut totals = (0.0, 0.0);
    for view in views {
        let r = Render::standard(view, SIZE);
        let rays = CameraRays::new(&r.camera, SIZE.0, SIZE.1).unwrap();
        let rp = ReferenceParams::from_params(&SaoParams::default(), 16).unwrap();
        let ball = reference::ball_obscurance(&r.view.scene, &rays, &r.viewport, &rp);
        let disk = reference::screen_obscurance(&r.view.scene, &rays, &r.viewport, &rp);
        let ones = vec![1.0f32; ball.len()];
        let geometry = |i: usize| r.is_geometry(i);
        println!("{}:", r.view.name);
        let trivial_disk = compare(&ones, &disk, geometry);
        let trivial_ball = compare(&ones, &ball, geometry);
        report("A ≡ 1 vs disk limit", &trivial_disk);
        report("A ≡ 1 vs ball", &trivial_ball);
        report("disk limit vs ball", &compare(&disk, &ball, geometry));
        let mut disk_mse = Vec::new();
        for (name, params) in [
            ("paper", SaoParams::paper()),
            ("SAO", SaoParams::default()),
            ("SAO + rejection", rejecting()),
        ] {
            let ao = r.stages(params).ao;
            let vs_disk = compare(&ao, &disk, geometry);
            let vs_ball = compare(&ao, &ball, geometry);
            report(&format!("{name} vs disk limit"), &vs_disk);
            report(&format!("{name} vs ball"), &vs_ball);
            disk_mse.push(vs_disk.mse);
            assert!(
                vs_disk.mse <= 0.010 && vs_disk.correlation >= 0.84,
                "{name}: {vs_disk:?}"
            );
            assert!(
                vs_ball.mse <= 0.073 && vs_ball.correlation >= 0.76,
                "{name}: {vs_ball:?}"
            );
            assert!(
                vs_disk.mse * 3.0 <= trivial_disk.mse,
                "{name}: {vs_disk:?} vs {trivial_disk:?}"
            );
            assert!(
                vs_ball.mse * 1.5 <= trivial_ball.mse,
                "{name}: {vs_ball:?} vs {trivial_ball:?}"
            );
        }
        assert!(
            disk_mse[1] <= disk_mse[0] * 1.01,
            "{}: defaults {} vs paper {}",
            r.view.name,
            disk_mse[1],
            disk_mse[0]
        );
        totals.0 += disk_mse[0];
        totals.1 += disk_mse[1];
    }
    assert!(
        totals.1 < totals.0 * 0.9,
        "defaults {} vs paper {}",
        totals.1,
        totals.0
    );
}

/// The depth convention must not matter beyond its precision: the AO of the box in the room
/// from every convention, far plane and depth format (and NDC input for OpenGL) against
/// reversed-Z, infinite far, f32. Tiny z differences can move a sample across a pixel boundary
/// (Eq. 10 truncates) or a pair across the quad filter's 2 cm threshold, so a pixel may differ
/// by a sample's worth before the blur. Measured with the defaults' 13 adjacent blur taps: every
/// pixel within 0.004 (about 1/255; the worst is OpenGL window depth with a finite far plane).
/// Asserted: every pixel within 2/255, the GPU parity tolerance. With the paper's 7 taps of
/// stride 3 (and the plane weight) 99.75 % of pixels were within 2/255 and the largest
/// difference 0.166: at output pixels (30, 28–29) a quad pair's z differ by 2 cm give or take
/// the convention's precision, so the quad bilateral's hard threshold averages the pair in one
/// convention and not in the other (raw A 1.000 and 0.454 in both; after the quad filter 0.727
/// against 1.000), and 7 taps 3 px apart spread that difference where 13 adjacent taps, which
/// weigh the pair's neighbours too, dilute it below a level.
#[test]
fn conventions_agree() {
    let base = Render::standard(AnalyticView::box_in_room(), SIZE)
        .stages(SaoParams::default())
        .ao;
    for (name, projection) in projections(SIZE.0, SIZE.1) {
        if name == "ortho" {
            continue;
        }
        for convention in DepthConvention::ALL {
            for (source, format) in [
                (DepthSource::Window, DepthFormat::F32),
                (DepthSource::Window, DepthFormat::Unorm24),
                (DepthSource::Ndc, DepthFormat::F32),
            ] {
                if source == DepthSource::Ndc && convention.range() == DepthRange::ZeroToOne {
                    continue; // identical to Window
                }
                let r = Render::new(
                    AnalyticView::box_in_room(),
                    projection,
                    convention,
                    source,
                    format,
                    SIZE,
                );
                let ao = r.stages(SaoParams::default()).ao;
                let close = ao
                    .iter()
                    .zip(&base)
                    .filter(|(a, b)| (*a - *b).abs() <= 2.0 / 255.0)
                    .count();
                let worst = ao
                    .iter()
                    .zip(&base)
                    .map(|(a, b)| (a - b).abs())
                    .fold(0.0f32, f32::max);
                let share = close as f64 / ao.len() as f64;
                println!(
                    "  {name:>8} {:>10} {source:?} {format:?}: {:.3}% within 2/255, worst {worst:.3}",
                    convention_name(convention),
                    share * 100.0
                );
                assert!(
                    share == 1.0 && worst <= 2.0 / 255.0,
                    "{name} {convention:?} {source:?} {format:?}: {share}, worst {worst}"
                );
            }
        }
    }
}

/// Every pass works on independent rows, so the result is bit-identical for 1, 2 and 3 threads.
#[test]
fn bit_identical_for_any_thread_count() {
    let r = Render::standard(AnalyticView::spheres(), SIZE);
    let run = |threads| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| r.stages(rejecting()))
    };
    let one = run(1);
    for threads in [2, 3] {
        let other = run(threads);
        assert_eq!(one.hierarchy, other.hierarchy);
        assert_eq!(one.packed, other.packed);
        assert_eq!(one.horizontal, other.horizontal);
        let bits = |v: &[f32]| v.iter().map(|a| a.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&one.raw), bits(&other.raw));
        assert_eq!(bits(&one.quad), bits(&other.quad));
        assert_eq!(bits(&one.ao), bits(&other.ao));
    }
}

/// The guard band lets geometry outside the output occlude it: replacing the guard band's depth
/// with the background can only remove occluders (a sample there then contributes 0, and the
/// normalisation counts the same in-image samples), so the raw A of every output pixel can only
/// rise, and at the crease, whose wall and floor continue into the band, it must rise somewhere.
#[test]
fn guard_band_geometry_occludes_the_output() {
    let r = Render::standard(AnalyticView::crease(), SIZE);
    let sao = r.sao(SaoParams::default());
    let with = sao.stages(&r.raster.depth).unwrap().raw;
    let (w, h, g) = SIZE;
    let far = sao.z_constants().far_depth;
    let cleared: Vec<f32> = r
        .raster
        .depth
        .iter()
        .enumerate()
        .map(|(i, &d)| {
            let (x, y) = (i % w, i / w);
            if x < g || y < g || x >= w - g || y >= h - g {
                far
            } else {
                d
            }
        })
        .collect();
    let without = sao.stages(&cleared).unwrap().raw;
    assert!(with.iter().zip(&without).all(|(a, b)| a <= b));
    let raised = with.iter().zip(&without).filter(|(a, b)| a < b).count();
    println!("{raised} output pixels lose occlusion without the guard band");
    assert!(raised > 20);
}

/// `run` writes exactly the final image of `stages`; without the quad filter `quad == raw`.
#[test]
fn run_matches_stages() {
    let r = Render::standard(AnalyticView::box_in_room(), SIZE);
    let sao = r.sao(SaoParams::default());
    let mut ao = vec![0.0; r.viewport.output_len()];
    sao.run(&r.raster.depth, &mut ao).unwrap();
    assert_eq!(ao, sao.stages(&r.raster.depth).unwrap().ao);
    let st = r.stages(SaoParams {
        quad_depth_threshold: None,
        ..SaoParams::default()
    });
    assert_eq!(st.quad, st.raw);
    assert!(st.ao.iter().all(|a| (0.0..=1.0).contains(a)));
}

/// Snapshots of the final AO (2×2 block means quantised to u8, as hex) of the analytic views
/// with reversed-Z infinite-far f32 depth, so any change to a pass shows up in review.
#[test]
fn snapshots() {
    for view in [
        AnalyticView::crease(),
        AnalyticView::box_in_room(),
        AnalyticView::spheres(),
    ] {
        let r = Render::standard(view, SIZE);
        let st = r.stages(SaoParams::default());
        insta::assert_snapshot!(r.view.name, hex_grid(&st.ao, r.viewport.output_width()));
    }
    let r = Render::standard(AnalyticView::box_in_room(), SIZE);
    let st = r.stages(SaoParams {
        estimator: Estimator::ALCHEMY,
        ..rejecting()
    });
    insta::assert_snapshot!(
        "box_in_room_eq1_rejection",
        hex_grid(&st.ao, r.viewport.output_width())
    );
}

/// The depth-buffer reference (`reference::buffer_obscurance`, for frames known only by their
/// depth) converges to the exact-depth one (`screen_obscurance`) on the analytic views: both
/// take 256 samples over Eq. 5's disk with the same falloff, and differ only where the buffer
/// snaps each sample to its texel and estimates the normal from its neighbours. Measured
/// (printed): MSE 0.0001 / 0.0007 / 0.0005 (crease, box, spheres) and correlation
/// 0.990–0.999 between the two, an order of magnitude closer than any pass is to either (MSE
/// 0.004–0.008 above). Bounds: MSE 0.0015, correlation 0.95. With the normal facing away from
/// the eye (a sign error) the crease gives MSE 0.049 and fails.
#[test]
fn the_depth_buffer_reference_converges_to_the_exact_one() {
    for view in [
        AnalyticView::crease(),
        AnalyticView::box_in_room(),
        AnalyticView::spheres(),
    ] {
        let r = Render::standard(view, SIZE);
        let (iw, ih) = (r.viewport.input_width(), r.viewport.input_height());
        let rays = CameraRays::new(&r.camera, iw, ih).unwrap();
        let rp = ReferenceParams::from_params(&SaoParams::default(), 16).unwrap();
        let exact = reference::screen_obscurance(&r.view.scene, &rays, &r.viewport, &rp);
        let positions = reference::view_positions(&r.camera, &r.raster.depth, iw, ih);
        let buffer = reference::buffer_obscurance(&positions, &rays, &r.viewport, &rp);
        let c = compare(&buffer, &exact, |i| r.is_geometry(i));
        report(&format!("{}: depth buffer vs exact depth", r.view.name), &c);
        assert!(
            c.mse <= 0.0015 && c.correlation >= 0.95,
            "{}: {c:?}",
            r.view.name
        );
    }
}
