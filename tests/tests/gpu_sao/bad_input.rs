//! Bad input: every refusal of the pass.

use super::*;

/// Bad input is an error, never a panic, and leaves the pass usable.
#[test]
fn bad_input_is_an_error() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let mut pass = SaoPass::new(&ctx).unwrap();
    let case = Case::standard(AnalyticView::crease(), SaoParams::default(), "errors");
    let (w, h) = (SIZE.0 as u32, SIZE.1 as u32);
    let device = ctx.device();
    let texture = |size: (u32, u32), format, usage| {
        device.create_texture(&wgpu::TextureDescriptor {
            label: None,
            size: wgpu::Extent3d {
                width: size.0,
                height: size.1,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage,
            view_formats: &[],
        })
    };
    let sampled = wgpu::TextureUsages::TEXTURE_BINDING;
    let r32 = wgpu::TextureFormat::R32Float;
    let bad = [
        (texture((w - 2, h), r32, sampled), "size"),
        (texture((w, h + 1), r32, sampled), "size"),
        (
            texture((w, h), wgpu::TextureFormat::Rgba8Unorm, sampled),
            "format",
        ),
        (
            texture((w, h), wgpu::TextureFormat::R16Float, sampled),
            "format",
        ),
        (texture((w, h), r32, wgpu::TextureUsages::COPY_DST), "usage"),
    ];
    for (t, what) in &bad {
        let mut encoder = device.create_command_encoder(&Default::default());
        let e = pass
            .encode(&ctx, &mut encoder, &case.sao, t, None)
            .unwrap_err();
        println!("{what}: {e}");
        assert!(
            matches!(e, GpuError::InvalidResource { .. }),
            "{what}: {e:?}"
        );
    }

    // A depth slice of the wrong length, with NaN, out of the range: the CPU's errors.
    let mut depth = case.raster.depth.clone();
    let short = &depth[1..];
    let cpu_err = case
        .sao
        .run(short, &mut vec![0.0; case.sao.viewport().output_len()]);
    let gpu_err = pass.evaluate(&ctx, &case.sao, short).unwrap_err();
    assert!(
        matches!(gpu_err, GpuError::Sao(SaoError::BufferSize { .. })),
        "{gpu_err:?}"
    );
    assert_eq!(Err(gpu_sao_error(gpu_err)), cpu_err);
    for (i, v) in [(517, f32::NAN), (2049, 1.5), (3000, -0.25)] {
        let keep = depth[i];
        depth[i] = v;
        let cpu = case.sao.stages(&depth).unwrap_err();
        let gpu = pass.evaluate(&ctx, &case.sao, &depth).unwrap_err();
        println!("depth {v} at {i}: {gpu}");
        assert_eq!(gpu_sao_error(gpu), cpu);
        depth[i] = keep;
    }

    // A guard band that leaves no output cannot even make a set-up; `?` turns it into a
    // GpuError.
    let guard = || -> Result<Sao, GpuError> {
        let viewport = Viewport::new(64, 48, 24)?;
        let camera = AnalyticView::crease()
            .camera(
                perspective(64, 48, Far::Infinite),
                DepthConvention::ZERO_TO_ONE_REVERSED,
            )
            .map_err(GpuError::Sao)?;
        Ok(Sao::from_camera(
            &camera,
            DepthSource::Window,
            viewport,
            SaoParams::default(),
        )?)
    };
    let e = guard().unwrap_err();
    assert!(
        matches!(e, GpuError::Sao(SaoError::GuardBand { guard: 24, .. })),
        "{e:?}"
    );

    // An input beyond the device's largest texture.
    let max = device.limits().max_texture_dimension_2d as usize;
    if max < ocean_sao::MAX_SIDE {
        let (bw, bh) = (max + 2, 8);
        let camera = AnalyticView::crease()
            .camera(
                perspective(bw, bh, Far::Infinite),
                DepthConvention::ZERO_TO_ONE_REVERSED,
            )
            .unwrap();
        let big = Sao::from_camera(
            &camera,
            DepthSource::Window,
            Viewport::new(bw, bh, 1).unwrap(),
            SaoParams::default(),
        )
        .unwrap();
        let e = pass.evaluate(&ctx, &big, &vec![0.5; bw * bh]).unwrap_err();
        println!("{bw} x {bh}: {e}");
        assert!(matches!(e, GpuError::TooLarge { .. }), "{e:?}");
    }

    // Still usable, with the same result as before the errors.
    let ao = pass.evaluate(&ctx, &case.sao, &case.raster.depth).unwrap();
    assert_eq!(ao, case.sao.stages(&case.raster.depth).unwrap().ao);
}

fn gpu_sao_error(e: GpuError) -> SaoError {
    match e {
        GpuError::Sao(e) => e,
        other => panic!("expected an SAO error, got {other:?}"),
    }
}
