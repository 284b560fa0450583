//! The relief texture a renderer reads: its layout (isotropic cones, or the four quadrant
//! layers), and uploading a texture or a mip chain of either.

use super::*;

/// The relief texture a [`ReliefRenderer`] reads, and so which shader it draws with.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ReliefLayout {
    /// One `rgba32float` texture of isotropic cones ([`ReliefTexture`];
    /// shaders `relief` and `relief_probe`).
    Isotropic,
    /// A 4-layer `rgba32float` texture array of quadrant cones ([`QuadReliefTexture`], §18.1;
    /// shaders `relief_quad` and `relief_quad_probe`): each ray reads the layer of its
    /// direction's quadrant.
    Quad,
}

impl ReliefLayout {
    /// Both layouts, in the order of [`ReliefLayout::index`].
    pub(super) const ALL: [ReliefLayout; 2] = [ReliefLayout::Isotropic, ReliefLayout::Quad];

    pub(super) fn index(self) -> usize {
        match self {
            ReliefLayout::Isotropic => 0,
            ReliefLayout::Quad => 1,
        }
    }

    /// Array layers of the texture.
    pub fn layers(self) -> u32 {
        match self {
            ReliefLayout::Isotropic => 1,
            ReliefLayout::Quad => 4,
        }
    }

    /// The draw shader's name in [`crate::shaders`].
    pub fn draw_shader(self) -> &'static str {
        match self {
            ReliefLayout::Isotropic => "relief",
            ReliefLayout::Quad => "relief_quad",
        }
    }

    /// The probe shader's name in [`crate::shaders`].
    pub fn probe_shader(self) -> &'static str {
        match self {
            ReliefLayout::Isotropic => "relief_probe",
            ReliefLayout::Quad => "relief_quad_probe",
        }
    }

    /// The view dimension of binding 1: `texture_2d` or `texture_2d_array`. (Not one array
    /// type for both: wgpu's GL backend makes a one-layer texture a `TEXTURE_2D`, which a
    /// `D2Array` view cannot bind.)
    pub(super) fn view_dimension(self) -> wgpu::TextureViewDimension {
        match self {
            ReliefLayout::Isotropic => wgpu::TextureViewDimension::D2,
            ReliefLayout::Quad => wgpu::TextureViewDimension::D2Array,
        }
    }
}

#[derive(Debug)]
pub(super) struct TextureState {
    pub(super) size: usize,
    pub(super) edge: Edge,
    pub(super) levels: usize,
    pub(super) layout: ReliefLayout,
    pub(super) view: wgpu::TextureView,
}

impl ReliefRenderer {
    /// Uploads the relief texture (`[depth, cone, clearance, near cap]` per texel, an
    /// `rgba32float` texture read with `textureLoad`) that every later draw and probe reads:
    /// one level, so every fragment reads level 0 whatever its footprint (see
    /// [`set_mips`](Self::set_mips)).
    ///
    /// # Errors
    ///
    /// [`GpuError::TooLarge`] for a side above the device's largest 2D texture;
    /// [`GpuError::Wgpu`] for a device error.
    pub fn set_texture(
        &mut self,
        ctx: &GpuContext,
        texture: &ReliefTexture,
    ) -> Result<(), GpuError> {
        let n = texture.size();
        self.upload(
            ctx,
            (n, texture.edge(), 1),
            ReliefLayout::Isotropic,
            (n, n),
            texture.texels(),
        )
    }

    /// Uploads a relief texture with its mip levels ([`ReliefMips`]: each level its own
    /// box-filtered surface with its own cones, [`ocean_relief::lod`]). Each fragment picks one
    /// level from its footprint ([`ocean_relief::lod::mip_level`] of the screen derivatives of
    /// the polygon's texture coordinates), once, before the tracer's loops; the viewing ray,
    /// the light ray and the relief normal read that level. Replaces any earlier texture.
    ///
    /// # Errors
    ///
    /// [`GpuError::TooLarge`] when the atlas of the levels (`3N/2` texels wide for two levels
    /// or more) is wider than the device's largest 2D texture; [`GpuError::Wgpu`] for a device
    /// error.
    pub fn set_mips(&mut self, ctx: &GpuContext, mips: &ReliefMips) -> Result<(), GpuError> {
        let n = mips.size();
        self.upload(
            ctx,
            (n, mips.edge(), mips.len()),
            ReliefLayout::Isotropic,
            atlas_size(n, mips.len()),
            &mips.atlas(),
        )
    }

    /// [`set_mips`](Self::set_mips) for quad-directional levels ([`QuadReliefMips`]; the
    /// layers as [`set_quad_texture`](Self::set_quad_texture) uploads them, at every level).
    ///
    /// # Errors
    ///
    /// As [`set_mips`](Self::set_mips).
    pub fn set_quad_mips(
        &mut self,
        ctx: &GpuContext,
        mips: &QuadReliefMips,
    ) -> Result<(), GpuError> {
        let n = mips.size();
        let texels: Vec<[f32; 4]> = mips.atlas_layers().concat();
        self.upload(
            ctx,
            (n, mips.edge(), mips.len()),
            ReliefLayout::Quad,
            atlas_size(n, mips.len()),
            &texels,
        )
    }

    /// Uploads a quad-directional relief texture ([`QuadReliefTexture`], §18.1): a 4-layer
    /// `rgba32float` array, layer `k` the `[depth, c_k, D_k, E_k]` texels of quadrant `k`
    /// ([`ocean_relief::Quadrant::index`]). Later draws and probes use the `relief_quad`
    /// shaders: each viewing and light ray reads the layer of its direction's quadrant, as
    /// [`QuadReliefTexture::trace`] and [`QuadReliefTexture::in_shadow`] do. Replaces the
    /// texture of [`set_texture`](Self::set_texture) (and the other way round).
    ///
    /// # Errors
    ///
    /// As [`set_texture`](Self::set_texture).
    pub fn set_quad_texture(
        &mut self,
        ctx: &GpuContext,
        texture: &QuadReliefTexture,
    ) -> Result<(), GpuError> {
        let n = texture.size();
        self.upload(
            ctx,
            (n, texture.edge(), 1),
            ReliefLayout::Quad,
            (n, n),
            &texture.texels(),
        )
    }

    /// The layout of the texture set last, if any.
    pub fn layout(&self) -> Option<ReliefLayout> {
        self.texture.as_ref().map(|t| t.layout)
    }

    /// Uploads `texels` (layer by layer, each `width × height` row-major) of a relief texture of
    /// side `n`, edge mode `edge` and `levels` levels packed as `ocean_relief::lod`'s atlas.
    fn upload(
        &mut self,
        ctx: &GpuContext,
        (n, edge, levels): (usize, Edge, usize),
        layout: ReliefLayout,
        (width, height): (usize, usize),
        texels: &[[f32; 4]],
    ) -> Result<(), GpuError> {
        let max = ctx.device().limits().max_texture_dimension_2d;
        if width as u64 > u64::from(max) {
            return Err(GpuError::TooLarge {
                what: if levels > 1 {
                    "relief texture atlas width (texels: 3/2 of the side)"
                } else {
                    "relief texture side (texels)"
                },
                needed: width as u64,
                limit: u64::from(max),
            });
        }
        let device = ctx.device();
        let view = crate::scoped(device, || {
            let extent = wgpu::Extent3d {
                width: width as u32,
                height: height as u32,
                depth_or_array_layers: layout.layers(),
            };
            let t = device.create_texture(&wgpu::TextureDescriptor {
                label: Some("ocean relief texture"),
                size: extent,
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: wgpu::TextureFormat::Rgba32Float,
                usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
                view_formats: &[],
            });
            ctx.queue().write_texture(
                wgpu::TexelCopyTextureInfo {
                    texture: &t,
                    mip_level: 0,
                    origin: wgpu::Origin3d::ZERO,
                    aspect: wgpu::TextureAspect::All,
                },
                bytemuck::cast_slice(texels),
                wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(width as u32 * 16),
                    rows_per_image: Some(height as u32),
                },
                extent,
            );
            Ok(t.create_view(&wgpu::TextureViewDescriptor {
                dimension: Some(layout.view_dimension()),
                ..Default::default()
            }))
        })?;
        self.texture = Some(TextureState {
            size: n,
            edge,
            levels,
            layout,
            view,
        });
        Ok(())
    }

    pub(super) fn texture_state(&self) -> Result<&TextureState, GpuError> {
        self.texture.as_ref().ok_or(GpuError::NotConfigured {
            what: "relief texture",
            call: "ReliefRenderer::set_texture",
        })
    }
}
