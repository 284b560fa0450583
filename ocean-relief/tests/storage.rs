//! Storage rounds down: a decoded value is never above the stored one, and it is the largest
//! code that satisfies that.

use ocean_relief::storage::{Encoding, decode_f16, decode_unorm8, encode_f16, encode_unorm8};
use ocean_relief::{ConeMap, ConeParams, Edge};

/// Values around every 8-bit code (each decoded value and its neighbouring floats) and a sweep of
/// `[0, 1.5]`: the encoder picks the largest code whose decoded value is at most the input
/// (clamped to 1), linear and square-root.
#[test]
fn unorm8_rounds_down() {
    for sqrt in [false, true] {
        let mut inputs: Vec<f32> = (0..=1_000_000).map(|k| 1.5 * k as f32 / 1e6).collect();
        for k in 0..=255u8 {
            let d = decode_unorm8(k, sqrt);
            inputs.extend([d, d.next_down(), d.next_up()]);
        }
        for r in inputs {
            let k = encode_unorm8(r, sqrt);
            let clamped = r.clamp(0.0, 1.0);
            assert!(decode_unorm8(k, sqrt) <= clamped, "{r} {sqrt}");
            if k < 255 {
                assert!(
                    decode_unorm8(k + 1, sqrt) > clamped,
                    "{r} {sqrt}: {k} is not the largest"
                );
            }
        }
        assert_eq!(encode_unorm8(1.0, sqrt), 255);
        assert_eq!(encode_unorm8(7.0, sqrt), 255);
        assert_eq!(encode_unorm8(0.0, sqrt), 0);
        assert_eq!(encode_unorm8(f32::NAN, sqrt), 0);
        assert_eq!(encode_unorm8(-1.0, sqrt), 0);
    }
    // The square-root encoding keeps more of a narrow cone: 0.01 decodes to 0.00996 (code 25)
    // instead of 0.00784 (code 2).
    assert_eq!(encode_unorm8(0.01, false), 2);
    assert_eq!(encode_unorm8(0.01, true), 25);
}

/// The decoder agrees with the `half` crate on every finite bit pattern, and the encoder returns,
/// for every non-negative half and its neighbouring floats, the largest half not above them.
#[test]
fn f16_rounds_down() {
    for h in 0..=0xffffu16 {
        let reference = half::f16::from_bits(h).to_f32();
        let mine = decode_f16(h);
        assert!(
            mine == reference || (mine.is_nan() && reference.is_nan()),
            "{h:04x}"
        );
    }
    for h in 0..=0x7bffu16 {
        let d = decode_f16(h);
        for r in [d, d.next_up(), (d + decode_f16(h + 1)) * 0.5] {
            let e = encode_f16(r);
            assert!(decode_f16(e) <= r, "{r}");
            assert!(
                e == 0x7bff || decode_f16(e + 1) > r,
                "{r}: {e:04x} is not the largest"
            );
        }
        if h > 0 {
            assert_eq!(encode_f16(d.next_down()), h - 1);
        }
        assert_eq!(encode_f16(d), h);
    }
    assert_eq!(encode_f16(1.0e9), 0x7bff); // 65504
    assert_eq!(encode_f16(f32::NAN), 0);
    assert_eq!(encode_f16(-3.0), 0);
}

/// A quantised cone map is below the original everywhere, and the 8-bit encodings clamp the
/// ratio to 1 as the book does, while f16 keeps ratios above 1.
#[test]
fn quantised_maps_are_below_and_clamped() {
    // A shallow relief (heights 0.45 .. 0.55): cones wider than one texture width per unit depth.
    let h: Vec<f32> = ocean_relief::maps::value_noise(32, 4, 3, 2)
        .iter()
        .map(|h| 0.45 + 0.1 * h)
        .collect();
    let map = ocean_relief::maps::to_map(32, &h, Edge::Wrap).unwrap();
    let cones = ConeMap::generate(&map, ConeParams::relaxed(4.0)).unwrap();
    assert!(cones.ratios().iter().any(|&r| r > 1.0));
    for enc in [
        Encoding::Unorm8,
        Encoding::Unorm8Sqrt,
        Encoding::F16,
        Encoding::F32,
    ] {
        let q = cones.quantized(enc).unwrap();
        for (a, b) in [
            (q.ratios(), cones.ratios()),
            (q.clearance(), cones.clearance()),
            (q.near_cap(), cones.near_cap()),
        ] {
            assert!(a.iter().zip(b).all(|(x, y)| x <= y), "{enc:?}");
        }
        let max = q.ratios().iter().fold(0.0f32, |a, &b| a.max(b));
        match enc {
            Encoding::Unorm8 | Encoding::Unorm8Sqrt => assert_eq!(max, 1.0),
            Encoding::F16 | Encoding::F32 => assert!(max > 1.0),
        }
    }
    assert!(cones.quantized(Encoding::F32).unwrap() == cones);
}
