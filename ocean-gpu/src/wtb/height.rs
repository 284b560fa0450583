//! The height-only terms of a frame on the GPU (`shaders/wtb_height.wgsl`): capillary noise
//! (Eq. 9) and the beach run-up, the twin of `ocean_wtb::scene::Frame::height_field`.

use bytemuck::{Pod, Zeroable};
use ocean_wtb::Terrain;
use ocean_wtb::effects::NOISE_TURNS_STEP;
use ocean_wtb::march::Plan;

use super::params::split_time;

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
    /// t split as [`MarchParams::time`](super::MarchParams::time).
    pub time: [f32; 4],
}

impl HeightParams {
    /// The block for `plan` over `terrain` (`nx` × `nz` points, `groups_x` workgroups along
    /// x), or `None` when the frame has no height field: no noise, and no run-up (without a
    /// beach, a run-up of 0 or a terrain), as on the CPU.
    pub(crate) fn new(plan: &Plan, terrain: &Terrain, groups_x: u32) -> Option<Self> {
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

/// The height pass's buffers, kept between calls for one grid and terrain buffer.
#[derive(Debug)]
pub(crate) struct HeightBuffers {
    pub(crate) uniform: wgpu::Buffer,
    /// One `f32` per grid point; the layers pass copies it.
    pub(crate) output: wgpu::Buffer,
    pub(crate) bind_group: wgpu::BindGroup,
    /// The grid points it was made for.
    pub(crate) points: u64,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn params_match_the_wgsl_layout() {
        let b = crate::shaders::get("wtb_height")
            .unwrap()
            .bindings()
            .unwrap();
        assert_eq!(std::mem::size_of::<HeightParams>(), 64);
        assert_eq!(b[0].size as usize, std::mem::size_of::<HeightParams>());
        let offset = |name: &str| {
            b[0].members
                .iter()
                .find(|m| m.name == name)
                .unwrap_or_else(|| panic!("{name}"))
                .offset
        };
        assert_eq!(offset("seed"), 16);
        assert_eq!(offset("run_up_depth"), 36);
        assert_eq!(offset("time"), 48);
    }
}
