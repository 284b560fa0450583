//! Readback helpers of `ocean_gpu::readback` on a real device: buffers, textures whose rows
//! need padding to 256 bytes, and argument checking.

use ocean_gpu::readback::{read_buffer, read_buffer_as, read_texture};
use ocean_gpu::wgpu;
use ocean_gpu::{GpuError, GpuTimer};
use ocean_tests::gpu_context_or_skip;

#[test]
fn buffer_round_trip() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let values: Vec<f32> = (0..1000).map(|i| i as f32 * 0.25 - 7.0).collect();
    let buf = ctx.device().create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: 4000,
        usage: wgpu::BufferUsages::COPY_SRC | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    ctx.queue()
        .write_buffer(&buf, 0, bytemuck::cast_slice(&values));
    let back: Vec<f32> = read_buffer_as(&ctx, &buf).unwrap();
    assert_eq!(back, values);
    // A sub-range: values 10..20 are bytes 40..80.
    let part = read_buffer(&ctx, &buf, 40, 40).unwrap();
    assert_eq!(bytemuck::cast_slice::<u8, f32>(&part), &values[10..20]);
    // Misaligned, out-of-range and empty ranges are errors.
    assert!(matches!(
        read_buffer(&ctx, &buf, 2, 8),
        Err(GpuError::InvalidResource { .. })
    ));
    assert!(matches!(
        read_buffer(&ctx, &buf, 3996, 8),
        Err(GpuError::InvalidResource { .. })
    ));
    assert!(matches!(
        read_buffer(&ctx, &buf, 0, 0),
        Err(GpuError::InvalidResource { .. })
    ));
    let no_copy = ctx.device().create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: 16,
        usage: wgpu::BufferUsages::UNIFORM,
        mapped_at_creation: false,
    });
    assert!(read_buffer(&ctx, &no_copy, 0, 16).is_err());
}

/// 37 × 5 rgba8 texels: 148 bytes per row, copied with a 256-byte pitch; the readback must
/// return exactly the 148 · 5 bytes written, with no padding bytes.
#[test]
fn texture_rows_are_unpadded() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    let (w, h) = (37u32, 5u32);
    let texture = ctx.device().create_texture(&wgpu::TextureDescriptor {
        label: None,
        size: wgpu::Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Rgba8Unorm,
        usage: wgpu::TextureUsages::COPY_SRC | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    let data: Vec<u8> = (0..w * h * 4).map(|i| (i * 7 % 251) as u8).collect();
    ctx.queue().write_texture(
        wgpu::TexelCopyTextureInfo {
            texture: &texture,
            mip_level: 0,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        &data,
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(w * 4),
            rows_per_image: Some(h),
        },
        texture.size(),
    );
    let back = read_texture(&ctx, &texture, 0).unwrap();
    assert_eq!(back.layout.unpadded_bytes_per_row, 148);
    assert_eq!(back.layout.padded_bytes_per_row, 256);
    assert_eq!(back.data.len(), 148 * 5);
    assert_eq!(back.data, data);
    assert!(
        read_texture(&ctx, &texture, 1).is_err(),
        "mip 1 does not exist"
    );
}

#[test]
fn timer_exists_iff_timestamps_supported() {
    let Some(ctx) = gpu_context_or_skip() else {
        return;
    };
    assert_eq!(GpuTimer::new(&ctx).is_some(), ctx.supports_timestamps());
}
