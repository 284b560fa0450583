//! Bad input: every error path, and extreme views that must never leave a pixel unlit.

use super::*;

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

/// The bad-input rule for views: grazing, vertical, tiny and huge altitudes, far from
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
