use core::ptr::{null, null_mut};

use glam::{DVec2, DVec3};
use ocean_brdf::{Lighting, SeaParams, SkyParams, Spectrum, SpectrumParams};
use ocean_core::Camera;

use super::*;
use ocean_core::camera::DepthConvention;

use crate::status::last_error;

/// An OpenGL camera 6 m above the sea, 100 km and 40 km from the origin, looking ahead
/// and down.
fn camera() -> (OceanCamera, Camera) {
    let eye = DVec3::new(1.0e5 + 2.0, 6.0, -4.0e4);
    let view =
        ocean_core::camera::look_at(eye, eye + DVec3::new(0.0, -1.0, -8.0), DVec3::Y).unwrap();
    let projection = ocean_core::Projection::Perspective {
        fov_y: 0.9,
        aspect: 1.5,
        near: 0.1,
        far: ocean_core::Far::Finite(2000.0),
    };
    let made = Camera::new(view, projection, DepthConvention::NEG_ONE_TO_ONE).unwrap();
    let desc = OceanCamera::from_camera(&made);
    // What the library reads back from the C layout (its matrices are made from the
    // parameters again).
    let camera = crate::camera::camera_from(&desc).unwrap();
    (desc, camera)
}

/// A camera whose projection mirrors x: refused.
fn mirrored(mut c: OceanCamera) -> OceanCamera {
    c.projection[0] = -c.projection[0];
    c
}

/// A registered spectrum and lighting of the default parameters (never destroyed: the
/// tests end with the process).
fn handles() -> (*const OceanSpectrum, *const OceanLighting) {
    let spectrum = OceanSpectrum {
        spectrum: Spectrum::new(SpectrumParams::default()).unwrap(),
    };
    let lighting = OceanLighting {
        lighting: Lighting::new(SkyParams::default(), SeaParams::default()).unwrap(),
    };
    let (mut s, mut l) = (core::ptr::null_mut(), core::ptr::null_mut());
    // SAFETY: writable locals.
    unsafe {
        crate::boundary::write_handle(&mut s, spectrum).unwrap();
        crate::boundary::write_handle(&mut l, lighting).unwrap();
    }
    (s, l)
}

fn wave_count(spectrum: *const OceanSpectrum) -> usize {
    crate::boundary::borrow(spectrum, "spectrum")
        .unwrap()
        .spectrum
        .waves()
        .len()
}

fn default_params() -> OceanSurfaceDrawParams {
    let mut p = OceanSurfaceDrawParams::default();
    // SAFETY: writable out.
    let status = unsafe { ocean_surface_draw_params_default(&mut p) };
    assert_eq!(status, OceanStatus::Ok);
    p
}

fn mesh() -> OceanWaterGridDesc {
    OceanWaterGridDesc {
        origin_x: 1.0e5 - 30.0,
        origin_z: -4.0e4 - 60.0,
        spacing: 0.5,
        nx: 121,
        nz: 101,
    }
}

#[test]
fn the_default_params_are_the_renderers() {
    let p = default_params();
    let (options, filter) = params_from(&p).unwrap();
    // The renderer's defaults with an rgba8unorm target (the shader sRGB-encodes), and the
    // paper's filter.
    assert_eq!(options, OceanOptions::default());
    assert_eq!(filter, Filter::PAPER);
    assert_eq!((p.srgb_encode, p.sky_map_size), (1, 512));
    // SAFETY: NULL is refused before any write.
    let status = unsafe { ocean_surface_draw_params_default(null_mut()) };
    assert_eq!(status, OceanStatus::NullPointer);
}

/// The bytes are `ocean_gpu::frame_uniform`'s block, the one `OceanRenderer` draws with
/// (whose parity with the CPU twins the GPU tests check), plus the mesh.
#[test]
fn the_block_is_the_renderers() {
    let (desc, camera) = camera();
    let (spectrum, lighting) = handles();
    let p = default_params();
    let m = mesh();
    let mut out = [0xAAu8; OCEAN_SURFACE_UNIFORMS_SIZE + 4];
    // SAFETY: readable inputs, live handles, `out` holds `len` writable bytes.
    let status = unsafe {
        ocean_surface_uniforms(
            &desc,
            spectrum,
            lighting,
            &p,
            &m,
            12.5,
            96,
            64,
            out.as_mut_ptr(),
            OCEAN_SURFACE_UNIFORMS_SIZE,
        )
    };
    assert_eq!(status, OceanStatus::Ok, "{}", last_error());
    let surface = FilteredSurface::new(
        &crate::boundary::borrow(spectrum, "spectrum")
            .unwrap()
            .spectrum,
        Filter::PAPER,
    )
    .unwrap();
    let mesh_grid = MeshGrid {
        origin: DVec2::new(m.origin_x, m.origin_z),
        spacing: 0.5,
        nx: 121,
        nz: 101,
    };
    let want = ocean_gpu::frame_uniform(
        &OceanOptions::default(),
        &WaveTexels::new(&surface),
        Some(
            &crate::boundary::borrow(lighting, "lighting")
                .unwrap()
                .lighting,
        ),
        &camera,
        12.5,
        (96, 64),
        Some(&mesh_grid),
    )
    .unwrap();
    assert_eq!(
        &out[..OCEAN_SURFACE_UNIFORMS_SIZE],
        bytemuck::bytes_of(&want)
    );
    assert_eq!(out[OCEAN_SURFACE_UNIFORMS_SIZE..], [0xAA; 4]);
    let u: ocean_gpu::FrameUniform =
        bytemuck::pod_read_unaligned(&out[..OCEAN_SURFACE_UNIFORMS_SIZE]);
    // The mesh's origin relative to the eye, (1e5 − 30, −4e4 − 60) − (1e5 + 2, −4e4) and
    // −6 m down, exact in f32; its spacing and sides.
    assert_eq!(u.mesh_grid, [-32.0, -6.0, -60.0, 0.5]);
    assert_eq!(u.mesh_counts, [121, 101, 0, 0]);
    // The spectrum's 60 waves, sRGB encoding; the Sun from the lighting (not zero).
    assert_eq!(u.counts[2..], [60, 1]);
    assert!(u.sun_radiance[..3].iter().all(|&c| c > 0.0));
    // Without a mesh the mesh fields are zero and nothing else changes.
    let mut no_mesh = [0u8; OCEAN_SURFACE_UNIFORMS_SIZE];
    // SAFETY: as above, `mesh` NULL.
    let status = unsafe {
        ocean_surface_uniforms(
            &desc,
            spectrum,
            lighting,
            &p,
            null(),
            12.5,
            96,
            64,
            no_mesh.as_mut_ptr(),
            no_mesh.len(),
        )
    };
    assert_eq!(status, OceanStatus::Ok, "{}", last_error());
    let v: ocean_gpu::FrameUniform = bytemuck::pod_read_unaligned(&no_mesh);
    assert_eq!(
        v,
        ocean_gpu::FrameUniform {
            mesh_grid: [0.0; 4],
            mesh_counts: [0; 4],
            ..u
        }
    );
}

#[test]
fn wave_and_fresnel_texels_are_the_renderers() {
    let (desc, camera) = camera();
    let (spectrum, _) = handles();
    let n = wave_count(spectrum);
    let mut out = vec![f32::NAN; 12 * n];
    // SAFETY: readable inputs, `out` holds `len` writable floats.
    let status =
        unsafe { ocean_surface_wave_texels(&desc, spectrum, 3.0e5, out.as_mut_ptr(), out.len()) };
    assert_eq!(status, OceanStatus::Ok, "{}", last_error());
    let surface = FilteredSurface::new(
        &crate::boundary::borrow(spectrum, "spectrum")
            .unwrap()
            .spectrum,
        Filter::PAPER,
    )
    .unwrap();
    let want = WaveTexels::new(&surface).frame_texels(&camera, 3.0e5);
    assert_eq!(out, bytemuck::cast_slice::<[f32; 4], f32>(&want));
    // Row 0's phases: each θ₀ in [−π, π], k·o − ωt + Φ modulo 2π.
    let o = DVec2::new(camera.eye().x, camera.eye().z);
    for (i, w) in surface.wave_set().waves().iter().enumerate() {
        let theta = f64::from(out[4 * i + 3]);
        let d = (w.phase_at(o, 3.0e5) - theta) / core::f64::consts::TAU;
        assert!((d - d.round()).abs() < 1e-6, "wave {i}: {d}");
    }

    let mut table = vec![f32::NAN; 33 * 33];
    // SAFETY: `table` holds `len` writable floats.
    let status = unsafe { ocean_surface_fresnel_texels(table.as_mut_ptr(), table.len()) };
    assert_eq!(status, OceanStatus::Ok, "{}", last_error());
    // On the σ_v = 0 column the sea is smooth and Schlick's F exact: D vanishes there, to
    // the rounding of the table's quadrature (below 2e-15). Every texel is the f64 table
    // rounded to f32.
    assert!((0..33).all(|i| table[33 * i].abs() < 2e-15));
    let exact = ocean_brdf::fresnel_table::FRESNEL_TABLE;
    assert!(table.iter().zip(exact.iter()).all(|(&t, &e)| t == e as f32));
}

#[test]
fn bad_input_is_refused_and_nothing_is_written() {
    let (desc, _) = camera();
    let (spectrum, lighting) = handles();
    let good = default_params();
    let m = mesh();
    let call = |desc: &OceanCamera,
                p: &OceanSurfaceDrawParams,
                m: *const OceanWaterGridDesc,
                time: f64,
                size: (u32, u32),
                len: usize| {
        let mut out = [7u8; 400];
        // SAFETY: readable inputs, live handles, `out` holds at least `len` bytes.
        let status = unsafe {
            ocean_surface_uniforms(
                desc,
                spectrum,
                lighting,
                p,
                m,
                time,
                size.0,
                size.1,
                out.as_mut_ptr(),
                len,
            )
        };
        assert!(out.iter().all(|&b| b == 7), "written on failure");
        (status, last_error())
    };
    let with = |f: &dyn Fn(&mut OceanSurfaceDrawParams)| {
        let mut p = good;
        f(&mut p);
        call(&desc, &p, &m, 0.0, (8, 8), 352)
    };
    let with_mesh = |f: &dyn Fn(&mut OceanWaterGridDesc)| {
        let mut g = m;
        f(&mut g);
        call(&desc, &good, &g, 0.0, (8, 8), 352)
    };
    let below = {
        let eye = DVec3::new(0.0, -1.0, 0.0);
        let view = ocean_core::camera::look_at(eye, DVec3::new(0.0, -1.0, -5.0), DVec3::Y).unwrap();
        OceanCamera {
            view: view.to_cols_array(),
            ..desc
        }
    };
    let cases: [(OceanStatus, &str, (OceanStatus, String)); 14] = [
        (
            OceanStatus::LengthMismatch,
            "holds exactly 352",
            call(&desc, &good, &m, 0.0, (8, 8), 351),
        ),
        (
            OceanStatus::LengthMismatch,
            "holds exactly 352",
            call(&desc, &good, &m, 0.0, (8, 8), 353),
        ),
        (
            OceanStatus::Empty,
            "0 x 8",
            call(&desc, &good, &m, 0.0, (0, 8), 352),
        ),
        (
            OceanStatus::NonFinite,
            "time",
            call(&desc, &good, &m, f64::NAN, (8, 8), 352),
        ),
        (
            OceanStatus::InvalidArgument,
            "above the sea",
            call(&below, &good, &m, 0.0, (8, 8), 352),
        ),
        (
            OceanStatus::InvalidArgument,
            "camera",
            call(&mirrored(desc), &good, &m, 0.0, (8, 8), 352),
        ),
        (
            OceanStatus::InvalidArgument,
            "srgb_encode",
            with(&|p| p.srgb_encode = 2),
        ),
        (
            OceanStatus::NonFinite,
            "params->exposure",
            with(&|p| p.exposure = f64::INFINITY),
        ),
        (
            OceanStatus::InvalidArgument,
            "params",
            with(&|p| p.n_max = 0.5),
        ),
        (
            OceanStatus::InvalidArgument,
            "sky_map_size",
            with(&|p| p.sky_map_size = 100),
        ),
        (
            OceanStatus::InvalidArgument,
            "cell_px",
            with(&|p| p.cell_px = 0.5),
        ),
        (
            OceanStatus::Empty,
            "mesh is 0 x 101",
            with_mesh(&|g| g.nx = 0),
        ),
        (
            OceanStatus::NonFinite,
            "mesh->spacing",
            with_mesh(&|g| g.spacing = f64::NAN),
        ),
        (
            OceanStatus::InvalidArgument,
            "mesh",
            with_mesh(&|g| g.spacing = 0.0),
        ),
    ];
    for (status, text, (got, message)) in cases {
        assert_eq!(got, status, "{text}: {message}");
        assert!(message.contains(text), "{text}: {message}");
    }
    let mut out = [0u8; 352];
    // SAFETY: NULL pointers are refused before anything is read or written.
    unsafe {
        let o = out.as_mut_ptr();
        assert_eq!(
            ocean_surface_uniforms(null(), spectrum, lighting, &good, &m, 0.0, 8, 8, o, 352,),
            OceanStatus::NullPointer
        );
        assert_eq!(
            ocean_surface_uniforms(&desc, null(), lighting, &good, &m, 0.0, 8, 8, o, 352,),
            OceanStatus::NullPointer
        );
        assert_eq!(
            ocean_surface_uniforms(&desc, spectrum, null(), &good, &m, 0.0, 8, 8, o, 352,),
            OceanStatus::NullPointer
        );
        assert_eq!(
            ocean_surface_uniforms(&desc, spectrum, lighting, null(), &m, 0.0, 8, 8, o, 352,),
            OceanStatus::NullPointer
        );
        assert_eq!(
            ocean_surface_uniforms(
                &desc,
                spectrum,
                lighting,
                &good,
                &m,
                0.0,
                8,
                8,
                null_mut(),
                352,
            ),
            OceanStatus::NullPointer
        );
    }

    // The texel functions: wrong lengths, NaN time, NULL.
    let n = wave_count(spectrum);
    let mut texels = vec![7.0f32; 12 * n + 1];
    // SAFETY: `texels` holds at least `len` writable floats; NULL is refused.
    unsafe {
        let t = texels.as_mut_ptr();
        assert_eq!(
            ocean_surface_wave_texels(&desc, spectrum, 0.0, t, 12 * n + 1),
            OceanStatus::LengthMismatch
        );
        assert!(last_error().contains(&format!("exactly {}", 12 * n)));
        assert_eq!(
            ocean_surface_wave_texels(&desc, spectrum, f64::INFINITY, t, 12 * n),
            OceanStatus::NonFinite
        );
        assert_eq!(
            ocean_surface_wave_texels(&desc, null(), 0.0, t, 12 * n),
            OceanStatus::NullPointer
        );
        assert_eq!(
            ocean_surface_wave_texels(&desc, spectrum, 0.0, null_mut(), 12 * n),
            OceanStatus::NullPointer
        );
        assert_eq!(
            ocean_surface_fresnel_texels(t, 33 * 32),
            OceanStatus::LengthMismatch
        );
        assert!(last_error().contains("exactly 1089"));
        assert_eq!(
            ocean_surface_fresnel_texels(null_mut(), 1089),
            OceanStatus::NullPointer
        );
    }
    assert!(texels.iter().all(|&t| t == 7.0), "written on failure");
}

#[test]
fn a_time_past_the_phase_limit_is_refused() {
    // time = DBL_MAX gave a NaN phase texel (omega t overflowed) behind success.
    let (desc, _) = camera();
    let (spectrum, _) = handles();
    let n = wave_count(spectrum);
    let mut out = vec![-1.0f32; 12 * n];
    for time in [f64::MAX, 1e300, -1e20] {
        // SAFETY: readable inputs, `out` holds `len` writable floats.
        let s = unsafe {
            ocean_surface_wave_texels(&desc, spectrum, time, out.as_mut_ptr(), out.len())
        };
        assert_eq!(s, OceanStatus::InvalidArgument, "{time}");
        assert!(last_error().contains("`time`"), "{}", last_error());
        assert!(out.iter().all(|&v| v == -1.0), "written on failure");
    }
    // SAFETY: as above.
    let s = unsafe { ocean_surface_wave_texels(&desc, spectrum, 1e9, out.as_mut_ptr(), out.len()) };
    assert_eq!(s, OceanStatus::Ok, "{}", last_error());
    assert!(out.iter().all(|v| v.is_finite()));
}
