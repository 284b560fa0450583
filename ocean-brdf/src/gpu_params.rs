//! The ocean renderer's uniform block and wave texture (`ocean-gpu`'s `ocean_common.wgsl`),
//! defined here beside the filtering and lighting they encode, so that the renderer, the C
//! ABI's `ocean_surface_uniforms` and an engine drawing the exported shader share one layout.
//! [`WaveTexels`] holds a filtered surface's per-wave data (Eq. 2 to 4, Appendix A) with the
//! phases reduced modulo 2π in `f64`; `ocean-gpu` fills [`FrameUniform`] from a camera, the
//! renderer's options and a [`crate::Lighting`].

use alloc::vec;
use alloc::vec::Vec;

use glam::DVec2;
use ocean_core::phase::reduce_angle;
use ocean_core::{Camera, Wave};

use crate::FilteredSurface;
use crate::variance::{trochoid_slope_variance, wave_variance_term};

/// Rows of the wave texture.
pub const WAVE_ROWS: u32 = 3;

/// The shaders' uniform block, byte for byte the WGSL `Frame` of `ocean_common.wgsl` (352 bytes,
/// std140); the field documentation is there.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct FrameUniform {
    /// Camera-relative position → clip (WebGPU depth range).
    pub view_proj: [[f32; 4]; 4],
    /// Clip → camera-relative position.
    pub inv_view_proj: [[f32; 4]; 4],
    /// Eye height, distance cap, NDC depth of the near plane, NDC depth halfway to the far one.
    pub camera: [f32; 4],
    /// Viewport size (px), pixel position of grid vertex (0, 0).
    pub viewport: [f32; 4],
    /// Cell size (px), N_min, N_max, exposure.
    pub grid: [f32; 4],
    /// Grid vertices per row, grid rows, waves, flags (bit 0: sRGB-encode in the shader).
    pub counts: [u32; 4],
    /// Wind direction (x, z), Fresnel R, the Sun's solid angle.
    pub sea: [f32; 4],
    /// Unit vector towards the Sun, cos of its angular radius.
    pub sun_dir: [f32; 4],
    /// The Sun's radiance (rgb), NDC depth of the far plane.
    pub sun_radiance: [f32; 4],
    /// `L_sea` (rgb).
    pub sea_radiance: [f32; 4],
    /// Sky map size, its stereographic half-width, the Sun's least slope variance.
    pub sky: [f32; 4],
    /// Probe item count.
    pub probe: [u32; 4],
    /// Local waves: the local grid's point (0, 0) relative to o, 1 / its spacing.
    pub local: [f32; 4],
    /// Local grid points per row and rows, local trains.
    pub local_counts: [u32; 4],
    /// The caller's mesh (`mesh_vs`): its grid point (0, 0) at rest relative to the eye, its
    /// spacing.
    pub mesh_grid: [f32; 4],
    /// The mesh's grid points per row and rows.
    pub mesh_counts: [u32; 4],
}

/// The wave texture of a filtered surface (binding 1 of `ocean_common.wgsl`): one column per
/// wave, longest first, three rows of `rgba32float` texels.
///
/// Row 0 holds `(λ, k_x, k_z, θ₀)` with the phase `θ₀ = k·o − ωt + Φ` of the frame (`o` the
/// eye's horizontal position), reduced modulo 2π in `f64`; row 1 `(A, A k_x/|k|, A k_z/|k|, 0)`;
/// row 2 `(k·A, (k̂·wind)², S_x, S_y)`, `S` the slope variance (Eq. 4 with `w_r = 1`, Appendix
/// A) of the wave and every shorter one, summed in `f64`. Rows 1 and 2 are fixed; row 0
/// changes every frame ([`WaveTexels::phases`]).
#[derive(Clone, Debug, PartialEq)]
pub struct WaveTexels {
    waves: Vec<Wave>,
    /// Rows 0 to 2, row-major, row 0's phases 0.
    texels: Vec<[f32; 4]>,
    n_min: f64,
    n_max: f64,
    wind: DVec2,
}

impl Default for WaveTexels {
    /// No waves, the paper's filter ([`crate::Filter::PAPER`]), wind along +x: the surface
    /// fields of a block whose draw reads none of them (the lighting probe's).
    fn default() -> Self {
        Self {
            waves: Vec::new(),
            texels: Vec::new(),
            n_min: crate::Filter::PAPER.n_min(),
            n_max: crate::Filter::PAPER.n_max(),
            wind: DVec2::X,
        }
    }
}

impl WaveTexels {
    /// The texels of `surface`'s waves (sorted longest first, as [`FilteredSurface`] keeps
    /// them), with its filter thresholds and wind for the uniform block.
    pub fn new(surface: &FilteredSurface) -> Self {
        let waves = surface.wave_set().waves();
        let n = waves.len();
        let wind = surface.wind();
        let mut texels = vec![[0.0f32; 4]; n * WAVE_ROWS as usize];
        // The variance of wave i and every shorter one (they follow it), in f64.
        let mut suffix = DVec2::ZERO;
        for i in (0..n).rev() {
            let w = &waves[i];
            let k = w.wave_vector();
            let m = w.wavenumber();
            let a = w.amplitude();
            let (ka, cos2) = wave_variance_term(w, wind);
            let var = trochoid_slope_variance(ka);
            suffix += DVec2::new(var * cos2, var * (1.0 - cos2));
            texels[i] = [surface.wavelengths()[i] as f32, k.x as f32, k.y as f32, 0.0];
            texels[n + i] = [a as f32, (a * k.x / m) as f32, (a * k.y / m) as f32, 0.0];
            texels[2 * n + i] = [ka as f32, cos2 as f32, suffix.x as f32, suffix.y as f32];
        }
        Self {
            waves: waves.to_vec(),
            texels,
            n_min: surface.filter().n_min(),
            n_max: surface.filter().n_max(),
            wind,
        }
    }

    /// The texels, rows 0 to 2, row-major, with row 0's phases 0.
    pub fn texels(&self) -> &[[f32; 4]] {
        &self.texels
    }

    /// N_min of the surface's filter.
    pub fn n_min(&self) -> f64 {
        self.n_min
    }

    /// N_max of the surface's filter.
    pub fn n_max(&self) -> f64 {
        self.n_max
    }

    /// The surface's wind direction (x, z).
    pub fn wind(&self) -> DVec2 {
        self.wind
    }

    /// The number of waves: the texture's width.
    pub fn wave_count(&self) -> usize {
        self.waves.len()
    }

    /// Row 0 for a frame at `time` seen from an eye at horizontal position `o` (world x, z):
    /// `θ₀ = k·o − ωt + Φ` reduced modulo 2π in `f64` (ARCHITECTURE.md), so the shader's phase
    /// `k·(x − o) + θ₀` never holds a large number in `f32`.
    pub fn phases(&self, o: DVec2, time: f64) -> Vec<[f32; 4]> {
        self.waves
            .iter()
            .zip(&self.texels)
            .map(|(w, t)| [t[0], t[1], t[2], reduce_angle(w.phase_at(o, time)) as f32])
            .collect()
    }

    /// The whole texture for a frame at `time` seen by `camera`: the three rows, row-major,
    /// row 0 with [`phases`](Self::phases) at the eye's horizontal position.
    pub fn frame_texels(&self, camera: &Camera, time: f64) -> Vec<[f32; 4]> {
        let eye = camera.eye();
        let phases = self.phases(DVec2::new(eye.x, eye.z), time);
        let mut texels = self.texels.clone();
        texels[..phases.len()].copy_from_slice(&phases);
        texels
    }
}
