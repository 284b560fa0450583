//! The compute pipeline shape shared by the grid passes.

use crate::{GpuError, shaders};

/// The pipeline and bind group layout of a registered grid pass: entry point `displace`, a
/// uniform block of `uniform_size` bytes at binding 0, read-only storage buffers at bindings 1
/// and 2 (the pass's inputs) and read-write ones at 3 and 4 (positions and normals, the
/// layout of [`crate::TrochoidTarget`]).
pub(crate) fn displace_pipeline(
    device: &wgpu::Device,
    shader: &str,
    uniform_size: usize,
) -> Result<(wgpu::ComputePipeline, wgpu::BindGroupLayout), GpuError> {
    let (mut pipelines, layout) = compute_pipelines(device, shader, uniform_size, &["displace"])?;
    Ok((pipelines.remove(0), layout))
}

/// One pipeline per entry point of a registered compute shader, all on the bind group layout of
/// [`displace_pipeline`] (a uniform block, two read-only and two read-write storage buffers).
pub(crate) fn compute_pipelines(
    device: &wgpu::Device,
    shader: &str,
    uniform_size: usize,
    entry_points: &[&str],
) -> Result<(Vec<wgpu::ComputePipeline>, wgpu::BindGroupLayout), GpuError> {
    compute_pipelines_with(
        device,
        shader,
        uniform_size,
        &[true, true, false, false],
        entry_points,
    )
}

/// [`compute_pipelines`] on a layout of a uniform block at binding 0 and one storage buffer per
/// entry of `read_only` from binding 1 (`true`: read-only).
pub(crate) fn compute_pipelines_with(
    device: &wgpu::Device,
    shader: &str,
    uniform_size: usize,
    read_only: &[bool],
    entry_points: &[&str],
) -> Result<(Vec<wgpu::ComputePipeline>, wgpu::BindGroupLayout), GpuError> {
    let entry = shaders::get(shader).ok_or_else(|| {
        GpuError::Shader(shaders::ShaderError::UnknownShader {
            name: shader.to_owned(),
            available: String::new(),
        })
    })?;
    let label = |what: &str| format!("ocean {shader} {what}");
    crate::scoped(device, || {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(&label("shader")),
            source: wgpu::ShaderSource::Wgsl(entry.source.into()),
        });
        let buffer = |binding, ty, min_binding_size| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty,
                has_dynamic_offset: false,
                min_binding_size,
            },
            count: None,
        };
        let storage = |read_only| wgpu::BufferBindingType::Storage { read_only };
        let mut entries = vec![buffer(
            0,
            wgpu::BufferBindingType::Uniform,
            wgpu::BufferSize::new(uniform_size as u64),
        )];
        for (n, &ro) in read_only.iter().enumerate() {
            entries.push(buffer(n as u32 + 1, storage(ro), None));
        }
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some(&label("bind group layout")),
            entries: &entries,
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(&label("pipeline layout")),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipelines = entry_points
            .iter()
            .map(|entry| {
                device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                    label: Some(&label(entry)),
                    layout: Some(&pipeline_layout),
                    module: &module,
                    entry_point: Some(entry),
                    compilation_options: wgpu::PipelineCompilationOptions::default(),
                    cache: None,
                })
            })
            .collect();
        Ok((pipelines, layout))
    })
}

/// Bind groups a displacement pass keeps (`TrochoidPass`, `LayersPass`; the least recently used
/// is evicted first).
pub(crate) const BIND_GROUP_CACHE: usize = 4;

/// Bind groups kept for the targets a grid pass wrote last, least recently used first: a frame
/// loop that alternates between a few targets builds each bind group once.
#[derive(Debug, Default)]
pub(crate) struct BindGroupCache {
    entries: Vec<CachedBindGroup>,
}

#[derive(Debug)]
struct CachedBindGroup {
    positions: wgpu::Buffer,
    normals: wgpu::Buffer,
    out_size: u64,
    group: wgpu::BindGroup,
}

impl BindGroupCache {
    /// Forgets every bind group (the input buffers they hold were replaced).
    pub(crate) fn clear(&mut self) {
        self.entries.clear();
    }

    /// The bind group of a [`displace_pipeline`] layout over `inputs` (bindings 0, 1 and 2) and
    /// `target` (3 and 4, `out_size` bytes each), and whether it had to be created. At most
    /// [`BIND_GROUP_CACHE`] are kept.
    pub(crate) fn get(
        &mut self,
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        label: &str,
        inputs: [&wgpu::Buffer; 3],
        target: &crate::TrochoidTarget,
        out_size: u64,
    ) -> (wgpu::BindGroup, bool) {
        let hit = self.entries.iter().position(|c| {
            c.positions == target.positions && c.normals == target.normals && c.out_size == out_size
        });
        if let Some(i) = hit {
            let cached = self.entries.remove(i);
            let group = cached.group.clone();
            self.entries.push(cached);
            return (group, false);
        }
        let output = |buffer| {
            wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                buffer,
                offset: 0,
                size: wgpu::BufferSize::new(out_size),
            })
        };
        let entry = |binding, resource| wgpu::BindGroupEntry { binding, resource };
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(label),
            layout,
            entries: &[
                entry(0, inputs[0].as_entire_binding()),
                entry(1, inputs[1].as_entire_binding()),
                entry(2, inputs[2].as_entire_binding()),
                entry(3, output(&target.positions)),
                entry(4, output(&target.normals)),
            ],
        });
        if self.entries.len() == BIND_GROUP_CACHE {
            self.entries.remove(0);
        }
        self.entries.push(CachedBindGroup {
            positions: target.positions.clone(),
            normals: target.normals.clone(),
            out_size,
            group: group.clone(),
        });
        (group, true)
    }
}

/// Checks that `texture` can be a single-sampled render target of `format` (exactly: a pipeline's
/// colour target format must be its attachment's, and an sRGB twin would fail wgpu's
/// validation when the pass is recorded, past any error scope) for a viewport of `size`; `what`
/// names it in the error.
pub(crate) fn check_render_target(
    what: &'static str,
    texture: &wgpu::Texture,
    format: wgpu::TextureFormat,
    size: (u32, u32),
) -> Result<(), GpuError> {
    check_render_target_samples(what, texture, format, size, 1)
}

/// As [`check_render_target`], for a target of `samples` samples per pixel.
pub(crate) fn check_render_target_samples(
    what: &'static str,
    texture: &wgpu::Texture,
    format: wgpu::TextureFormat,
    size: (u32, u32),
    samples: u32,
) -> Result<(), GpuError> {
    let t = texture;
    if t.format() != format {
        return Err(GpuError::InvalidResource {
            what,
            reason: format!("format {:?}, the renderer draws {format:?}", t.format()),
        });
    }
    if !t.usage().contains(wgpu::TextureUsages::RENDER_ATTACHMENT) {
        return Err(GpuError::InvalidResource {
            what,
            reason: "needs RENDER_ATTACHMENT usage".to_owned(),
        });
    }
    if t.sample_count() != samples || t.width() < size.0 || t.height() < size.1 {
        return Err(GpuError::InvalidResource {
            what,
            reason: format!(
                "{} x {} with {} samples cannot hold a {} x {} viewport of {samples} sample{}",
                t.width(),
                t.height(),
                t.sample_count(),
                size.0,
                size.1,
                if samples == 1 { "" } else { "s" }
            ),
        });
    }
    Ok(())
}
