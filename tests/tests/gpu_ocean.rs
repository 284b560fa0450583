//! The GPU ocean renderer (`ocean_gpu::OceanRenderer`, Bruneton et al. 2010) against its CPU
//! twins in `ocean_brdf`: the sea colour of Algorithm 5.1, the projected grid's geometry (rays,
//! sea-plane hits, footprints, Eq. 2), the per-pixel normal and slope variance (Eq. 3 and 4),
//! the waves each sum visits, a stored reference image, and the error paths.
//!
//! The probes (`probe_sea_color`, `probe_surface`) run the render shaders' own WGSL functions on
//! lists of inputs, so what is compared here is what the vertex and fragment stages compute.
//!
//! Run with `OCEAN_REQUIRE_GPU=1` to turn a missing adapter into a failure (CI runs these on
//! lavapipe with `WGPU_BACKEND=vulkan` and on llvmpipe with `WGPU_BACKEND=gl`). The reference
//! image is rewritten with `OCEAN_BLESS=1`.

use std::path::PathBuf;

use glam::{DVec2, DVec3};
use ocean_brdf::sea::{sea_color_unchecked, visible_normal};
use ocean_brdf::surface::{pixel_footprint, pixel_ray, sea_plane_hit};
use ocean_brdf::{
    Filter, FilteredSurface, Lighting, SeaLight, SeaParams, SkyParams, SlopeVariance, Spectrum,
    SpectrumParams,
};
use ocean_core::{Camera, DepthConvention, Far, Projection};
use ocean_gpu::{GpuContext, GpuError, OceanOptions, OceanRenderer, SeaColorInput, wgpu};
use ocean_tests::{gpu_context_or_skip, texture_2d};

/// The default sea: 60 waves from 2 cm to 30 m under a 10 m/s wind, the paper's filter.
fn surface() -> FilteredSurface {
    let spectrum = Spectrum::new(SpectrumParams::default()).expect("default spectrum");
    FilteredSurface::new(&spectrum, Filter::PAPER).expect("default surface")
}

/// The default clear sky (Sun 25° up towards −z) over deep blue water.
fn lighting() -> Lighting {
    Lighting::new(SkyParams::default(), SeaParams::default()).expect("default lighting")
}

/// A camera at `eye` looking along `dir`, 60° vertical field of view, for a `width × height`
/// viewport.
fn camera(eye: DVec3, dir: DVec3, width: u32, height: u32, depth: DepthConvention) -> Camera {
    Camera::look_at(
        eye,
        eye + dir,
        DVec3::Y,
        Projection::Perspective {
            fov_y: 60f64.to_radians(),
            aspect: f64::from(width) / f64::from(height),
            near: 0.1,
            far: Far::Finite(100_000.0),
        },
        depth,
    )
    .expect("valid camera")
}

/// 4 m above the sea, looking at the horizon towards the Sun (−z).
fn horizon_camera(width: u32, height: u32) -> Camera {
    camera(
        DVec3::new(0.0, 4.0, 0.0),
        DVec3::new(0.0, 0.0, -1.0),
        width,
        height,
        DepthConvention::ZERO_TO_ONE,
    )
}

fn renderer(ctx: &GpuContext, options: OceanOptions) -> OceanRenderer {
    let mut r = OceanRenderer::new(ctx, options).expect("renderer");
    r.set_surface(ctx, &surface()).expect("surface");
    r.set_lighting(ctx, &lighting()).expect("lighting");
    r
}

fn unit(v: DVec3) -> DVec3 {
    v.normalize()
}

/// A unit vector `elevation` degrees above the horizon, at `azimuth` degrees from +x towards +z.
fn dir(elevation: f64, azimuth: f64) -> DVec3 {
    let (e, a) = (elevation.to_radians(), azimuth.to_radians());
    DVec3::new(e.cos() * a.cos(), e.sin(), e.cos() * a.sin())
}

#[path = "gpu_ocean/bad_input.rs"]
mod bad_input;
#[path = "gpu_ocean/geometry.rs"]
mod geometry;
#[path = "gpu_ocean/images.rs"]
mod images;
#[path = "gpu_ocean/sea_color.rs"]
mod sea_color;
