//! One box's march on the GPU: its uniform block and statics (`ocean_wtb::gpu_params`, beside
//! the march they encode) with the dispatch shapes of this device.

use ocean_wtb::gpu_params::MarchStatics;
use ocean_wtb::march::MarchBox;
use ocean_wtb::{Terrain, WaterGrid};

pub use ocean_wtb::gpu_params::{MAX_TIME, MarchParams, with_effects};

use crate::GpuError;
use crate::trochoid::{WORKGROUP_SIZE, dispatch_shape};

/// One box's static march: its uniform block without the plan's effects, its statics (ray
/// descriptors, then the shortening table) and its dispatch shapes.
#[derive(Clone, Debug)]
pub(crate) struct BoxSetup {
    pub(crate) params: MarchParams,
    pub(crate) statics: Vec<u32>,
    /// Points of the box rectangle.
    pub(crate) points: u64,
    /// Workgroups of the points' dispatches.
    pub(crate) groups: (u32, u32),
    /// Workgroups of the rays' dispatch.
    pub(crate) ray_groups: (u32, u32),
}

impl BoxSetup {
    /// The static march of `b` on `grid` over `terrain`.
    pub(crate) fn new(
        grid: &WaterGrid,
        terrain: &Terrain,
        b: &MarchBox,
        max_groups_per_dim: u32,
    ) -> Result<Self, GpuError> {
        let MarchStatics {
            mut params,
            statics,
        } = MarchStatics::new(grid, terrain, b)?;
        let points = b.rect.len() as u64;
        let groups = dispatch_shape(
            u32::try_from(points.div_ceil(u64::from(WORKGROUP_SIZE))).map_err(|_| {
                GpuError::TooLarge {
                    what: "box rectangle points",
                    needed: points,
                    limit: u64::from(u32::MAX),
                }
            })?,
            max_groups_per_dim,
        )?;
        let ray_groups = dispatch_shape(params.rays.div_ceil(WORKGROUP_SIZE), max_groups_per_dim)?;
        params.groups_x = groups.0;
        params.ray_groups_x = ray_groups.0;
        Ok(Self {
            params,
            statics,
            points,
            groups,
            ray_groups,
        })
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
}
