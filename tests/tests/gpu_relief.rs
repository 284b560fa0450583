//! GPU/CPU parity of relief mapping: `ocean_gpu::ReliefRenderer`'s tracer and shadow
//! test against `ocean_relief`'s CPU tracers and `shadow::in_shadow` (through its probe, on rays
//! at 0–80° from the normal over several maps, both edge modes and every method), its headless
//! render against the CPU twin pixel by pixel (the depth it writes against
//! `occlusion::occlusion_depth`, shadowed and lit pixels against `in_shadow`, the shading), its
//! occlusion in the caller's depth buffer, `ocean_gpu::ConeMapGenerator` against
//! `ConeMap::generate`; then bad input.
//!
//! Acceptance (ARCHITECTURE.md, "CPU and GPU twins"): GPU hits within 0.01 texel of the CPU's, cone maps equal up to
//! quantisation. Both were measured bit-identical on Mesa's lavapipe (Vulkan) and llvmpipe (GL):
//! the tracer does the CPU's exact bilinear fetch and rounds every operation as the CPU does
//! (`relief_common.wgsl`), the generator computes the CPU's `f64` bound in double-`f32`
//! (`relief_cone.wgsl`). On software adapters the tests assert that bit for bit, so a
//! divergence in arithmetic fails long before the parity tolerance would; on other adapters
//! they assert the parity tolerances.
//!
//! Run with `OCEAN_REQUIRE_GPU=1` to turn a missing adapter into a failure.

use std::time::Instant;

use glam::{DVec2, DVec3, Vec2, Vec3};
use ocean_brdf::Irradiance;
use ocean_core::{Camera, DepthConvention, Far, Projection};
use ocean_gpu::relief::window_depth;
use ocean_gpu::{
    ConeMapGenerator, GpuContext, GpuError, ReliefLayout, ReliefRay, ReliefRenderer, ReliefScene,
    TangentFrame, wgpu,
};
use ocean_relief::maps::{boxes, bumps, pins, thin_walls, to_map, value_noise, white_noise};
use ocean_relief::occlusion::{occlusion_depth, view_distance};
use ocean_relief::shadow::in_shadow;
use ocean_relief::trace::BinarySearch;
use ocean_relief::{
    ConeMap, ConeParams, Edge, HeightMap, Hit, Method, QuadConeMap, QuadReliefMips,
    QuadReliefTexture, Ray, ReliefError, ReliefMips, ReliefTexture,
};
use ocean_tests::{gpu_context_or_skip, texture_2d};

/// Whether the adapter is a software rasteriser (Mesa's lavapipe or llvmpipe): there the GPU
/// was measured to match the CPU bit for bit, and the tests hold it to that.
fn software(ctx: &GpuContext) -> bool {
    ctx.adapter_info()
        .is_some_and(|i| i.device_type == wgpu::DeviceType::Cpu)
}

/// Deterministic numbers in [0, 1) (SplitMix64).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f32 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        (z >> 40) as f32 / (1u64 << 24) as f32
    }
}

/// Side of the test maps.
const N: usize = 64;

/// The parity tolerance on hits, texels.
const HIT_TOL_TEXELS: f32 = 0.01;

/// Six procedural maps (smooth and white noise, boxes with steep walls, thin walls, pins,
/// bumps) in both edge modes, 64² and, for the noise, also 50² (a side that is not a power of
/// two: a wrap-mode texel index taken modulo 50 cannot hide a wrong remainder of a negative
/// index, which modulo 64 can).
fn test_maps() -> Vec<(&'static str, HeightMap)> {
    let mut out = Vec::new();
    for edge in [Edge::Wrap, Edge::Clamp] {
        let m = |h: Vec<f32>| to_map(N, &h, edge).unwrap();
        out.push((
            "noise 50",
            to_map(50, &value_noise(50, 5, 4, 21), edge).unwrap(),
        ));
        out.push(("noise", m(value_noise(N, 4, 4, 1))));
        out.push(("boxes", m(boxes(N, 12, 2))));
        out.push(("walls", m(thin_walls(N, 8))));
        out.push(("pins", m(pins(N, 40, 3))));
        out.push(("bumps", m(bumps(N, 10, 6.0, 4))));
        out.push(("white", m(white_noise(N, 5))));
    }
    out
}

/// Every method and binary search the shader supports, with the book's and the accuracy
/// table's step counts and the degenerate ones (one linear step; no bisection).
fn methods() -> Vec<Method> {
    vec![
        Method::Linear {
            linear: 15,
            binary: 6,
        },
        Method::Linear {
            linear: 1,
            binary: 0,
        },
        Method::ConeStep { steps: 21 },
        Method::Relaxed {
            cone: 15,
            binary: 6,
            search: BinarySearch::LastStep,
        },
        Method::Relaxed {
            cone: 15,
            binary: 6,
            search: BinarySearch::Book,
        },
        Method::Relaxed {
            cone: 32,
            binary: 6,
            search: BinarySearch::Shared,
        },
        Method::Relaxed {
            cone: 3,
            binary: 0,
            search: BinarySearch::LastStep,
        },
    ]
}

/// Polar angles of the rays from the normal, degrees.
const ANGLES: [f32; 6] = [0.0, 20.0, 40.0, 60.0, 70.0, 80.0];
/// Relief depths of the rays, texture widths.
const SCALES: [f32; 4] = [0.05, 0.1, 0.2, 0.4];

/// Rays at every angle of [`ANGLES`], any azimuth, every depth of [`SCALES`], starting
/// anywhere on the tile and its neighbours, each with a light from a random direction above the
/// polygon (and one in 16 at or below it, where `in_shadow` answers "shadowed" without tracing).
fn rays(rng: &mut Rng, count: usize) -> Vec<(Vec2, Vec3, f32, Vec3)> {
    (0..count)
        .map(|k| {
            let theta = ANGLES[k % ANGLES.len()].to_radians();
            let phi = rng.next() * std::f32::consts::TAU;
            let (s, c) = theta.sin_cos();
            let view = Vec3::new(s * phi.cos(), s * phi.sin(), -c);
            let start = Vec2::new(rng.next() * 1.5 - 0.25, rng.next() * 1.5 - 0.25);
            let scale = SCALES[(k / ANGLES.len()) % SCALES.len()];
            let lz = if k % 16 == 5 {
                -rng.next() * 0.5
            } else {
                rng.next() + 0.05
            };
            let light = Vec3::new(rng.next() - 0.5, rng.next() - 0.5, lz);
            (start, view, scale, light)
        })
        .collect()
}

/// The largest distance between two hits in texels, horizontally (uv) and vertically (a depth
/// unit is `scale` texture widths).
fn texel_distance(a: Vec3, b: Vec3, scale: f32, n: usize) -> f32 {
    let d = (a - b).abs();
    d.x.max(d.y).max(d.z * scale) * n as f32
}

#[path = "gpu_relief/bad_input.rs"]
mod bad_input;
#[path = "gpu_relief/cones.rs"]
mod cones;
use probe::MIP_LEVELS;
use render::{Setup, cameras};

#[path = "gpu_relief/probe.rs"]
mod probe;
#[path = "gpu_relief/render.rs"]
mod render;
#[path = "gpu_relief/timing.rs"]
mod timing;
