//! The uniform blocks of the GPU twins of a frame's march and height field (`ocean-gpu`'s
//! `wtb_march.wgsl` and `wtb_height.wgsl`), defined here beside the march they encode, with the
//! functions that fill them from a box ([`MarchStatics`]), a plan's effects ([`with_effects`])
//! and a frame's height terms ([`HeightParams::new`]). `ocean-gpu` adds only the dispatch widths
//! and checks every member's offset against the WGSL.
//!
//! 64-bit integers are `[low, high]` words; times are split into exact 12-bit parts
//! ([`split_time`]) so the shader's `f32` arithmetic keeps the phase of a frame at 10⁶ s.

use alloc::vec::Vec;

use bytemuck::{Pod, Zeroable};

use crate::box_frame::FixedTraversal;
use crate::effects::{NOISE_TURNS_STEP, Refraction, ShorteningTable};
use crate::march::{MarchBox, Plan};
use crate::{Terrain, WaterGrid, WtbError};

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

/// Flags of the static march (terrain, refraction, shoaling, round waves, beach).
const STATIC_FLAGS: u32 = 1 | 2 | 4 | 8 | 16;

/// Largest time the dispersion phase's split takes, seconds (2³⁶).
pub const MAX_TIME: f64 = (1u64 << 36) as f64;

/// `v` as `[low, high]` 32-bit words.
pub fn words(v: i64) -> [u32; 2] {
    [v as u32, (v >> 32) as u32]
}

/// `t` split as the shader's `time` (see [`MarchParams::time`]).
pub fn split_time(t: f64) -> [f32; 4] {
    let whole = ocean_core::math::floor(t);
    let w = (t - whole) as f32;
    let n = whole as u64;
    [
        (n >> 24) as f32,
        ((n >> 12) & 0xfff) as f32,
        (n & 0xfff) as f32,
        w,
    ]
}

/// A box's static march: its uniform block without the plan's effects and without the
/// dispatch widths (`groups_x`, `ray_groups_x`: the caller's, from its device's limits), and its
/// statics buffer (ray descriptors, then the shortening table).
#[derive(Clone, Debug)]
pub struct MarchStatics {
    /// The block; [`with_effects`] adds a plan's time-dependent part.
    pub params: MarchParams,
    /// Eight words per ray with steps (ray, first step, steps, 0, centre x and z as `f32`
    /// bits, 0, 0), then [`ShorteningTable::SAMPLES`] + 1 `f32` values from word
    /// [`MarchParams::table`].
    pub statics: Vec<u32>,
}

impl MarchStatics {
    /// The static march of `b` on `grid` over `terrain`.
    ///
    /// # Errors
    ///
    /// The box's traversal's ([`crate::box_frame::BoxFrame::traversal`]).
    pub fn new(grid: &WaterGrid, terrain: &Terrain, b: &MarchBox) -> Result<Self, WtbError> {
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
        let mut flags = 0u32;
        for (on, bit) in [
            (terrain.heights().is_some(), 1),
            (b.refraction, 2),
            (b.shoaling, 4),
            (b.round_waves, 8),
            (b.beach.is_some(), 16),
        ] {
            if on {
                flags |= bit;
            }
        }
        let r = b.rect;
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
            cell: (s / crate::box_frame::FIXED_ONE as f64) as f32,
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
            groups_x: 0,
            irregular_scale: 0.0,
            irregular_freq: 0.0,
            irregular_k: 0.0,
            irregular_phase: 0.0,
            origin_a: ab0.x as f32,
            origin_b: ab0.y as f32,
            a_di: (u.x * s) as f32,
            a_dj: (u.y * s) as f32,
            b_di: (v.x * s) as f32,
            b_dj: (v.y * s) as f32,
            omega_deep: ocean_core::math::sqrt(ocean_core::GRAVITY * b.peak_k) as f32,
            ray_groups_x: 0,
            _pad: 0,
            time: [0.0; 4],
        };
        Ok(Self { params, statics })
    }
}

/// `params` (a box's static block) with `plan`'s time-dependent effects at `plan.t`: the
/// irregular height of Eq. 8 and the dispersion refraction of Eq. 4.
pub fn with_effects(params: &MarchParams, plan: &Plan) -> MarchParams {
    let e = &plan.effects;
    let mut p = *params;
    p.flags &= STATIC_FLAGS;
    if e.irregular.is_some() {
        p.flags |= 32;
    }
    if e.refraction == Refraction::Dispersion {
        p.flags |= 64;
    }
    p.irregular_scale = e.irregular.map_or(0.0, |x| x.scale as f32);
    p.irregular_freq = e.irregular.map_or(0.0, |x| x.frequency as f32);
    p.irregular_k = e.irregular.map_or(0.0, |x| x.envelope_wavenumber as f32);
    p.irregular_phase = e.irregular.map_or(0.0, |x| {
        ocean_core::phase::reduce_angle(x.envelope_wavenumber * x.envelope_speed * plan.t) as f32
    });
    p.time = split_time(plan.t);
    p
}

/// The height pass's uniform block, byte for byte the WGSL `Params` of `wtb_height.wgsl`
/// (64 bytes).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct HeightParams {
    /// Water grid columns.
    pub nx: u32,
    /// Water grid rows.
    pub nz: u32,
    /// 1 noise, 2 run-up.
    pub flags: u32,
    /// Workgroups along x.
    pub groups_x: u32,
    /// Noise seed, `[low, high]` words.
    pub seed: [u32; 2],
    /// Noise amplitude b, metres.
    pub amplitude: f32,
    /// [`NOISE_TURNS_STEP`].
    pub step: f32,
    /// Run-up at the shoreline, metres.
    pub run_up: f32,
    /// Depth where the run-up has faded to 0, metres.
    pub run_up_depth: f32,
    /// Padding.
    pub _pad: [u32; 2],
    /// t split as [`MarchParams::time`](MarchParams::time).
    pub time: [f32; 4],
}

impl HeightParams {
    /// The block for `plan` over `terrain` (`nx` × `nz` points, `groups_x` workgroups along
    /// x), or `None` when the frame has no height field: no noise, and no run-up (without a
    /// beach, a run-up of 0 or a terrain), as on the CPU.
    pub fn new(plan: &Plan, terrain: &Terrain, groups_x: u32) -> Option<Self> {
        let e = &plan.effects;
        let run_up = e
            .beach
            .filter(|b| b.run_up != 0.0 && terrain.heights().is_some());
        if e.noise.is_none() && run_up.is_none() {
            return None;
        }
        let grid = terrain.grid();
        let mut flags = 0;
        if e.noise.is_some() {
            flags |= 1;
        }
        if run_up.is_some() {
            flags |= 2;
        }
        let seed = e.noise.map_or(0, |n| n.seed);
        Some(Self {
            nx: grid.nx() as u32,
            nz: grid.nz() as u32,
            flags,
            groups_x,
            seed: [seed as u32, (seed >> 32) as u32],
            amplitude: e.noise.map_or(0.0, |n| n.amplitude as f32),
            step: NOISE_TURNS_STEP,
            run_up: run_up.map_or(0.0, |b| b.run_up as f32),
            run_up_depth: run_up.map_or(0.0, |b| b.run_up_depth as f32),
            _pad: [0; 2],
            time: split_time(plan.t),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
