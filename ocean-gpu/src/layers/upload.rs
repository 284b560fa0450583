//! The host side of one run of the layers pass: the layer descriptions and the packed data
//! words (coefficients, sine and cosine tables, modulations) it uploads, and the buffers they
//! grow into.

use super::*;

/// The input buffers of a pass, host staging areas, and the bind groups built on them.
#[derive(Debug)]
pub(super) struct Inputs {
    pub(super) params: wgpu::Buffer,
    pub(super) descs: wgpu::Buffer,
    pub(super) data: wgpu::Buffer,
    /// The descriptors as uploaded; kept to avoid a host allocation per run.
    pub(super) desc_scratch: Vec<LayerDesc>,
    /// Coefficients and rectangle tables of every layer, as uploaded to the start of `data`.
    pub(super) scratch: Vec<f32>,
    /// One layer's full-grid tables from [`ocean_core::WaveSet::grid_sin_cos`] (rows, then
    /// columns).
    pub(super) full_tables: Vec<[f32; 2]>,
    /// Least recently used first.
    pub(super) bind_groups: crate::pipeline::BindGroupCache,
    pub(super) stats: LayersStats,
}

/// Everything one dispatch needs besides the data, checked on the host.
pub(super) struct Prepared {
    pub(super) params: LayersParams,
    pub(super) groups: (u32, u32),
    pub(super) points: u64,
    /// Words of coefficients and tables (the start of `data`, staged in `scratch`).
    pub(super) scratch_words: u64,
    /// Words of `data` the run uses.
    pub(super) data_words: u64,
    /// Largest binding the device allows, bytes.
    pub(super) binding_limit: u64,
}

impl Inputs {
    pub(super) fn new(device: &wgpu::Device) -> Self {
        let storage = wgpu::BufferUsages::STORAGE;
        Self {
            params: input_buffer(
                device,
                "ocean layers params",
                std::mem::size_of::<LayersParams>() as u64,
                wgpu::BufferUsages::UNIFORM,
            ),
            descs: input_buffer(
                device,
                "ocean layers descriptors",
                INITIAL_LAYERS * DESC_STRIDE,
                storage,
            ),
            data: input_buffer(
                device,
                "ocean layers data",
                INITIAL_DATA_WORDS * WORD,
                storage,
            ),
            desc_scratch: Vec::new(),
            scratch: Vec::new(),
            full_tables: Vec::new(),
            bind_groups: Default::default(),
            stats: LayersStats {
                buffers_created: 3,
                bind_groups_created: 0,
                layer_capacity: INITIAL_LAYERS,
                data_capacity: INITIAL_DATA_WORDS,
            },
        }
    }

    /// Replaces the descriptor and data buffers that are too small for `p` (their contents are
    /// rewritten by every run, so nothing is copied). Cached bind groups refer to the old
    /// buffers and are dropped with them.
    pub(super) fn reserve(&mut self, device: &wgpu::Device, p: &Prepared) -> Result<(), GpuError> {
        let [descs, data] = grow_inputs(
            device,
            [
                (
                    &mut self.descs,
                    u64::from(p.params.layers) * DESC_STRIDE,
                    "ocean layers descriptors",
                ),
                (&mut self.data, p.data_words * WORD, "ocean layers data"),
            ],
            p.binding_limit,
        )?;
        if descs {
            self.stats.layer_capacity = self.descs.size() / DESC_STRIDE;
            self.stats.buffers_created += 1;
        }
        if data {
            self.stats.data_capacity = self.data.size() / WORD;
            self.stats.buffers_created += 1;
        }
        if !descs && !data {
            return Ok(());
        }
        self.bind_groups.clear();
        Ok(())
    }

    /// Fills `desc_scratch` and `scratch` (coefficients and rectangle tables) for `input`,
    /// with the offsets `p` was sized for. Time and grid were validated.
    pub(super) fn stage<L: LayerView>(
        &mut self,
        input: &Input<'_, L>,
        p: &Prepared,
    ) -> Result<(), GpuError> {
        let grid = input.grid;
        let (gnx, gnz) = grid.size;
        self.desc_scratch.clear();
        self.scratch.clear();
        self.scratch.reserve(p.scratch_words as usize);
        // Modulation follows the coefficients and tables, in layer order.
        let mut modulation = p.scratch_words;
        for layer in input.layers {
            let r = layer.rect();
            let coeffs = layer.waves().coeffs();
            let w = coeffs.len();
            // Offsets fit u32: the total was checked in `prepare`.
            let coeff_offset = self.scratch.len() as u32;
            self.scratch.extend_from_slice(bytemuck::cast_slice(coeffs));
            // The CPU's own tables for the whole grid, then the rectangle's rows and columns.
            self.full_tables.clear();
            self.full_tables.resize(w * (gnz + gnx), [0.0; 2]);
            let (rows, cols) = self.full_tables.split_at_mut(w * gnz);
            layer.waves().grid_sin_cos(grid, input.time, rows, cols)?;
            let rows_offset = self.scratch.len() as u32;
            for wi in 0..w {
                let start = wi * gnz + r.j0;
                self.scratch
                    .extend_from_slice(bytemuck::cast_slice(&rows[start..start + r.nz]));
            }
            let cols_offset = self.scratch.len() as u32;
            for wi in 0..w {
                let start = wi * gnx + r.i0;
                self.scratch
                    .extend_from_slice(bytemuck::cast_slice(&cols[start..start + r.nx]));
            }
            self.desc_scratch.push(LayerDesc {
                i0: r.i0 as u32,
                j0: r.j0 as u32,
                nx: r.nx as u32,
                nz: r.nz as u32,
                waves: w as u32,
                coeffs: coeff_offset,
                rows: rows_offset,
                cols: cols_offset,
                modulation: modulation as u32,
                _pad: [0; 3],
            });
            modulation += 2 * r.len() as u64;
        }
        debug_assert_eq!(self.scratch.len() as u64, p.scratch_words);
        Ok(())
    }

    /// The bind group of the current input buffers and `target`, from the cache or new.
    pub(super) fn bind_group(
        &mut self,
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        target: &TrochoidTarget,
        out_size: u64,
    ) -> wgpu::BindGroup {
        let (group, created) = self.bind_groups.get(
            device,
            layout,
            "ocean layers bind group",
            [&self.params, &self.descs, &self.data],
            target,
            out_size,
        );
        if created {
            self.stats.bind_groups_created += 1;
        }
        group
    }
}
