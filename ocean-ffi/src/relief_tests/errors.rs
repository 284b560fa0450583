//! The refusals of the map and cone constructors: the status, a message naming the problem, and
//! nothing written.

use super::*;

/// Every bad input of the map constructors: the status, a message naming the problem, and
/// `*out` untouched.
#[test]
fn map_errors_are_mapped_and_write_nothing() {
    let h = heights();
    let sentinel = 0x10 as *mut OceanReliefMap;
    let create = |h: &[f32], w: u32, ht: u32, edge: u32, range: u32| {
        let mut m = sentinel;
        // SAFETY: `h` holds `h.len()` floats; `m` is writable.
        let s =
            unsafe { ocean_relief_map_create_f32(h.as_ptr(), h.len(), w, ht, edge, range, &mut m) };
        assert_eq!(m, sentinel, "out written on failure");
        (s, last_error())
    };
    let refuse = OCEAN_RELIEF_RANGE_REFUSE;
    let wrap = OCEAN_RELIEF_EDGE_WRAP;
    // Zero-sized.
    let (s, msg) = create(&[], 0, 0, wrap, refuse);
    assert_eq!(s, OceanStatus::Empty);
    assert!(msg.contains("empty"), "{msg}");
    // Non-square.
    let (s, msg) = create(&h[..32 * 16], 32, 16, wrap, refuse);
    assert_eq!(s, OceanStatus::InvalidArgument);
    assert!(msg.contains("square"), "{msg}");
    // Too small and too large (the documented cap, 4096).
    let (s, msg) = create(&h[..1], 1, 1, wrap, refuse);
    assert_eq!(s, OceanStatus::InvalidArgument);
    assert!(msg.contains("4096"), "{msg}");
    let big = vec![0.5f32; 4097 * 4097];
    let (s, msg) = create(&big, 4097, 4097, wrap, refuse);
    assert_eq!(s, OceanStatus::InvalidArgument);
    assert!(msg.contains("OCEAN_RELIEF_MAX_SIDE"), "{msg}");
    // Wrong length.
    let (s, msg) = create(&h[..TEXELS - 1], N, N, wrap, refuse);
    assert_eq!(s, OceanStatus::LengthMismatch);
    assert!(msg.contains("1023") && msg.contains("1024"), "{msg}");
    // NaN, at texel (5, 2): the message names it.
    let mut bad = h.clone();
    bad[2 * 32 + 5] = f32::NAN;
    let (s, msg) = create(&bad, N, N, wrap, refuse);
    assert_eq!(s, OceanStatus::NonFinite);
    assert!(msg.contains("(5, 2)"), "{msg}");
    // Out of [0, 1]: refused, or normalised on request.
    let mut over = h.clone();
    over[7] = 1.5;
    let (s, msg) = create(&over, N, N, wrap, refuse);
    assert_eq!(s, OceanStatus::InvalidArgument);
    assert!(msg.contains("1.5") && msg.contains("(7, 0)"), "{msg}");
    let m = map_f32(&over, wrap, OCEAN_RELIEF_RANGE_NORMALIZE);
    // The largest height (1.5) becomes depth 0.
    assert_eq!(depths_of(m)[7], 0.0);
    ocean_relief_map_destroy(m);
    // Unknown enumeration values.
    let (s, msg) = create(&h, N, N, 2, refuse);
    assert_eq!(s, OceanStatus::InvalidArgument);
    assert!(msg.contains("`edge` = 2"), "{msg}");
    let (s, msg) = create(&h, N, N, wrap, 9);
    assert_eq!(s, OceanStatus::InvalidArgument);
    assert!(msg.contains("`range` = 9"), "{msg}");
    // NULL and misaligned pointers.
    let mut m = sentinel;
    // SAFETY: NULL is checked.
    let s = unsafe { ocean_relief_map_create_f32(null(), 4, 2, 2, wrap, refuse, &mut m) };
    assert_eq!(s, OceanStatus::NullPointer);
    assert_eq!(m, sentinel);
    let bytes = [0u8; 64];
    // SAFETY: a misaligned pointer is checked before any read.
    let s = unsafe {
        ocean_relief_map_create_f32(
            bytes.as_ptr().wrapping_add(1).cast(),
            4,
            2,
            2,
            wrap,
            refuse,
            &mut m,
        )
    };
    assert_eq!(s, OceanStatus::MisalignedPointer);
    // SAFETY: misaligned u16 pointer, checked.
    let s = unsafe {
        ocean_relief_map_create_u16(bytes.as_ptr().wrapping_add(1).cast(), 4, 2, 2, wrap, &mut m)
    };
    assert_eq!(s, OceanStatus::MisalignedPointer);
    // SAFETY: NULL out is checked.
    let s = unsafe { ocean_relief_map_create_u8(bytes.as_ptr(), 4, 2, 2, wrap, null_mut()) };
    assert_eq!(s, OceanStatus::NullPointer);
    assert_eq!(m, sentinel);
}

/// Bad cone parameters and output buffers: the status, and nothing written.
#[test]
fn cone_errors_are_mapped_and_write_nothing() {
    let h = heights();
    let m = map_f32(&h, OCEAN_RELIEF_EDGE_WRAP, OCEAN_RELIEF_RANGE_REFUSE);
    let sentinel = 0x10 as *mut OceanReliefCones;
    // An unknown kind, from C memory.
    let kind_2 = Poked::new(
        &params(OceanReliefConeKind::Relaxed, 1.0),
        core::mem::offset_of!(OceanReliefConeParams, kind),
        2,
    );
    let mut out = sentinel;
    // SAFETY: live handle, a readable struct, a writable pointer; no callback.
    let s = unsafe { ocean_relief_cones_create(m, kind_2.as_ptr(), None, null_mut(), &mut out) };
    assert_eq!(s, OceanStatus::InvalidArgument);
    assert_eq!(
        last_error(),
        "ocean_relief_cones_create: params->kind = 2 is neither OCEAN_RELIEF_CONE_KIND_RELAXED (0) \
         nor OCEAN_RELIEF_CONE_KIND_CONSERVATIVE (1)"
    );
    assert_eq!(out, sentinel, "written on failure");
    for (p, status, needle) in [
        (
            params(OceanReliefConeKind::Relaxed, f32::NAN),
            OceanStatus::NonFinite,
            "max_ratio",
        ),
        (
            params(OceanReliefConeKind::Relaxed, 0.0),
            OceanStatus::InvalidArgument,
            "max_ratio = 0",
        ),
        (
            params(OceanReliefConeKind::Relaxed, 65.0),
            OceanStatus::InvalidArgument,
            "max_ratio = 65",
        ),
    ] {
        let mut c = sentinel;
        // SAFETY: live handle, valid pointers.
        let s = unsafe { ocean_relief_cones_create(m, &p, None, null_mut(), &mut c) };
        assert_eq!(s, status, "{p:?}");
        assert!(last_error().contains(needle), "{}", last_error());
        assert_eq!(c, sentinel);
    }
    let mut d = OceanReliefConeParams::default();
    // SAFETY: writable out.
    let st = unsafe { ocean_relief_cone_params_default(&mut d) };
    assert_eq!(st, OceanStatus::Ok);
    assert_eq!(d, params(OceanReliefConeKind::Relaxed, 1.0));
    let c = cones(m, &d);
    // Wrong lengths, unknown encoding, misaligned output: untouched buffers.
    let mut t = vec![-7.0f32; 4 * TEXELS + 1];
    // SAFETY: buffer of the given length.
    let s = unsafe { ocean_relief_cones_texels(c, t.as_mut_ptr(), t.len()) };
    assert_eq!(s, OceanStatus::LengthMismatch);
    assert!(t.iter().all(|&v| v == -7.0));
    let mut e = vec![0xEEu16; 3 * TEXELS + 2];
    // SAFETY: buffer of the given length.
    let s = unsafe { ocean_relief_cones_encode(c, 4, e.as_mut_ptr().cast(), 3 * TEXELS) };
    assert_eq!(s, OceanStatus::InvalidArgument);
    assert!(last_error().contains("`encoding` = 4"));
    // SAFETY: a misaligned u16 pointer is checked before any write.
    let s = unsafe {
        ocean_relief_cones_encode(
            c,
            OCEAN_RELIEF_ENCODING_F16,
            e.as_mut_ptr().cast::<u8>().wrapping_add(1).cast(),
            3 * TEXELS,
        )
    };
    assert_eq!(s, OceanStatus::MisalignedPointer);
    assert!(e.iter().all(|&v| v == 0xEE));
    // SAFETY: NULL handle is checked.
    let s = unsafe { ocean_relief_cones_texels(null(), t.as_mut_ptr(), 4 * TEXELS) };
    assert_eq!(s, OceanStatus::NullPointer);
    ocean_relief_cones_destroy(c);
    ocean_relief_cones_destroy(null_mut());
    ocean_relief_map_destroy(m);
}
