use super::*;

#[test]
fn frame_uniform_matches_the_wgsl_struct() {
    // Two mat4x4 (128 bytes) and fourteen vec4 (224): 352 bytes, the WGSL `Frame`.
    assert_eq!(std::mem::size_of::<FrameUniform>(), 352);
    let b = shaders::get("ocean").unwrap().bindings().unwrap();
    assert_eq!(b[0].name, "frame");
    assert_eq!(b[0].size as usize, std::mem::size_of::<FrameUniform>());
    let offsets: Vec<(&str, u32)> = b[0]
        .members
        .iter()
        .map(|m| (m.name.as_str(), m.offset))
        .collect();
    assert_eq!(
        offsets,
        vec![
            ("view_proj", 0),
            ("inv_view_proj", 64),
            ("camera", 128),
            ("viewport", 144),
            ("grid", 160),
            ("counts", 176),
            ("sea", 192),
            ("sun_dir", 208),
            ("sun_radiance", 224),
            ("sea_radiance", 240),
            ("sky", 256),
            ("probe", 272),
            ("local", 288),
            ("local_counts", 304),
            ("mesh_grid", 320),
            ("mesh_counts", 336),
        ]
    );
    // The probe module declares the same block.
    let p = shaders::get("ocean_probe").unwrap().bindings().unwrap();
    assert_eq!(p[0].members, b[0].members);
}

#[test]
fn grid_covers_the_viewport_and_its_margin() {
    let o = OceanOptions::default();
    // 96 px at 8 px cells with 10 % on each side: 115.2 px → 15 cells → 16 vertices.
    assert_eq!(grid_counts(&o, 96, 64).unwrap(), (16, 11));
    let no_margin = OceanOptions {
        margin: 0.0,
        ..OceanOptions::default()
    };
    // Exactly 12 cells of 8 px span 96 px: 13 vertices, the last on the right edge.
    assert_eq!(grid_counts(&no_margin, 96, 64).unwrap(), (13, 9));
    let huge = OceanOptions {
        cell_px: 1.0,
        margin: 2.0,
        ..OceanOptions::default()
    };
    assert!(matches!(
        grid_counts(&huge, u32::MAX, u32::MAX),
        Err(GpuError::TooLarge { .. })
    ));
}

#[test]
fn opengl_depth_folds_into_webgpu_clip_space() {
    use ocean_core::{DepthConvention, Far, Projection};
    let projection = Projection::Perspective {
        fov_y: 1.0,
        aspect: 1.5,
        near: 0.5,
        far: Far::Finite(1000.0),
    };
    let gl = Camera::look_at(
        DVec3::new(0.0, 4.0, 0.0),
        DVec3::new(0.0, 3.0, -10.0),
        DVec3::Y,
        projection,
        DepthConvention::NEG_ONE_TO_ONE,
    )
    .unwrap();
    let wgpu_cam = Camera::look_at(
        DVec3::new(0.0, 4.0, 0.0),
        DVec3::new(0.0, 3.0, -10.0),
        DVec3::Y,
        projection,
        DepthConvention::ZERO_TO_ONE,
    )
    .unwrap();
    // Folding [−1, 1] into [0, 1] gives the [0, 1] camera's matrix.
    let range = gl.depth().range();
    let folded = range.to_zero_to_one() * gl.view_projection_f64();
    let direct = wgpu_cam.view_projection_f64();
    assert!(folded.abs_diff_eq(direct, 1e-12), "{folded} vs {direct}");
    assert_eq!(range.window_depth(-1.0), 0.0);
    assert_eq!(range.window_depth(0.0), 0.5);
    assert_eq!(range.window_depth(1.0), 1.0);
}

fn test_surface() -> FilteredSurface {
    let spectrum =
        ocean_brdf::Spectrum::new(ocean_brdf::SpectrumParams::default()).expect("spectrum");
    FilteredSurface::new(&spectrum, ocean_brdf::Filter::PAPER).expect("surface")
}

/// An OpenGL camera 3 m above the sea, 100 km and 40 km from the origin, looking ahead and
/// down.
fn far_camera() -> Camera {
    use ocean_core::{DepthConvention, Far, Projection};
    let eye = DVec3::new(1.0e5 + 2.0, 3.0, -4.0e4);
    Camera::look_at(
        eye,
        eye + DVec3::new(0.0, -1.0, -10.0),
        DVec3::Y,
        Projection::Perspective {
            fov_y: 1.0,
            aspect: 1.5,
            near: 0.1,
            far: Far::Finite(1000.0),
        },
        DepthConvention::NEG_ONE_TO_ONE,
    )
    .unwrap()
}

#[test]
fn the_mesh_origin_is_stored_relative_to_the_eye() {
    let waves = WaveTexels::new(&test_surface());
    let camera = far_camera();
    let mesh = MeshGrid {
        origin: DVec2::new(1.0e5 - 10.0, -4.0e4 - 20.0),
        spacing: 0.5,
        nx: 129,
        nz: 65,
    };
    let options = OceanOptions::default();
    let with = frame_uniform(&options, &waves, None, &camera, 7.0, (96, 64), Some(&mesh)).unwrap();
    // (1e5 − 10, 0, −4e4 − 20) − (1e5 + 2, 3, −4e4), formed in f64: exact in f32.
    assert_eq!(with.mesh_grid, [-12.0, -3.0, -20.0, 0.5]);
    assert_eq!(with.mesh_counts, [129, 65, 0, 0]);
    // Everything else is the renderer's block: the projected grid of a 96 x 64 viewport
    // (16 x 11 vertices, as `grid_covers_the_viewport_and_its_margin`), the spectrum's
    // waves, sRGB encoding for rgba8unorm, no lighting, no local waves.
    let without = frame_uniform(&options, &waves, None, &camera, 7.0, (96, 64), None).unwrap();
    assert_eq!(
        FrameUniform {
            mesh_grid: [0.0; 4],
            mesh_counts: [0; 4],
            ..with
        },
        without
    );
    assert_eq!(without.counts, [16, 11, waves.wave_count() as u32, 1]);
    assert_eq!(without.camera[0], 3.0);
    // No Sun without a lighting; w is the far plane's depth, OpenGL's 1 folded into
    // WebGPU's range (still 1).
    assert_eq!(without.sun_radiance, [0.0, 0.0, 0.0, 1.0]);
}

#[test]
fn frame_uniform_refuses_bad_input() {
    let waves = WaveTexels::new(&test_surface());
    let camera = far_camera();
    let options = OceanOptions::default();
    let mesh = MeshGrid {
        origin: DVec2::ZERO,
        spacing: 1.0,
        nx: 2,
        nz: 2,
    };
    let call = |o: &OceanOptions, time: f64, size, m: &MeshGrid| {
        frame_uniform(o, &waves, None, &camera, time, size, Some(m))
    };
    assert!(call(&options, 0.0, (8, 8), &mesh).is_ok());
    assert!(matches!(
        call(&options, f64::NAN, (8, 8), &mesh),
        Err(GpuError::Eval(_))
    ));
    assert!(matches!(
        call(&options, 0.0, (0, 8), &mesh),
        Err(GpuError::InvalidInput {
            what: "viewport",
            ..
        })
    ));
    let bad_options = OceanOptions {
        exposure: 0.0,
        ..OceanOptions::default()
    };
    assert!(matches!(
        call(&bad_options, 0.0, (8, 8), &mesh),
        Err(GpuError::InvalidInput {
            what: "exposure",
            ..
        })
    ));
    for m in [
        MeshGrid {
            spacing: 0.0,
            ..mesh
        },
        MeshGrid {
            spacing: f64::INFINITY,
            ..mesh
        },
        MeshGrid { nx: 0, ..mesh },
        MeshGrid {
            origin: DVec2::new(f64::NAN, 0.0),
            ..mesh
        },
        MeshGrid {
            origin: DVec2::new(1e300, 0.0),
            ..mesh
        },
    ] {
        assert!(
            matches!(
                call(&options, 0.0, (8, 8), &m),
                Err(GpuError::InvalidInput { what: "mesh", .. })
            ),
            "{m:?}"
        );
    }
}

#[test]
fn wave_texels_form_each_frames_phases_in_f64() {
    let surface = test_surface();
    let waves = WaveTexels::new(&surface);
    let n = waves.wave_count();
    assert_eq!(n, surface.wave_set().waves().len());
    let camera = far_camera();
    let time = 1.0e6;
    let texels = waves.frame_texels(&camera, time);
    assert_eq!(texels.len(), 3 * n);
    // Rows 1 and 2 are the fixed ones; row 0 keeps (λ, k) and gains θ₀ at o.
    assert_eq!(texels[n..], waves.texels()[n..]);
    let o = DVec2::new(1.0e5 + 2.0, -4.0e4);
    for (i, w) in surface.wave_set().waves().iter().enumerate() {
        assert_eq!(texels[i][..3], waves.texels()[i][..3]);
        // k·o − ωt + Φ reaches about 10⁸ rad here; reduced in f64 it lies in [−π, π] and
        // equals the unreduced phase modulo 2π.
        let theta = f64::from(texels[i][3]);
        assert!(theta.abs() <= std::f64::consts::PI + 1e-6, "{theta}");
        let d = (w.phase_at(o, time) - theta) / std::f64::consts::TAU;
        assert!((d - d.round()).abs() < 1e-6, "wave {i}: {d}");
    }
}
