//! Any guard band gives the interior an aligned one gives.

use super::*;

/// Any guard band gives the interior an aligned one gives, on the GPU as on the CPU
/// (`ocean-sao/tests/guard.rs`, the same scene and comparison): every guard band from 0 to
/// 300 px against the multiple of 32 below it, within 1/255 on every interior pixel, with the
/// z levels anchored at the guard band modulo 32 (`SaoUniforms::mip_origin`).
#[test]
fn any_guard_band_gives_the_aligned_interior() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let mut pass = SaoPass::new(&ctx).unwrap();
    const OUT: (usize, usize) = (128, 80);
    const MARGIN: usize = 25;
    let mut interior = |g: usize| -> Vec<f32> {
        let (w, h) = (OUT.0 + 2 * g, OUT.1 + 2 * g);
        let v = AnalyticView::boxes(0.6, 0.7, 8.5);
        let camera = v
            .camera(
                guarded_perspective(OUT, g, 1.0),
                DepthConvention::ZERO_TO_ONE_REVERSED,
            )
            .unwrap();
        let raster = v
            .scene
            .rasterise(&camera, w, h, DepthSource::Window, DepthFormat::F32)
            .unwrap();
        let params = SaoParams {
            mip_switch_log2: 0,
            ..SaoParams::default()
        };
        let viewport = Viewport::new(w, h, g).unwrap();
        let sao = Sao::from_camera(&camera, DepthSource::Window, viewport, params).unwrap();
        let ao = pass.evaluate(&ctx, &sao, &raster.depth).unwrap();
        (MARGIN..OUT.1 - MARGIN)
            .flat_map(|y| (MARGIN..OUT.0 - MARGIN).map(move |x| y * OUT.0 + x))
            .map(|i| ao[i])
            .collect()
    };
    let (worst, g) = worst_against_aligned(300, 32, &mut interior);
    println!(
        "worst interior difference: {:.2}/255 at g = {g}",
        worst * 255.0
    );
    assert!(worst <= 1.0 / 255.0, "{}/255 at g = {g}", worst * 255.0);
    assert!(
        interior(0).iter().any(|&a| a < 0.8),
        "the interior holds obscurance"
    );
}
