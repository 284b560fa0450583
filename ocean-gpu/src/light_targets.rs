//! Split light targets: the direct (Sun) and ambient (sky, refracted and bounced) radiance of a
//! frame in two linear render targets, so that an ambient obscurance darkens the ambient part
//! alone before one pass composes, tone-maps and encodes the frame.
//!
//! SAO (McGuire, Mara & Luebke 2012) estimates how much of the surrounding hemisphere is open,
//! which is what scales light arriving from all around a point; light from the Sun's disc is
//! either visible or shadowed, and an obscurance applied to it darkens sunlit contact regions
//! that are not darker in reality. The renderers that draw into these targets
//! ([`crate::OceanRenderer::render_layers`], [`crate::ReliefRenderer::render_layers`]) write
//! their Sun term at location 0 and the rest at location 1, alpha 1 where they drew; alpha 0
//! (the cleared value) marks pixels where nothing drew, which
//! [`crate::OceanRenderer::compose`] fills with the sky.

use crate::GpuError;
use crate::pipeline::check_render_target_samples;

/// Samples per pixel of multisampled [`LightTargets`]: 4, the one count besides 1 that WebGPU
/// guarantees for every renderable format.
pub const MSAA_SAMPLES: u32 = 4;

/// Format of both radiance targets. WebGPU's downlevel limits cannot render to `rgba32float`;
/// `f16`'s 3 significant digits are below what an 8-bit tone-mapped result shows, and
/// radiances beyond its 65504 limit (the Sun's glitter on the sea) saturate the tone map anyway
/// at the exposures [`crate::OceanOptions::exposure`] is meant for (from a radiance of 1 at
/// the default 8).
pub const RADIANCE_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

/// The targets of a split-light frame: the direct and ambient radiance ([`RADIANCE_FORMAT`],
/// `RENDER_ATTACHMENT`, and `TEXTURE_BINDING` for the composition) and the depth buffer every
/// renderer tests and writes (`TEXTURE_BINDING` too when an obscurance pass reads it).
///
/// Clear the radiance targets to transparent black (`wgpu::Color::TRANSPARENT`) and the depth
/// to the camera's far end before the first draw; each draw loads them.
///
/// The three targets have one sample per pixel, or [`MSAA_SAMPLES`] for a multisampled
/// (antialiased) frame: the renderers then rasterise every edge at that many coverage samples,
/// [`crate::OceanRenderer::compose`] resolves the radiance, tone-mapping each sample before it
/// averages them, and [`crate::DepthResolve`] gives an obscurance pass a single-sampled depth.
/// Multisampled targets need [`crate::GpuContext::supports_multisampled_light`] (not wgpu's GL
/// backend); the renderers refuse them elsewhere with [`GpuError::UnsuitableAdapter`].
#[derive(Clone, Copy, Debug)]
pub struct LightTargets<'a> {
    /// Direct (Sun) radiance, linear, alpha 1 where drawn.
    pub direct: &'a wgpu::TextureView,
    /// Ambient radiance, linear, alpha 1 where drawn.
    pub ambient: &'a wgpu::TextureView,
    /// Depth.
    pub depth: &'a wgpu::TextureView,
}

impl LightTargets<'_> {
    /// Samples per pixel of the targets (the depth target's; the renderers refuse radiance
    /// targets of another count).
    pub fn sample_count(&self) -> u32 {
        self.depth.texture().sample_count()
    }

    /// Checks formats, usages, sizes and sample counts (1 or [`MSAA_SAMPLES`], the same for
    /// all three) against a `size` viewport and `depth_format`; returns the sample count.
    pub(crate) fn check(
        &self,
        depth_format: wgpu::TextureFormat,
        size: (u32, u32),
    ) -> Result<u32, GpuError> {
        let samples = self.sample_count();
        if samples != 1 && samples != MSAA_SAMPLES {
            return Err(GpuError::InvalidResource {
                what: "depth target",
                reason: format!(
                    "{samples} samples per pixel: light targets have 1 or {MSAA_SAMPLES}"
                ),
            });
        }
        let radiance = |what, view: &wgpu::TextureView| {
            check_render_target_samples(what, view.texture(), RADIANCE_FORMAT, size, samples)
        };
        radiance("direct light target", self.direct)?;
        radiance("ambient light target", self.ambient)?;
        check_render_target_samples(
            "depth target",
            self.depth.texture(),
            depth_format,
            size,
            samples,
        )?;
        Ok(samples)
    }

    /// The two radiance attachments, loaded and stored: for a caller's own pass that draws
    /// into the same targets (its fragment stage writing the direct light at location 0 and
    /// the ambient light at location 1).
    pub fn color_attachments(&self) -> [Option<wgpu::RenderPassColorAttachment<'_>>; 2] {
        let load = |view| {
            Some(wgpu::RenderPassColorAttachment {
                view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Load,
                    store: wgpu::StoreOp::Store,
                },
            })
        };
        [load(self.direct), load(self.ambient)]
    }

    /// The depth attachment, loaded and stored.
    pub fn depth_attachment(&self) -> wgpu::RenderPassDepthStencilAttachment<'_> {
        wgpu::RenderPassDepthStencilAttachment {
            view: self.depth,
            depth_ops: Some(wgpu::Operations {
                load: wgpu::LoadOp::Load,
                store: wgpu::StoreOp::Store,
            }),
            stencil_ops: None,
        }
    }
}

/// Refuses `samples` > 1 where multisampled light targets do not work
/// ([`crate::GpuContext::supports_multisampled_light`]).
pub(crate) fn check_multisampling(ctx: &crate::GpuContext, samples: u32) -> Result<(), GpuError> {
    if samples > 1 && !ctx.supports_multisampled_light() {
        return Err(GpuError::UnsuitableAdapter {
            adapter: ctx.describe(),
            reason: format!(
                "multisampled light targets ({samples} samples) are lost on wgpu's GL backend; \
                 use 1 sample per pixel or another backend"
            ),
        });
    }
    Ok(())
}

/// The two colour target states of a pipeline that draws into [`LightTargets`].
pub(crate) fn radiance_targets() -> [Option<wgpu::ColorTargetState>; 2] {
    let t = Some(wgpu::ColorTargetState::from(RADIANCE_FORMAT));
    [t.clone(), t]
}

/// The multisample state of a pipeline that draws into [`LightTargets`] of `samples` samples
/// per pixel (every sample a fragment covers gets its one shaded value).
pub(crate) fn multisample(samples: u32) -> wgpu::MultisampleState {
    wgpu::MultisampleState {
        count: samples,
        ..wgpu::MultisampleState::default()
    }
}

/// Checks a texture read by the composition: `format` (up to sRGB), `TEXTURE_BINDING`, at least
/// the viewport.
pub(crate) fn check_input(
    what: &'static str,
    view: &wgpu::TextureView,
    format: wgpu::TextureFormat,
    size: (u32, u32),
) -> Result<(), GpuError> {
    let t = view.texture();
    if t.format() != format {
        return Err(GpuError::InvalidResource {
            what,
            reason: format!("format {:?}, {format:?} is read", t.format()),
        });
    }
    if !t.usage().contains(wgpu::TextureUsages::TEXTURE_BINDING) {
        return Err(GpuError::InvalidResource {
            what,
            reason: "needs TEXTURE_BINDING usage".to_owned(),
        });
    }
    if t.width() < size.0 || t.height() < size.1 {
        return Err(GpuError::InvalidResource {
            what,
            reason: format!(
                "{} x {} cannot cover a {} x {} viewport",
                t.width(),
                t.height(),
                size.0,
                size.1
            ),
        });
    }
    Ok(())
}
