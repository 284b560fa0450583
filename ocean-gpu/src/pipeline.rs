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
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some(&label("bind group layout")),
            entries: &[
                buffer(
                    0,
                    wgpu::BufferBindingType::Uniform,
                    wgpu::BufferSize::new(uniform_size as u64),
                ),
                buffer(1, storage(true), None),
                buffer(2, storage(true), None),
                buffer(3, storage(false), None),
                buffer(4, storage(false), None),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(&label("pipeline layout")),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(&label("pipeline")),
            layout: Some(&pipeline_layout),
            module: &module,
            entry_point: Some("displace"),
            compilation_options: wgpu::PipelineCompilationOptions::default(),
            cache: None,
        });
        Ok((pipeline, layout))
    })
}
