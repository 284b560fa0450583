//! The renderer's GPU resources: the bind group layout shared by its passes, the wave and
//! effective-Fresnel textures, and the projected grid's index buffer.

use super::*;

/// The index buffer of the last grid size drawn.
#[derive(Debug)]
pub(super) struct GridIndices {
    pub(super) size: (u32, u32),
    pub(super) count: u32,
    pub(super) buffer: wgpu::Buffer,
}

/// Bindings 0–3 and 6–8 of `ocean_common.wgsl`, visible to `stages`.
pub(super) fn common_layout_entries(stages: wgpu::ShaderStages) -> [wgpu::BindGroupLayoutEntry; 7] {
    let texture = |binding, filterable| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: stages,
        ty: wgpu::BindingType::Texture {
            sample_type: wgpu::TextureSampleType::Float { filterable },
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        },
        count: None,
    };
    [
        wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: stages,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: wgpu::BufferSize::new(std::mem::size_of::<FrameUniform>() as u64),
            },
            count: None,
        },
        texture(1, false),
        texture(2, true),
        wgpu::BindGroupLayoutEntry {
            binding: 3,
            visibility: stages,
            ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
            count: None,
        },
        texture(FRESNEL_BINDING, false),
        wgpu::BindGroupLayoutEntry {
            binding: LOCAL_FIELDS_BINDING,
            visibility: stages,
            ty: wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { filterable: false },
                view_dimension: wgpu::TextureViewDimension::D2Array,
                multisampled: false,
            },
            count: None,
        },
        texture(LOCAL_TRAINS_BINDING, false),
    ]
}

/// Binding of the effective Fresnel table (after the probes' 4 and 5).
pub(super) const FRESNEL_BINDING: u32 = 6;

/// Bindings of the local waves' fields and trains.
pub(super) const LOCAL_FIELDS_BINDING: u32 = 7;

pub(super) const LOCAL_TRAINS_BINDING: u32 = 8;

/// The texels of the effective Fresnel table texture (binding 6 of `ocean_common.wgsl`, 33 × 33
/// `r32float`, row-major): texel `(j, i)`, element `33 i + j`, holds the roughness correction
/// `D(cos θ_v = (i/32)², σ_v = (j/32)²)` of [`ocean_brdf::fresnel_table`] (Eq. 24) rounded to
/// `f32`.
pub fn fresnel_table_texels() -> Vec<f32> {
    ocean_brdf::fresnel_table::FRESNEL_TABLE
        .iter()
        .map(|&m| m as f32)
        .collect()
}

/// The effective Fresnel table (`ocean_brdf::fresnel_table`) as a 33 × 33 `r32float` texture:
/// texel (j, i) holds the correction `D(cos θ_v = (i/32)², σ_v = (j/32)²)` to Schlick's value.
pub(super) fn fresnel_table_texture(ctx: &GpuContext) -> wgpu::Texture {
    let n = ocean_brdf::fresnel_table::FRESNEL_TABLE_SIZE as u32;
    let texture = ctx.device().create_texture(&wgpu::TextureDescriptor {
        label: Some("ocean effective Fresnel table"),
        size: wgpu::Extent3d {
            width: n,
            height: n,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::R32Float,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    let texels = fresnel_table_texels();
    ctx.queue().write_texture(
        wgpu::TexelCopyTextureInfo {
            texture: &texture,
            mip_level: 0,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        bytemuck::cast_slice(&texels),
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(4 * n),
            rows_per_image: Some(n),
        },
        wgpu::Extent3d {
            width: n,
            height: n,
            depth_or_array_layers: 1,
        },
    );
    texture
}

#[allow(clippy::too_many_arguments)]
pub(super) fn draw_bind_group(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    uniform: &wgpu::Buffer,
    waves: &wgpu::TextureView,
    sky: &wgpu::TextureView,
    sampler: &wgpu::Sampler,
    fresnel: &wgpu::TextureView,
    local: &LocalTextures,
) -> wgpu::BindGroup {
    let entry = |binding, resource| wgpu::BindGroupEntry { binding, resource };
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("ocean bind group"),
        layout,
        entries: &[
            entry(0, uniform.as_entire_binding()),
            entry(1, wgpu::BindingResource::TextureView(waves)),
            entry(2, wgpu::BindingResource::TextureView(sky)),
            entry(3, wgpu::BindingResource::Sampler(sampler)),
            entry(FRESNEL_BINDING, wgpu::BindingResource::TextureView(fresnel)),
            entry(
                LOCAL_FIELDS_BINDING,
                wgpu::BindingResource::TextureView(&local.fields_view),
            ),
            entry(
                LOCAL_TRAINS_BINDING,
                wgpu::BindingResource::TextureView(&local.trains_view),
            ),
        ],
    })
}

/// The wave texture for `n` waves: `n × 3` texels of `rgba32float`.
pub(super) fn wave_texture(device: &wgpu::Device, n: u32) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: Some("ocean waves"),
        size: wgpu::Extent3d {
            width: n,
            height: WAVE_ROWS,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Rgba32Float,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    })
}

/// Writes the first `rows` rows of `n` texels each (`texels`, row-major) into the wave texture.
pub(super) fn write_waves(
    ctx: &GpuContext,
    texture: &wgpu::Texture,
    texels: &[[f32; 4]],
    n: u32,
    rows: u32,
) {
    ctx.queue().write_texture(
        wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: 0,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        bytemuck::cast_slice(texels),
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(n * 16),
            rows_per_image: Some(rows),
        },
        wgpu::Extent3d {
            width: n,
            height: rows,
            depth_or_array_layers: 1,
        },
    );
}

/// The index buffer of an `nx × ny` grid: two triangles per cell, rows from the top of the
/// screen (the far sea) down, so that without a depth buffer nearer cells are drawn last.
pub(super) fn grid_indices(ctx: &GpuContext, nx: u32, ny: u32) -> Result<GridIndices, GpuError> {
    let cells = u64::from(nx.saturating_sub(1)) * u64::from(ny.saturating_sub(1));
    let count = cells * 6;
    let bytes = count * 4;
    let device = ctx.device();
    let limit = device.limits().max_buffer_size;
    if count > u64::from(u32::MAX) || bytes > limit || count == 0 {
        return Err(GpuError::TooLarge {
            what: "projected grid index buffer (bytes)",
            needed: bytes,
            limit: limit.min(u64::from(u32::MAX)),
        });
    }
    let mut indices = Vec::with_capacity(count as usize);
    for j in 0..ny - 1 {
        for i in 0..nx - 1 {
            let a = j * nx + i;
            let c = a + nx;
            indices.extend_from_slice(&[a, c, a + 1, a + 1, c, c + 1]);
        }
    }
    crate::scoped(device, || {
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("ocean grid indices"),
            size: bytes,
            usage: wgpu::BufferUsages::INDEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        ctx.queue()
            .write_buffer(&buffer, 0, bytemuck::cast_slice(&indices));
        Ok(GridIndices {
            size: (nx, ny),
            count: count as u32,
            buffer,
        })
    })
}
