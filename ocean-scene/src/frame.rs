//! One frame of the scene, pass by pass: clear, sea, island, rocks and pier, obscurance,
//! compose, readback, each submitted and timed alone.

use std::time::Instant;

use ocean_brdf::{Irradiance, Lighting};
use ocean_core::Camera;
use ocean_gpu::{ComposeInputs, GpuContext, OceanRenderer, ReliefScene, wgpu};

use crate::obscurance::Obscurance;
use crate::relief_draws::RockDraw;
use crate::solids::SolidRenderer;
use crate::targets::Targets;
use crate::terrain::TerrainRenderer;

/// What one frame draws besides the sea.
pub(crate) struct Dressing<'a> {
    pub(crate) terrain: Option<&'a TerrainRenderer>,
    pub(crate) obscurance: &'a mut Obscurance,
    pub(crate) lighting: &'a Lighting,
    /// The environment's irradiance on every orientation, once per run.
    pub(crate) sky: &'a Irradiance,
    pub(crate) rocks: &'a [RockDraw],
    pub(crate) solids: Option<&'a SolidRenderer>,
}

/// The passes of a frame, in order, for the timing summary.
pub const PASSES: [(&str, &str); 7] = [
    ("clear", "the split light and depth targets"),
    (
        "sea",
        "projected grid, filtered waves and local waves, Algorithm 5.1 split",
    ),
    ("island", "terrain"),
    (
        "rocks, pier",
        "relief mapping by relaxed cone stepping, self-shadowed; posts",
    ),
    (
        "obscurance",
        "SAO: depth resolve at 4 samples, z, MIP levels, samples, two blurs",
    ),
    (
        "compose",
        "direct + A x ambient, sky, tone mapping, sample average",
    ),
    ("readback", "copy to the CPU"),
];

/// One frame read back: RGBA8 rows from the top, and the single-sampled window depth when
/// asked for.
pub(crate) struct FrameImage {
    pub(crate) rgba: Vec<u8>,
    pub(crate) depth: Option<Vec<f32>>,
}

/// Draws one frame (the sea, the island, the rocks, their obscurance and the composition) and
/// reads it back (the depth too with `read_depth`). Each pass is submitted and waited for
/// alone, and its wall time added to `times` (in `PASSES` order): the figures are then per pass
/// on every backend, timestamp queries or not.
#[allow(clippy::too_many_arguments)]
pub(crate) fn draw_frame(
    ctx: &GpuContext,
    ocean: &OceanRenderer,
    dressing: &mut Dressing<'_>,
    camera: &Camera,
    time: f64,
    t: &Targets,
    read_depth: bool,
    times: &mut [f64; PASSES.len()],
) -> Result<FrameImage, ocean_gpu::GpuError> {
    draw_passes(ctx, ocean, dressing, camera, time, t, &t.color_view, times)?;
    let started = Instant::now();
    let rgba = ocean_gpu::readback::read_texture(ctx, &t.color, 0)?.data;
    let depth = if read_depth {
        let bytes = ocean_gpu::readback::read_texture(ctx, t.single_depth(), 0)?.data;
        Some(bytemuck::pod_collect_to_vec(&bytes))
    } else {
        None
    };
    times[6] += started.elapsed().as_secs_f64();
    Ok(FrameImage { rgba, depth })
}

/// The passes of [`draw_frame`] up to the composition, which writes into `out` (the targets'
/// colour, or a caller's texture of the same size and format).
#[allow(clippy::too_many_arguments)]
pub(crate) fn draw_passes(
    ctx: &GpuContext,
    ocean: &OceanRenderer,
    dressing: &mut Dressing<'_>,
    camera: &Camera,
    time: f64,
    t: &Targets,
    out: &wgpu::TextureView,
    times: &mut [f64; PASSES.len()],
) -> Result<(), ocean_gpu::GpuError> {
    let size = (t.color.width(), t.color.height());
    let encoder = || {
        ctx.device()
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("ocean render"),
            })
    };
    let submit = |encoder: wgpu::CommandEncoder, slot: &mut f64, started: Instant| {
        ctx.queue().submit([encoder.finish()]);
        ctx.wait_idle()?;
        *slot += started.elapsed().as_secs_f64();
        Ok::<_, ocean_gpu::GpuError>(())
    };
    let light = t.light();

    let started = Instant::now();
    let mut e = encoder();
    let clear = |view| {
        Some(wgpu::RenderPassColorAttachment {
            view,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations {
                load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                store: wgpu::StoreOp::Store,
            },
        })
    };
    // Every renderer loads the targets: clear them first (depth to the far plane, 1 in
    // WebGPU's forward range, which the scene's cameras use; alpha 0 marks the sky).
    e.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("ocean render clear"),
        color_attachments: &[clear(&t.direct), clear(&t.ambient)],
        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
            view: &t.depth_view,
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
    submit(e, &mut times[0], started)?;

    let started = Instant::now();
    let mut e = encoder();
    ocean.render_layers(ctx, &mut e, camera, time, &light, size)?;
    submit(e, &mut times[1], started)?;

    if let Some(terrain) = dressing.terrain {
        let started = Instant::now();
        let mut e = encoder();
        terrain.draw(ctx, &mut e, camera, dressing.lighting, dressing.sky, &light);
        submit(e, &mut times[2], started)?;
    }

    if !dressing.rocks.is_empty() || dressing.solids.is_some() {
        let started = Instant::now();
        let mut e = encoder();
        let eye = camera.eye();
        for rock in dressing.rocks {
            // Only the faces whose front the eye sees: the shader would discard the others
            // after rasterising them.
            let faces: Vec<ReliefScene> = rock
                .faces
                .iter()
                .filter(|f| (eye - f.origin).dot(f.edge_u.cross(f.edge_v)) > 0.0)
                .cloned()
                .collect();
            rock.renderer
                .render_layers(ctx, &mut e, camera, &faces, &light, size)?;
        }
        if let Some(solids) = dressing.solids {
            solids.draw(ctx, &mut e, camera, dressing.lighting, dressing.sky, &light);
        }
        submit(e, &mut times[3], started)?;
    }

    let started = Instant::now();
    let mut e = encoder();
    if let Some((pass, _, view)) = &t.resolved {
        pass.encode(ctx, &mut e, &t.depth_view, view, camera.depth().direction())?;
    }
    let obscurance = dressing.obscurance.encode(ctx, &mut e, t.single_depth())?;
    submit(e, &mut times[4], started)?;

    let started = Instant::now();
    let mut e = encoder();
    let inputs = ComposeInputs {
        direct: &t.direct,
        ambient: &t.ambient,
        obscurance,
    };
    ocean.compose(ctx, &mut e, &inputs, out, size)?;
    submit(e, &mut times[5], started)
}
