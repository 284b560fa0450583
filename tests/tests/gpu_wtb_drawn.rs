//! The mesh the GPU draws against the CPU's drawn height query: the vertices of a frame are
//! evaluated by `ocean_gpu::LayersPass`, triangulated as `ocean_wtb::drawn` documents (each cell
//! split along the diagonal from (i+1, j) to (i, j+1)) and rasterised top-down into an image of
//! heights (their f32 bits in R32Uint, which GL can render to), the highest triangle winning
//! where the mesh folds; every pixel centre is then asked of `Frame::drawn_heights`. Where both
//! say the point is covered the heights must agree as the GPU parity of the vertices does
//! (1 mm RMS), and within 2 mm at any pixel: the GPU's vertices differ from the CPU's
//! by f32 rounding, and the rasteriser interpolates in f32 from vertices snapped to its
//! sub-pixel grid. Coverage may differ only where the rasteriser's edge rules decide: at a few
//! pixels (under 0.5 %), all within 1.5 pixels of the displaced mesh's outline.

use glam::{DVec2, Vec3};
use ocean_gpu::wgpu::util::DeviceExt;
use ocean_gpu::{GpuContext, LayersPass, wgpu};
use ocean_tests::{HEIGHT_RMS_TOL_M, gpu_context_or_skip, texture_2d};
use ocean_wtb::scenarios;
use ocean_wtb::scene::{DrawnSample, Scene};

/// Largest height difference at any pixel, metres. Measured at most 2·10⁻⁵ m on lavapipe and
/// llvmpipe; a rasteriser snapping vertices to 1/256 pixel (0.5 mm here) may add up to the
/// slope times that. The other diagonal gives 4 cm.
const HEIGHT_MAX_TOL_M: f64 = 2e-3;
/// Pixels along the longer side of the image.
const PIXELS: u32 = 512;
/// What the image holds where no triangle is drawn.
const EMPTY: f32 = -1000.0;
/// Heights map to depth 0.5 − y / (2 · DEPTH_RANGE): the highest is nearest.
const DEPTH_RANGE: f32 = 1000.0;

const SHADER: &str = r"
struct View { min: vec2<f32>, inv_size: vec2<f32> }
@group(0) @binding(0) var<uniform> view: View;
struct Out { @builtin(position) clip: vec4<f32>, @location(0) height: f32 }
@vertex fn vs(@location(0) p: vec3<f32>) -> Out {
    let uv = (p.xz - view.min) * view.inv_size;
    // Framebuffer rows run along +z (clip y is up, framebuffer y down).
    let depth = 0.5 - p.y / (2.0 * DEPTH_RANGE);
    return Out(vec4<f32>(2.0 * uv.x - 1.0, 1.0 - 2.0 * uv.y, depth, 1.0), p.y);
}
// The height's bits: R32Float is not renderable on downlevel (GL) adapters, R32Uint is.
@fragment fn fs(in: Out) -> @location(0) u32 { return bitcast<u32>(in.height); }
";

/// Indices of the drawn triangulation of an `nx` × `nz` grid (lower, then upper triangle).
fn indices(nx: u32, nz: u32) -> Vec<u32> {
    let mut out = Vec::new();
    for j in 0..nz - 1 {
        for i in 0..nx - 1 {
            let (a, b, c, d) = (
                j * nx + i,
                j * nx + i + 1,
                (j + 1) * nx + i,
                (j + 1) * nx + i + 1,
            );
            out.extend_from_slice(&[a, b, c, b, d, c]);
        }
    }
    out
}

/// Rasterises `positions` (relative to the grid origin) over the rectangle from `min`
/// (relative too) of `size.0` × `size.1` pixels of side `pixel`: the heights, or [`EMPTY`].
fn raster(
    ctx: &GpuContext,
    positions: &[Vec3],
    index: &[u32],
    min: DVec2,
    pixel: f64,
    size: (u32, u32),
) -> Vec<f32> {
    let device = ctx.device();
    let texture = |format, usage| texture_2d(ctx, size, format, usage);
    let color = texture(
        wgpu::TextureFormat::R32Uint,
        wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
    );
    let depth = texture(
        wgpu::TextureFormat::Depth32Float,
        wgpu::TextureUsages::RENDER_ATTACHMENT,
    );
    let source = SHADER.replace("DEPTH_RANGE", &format!("{DEPTH_RANGE:.1}"));
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("drawn heights"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let attributes = wgpu::vertex_attr_array![0 => Float32x3];
    let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("drawn heights"),
        layout: None,
        vertex: wgpu::VertexState {
            module: &module,
            entry_point: Some("vs"),
            compilation_options: Default::default(),
            buffers: &[Some(wgpu::VertexBufferLayout {
                array_stride: 12,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &attributes,
            })],
        },
        primitive: wgpu::PrimitiveState {
            cull_mode: None,
            ..Default::default()
        },
        depth_stencil: Some(wgpu::DepthStencilState {
            format: wgpu::TextureFormat::Depth32Float,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Less),
            stencil: wgpu::StencilState::default(),
            bias: wgpu::DepthBiasState::default(),
        }),
        multisample: wgpu::MultisampleState::default(),
        fragment: Some(wgpu::FragmentState {
            module: &module,
            entry_point: Some("fs"),
            compilation_options: Default::default(),
            targets: &[Some(wgpu::TextureFormat::R32Uint.into())],
        }),
        multiview_mask: None,
        cache: None,
    });
    let init = |contents: &[u8], usage| {
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: None,
            contents,
            usage,
        })
    };
    let view_size = [size.0 as f64 * pixel, size.1 as f64 * pixel];
    let uniform: [f32; 4] = [
        min.x as f32,
        min.y as f32,
        (1.0 / view_size[0]) as f32,
        (1.0 / view_size[1]) as f32,
    ];
    let uniform = init(bytemuck::bytes_of(&uniform), wgpu::BufferUsages::UNIFORM);
    let vertices = init(bytemuck::cast_slice(positions), wgpu::BufferUsages::VERTEX);
    let index_buffer = init(bytemuck::cast_slice(index), wgpu::BufferUsages::INDEX);
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[wgpu::BindGroupEntry {
            binding: 0,
            resource: uniform.as_entire_binding(),
        }],
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let (color_view, depth_view) = (
            color.create_view(&Default::default()),
            depth.create_view(&Default::default()),
        );
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("drawn heights"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &color_view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color {
                        r: f64::from(EMPTY.to_bits()),
                        g: 0.0,
                        b: 0.0,
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
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &group, &[]);
        pass.set_vertex_buffer(0, vertices.slice(..));
        pass.set_index_buffer(index_buffer.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..index.len() as u32, 0, 0..1);
    }
    ctx.queue().submit([encoder.finish()]);
    let data = ocean_gpu::readback::read_texture(ctx, &color, 0).unwrap();
    let bits: Vec<u32> = bytemuck::pod_collect_to_vec(&data.data);
    bits.into_iter().map(f32::from_bits).collect()
}

/// Distance from `p` to the closed polyline `outline`.
fn distance_to(outline: &[DVec2], p: DVec2) -> f64 {
    let mut best = f64::INFINITY;
    for (k, &a) in outline.iter().enumerate() {
        let b = outline[(k + 1) % outline.len()];
        let t = ((p - a).dot(b - a) / (b - a).length_squared().max(1e-300)).clamp(0.0, 1.0);
        best = best.min(p.distance(a + t * (b - a)));
    }
    best
}

fn check(ctx: &GpuContext, pass: &LayersPass, scene: &mut Scene, t: f64, label: &str) {
    let frame = scene.frame(t, None).unwrap();
    let grid = frame.grid();
    let (nx, nz, s, origin) = (grid.nx(), grid.nz(), grid.spacing(), grid.origin());
    let gpu = pass
        .evaluate(
            ctx,
            grid.grid(),
            frame.time(),
            &frame.layers(),
            frame.height_field(),
        )
        .unwrap();
    let (mut pos, mut nrm) = (vec![Vec3::ZERO; grid.len()], vec![Vec3::ZERO; grid.len()]);
    frame.evaluate(&mut pos, &mut nrm).unwrap();
    let top = pos.iter().map(|p| p.y.abs()).fold(0.0f32, f32::max);
    assert!(top > 0.1, "{label}: no waves ({top} m)");

    // The grid's rectangle and 2 m around it, in square pixels.
    let margin = 2.0;
    let span = DVec2::new((nx - 1) as f64 * s, (nz - 1) as f64 * s) + 2.0 * margin;
    let pixel = span.max_element() / f64::from(PIXELS);
    let size = (
        (span.x / pixel).ceil() as u32,
        (span.y / pixel).ceil() as u32,
    );
    let min = DVec2::splat(-margin);
    let index = indices(nx as u32, nz as u32);
    let image = raster(ctx, &gpu.positions, &index, min, pixel, size);

    let (w, h) = (size.0 as usize, size.1 as usize);
    let at: Vec<DVec2> = (0..w * h)
        .map(|q| origin + min + pixel * DVec2::new((q % w) as f64 + 0.5, (q / w) as f64 + 0.5))
        .collect();
    let mut drawn = vec![frame.drawn_height_at(at[0]).unwrap(); at.len()];
    frame.drawn_heights(&at, &mut drawn).unwrap();

    // The displaced mesh's outline (world x, z), around the grid's edge points.
    let edge = (0..nx)
        .map(|i| (i, 0))
        .chain((1..nz).map(|j| (nx - 1, j)))
        .chain((0..nx - 1).rev().map(|i| (i, nz - 1)))
        .chain((1..nz - 1).rev().map(|j| (0, j)));
    let outline: Vec<DVec2> = edge
        .map(|(i, j)| {
            let p = pos[j * nx + i];
            origin + DVec2::new(f64::from(p.x), f64::from(p.z))
        })
        .collect();

    let (mut compared, mut sum2, mut max, mut disagree, mut worst_edge) = (0, 0.0, 0.0f64, 0, 0.0);
    for ((&g, d), p) in image.iter().zip(&drawn).zip(&at) {
        let DrawnSample {
            height, triangle, ..
        } = *d;
        match (g != EMPTY, triangle.is_some()) {
            (true, true) => {
                let e = f64::from(g) - height;
                compared += 1;
                sum2 += e * e;
                max = max.max(e.abs());
            }
            (false, false) => {}
            _ => {
                disagree += 1;
                worst_edge = f64::max(worst_edge, distance_to(&outline, *p) / pixel);
            }
        }
    }
    let rms = (sum2 / compared as f64).sqrt();
    println!(
        "{label}: {w}×{h} pixels of {pixel:.3} m, |y| up to {top:.3} m: {compared} compared, \
         height RMS {rms:.2e} m, max {max:.2e} m; {disagree} coverage disagreements, at most \
         {worst_edge:.2} pixels from the outline"
    );
    assert!(compared > w * h / 2, "{label}: {compared} pixels compared");
    assert!(rms <= HEIGHT_RMS_TOL_M, "{label}: height RMS {rms} m");
    assert!(max <= HEIGHT_MAX_TOL_M, "{label}: height max {max} m");
    assert!(disagree * 200 < w * h, "{label}: {disagree} disagreements");
    assert!(
        worst_edge <= 1.5,
        "{label}: {worst_edge} px off the outline"
    );
}

#[test]
fn the_gpu_draws_the_drawn_query_surface() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let pass = LayersPass::new(&ctx).unwrap();
    for (scene, label) in [
        (scenarios::scenario_1(64), "scenario 1, 64²"),
        (scenarios::scenario_2(64), "scenario 2, 64²"),
        (scenarios::island(64), "island, 64²"),
    ] {
        check(&ctx, &pass, &mut scene.unwrap(), 7.0, label);
    }
}
