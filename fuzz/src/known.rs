//! Non-finite outputs already found and reported, skipped so that a campaign can go past them.
//! Each entry names the function, says when it happens and how to reproduce it; remove the
//! entry when the library is fixed. FUZZING.md lists them too.

use std::any::Any;
use std::fmt::Debug;

use crate::cmem::CMem;

use ocean::{
    OceanCamera, OceanDVec2, OceanDVec3, OceanGrid, OceanReliefMethod, OceanReliefRay,
    OceanSeaColorInput, OceanSeaParams, OceanSkyParams,
};

/// The sky of a lighting query's inputs, as the harness reports them (`ops_lighting.rs`).
fn sky_of(a: &dyn Any) -> Option<&OceanSkyParams> {
    type Made = Option<(OceanSkyParams, OceanSeaParams)>;
    let made = a
        .downcast_ref::<Made>()
        .or_else(|| a.downcast_ref::<(Made, OceanDVec3)>().map(|x| &x.0))
        .or_else(|| a.downcast_ref::<(Made, OceanSeaColorInput)>().map(|x| &x.0))
        .or_else(|| {
            a.downcast_ref::<(Made, Vec<OceanSeaColorInput>, usize)>()
                .map(|x| &x.0)
        })
        .or_else(|| a.downcast_ref::<(Made, u32, usize)>().map(|x| &x.0))?;
    made.as_ref().map(|(sky, _)| sky)
}

/// A CIE gradation 1 + a exp(b / cos theta) with a != 0 and b > 0: unbounded towards the
/// horizon.
fn unbounded_gradation(a: &dyn Any) -> bool {
    sky_of(a).is_some_and(|s| s.cie.a != 0.0 && s.cie.b > 0.0)
}

/// The inputs of a checked call, as passed to `check::outputs`: printable, and typed, so that
/// an entry below can recognise its case.
pub trait Args: Debug + Any {}
impl<T: Debug + Any> Args for T {}

/// One known case of a successful call with a non-finite output.
pub struct Known {
    /// The C ABI function.
    pub function: &'static str,
    /// Whether `inputs` (the tuple the call site passes) is this case.
    pub matches: fn(&dyn Any) -> bool,
    /// What goes wrong, and a reproducing input.
    pub note: &'static str,
}

/// The note of every lighting output of a sky whose gradation is unbounded.
const UNBOUNDED_SKY: &str = "a CIE sky whose gradation 1 + a exp(b / cos theta) grows without \
    bound towards the horizon (a != 0, b > 0; every coefficient is only required to lie in \
    [-1000, 1000] and give non-negative radiance, include/ocean.h) is accepted by \
    ocean_lighting_create, and then its irradiance quadrature overflows: the sky irradiance \
    and what derives from it (irradiance, sea and environment radiance, sea colour, sky map \
    texels) are +inf or NaN. Reproducer: fuzz/known/unbounded_sky_gradation.bin (a = b = c = \
    10.75, d = -3, e = 0.45, zenith radiance (10.75, 1.2e-38, 10.75), the default Sun).";

/// A traced ray starting beyond 1e30 texture widths.
fn far_ray_start(a: &dyn Any) -> bool {
    a.downcast_ref::<(CMem<OceanReliefMethod>, Vec<OceanReliefRay>, usize)>()
        .is_some_and(|(_, rays, n)| {
            rays[..*n]
                .iter()
                .any(|r| r.start_u.abs() > 1e30 || r.start_v.abs() > 1e30)
        })
}

/// The note of the relief tracers' case.
const FAR_RAY_START: &str = "a ray whose start (u, v) is finite but huge (any float is \
    accepted) is traced to a hit at u or v = -inf. Reproducer: \
    fuzz/known/relief_trace_far_start.bin (linear search, 36 steps, 12 binary; rays starting at \
    u = -3.4028235e38 or v = -3.4028235e38, direction (0.3, -0.2, 1)).";

/// The known non-finite cases.
pub const KNOWN_NON_FINITE: &[Known] = &[
    Known {
        function: "ocean_pixel_footprint",
        matches: |a| {
            a.downcast_ref::<(CMem<OceanCamera>, u32, u32, f64, f64, f64)>()
                .is_some_and(|&(.., max_distance)| max_distance > 1e150)
        },
        note: "max_distance above about 1e154 m: rays beyond the horizon stop that far away, and the \
           footprint, the length of the difference of two such hits (ocean-brdf's \
           pixel_footprint, a square root of a sum of squares), overflows to +inf although the \
           call succeeds. Reproducer: fuzz/known/pixel_footprint_overflow.bin (camera 10 m up \
           looking along -z, viewport 4294967295 x 1077883164, pixel (100, 172.65625), \
           max_distance 5.06e254).",
    },
    Known {
        function: "ocean_surface_wave_texels",
        matches: |a| {
            a.downcast_ref::<(CMem<OceanCamera>, f64, usize)>()
                .is_some_and(|&(_, time, _)| time.abs() > 1e300)
        },
        note: "a finite `time` so large that omega * time overflows (|time| above about \
               f64::MAX / omega, 3e306 s for the shortest default wave): the phase \
               k.o - omega t + phi of ocean-core's Wave::phase_at is -inf, and its reduction \
               (ocean-core/src/phase.rs) NaN, written as the phase texel although the call \
               succeeds. Reproducer: fuzz/known/wave_texels_time_overflow.bin (written by \
               hand: a spectrum of the default parameters with wave_count 1, then the draw \
               data with the default camera, z_near 0.5, and time = f64::MAX).",
    },
    Known {
        function: "ocean_waves_evaluate",
        matches: |a| {
            a.downcast_ref::<(Vec<OceanDVec2>, usize, f64)>()
                .is_some_and(|&(_, _, time)| time.abs() > 1e300)
        },
        note: "the same overflow of omega * time (ocean-core's Wave::phase_at) in the CPU \
               evaluation: every position and normal NaN although the call succeeds. \
               Reproducer: fuzz/known/waves_evaluate_time_overflow.bin (written by hand: one \
               wave of the harness's defaults, amplitude 0.5 m, wavelength 20 m, infinite \
               depth, evaluated at one point at time = f64::MAX).",
    },
    Known {
        function: "ocean_waves_evaluate_grid",
        matches: |a| {
            a.downcast_ref::<(OceanGrid, f64)>().is_some_and(|&(g, _)| {
                let max = f64::from(f32::MAX);
                g.nx as f64 * g.spacing_x > max || g.nz as f64 * g.spacing_z > max
            })
        },
        note: "a grid whose extent does not fit in a float (nx * spacing_x or nz * spacing_z \
               above f32::MAX) is accepted (a spacing need only be finite and > 0) but its \
               positions, floats relative to the origin, overflow: +inf, and NaN even at \
               point (0, 0) (0 times an infinite float spacing). Reproducer: \
               fuzz/known/waves_grid_huge_spacing.bin (a 1 x 1 grid, spacing_x 2.57e151, time \
               -1.4e-296).",
    },
    Known {
        function: "ocean_waves_evaluate_grid",
        matches: |a| {
            a.downcast_ref::<(OceanGrid, f64)>()
                .is_some_and(|&(_, time)| time.abs() > 1e300)
        },
        note: "the same overflow on a grid: every position and normal NaN. Reproducer: \
               fuzz/known/waves_grid_time_overflow.bin (a 1 x 4 grid at time = f64::MAX).",
    },
    Known {
        function: "ocean_lighting_sky_irradiance",
        matches: unbounded_gradation,
        note: UNBOUNDED_SKY,
    },
    Known {
        function: "ocean_lighting_irradiance",
        matches: unbounded_gradation,
        note: UNBOUNDED_SKY,
    },
    Known {
        function: "ocean_lighting_sea_radiance",
        matches: unbounded_gradation,
        note: UNBOUNDED_SKY,
    },
    Known {
        function: "ocean_lighting_below_horizon_radiance",
        matches: unbounded_gradation,
        note: UNBOUNDED_SKY,
    },
    Known {
        function: "ocean_lighting_environment_radiance",
        matches: unbounded_gradation,
        note: UNBOUNDED_SKY,
    },
    Known {
        function: "ocean_sea_color",
        matches: unbounded_gradation,
        note: UNBOUNDED_SKY,
    },
    Known {
        function: "ocean_sea_color_batch",
        matches: unbounded_gradation,
        note: UNBOUNDED_SKY,
    },
    Known {
        function: "ocean_sky_map_copy_level",
        matches: unbounded_gradation,
        note: UNBOUNDED_SKY,
    },
    Known {
        function: "ocean_relief_trace",
        matches: far_ray_start,
        note: FAR_RAY_START,
    },
    Known {
        function: "ocean_relief_quad_trace",
        matches: far_ray_start,
        note: FAR_RAY_START,
    },
    Known {
        function: "ocean_wtb_scene_evaluate (filtered_slope_variance)",
        matches: |_| true,
        note: "OceanFrameStats::filtered_slope_variance is NaN after a successful evaluation of \
               a scene whose train filter removes a train (filtered_trains 1, removed_trains \
               1; refraction and shoaling on, an explicit budget of SIZE_MAX trains; the cause \
               is not yet narrowed down). Reproducer: \
               fuzz/known/scene_filtered_slope_variance_nan.bin.",
    },
];

/// Whether the non-finite output of `function` for `inputs` is a known case. With
/// `OCEAN_FUZZ_REPORT_KNOWN=1` in the environment none is: a reproducer in `fuzz/known/` then
/// crashes, which shows that it still reproduces.
pub fn known_non_finite(function: &str, inputs: &dyn Args) -> bool {
    if std::env::var_os("OCEAN_FUZZ_REPORT_KNOWN").is_some_and(|v| v == "1") {
        return false;
    }
    let inputs: &dyn Any = inputs;
    KNOWN_NON_FINITE
        .iter()
        .any(|k| k.function == function && (k.matches)(inputs))
}
