//! The analytic scenes, depth conventions, MIP filters and levels, options and guard bands
//! against the CPU.

use super::*;

/// Every analytic scene, reversed Z with the appendix's falloff and forward Z (finite far
/// plane) with Eq. 1.
#[test]
fn analytic_scenes_match_the_cpu() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let mut pass = SaoPass::new(&ctx).unwrap();
    for view in AnalyticView::all() {
        let occludes = view.name != "open_plane";
        let falloff = check(
            &ctx,
            &mut pass,
            &Case::standard(view.clone(), SaoParams::default(), "reversed Z, falloff"),
        );
        let alchemy = check(
            &ctx,
            &mut pass,
            &Case::new(
                view.clone(),
                perspective(SIZE.0, SIZE.1, Far::Finite(100.0)),
                DepthConvention::ZERO_TO_ONE,
                DepthSource::Window,
                DepthFormat::F32,
                SIZE,
                SaoParams {
                    estimator: Estimator::ALCHEMY,
                    ..SaoParams::default()
                },
                "forward Z, finite far, Eq. 1",
            ),
        );
        // The scenes with contacts darken somewhere, so the comparison, which holds every
        // stage to the CPU's bits, covers real obscurance: the sample pass's darkest A is
        // below 0.8 (measured 0.00 with the falloff, 0.46–0.67 with Eq. 1; after the default
        // 13-tap blur 0.11–0.26 and 0.74–0.80, where the paper's 7 taps left 0.00–0.19 and
        // 0.61–0.75). The open plane occludes nothing (A = 1 everywhere, as on the CPU).
        println!(
            "{}: darkest A falloff {:.3}, Eq. 1 {:.3} (raw {:.3}, {:.3})",
            view.name, falloff.darkest, alchemy.darkest, falloff.darkest_raw, alchemy.darkest_raw
        );
        for r in [falloff, alchemy] {
            if occludes {
                assert!(
                    r.darkest_raw < 0.8,
                    "{}: darkest raw A {}",
                    view.name,
                    r.darkest_raw
                );
            } else {
                assert_eq!(r.darkest, 1.0, "open plane");
            }
        }
    }
}

/// The other depth conventions and sources, an orthographic camera, 24-bit depth values.
#[test]
fn depth_conventions_match_the_cpu() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let mut pass = SaoPass::new(&ctx).unwrap();
    let (w, h, _) = SIZE;
    let cases = [
        (
            perspective(w, h, Far::Finite(100.0)),
            DepthConvention::NEG_ONE_TO_ONE,
            DepthSource::Window,
            DepthFormat::F32,
            "[-1,1] window depth, finite far",
        ),
        (
            perspective(w, h, Far::Infinite),
            DepthConvention::NEG_ONE_TO_ONE,
            DepthSource::Ndc,
            DepthFormat::F32,
            "[-1,1] NDC depth, infinite far",
        ),
        (
            perspective(w, h, Far::Finite(100.0)),
            DepthConvention::ZERO_TO_ONE_REVERSED,
            DepthSource::Window,
            DepthFormat::F32,
            "reversed Z, finite far",
        ),
        (
            perspective(w, h, Far::Infinite),
            DepthConvention::ZERO_TO_ONE,
            DepthSource::Window,
            DepthFormat::Unorm24,
            "forward Z, infinite far, 24-bit depth",
        ),
        (
            orthographic(w, h),
            DepthConvention::ZERO_TO_ONE_REVERSED,
            DepthSource::Window,
            DepthFormat::F32,
            "orthographic, reversed Z",
        ),
        (
            orthographic(w, h),
            DepthConvention::NEG_ONE_TO_ONE,
            DepthSource::Window,
            DepthFormat::Unorm24,
            "orthographic, [-1,1], 24-bit depth",
        ),
    ];
    for (projection, convention, source, format, what) in cases {
        let r = check(
            &ctx,
            &mut pass,
            &Case::new(
                AnalyticView::box_in_room(),
                projection,
                convention,
                source,
                format,
                SIZE,
                SaoParams::default(),
                what,
            ),
        );
        assert!(r.darkest < 0.7, "{what}: darkest A {}", r.darkest);
    }
}

/// Every MIP filter of Table 1, no hierarchy at all (every sample from level 0), the full
/// hierarchy (13 levels requested, cut at 1 × 1), and a radius large enough that the samples
/// reach the coarsest levels.
#[test]
fn mip_filters_and_levels_match_the_cpu() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let mut pass = SaoPass::new(&ctx).unwrap();
    for filter in MipFilter::ALL {
        for (radius, max_mip) in [(1.0, 5), (4.0, 13)] {
            let params = SaoParams {
                mip_filter: filter,
                radius,
                max_mip,
                ..SaoParams::default()
            };
            let r = check(
                &ctx,
                &mut pass,
                &Case::standard(
                    AnalyticView::spheres(),
                    params,
                    &format!("{}, r = {radius} m, max_mip {max_mip}", filter.name()),
                ),
            );
            // 160 × 120 halves 7 times to 1 × 1.
            assert_eq!(r.levels.len(), if max_mip == 13 { 8 } else { 6 });
        }
    }
    let r = check(
        &ctx,
        &mut pass,
        &Case::standard(
            AnalyticView::box_in_room(),
            SaoParams {
                max_mip: 0,
                radius: 4.0,
                ..SaoParams::default()
            },
            "max_mip 0 (no hierarchy), r = 4 m",
        ),
    );
    assert_eq!(r.levels.len(), 1);
}

/// The options around the sample pass and the blur: Eq. 1 with k = 2 (the `pow` path), the
/// normal rejection, no quad bilateral, the released shader's blur (9 taps, stride 2, 2000),
/// the paper's quad normals and depth-keyed blur, the plane weight without its fade, the widest
/// blur (63 taps), a spiral of 30 samples, q' = 1 and q' = 256.
#[test]
fn options_match_the_cpu() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let mut pass = SaoPass::new(&ctx).unwrap();
    let variants = [
        (
            SaoParams {
                estimator: Estimator::Alchemy {
                    sigma: 0.4,
                    beta: 2.0e-3,
                    k: 2.0,
                },
                ..SaoParams::default()
            },
            "Eq. 1 with k = 2",
        ),
        (
            SaoParams {
                normal_rejection: Some(NormalRejection {
                    max_incidence: 80f32.to_radians(),
                }),
                quad_depth_threshold: None,
                ..SaoParams::default()
            },
            "normal rejection, no quad bilateral",
        ),
        (
            SaoParams {
                blur: BlurParams {
                    taps: 9,
                    stride: 2,
                    depth_scale: 2000.0,
                    sigma: 2.0,
                    ..BlurParams::default()
                },
                ..SaoParams::default()
            },
            "blur 9 taps, stride 2, scale 2000",
        ),
        (SaoParams::paper(), "the paper's normals and blur weight"),
        (
            SaoParams {
                blur: BlurParams {
                    world_extent: 0.0,
                    ..BlurParams::default()
                },
                ..SaoParams::default()
            },
            "plane weight without the world fade",
        ),
        (
            SaoParams {
                blur: BlurParams {
                    taps: 63,
                    stride: 1,
                    ..BlurParams::default()
                },
                ..SaoParams::default()
            },
            "blur 63 taps",
        ),
        (
            SaoParams {
                samples: 30,
                spiral_turns: ocean_sao::spiral::default_spiral_turns(30) as f32,
                mip_switch_log2: 0,
                ..SaoParams::default()
            },
            "30 samples, q' = 1",
        ),
        (
            SaoParams {
                mip_switch_log2: 8,
                radius: 2.0,
                ..SaoParams::default()
            },
            "q' = 256, r = 2 m",
        ),
    ];
    for (params, what) in variants {
        check(
            &ctx,
            &mut pass,
            &Case::standard(AnalyticView::crease(), params, what),
        );
    }
}

/// Guard bands: none on an odd-sized image (quad partners and MIP children fall off the
/// image), a 1-pixel one, and one that leaves a single output column.
#[test]
fn guard_bands_match_the_cpu() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let mut pass = SaoPass::new(&ctx).unwrap();
    for (w, h, guard) in [(97, 75, 0), (96, 64, 1), (81, 96, 40)] {
        let r = check(
            &ctx,
            &mut pass,
            &Case::new(
                AnalyticView::box_in_room(),
                perspective(w, h, Far::Infinite),
                DepthConvention::ZERO_TO_ONE_REVERSED,
                DepthSource::Window,
                DepthFormat::F32,
                (w, h, guard),
                SaoParams::default(),
                "guard band",
            ),
        );
        assert_eq!(r.ao.n, (w - 2 * guard) * (h - 2 * guard));
    }
}
