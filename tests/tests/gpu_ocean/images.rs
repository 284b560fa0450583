//! Headless renders: the reference image, depth conventions and targets, and drawing into the
//! caller's targets.

use super::*;

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
