//! Large hash values, the caller's depth textures (float and fixed point) against the CPU.

use super::*;

/// Eq. 8's hash reaches 2²⁴ (its fourth byte, reduced with `HASH_BYTE_TURNS[3]`) only where
/// `10·x·y` does, beyond the small images above: a 1400 × 1300 view (hash up to 1.8·10⁷)
/// checks that byte's reduction.
#[test]
fn large_hash_values_match_the_cpu() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let mut pass = SaoPass::new(&ctx).unwrap();
    let (w, h) = (1400, 1300);
    assert!(ocean_sao::spiral::hash(w as u32 - 1, h as u32 - 1) >= 1 << 24);
    check(
        &ctx,
        &mut pass,
        &Case::new(
            AnalyticView::box_in_room(),
            perspective(w, h, Far::Infinite),
            DepthConvention::ZERO_TO_ONE_REVERSED,
            DepthSource::Window,
            DepthFormat::F32,
            (w, h, 0),
            SaoParams::default(),
            "hash above 2^24",
        ),
    );
}

/// A fragment shader that writes an `R32Float` texture into a depth attachment through
/// `frag_depth`: the way to fill a Depth32Float texture with chosen values (WebGPU allows no
/// copies into it).
const DEPTH_WRITER: &str = "
@group(0) @binding(0) var src: texture_2d<f32>;
@vertex fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    let uv = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));
    return vec4<f32>(uv * 2.0 - 1.0, 0.5, 1.0);
}
@fragment fn fs(@builtin(position) p: vec4<f32>) -> @builtin(frag_depth) f32 {
    return textureLoad(src, vec2<i32>(p.xy), 0).x;
}
";

/// A `format` depth texture (`TEXTURE_BINDING | RENDER_ATTACHMENT`) of `w × h` holding `depth`.
fn depth_texture(
    ctx: &GpuContext,
    depth: &[f32],
    (w, h): (u32, u32),
    format: wgpu::TextureFormat,
) -> wgpu::Texture {
    let device = ctx.device();
    let size = wgpu::Extent3d {
        width: w,
        height: h,
        depth_or_array_layers: 1,
    };
    let src = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("depth values"),
        size,
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::R32Float,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    ctx.queue().write_texture(
        src.as_image_copy(),
        bytemuck::cast_slice(depth),
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(4 * w),
            rows_per_image: Some(h),
        },
        size,
    );
    let target = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("depth buffer"),
        size,
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::RENDER_ATTACHMENT,
        view_formats: &[],
    });
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("depth writer"),
        source: wgpu::ShaderSource::Wgsl(DEPTH_WRITER.into()),
    });
    let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("depth writer"),
        layout: None,
        vertex: wgpu::VertexState {
            module: &module,
            entry_point: Some("vs"),
            compilation_options: Default::default(),
            buffers: &[],
        },
        primitive: wgpu::PrimitiveState::default(),
        depth_stencil: Some(wgpu::DepthStencilState {
            format,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Always),
            stencil: wgpu::StencilState::default(),
            bias: wgpu::DepthBiasState::default(),
        }),
        multisample: wgpu::MultisampleState::default(),
        fragment: Some(wgpu::FragmentState {
            module: &module,
            entry_point: Some("fs"),
            compilation_options: Default::default(),
            targets: &[],
        }),
        multiview_mask: None,
        cache: None,
    });
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[wgpu::BindGroupEntry {
            binding: 0,
            resource: wgpu::BindingResource::TextureView(&src.create_view(&Default::default())),
        }],
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let view = target.create_view(&Default::default());
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("write depth"),
            color_attachments: &[],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(0.0),
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &group, &[]);
        pass.draw(0..3, 0..1);
    }
    ctx.queue().submit([encoder.finish()]);
    target
}

/// Records `pass` into a new encoder with `depth` and `timer`, submits and reads A back.
fn encode_and_read(
    ctx: &GpuContext,
    pass: &mut SaoPass,
    sao: &Sao,
    depth: &wgpu::Texture,
    timer: Option<&SaoTimer>,
) -> Result<Vec<f32>, GpuError> {
    let mut encoder = ctx.device().create_command_encoder(&Default::default());
    pass.encode(ctx, &mut encoder, sao, depth, timer)?;
    if let Some(t) = timer {
        t.resolve(&mut encoder);
    }
    ctx.queue().submit([encoder.finish()]);
    let ao = pass.ao_texture().expect("encode made the AO texture");
    let data = ocean_gpu::readback::read_texture(ctx, ao, 0)?;
    Ok(bytemuck::pod_collect_to_vec(&data.data))
}

/// The caller's Depth32Float depth buffer (its depth aspect read unfiltered by the same
/// shader as an R32Float texture): the same A as the uploaded slice, for forward and reversed
/// Z; per-pass timestamps where the adapter has them; one pass at a time gives the same A; the
/// textures are kept while the size stays.
#[test]
fn caller_depth_texture_matches_the_cpu() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let mut pass = SaoPass::new(&ctx).unwrap();
    for (convention, name) in [
        (DepthConvention::ZERO_TO_ONE_REVERSED, "reversed Z"),
        (DepthConvention::ZERO_TO_ONE, "forward Z"),
    ] {
        let case = Case::new(
            AnalyticView::spheres(),
            perspective(SIZE.0, SIZE.1, Far::Finite(100.0)),
            convention,
            DepthSource::Window,
            DepthFormat::F32,
            SIZE,
            SaoParams::default(),
            "Depth32Float",
        );
        let size = (SIZE.0 as u32, SIZE.1 as u32);
        let texture = depth_texture(
            &ctx,
            &case.raster.depth,
            size,
            wgpu::TextureFormat::Depth32Float,
        );
        let timer = SaoTimer::new(&ctx);
        let ao = encode_and_read(&ctx, &mut pass, &case.sao, &texture, timer.as_ref()).unwrap();
        let cpu = case.sao.stages(&case.raster.depth).unwrap();
        let d = FloatDiff::new(&ao, &cpu.ao, f64::from(AO_TOL), false);
        println!("{} {name}: {d}", case.label);
        assert!(d.share() >= AO_SHARE, "{}: {d}", case.label);
        // frag_depth stores the f32 unchanged, so the A is the uploaded slice's.
        let slice = pass.evaluate(&ctx, &case.sao, &case.raster.depth).unwrap();
        assert_eq!(ao, slice, "Depth32Float and R32Float inputs differ");
        if software(&ctx) {
            assert_eq!(d.equal, d.n, "{}: {d}", case.label);
        }
        match &timer {
            Some(t) => {
                let times = t.read(&ctx).unwrap();
                // Written, resolved and read for every pass (the counter never went back).
                for stage in SaoStage::ALL {
                    let ms = times.get(stage).map(|d| d.ms());
                    println!("  {}: {ms:?} ms", stage.name());
                    assert!(ms.is_some(), "{}: no time", stage.name());
                }
                assert!(times.total().is_some_and(|d| d.ns > 0.0));
            }
            None => println!("  (no timestamps on this adapter)"),
        }

        // One pass per submission reads what the earlier ones left: the same A.
        let before = pass.ao_texture().unwrap().clone();
        for stage in SaoStage::ALL {
            let mut encoder = ctx.device().create_command_encoder(&Default::default());
            pass.encode_stage(&ctx, &mut encoder, &case.sao, &texture, stage, None)
                .unwrap();
            ctx.queue().submit([encoder.finish()]);
        }
        let data = ocean_gpu::readback::read_texture(&ctx, pass.ao_texture().unwrap(), 0).unwrap();
        assert_eq!(bytemuck::pod_collect_to_vec::<u8, f32>(&data.data), ao);
        assert!(
            pass.ao_texture().unwrap() == &before,
            "the textures are kept for the same size"
        );
    }
    // Another size makes new textures.
    let before = pass.ao_texture().unwrap().clone();
    let small = Case::new(
        AnalyticView::spheres(),
        perspective(64, 48, Far::Infinite),
        DepthConvention::ZERO_TO_ONE_REVERSED,
        DepthSource::Window,
        DepthFormat::F32,
        (64, 48, 4),
        SaoParams::default(),
        "small",
    );
    let ao = pass
        .evaluate(&ctx, &small.sao, &small.raster.depth)
        .unwrap();
    assert_eq!(ao.len(), 56 * 40);
    assert!(pass.ao_texture().unwrap() != &before);
}

/// A compute shader that copies the depth aspect of a depth texture into an `R32Float`
/// texture: the values the device stored, which no copy command may read from a fixed-point
/// depth format.
const DEPTH_READER: &str = "
@group(0) @binding(0) var src: texture_2d<f32>;
@group(0) @binding(1) var dst: texture_storage_2d<r32float, write>;
@compute @workgroup_size(8, 8)
fn copy(@builtin(global_invocation_id) id: vec3<u32>) {
    if (any(id.xy >= textureDimensions(src))) {
        return;
    }
    textureStore(dst, vec2<i32>(id.xy), textureLoad(src, vec2<i32>(id.xy), 0));
}
";

/// The depth values `texture` holds, as the shaders read them.
fn stored_depth(ctx: &GpuContext, texture: &wgpu::Texture) -> Vec<f32> {
    let device = ctx.device();
    let (w, h) = (texture.width(), texture.height());
    let dst = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("stored depth"),
        size: wgpu::Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::R32Float,
        usage: wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: None,
        entries: &[
            wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty: wgpu::BindingType::Texture {
                    sample_type: wgpu::TextureSampleType::Float { filterable: false },
                    view_dimension: wgpu::TextureViewDimension::D2,
                    multisampled: false,
                },
                count: None,
            },
            wgpu::BindGroupLayoutEntry {
                binding: 1,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty: wgpu::BindingType::StorageTexture {
                    access: wgpu::StorageTextureAccess::WriteOnly,
                    format: wgpu::TextureFormat::R32Float,
                    view_dimension: wgpu::TextureViewDimension::D2,
                },
                count: None,
            },
        ],
    });
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("depth reader"),
        source: wgpu::ShaderSource::Wgsl(DEPTH_READER.into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some("depth reader"),
        layout: Some(
            &device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: None,
                bind_group_layouts: &[Some(&layout)],
                immediate_size: 0,
            }),
        ),
        module: &module,
        entry_point: Some("copy"),
        compilation_options: Default::default(),
        cache: None,
    });
    let src = texture.create_view(&wgpu::TextureViewDescriptor {
        aspect: wgpu::TextureAspect::DepthOnly,
        ..Default::default()
    });
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &layout,
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::TextureView(&src),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: wgpu::BindingResource::TextureView(&dst.create_view(&Default::default())),
            },
        ],
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &group, &[]);
        pass.dispatch_workgroups(w.div_ceil(8), h.div_ceil(8), 1);
    }
    ctx.queue().submit([encoder.finish()]);
    let data = ocean_gpu::readback::read_texture(ctx, &dst, 0).unwrap();
    bytemuck::pod_collect_to_vec(&data.data)
}

/// Depth24Plus and Depth16Unorm depth buffers are read through their depth aspect too. What a
/// shader reads back from them is the device's fixed-point rounding and conversion of the
/// values written (measured on lavapipe and llvmpipe: none of the 24-bit values and 0.16% of
/// the 16-bit ones read back as the `f32` written), so the CPU runs on the values read back by
/// a shader of the test's own.
#[test]
fn fixed_point_depth_textures_match_the_cpu() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let mut pass = SaoPass::new(&ctx).unwrap();
    let case = Case::new(
        AnalyticView::box_in_room(),
        perspective(SIZE.0, SIZE.1, Far::Finite(20.0)),
        DepthConvention::ZERO_TO_ONE,
        DepthSource::Window,
        DepthFormat::Unorm24,
        SIZE,
        SaoParams::default(),
        "fixed point",
    );
    let size = (SIZE.0 as u32, SIZE.1 as u32);
    for format in [
        wgpu::TextureFormat::Depth24Plus,
        wgpu::TextureFormat::Depth16Unorm,
    ] {
        let texture = depth_texture(&ctx, &case.raster.depth, size, format);
        let stored = stored_depth(&ctx, &texture);
        let kept = stored
            .iter()
            .zip(&case.raster.depth)
            .filter(|(a, b)| a == b)
            .count();
        let cpu = case.sao.stages(&stored).unwrap();
        let ao = encode_and_read(&ctx, &mut pass, &case.sao, &texture, None).unwrap();
        let d = FloatDiff::new(&ao, &cpu.ao, f64::from(AO_TOL), false);
        println!(
            "{format:?}: {:.2}% of the depth values kept as written; A: {d}",
            100.0 * kept as f64 / stored.len() as f64
        );
        assert!(d.share() >= AO_SHARE, "{format:?}: {d}");
        if software(&ctx) {
            assert_eq!(d.equal, d.n, "{format:?}: {d}");
        }
    }
}
