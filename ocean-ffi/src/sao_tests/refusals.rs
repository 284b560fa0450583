//! The refusals of `ocean_sao_create` and `ocean_sao_run`: bad arguments and buffers, with the
//! outputs untouched.

use super::*;

#[test]
fn create_refuses_bad_arguments_and_leaves_out_untouched() {
    let camera = sao_camera(
        perspective(Far::Finite(100.0)),
        DepthConvention::ZERO_TO_ONE,
        DepthSource::Window,
    );
    let params = defaults();
    let sentinel = 0x10usize as *mut OceanSao;
    let attempt = |w: u32, h: u32, g: u32, c: &SaoCamera, p: &OceanSaoParams| {
        let mut out = sentinel;
        // SAFETY: valid pointers.
        let status = unsafe { ocean_sao_create(w, h, g, &c.camera, c.depth_source, p, &mut out) };
        if status == OceanStatus::Ok {
            ocean_sao_destroy(out);
        } else {
            assert_eq!(out, sentinel, "out written on failure");
        }
        (status, last_error())
    };
    let with_matrix = |k: usize, v: f32| {
        let mut c = camera;
        c.camera.projection[k] = f64::from(v);
        c
    };
    let mut huge = camera;
    // A valid projection (fov_y = 2e-38 rad) whose Eq. 5 constant S' = h P11 / 2 overflows f32.
    huge.camera.projection[0] = 7.5e37;
    huge.camera.projection[5] = 1.0e38;
    let cases: Vec<(u32, u32, u32, SaoCamera, OceanSaoParams, OceanStatus, &str)> = vec![
        (0, H, G, camera, params, OceanStatus::Empty, "empty"),
        (W, 0, G, camera, params, OceanStatus::Empty, "empty"),
        (
            1,
            H,
            0,
            camera,
            params,
            OceanStatus::InvalidArgument,
            "image size",
        ),
        (
            OCEAN_SAO_MAX_SIDE + 1,
            H,
            G,
            camera,
            params,
            OceanStatus::InvalidArgument,
            "image size",
        ),
        (
            W,
            H,
            H / 2,
            camera,
            params,
            OceanStatus::InvalidArgument,
            "guard band",
        ),
        (
            W,
            H,
            u32::MAX,
            camera,
            params,
            OceanStatus::InvalidArgument,
            "guard band",
        ),
        (
            W,
            H,
            G,
            with_matrix(10, f32::NAN),
            params,
            OceanStatus::NonFinite,
            "projection[10]",
        ),
        (
            W,
            H,
            G,
            with_matrix(11, 1.0),
            params,
            OceanStatus::InvalidArgument,
            "bottom row",
        ),
        (
            W,
            H,
            G,
            huge,
            params,
            OceanStatus::InvalidArgument,
            "degenerate",
        ),
        (
            W,
            H,
            G,
            camera,
            OceanSaoParams {
                samples: 0,
                ..params
            },
            OceanStatus::InvalidArgument,
            "samples",
        ),
        (
            W,
            H,
            G,
            camera,
            OceanSaoParams {
                radius: f32::NAN,
                ..params
            },
            OceanStatus::NonFinite,
            "radius",
        ),
        (
            W,
            H,
            G,
            camera,
            OceanSaoParams {
                blur: OceanSaoBlurParams {
                    taps: 8,
                    ..params.blur
                },
                ..params
            },
            OceanStatus::InvalidArgument,
            "odd",
        ),
        (
            W,
            H,
            G,
            camera,
            OceanSaoParams {
                quad_filter: 2,
                ..params
            },
            OceanStatus::InvalidArgument,
            "quad_filter",
        ),
        (
            W,
            H,
            G,
            camera,
            OceanSaoParams {
                normal_rejection: 1,
                normal_max_incidence: 0.0,
                ..params
            },
            OceanStatus::InvalidArgument,
            "max_incidence",
        ),
        (
            W,
            H,
            G,
            camera,
            OceanSaoParams {
                estimator: OceanSaoEstimator::Alchemy,
                alchemy_k: f32::INFINITY,
                ..params
            },
            OceanStatus::NonFinite,
            "`k`",
        ),
        (
            W,
            H,
            G,
            camera,
            OceanSaoParams {
                z_min: 5.0,
                ..params
            },
            OceanStatus::InvalidArgument,
            "z_min",
        ),
    ];
    for (w, h, g, c, p, status, needle) in cases {
        let (got, message) = attempt(w, h, g, &c, &p);
        assert_eq!(got, status, "{w} x {h} guard {g}: {message}");
        assert!(
            message.starts_with("ocean_sao_create: ") && message.contains(needle),
            "{needle:?} not in {message:?}"
        );
    }
    // Unknown enumerators, from C memory: the camera's, then the parameters' in field order.
    let poked_camera = Poked::new(
        &camera.camera,
        core::mem::offset_of!(OceanCamera, depth_convention),
        7,
    );
    let good_camera: *const OceanCamera = &camera.camera;
    let at = |f: usize| Poked::new(&params, f, 7);
    let good_params: *const OceanSaoParams = &params;
    for (c, p, needle) in [
        (
            poked_camera.as_ptr(),
            good_params,
            "camera->depth_convention = 7 is not an OceanDepthConvention (0, 1 or 2)",
        ),
        (
            good_camera,
            at(core::mem::offset_of!(OceanSaoParams, mip_filter)).as_ptr(),
            "params->mip_filter = 7 is not an OCEAN_SAO_MIP_FILTER_* value (0 to 4)",
        ),
        (
            good_camera,
            at(core::mem::offset_of!(OceanSaoParams, estimator)).as_ptr(),
            "params->estimator = 7 is neither OCEAN_SAO_ESTIMATOR_FALLOFF (0) nor",
        ),
        (
            good_camera,
            at(core::mem::offset_of!(OceanSaoParams, normals)).as_ptr(),
            "params->normals = 7 is neither OCEAN_SAO_NORMALS_QUAD (0) nor",
        ),
        (
            good_camera,
            at(core::mem::offset_of!(OceanSaoParams, blur)
                + core::mem::offset_of!(OceanSaoBlurParams, weight))
            .as_ptr(),
            "params->blur.weight = 7 is neither OCEAN_SAO_BLUR_WEIGHT_DEPTH (0) nor",
        ),
    ] {
        let mut out = sentinel;
        // SAFETY: readable structs (from C memory), a writable pointer.
        let status = unsafe { ocean_sao_create(W, H, G, c, camera.depth_source, p, &mut out) };
        let message = last_error();
        assert_eq!(status, OceanStatus::InvalidArgument, "{message}");
        assert_eq!(out, sentinel, "out written on failure");
        assert!(message.contains(needle), "{needle:?} not in {message:?}");
    }
    // Members of the estimator not chosen, and thresholds of disabled filters, are not read.
    let (got, message) = attempt(
        W,
        H,
        G,
        &camera,
        &OceanSaoParams {
            alchemy_k: f32::NAN,
            quad_filter: 0,
            quad_depth_threshold: f32::NAN,
            normal_max_incidence: -1.0,
            ..params
        },
    );
    assert_eq!(got, OceanStatus::Ok, "{message}");

    // NULL and misaligned pointers.
    let mut out = sentinel;
    // SAFETY: refused before any access.
    unsafe {
        assert_eq!(
            ocean_sao_create(W, H, G, null(), 0, &params, &mut out),
            OceanStatus::NullPointer
        );
        assert_eq!(
            ocean_sao_create(W, H, G, &camera.camera, 0, null(), &mut out),
            OceanStatus::NullPointer
        );
        assert_eq!(
            ocean_sao_create(W, H, G, &camera.camera, 0, &params, null_mut()),
            OceanStatus::NullPointer
        );
        let storage = [0u64; 16];
        let bad = storage.as_ptr().cast::<u8>().wrapping_add(2);
        assert_eq!(
            ocean_sao_create(W, H, G, bad.cast(), 0, &params, &mut out),
            OceanStatus::MisalignedPointer
        );
        assert_eq!(
            ocean_sao_params_default(bad.cast_mut().cast()),
            OceanStatus::MisalignedPointer
        );
        assert_eq!(
            ocean_sao_params_default(null_mut()),
            OceanStatus::NullPointer
        );
    }
    assert_eq!(out, sentinel);
    // Destroy is NULL-safe and ignores misaligned pointers.
    {
        ocean_sao_destroy(null_mut());
        let mut storage = [0u64; 8];
        ocean_sao_destroy(storage.as_mut_ptr().cast::<u8>().wrapping_add(3).cast());
    }
}

#[test]
fn run_refuses_bad_buffers_and_leaves_outputs_untouched() {
    let p = perspective(Far::Finite(100.0));
    let c = DepthConvention::ZERO_TO_ONE;
    let camera = sao_camera(p, c, DepthSource::Window);
    let handle = create(&camera, &defaults());
    let depth = crease_depth(p, c, DepthSource::Window);
    let mut ao = vec![7.0f32; OUT_LEN];
    let mut z = vec![7.0f32; IN_LEN];
    let untouched = |v: &[f32]| v.iter().all(|&a| a == 7.0);

    let with = |x: usize, y: usize, v: f32| {
        let mut d = depth.clone();
        d[y * W as usize + x] = v;
        d
    };
    let cases: Vec<(Vec<f32>, usize, usize, OceanStatus, &str)> = vec![
        (
            with(5, 3, f32::NAN),
            IN_LEN,
            OUT_LEN,
            OceanStatus::NonFinite,
            "(5, 3)",
        ),
        (
            with(70, 50, f32::NEG_INFINITY),
            IN_LEN,
            OUT_LEN,
            OceanStatus::NonFinite,
            "(70, 50)",
        ),
        (
            with(9, 40, 1.5),
            IN_LEN,
            OUT_LEN,
            OceanStatus::InvalidArgument,
            "depth 1.5 at (9, 40) is outside [0, 1]",
        ),
        (
            with(0, 0, -0.25),
            IN_LEN,
            OUT_LEN,
            OceanStatus::InvalidArgument,
            "outside",
        ),
        (
            depth.clone(),
            IN_LEN - 1,
            OUT_LEN,
            OceanStatus::LengthMismatch,
            "depth_len",
        ),
        (
            depth.clone(),
            IN_LEN,
            OUT_LEN + 1,
            OceanStatus::LengthMismatch,
            "ao_len",
        ),
        (
            depth.clone(),
            IN_LEN,
            0,
            OceanStatus::LengthMismatch,
            "ao_len",
        ),
    ];
    for (d, dlen, alen, status, needle) in cases {
        // SAFETY: `d` holds IN_LEN >= dlen floats; `ao` holds OUT_LEN, and a larger `alen` is
        // refused before any access.
        let got = unsafe { ocean_sao_run(handle, d.as_ptr(), dlen, ao.as_mut_ptr(), alen) };
        assert_eq!(got, status, "{}", last_error());
        assert!(
            last_error().starts_with("ocean_sao_run: ") && last_error().contains(needle),
            "{needle:?} not in {}",
            last_error()
        );
        assert!(untouched(&ao), "ao written on failure ({needle})");
        if alen == OUT_LEN {
            // SAFETY: as above, `z` holds IN_LEN floats.
            let got = unsafe { ocean_sao_view_z(handle, d.as_ptr(), dlen, z.as_mut_ptr(), IN_LEN) };
            assert_eq!(got, status, "{}", last_error());
            assert!(last_error().starts_with("ocean_sao_view_z: "));
            assert!(untouched(&z), "z written on failure ({needle})");
        }
    }
    // SAFETY: refused before any access (NULL, misaligned, overlapping).
    unsafe {
        assert_eq!(
            ocean_sao_run(null(), depth.as_ptr(), IN_LEN, ao.as_mut_ptr(), OUT_LEN),
            OceanStatus::NullPointer
        );
        assert_eq!(
            ocean_sao_run(handle, null(), IN_LEN, ao.as_mut_ptr(), OUT_LEN),
            OceanStatus::NullPointer
        );
        assert_eq!(
            ocean_sao_run(handle, depth.as_ptr(), IN_LEN, null_mut(), OUT_LEN),
            OceanStatus::NullPointer
        );
        let misaligned = ao.as_mut_ptr().cast::<u8>().wrapping_add(1).cast::<f32>();
        assert_eq!(
            ocean_sao_run(handle, depth.as_ptr(), IN_LEN, misaligned, OUT_LEN),
            OceanStatus::MisalignedPointer
        );
        // The AO written over the depth buffer it reads.
        let mut shared = depth.clone();
        let before = shared.clone();
        let status = ocean_sao_run(
            handle,
            shared.as_ptr(),
            IN_LEN,
            shared.as_mut_ptr().add(100),
            OUT_LEN,
        );
        assert_eq!(status, OceanStatus::InvalidArgument);
        assert!(last_error().contains("overlap"), "{}", last_error());
        assert_eq!(shared, before);
        assert_eq!(
            ocean_sao_view_z(handle, depth.as_ptr(), IN_LEN, null_mut(), IN_LEN),
            OceanStatus::NullPointer
        );
    }
    assert!(untouched(&ao) && untouched(&z));
    // After all that, a good call succeeds and clears the message.
    let good = run(handle, &depth);
    assert!(good.iter().all(|a| (0.0..=1.0).contains(a)));
    ocean_sao_destroy(handle);
}
