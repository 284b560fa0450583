//! The height-only terms of a frame on the GPU (`shaders/wtb_height.wgsl`): capillary noise
//! (Eq. 9) and the beach run-up, the twin of `ocean_wtb::scene::Frame::height_field`.

pub use ocean_wtb::gpu_params::HeightParams;

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
