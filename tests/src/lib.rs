//! Shared helpers of the workspace integration tests.
//!
//! GPU tests call [`gpu_context_or_skip`]: on a machine without any usable adapter they print
//! why and pass vacuously, unless `OCEAN_REQUIRE_GPU=1` is set (as in CI, which runs them on
//! lavapipe with `WGPU_BACKEND=vulkan` and on llvmpipe with `WGPU_BACKEND=gl`), where a missing
//! adapter is a failure.
//!
//! Tests that need tools a fresh machine lacks (GLM's headers, `glslangValidator`,
//! `spirv-val`) call [`tool_or_skip`] or [`cpp_header_or_skip`] the same way, with
//! `OCEAN_REQUIRE_TOOLS=1` (set in CI) turning a missing tool into a failure. So
//! `cargo test --workspace` passes on a fresh machine and CI still runs everything.

use std::f64::consts::TAU;

use glam::{DVec2, Vec3};
use ocean_core::{Depth, WaveDesc, WaveSet};
use ocean_gpu::GpuContext;

/// Whether `OCEAN_REQUIRE_GPU=1` is set.
pub fn gpu_required() -> bool {
    flag("OCEAN_REQUIRE_GPU")
}

/// Whether `OCEAN_REQUIRE_TOOLS=1` is set.
pub fn tools_required() -> bool {
    flag("OCEAN_REQUIRE_TOOLS")
}

fn flag(name: &str) -> bool {
    std::env::var(name).is_ok_and(|v| v.trim() == "1")
}

/// Prints why a test is skipped, or panics when `OCEAN_REQUIRE_TOOLS=1` is set.
fn skip_or_fail(what: &str, package: &str) {
    if tools_required() {
        panic!("OCEAN_REQUIRE_TOOLS=1 is set but {what}: install Debian's `{package}`");
    }
    eprintln!(
        "SKIPPED: {what} (install Debian's `{package}`; set OCEAN_REQUIRE_TOOLS=1 to make this \
         a failure)"
    );
}

/// `program` when it can be started, else `None` after a skip message (a panic when
/// `OCEAN_REQUIRE_TOOLS=1`). `package` names the Debian package that provides it.
pub fn tool_or_skip(program: &str, package: &str) -> Option<String> {
    match std::process::Command::new(program)
        .arg("--version")
        .output()
    {
        Ok(_) => Some(program.to_owned()),
        Err(e) => {
            skip_or_fail(&format!("`{program}` cannot be run ({e})"), package);
            None
        }
    }
}

/// Whether the C++ compiler `cxx` finds `header` (for instance `glm/glm.hpp`); `false` after a
/// skip message (a panic when `OCEAN_REQUIRE_TOOLS=1`).
pub fn cpp_header_or_skip(cxx: &std::ffi::OsStr, header: &str, package: &str) -> bool {
    use std::io::Write;
    use std::process::{Command, Stdio};
    let probe = Command::new(cxx)
        .args(["-fsyntax-only", "-x", "c++", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .and_then(|mut child| {
            child
                .stdin
                .take()
                .expect("piped stdin")
                .write_all(format!("#include <{header}>\n").as_bytes())?;
            child.wait()
        });
    match probe {
        Ok(status) if status.success() => true,
        // A compiler that cannot start is the C ABI test's own failure, reported there.
        Err(_) => true,
        Ok(_) => {
            skip_or_fail(&format!("{cxx:?} does not find <{header}>"), package);
            false
        }
    }
}

/// The headless GPU context (adapter chosen by `WGPU_BACKEND`), or `None` after printing a skip
/// message when no usable adapter exists.
///
/// # Panics
///
/// When `OCEAN_REQUIRE_GPU=1` is set and no context can be created: CI must not pass GPU tests
/// by skipping them.
pub fn gpu_context_or_skip() -> Option<GpuContext> {
    match GpuContext::headless() {
        Ok(ctx) => {
            eprintln!("GPU tests on {}", ctx.describe());
            Some(ctx)
        }
        Err(e) if gpu_required() => {
            panic!("OCEAN_REQUIRE_GPU=1 is set but no GPU context could be created: {e}")
        }
        Err(e) => {
            eprintln!(
                "SKIPPED: no usable GPU adapter ({e}). Set OCEAN_REQUIRE_GPU=1 to make this a \
                 failure."
            );
            None
        }
    }
}

/// A realistic sea for parity tests: six waves from 3 m to 120 m wavelength, spread over
/// directions around a mean wind from +x, deep and finite depth, steepness k·A from 0.05 to 0.6,
/// Σ k·A = 1.5 (so crests fold where waves align: the normals' worst case, as in the lighting
/// paper's spectra).
pub fn realistic_waves() -> WaveSet {
    // (wavelength m, steepness k·A, direction angle rad, phase rad, depth)
    let spec: [(f64, f64, f64, f64, Depth); 6] = [
        (120.0, 0.05, 0.0, 0.0, Depth::Deep),
        (57.0, 0.12, 0.35, 1.3, Depth::Deep),
        (23.0, 0.2, -0.6, 2.9, Depth::Finite(15.0)),
        (9.5, 0.35, 1.1, -0.7, Depth::Deep),
        (5.2, 0.6, -1.4, 0.4, Depth::Deep),
        (3.1, 0.18, 2.6, -2.2, Depth::Finite(4.0)),
    ];
    let descs: Vec<WaveDesc> = spec
        .iter()
        .map(|&(wavelength, steepness, angle, phase, depth)| WaveDesc {
            amplitude: steepness * wavelength / TAU,
            wavelength,
            direction: DVec2::new(angle.cos(), angle.sin()),
            phase,
            depth,
        })
        .collect();
    WaveSet::from_descs(&descs).expect("valid wave set")
}

/// The parity tolerances (ARCHITECTURE.md, "CPU and GPU twins") between the GPU and its CPU twin: heights within 1 mm RMS,
/// horizontal positions within 1 mm at every point, normals within 0.1° at every point.
pub const HEIGHT_RMS_TOL_M: f64 = 1e-3;
/// See [`HEIGHT_RMS_TOL_M`].
pub const HORIZONTAL_MAX_TOL_M: f64 = 1e-3;
/// See [`HEIGHT_RMS_TOL_M`].
pub const NORMAL_MAX_TOL_DEG: f64 = 0.1;

/// Prints `d` under `label` and asserts the parity tolerances.
///
/// # Panics
///
/// When a difference exceeds its tolerance.
pub fn assert_parity(label: &str, d: &GridDiff) {
    println!("{label}: {d}");
    assert!(
        d.height_rms <= HEIGHT_RMS_TOL_M,
        "{label}: height RMS {} m > {HEIGHT_RMS_TOL_M} m",
        d.height_rms
    );
    assert!(
        d.horizontal_max <= HORIZONTAL_MAX_TOL_M,
        "{label}: horizontal difference {} m > {HORIZONTAL_MAX_TOL_M} m",
        d.horizontal_max
    );
    assert!(
        d.normal_max_deg <= NORMAL_MAX_TOL_DEG,
        "{label}: max normal angle {} deg > {NORMAL_MAX_TOL_DEG} deg",
        d.normal_max_deg
    );
}

/// The 256 × 256 parity grid (0.5 m × 0.75 m cells) at `origin`.
pub fn grid_256(origin: glam::DVec2) -> ocean_core::Grid {
    ocean_core::Grid {
        origin,
        spacing: glam::DVec2::new(0.5, 0.75),
        size: (256, 256),
    }
}

/// Differences between two evaluations of the same grid.
#[derive(Clone, Copy, Debug, Default)]
pub struct GridDiff {
    /// Points compared.
    pub points: usize,
    /// RMS of the height (y) difference, metres.
    pub height_rms: f64,
    /// Largest height difference, metres.
    pub height_max: f64,
    /// Largest horizontal (x, z) position difference, metres.
    pub horizontal_max: f64,
    /// RMS of the angle between normals, degrees.
    pub normal_rms_deg: f64,
    /// Largest angle between normals, degrees.
    pub normal_max_deg: f64,
}

/// Angle between two (not necessarily unit) vectors in degrees, computed as
/// atan2(|a × b|, a · b) in `f64`, which stays accurate for tiny angles (acos does not).
pub fn angle_deg(a: Vec3, b: Vec3) -> f64 {
    let a = a.as_dvec3();
    let b = b.as_dvec3();
    a.cross(b).length().atan2(a.dot(b)).to_degrees()
}

/// Compares positions and normals point by point.
///
/// # Panics
///
/// If the slices differ in length or are empty.
pub fn compare(pos_a: &[Vec3], nrm_a: &[Vec3], pos_b: &[Vec3], nrm_b: &[Vec3]) -> GridDiff {
    let n = pos_a.len();
    assert!(n > 0, "nothing to compare");
    assert!(
        nrm_a.len() == n && pos_b.len() == n && nrm_b.len() == n,
        "length mismatch"
    );
    let mut d = GridDiff {
        points: n,
        ..GridDiff::default()
    };
    let (mut h2, mut a2) = (0.0, 0.0);
    for i in 0..n {
        let (pa, pb) = (pos_a[i].as_dvec3(), pos_b[i].as_dvec3());
        let dh = (pa.y - pb.y).abs();
        h2 += dh * dh;
        d.height_max = d.height_max.max(dh);
        d.horizontal_max = d
            .horizontal_max
            .max((pa.x - pb.x).abs())
            .max((pa.z - pb.z).abs());
        let ang = angle_deg(nrm_a[i], nrm_b[i]);
        a2 += ang * ang;
        d.normal_max_deg = d.normal_max_deg.max(ang);
    }
    d.height_rms = (h2 / n as f64).sqrt();
    d.normal_rms_deg = (a2 / n as f64).sqrt();
    d
}

impl std::fmt::Display for GridDiff {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} points: height RMS {:.3e} m, max {:.3e} m; horizontal max {:.3e} m; \
             normal angle RMS {:.3e} deg, max {:.3e} deg",
            self.points,
            self.height_rms,
            self.height_max,
            self.horizontal_max,
            self.normal_rms_deg,
            self.normal_max_deg
        )
    }
}

/// A one-level, single-sample 2D texture of `size` texels: the colour and depth targets of the
/// tests that draw.
pub fn texture_2d(
    ctx: &GpuContext,
    size: (u32, u32),
    format: ocean_gpu::wgpu::TextureFormat,
    usage: ocean_gpu::wgpu::TextureUsages,
) -> ocean_gpu::wgpu::Texture {
    use ocean_gpu::wgpu;
    ctx.device().create_texture(&wgpu::TextureDescriptor {
        label: None,
        size: wgpu::Extent3d {
            width: size.0,
            height: size.1,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage,
        view_formats: &[],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angle_of_known_vectors() {
        assert_eq!(angle_deg(Vec3::Y, Vec3::Y), 0.0);
        assert!((angle_deg(Vec3::Y, Vec3::X) - 90.0).abs() < 1e-12);
        // 1e-4 rad = 5.7296e-3 deg, resolved exactly where acos(dot) would round to 0.
        let tilted = Vec3::new(1e-4f32.sin(), 1e-4f32.cos(), 0.0);
        assert!((angle_deg(Vec3::Y, tilted) - 1e-4f64.to_degrees()).abs() < 1e-9);
    }

    #[test]
    fn compare_reports_rms_and_max() {
        // Heights differ by 0 and 2 mm: RMS = sqrt((0 + 4e-6) / 2) = 1.414 mm, max 2 mm.
        let a = [Vec3::ZERO, Vec3::ZERO];
        let b = [Vec3::ZERO, Vec3::new(0.0, 0.002, 0.0)];
        let n = [Vec3::Y, Vec3::Y];
        let d = compare(&a, &n, &b, &n);
        assert!((d.height_rms - 0.002 / 2f64.sqrt()).abs() < 1e-9);
        assert!((d.height_max - 0.002).abs() < 1e-9);
        assert_eq!(d.normal_max_deg, 0.0);
    }

    #[test]
    fn realistic_waves_are_steep_and_varied() {
        let w = realistic_waves();
        assert_eq!(w.waves().len(), 6);
        assert!((w.steepness_sum() - 1.5).abs() < 1e-12);
        assert!(w.waves().iter().any(|w| w.steepness() >= 0.5));
    }
}
