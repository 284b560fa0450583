//! Parameters of the passes, their defaults and their accepted ranges.

use core::f32::consts::FRAC_PI_2;

use crate::SaoError;
use crate::error::check_range;
use crate::hierarchy::MipFilter;
use crate::reconstruct::{NormalEstimate, NormalRejection};

/// Largest sample count `s` accepted.
pub const MAX_SAMPLES: u32 = 64;
/// Largest MIP level accepted (`log₂ MAX_SIDE − 1`).
pub const MAX_MIP: u32 = 13;
/// Largest `log₂ q'` accepted (q' = 256 px).
pub const MAX_MIP_SWITCH_LOG2: u32 = 8;
/// Largest blur tap count accepted.
pub const MAX_BLUR_TAPS: u32 = 63;

/// The obscurance estimator of the sample pass. Both sum over the `n` samples `Q_i` that fall
/// inside the input image, with `v = Q_i − C`, the face normal `n̂` and the world-space radius
/// `r`; samples outside the ball (`v·v ≥ r²`) contribute nothing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Estimator {
    /// AlchemyAO's estimator, Eq. 1:
    /// `A = max(0, 1 − (2σ/n)·Σ max(0, v·n̂ + z_C·β)/(v·v + ε))^k`.
    ///
    /// Eq. 1 itself sums over "points distributed on a ball about C"; the ball test makes that
    /// explicit for depth-buffer samples that land farther away.
    Alchemy {
        /// Intensity σ (metres: the sum has units of 1/m).
        sigma: f32,
        /// Depth-proportional bias β (`z_C·β` is in metres; `z_C < 0`, so it subtracts).
        beta: f32,
        /// Contrast exponent k.
        k: f32,
    },
    /// The updated falloff of the paper's appendix (June 2012):
    /// `A = max(0, 1 − (5·intensity/(r⁶·n))·Σ max(r² − v·v, 0)³·max((v·n̂ − β)/(v·v + ε), 0))`,
    /// evaluated with `(r² − v·v)³/r⁶ = (max(r² − v·v, 0)·(1/r²))³`. The appendix's formula
    /// has no intensity: 1 reproduces it, other values scale the obscurance.
    Falloff {
        /// Bias β in metres (the appendix: ≈ 1 cm in human-scale scenes).
        beta: f32,
        /// Intensity multiplier.
        intensity: f32,
    },
}

impl Estimator {
    /// The appendix's falloff with β = 1 cm and intensity 1.
    pub const FALLOFF: Self = Self::Falloff {
        beta: 0.01,
        intensity: 1.0,
    };

    /// Eq. 1 with σ = 0.25 m, β = 10⁻³ (1 cm at 10 m) and k = 1: an aesthetic choice (the paper
    /// gives no values).
    pub const ALCHEMY: Self = Self::Alchemy {
        sigma: 0.25,
        beta: 1.0e-3,
        k: 1.0,
    };
}

/// What the bilateral reconstruction compares a tap's depth key with (see [`crate::blur`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum BlurWeight {
    /// The centre pixel's key, as the paper (§2.4): on a surface sloped to the view the taps
    /// of the surface itself differ from the centre and are rejected, so the sampling pattern
    /// stays visible there.
    Depth,
    /// The key the plane through the centre pixel predicts at the tap, the plane's slope along
    /// the pass's axis taken from the nearer-in-depth of the two adjacent pixels: taps on the
    /// same sloped surface count fully, taps across a depth edge do not.
    #[default]
    Plane,
}

/// The separable bilateral reconstruction (§2.4): `taps` taps `stride` pixels apart, Gaussian
/// weights `exp(−t²/(2σ²))` for tap `t` (in taps, −R..=R with `R = (taps − 1)/2`) times
/// `max(0, 1 − depth_scale·|key_t − key_ref|)` where `key = z/z_min` is the packed depth and
/// `key_ref` the centre's key or the centre plane's prediction ([`BlurWeight`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlurParams {
    /// Tap count (odd): 7 in the paper (the released shader used 9), 13 by default.
    pub taps: u32,
    /// Pixels between taps: 3 in the paper (the released shader used 2), 1 by default.
    pub stride: u32,
    /// Depth-difference scale: 2¹¹ in the paper (the released shader used 2000).
    pub depth_scale: f32,
    /// Gaussian standard deviation in taps. The paper does not print it; R/2 (1.5 for 7 taps,
    /// 3 for the default 13) gives the outermost taps e⁻² of the centre's weight.
    pub sigma: f32,
    /// What a tap's key is compared with (default [`BlurWeight::Plane`]; the paper:
    /// [`BlurWeight::Depth`]).
    pub weight: BlurWeight,
    /// With [`BlurWeight::Plane`]: the distance from the centre, as a fraction of the
    /// obscurance radius, at which a tap's weight fades to 0 ([`crate::blur`]), in `[0, 10³]`;
    /// 0 disables the fade. Default 0.5: a compromise measured on boxes on a floor and the
    /// analytic scenes at 640 × 360 with the paper's 7 taps of stride 3: larger values leave
    /// less of the sampling pattern on faces seen at grazing angles (RMS against the 7 × 7
    /// mean beyond 70°: 5.3–5.7/255 at 0.5,
    /// 4.4–4.7 without the fade, 11–12 with the paper's weight) and spread contact obscurance
    /// farther (error against the estimator's 256-sample limit: 0.5 gives 14–20% more MSE than
    /// the paper's weight on the crease and the box in a room, 5% less on the spheres; 0.3
    /// gives 9% more to 18% less, no fade 35–55% more).
    pub world_extent: f32,
}

impl Default for BlurParams {
    /// 13 adjacent taps (σ = 3 taps, the outermost e⁻² of the centre as in the paper's) with
    /// the plane weight. The paper's 7 taps 3 pixels apart average only pixels whose
    /// coordinates agree modulo 3: on surfaces obscured everywhere and uneven at the scale of
    /// a pixel (a relief-mapped rock), where the sample pass's per-pixel rotation leaves its
    /// strongest residue, each pixel of a 3 × 3 cell keeps its own average, and the result is
    /// a lattice of that period. Adjacent taps over a 13-pixel span average every pixel with
    /// its neighbours and leave none.
    fn default() -> Self {
        Self {
            taps: 13,
            stride: 1,
            depth_scale: 2048.0,
            sigma: 3.0,
            weight: BlurWeight::Plane,
            world_extent: 0.5,
        }
    }
}

impl BlurParams {
    /// The paper's blur (§2.4): 7 taps 3 pixels apart, σ = 1.5 taps, weighed by the centre's
    /// depth key with scale 2¹¹.
    pub fn paper() -> Self {
        Self {
            taps: 7,
            stride: 3,
            depth_scale: 2048.0,
            sigma: 1.5,
            weight: BlurWeight::Depth,
            world_extent: 0.5,
        }
    }
}

impl BlurParams {
    /// Checks the ranges: `taps` odd in `1 ..= 63`, `stride` in `1 ..= 64`, `depth_scale` in
    /// `[0, 10⁹]`, `sigma` in `[10⁻³, 10³]`, `world_extent` in `[0, 10³]`.
    ///
    /// # Errors
    ///
    /// [`SaoError::EvenTaps`], [`SaoError::OutOfRange`], [`SaoError::NotFinite`].
    pub fn validate(&self) -> Result<(), SaoError> {
        check_range(
            "blur.taps",
            f64::from(self.taps),
            1.0,
            f64::from(MAX_BLUR_TAPS),
        )?;
        if self.taps.is_multiple_of(2) {
            return Err(SaoError::EvenTaps(self.taps));
        }
        check_range("blur.stride", f64::from(self.stride), 1.0, 64.0)?;
        check_range("blur.depth_scale", self.depth_scale, 0.0, 1.0e9)?;
        check_range("blur.sigma", self.sigma, 1.0e-3, 1.0e3)?;
        check_range("blur.world_extent", self.world_extent, 0.0, 1.0e3)?;
        Ok(())
    }

    /// `R = (taps − 1)/2`.
    pub fn radius(&self) -> u32 {
        self.taps / 2
    }

    /// The Gaussian weights for taps `0..=R` (unnormalised: the blur divides by the sum of the
    /// weights it used), computed in `f64` and rounded to `f32`.
    pub fn gaussian(&self) -> alloc::vec::Vec<f32> {
        let s = f64::from(self.sigma);
        (0..=self.radius())
            .map(|t| {
                let t = f64::from(t);
                libm::exp(-t * t / (2.0 * s * s)) as f32
            })
            .collect()
    }
}

/// All parameters of the CPU reference (and of its GPU twin).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SaoParams {
    /// World-space radius r of the ball, metres, in `[10⁻⁴, 10⁴]`.
    pub radius: f32,
    /// Samples per pixel `s`, in `1 ..= 64` (the paper: 9).
    pub samples: u32,
    /// Spiral turns τ, in `[10⁻³, 10³]` (the paper: 7 for 9 samples; see
    /// [`crate::spiral::default_spiral_turns`] for this crate's convention for other `s`).
    pub spiral_turns: f32,
    /// `log₂ q'` of Eq. 9, in `0 ..= 8` (the paper: all of 2³ ≤ q' ≤ 2⁵ are equivalent; the
    /// released shader: 3). `q'` is a power of two so that Eq. 9 is an integer bit operation.
    pub mip_switch_log2: u32,
    /// Highest MIP level read, in `0 ..= 13` (the released shader: 5). 0 reads every sample from
    /// level 0 (no hierarchy).
    pub max_mip: u32,
    /// The MIP filter (Table 1).
    pub mip_filter: MipFilter,
    /// The estimator (Eq. 1 or the appendix).
    pub estimator: Estimator,
    /// ε of Eq. 1 and the appendix, in m², in `[10⁻¹², 10⁴]` (> 0 so that a sample at C itself
    /// never divides 0 by 0).
    pub epsilon: f32,
    /// The 2×2 quad bilateral of §2.3: pairs of pixels are averaged when their z differ by less
    /// than this many metres (default 0.02 m); `None` disables the filter.
    pub quad_depth_threshold: Option<f32>,
    /// How face normals are reconstructed (default [`NormalEstimate::Nearest`]; the paper:
    /// [`NormalEstimate::Quad`]).
    pub normals: NormalEstimate,
    /// Reject unreliable normals at depth edges (`None`: the paper's behaviour).
    pub normal_rejection: Option<NormalRejection>,
    /// `z_min` of the packing (§2.3), metres, negative, in `[−10⁸, −10⁻⁴]`: the farthest plane
    /// at which sharp AO features are desired (the paper: −200 m).
    pub z_min: f32,
    /// The bilateral reconstruction passes (§2.4).
    pub blur: BlurParams,
}

impl Default for SaoParams {
    fn default() -> Self {
        Self {
            radius: 1.0,
            samples: 9,
            spiral_turns: 7.0,
            mip_switch_log2: 3,
            max_mip: 5,
            mip_filter: MipFilter::RotatedGrid,
            estimator: Estimator::FALLOFF,
            epsilon: 0.01,
            quad_depth_threshold: Some(0.02),
            normals: NormalEstimate::Nearest,
            normal_rejection: None,
            z_min: -200.0,
            blur: BlurParams::default(),
        }
    }
}

impl SaoParams {
    /// The defaults with the paper's own normals (Eq. 4's quad differences) and blur (§2.4: 7
    /// taps 3 pixels apart, weighed by the centre's depth key): the reference the fidelity
    /// tests and comparisons use.
    pub fn paper() -> Self {
        let d = Self::default();
        Self {
            normals: NormalEstimate::Quad,
            blur: BlurParams::paper(),
            ..d
        }
    }
}

impl SaoParams {
    /// Checks every range documented on the fields.
    ///
    /// # Errors
    ///
    /// [`SaoError::NotFinite`], [`SaoError::OutOfRange`], [`SaoError::EvenTaps`].
    pub fn validate(&self) -> Result<(), SaoError> {
        check_range("radius", self.radius, 1.0e-4, 1.0e4)?;
        check_range(
            "samples",
            f64::from(self.samples),
            1.0,
            f64::from(MAX_SAMPLES),
        )?;
        check_range("spiral_turns", self.spiral_turns, 1.0e-3, 1.0e3)?;
        check_range(
            "mip_switch_log2",
            f64::from(self.mip_switch_log2),
            0.0,
            f64::from(MAX_MIP_SWITCH_LOG2),
        )?;
        check_range("max_mip", f64::from(self.max_mip), 0.0, f64::from(MAX_MIP))?;
        check_range("epsilon", self.epsilon, 1.0e-12, 1.0e4)?;
        match self.estimator {
            Estimator::Alchemy { sigma, beta, k } => {
                check_range("sigma", sigma, 0.0, 1.0e4)?;
                check_range("beta", beta, 0.0, 1.0)?;
                check_range("k", k, 1.0e-2, 16.0)?;
            }
            Estimator::Falloff { beta, intensity } => {
                check_range("beta", beta, 0.0, 1.0e3)?;
                check_range("intensity", intensity, 0.0, 1.0e3)?;
            }
        }
        if let Some(t) = self.quad_depth_threshold {
            check_range("quad_depth_threshold", t, 0.0, 1.0e6)?;
        }
        if let Some(r) = self.normal_rejection {
            check_range(
                "normal_rejection.max_incidence",
                r.max_incidence,
                1.0e-3,
                FRAC_PI_2 - 1.0e-3,
            )?;
        }
        check_range("z_min", self.z_min, -1.0e8, -1.0e-4)?;
        self.blur.validate()
    }
}
