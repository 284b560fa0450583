//! The parameter block the GPU twin of the passes reads, defined once here so that the WGSL
//! uniform (ocean-gpu's `sao_common.wgsl`), the CPU reference and a C header share one layout.
//!
//! [`SaoUniforms`] holds exactly the host-side constants the CPU passes use ([`Sao`]'s
//! [`SampleConstants`](crate::sample::SampleConstants),
//! [`BlurConstants`](crate::blur::BlurConstants), Eq. 2's and Eq. 3's constants), each computed
//! once in `f64` and rounded once to `f32` on the host, so both sides start from the same bits.
//!
//! The layout is `#[repr(C)]`, every member 4 bytes, grouped in 16-byte rows with explicit
//! padding: it is the same under std140 (uniform buffers, where `vec2` aligns to 8 and arrays
//! of `vec4` have a 16-byte stride) and std430, and has no implicit padding (`Pod`).
//!
//! The GPU cannot return errors, so what the CPU's z pass checks per pixel (finite depth, inside
//! the convention's range) is checked on the host before an upload: [`check_depth`].

use bytemuck::{Pod, Zeroable};

use crate::SaoError;
use crate::hierarchy::MipFilter;
use crate::params::BlurWeight;
use crate::pipeline::Sao;
use crate::reconstruct::NormalEstimate;
use crate::reconstruct::ZConstants;
use crate::sample::EstimatorConstants;
use crate::viewport::Viewport;

/// [`SaoUniforms::estimator`] of Eq. 1 (AlchemyAO).
pub const ESTIMATOR_ALCHEMY: u32 = 0;
/// [`SaoUniforms::estimator`] of the appendix's falloff.
pub const ESTIMATOR_FALLOFF: u32 = 1;

/// Number of `vec4` rows of [`SaoUniforms::gauss`]: `MAX_BLUR_TAPS = 63` taps have
/// `R + 1 = 32` weights.
pub const GAUSS_ROWS: usize = 8;

/// The code of a [`MipFilter`] in [`SaoUniforms::mip_filter`]: Table 1's order (0 rotated grid,
/// 1 arithmetic mean, 2 harmonic mean, 3 min, 4 max).
pub fn mip_filter_code(filter: MipFilter) -> u32 {
    match filter {
        MipFilter::RotatedGrid => 0,
        MipFilter::ArithmeticMean => 1,
        MipFilter::HarmonicMean => 2,
        MipFilter::Min => 3,
        MipFilter::Max => 4,
    }
}

pub use crate::hierarchy::level_count;

/// Every constant of the five passes, byte for byte the WGSL `Params` block of ocean-gpu's SAO
/// shaders (304 bytes). Built by [`SaoUniforms::new`] from a validated [`Sao`].
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct SaoUniforms {
    /// Eq. 2: `[c₀, c₁, c₂, c₃]`, `z(d) = (c₀ + c₃·d) / (c₁·d + c₂)` ([`ZConstants::c`]).
    pub z_c: [f32; 4],
    /// Eq. 3: `scale` ([`crate::ProjectionInfo::scale`]).
    pub scale: [f32; 2],
    /// Eq. 3: `offset` ([`crate::ProjectionInfo::offset`]).
    pub offset: [f32; 2],
    /// Input (depth buffer) width and height, pixels.
    pub input_size: [u32; 2],
    /// Output width and height: the input inset by the guard band on every side.
    pub output_size: [u32; 2],
    /// Guard band, pixels on every side.
    pub guard: u32,
    /// 1 for a perspective (Eq. 3 multiplies by z, Eq. 5 divides by −z), 0 for orthographic.
    pub perspective: u32,
    /// Stored depth of the far end (the clear value), read as sky ([`ZConstants::far_depth`]).
    pub far_depth: f32,
    /// The level-0 pixel the MIP levels are anchored at ([`Sao::mip_origin`]).
    pub mip_origin: u32,
    /// Eq. 5's numerator `r·S'`.
    pub radius_pixels: f32,
    /// `r²`.
    pub radius2: f32,
    /// `1/r²`.
    pub inv_radius2: f32,
    /// ε of Eq. 1 and the appendix, m².
    pub epsilon: f32,
    /// Samples per pixel `s`.
    pub samples: u32,
    /// `f32(1/s)` (Eq. 6).
    pub inv_samples: f32,
    /// `f32(2π·τ)` (Eq. 6).
    pub two_pi_turns: f32,
    /// `log₂ q'` (Eq. 9).
    pub mip_switch_log2: u32,
    /// Highest level the sample pass reads: `min(params.max_mip, levels − 1)` (Eq. 9's clamp
    /// at the hierarchy actually built, as the CPU's `sample_pixel`).
    pub max_mip: u32,
    /// [`mip_filter_code`] of Table 1's filter.
    pub mip_filter: u32,
    /// [`ESTIMATOR_ALCHEMY`] or [`ESTIMATOR_FALLOFF`].
    pub estimator: u32,
    /// `2σ` (Eq. 1) or `5·intensity` (appendix).
    pub strength: f32,
    /// β (either estimator).
    pub beta: f32,
    /// Eq. 1's contrast exponent k (1 for the falloff).
    pub k: f32,
    /// `1/cos γ_max` of the normal rejection (0 when [`SaoUniforms::normal_rejection`] is 0).
    pub normal_limit: f32,
    /// The 2×2 quad bilateral's depth threshold, metres (0 when
    /// [`SaoUniforms::quad_filter`] is 0).
    pub quad_threshold: f32,
    /// 1 when the normal rejection is on.
    pub normal_rejection: u32,
    /// 1 when the 2×2 quad bilateral is on.
    pub quad_filter: u32,
    /// `f32(1/z_min)` of the packing (§2.3).
    pub inv_z_min: f32,
    /// Blur radius `R = (taps − 1)/2`.
    pub blur_radius: u32,
    /// Pixels between blur taps.
    pub blur_stride: u32,
    /// The blur's depth-difference scale.
    pub depth_scale: f32,
    /// 1 for the blur's plane weight ([`crate::BlurWeight::Plane`]), 0 for the paper's.
    pub blur_plane: u32,
    /// 1 for normals from the nearer neighbours ([`crate::NormalEstimate::Nearest`]), 0 for
    /// Eq. 4's quad differences.
    pub normals_nearest: u32,
    /// `1/(world_extent·r)` of the plane weight's fade, 0 when disabled.
    pub inv_blur_extent: f32,
    /// `z_min` of the key (metres), for the fade's depth differences.
    pub z_min: f32,
    /// Padding, 0.
    pub _pad0: u32,
    /// Padding, 0.
    pub _pad1: u32,
    /// The blur's Gaussian weights `gauss[t]` for `t = 0..=R` at `[t / 4][t % 4]`; the rest 0.
    pub gauss: [[f32; 4]; GAUSS_ROWS],
}

impl SaoUniforms {
    /// The constants of `sao` (already validated by [`Sao::new`]).
    pub fn new(sao: &Sao) -> Self {
        let vp = sao.viewport();
        let z = sao.z_constants();
        let info = sao.projection_info();
        let params = sao.params();
        let k = sao.sample_constants();
        let blur = sao.blur_constants();
        let levels = level_count(vp.input_width(), vp.input_height(), params.max_mip);
        let (estimator, strength, beta, exponent) = match k.estimator {
            EstimatorConstants::Alchemy { two_sigma, beta, k } => {
                (ESTIMATOR_ALCHEMY, two_sigma, beta, k)
            }
            EstimatorConstants::Falloff {
                five_intensity,
                beta,
            } => (ESTIMATOR_FALLOFF, five_intensity, beta, 1.0),
        };
        let mut gauss = [[0.0f32; 4]; GAUSS_ROWS];
        for (t, &g) in blur.gauss.iter().enumerate().take(4 * GAUSS_ROWS) {
            gauss[t / 4][t % 4] = g;
        }
        Self {
            z_c: z.c,
            scale: info.scale,
            offset: info.offset,
            input_size: [vp.input_width() as u32, vp.input_height() as u32],
            output_size: [vp.output_width() as u32, vp.output_height() as u32],
            guard: vp.guard() as u32,
            perspective: u32::from(info.perspective),
            far_depth: z.far_depth,
            mip_origin: sao.mip_origin() as u32,
            radius_pixels: k.radius_pixels,
            radius2: k.radius2,
            inv_radius2: k.inv_radius2,
            epsilon: k.epsilon,
            samples: k.spiral.samples,
            inv_samples: k.spiral.inv_samples,
            two_pi_turns: k.spiral.two_pi_turns,
            mip_switch_log2: k.mip_switch_log2,
            max_mip: k.max_mip.min(levels - 1),
            mip_filter: mip_filter_code(params.mip_filter),
            estimator,
            strength,
            beta,
            k: exponent,
            normal_limit: k.normal_limit.unwrap_or(0.0),
            quad_threshold: params.quad_depth_threshold.unwrap_or(0.0),
            normal_rejection: u32::from(k.normal_limit.is_some()),
            quad_filter: u32::from(params.quad_depth_threshold.is_some()),
            inv_z_min: (1.0 / f64::from(params.z_min)) as f32,
            blur_radius: params.blur.radius(),
            blur_stride: blur.stride,
            depth_scale: blur.depth_scale,
            blur_plane: u32::from(blur.weight == BlurWeight::Plane),
            normals_nearest: u32::from(k.normals == NormalEstimate::Nearest),
            inv_blur_extent: blur.inv_extent,
            z_min: blur.z_min,
            _pad0: 0,
            _pad1: 0,
            gauss,
        }
    }

    /// Number of z levels the passes build (see [`level_count`]).
    pub fn levels(&self) -> u32 {
        self.max_mip + 1
    }
}

/// The checks of [`ZConstants::z_pass`] without computing z: `depth` holds one value per input
/// pixel of `viewport`, each finite and inside [`ZConstants::depth_range`]. A GPU pass that
/// uploads a depth slice calls it first, since a shader cannot report the offending pixel.
///
/// # Errors
///
/// As [`ZConstants::z_pass`], for the same first offending pixel in row-major order:
/// [`SaoError::BufferSize`], [`SaoError::DepthNotFinite`], [`SaoError::DepthOutOfRange`].
pub fn check_depth(z: &ZConstants, viewport: &Viewport, depth: &[f32]) -> Result<(), SaoError> {
    z.check_depth(viewport, depth)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hierarchy::ZHierarchy;
    use crate::params::{BlurParams, Estimator, SaoParams};
    use crate::reconstruct::{DepthSource, NormalRejection};
    use core::mem::{offset_of, size_of};
    use ocean_core::{DepthConvention, Far, Projection};

    fn sao(w: usize, h: usize, guard: usize, params: SaoParams) -> Sao {
        let projection = Projection::Perspective {
            fov_y: 1.0,
            aspect: w as f64 / h as f64,
            near: 0.1,
            far: Far::Infinite,
        };
        Sao::new(
            &projection,
            DepthConvention::ZERO_TO_ONE_REVERSED,
            DepthSource::Window,
            Viewport::new(w, h, guard).unwrap(),
            params,
        )
        .unwrap()
    }

    #[test]
    fn layout_is_std140_rows_without_implicit_padding() {
        // 19 rows of 16 bytes; the arrays and vectors start on their std140 alignment.
        assert_eq!(size_of::<SaoUniforms>(), 304);
        assert_eq!(offset_of!(SaoUniforms, scale), 16);
        assert_eq!(offset_of!(SaoUniforms, input_size), 32);
        assert_eq!(offset_of!(SaoUniforms, guard), 48);
        assert_eq!(offset_of!(SaoUniforms, radius_pixels), 64);
        assert_eq!(offset_of!(SaoUniforms, samples), 80);
        assert_eq!(offset_of!(SaoUniforms, max_mip), 96);
        assert_eq!(offset_of!(SaoUniforms, beta), 112);
        assert_eq!(offset_of!(SaoUniforms, normal_rejection), 128);
        assert_eq!(offset_of!(SaoUniforms, blur_stride), 144);
        assert_eq!(offset_of!(SaoUniforms, inv_blur_extent), 160);
        assert_eq!(offset_of!(SaoUniforms, gauss), 176);
    }

    #[test]
    fn level_count_matches_the_cpu_hierarchy() {
        for (w, h) in [
            (2, 2),
            (3, 2),
            (17, 5),
            (64, 64),
            (65, 33),
            (1, 1),
            (300, 7),
        ] {
            for max_mip in [0, 1, 3, 5, 13] {
                let built = ZHierarchy::build(
                    alloc::vec![-1.0; w * h],
                    w,
                    h,
                    MipFilter::RotatedGrid,
                    max_mip,
                )
                .unwrap();
                assert_eq!(
                    level_count(w, h, max_mip),
                    built.levels().len() as u32,
                    "{w} x {h}, max_mip {max_mip}"
                );
            }
        }
    }

    #[test]
    fn uniforms_copy_the_cpu_constants() {
        let params = SaoParams {
            estimator: Estimator::Alchemy {
                sigma: 0.3,
                beta: 2.0e-3,
                k: 1.5,
            },
            normal_rejection: Some(NormalRejection { max_incidence: 1.2 }),
            quad_depth_threshold: None,
            mip_filter: MipFilter::Min,
            max_mip: 13,
            blur: BlurParams {
                taps: 63,
                ..BlurParams::default()
            },
            ..SaoParams::default()
        };
        let s = sao(40, 30, 3, params);
        let u = SaoUniforms::new(&s);
        let k = s.sample_constants();
        assert_eq!(u.z_c, s.z_constants().c);
        assert_eq!(u.input_size, [40, 30]);
        assert_eq!(u.output_size, [34, 24]);
        assert_eq!(u.guard, 3);
        assert_eq!(u.perspective, 1);
        assert_eq!(u.far_depth, 0.0, "reversed Z: the far end is 0");
        assert_eq!(u.radius_pixels.to_bits(), k.radius_pixels.to_bits());
        assert_eq!(u.two_pi_turns.to_bits(), k.spiral.two_pi_turns.to_bits());
        // 40 × 30 halves 5 times to 1 × 1: max_mip 13 is cut to 5.
        assert_eq!(u.max_mip, 5);
        assert_eq!(u.levels(), 6);
        assert_eq!(u.mip_filter, 3);
        assert_eq!(u.estimator, ESTIMATOR_ALCHEMY);
        assert_eq!(u.strength, 0.6);
        assert_eq!(u.k, 1.5);
        assert_eq!(u.normal_rejection, 1);
        assert!(u.normal_limit > 1.0);
        assert_eq!((u.quad_filter, u.quad_threshold), (0, 0.0));
        assert_eq!(u.blur_radius, 31);
        let gauss = &s.blur_constants().gauss;
        assert_eq!(gauss.len(), 32);
        for (t, &g) in gauss.iter().enumerate() {
            assert_eq!(u.gauss[t / 4][t % 4].to_bits(), g.to_bits());
        }
        assert_eq!(u.inv_z_min, (1.0 / -200.0f64) as f32);

        let d = SaoUniforms::new(&sao(40, 30, 3, SaoParams::default()));
        assert_eq!(d.estimator, ESTIMATOR_FALLOFF);
        assert_eq!((d.strength, d.beta, d.k), (5.0, 0.01, 1.0));
        assert_eq!((d.quad_filter, d.quad_threshold), (1, 0.02));
        assert_eq!((d.normal_rejection, d.normal_limit), (0, 0.0));
        assert_eq!(
            (d.gauss[1][3], d.gauss[2]),
            (0.0, [0.0; 4]),
            "13 taps: 7 weights, two rows"
        );
        assert_eq!(d.max_mip, 5);
    }

    #[test]
    fn check_depth_reports_what_the_z_pass_reports() {
        let s = sao(6, 4, 1, SaoParams::default());
        let (z, vp) = (s.z_constants(), s.viewport());
        let good = alloc::vec![0.5f32; 24];
        assert_eq!(check_depth(z, vp, &good), Ok(()));
        let cases: [alloc::vec::Vec<f32>; 4] = [
            alloc::vec![0.5; 23],
            {
                let mut d = good.clone();
                d[9] = f32::NAN;
                d[13] = 2.0;
                d
            },
            {
                let mut d = good.clone();
                d[7] = -0.25;
                d[13] = f32::INFINITY;
                d
            },
            {
                let mut d = good.clone();
                d[23] = 1.0 + f32::EPSILON;
                d
            },
        ];
        for d in &cases {
            let cpu = z.z_pass(vp, d).unwrap_err();
            assert_eq!(check_depth(z, vp, d), Err(cpu));
        }
    }
}
