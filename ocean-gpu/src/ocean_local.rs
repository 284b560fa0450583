//! The local waves of the ocean renderer (Bruneton et al. 2010, §6; CPU twin
//! [`ocean_brdf::local`]): the textures of bindings 7 and 8 of `ocean_common.wgsl` and the
//! per-frame phases of the trains.

use glam::DVec2;
use ocean_brdf::LocalWaves;
use ocean_brdf::variance::wave_variance_term;
use ocean_core::Wave;
use ocean_core::phase::reduce_angle;

use crate::{GpuContext, GpuError};

/// Rows of the trains texture (see `ocean_common.wgsl`).
pub(crate) const TRAIN_ROWS: u32 = 3;

/// The local waves on the device: the fields (open-sea factor and every set's μ) and the
/// trains, with what the host needs to form each frame's phases.
#[derive(Debug)]
pub(crate) struct LocalTextures {
    fields: wgpu::Texture,
    /// Layers of `fields`: the open-sea factor and one per set.
    layers: u32,
    pub fields_view: wgpu::TextureView,
    pub trains_texture: wgpu::Texture,
    pub trains_view: wgpu::TextureView,
    /// The trains in the texture's column order.
    trains: Vec<Wave>,
    /// The trains texture's texels (row 0's phases are filled per frame).
    texels: Vec<[f32; 4]>,
    /// Point (0, 0) of the grid (world x, z), spacing, points per row and rows; `None` for
    /// the empty placeholder.
    grid: Option<(DVec2, f64, u32, u32)>,
}

fn texture(
    device: &wgpu::Device,
    label: &'static str,
    size: (u32, u32, u32),
    format: wgpu::TextureFormat,
) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: Some(label),
        size: wgpu::Extent3d {
            width: size.0,
            height: size.1,
            depth_or_array_layers: size.2,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    })
}

fn array_view(t: &wgpu::Texture) -> wgpu::TextureView {
    t.create_view(&wgpu::TextureViewDescriptor {
        dimension: Some(wgpu::TextureViewDimension::D2Array),
        ..Default::default()
    })
}

/// Writes `texels` (row-major, `width` per row, `rows` rows per layer) into `t` from its
/// origin; `bytes` per texel.
fn write(ctx: &GpuContext, t: &wgpu::Texture, data: &[u8], size: (u32, u32, u32), bytes: u32) {
    ctx.queue().write_texture(
        wgpu::TexelCopyTextureInfo {
            texture: t,
            mip_level: 0,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        data,
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(size.0 * bytes),
            rows_per_image: Some(size.1),
        },
        wgpu::Extent3d {
            width: size.0,
            height: size.1,
            depth_or_array_layers: size.2,
        },
    );
}

impl LocalTextures {
    /// No local waves: a one-texel field that the shader never reads (the grid has no points)
    /// and one train column it never reads (no trains).
    pub fn empty(ctx: &GpuContext) -> Self {
        let device = ctx.device();
        let fields = texture(
            device,
            "ocean local fields",
            (1, 1, 1),
            wgpu::TextureFormat::Rg32Float,
        );
        let trains_texture = texture(
            device,
            "ocean local trains",
            (1, TRAIN_ROWS, 1),
            wgpu::TextureFormat::Rgba32Float,
        );
        Self {
            fields_view: array_view(&fields),
            fields,
            layers: 1,
            trains_view: trains_texture.create_view(&wgpu::TextureViewDescriptor::default()),
            trains_texture,
            trains: Vec::new(),
            texels: Vec::new(),
            grid: None,
        }
    }

    /// Uploads `local`: its open-sea factor and every set's μ as the layers of the fields
    /// texture, its trains (grouped by set) as the columns of the trains texture.
    ///
    /// # Errors
    ///
    /// [`GpuError::TooLarge`] for a grid side or a train count beyond the device's largest 2D
    /// texture, or more sets than its array layers allow (less one).
    pub fn new(ctx: &GpuContext, local: &LocalWaves) -> Result<Self, GpuError> {
        let device = ctx.device();
        let limits = device.limits();
        let (origin, spacing, nx, nz) = local.grid();
        let side = limits.max_texture_dimension_2d;
        for (what, n) in [
            ("local grid points per row", nx),
            ("local grid rows", nz),
            ("local trains", local.train_count()),
        ] {
            if n as u64 > u64::from(side) {
                return Err(GpuError::TooLarge {
                    what,
                    needed: n as u64,
                    limit: u64::from(side),
                });
            }
        }
        let layers = local.set_count() + 1;
        if layers as u64 > u64::from(limits.max_texture_array_layers) {
            return Err(GpuError::TooLarge {
                what: "local wave sets (one texture layer each, plus one)",
                needed: layers as u64,
                limit: u64::from(limits.max_texture_array_layers),
            });
        }
        let Contents {
            field,
            trains,
            texels,
            columns,
        } = Contents::of(local);
        let size = (nx as u32, nz as u32, layers as u32);
        let (fields_view, trains_texture) = crate::scoped(device, || {
            let fields = texture(
                device,
                "ocean local fields",
                size,
                wgpu::TextureFormat::Rg32Float,
            );
            write(ctx, &fields, bytemuck::cast_slice(&field), size, 8);
            let trains_texture = texture(
                device,
                "ocean local trains",
                (columns as u32, TRAIN_ROWS, 1),
                wgpu::TextureFormat::Rgba32Float,
            );
            write(
                ctx,
                &trains_texture,
                bytemuck::cast_slice(&texels),
                (columns as u32, TRAIN_ROWS, 1),
                16,
            );
            Ok((fields, trains_texture))
        })?;
        Ok(Self {
            fields_view: array_view(&fields_view),
            fields: fields_view,
            layers: layers as u32,
            trains_view: trains_texture.create_view(&wgpu::TextureViewDescriptor::default()),
            trains_texture,
            trains,
            texels,
            grid: Some((origin, spacing, nx as u32, nz as u32)),
        })
    }

    /// Writes `local` into these textures if it has their shape (the grid's size, the number
    /// of sets and of trains): the per-frame case of boxes whose μ and trains change while the
    /// scene stays. Returns whether it did; `false` leaves everything as it was (make new
    /// textures with [`LocalTextures::new`] then).
    pub fn rewrite(&mut self, ctx: &GpuContext, local: &LocalWaves) -> bool {
        let (origin, spacing, nx, nz) = local.grid();
        let same = self
            .grid
            .is_some_and(|(_, _, gx, gz)| (gx as usize, gz as usize) == (nx, nz))
            && self.layers as usize == local.set_count() + 1
            && self.trains.len() == local.train_count();
        if !same {
            return false;
        }
        let Contents {
            field,
            trains,
            texels,
            columns,
        } = Contents::of(local);
        write(
            ctx,
            &self.fields,
            bytemuck::cast_slice(&field),
            (nx as u32, nz as u32, self.layers),
            8,
        );
        write(
            ctx,
            &self.trains_texture,
            bytemuck::cast_slice(&texels),
            (columns as u32, TRAIN_ROWS, 1),
            16,
        );
        self.trains = trains;
        self.texels = texels;
        self.grid = Some((origin, spacing, nx as u32, nz as u32));
        true
    }

    /// The uniform block's `local` and `local_counts` for a frame centred on `o`.
    pub fn uniform(&self, o: DVec2) -> ([f32; 4], [u32; 4]) {
        match self.grid {
            Some((origin, spacing, nx, nz)) => {
                let d = origin - o;
                (
                    [d.x as f32, d.y as f32, (1.0 / spacing) as f32, 0.0],
                    [nx, nz, self.trains.len() as u32, 0],
                )
            }
            None => ([0.0, 0.0, 1.0, 0.0], [0, 0, 0, 0]),
        }
    }

    /// Row 0 of the trains texture for a frame centred on `o` at `time`: θ₀ = k·o − ωt + Φ
    /// reduced modulo 2π in `f64`, as for the open sea's waves.
    pub fn phases(&self, o: DVec2, time: f64) -> Vec<[f32; 4]> {
        self.trains
            .iter()
            .zip(&self.texels)
            .map(|(w, t)| [t[0], t[1], t[2], reduce_angle(w.phase_at(o, time)) as f32])
            .collect()
    }

    /// Writes a frame's phases (from [`phases`](Self::phases)) into the trains texture.
    pub fn write_phases(&self, ctx: &GpuContext, phases: &[[f32; 4]]) {
        if !phases.is_empty() {
            write(
                ctx,
                &self.trains_texture,
                bytemuck::cast_slice(phases),
                (phases.len() as u32, 1, 1),
                16,
            );
        }
    }

    /// A trains texture of its own holding `phases` (for the probes, which must not change
    /// what a recorded frame will read).
    pub fn view_with_phases(&self, ctx: &GpuContext, phases: &[[f32; 4]]) -> wgpu::TextureView {
        let columns = self.trains.len().max(1) as u32;
        let t = texture(
            ctx.device(),
            "ocean probe local trains",
            (columns, TRAIN_ROWS, 1),
            wgpu::TextureFormat::Rgba32Float,
        );
        let mut texels = self.texels.clone();
        if texels.is_empty() {
            texels = vec![[0.0; 4]; TRAIN_ROWS as usize];
        }
        texels[..phases.len()].copy_from_slice(phases);
        write(
            ctx,
            &t,
            bytemuck::cast_slice(&texels),
            (columns, TRAIN_ROWS, 1),
            16,
        );
        t.create_view(&wgpu::TextureViewDescriptor::default())
    }
}

/// What the textures hold for some local waves.
struct Contents {
    /// The fields texture's texels, layer after layer: the open-sea factor, then each set's μ.
    field: Vec<[f32; 2]>,
    /// The trains in column order.
    trains: Vec<Wave>,
    /// The trains texture's texels (three rows of `columns`; row 0's phases filled per frame).
    texels: Vec<[f32; 4]>,
    /// Columns of the trains texture (at least 1).
    columns: usize,
}

impl Contents {
    fn of(local: &LocalWaves) -> Self {
        let (_, _, nx, nz) = local.grid();
        let mut field = Vec::with_capacity(nx * nz * (local.set_count() + 1));
        field.extend(local.open_scale().iter().map(|&s| [s, 0.0]));
        let mut trains = Vec::new();
        let mut rows12 = Vec::new();
        for k in 0..local.set_count() {
            let Some((waves, mu)) = local.set(k) else {
                break;
            };
            field.extend_from_slice(mu);
            for w in waves.waves() {
                let (kv, m, a) = (w.wave_vector(), w.wavenumber(), w.amplitude());
                let (ka, cos2) = wave_variance_term(w, local.wind());
                rows12.push((
                    [
                        a as f32,
                        (a * kv.x / m) as f32,
                        (a * kv.y / m) as f32,
                        k as f32,
                    ],
                    [ka as f32, cos2 as f32, 0.0, 0.0],
                ));
                trains.push(*w);
            }
        }
        let columns = trains.len().max(1);
        let mut texels = vec![[0.0f32; 4]; columns * TRAIN_ROWS as usize];
        for (j, (w, (r1, r2))) in trains.iter().zip(&rows12).enumerate() {
            let k = w.wave_vector();
            texels[j] = [w.wavelength() as f32, k.x as f32, k.y as f32, 0.0];
            texels[columns + j] = *r1;
            texels[2 * columns + j] = *r2;
        }
        Self {
            field,
            trains,
            texels,
            columns,
        }
    }
}
