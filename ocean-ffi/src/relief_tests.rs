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

#[path = "relief_tests/errors.rs"]
mod errors;
#[path = "relief_tests/trace.rs"]
mod trace;
