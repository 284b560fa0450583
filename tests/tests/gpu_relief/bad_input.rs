//! Bad input: every refusal of the renderer, the generator and the probe.

use super::*;

/// A device on the test's adapter with exactly WebGPU's downlevel limits.
fn downlevel_context() -> GpuContext {
    let instance =
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    let adapter =
        pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default()))
            .unwrap();
    let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        required_limits: wgpu::Limits::downlevel_defaults(),
        ..Default::default()
    }))
    .unwrap();
    GpuContext::from_device(device, queue)
}

fn input<T>(r: Result<T, GpuError>) -> bool {
    matches!(r, Err(GpuError::InvalidInput { .. }))
}

fn relief<T>(r: Result<T, GpuError>) -> bool {
    matches!(r, Err(GpuError::Relief(_)))
}

fn resource<T>(r: Result<T, GpuError>) -> bool {
    matches!(r, Err(GpuError::InvalidResource { .. }))
}

/// Bad input is an error, never a panic, and nothing is drawn.
#[test]
fn bad_input_is_refused() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let setup = Setup::new(Method::ConeStep { steps: 8 });
    let (_, camera) = cameras().remove(0);
    let mut renderer = ReliefRenderer::new(&ctx, Default::default()).unwrap();
    // No texture yet.
    assert!(matches!(
        renderer.render_image(&ctx, &camera, &setup.scene, 8, 8),
        Err(GpuError::NotConfigured { .. })
    ));
    assert!(matches!(
        renderer.probe(&ctx, &Method::ConeStep { steps: 1 }, &[]),
        Err(GpuError::NotConfigured { .. })
    ));
    renderer.set_texture(&ctx, &setup.texture).unwrap();

    // Scenes.
    let bad = |f: fn(&mut ReliefScene)| {
        let mut s = setup.scene;
        f(&mut s);
        renderer.render_image(&ctx, &camera, &s, 8, 8)
    };
    assert!(input(bad(|s| s.depth = f64::NAN)));
    assert!(input(bad(|s| s.depth = -0.1)));
    assert!(input(bad(|s| s.origin.x = f64::INFINITY)));
    assert!(
        input(bad(|s| s.edge_v = DVec3::new(0.5, 0.0, -2.0))),
        "not orthogonal"
    );
    assert!(
        input(bad(|s| s.tiles = DVec2::new(2.0, 3.0))),
        "texels not square"
    );
    assert!(input(bad(|s| s.edge_u = DVec3::ZERO)));
    assert!(input(bad(|s| s.light_dir = DVec3::ZERO)));
    assert!(input(bad(|s| s.light_dir.y = f64::NAN)));
    assert!(input(bad(|s| s.albedo[1] = f32::NAN)));
    assert!(input(bad(|s| s.ambient = -1.0)));
    assert!(relief(bad(|s| s.shadow_bias = f32::NAN)));
    assert!(relief(bad(|s| s.shadow_bias = 2.0)));
    assert!(relief(bad(|s| s.method = Method::ConeStep { steps: 0 })));
    assert!(relief(bad(|s| {
        s.method = Method::Linear {
            linear: 4,
            binary: 5000,
        }
    })));
    // Viewports and targets.
    assert!(input(renderer.render_image(
        &ctx,
        &camera,
        &setup.scene,
        0,
        8
    )));
    assert!(input(renderer.render_image(
        &ctx,
        &camera,
        &setup.scene,
        8,
        1 << 20
    )));
    let device = ctx.device();
    let target = |w, h, format| {
        device
            .create_texture(&wgpu::TextureDescriptor {
                label: None,
                size: wgpu::Extent3d {
                    width: w,
                    height: h,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                view_formats: &[],
            })
            .create_view(&Default::default())
    };
    let c16 = target(16, 16, wgpu::TextureFormat::Rgba8Unorm);
    let d16 = target(16, 16, wgpu::TextureFormat::Depth32Float);
    let d8 = target(8, 8, wgpu::TextureFormat::Depth32Float);
    let c16_float = target(16, 16, wgpu::TextureFormat::Rgba16Float);
    let mut encoder = device.create_command_encoder(&Default::default());
    let s = &setup.scene;
    assert!(resource(renderer.render(
        &ctx,
        &mut encoder,
        &camera,
        s,
        &c16,
        &d8,
        (16, 16)
    )));
    assert!(resource(renderer.render(
        &ctx,
        &mut encoder,
        &camera,
        s,
        &c16_float,
        &d16,
        (16, 16)
    )));
    assert!(resource(renderer.render(
        &ctx,
        &mut encoder,
        &camera,
        s,
        &d16,
        &d16,
        (16, 16)
    )));
    renderer
        .render(&ctx, &mut encoder, &camera, s, &c16, &d16, (16, 16))
        .unwrap();
    ctx.queue().submit([encoder.finish()]);

    // A texture wider than the device's largest 2D texture: on a device with WebGPU's
    // downlevel limits (2048; the headless context takes the adapter's larger one), a 2049²
    // relief texture.
    let small = downlevel_context();
    let side = small.device().limits().max_texture_dimension_2d as usize + 1;
    assert_eq!(side, 2049);
    let flat = HeightMap::from_depths(
        side,
        side,
        &vec![0.5; side * side],
        Edge::Wrap,
        Default::default(),
    )
    .unwrap();
    let none = ConeMap::from_ratios(side, Edge::Wrap, vec![0.0; side * side]).unwrap();
    let big = ReliefTexture::new(&flat, &none).unwrap();
    let mut small_renderer = ReliefRenderer::new(&small, Default::default()).unwrap();
    assert!(matches!(
        small_renderer.set_texture(&small, &big),
        Err(GpuError::TooLarge {
            needed: 2049,
            limit: 2048,
            ..
        })
    ));

    // Probe rays.
    let ok = ReliefRay {
        start: Vec2::new(0.5, 0.5),
        view: Vec3::new(0.3, 0.0, -1.0),
        depth_scale: 0.1,
        point: Vec3::new(0.5, 0.5, 0.2),
        light: Vec3::new(0.0, 0.5, 1.0),
        bias: 0.01,
        ..Default::default()
    };
    let m = Method::ConeStep { steps: 8 };
    assert_eq!(renderer.probe(&ctx, &m, &[ok]).unwrap().len(), 1);
    for r in [
        ReliefRay {
            start: Vec2::new(f32::NAN, 0.0),
            ..ok
        },
        ReliefRay {
            view: Vec3::new(0.0, 0.0, 1.0),
            ..ok
        },
        ReliefRay {
            depth_scale: -1.0,
            ..ok
        },
        ReliefRay {
            bias: f32::NAN,
            ..ok
        },
        ReliefRay {
            light: Vec3::new(0.0, f32::INFINITY, 1.0),
            ..ok
        },
        ReliefRay {
            footprint: [Vec2::new(f32::NAN, 0.0), Vec2::ZERO],
            ..ok
        },
    ] {
        assert!(input(renderer.probe(&ctx, &m, &[r])), "{r:?}");
    }
    assert!(input(renderer.probe(&ctx, &m, &[])));
    assert!(relief(renderer.probe(
        &ctx,
        &Method::ConeStep { steps: 0 },
        &[ok]
    )));

    // Cone map generation.
    let generator = ConeMapGenerator::new(&ctx).unwrap();
    for cap in [f32::NAN, 0.0, -1.0, 65.0] {
        assert!(
            matches!(
                generator.generate(&ctx, &setup.map, ConeParams::relaxed(cap).with_parts(0)),
                Err(GpuError::Relief(
                    ReliefError::NotFinite(_) | ReliefError::OutOfRange { .. }
                ))
            ),
            "{cap}"
        );
    }
    // The GPU bounds whole cells: a finer bound (the CPU's default) is refused, for both kinds
    // of map, rather than answered with other cones.
    for p in [
        ConeParams::relaxed(1.0),
        ConeParams::conservative(1.0).with_parts(1),
    ] {
        assert!(
            matches!(
                generator.generate(&ctx, &setup.map, p),
                Err(GpuError::Relief(ReliefError::Unsupported(_)))
            ),
            "{p:?}"
        );
        assert!(matches!(
            generator.generate_quad(&ctx, &setup.map, p),
            Err(GpuError::Relief(ReliefError::Unsupported(_)))
        ));
    }
    // A clamp-mode map whose cell buffer exceeds the device's largest storage binding.
    let limit = device.limits().max_storage_buffer_binding_size;
    let side = ((limit / 32) as f64).sqrt() as usize + 1;
    let flat = HeightMap::from_depths(
        side,
        side,
        &vec![0.5; side * side],
        Edge::Clamp,
        Default::default(),
    )
    .unwrap();
    assert!(matches!(
        generator.generate(&ctx, &flat, ConeParams::relaxed(1.0).with_parts(0)),
        Err(GpuError::TooLarge { .. })
    ));
}
