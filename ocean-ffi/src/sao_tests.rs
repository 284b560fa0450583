//! Tests of the SAO C ABI: the wrapper adds nothing to ocean-sao's arithmetic, maps every error
//! to a status with a message, and never writes an output on failure.

use core::ffi::CStr;
use core::ptr::{null, null_mut};

use ocean_core::camera::{DepthConvention, Far, Projection};
use ocean_sao::analytic::{AnalyticView, DepthFormat};
use ocean_sao::{DepthSource, Estimator, MipFilter, NormalRejection, Sao, SaoError, SaoParams};

use super::*;
use crate::boundary::enums::Poked;
use crate::camera::{OceanCamera, OceanDepthConvention, projection_from_matrix};
use crate::sao_depth::OceanSaoDepth;

/// Input 72 x 56 with an 8 px guard band: output 56 x 40.
const W: u32 = 72;
const H: u32 = 56;
const G: u32 = 8;
const OUT_LEN: usize = ((W - 2 * G) * (H - 2 * G)) as usize;
const IN_LEN: usize = (W * H) as usize;

fn last_error() -> String {
    // SAFETY: a valid NUL-terminated string until the next status call; copied at once.
    unsafe { CStr::from_ptr(crate::ocean_last_error_message()) }
        .to_string_lossy()
        .into_owned()
}

fn convention_value(c: DepthConvention) -> OceanDepthConvention {
    if c == DepthConvention::ZERO_TO_ONE {
        OceanDepthConvention::ZeroToOne
    } else if c == DepthConvention::ZERO_TO_ONE_REVERSED {
        OceanDepthConvention::ZeroToOneReversed
    } else {
        OceanDepthConvention::NegOneToOne
    }
}

fn source_value(s: DepthSource) -> u32 {
    match s {
        DepthSource::Window => OceanSaoDepth::Window as u32,
        DepthSource::Ndc => OceanSaoDepth::Ndc as u32,
    }
}

/// What `ocean_sao_create` takes of the camera, as these tests vary it: the `OceanCamera` (the
/// identity view: SAO reads only the projection) and what the depth buffer holds.
#[derive(Clone, Copy, Debug)]
struct SaoCamera {
    camera: OceanCamera,
    depth_source: u32,
}

/// The camera of projection `p`, its matrix rounded to `f32` as a renderer's would be.
fn sao_camera(p: Projection, c: DepthConvention, s: DepthSource) -> SaoCamera {
    SaoCamera {
        camera: OceanCamera {
            view: glam::DMat4::IDENTITY.to_cols_array(),
            projection: p.matrix(c).unwrap().to_cols_array().map(f64::from),
            depth_convention: convention_value(c),
            reserved: 0,
        },
        depth_source: source_value(s),
    }
}

fn perspective(far: Far) -> Projection {
    Projection::Perspective {
        fov_y: 1.0,
        aspect: f64::from(W) / f64::from(H),
        near: 0.1,
        far,
    }
}

fn orthographic() -> Projection {
    let half_w = 3.0 * f64::from(W) / f64::from(H);
    Projection::Orthographic {
        left: -half_w,
        right: half_w,
        bottom: -3.0,
        top: 3.0,
        near: 0.05,
        far: 40.0,
    }
}

fn defaults() -> OceanSaoParams {
    let mut p = OceanSaoParams::default();
    // SAFETY: writable out.
    assert_eq!(unsafe { ocean_sao_params_default(&mut p) }, OceanStatus::Ok);
    p
}

/// Every non-default choice at once: Eq. 1 with k = 2, harmonic-mean MIPs, the normal
/// rejection, no quad filter, the paper's quad normals, a 9-tap blur with stride 2 and the
/// paper's depth-keyed weight.
fn custom() -> OceanSaoParams {
    OceanSaoParams {
        radius: 0.7,
        samples: 13,
        spiral_turns: 10.0,
        max_mip: 4,
        mip_filter: OceanSaoMipFilter::HarmonicMean,
        estimator: OceanSaoEstimator::Alchemy,
        alchemy_sigma: 0.4,
        alchemy_beta: 2.0e-3,
        alchemy_k: 2.0,
        quad_filter: 0,
        normal_rejection: 1,
        normal_max_incidence: 80f32.to_radians(),
        normals: OceanSaoNormals::Quad,
        blur: OceanSaoBlurParams {
            taps: 9,
            stride: 2,
            depth_scale: 2000.0,
            sigma: 2.0,
            weight: OceanSaoBlurWeight::Depth,
            world_extent: 0.0,
        },
        ..defaults()
    }
}

fn create(camera: &SaoCamera, params: &OceanSaoParams) -> *mut OceanSao {
    let mut s = null_mut();
    // SAFETY: valid pointers.
    let status =
        unsafe { ocean_sao_create(W, H, G, &camera.camera, camera.depth_source, params, &mut s) };
    assert_eq!(status, OceanStatus::Ok, "{}", last_error());
    assert!(!s.is_null());
    s
}

fn run(s: *const OceanSao, depth: &[f32]) -> Vec<f32> {
    let mut ao = vec![-1.0f32; OUT_LEN];
    // SAFETY: live handle, buffers of the given lengths.
    let status =
        unsafe { ocean_sao_run(s, depth.as_ptr(), depth.len(), ao.as_mut_ptr(), ao.len()) };
    assert_eq!(status, OceanStatus::Ok, "{}", last_error());
    assert_eq!(last_error(), "");
    ao
}

fn bits(v: &[f32]) -> Vec<u32> {
    v.iter().map(|x| x.to_bits()).collect()
}

/// The crease (floor meeting a wall) rendered exactly by ocean-sao's rasteriser.
fn crease_depth(p: Projection, c: DepthConvention, s: DepthSource) -> Vec<f32> {
    let view = AnalyticView::crease();
    let camera = view.camera(p, c).unwrap();
    view.scene
        .rasterise(&camera, W as usize, H as usize, s, DepthFormat::F32)
        .unwrap()
        .depth
}

#[test]
fn defaults_are_the_crate_defaults() {
    let p = defaults();
    assert_eq!(params_from(&p).unwrap(), SaoParams::default());
    // The estimator not chosen holds its own defaults.
    let alchemy = OceanSaoParams {
        estimator: OceanSaoEstimator::Alchemy,
        ..p
    };
    assert_eq!(params_from(&alchemy).unwrap().estimator, Estimator::ALCHEMY);
    assert_eq!(p.quad_filter, 1);
    assert_eq!(p.normal_rejection, 0);
    let rejecting = OceanSaoParams {
        normal_rejection: 1,
        ..p
    };
    assert_eq!(
        params_from(&rejecting).unwrap().normal_rejection,
        Some(NormalRejection {
            max_incidence: 85f32.to_radians()
        })
    );
    let custom = params_from(&custom()).unwrap();
    assert_eq!(custom.mip_filter, MipFilter::HarmonicMean);
    assert_eq!(custom.quad_depth_threshold, None);
    assert_eq!(
        custom.estimator,
        Estimator::Alchemy {
            sigma: 0.4,
            beta: 2.0e-3,
            k: 2.0
        }
    );
}

/// The C ABI's AO and view z are ocean-sao's, bit for bit, for the camera read from the
/// matrix: every projection kind, convention, depth source and two parameter sets. Against the
/// parameters the matrix was built from (before its f32 rounding) the AO agrees to 1/255.
#[test]
fn run_and_view_z_match_the_crate_bit_for_bit() {
    let mut runs = 0;
    let mut bit_identical_to_nominal = 0;
    for p in [
        perspective(Far::Finite(100.0)),
        perspective(Far::Infinite),
        orthographic(),
    ] {
        for c in DepthConvention::ALL {
            for s in [DepthSource::Window, DepthSource::Ndc] {
                let depth = crease_depth(p, c, s);
                let camera = sao_camera(p, c, s);
                let read = projection_from_matrix(&camera.camera.projection, c).unwrap();
                let viewport = Viewport::new(W as usize, H as usize, G as usize).unwrap();
                for params in [defaults(), custom()] {
                    let core_params = params_from(&params).unwrap();
                    let handle = create(&camera, &params);
                    let ao = run(handle, &depth);

                    let sao = Sao::new(&read, c, s, viewport, core_params).unwrap();
                    let mut expected = vec![0.0f32; OUT_LEN];
                    sao.run(&depth, &mut expected).unwrap();
                    assert_eq!(bits(&ao), bits(&expected), "{p:?} {c:?} {s:?}");
                    assert!(ao.iter().any(|&a| a < 0.9), "{p:?} {c:?} {s:?}: no crease");

                    let mut z = vec![0.0f32; IN_LEN];
                    // SAFETY: live handle, buffers of the given lengths.
                    let status = unsafe {
                        ocean_sao_view_z(handle, depth.as_ptr(), IN_LEN, z.as_mut_ptr(), IN_LEN)
                    };
                    assert_eq!(status, OceanStatus::Ok, "{}", last_error());
                    let expected_z = sao.z_constants().z_pass(&viewport, &depth).unwrap();
                    assert_eq!(bits(&z), bits(&expected_z));

                    let nominal = Sao::new(&p, c, s, viewport, core_params).unwrap();
                    let mut from_nominal = vec![0.0f32; OUT_LEN];
                    nominal.run(&depth, &mut from_nominal).unwrap();
                    let worst = ao
                        .iter()
                        .zip(&from_nominal)
                        .map(|(a, b)| (a - b).abs())
                        .fold(0.0f32, f32::max);
                    assert!(worst <= 1.0 / 255.0, "{p:?} {c:?} {s:?}: {worst}");
                    bit_identical_to_nominal += usize::from(worst == 0.0);
                    ocean_sao_destroy(handle);
                    runs += 1;
                }
            }
        }
    }
    assert_eq!(runs, 36);
    println!("{bit_identical_to_nominal} of {runs} runs bit-identical to the nominal parameters");
}

#[test]
fn describe_reports_sizes_planes_and_constants() {
    for (p, c, ortho, far) in [
        (
            perspective(Far::Finite(100.0)),
            DepthConvention::NEG_ONE_TO_ONE,
            0,
            100.0,
        ),
        (
            perspective(Far::Infinite),
            DepthConvention::ZERO_TO_ONE_REVERSED,
            0,
            f64::INFINITY,
        ),
        (orthographic(), DepthConvention::ZERO_TO_ONE, 1, 40.0),
    ] {
        let camera = sao_camera(p, c, DepthSource::Window);
        let handle = create(&camera, &defaults());
        let mut info = OceanSaoInfo::default();
        // SAFETY: live handle, writable out.
        let status = unsafe { ocean_sao_describe(handle, &mut info) };
        assert_eq!(status, OceanStatus::Ok, "{}", last_error());
        let read = projection_from_matrix(&camera.camera.projection, c).unwrap();
        let sao = Sao::new(
            &read,
            c,
            DepthSource::Window,
            Viewport::new(W as usize, H as usize, G as usize).unwrap(),
            SaoParams::default(),
        )
        .unwrap();
        assert_eq!(
            (
                info.input_width,
                info.input_height,
                info.guard,
                info.output_width,
                info.output_height
            ),
            (W, H, G, W - 2 * G, H - 2 * G)
        );
        assert_eq!(info.orthographic, ortho);
        assert!((info.near - p.near()).abs() <= 1.0e-6 * p.near().abs());
        if far.is_finite() {
            assert!((info.far - far).abs() <= 1.0e-3 * far, "{}", info.far);
        } else {
            assert_eq!(info.far, f64::INFINITY);
        }
        let z = sao.z_constants();
        assert_eq!(info.z_constants, z.c);
        assert_eq!(
            (info.near_depth, info.far_depth),
            (z.near_depth, z.far_depth)
        );
        assert_eq!(
            info.pixels_per_metre,
            sao.projection_info().pixels_per_metre
        );
        ocean_sao_destroy(handle);
    }
    let mut info = OceanSaoInfo::default();
    // SAFETY: refused before any access.
    let status = unsafe { ocean_sao_describe(null(), &mut info) };
    assert_eq!(status, OceanStatus::NullPointer);
    assert_eq!(info, OceanSaoInfo::default());
}

#[test]
fn every_sao_error_has_a_fitting_status() {
    let cases = [
        (
            SaoError::Camera(ocean_core::camera::CameraError::NotFinite {
                name: "near",
                value: f64::NAN,
            }),
            OceanStatus::NonFinite,
        ),
        (
            SaoError::Camera(ocean_core::camera::CameraError::Near(-1.0)),
            OceanStatus::InvalidArgument,
        ),
        (
            SaoError::DegenerateProjection("Eq. 2 constants"),
            OceanStatus::InvalidArgument,
        ),
        (
            SaoError::ImageSize {
                width: 0,
                height: 5,
            },
            OceanStatus::Empty,
        ),
        (
            SaoError::ImageSize {
                width: 5,
                height: 0,
            },
            OceanStatus::Empty,
        ),
        (
            SaoError::ImageSize {
                width: 1,
                height: 5,
            },
            OceanStatus::InvalidArgument,
        ),
        (
            SaoError::GuardBand {
                guard: 3,
                width: 6,
                height: 6,
            },
            OceanStatus::InvalidArgument,
        ),
        (
            SaoError::BufferSize {
                name: "ao",
                expected: 4,
                got: 3,
            },
            OceanStatus::InvalidArgument,
        ),
        (
            SaoError::DepthNotFinite { x: 1, y: 2 },
            OceanStatus::NonFinite,
        ),
        (
            SaoError::DepthOutOfRange {
                x: 1,
                y: 2,
                value: 2.0,
                min: 0.0,
                max: 1.0,
            },
            OceanStatus::InvalidArgument,
        ),
        (SaoError::NotFinite("radius"), OceanStatus::NonFinite),
        (
            SaoError::OutOfRange {
                name: "samples",
                value: 0.0,
                min: 1.0,
                max: 64.0,
            },
            OceanStatus::InvalidArgument,
        ),
        (
            SaoError::UnsupportedFormat("x"),
            OceanStatus::InvalidArgument,
        ),
        (SaoError::EvenTaps(8), OceanStatus::InvalidArgument),
    ];
    for (e, status) in cases {
        let err = sao_error("ctx: ", e);
        assert_eq!(err.status, status, "{e:?}");
        assert_eq!(err.message, format!("ctx: {e}"));
    }
}

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
