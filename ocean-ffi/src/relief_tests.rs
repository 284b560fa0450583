//! Tests of the relief C ABI: the wrapper adds nothing to ocean-relief's arithmetic (every
//! output bit-identical to the crate's), maps every error to a status with a message, never
//! writes an output on failure, and cancels from a C callback.

use core::ffi::{c_int, c_void};
use core::ptr::{null, null_mut};

use ocean_relief::maps::{boxes, to_map, value_noise};
use ocean_relief::mip::{MipRule, chain};
use ocean_relief::storage::{Encoded, Encoding, encode};
use ocean_relief::trace::{BinarySearch, Method, Ray};
use ocean_relief::{ConeMap, ConeParams, Edge, HeightMap, HeightRange, ReliefTexture};

use super::*;
use crate::boundary::enums::Poked;
use crate::relief_mips::*;
use crate::relief_trace::*;

const N: u32 = 32;
const TEXELS: usize = (N * N) as usize;

use crate::status::last_error;

// The parameter values as a C caller passes them (`uint32_t`).
const OCEAN_RELIEF_EDGE_WRAP: u32 = OceanReliefEdge::Wrap as u32;
const OCEAN_RELIEF_EDGE_CLAMP: u32 = OceanReliefEdge::Clamp as u32;
const OCEAN_RELIEF_RANGE_REFUSE: u32 = OceanReliefRange::Refuse as u32;
const OCEAN_RELIEF_RANGE_NORMALIZE: u32 = OceanReliefRange::Normalize as u32;
const OCEAN_RELIEF_ENCODING_UNORM8: u32 = OceanReliefEncoding::Unorm8 as u32;
const OCEAN_RELIEF_ENCODING_UNORM8_SQRT: u32 = OceanReliefEncoding::Unorm8Sqrt as u32;
const OCEAN_RELIEF_ENCODING_F16: u32 = OceanReliefEncoding::F16 as u32;
const OCEAN_RELIEF_ENCODING_F32: u32 = OceanReliefEncoding::F32 as u32;
const OCEAN_RELIEF_MIP_WINDOW: u32 = OceanReliefMip::Window as u32;
const OCEAN_RELIEF_MIP_GROUP: u32 = OceanReliefMip::Group as u32;

/// Value-noise heights in [0, 1] (the crate's `to_map` input).
fn heights() -> Vec<f32> {
    value_noise(N as usize, 4, 3, 9)
}

fn map_f32(h: &[f32], edge: u32, range: u32) -> *mut OceanReliefMap {
    let mut m = null_mut();
    // SAFETY: valid pointers and lengths.
    let s = unsafe { ocean_relief_map_create_f32(h.as_ptr(), h.len(), N, N, edge, range, &mut m) };
    assert_eq!(s, OceanStatus::Ok, "{}", last_error());
    m
}

fn params(kind: OceanReliefConeKind, max_ratio: f32) -> OceanReliefConeParams {
    OceanReliefConeParams {
        next: crate::boundary::OceanNext::NULL,
        kind,
        max_ratio,
    }
}

fn cones(map: *const OceanReliefMap, p: &OceanReliefConeParams) -> *mut OceanReliefCones {
    let mut c = null_mut();
    // SAFETY: live handle, valid pointers; no callback.
    let s = unsafe { ocean_relief_cones_create(map, p, None, null_mut(), &mut c) };
    assert_eq!(s, OceanStatus::Ok, "{}", last_error());
    c
}

fn depths_of(map: *const OceanReliefMap) -> Vec<f32> {
    let mut d = vec![-1.0f32; TEXELS];
    // SAFETY: live handle, buffer of the given length.
    let s = unsafe { ocean_relief_map_depths(map, d.as_mut_ptr(), d.len()) };
    assert_eq!(s, OceanStatus::Ok, "{}", last_error());
    d
}

/// The crate's `[c, D, E]` per texel under `encoding`, as raw element bits (u32).
fn crate_encoded(c: &ConeMap, encoding: Encoding) -> Vec<u32> {
    let chans = [c.ratios(), c.clearance(), c.near_cap()].map(|v| match encode(v, encoding) {
        Encoded::Unorm8(x) => x.into_iter().map(u32::from).collect::<Vec<_>>(),
        Encoded::F16(x) => x.into_iter().map(u32::from).collect(),
        Encoded::F32(x) => x.into_iter().map(f32::to_bits).collect(),
    });
    (0..chans[0].len())
        .flat_map(|k| [chans[0][k], chans[1][k], chans[2][k]])
        .collect()
}

/// `ocean_relief_cones_encode` (or a mip level) read back as raw element bits (u32).
fn ffi_encoded(
    len: usize,
    encoding: u32,
    mut call: impl FnMut(*mut c_void, usize) -> OceanStatus,
) -> Vec<u32> {
    match encoding {
        OCEAN_RELIEF_ENCODING_UNORM8 | OCEAN_RELIEF_ENCODING_UNORM8_SQRT => {
            let mut v = vec![0xAAu8; len];
            assert_eq!(
                call(v.as_mut_ptr().cast(), len),
                OceanStatus::Ok,
                "{}",
                last_error()
            );
            v.into_iter().map(u32::from).collect()
        }
        OCEAN_RELIEF_ENCODING_F16 => {
            let mut v = vec![0xAAAAu16; len];
            assert_eq!(
                call(v.as_mut_ptr().cast(), len),
                OceanStatus::Ok,
                "{}",
                last_error()
            );
            v.into_iter().map(u32::from).collect()
        }
        _ => {
            let mut v = vec![-1.0f32; len];
            assert_eq!(
                call(v.as_mut_ptr().cast(), len),
                OceanStatus::Ok,
                "{}",
                last_error()
            );
            v.into_iter().map(f32::to_bits).collect()
        }
    }
}

const ENCODINGS: [(u32, Encoding); 4] = [
    (OCEAN_RELIEF_ENCODING_UNORM8, Encoding::Unorm8),
    (OCEAN_RELIEF_ENCODING_UNORM8_SQRT, Encoding::Unorm8Sqrt),
    (OCEAN_RELIEF_ENCODING_F16, Encoding::F16),
    (OCEAN_RELIEF_ENCODING_F32, Encoding::F32),
];

/// The three constructors store the crate's depths, bit for bit: f32 heights (refused range
/// and normalised), 8-bit and 16-bit heights, both edge modes.
#[test]
fn maps_are_the_crates() {
    let h = heights();
    for (edge, e) in [
        (OCEAN_RELIEF_EDGE_WRAP, Edge::Wrap),
        (OCEAN_RELIEF_EDGE_CLAMP, Edge::Clamp),
    ] {
        let m = map_f32(&h, edge, OCEAN_RELIEF_RANGE_REFUSE);
        let want = HeightMap::from_heights(32, 32, &h, e, HeightRange::Refuse).unwrap();
        assert_eq!(depths_of(m), want.depths());
        ocean_relief_map_destroy(m);

        // Heights in [-3, 5]: normalised to [0, 1].
        let wide: Vec<f32> = h.iter().map(|v| 8.0 * v - 3.0).collect();
        let m = map_f32(&wide, edge, OCEAN_RELIEF_RANGE_NORMALIZE);
        let want = HeightMap::from_heights(32, 32, &wide, e, HeightRange::Normalize).unwrap();
        assert_eq!(depths_of(m), want.depths());
        let mut side = 0u32;
        // SAFETY: live handle, writable out.
        let st = unsafe { ocean_relief_map_size(m, &mut side) };
        assert_eq!(st, OceanStatus::Ok);
        assert_eq!(side, N);
        ocean_relief_map_destroy(m);

        let h8: Vec<u8> = (0..TEXELS).map(|k| (k * 37 % 256) as u8).collect();
        let mut m = null_mut();
        // SAFETY: valid pointers.
        let s = unsafe { ocean_relief_map_create_u8(h8.as_ptr(), h8.len(), N, N, edge, &mut m) };
        assert_eq!(s, OceanStatus::Ok);
        assert_eq!(
            depths_of(m),
            HeightMap::from_u8(32, 32, &h8, e).unwrap().depths()
        );
        ocean_relief_map_destroy(m);

        let h16: Vec<u16> = (0..TEXELS).map(|k| (k * 2113 % 65536) as u16).collect();
        let mut m = null_mut();
        // SAFETY: valid pointers.
        let s = unsafe { ocean_relief_map_create_u16(h16.as_ptr(), h16.len(), N, N, edge, &mut m) };
        assert_eq!(s, OceanStatus::Ok);
        assert_eq!(
            depths_of(m),
            HeightMap::from_u16(32, 32, &h16, e).unwrap().depths()
        );
        ocean_relief_map_destroy(m);
    }
    ocean_relief_map_destroy(null_mut());
}

/// Cone maps through the handle and straight into buffers equal `ConeMap::generate`'s bits in
/// every channel and encoding, relaxed and conservative, wrap and clamp.
#[test]
fn cones_are_the_crates_in_every_encoding() {
    let h = heights();
    for (edge, e) in [
        (OCEAN_RELIEF_EDGE_WRAP, Edge::Wrap),
        (OCEAN_RELIEF_EDGE_CLAMP, Edge::Clamp),
    ] {
        let m = map_f32(&h, edge, OCEAN_RELIEF_RANGE_REFUSE);
        let hm = HeightMap::from_heights(32, 32, &h, e, HeightRange::Refuse).unwrap();
        for (kind, p) in [
            (OceanReliefConeKind::Relaxed, ConeParams::relaxed(2.5)),
            (
                OceanReliefConeKind::Conservative,
                ConeParams::conservative(1.0),
            ),
        ] {
            let want = ConeMap::generate(&hm, p).unwrap();
            let fp = params(kind, p.max_ratio);
            let c = cones(m, &fp);
            // The texels: [depth, c, D, E].
            let mut t = vec![-1.0f32; 4 * TEXELS];
            // SAFETY: live handle, buffer of the given length.
            let s = unsafe { ocean_relief_cones_texels(c, t.as_mut_ptr(), t.len()) };
            assert_eq!(s, OceanStatus::Ok, "{}", last_error());
            let tex = ReliefTexture::new(&hm, &want).unwrap();
            let flat: Vec<f32> = tex.texels().iter().flatten().copied().collect();
            assert_eq!(t, flat);
            // The direct path gives the same texels.
            let mut direct = vec![-1.0f32; 4 * TEXELS];
            // SAFETY: live handle, valid pointers.
            let s = unsafe {
                ocean_relief_generate_texels(
                    m,
                    &fp,
                    None,
                    null_mut(),
                    direct.as_mut_ptr(),
                    direct.len(),
                )
            };
            assert_eq!(s, OceanStatus::Ok, "{}", last_error());
            assert_eq!(direct, flat);
            for (code, enc) in ENCODINGS {
                let expect = crate_encoded(&want, enc);
                let got = ffi_encoded(3 * TEXELS, code, |out, len| {
                    // SAFETY: live handle, buffer of `len` elements of the encoding's type.
                    unsafe { ocean_relief_cones_encode(c, code, out, len) }
                });
                assert_eq!(got, expect, "{e:?} {p:?} {enc:?}");
                let direct = ffi_encoded(3 * TEXELS, code, |out, len| {
                    // SAFETY: as above.
                    unsafe {
                        ocean_relief_generate_encoded(m, &fp, None, null_mut(), code, out, len)
                    }
                });
                assert_eq!(direct, expect, "direct {e:?} {p:?} {enc:?}");
                // Quantised handle: the crate's `quantized`, read back as f32.
                let mut q = null_mut();
                // SAFETY: live handle, writable out.
                let s = unsafe { ocean_relief_cones_quantize(c, code, &mut q) };
                assert_eq!(s, OceanStatus::Ok, "{}", last_error());
                let mut qt = vec![-1.0f32; 4 * TEXELS];
                // SAFETY: live handle, buffer of the given length.
                let s = unsafe { ocean_relief_cones_texels(q, qt.as_mut_ptr(), qt.len()) };
                assert_eq!(s, OceanStatus::Ok);
                let wq = ReliefTexture::new(&hm, &want.quantized(enc).unwrap()).unwrap();
                let wq: Vec<f32> = wq.texels().iter().flatten().copied().collect();
                assert_eq!(qt, wq);
                ocean_relief_cones_destroy(q);
            }
            ocean_relief_cones_destroy(c);
        }
        ocean_relief_map_destroy(m);
    }
}

/// A C callback that records its calls in a `Vec<(usize, usize)>` and cancels on call number
/// `cancel_at` (1-based; 0 never cancels).
struct Recorder {
    calls: Vec<(usize, usize)>,
    cancel_at: usize,
}

unsafe extern "C" fn record(user: *mut c_void, done: usize, total: usize) -> c_int {
    // SAFETY: the tests pass a live, exclusive `Recorder`.
    let r = unsafe { &mut *user.cast::<Recorder>() };
    r.calls.push((done, total));
    c_int::from(r.calls.len() == r.cancel_at)
}

/// The callback sees 0 first and the total last (rows of cells: N in wrap mode, N + 1 in clamp
/// mode, one row a band at this size), and the result is the one without a callback.
#[test]
fn progress_reaches_total_and_output_is_unchanged() {
    let h = heights();
    for (edge, total) in [(OCEAN_RELIEF_EDGE_WRAP, 32), (OCEAN_RELIEF_EDGE_CLAMP, 33)] {
        let m = map_f32(&h, edge, OCEAN_RELIEF_RANGE_REFUSE);
        let p = params(OceanReliefConeKind::Relaxed, 1.0);
        let plain = cones(m, &p);
        let mut rec = Recorder {
            calls: Vec::new(),
            cancel_at: 0,
        };
        let mut c = null_mut();
        // SAFETY: live handle, callback with its live user data.
        let s = unsafe {
            ocean_relief_cones_create(m, &p, Some(record), (&raw mut rec).cast(), &mut c)
        };
        assert_eq!(s, OceanStatus::Ok, "{}", last_error());
        let expected: Vec<(usize, usize)> = (0..=total).map(|d| (d, total)).collect();
        assert_eq!(rec.calls, expected);
        let read = |c: *const OceanReliefCones| {
            let mut t = vec![0.0f32; 4 * TEXELS];
            // SAFETY: live handle, buffer of the given length.
            let st = unsafe { ocean_relief_cones_texels(c, t.as_mut_ptr(), t.len()) };
            assert_eq!(st, OceanStatus::Ok);
            t
        };
        assert_eq!(read(c), read(plain));
        ocean_relief_cones_destroy(c);
        ocean_relief_cones_destroy(plain);
        ocean_relief_map_destroy(m);
    }
}

/// Cancelling on the first call (before any work), the third, or the last (all work done):
/// `OCEAN_STATUS_CANCELLED`, no further call, and neither the handle nor a buffer written.
#[test]
fn cancellation_writes_nothing() {
    let h = heights();
    let m = map_f32(&h, OCEAN_RELIEF_EDGE_WRAP, OCEAN_RELIEF_RANGE_REFUSE);
    let p = params(OceanReliefConeKind::Relaxed, 1.0);
    for k in [1usize, 3, 33] {
        let mut rec = Recorder {
            calls: Vec::new(),
            cancel_at: k,
        };
        let sentinel = 0x10 as *mut OceanReliefCones;
        let mut c = sentinel;
        // SAFETY: live handle, callback with its live user data.
        let s = unsafe {
            ocean_relief_cones_create(m, &p, Some(record), (&raw mut rec).cast(), &mut c)
        };
        assert_eq!(s, OceanStatus::Cancelled);
        assert!(last_error().contains("cancelled"), "{}", last_error());
        assert_eq!(c, sentinel);
        assert_eq!(rec.calls.len(), k);

        let mut rec = Recorder {
            calls: Vec::new(),
            cancel_at: k,
        };
        let mut t = vec![-7.0f32; 4 * TEXELS];
        // SAFETY: as above, buffer of the given length.
        let s = unsafe {
            ocean_relief_generate_texels(
                m,
                &p,
                Some(record),
                (&raw mut rec).cast(),
                t.as_mut_ptr(),
                t.len(),
            )
        };
        assert_eq!(s, OceanStatus::Cancelled);
        assert!(t.iter().all(|&v| v == -7.0));

        let mut rec = Recorder {
            calls: Vec::new(),
            cancel_at: k,
        };
        let mut e = vec![0xEEu8; 3 * TEXELS];
        // SAFETY: as above.
        let s = unsafe {
            ocean_relief_generate_encoded(
                m,
                &p,
                Some(record),
                (&raw mut rec).cast(),
                OCEAN_RELIEF_ENCODING_UNORM8,
                e.as_mut_ptr().cast(),
                e.len(),
            )
        };
        assert_eq!(s, OceanStatus::Cancelled);
        assert!(e.iter().all(|&v| v == 0xEE));
    }
    // Bad arguments are refused before the callback is ever called.
    let mut rec = Recorder {
        calls: Vec::new(),
        cancel_at: 0,
    };
    let mut t = vec![-7.0f32; 4 * TEXELS - 1];
    // SAFETY: buffer of the given length.
    let s = unsafe {
        ocean_relief_generate_texels(
            m,
            &p,
            Some(record),
            (&raw mut rec).cast(),
            t.as_mut_ptr(),
            t.len(),
        )
    };
    assert_eq!(s, OceanStatus::LengthMismatch);
    assert!(rec.calls.is_empty());
    ocean_relief_map_destroy(m);
}

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

/// The mip chain is the crate's (both rules, every level, every encoding); a side that is not a
/// power of two is refused.
#[test]
fn mips_are_the_crates() {
    let h = heights();
    let hm = HeightMap::from_heights(32, 32, &h, Edge::Wrap, HeightRange::Refuse).unwrap();
    let want_cones = ConeMap::generate(&hm, ConeParams::relaxed(1.0)).unwrap();
    let m = map_f32(&h, OCEAN_RELIEF_EDGE_WRAP, OCEAN_RELIEF_RANGE_REFUSE);
    let c = cones(m, &params(OceanReliefConeKind::Relaxed, 1.0));
    for (code, rule) in [
        (OCEAN_RELIEF_MIP_WINDOW, MipRule::Window),
        (OCEAN_RELIEF_MIP_GROUP, MipRule::Group),
    ] {
        let want = chain(&want_cones, rule).unwrap();
        let mut mips = null_mut();
        // SAFETY: live handle, writable out.
        let st = unsafe { ocean_relief_mips_create(c, code, &mut mips) };
        assert_eq!(st, OceanStatus::Ok);
        let mut count = 0u32;
        // SAFETY: live handle, writable out.
        let st = unsafe { ocean_relief_mips_level_count(mips, &mut count) };
        assert_eq!(st, OceanStatus::Ok);
        // 32 → 16 → 8 → 4 → 2 → 1.
        assert_eq!(count, 6);
        for level in 0..count {
            let mut side = 0u32;
            // SAFETY: live handle, writable out.
            let s = unsafe { ocean_relief_mips_level_size(mips, level, &mut side) };
            assert_eq!(s, OceanStatus::Ok);
            assert_eq!(side, 32 >> level);
            let len = 3 * (side * side) as usize;
            for (enc_code, enc) in ENCODINGS {
                let got = ffi_encoded(len, enc_code, |out, len| {
                    // SAFETY: live handle, buffer of `len` elements.
                    unsafe { ocean_relief_mips_copy_level(mips, level, enc_code, out, len) }
                });
                assert_eq!(got, crate_encoded(&want[level as usize], enc));
            }
        }
        let mut side = 77u32;
        // SAFETY: live handle, writable out.
        let s = unsafe { ocean_relief_mips_level_size(mips, 6, &mut side) };
        assert_eq!(s, OceanStatus::InvalidArgument);
        assert!(last_error().contains("levels 0 to 5"));
        assert_eq!(side, 77);
        ocean_relief_mips_destroy(mips);
    }
    // 24 is not a power of two.
    let h24 = vec![0.5f32; 24 * 24];
    let mut m24 = null_mut();
    // SAFETY: valid pointers.
    let s = unsafe { ocean_relief_map_create_f32(h24.as_ptr(), h24.len(), 24, 24, 0, 0, &mut m24) };
    assert_eq!(s, OceanStatus::Ok);
    let c24 = cones(m24, &params(OceanReliefConeKind::Relaxed, 1.0));
    let sentinel = 0x10 as *mut OceanReliefMips;
    let mut mips = sentinel;
    // SAFETY: live handle, writable out.
    let s = unsafe { ocean_relief_mips_create(c24, OCEAN_RELIEF_MIP_WINDOW, &mut mips) };
    assert_eq!(s, OceanStatus::InvalidArgument);
    assert!(last_error().contains("power-of-two"), "{}", last_error());
    assert_eq!(mips, sentinel);
    ocean_relief_cones_destroy(c24);
    ocean_relief_map_destroy(m24);
    ocean_relief_cones_destroy(c);
    ocean_relief_map_destroy(m);
    ocean_relief_mips_destroy(null_mut());
}

/// Normals are the crate's; a bad depth is refused with the buffer untouched.
#[test]
fn normals_are_the_crates() {
    let h = heights();
    let hm = HeightMap::from_heights(32, 32, &h, Edge::Clamp, HeightRange::Refuse).unwrap();
    let m = map_f32(&h, OCEAN_RELIEF_EDGE_CLAMP, OCEAN_RELIEF_RANGE_REFUSE);
    let mut xyz = vec![0.0f32; 3 * TEXELS];
    // SAFETY: live handle, buffer of the given length.
    let s = unsafe { ocean_relief_normals(m, 12.5, xyz.as_mut_ptr(), xyz.len()) };
    assert_eq!(s, OceanStatus::Ok, "{}", last_error());
    let want: Vec<f32> = ocean_relief::relief::normals(&hm, 12.5)
        .unwrap()
        .iter()
        .flat_map(|v| v.to_array())
        .collect();
    assert_eq!(xyz, want);
    let mut keep = vec![9.0f32; 3 * TEXELS];
    for (depth, status) in [
        (f32::INFINITY, OceanStatus::NonFinite),
        (-1.0, OceanStatus::InvalidArgument),
    ] {
        // SAFETY: live handle, buffer of the given length.
        let s = unsafe { ocean_relief_normals(m, depth, keep.as_mut_ptr(), keep.len()) };
        assert_eq!(s, status);
    }
    assert!(keep.iter().all(|&v| v == 9.0));
    ocean_relief_map_destroy(m);
}

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
