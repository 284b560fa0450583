//! The render targets of a scene's frames: split light and depth, the resolved depth the
//! obscurance reads, and the composed colour.

use ocean_gpu::{DepthResolve, GpuContext, LightTargets, RADIANCE_FORMAT, wgpu};

use crate::SceneError;

/// The format of a frame's colour ([`crate::SceneRenderer::render_into`]'s target): 8-bit RGBA holding
/// tone-mapped, sRGB-encoded values (a view of an `Rgba8UnormSrgb` texture would encode twice).
pub const COLOR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// The targets of the frames: split light and depth (what every renderer draws into, with
/// `samples` samples per pixel), the single-sampled depth the obscurance reads (the resolve of
/// a multisampled depth) and the composed display colour (what is read back).
pub(crate) struct Targets {
    pub(crate) direct: wgpu::TextureView,
    pub(crate) ambient: wgpu::TextureView,
    pub(crate) depth: wgpu::Texture,
    pub(crate) depth_view: wgpu::TextureView,
    /// With multisampled targets, the resolve pass and the depth it writes.
    pub(crate) resolved: Option<(DepthResolve, wgpu::Texture, wgpu::TextureView)>,
    pub(crate) color: wgpu::Texture,
    pub(crate) color_view: wgpu::TextureView,
}

impl Targets {
    pub(crate) fn new(
        ctx: &GpuContext,
        width: u32,
        height: u32,
        samples: u32,
    ) -> Result<Self, SceneError> {
        use ocean_gpu::wgpu;
        let texture = |label, format, usage, sample_count| {
            ctx.device().create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d {
                    width,
                    height,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let drawn_and_read =
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING;
        let view = |t: &wgpu::Texture| t.create_view(&wgpu::TextureViewDescriptor::default());
        let direct = texture(
            "ocean render direct",
            RADIANCE_FORMAT,
            drawn_and_read,
            samples,
        );
        let ambient = texture(
            "ocean render ambient",
            RADIANCE_FORMAT,
            drawn_and_read,
            samples,
        );
        let depth_format = wgpu::TextureFormat::Depth32Float;
        // Copied too when the single-sampled depth is written out.
        let copied = drawn_and_read | wgpu::TextureUsages::COPY_SRC;
        let depth = if samples > 1 {
            texture("ocean render depth", depth_format, drawn_and_read, samples)
        } else {
            texture("ocean render depth", depth_format, copied, 1)
        };
        let resolved = if samples > 1 {
            let pass = DepthResolve::new(ctx, depth_format)?;
            let t = texture("ocean render resolved depth", depth_format, copied, 1);
            let v = view(&t);
            Some((pass, t, v))
        } else {
            None
        };
        let color = texture(
            "ocean render colour",
            COLOR_FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            1,
        );
        Ok(Self {
            direct: view(&direct),
            ambient: view(&ambient),
            depth_view: view(&depth),
            color_view: view(&color),
            depth,
            resolved,
            color,
        })
    }

    /// The single-sampled depth: the resolved one with multisampled targets.
    pub(crate) fn single_depth(&self) -> &wgpu::Texture {
        self.resolved.as_ref().map_or(&self.depth, |(_, t, _)| t)
    }

    pub(crate) fn light(&self) -> LightTargets<'_> {
        LightTargets {
            direct: &self.direct,
            ambient: &self.ambient,
            depth: &self.depth_view,
        }
    }
}
