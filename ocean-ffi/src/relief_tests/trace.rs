//! The tracer and the shadow test through the C ABI: the crate's answers bit for bit, and every
//! refusal.

use super::*;

/// Rays at 0–80° from the normal, random starts and azimuths (a fixed LCG).
fn test_rays(count: usize, depth: f32) -> Vec<OceanReliefRay> {
    let mut s = 12345u32;
    let mut next = || {
        s = s.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
        (s >> 8) as f32 / (1u32 << 24) as f32
    };
    (0..count)
        .map(|_| {
            let (u, v) = (next(), next());
            let theta = 80f32.to_radians() * next();
            let phi = std::f32::consts::TAU * next();
            let mut r = OceanReliefRay::default();
            // SAFETY: writable out.
            let st = unsafe {
                ocean_relief_ray_from_view(
                    u,
                    v,
                    theta.sin() * phi.cos(),
                    theta.sin() * phi.sin(),
                    -theta.cos(),
                    depth,
                    &mut r,
                )
            };
            assert_eq!(st, OceanStatus::Ok, "{}", last_error());
            r
        })
        .collect()
}

/// Every method's hits equal `Method::trace`'s bits, ray by ray (1000 rays: several parallel
/// chunks), and the shadow answers equal `shadow::in_shadow`'s.
#[test]
fn trace_and_shadow_are_the_crates() {
    let hb = boxes(32, 6, 4);
    let hm = to_map(32, &hb, Edge::Wrap).unwrap();
    let relaxed = ConeMap::generate(&hm, ConeParams::relaxed(4.0)).unwrap();
    let conservative = ConeMap::generate(&hm, ConeParams::conservative(4.0)).unwrap();
    let m = map_f32(&hb, OCEAN_RELIEF_EDGE_WRAP, OCEAN_RELIEF_RANGE_REFUSE);
    let c_rel = cones(m, &params(OceanReliefConeKind::Relaxed, 4.0));
    let c_con = cones(m, &params(OceanReliefConeKind::Conservative, 4.0));
    let rays = test_rays(1000, 0.15);
    let methods = [
        (
            OceanReliefMethod {
                next: crate::boundary::OceanNext::NULL,
                method: OceanReliefTracer::Linear,
                steps: 15,
                binary: 6,
                search: OceanReliefSearch::LastStep,
            },
            Method::Linear {
                linear: 15,
                binary: 6,
            },
            false,
        ),
        (
            OceanReliefMethod {
                next: crate::boundary::OceanNext::NULL,
                method: OceanReliefTracer::ConeStep,
                steps: 21,
                binary: 0,
                search: OceanReliefSearch::LastStep,
            },
            Method::ConeStep { steps: 21 },
            true,
        ),
        (
            OceanReliefMethod {
                next: crate::boundary::OceanNext::NULL,
                method: OceanReliefTracer::Relaxed,
                steps: 15,
                binary: 6,
                search: OceanReliefSearch::LastStep,
            },
            Method::Relaxed {
                cone: 15,
                binary: 6,
                search: BinarySearch::LastStep,
            },
            false,
        ),
        (
            OceanReliefMethod {
                next: crate::boundary::OceanNext::NULL,
                method: OceanReliefTracer::Relaxed,
                steps: 15,
                binary: 6,
                search: OceanReliefSearch::Book,
            },
            Method::Relaxed {
                cone: 15,
                binary: 6,
                search: BinarySearch::Book,
            },
            false,
        ),
        (
            OceanReliefMethod {
                next: crate::boundary::OceanNext::NULL,
                method: OceanReliefTracer::Relaxed,
                steps: 15,
                binary: 6,
                search: OceanReliefSearch::Shared,
            },
            Method::Relaxed {
                cone: 15,
                binary: 6,
                search: BinarySearch::Shared,
            },
            false,
        ),
    ];
    for (fm, method, conservative_cones) in methods {
        let (c, cm) = if conservative_cones {
            (c_con, &conservative)
        } else {
            (c_rel, &relaxed)
        };
        let texture = ReliefTexture::new(&hm, cm).unwrap();
        let mut hits = vec![OceanReliefHit::default(); rays.len()];
        // SAFETY: live handle, arrays of `rays.len()` elements.
        let s = unsafe { ocean_relief_trace(c, &fm, rays.as_ptr(), rays.len(), hits.as_mut_ptr()) };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        for (r, h) in rays.iter().zip(&hits) {
            let ray = Ray {
                start: glam::Vec2::new(r.start_u, r.start_v),
                dir: glam::Vec3::new(r.dir_x, r.dir_y, r.dir_z),
            };
            let want = method.trace(&texture, &ray).unwrap();
            assert_eq!(
                (h.pos.u.to_bits(), h.pos.v.to_bits(), h.pos.depth.to_bits()),
                (
                    want.pos.x.to_bits(),
                    want.pos.y.to_bits(),
                    want.pos.z.to_bits()
                ),
                "{method:?}"
            );
            assert_eq!(h.fetches, want.fetches);
        }
        // Shadows at the hits, light 40° above the horizon.
        let points: Vec<OceanReliefPoint> = hits.iter().map(|h| h.pos).collect();
        let light = glam::Vec3::new(0.6, 0.3, 0.7);
        let mut shadow = vec![7u8; points.len()];
        // SAFETY: live handle, arrays of `points.len()` elements.
        let s = unsafe {
            ocean_relief_shadow(
                c,
                &fm,
                points.as_ptr(),
                points.len(),
                light.x,
                light.y,
                light.z,
                0.15,
                0.01,
                shadow.as_mut_ptr(),
            )
        };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        let mut lit = 0;
        for (p, &sh) in points.iter().zip(&shadow) {
            let want = ocean_relief::shadow::in_shadow(
                &texture,
                &method,
                glam::Vec3::new(p.u, p.v, p.depth),
                light,
                0.15,
                0.01,
            )
            .unwrap();
            assert_eq!(sh, u8::from(want));
            lit += usize::from(!want);
        }
        // Boxes on a floor under a 40° light: some points are lit, some are not.
        assert!(
            lit > 0 && lit < points.len(),
            "{lit} of {} lit",
            points.len()
        );
    }
    ocean_relief_cones_destroy(c_rel);
    ocean_relief_cones_destroy(c_con);
    ocean_relief_map_destroy(m);
}

/// Bad methods, rays and shadow arguments: the status, a message naming the culprit, and the
/// outputs untouched.
#[test]
fn trace_errors_are_mapped_and_write_nothing() {
    let h = heights();
    let m = map_f32(&h, OCEAN_RELIEF_EDGE_WRAP, OCEAN_RELIEF_RANGE_REFUSE);
    let c = cones(m, &params(OceanReliefConeKind::Relaxed, 1.0));
    let good = OceanReliefMethod {
        next: crate::boundary::OceanNext::NULL,
        method: OceanReliefTracer::Relaxed,
        steps: 15,
        binary: 6,
        search: OceanReliefSearch::LastStep,
    };
    let rays = test_rays(4, 0.1);
    let untouched = OceanReliefHit {
        pos: OceanReliefPoint {
            u: -9.0,
            v: -9.0,
            depth: -9.0,
        },
        fetches: 99,
    };
    let trace = |method: *const OceanReliefMethod, rays: &[OceanReliefRay]| {
        let mut hits = vec![untouched; rays.len().max(1)];
        // SAFETY: live handle, arrays of `rays.len()` elements.
        let s =
            unsafe { ocean_relief_trace(c, method, rays.as_ptr(), rays.len(), hits.as_mut_ptr()) };
        assert!(hits.iter().all(|h| *h == untouched), "written on failure");
        (s, last_error())
    };
    // Unknown enumerators, from C memory, whatever the other members.
    for (offset, raw, base, needle) in [
        (
            core::mem::offset_of!(OceanReliefMethod, method),
            3,
            good,
            "method->method = 3 is not an OCEAN_RELIEF_TRACER_* value (0 to 2)",
        ),
        (
            core::mem::offset_of!(OceanReliefMethod, search),
            3,
            good,
            "method->search = 3 is not an OCEAN_RELIEF_SEARCH_* value (0 to 2)",
        ),
        // Checked even where the tracer does not read it (cone step mapping).
        (
            core::mem::offset_of!(OceanReliefMethod, search),
            77,
            OceanReliefMethod {
                method: OceanReliefTracer::ConeStep,
                ..good
            },
            "method->search = 77 is not",
        ),
    ] {
        let bad = Poked::new(&base, offset, raw);
        let (s, msg) = trace(bad.as_ptr(), &rays);
        assert_eq!(s, OceanStatus::InvalidArgument, "{needle}");
        assert!(msg.contains(needle), "{msg}");
    }
    for (method, needle) in [
        (OceanReliefMethod { steps: 0, ..good }, "method->steps = 0"),
        (
            OceanReliefMethod {
                steps: 4097,
                ..good
            },
            "method->steps = 4097",
        ),
        (
            OceanReliefMethod {
                binary: 5000,
                ..good
            },
            "method->binary = 5000",
        ),
    ] {
        let (s, msg) = trace(&method, &rays);
        assert_eq!(s, OceanStatus::InvalidArgument, "{method:?}");
        assert!(msg.contains(needle), "{msg}");
    }
    // Cone step mapping reads neither `binary` nor `search` (any enumerator).
    let csm = OceanReliefMethod {
        next: crate::boundary::OceanNext::NULL,
        method: OceanReliefTracer::ConeStep,
        steps: 8,
        binary: 9999,
        search: OceanReliefSearch::Shared,
    };
    let mut hits = vec![untouched; rays.len()];
    // SAFETY: arrays of `rays.len()` elements.
    let s = unsafe { ocean_relief_trace(c, &csm, rays.as_ptr(), rays.len(), hits.as_mut_ptr()) };
    assert_eq!(s, OceanStatus::Ok, "{}", last_error());
    // Bad rays: the third is named.
    let mut bad = rays.clone();
    bad[2].dir_y = f32::NAN;
    let (s, msg) = trace(&good, &bad);
    assert_eq!(s, OceanStatus::NonFinite);
    assert!(msg.contains("rays[2].dir_y"), "{msg}");
    let mut bad = rays.clone();
    bad[1].dir_z = 0.0;
    let (s, msg) = trace(&good, &bad);
    assert_eq!(s, OceanStatus::InvalidArgument);
    assert!(msg.contains("rays[1].dir_z"), "{msg}");
    let (s, _) = trace(&good, &[]);
    assert_eq!(s, OceanStatus::Empty);
    // Overlapping arrays.
    let mut buf = vec![OceanReliefHit::default(); 8];
    let p = buf.as_mut_ptr();
    // SAFETY: both views lie inside `buf`; the overlap is detected before any access.
    let s = unsafe { ocean_relief_trace(c, &good, p.cast_const().cast(), 2, p) };
    assert_eq!(s, OceanStatus::InvalidArgument);
    assert!(last_error().contains("overlap"));
    // ray_from_view.
    let mut r = OceanReliefRay {
        start_u: 5.0,
        ..Default::default()
    };
    // SAFETY: writable out.
    let s = unsafe { ocean_relief_ray_from_view(0.0, 0.0, 0.0, 0.0, 1.0, 0.1, &mut r) };
    assert_eq!(s, OceanStatus::InvalidArgument);
    // SAFETY: writable out.
    let s = unsafe { ocean_relief_ray_from_view(0.0, 0.0, 0.0, f32::NAN, -1.0, 0.1, &mut r) };
    assert_eq!(s, OceanStatus::NonFinite);
    assert!(last_error().contains("view_y"));
    // SAFETY: writable out.
    let s = unsafe { ocean_relief_ray_from_view(0.0, 0.0, 0.0, 0.0, -1.0, -0.1, &mut r) };
    assert_eq!(s, OceanStatus::InvalidArgument);
    assert_eq!(r.start_u, 5.0);
    // Shadows.
    let points = [OceanReliefPoint {
        u: 0.5,
        v: 0.5,
        depth: 0.5,
    }];
    let shadow = |lz: f32, scale: f32, bias: f32, pts: &[OceanReliefPoint]| {
        let mut out = [7u8; 1];
        // SAFETY: live handle, arrays of `pts.len()` (<= 1) elements.
        let s = unsafe {
            ocean_relief_shadow(
                c,
                &good,
                pts.as_ptr(),
                pts.len(),
                0.0,
                0.0,
                lz,
                scale,
                bias,
                out.as_mut_ptr(),
            )
        };
        assert_eq!(out, [7], "written on failure");
        s
    };
    assert_eq!(shadow(f32::NAN, 0.1, 0.0, &points), OceanStatus::NonFinite);
    assert_eq!(
        shadow(1.0, -0.1, 0.0, &points),
        OceanStatus::InvalidArgument
    );
    assert_eq!(shadow(1.0, 0.1, 2.0, &points), OceanStatus::InvalidArgument);
    assert_eq!(shadow(1.0, 0.1, 0.0, &[]), OceanStatus::Empty);
    let nan_point = [OceanReliefPoint {
        u: f32::NAN,
        ..points[0]
    }];
    assert_eq!(shadow(1.0, 0.1, 0.0, &nan_point), OceanStatus::NonFinite);
    assert!(last_error().contains("points[0].u"));
    ocean_relief_cones_destroy(c);
    ocean_relief_map_destroy(m);
}
