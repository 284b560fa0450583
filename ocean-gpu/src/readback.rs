//! Copying GPU results back to the CPU, and GPU timestamps.
//!
//! Buffer-to-buffer copies need sizes that are multiples of [`wgpu::COPY_BUFFER_ALIGNMENT`]
//! (4 bytes); texture-to-buffer copies need every row to start at a multiple of
//! [`wgpu::COPY_BYTES_PER_ROW_ALIGNMENT`] (256 bytes), so rows are copied padded and the padding
//! is stripped here ([`TextureLayout`]).

use std::sync::mpsc;

use crate::{GpuContext, GpuError};

/// Waits for `slice` to be mapped for reading.
fn map_read(ctx: &GpuContext, slice: wgpu::BufferSlice<'_>) -> Result<(), GpuError> {
    let (tx, rx) = mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |r| {
        // The receiver outlives the poll below; a send error cannot happen, and if it did the
        // `recv` below reports it.
        let _ = tx.send(r);
    });
    ctx.device().poll(wgpu::PollType::wait_indefinitely())?;
    match rx.recv() {
        Ok(r) => Ok(r?),
        Err(_) => Err(GpuError::Wgpu(
            "buffer mapping callback was dropped without running".to_owned(),
        )),
    }
}

/// Copies `size` bytes of `buffer` from `offset` into a new `Vec`, through a staging buffer.
///
/// `buffer` needs [`wgpu::BufferUsages::COPY_SRC`]; `offset` and `size` must be multiples of 4
/// ([`wgpu::COPY_BUFFER_ALIGNMENT`]) and inside the buffer.
pub fn read_buffer(
    ctx: &GpuContext,
    buffer: &wgpu::Buffer,
    offset: u64,
    size: u64,
) -> Result<Vec<u8>, GpuError> {
    let invalid = |reason: String| GpuError::InvalidResource {
        what: "readback buffer range",
        reason,
    };
    if !buffer.usage().contains(wgpu::BufferUsages::COPY_SRC) {
        return Err(invalid("the buffer lacks COPY_SRC usage".to_owned()));
    }
    if size == 0
        || !offset.is_multiple_of(wgpu::COPY_BUFFER_ALIGNMENT)
        || !size.is_multiple_of(wgpu::COPY_BUFFER_ALIGNMENT)
    {
        return Err(invalid(format!(
            "offset {offset} and size {size} must be non-zero multiples of {}",
            wgpu::COPY_BUFFER_ALIGNMENT
        )));
    }
    if offset
        .checked_add(size)
        .is_none_or(|end| end > buffer.size())
    {
        return Err(invalid(format!(
            "bytes {offset}..{offset}+{size} exceed the buffer's {} bytes",
            buffer.size()
        )));
    }
    let device = ctx.device();
    let staging = crate::scoped(device, || {
        let staging = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("ocean-gpu readback staging"),
            size,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let mut enc = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("ocean-gpu readback"),
        });
        enc.copy_buffer_to_buffer(buffer, offset, &staging, 0, size);
        ctx.queue().submit([enc.finish()]);
        Ok(staging)
    })?;
    let slice = staging.slice(..);
    map_read(ctx, slice)?;
    let data = slice
        .get_mapped_range()
        .map_err(|e| GpuError::Wgpu(e.to_string()))?
        .to_vec();
    staging.unmap();
    Ok(data)
}

/// Reads a whole buffer of plain values (`f32`, `[f32; 4]`, ...) back as a `Vec<T>`.
pub fn read_buffer_as<T: bytemuck::Pod>(
    ctx: &GpuContext,
    buffer: &wgpu::Buffer,
) -> Result<Vec<T>, GpuError> {
    let bytes = read_buffer(ctx, buffer, 0, buffer.size())?;
    let elem = std::mem::size_of::<T>();
    if elem == 0 || bytes.len() % elem != 0 {
        return Err(GpuError::InvalidResource {
            what: "readback buffer",
            reason: format!(
                "{} bytes is not a whole number of {elem}-byte values",
                bytes.len()
            ),
        });
    }
    // `pod_collect_to_vec` copies, so the staging data need not be aligned for `T`.
    Ok(bytemuck::pod_collect_to_vec(&bytes))
}

/// How the rows of a texture copy lie in a buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TextureLayout {
    /// Width in texels.
    pub width: u32,
    /// Height in texels (rows per layer).
    pub height: u32,
    /// Array layers (or depth slices).
    pub layers: u32,
    /// Bytes per texel.
    pub bytes_per_texel: u32,
    /// Bytes of texel data per row: `width * bytes_per_texel`.
    pub unpadded_bytes_per_row: u32,
    /// Row pitch in the copy buffer: the unpadded size rounded up to
    /// [`wgpu::COPY_BYTES_PER_ROW_ALIGNMENT`] (256).
    pub padded_bytes_per_row: u32,
}

impl TextureLayout {
    /// The layout of a `width × height × layers` copy of `bytes_per_texel`-byte texels, or an
    /// error if a dimension is zero or a size overflows `u32` row pitches / `u64` totals.
    pub fn new(
        width: u32,
        height: u32,
        layers: u32,
        bytes_per_texel: u32,
    ) -> Result<Self, GpuError> {
        if width == 0 || height == 0 || layers == 0 || bytes_per_texel == 0 {
            return Err(GpuError::InvalidResource {
                what: "texture copy",
                reason: format!(
                    "empty copy: {width} x {height} x {layers} texels of {bytes_per_texel} bytes"
                ),
            });
        }
        let too_large = |needed: u64| GpuError::TooLarge {
            what: "texture row pitch",
            needed,
            limit: u64::from(u32::MAX),
        };
        let unpadded = u64::from(width) * u64::from(bytes_per_texel);
        let align = u64::from(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
        let padded = unpadded.div_ceil(align) * align;
        let unpadded_bytes_per_row = u32::try_from(unpadded).map_err(|_| too_large(unpadded))?;
        let padded_bytes_per_row = u32::try_from(padded).map_err(|_| too_large(padded))?;
        Ok(Self {
            width,
            height,
            layers,
            bytes_per_texel,
            unpadded_bytes_per_row,
            padded_bytes_per_row,
        })
    }

    /// Bytes of the padded copy buffer. The last row needs no padding, but the whole padded
    /// size is used so every row can be sliced the same way.
    pub fn padded_size(&self) -> u64 {
        u64::from(self.padded_bytes_per_row) * u64::from(self.height) * u64::from(self.layers)
    }

    /// Bytes of tightly packed texel data.
    pub fn unpadded_size(&self) -> u64 {
        u64::from(self.unpadded_bytes_per_row) * u64::from(self.height) * u64::from(self.layers)
    }

    /// Strips the row padding from `padded` (at least [`TextureLayout::padded_size`] bytes).
    pub fn unpad(&self, padded: &[u8]) -> Result<Vec<u8>, GpuError> {
        let need = self.padded_size();
        if (padded.len() as u64) < need {
            return Err(GpuError::InvalidResource {
                what: "padded texture data",
                reason: format!("{} bytes, expected at least {need}", padded.len()),
            });
        }
        let pitch = self.padded_bytes_per_row as usize;
        let row = self.unpadded_bytes_per_row as usize;
        let rows = self.height as usize * self.layers as usize;
        let mut out = Vec::with_capacity(row * rows);
        for r in padded.chunks_exact(pitch).take(rows) {
            out.extend_from_slice(&r[..row]);
        }
        Ok(out)
    }
}

/// Tightly packed texels read back from a texture.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureData {
    /// The copy's layout (the `data` below is unpadded).
    pub layout: TextureLayout,
    /// The texture's format.
    pub format: wgpu::TextureFormat,
    /// Texels, row-major, `layout.unpadded_bytes_per_row` bytes per row, layer after layer.
    pub data: Vec<u8>,
}

/// Reads mip level `mip` of every layer of `texture` (which needs
/// [`wgpu::TextureUsages::COPY_SRC`] and an uncompressed colour format, or a depth format
/// whose depth aspect can be copied, such as `Depth32Float`: its depth is read).
pub fn read_texture(
    ctx: &GpuContext,
    texture: &wgpu::Texture,
    mip: u32,
) -> Result<TextureData, GpuError> {
    let invalid = |reason: String| GpuError::InvalidResource {
        what: "readback texture",
        reason,
    };
    if !texture.usage().contains(wgpu::TextureUsages::COPY_SRC) {
        return Err(invalid("the texture lacks COPY_SRC usage".to_owned()));
    }
    if mip >= texture.mip_level_count() {
        return Err(invalid(format!(
            "mip level {mip} of a texture with {} levels",
            texture.mip_level_count()
        )));
    }
    let format = texture.format();
    let aspect = if format.has_depth_aspect() {
        wgpu::TextureAspect::DepthOnly
    } else {
        wgpu::TextureAspect::All
    };
    let bytes_per_texel = match (
        format.block_dimensions(),
        format.block_copy_size(Some(aspect)),
    ) {
        ((1, 1), Some(b)) if texture.sample_count() == 1 => b,
        _ => {
            return Err(invalid(format!(
                "format {format:?} with {} samples: compressed, multisampled, stencil or a \
                 depth that cannot be copied",
                texture.sample_count()
            )));
        }
    };
    let size = texture.size();
    let layers = match texture.dimension() {
        wgpu::TextureDimension::D3 => (size.depth_or_array_layers >> mip).max(1),
        _ => size.depth_or_array_layers,
    };
    let width = (size.width >> mip).max(1);
    let height = (size.height >> mip).max(1);
    let layout = TextureLayout::new(width, height, layers, bytes_per_texel)?;
    let device = ctx.device();
    let staging = crate::scoped(device, || {
        let staging = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("ocean-gpu texture readback staging"),
            size: layout.padded_size(),
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let mut enc = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("ocean-gpu texture readback"),
        });
        enc.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture,
                mip_level: mip,
                origin: wgpu::Origin3d::ZERO,
                aspect,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &staging,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(layout.padded_bytes_per_row),
                    rows_per_image: Some(height),
                },
            },
            wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: layers,
            },
        );
        ctx.queue().submit([enc.finish()]);
        Ok(staging)
    })?;
    let slice = staging.slice(..);
    map_read(ctx, slice)?;
    let data = {
        let view = slice
            .get_mapped_range()
            .map_err(|e| GpuError::Wgpu(e.to_string()))?;
        layout.unpad(&view)?
    };
    staging.unmap();
    Ok(TextureData {
        layout,
        format,
        data,
    })
}

/// A GPU time interval.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct GpuDuration {
    /// Nanoseconds.
    pub ns: f64,
}

impl GpuDuration {
    /// Milliseconds.
    pub fn ms(&self) -> f64 {
        self.ns * 1e-6
    }

    /// Converts a pair of raw timestamps to a duration: `(end - begin) * period` nanoseconds,
    /// with `period` from [`wgpu::Queue::get_timestamp_period`]. Timestamps that went backwards
    /// (some drivers reset the counter between passes) give `None`.
    pub fn from_ticks(begin: u64, end: u64, period_ns: f32) -> Option<Self> {
        let ticks = end.checked_sub(begin)?;
        Some(Self {
            ns: ticks as f64 * f64::from(period_ns),
        })
    }
}

/// Measures the GPU time of passes with timestamp queries.
///
/// Available only when the device has [`wgpu::Features::TIMESTAMP_QUERY`] (lavapipe and most
/// Vulkan, Metal and D3D12 drivers; not wgpu's GL backend): [`GpuTimer::new`] returns `None`
/// otherwise, and callers simply report no GPU time.
///
/// Use: pass [`GpuTimer::compute_pass_writes`] as the `timestamp_writes` of one compute pass,
/// call [`GpuTimer::resolve`] on the same encoder after the pass, submit, then
/// [`GpuTimer::read`].
#[derive(Debug)]
pub struct GpuTimer {
    queries: wgpu::QuerySet,
    resolve: wgpu::Buffer,
    period_ns: f32,
}

impl GpuTimer {
    /// A timer for one pass, or `None` when the device cannot write timestamps.
    pub fn new(ctx: &GpuContext) -> Option<Self> {
        if !ctx.supports_timestamps() {
            return None;
        }
        let device = ctx.device();
        let queries = device.create_query_set(&wgpu::QuerySetDescriptor {
            label: Some("ocean-gpu timer"),
            ty: wgpu::QueryType::Timestamp,
            count: 2,
        });
        let resolve = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("ocean-gpu timer resolve"),
            size: 2 * wgpu::QUERY_SIZE as u64,
            usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        Some(Self {
            queries,
            resolve,
            period_ns: ctx.queue().get_timestamp_period(),
        })
    }

    /// Timestamps written at the beginning and end of a compute pass.
    pub fn compute_pass_writes(&self) -> wgpu::ComputePassTimestampWrites<'_> {
        wgpu::ComputePassTimestampWrites {
            query_set: &self.queries,
            beginning_of_pass_write_index: Some(0),
            end_of_pass_write_index: Some(1),
        }
    }

    /// Timestamps written at the beginning and end of a render pass.
    pub fn render_pass_writes(&self) -> wgpu::RenderPassTimestampWrites<'_> {
        wgpu::RenderPassTimestampWrites {
            query_set: &self.queries,
            beginning_of_pass_write_index: Some(0),
            end_of_pass_write_index: Some(1),
        }
    }

    /// Records the copy of both timestamps into the timer's buffer; call after the pass ends.
    pub fn resolve(&self, encoder: &mut wgpu::CommandEncoder) {
        encoder.resolve_query_set(&self.queries, 0..2, &self.resolve, 0);
    }

    /// The pass's GPU time, after the resolving submission (waits for it). `None` when the
    /// counter went backwards (see [`GpuDuration::from_ticks`]).
    pub fn read(&self, ctx: &GpuContext) -> Result<Option<GpuDuration>, GpuError> {
        let ticks: Vec<u64> = read_buffer_as(ctx, &self.resolve)?;
        Ok(match ticks.as_slice() {
            &[begin, end] => GpuDuration::from_ticks(begin, end, self.period_ns),
            _ => None,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_pad_to_256_bytes() {
        // COPY_BYTES_PER_ROW_ALIGNMENT is 256: a row pitch is the texel bytes rounded up to it.
        let cases = [
            // (width, bytes per texel, expected unpadded, expected padded)
            (1, 4, 4, 256),     // one rgba8 texel still takes a whole 256-byte row
            (64, 4, 256, 256),  // exactly aligned: no padding
            (65, 4, 260, 512),  // one texel over: a second 256-byte block
            (100, 4, 400, 512), // r32float, 100 wide
            (37, 16, 592, 768), // rgba32float
            (256, 1, 256, 256), // r8
        ];
        for (w, b, unpadded, padded) in cases {
            let l = TextureLayout::new(w, 3, 2, b).unwrap();
            assert_eq!(l.unpadded_bytes_per_row, unpadded, "width {w}, {b} B/texel");
            assert_eq!(l.padded_bytes_per_row, padded, "width {w}, {b} B/texel");
            assert_eq!(l.padded_size(), u64::from(padded) * 6);
            assert_eq!(l.unpadded_size(), u64::from(unpadded) * 6);
        }
    }

    #[test]
    fn empty_and_overflowing_copies_are_errors() {
        assert!(TextureLayout::new(0, 1, 1, 4).is_err());
        assert!(TextureLayout::new(1, 0, 1, 4).is_err());
        assert!(TextureLayout::new(1, 1, 0, 4).is_err());
        assert!(TextureLayout::new(1, 1, 1, 0).is_err());
        // 2^30 texels of 16 bytes: 2^34 bytes per row, beyond a u32 row pitch.
        assert!(matches!(
            TextureLayout::new(1 << 30, 1, 1, 16),
            Err(GpuError::TooLarge { .. })
        ));
    }

    #[test]
    fn unpad_keeps_texels_and_drops_padding() {
        // 3 texels of 4 bytes = 12 data bytes per row, padded to 256; 2 rows x 2 layers.
        let l = TextureLayout::new(3, 2, 2, 4).unwrap();
        let mut padded = vec![0xEEu8; l.padded_size() as usize];
        for r in 0..4 {
            for b in 0..12 {
                padded[r * 256 + b] = (r * 12 + b) as u8;
            }
        }
        let out = l.unpad(&padded).unwrap();
        let expected: Vec<u8> = (0..48).collect();
        assert_eq!(out, expected, "padding bytes (0xEE) must not survive");
        assert!(l.unpad(&padded[..padded.len() - 1]).is_err());
    }

    #[test]
    fn timestamp_ticks_scale_by_period() {
        // 1000 ticks at 1.5 ns per tick is 1.5 µs = 0.0015 ms.
        let d = GpuDuration::from_ticks(500, 1500, 1.5).unwrap();
        assert_eq!(d.ns, 1500.0);
        assert!((d.ms() - 0.0015).abs() < 1e-15);
        assert_eq!(GpuDuration::from_ticks(10, 9, 1.0), None);
    }
}
