//! The SAO passes' pipelines, bind group layouts, textures and bind groups.
//!
//! Every z level is a texture of its own (see `shaders/sao_mip.wgsl` for why), r32float with
//! storage and sampled usage; the packed texels of the sample pass and of the horizontal blur
//! are r32uint (the four bytes of an RGBA8 texel as one word: exact integer packing, no float
//! conversion); the final A is r32float.

use ocean_sao::SaoUniforms;

use crate::{GpuError, shaders};

/// z level textures bound by the sample pass: `MAX_MIP + 1` (levels the hierarchy does not
/// have are bound to its last level and never read).
pub(crate) const LEVEL_SLOTS: u32 = ocean_sao::params::MAX_MIP + 1;
/// Bindings of the sample pass after its level slots: packed out, raw out, quad out.
const PACKED_BINDING: u32 = LEVEL_SLOTS + 1;
const RAW_BINDING: u32 = LEVEL_SLOTS + 2;
const QUAD_BINDING: u32 = LEVEL_SLOTS + 3;

/// Workgroup side of every pass (`TILE` in `sao_common.wgsl`).
pub(crate) const TILE: u32 = 8;

/// Depth texture formats the z pass reads (their depth aspect, or the red channel of an
/// `R32Float` texture), unfiltered.
pub const DEPTH_FORMATS: [wgpu::TextureFormat; 6] = [
    wgpu::TextureFormat::Depth32Float,
    wgpu::TextureFormat::R32Float,
    wgpu::TextureFormat::Depth24Plus,
    wgpu::TextureFormat::Depth24PlusStencil8,
    wgpu::TextureFormat::Depth16Unorm,
    wgpu::TextureFormat::Depth32FloatStencil8,
];

/// The pipelines and their bind group layouts.
#[derive(Debug)]
pub(crate) struct Pipelines {
    pub z: wgpu::ComputePipeline,
    pub mip: wgpu::ComputePipeline,
    /// Layout of the z and MIP passes: a texture in, an r32float storage texture out.
    pub level_layout: wgpu::BindGroupLayout,
    pub ao: wgpu::ComputePipeline,
    pub ao_layout: wgpu::BindGroupLayout,
    pub ao_stages: wgpu::ComputePipeline,
    pub ao_stages_layout: wgpu::BindGroupLayout,
    pub blur_h: wgpu::ComputePipeline,
    pub blur_h_layout: wgpu::BindGroupLayout,
    pub blur_v: wgpu::ComputePipeline,
    pub blur_v_layout: wgpu::BindGroupLayout,
}

fn uniform_entry() -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding: 0,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: wgpu::BufferSize::new(std::mem::size_of::<SaoUniforms>() as u64),
        },
        count: None,
    }
}

/// A sampled 2D texture read with `textureLoad`. Unfilterable float layouts also accept depth
/// textures (WebGPU's rule), so one shader reads Depth32Float and R32Float alike.
fn texture_entry(binding: u32, sample_type: wgpu::TextureSampleType) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Texture {
            sample_type,
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        },
        count: None,
    }
}

const FLOAT: wgpu::TextureSampleType = wgpu::TextureSampleType::Float { filterable: false };
const UINT: wgpu::TextureSampleType = wgpu::TextureSampleType::Uint;

fn storage_entry(binding: u32, format: wgpu::TextureFormat) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::StorageTexture {
            access: wgpu::StorageTextureAccess::WriteOnly,
            format,
            view_dimension: wgpu::TextureViewDimension::D2,
        },
        count: None,
    }
}

fn module(device: &wgpu::Device, name: &str) -> Result<wgpu::ShaderModule, GpuError> {
    let entry = shaders::get(name).ok_or_else(|| {
        GpuError::Shader(shaders::ShaderError::UnknownShader {
            name: name.to_owned(),
            available: String::new(),
        })
    })?;
    Ok(device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(name),
        source: wgpu::ShaderSource::Wgsl(entry.source.into()),
    }))
}

fn layout(
    device: &wgpu::Device,
    label: &str,
    entries: &[wgpu::BindGroupLayoutEntry],
) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(label),
        entries,
    })
}

fn pipeline(
    device: &wgpu::Device,
    module: &wgpu::ShaderModule,
    entry: &str,
    layout: &wgpu::BindGroupLayout,
) -> wgpu::ComputePipeline {
    let label = format!("ocean sao {entry}");
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some(&label),
        bind_group_layouts: &[Some(layout)],
        immediate_size: 0,
    });
    device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(&label),
        layout: Some(&pipeline_layout),
        module,
        entry_point: Some(entry),
        compilation_options: wgpu::PipelineCompilationOptions::default(),
        cache: None,
    })
}

impl Pipelines {
    pub(crate) fn new(device: &wgpu::Device) -> Result<Self, GpuError> {
        crate::scoped(device, || {
            let r32f = wgpu::TextureFormat::R32Float;
            let r32u = wgpu::TextureFormat::R32Uint;
            // The z and MIP passes share one layout: both read one texture and write one
            // r32float level.
            let level_layout = layout(
                device,
                "ocean sao level",
                &[
                    uniform_entry(),
                    texture_entry(1, FLOAT),
                    storage_entry(2, r32f),
                ],
            );
            let z = pipeline(device, &module(device, "sao_z")?, "z_pass", &level_layout);
            let mip = pipeline(
                device,
                &module(device, "sao_mip")?,
                "downsample",
                &level_layout,
            );
            let mut ao_entries = vec![uniform_entry()];
            ao_entries.extend((1..=LEVEL_SLOTS).map(|b| texture_entry(b, FLOAT)));
            ao_entries.push(storage_entry(PACKED_BINDING, r32u));
            let ao_layout = layout(device, "ocean sao ao", &ao_entries);
            ao_entries.push(storage_entry(RAW_BINDING, r32f));
            ao_entries.push(storage_entry(QUAD_BINDING, r32f));
            let ao_stages_layout = layout(device, "ocean sao ao stages", &ao_entries);
            let ao_module = module(device, "sao_ao")?;
            let ao = pipeline(device, &ao_module, "ao", &ao_layout);
            let ao_stages = pipeline(device, &ao_module, "ao_stages", &ao_stages_layout);
            let blur_h_layout = layout(
                device,
                "ocean sao blur horizontal",
                &[
                    uniform_entry(),
                    texture_entry(1, UINT),
                    storage_entry(2, r32u),
                ],
            );
            let blur_v_layout = layout(
                device,
                "ocean sao blur vertical",
                &[
                    uniform_entry(),
                    texture_entry(1, UINT),
                    storage_entry(3, r32f),
                ],
            );
            let blur = module(device, "sao_blur")?;
            Ok(Self {
                z,
                mip,
                level_layout,
                ao,
                ao_layout,
                ao_stages,
                ao_stages_layout,
                blur_h: pipeline(device, &blur, "blur_horizontal", &blur_h_layout),
                blur_h_layout,
                blur_v: pipeline(device, &blur, "blur_vertical", &blur_v_layout),
                blur_v_layout,
            })
        })
    }
}

/// What the textures of a [`Targets`] were sized for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct TargetKey {
    pub input: (u32, u32),
    pub output: (u32, u32),
    pub levels: u32,
}

impl TargetKey {
    pub(crate) fn new(u: &SaoUniforms) -> Self {
        Self {
            input: (u.input_size[0], u.input_size[1]),
            output: (u.output_size[0], u.output_size[1]),
            levels: u.levels(),
        }
    }

    /// Size of z level `m`: `max(1, side >> m)`.
    pub(crate) fn level_size(&self, m: u32) -> (u32, u32) {
        ((self.input.0 >> m).max(1), (self.input.1 >> m).max(1))
    }
}

/// The textures and bind groups for one input size, guard band and level count.
#[derive(Debug)]
pub(crate) struct Targets {
    pub key: TargetKey,
    /// z level `m` (level 0: the z pass's output).
    pub levels: Vec<wgpu::Texture>,
    /// `mip_groups[m]`: level `m` in, level `m + 1` out.
    pub mip_groups: Vec<wgpu::BindGroup>,
    pub packed: wgpu::Texture,
    pub horizontal: wgpu::Texture,
    pub ao: wgpu::Texture,
    pub ao_view: wgpu::TextureView,
    pub ao_group: wgpu::BindGroup,
    pub blur_h_group: wgpu::BindGroup,
    pub blur_v_group: wgpu::BindGroup,
    /// The raw and quad-filtered A textures and the `ao_stages` bind group, made on first use.
    pub stages: Option<StageTargets>,
    /// The z pass's bind group for the depth texture it read last.
    pub depth: Option<(wgpu::Texture, wgpu::BindGroup)>,
}

/// The sample pass's extra outputs for [`crate::SaoPass::evaluate_stages`].
#[derive(Debug)]
pub(crate) struct StageTargets {
    pub raw: wgpu::Texture,
    pub quad: wgpu::Texture,
    pub group: wgpu::BindGroup,
}

fn texture(
    device: &wgpu::Device,
    label: &str,
    (width, height): (u32, u32),
    format: wgpu::TextureFormat,
) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: Some(label),
        size: wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        // COPY_SRC: the stages are read back by the parity tests.
        usage: wgpu::TextureUsages::STORAGE_BINDING
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    })
}

fn view(t: &wgpu::Texture) -> wgpu::TextureView {
    t.create_view(&wgpu::TextureViewDescriptor::default())
}

fn group(
    device: &wgpu::Device,
    label: &str,
    layout: &wgpu::BindGroupLayout,
    uniform: &wgpu::Buffer,
    views: &[(u32, &wgpu::TextureView)],
) -> wgpu::BindGroup {
    let mut entries = vec![wgpu::BindGroupEntry {
        binding: 0,
        resource: uniform.as_entire_binding(),
    }];
    entries.extend(views.iter().map(|&(binding, v)| wgpu::BindGroupEntry {
        binding,
        resource: wgpu::BindingResource::TextureView(v),
    }));
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some(label),
        layout,
        entries: &entries,
    })
}

impl Targets {
    /// Allocates the textures for `key` and their bind groups (call inside [`crate::scoped`]).
    pub(crate) fn new(
        device: &wgpu::Device,
        p: &Pipelines,
        uniform: &wgpu::Buffer,
        key: TargetKey,
    ) -> Self {
        let r32f = wgpu::TextureFormat::R32Float;
        let r32u = wgpu::TextureFormat::R32Uint;
        let levels: Vec<wgpu::Texture> = (0..key.levels)
            .map(|m| texture(device, &format!("ocean sao z{m}"), key.level_size(m), r32f))
            .collect();
        let level_views: Vec<wgpu::TextureView> = levels.iter().map(view).collect();
        let mip_groups = level_views
            .windows(2)
            .map(|w| {
                group(
                    device,
                    "ocean sao mip",
                    &p.level_layout,
                    uniform,
                    &[(1, &w[0]), (2, &w[1])],
                )
            })
            .collect();
        let packed = texture(device, "ocean sao packed", key.output, r32u);
        let horizontal = texture(device, "ocean sao horizontal", key.output, r32u);
        let ao = texture(device, "ocean sao ao", key.output, r32f);
        let (packed_view, horizontal_view, ao_view) = (view(&packed), view(&horizontal), view(&ao));
        let ao_group = group(
            device,
            "ocean sao ao",
            &p.ao_layout,
            uniform,
            &Self::ao_views(&level_views, &packed_view, None),
        );
        let blur_h_group = group(
            device,
            "ocean sao blur horizontal",
            &p.blur_h_layout,
            uniform,
            &[(1, &packed_view), (2, &horizontal_view)],
        );
        let blur_v_group = group(
            device,
            "ocean sao blur vertical",
            &p.blur_v_layout,
            uniform,
            &[(1, &horizontal_view), (3, &ao_view)],
        );
        Self {
            key,
            levels,
            mip_groups,
            packed,
            horizontal,
            ao,
            ao_view,
            ao_group,
            blur_h_group,
            blur_v_group,
            stages: None,
            depth: None,
        }
    }

    /// The sample pass's texture bindings: every level slot (the last level repeated beyond
    /// the hierarchy), the packed output and, for `ao_stages`, the raw and quad outputs.
    fn ao_views<'a>(
        levels: &'a [wgpu::TextureView],
        packed: &'a wgpu::TextureView,
        stages: Option<(&'a wgpu::TextureView, &'a wgpu::TextureView)>,
    ) -> Vec<(u32, &'a wgpu::TextureView)> {
        let last = levels.len() - 1;
        let mut v: Vec<(u32, &wgpu::TextureView)> = (0..LEVEL_SLOTS)
            .map(|m| (m + 1, &levels[(m as usize).min(last)]))
            .collect();
        v.push((PACKED_BINDING, packed));
        if let Some((raw, quad)) = stages {
            v.push((RAW_BINDING, raw));
            v.push((QUAD_BINDING, quad));
        }
        v
    }

    /// The raw and quad textures and the `ao_stages` bind group (call inside
    /// [`crate::scoped`]; store them in [`Targets::stages`] once that succeeded).
    pub(crate) fn make_stages(
        &self,
        device: &wgpu::Device,
        p: &Pipelines,
        uniform: &wgpu::Buffer,
    ) -> StageTargets {
        let r32f = wgpu::TextureFormat::R32Float;
        let raw = texture(device, "ocean sao raw", self.key.output, r32f);
        let quad = texture(device, "ocean sao quad", self.key.output, r32f);
        let level_views: Vec<wgpu::TextureView> = self.levels.iter().map(view).collect();
        let (packed_view, raw_view, quad_view) = (view(&self.packed), view(&raw), view(&quad));
        let group = group(
            device,
            "ocean sao ao stages",
            &p.ao_stages_layout,
            uniform,
            &Self::ao_views(&level_views, &packed_view, Some((&raw_view, &quad_view))),
        );
        StageTargets { raw, quad, group }
    }

    /// The z pass's bind group kept for `depth`, if `depth` is the texture it was made for.
    pub(crate) fn cached_depth_group(&self, depth: &wgpu::Texture) -> Option<wgpu::BindGroup> {
        match &self.depth {
            Some((t, g)) if t == depth => Some(g.clone()),
            _ => None,
        }
    }

    /// The z pass's bind group for `depth`: its depth aspect (or its only one) in, level 0 out
    /// (call inside [`crate::scoped`]; keep it in [`Targets::depth`] once that succeeded).
    pub(crate) fn make_depth_group(
        &self,
        device: &wgpu::Device,
        p: &Pipelines,
        uniform: &wgpu::Buffer,
        depth: &wgpu::Texture,
    ) -> wgpu::BindGroup {
        let aspect = if depth.format().has_depth_aspect() {
            wgpu::TextureAspect::DepthOnly
        } else {
            wgpu::TextureAspect::All
        };
        let depth_view = depth.create_view(&wgpu::TextureViewDescriptor {
            label: Some("ocean sao depth"),
            dimension: Some(wgpu::TextureViewDimension::D2),
            aspect,
            mip_level_count: Some(1),
            array_layer_count: Some(1),
            ..Default::default()
        });
        let z0 = view(&self.levels[0]);
        group(
            device,
            "ocean sao z",
            &p.level_layout,
            uniform,
            &[(1, &depth_view), (2, &z0)],
        )
    }
}

/// Checks the caller's depth texture against the input size.
pub(crate) fn check_depth_texture(
    depth: &wgpu::Texture,
    input: (u32, u32),
) -> Result<(), GpuError> {
    let bad = |reason: String| {
        Err(GpuError::InvalidResource {
            what: "SAO depth texture",
            reason,
        })
    };
    if !DEPTH_FORMATS.contains(&depth.format()) {
        return bad(format!(
            "format {:?}; the z pass reads {DEPTH_FORMATS:?}",
            depth.format()
        ));
    }
    if depth.dimension() != wgpu::TextureDimension::D2 || depth.depth_or_array_layers() != 1 {
        return bad(format!(
            "a {:?} texture with {} layers; the z pass reads one 2D image",
            depth.dimension(),
            depth.depth_or_array_layers()
        ));
    }
    if depth.sample_count() != 1 {
        return bad(format!(
            "{} samples; resolve it to a single-sampled texture first",
            depth.sample_count()
        ));
    }
    if !depth.usage().contains(wgpu::TextureUsages::TEXTURE_BINDING) {
        return bad("it lacks TEXTURE_BINDING usage".to_owned());
    }
    if (depth.width(), depth.height()) != input {
        return bad(format!(
            "{} x {}, the viewport's input (guard band included) is {} x {}",
            depth.width(),
            depth.height(),
            input.0,
            input.1
        ));
    }
    Ok(())
}

/// Checks that the device can hold the input size and dispatch over it.
pub(crate) fn check_limits(device: &wgpu::Device, u: &SaoUniforms) -> Result<(), GpuError> {
    let limits = device.limits();
    let side = u.input_size[0].max(u.input_size[1]);
    if side > limits.max_texture_dimension_2d {
        return Err(GpuError::TooLarge {
            what: "SAO input side (texels)",
            needed: u64::from(side),
            limit: u64::from(limits.max_texture_dimension_2d),
        });
    }
    let groups = side.div_ceil(TILE);
    if groups > limits.max_compute_workgroups_per_dimension {
        return Err(GpuError::TooLarge {
            what: "SAO workgroups per dimension",
            needed: u64::from(groups),
            limit: u64::from(limits.max_compute_workgroups_per_dimension),
        });
    }
    Ok(())
}

/// Workgroups covering `(width, height)` pixels.
pub(crate) fn groups((width, height): (u32, u32)) -> (u32, u32) {
    (width.div_ceil(TILE), height.div_ceil(TILE))
}
