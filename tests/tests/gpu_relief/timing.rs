//! The draw time of a relief-mapped quad (ignored by default).

use super::*;

/// Draw time of a 640 × 480 view of the quad (relaxed 15 + 6, with and without self-shadowing),
/// averaged over 5 draws after a first one, each waited for, and the share of the pixels the
/// quad covers (printed; not run by default:
/// `cargo test -p ocean-tests --test gpu_relief -- --ignored`).
#[test]
#[ignore]
fn draw_time() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let setup = Setup::new(Method::Relaxed {
        cone: 15,
        binary: 6,
        search: BinarySearch::LastStep,
    });
    let camera = Camera::look_at(
        DVec3::new(0.0, 1.2, 0.6),
        DVec3::new(0.0, -0.05, 0.0),
        DVec3::Y,
        Projection::Perspective {
            fov_y: 1.0,
            aspect: 4.0 / 3.0,
            near: 0.1,
            far: Far::Finite(20.0),
        },
        DepthConvention::ZERO_TO_ONE,
    )
    .unwrap();
    let mut renderer = ReliefRenderer::new(&ctx, Default::default()).unwrap();
    renderer.set_texture(&ctx, &setup.texture).unwrap();
    let device = ctx.device();
    let texture = |format| {
        texture_2d(
            &ctx,
            (640, 480),
            format,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        )
    };
    let color = texture(wgpu::TextureFormat::Rgba8Unorm).create_view(&Default::default());
    let depth = texture(wgpu::TextureFormat::Depth32Float).create_view(&Default::default());
    for shadows in [false, true] {
        let scene = ReliefScene {
            shadows,
            ..setup.scene
        };
        let mut times = Vec::new();
        for _ in 0..6 {
            let t = Instant::now();
            let mut encoder = device.create_command_encoder(&Default::default());
            // Clear to black and the far plane, as a frame would.
            encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: None,
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &color,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &depth,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(1.0),
                        store: wgpu::StoreOp::Store,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            renderer
                .render(
                    &ctx,
                    &mut encoder,
                    &camera,
                    &scene,
                    &color,
                    &depth,
                    (640, 480),
                )
                .unwrap();
            ctx.queue().submit([encoder.finish()]);
            ctx.wait_idle().unwrap();
            times.push(t.elapsed());
        }
        let mean = times[1..].iter().sum::<std::time::Duration>() / 5;
        let image = renderer
            .render_image(&ctx, &camera, &scene, 640, 480)
            .unwrap();
        let covered = image.depth.iter().filter(|&&d| d < 1.0).count();
        eprintln!(
            "640 x 480 draw, shadows {shadows}: {mean:?} ({:.1}% of the pixels on the quad) on {}",
            100.0 * covered as f64 / (640.0 * 480.0),
            ctx.describe()
        );
    }
}
