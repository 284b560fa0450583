//! Wave train boxes marched on the GPU: the twin of `ocean_wtb::march::MarchBox::march` and
//! `MarchBox::time_modulation`, feeding [`LayersPass`].
//!
//! [`ocean_wtb::scene::Scene::plan`] does on the CPU what is cheap and sequential (the boxes'
//! lifecycles, frustum culling, the budget, one descriptor per wave ray); this pass does the
//! rest on the GPU, one invocation per wave ray for the march (paper §2: the rays are
//! independent), then per grid point for the land factor's smoothing, the time-dependent
//! effects and the evaluation of every box's trains (`shaders/wtb_march.wgsl`, then the layers
//! pass):
//!
//! | dispatch | over | does |
//! |---|---|---|
//! | `clear` | box rectangle | zero the modulation, land factor 0 on land and 1 elsewhere |
//! | `march` | wave rays | the quadrant scan (exact, the CPU's integers), land, recovery behind land (Fig. 5), shoaling, beach cap, side fades (Fig. 4), refraction lag (Fig. 6), round waves (Eq. 10) |
//! | `erode_x`, `erode_z`, `mean_x`, `mean_z` | box rectangle | the land factor's smoothing (`ocean_wtb::shore`) |
//! | `combine` | box rectangle | modulation · land factor, irregular height (Eq. 8), dispersion refraction (Eq. 4) |
//! | layers | water grid | every box's trains with its modulation, plus the height field |
//!
//! The traversal is the CPU's exactly (the same 64-bit integers, `ocean_wtb::FixedTraversal`),
//! so every grid point belongs to the same ray on both sides; the values differ by `f32`
//! rounding only. The dispersion option's phase (ω∞ − ω(D))·t is formed from an `f32` ω(D), so
//! it drifts from the CPU's by about 10⁻⁷·Δω·t rad (smoothly: no jitter, see the shader's
//! `turns`); at t = 1000 s that is below 10⁻⁴ rad.
//!
//! Each call uploads the terrain and creates the boxes' work buffers; the static march is
//! recomputed every call (on the GPU it costs a few dispatches per box).

use bytemuck::{Pod, Zeroable};
use ocean_core::Grid;
use ocean_wtb::effects::{Refraction, ShorteningTable};
use ocean_wtb::march::{MarchBox, Plan};
use ocean_wtb::{FixedTraversal, Terrain, WaterGrid};

use crate::layers::DeviceLayer;
use crate::readback::{GpuTimer, read_buffer_as};
use crate::trochoid::{WORKGROUP_SIZE, dispatch_shape};
use crate::{GpuContext, GpuError, GridOutput, LayersPass, TrochoidTarget};

/// The march's uniform block, byte for byte the WGSL `Params` of `wtb_march.wgsl` (208 bytes).
/// 64-bit integers are `[low, high]` words.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct MarchParams {
    /// Water grid columns.
    pub grid_nx: u32,
    /// Water grid rows.
    pub grid_nz: u32,
    /// The box rectangle's first column.
    pub i0: u32,
    /// Its first row.
    pub j0: u32,
    /// Its columns.
    pub nx: u32,
    /// Its rows.
    pub nz: u32,
    /// Ray descriptors.
    pub rays: u32,
    /// 1 terrain, 2 refraction, 4 shoaling, 8 round waves, 16 beach, 32 irregular, 64 dispersion.
    pub flags: u32,
    /// [`FixedTraversal::ca`].
    pub ca: [u32; 2],
    /// [`FixedTraversal::cb`].
    pub cb: [u32; 2],
    /// [`FixedTraversal::ux`].
    pub ux: [u32; 2],
    /// [`FixedTraversal::uz`].
    pub uz: [u32; 2],
    /// [`FixedTraversal::length`].
    pub length: [u32; 2],
    /// [`FixedTraversal::width`].
    pub width: [u32; 2],
    /// A cell centre's move per step, grid units.
    pub centre_step: [f32; 2],
    /// Candidate window half-width, grid units.
    pub half: f32,
    /// Metres per fixed-point unit.
    pub cell: f32,
    /// Side fade width, metres.
    pub smoothing: f32,
    /// Recovery distance behind land, metres.
    pub recovery: f32,
    /// ΣA of the box's trains, metres.
    pub amplitude: f32,
    /// Peak wavenumber, rad/m.
    pub peak_k: f32,
    /// Shoaling reference depth, metres.
    pub shallow_depth: f32,
    /// The beach's amplitude per metre of depth.
    pub beach_share: f32,
    /// Shortening table step in √depth.
    pub table_step: f32,
    /// Its intervals.
    pub table_len: u32,
    /// Word offset of its values in the statics buffer.
    pub table: u32,
    /// Smoothing radius, cells.
    pub radius: u32,
    /// Workgroups along x of the points' dispatches.
    pub groups_x: u32,
    /// Eq. 8: a.
    pub irregular_scale: f32,
    /// Eq. 8: f, rad/m.
    pub irregular_freq: f32,
    /// Eq. 8: k_e, rad/m.
    pub irregular_k: f32,
    /// k_e·c_e·t reduced to [−π, π].
    pub irregular_phase: f32,
    /// Internal a of the rectangle's first point, metres.
    pub origin_a: f32,
    /// Internal b of it, metres.
    pub origin_b: f32,
    /// a's change per column, metres.
    pub a_di: f32,
    /// a's change per row.
    pub a_dj: f32,
    /// b's change per column.
    pub b_di: f32,
    /// b's change per row.
    pub b_dj: f32,
    /// √(g k_p), rad/s.
    pub omega_deep: f32,
    /// Workgroups along x of the rays' dispatch.
    pub ray_groups_x: u32,
    /// Padding.
    pub _pad: u32,
    /// t = x·2²⁴ + y·2¹² + z + w, with x, y, z whole numbers below 2¹² and w in [0, 1).
    pub time: [f32; 4],
}

/// The entry points of `wtb_march.wgsl`, in dispatch order.
const ENTRIES: [&str; 7] = [
    "clear", "march", "erode_x", "erode_z", "mean_x", "mean_z", "combine",
];

/// Largest time the dispersion phase's split takes, seconds (2³⁶).
pub const MAX_TIME: f64 = (1u64 << 36) as f64;

fn words(v: i64) -> [u32; 2] {
    [v as u32, (v >> 32) as u32]
}

/// `t` split as the shader's `time` (see [`MarchParams::time`]).
fn split_time(t: f64) -> [f32; 4] {
    let whole = t.floor();
    let w = (t - whole) as f32;
    let n = whole as u64;
    [
        (n >> 24) as f32,
        ((n >> 12) & 0xfff) as f32,
        (n & 0xfff) as f32,
        w,
    ]
}

/// The evaluated grid and, per box of the plan, its modulation over its rectangle.
pub type MarchOutput = (GridOutput, Vec<Vec<[f32; 2]>>);

/// One box's prepared dispatch.
struct BoxRun {
    params: MarchParams,
    statics: Vec<u32>,
    points: u64,
    groups: (u32, u32),
    ray_groups: (u32, u32),
}

/// The ray march of wave train boxes and the evaluation of their grid on the GPU (see the
/// [module documentation](self)).
#[derive(Debug)]
pub struct WtbMarchPass {
    pipelines: Vec<wgpu::ComputePipeline>,
    layout: wgpu::BindGroupLayout,
    layers: LayersPass,
    max_groups_per_dim: u32,
}

impl WtbMarchPass {
    /// Builds the pipelines on `ctx`'s device.
    pub fn new(ctx: &GpuContext) -> Result<Self, GpuError> {
        let device = ctx.device();
        let (pipelines, layout) = crate::pipeline::compute_pipelines(
            device,
            "wtb_march",
            std::mem::size_of::<MarchParams>(),
            &ENTRIES,
        )?;
        Ok(Self {
            pipelines,
            layout,
            layers: LayersPass::new(ctx)?,
            max_groups_per_dim: device.limits().max_compute_workgroups_per_dimension,
        })
    }

    /// The uniform block and the statics (ray descriptors, shortening table) of one box.
    fn prepare_box(
        &self,
        grid: &WaterGrid,
        terrain: &Terrain,
        plan: &Plan,
        b: &MarchBox,
    ) -> Result<BoxRun, GpuError> {
        let traversal = b.frame.traversal(grid)?;
        let fixed: FixedTraversal = *traversal.fixed();
        let mut statics = Vec::new();
        let mut rays = 0u32;
        for r in traversal.rays() {
            let steps = traversal.ray(r).steps;
            if steps.is_empty() {
                continue;
            }
            let c = traversal.cell_centre(r, steps.start);
            statics.extend_from_slice(&[
                r,
                steps.start,
                steps.end - steps.start,
                0,
                (c.x as f32).to_bits(),
                (c.y as f32).to_bits(),
                0,
                0,
            ]);
            rays += 1;
        }
        let table = ShorteningTable::new(b.peak_k);
        let table_offset = statics.len() as u32;
        statics.extend(table.values().iter().map(|&v| (v as f32).to_bits()));
        let e = &plan.effects;
        let has_terrain = terrain.heights().is_some();
        let mut flags = 0u32;
        for (on, bit) in [
            (has_terrain, 1),
            (b.refraction, 2),
            (b.shoaling, 4),
            (b.round_waves, 8),
            (b.beach.is_some(), 16),
            (e.irregular.is_some(), 32),
            (e.refraction == Refraction::Dispersion, 64),
        ] {
            if on {
                flags |= bit;
            }
        }
        let r = b.rect;
        let points = r.len() as u64;
        let groups = dispatch_shape(
            u32::try_from(points.div_ceil(u64::from(WORKGROUP_SIZE))).map_err(|_| {
                GpuError::TooLarge {
                    what: "box rectangle points",
                    needed: points,
                    limit: u64::from(u32::MAX),
                }
            })?,
            self.max_groups_per_dim,
        )?;
        let ray_groups = dispatch_shape(rays.div_ceil(WORKGROUP_SIZE), self.max_groups_per_dim)?;
        let s = grid.spacing();
        let p0 = grid.point(r.i0, r.j0);
        let ab0 = b.frame.internal(p0);
        let (u, v) = (b.frame.u(), b.frame.v());
        let step = traversal.centre_step();
        let params = MarchParams {
            grid_nx: grid.nx() as u32,
            grid_nz: grid.nz() as u32,
            i0: r.i0 as u32,
            j0: r.j0 as u32,
            nx: r.nx as u32,
            nz: r.nz as u32,
            rays,
            flags,
            ca: words(fixed.ca),
            cb: words(fixed.cb),
            ux: words(fixed.ux),
            uz: words(fixed.uz),
            length: words(fixed.length),
            width: words(fixed.width),
            centre_step: [step.x as f32, step.y as f32],
            // The CPU's bounding half-width plus a margin far above the f32 rounding of the
            // centres (below 10⁻³ cells on a 4096² grid): still under 1 in all, so at most two
            // candidates per axis.
            half: (traversal.cell_half_extent() + 0.05) as f32,
            cell: (s / ocean_wtb::frame::FIXED_ONE as f64) as f32,
            smoothing: b.smoothing as f32,
            recovery: b.recovery as f32,
            amplitude: b.amplitude as f32,
            peak_k: b.peak_k as f32,
            shallow_depth: b.shallow_depth as f32,
            beach_share: b.beach.map_or(0.0, |x| x.max_depth_share as f32),
            table_step: table.step() as f32,
            table_len: ShorteningTable::SAMPLES as u32,
            table: table_offset,
            radius: b.shore_radius as u32,
            groups_x: groups.0,
            irregular_scale: e.irregular.map_or(0.0, |x| x.scale as f32),
            irregular_freq: e.irregular.map_or(0.0, |x| x.frequency as f32),
            irregular_k: e.irregular.map_or(0.0, |x| x.envelope_wavenumber as f32),
            irregular_phase: e.irregular.map_or(0.0, |x| {
                ocean_core::phase::reduce_angle(x.envelope_wavenumber * x.envelope_speed * plan.t)
                    as f32
            }),
            origin_a: ab0.x as f32,
            origin_b: ab0.y as f32,
            a_di: (u.x * s) as f32,
            a_dj: (u.y * s) as f32,
            b_di: (v.x * s) as f32,
            b_dj: (v.y * s) as f32,
            omega_deep: (ocean_core::GRAVITY * b.peak_k).sqrt() as f32,
            ray_groups_x: ray_groups.0,
            _pad: 0,
            time: split_time(plan.t),
        };
        Ok(BoxRun {
            params,
            statics,
            points,
            groups,
            ray_groups,
        })
    }

    /// Records every box's march and the grid's evaluation into `encoder`, writing the water
    /// grid's positions and normals into `target`; `height` is the additive height field
    /// (noise, run-up: `ocean_wtb::scene::Frame::height_field` at the plan's time), if any.
    /// Returns the boxes' modulation buffers (kept alive by wgpu until the work completes; the
    /// parity tests read them).
    ///
    /// # Errors
    ///
    /// [`GpuError::Wtb`] for a terrain of another grid, [`GpuError::Eval`] for a time outside
    /// `[0, 2³⁶)` s, or the layers pass's own errors; nothing is recorded then.
    #[allow(clippy::too_many_arguments)]
    pub fn encode(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        grid: &WaterGrid,
        terrain: &Terrain,
        plan: &Plan,
        height: Option<&[f32]>,
        target: &TrochoidTarget,
        timer: Option<&GpuTimer>,
    ) -> Result<Vec<wgpu::Buffer>, GpuError> {
        if terrain.grid() != grid {
            return Err(GpuError::Wtb(ocean_wtb::WtbError::TerrainSize {
                expected: grid.len(),
                got: terrain.grid().len(),
            }));
        }
        if !(0.0..MAX_TIME).contains(&plan.t) {
            return Err(GpuError::Eval(ocean_core::EvalError::Time(plan.t)));
        }
        let runs: Vec<BoxRun> = plan
            .boxes
            .iter()
            .map(|b| self.prepare_box(grid, terrain, plan, &b.march))
            .collect::<Result<_, _>>()?;
        let device = ctx.device();
        let storage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST;
        let buffer = |label: &str, size: u64, usage| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size: size.max(16),
                usage,
                mapped_at_creation: false,
            })
        };
        let terrain_buffer = buffer(
            "ocean wtb terrain",
            4 * terrain.heights().map_or(1, |h| h.len()) as u64,
            storage,
        );
        if let Some(h) = terrain.heights() {
            ctx.queue()
                .write_buffer(&terrain_buffer, 0, bytemuck::cast_slice(h));
        }
        let mut modulations = Vec::with_capacity(runs.len());
        crate::scoped(device, || {
            for run in &runs {
                let uniform = buffer(
                    "ocean wtb march params",
                    std::mem::size_of::<MarchParams>() as u64,
                    wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                );
                ctx.queue()
                    .write_buffer(&uniform, 0, bytemuck::bytes_of(&run.params));
                let statics = buffer(
                    "ocean wtb march statics",
                    4 * run.statics.len() as u64,
                    storage,
                );
                ctx.queue()
                    .write_buffer(&statics, 0, bytemuck::cast_slice(&run.statics));
                let work = buffer(
                    "ocean wtb march work",
                    16 * run.points,
                    wgpu::BufferUsages::STORAGE,
                );
                let modulation = buffer(
                    "ocean wtb modulation",
                    8 * run.points,
                    wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
                );
                let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("ocean wtb march bind group"),
                    layout: &self.layout,
                    entries: &[
                        wgpu::BindGroupEntry {
                            binding: 0,
                            resource: uniform.as_entire_binding(),
                        },
                        wgpu::BindGroupEntry {
                            binding: 1,
                            resource: statics.as_entire_binding(),
                        },
                        wgpu::BindGroupEntry {
                            binding: 2,
                            resource: terrain_buffer.as_entire_binding(),
                        },
                        wgpu::BindGroupEntry {
                            binding: 3,
                            resource: work.as_entire_binding(),
                        },
                        wgpu::BindGroupEntry {
                            binding: 4,
                            resource: modulation.as_entire_binding(),
                        },
                    ],
                });
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some("ocean wtb march"),
                    timestamp_writes: None,
                });
                pass.set_bind_group(0, &bind_group, &[]);
                for (n, pipeline) in self.pipelines.iter().enumerate() {
                    let filter = (2..6).contains(&n);
                    if filter && run.params.radius == 0 {
                        continue;
                    }
                    let (gx, gy) = if n == 1 { run.ray_groups } else { run.groups };
                    pass.set_pipeline(pipeline);
                    pass.dispatch_workgroups(gx, gy, 1);
                }
                drop(pass);
                modulations.push(modulation);
            }
            Ok(())
        })?;
        let layers: Vec<DeviceLayer<'_>> = plan
            .boxes
            .iter()
            .zip(&modulations)
            .map(|(b, m)| DeviceLayer {
                waves: &b.waves,
                rect: b.march.rect,
                modulation: m,
                offset: 0,
            })
            .collect();
        self.layers.encode_device(
            ctx,
            encoder,
            grid.grid(),
            plan.t,
            &layers,
            height,
            target,
            timer,
        )?;
        Ok(modulations)
    }

    /// Marches and evaluates `plan` and reads the grid back (positions relative to the grid's
    /// origin, as `Frame::evaluate`), with every box's modulation over its rectangle: a
    /// one-off query that allocates and waits, for tests and tools.
    ///
    /// # Errors
    ///
    /// As [`encode`](Self::encode).
    pub fn evaluate(
        &self,
        ctx: &GpuContext,
        grid: &WaterGrid,
        terrain: &Terrain,
        plan: &Plan,
        height: Option<&[f32]>,
    ) -> Result<MarchOutput, GpuError> {
        let g: &Grid = grid.grid();
        let target = TrochoidTarget::new(ctx, g)?;
        let timer = GpuTimer::new(ctx);
        let mut modulations = Vec::new();
        crate::trochoid::submit(ctx, "ocean wtb", timer.as_ref(), |encoder| {
            modulations = self.encode(
                ctx,
                encoder,
                grid,
                terrain,
                plan,
                height,
                &target,
                timer.as_ref(),
            )?;
            Ok(())
        })?;
        let out = target.read(ctx, g.point_count()?, timer.as_ref())?;
        let mut mus = Vec::with_capacity(modulations.len());
        for (m, b) in modulations.iter().zip(&plan.boxes) {
            let mut v: Vec<[f32; 2]> = read_buffer_as(ctx, m)?;
            v.truncate(b.march.rect.len());
            mus.push(v);
        }
        Ok((out, mus))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn params_match_the_wgsl_layout() {
        let b = crate::shaders::get("wtb_march")
            .unwrap()
            .bindings()
            .unwrap();
        assert_eq!(std::mem::size_of::<MarchParams>(), 208);
        assert_eq!(b[0].size as usize, std::mem::size_of::<MarchParams>());
        let offset = |name: &str| {
            b[0].members
                .iter()
                .find(|m| m.name == name)
                .unwrap_or_else(|| panic!("{name}"))
                .offset
        };
        assert_eq!(offset("ca"), 32);
        assert_eq!(offset("centre_step"), 80);
        assert_eq!(offset("omega_deep"), 180);
        assert_eq!(offset("ray_groups_x"), 184);
        assert_eq!(offset("time"), 192);
    }

    #[test]
    fn time_splits_into_exact_twelve_bit_parts() {
        // 10⁶ s + 0.25: 1_000_000 = 0·2²⁴ + 244·2¹² + 576.
        assert_eq!(split_time(1.0e6 + 0.25), [0.0, 244.0, 576.0, 0.25]);
        let t = 3.0 * 16_777_216.0 + 5.0 * 4096.0 + 7.0 + 0.5;
        assert_eq!(split_time(t), [3.0, 5.0, 7.0, 0.5]);
        assert_eq!(words(-1), [u32::MAX, u32::MAX]);
        assert_eq!(words(1 << 36), [0, 16]);
    }
}
