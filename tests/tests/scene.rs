//! The scene renderer of `ocean_scene` on the caller's device: a frame drawn into the caller's
//! texture ([`SceneRenderer::render_into`]) holds the bytes of the frame read back
//! ([`SceneRenderer::frame`]), bit for bit (the same passes on the same device); a target of
//! another format or size, a depth read the renderer was not built for, and a time that is not
//! finite are errors, not panics.
//!
//! Run with `OCEAN_REQUIRE_GPU=1` to turn a missing adapter into a failure.

use ocean_gpu::{GpuContext, GpuError, wgpu};
use ocean_scene::renderer::RenderOptions;
use ocean_scene::{COLOR_FORMAT, DEFAULT_SCENE, SceneDescription, SceneError, SceneRenderer};
use ocean_tests::gpu_context_or_skip;

const SIZE: (u32, u32) = (96, 54);

/// The built-in scene at [`SIZE`], one sample per pixel, on `ctx`.
fn renderer(ctx: &GpuContext) -> SceneRenderer {
    let mut scene = SceneDescription::parse(DEFAULT_SCENE, "built-in").expect("the built-in scene");
    (scene.render.width, scene.render.height) = SIZE;
    let options = RenderOptions {
        samples: Some(1),
        ..RenderOptions::default()
    };
    SceneRenderer::with_context(ctx.clone(), &scene, options).expect("the scene builds")
}

fn target(ctx: &GpuContext, format: wgpu::TextureFormat, size: (u32, u32)) -> wgpu::Texture {
    ctx.device().create_texture(&wgpu::TextureDescriptor {
        label: Some("caller's target"),
        size: wgpu::Extent3d {
            width: size.0,
            height: size.1,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    })
}

fn view(t: &wgpu::Texture) -> wgpu::TextureView {
    t.create_view(&wgpu::TextureViewDescriptor::default())
}

#[test]
fn a_frame_into_the_callers_texture_is_the_frame_read_back() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let mut r = renderer(&ctx);
    let read_back = r.frame(1.5, false).expect("frame");
    let texture = target(&ctx, COLOR_FORMAT, SIZE);
    let (camera, _) = r.render_into(1.5, &view(&texture)).expect("render_into");
    let drawn = ocean_gpu::readback::read_texture(&ctx, &texture, 0)
        .expect("read the caller's texture")
        .data;
    assert_eq!(camera, read_back.camera);
    assert_eq!(drawn.len(), read_back.rgba.len());
    let differing = drawn
        .iter()
        .zip(&read_back.rgba)
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(
        differing,
        0,
        "{differing} bytes differ on {}",
        ctx.describe()
    );
    // Not a blank image: the sea, the island and the sky differ.
    let first = &drawn[..4];
    assert!(drawn.chunks_exact(4).filter(|p| *p != first).count() > drawn.len() / 16);

    // A larger target: the frame in its top-left corner, the rest cleared to opaque black.
    let (w, h) = (SIZE.0 + 8, SIZE.1 + 4);
    let large = target(&ctx, COLOR_FORMAT, (w, h));
    r.render_into(1.5, &view(&large))
        .expect("render_into a larger target");
    let big = ocean_gpu::readback::read_texture(&ctx, &large, 0)
        .expect("read the larger target")
        .data;
    for y in 0..h as usize {
        for x in 0..w as usize {
            let px = &big[4 * (y * w as usize + x)..][..4];
            if x < SIZE.0 as usize && y < SIZE.1 as usize {
                let k = 4 * (y * SIZE.0 as usize + x);
                assert_eq!(px, &read_back.rgba[k..k + 4], "pixel ({x}, {y})");
            } else {
                assert_eq!(px, [0, 0, 0, 255], "pixel ({x}, {y}) outside the frame");
            }
        }
    }
}

#[test]
fn bad_targets_and_times_are_errors() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let mut r = renderer(&ctx);
    let refused = |e: Result<_, SceneError>| {
        matches!(e, Err(SceneError::Gpu(GpuError::InvalidResource { .. })))
    };
    let srgb = target(&ctx, wgpu::TextureFormat::Rgba8UnormSrgb, SIZE);
    assert!(refused(r.render_into(1.5, &view(&srgb))), "another format");
    let small = target(&ctx, COLOR_FORMAT, (SIZE.0 - 1, SIZE.1));
    assert!(refused(r.render_into(1.5, &view(&small))), "another size");
    assert!(
        matches!(r.frame(1.5, true), Err(SceneError::Unsupported(_))),
        "depth without RenderOptions::read_depth"
    );
    for t in [f64::NAN, f64::INFINITY] {
        assert!(r.frame(t, false).is_err(), "time {t}");
    }
    // The renderer stays usable.
    assert!(r.frame(1.5, false).is_ok());
}
