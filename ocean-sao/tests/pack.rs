//! The packing of A and z into one RGBA8 texel (§2.3).

use ocean_sao::SKY_Z;
use ocean_sao::pack::{
    MAX_KEY, SKY_KEY, decode_key, dequantise_ao, encode_key, pack, quantise_ao, texel_key,
};

const Z_MIN: f32 = -200.0;
const INV_Z_MIN: f32 = 1.0 / Z_MIN;

/// Every 16-bit key survives the trip through z and back exactly: key `q` stands for
/// `z = (q/65535)·z_min`, and encoding that z rounds to `q` (the rounding error of the products
/// is far below the ½ that would change it).
#[test]
fn keys_round_trip_exactly() {
    for q in 0..=MAX_KEY {
        let z = decode_key(q) * Z_MIN;
        assert_eq!(encode_key(z, INV_Z_MIN), q, "z = {z}");
        let t = pack(0.5, q);
        assert_eq!(texel_key(t), q);
    }
}

/// A key is `z/z_min` to within half a step of 1/65535 (plus the `f32` rounding of the
/// division): 1.5 mm at z_min = −200 m.
#[test]
fn keys_are_accurate() {
    for k in 0..=100_000 {
        let z = Z_MIN * k as f32 / 100_000.0;
        let key = f64::from(z) / f64::from(Z_MIN);
        let q = encode_key(z, INV_Z_MIN);
        let err = (f64::from(decode_key(q)) - key.min(f64::from(MAX_KEY) / 65535.0)).abs();
        assert!(
            err <= 0.5 / 65535.0 + 1e-7,
            "z {z}: key {key}, decoded {}",
            decode_key(q)
        );
    }
}

/// Background gets the reserved key; geometry beyond z_min saturates just below it; z ≥ 0 (only
/// behind an orthographic camera) and NaN map to 0.
#[test]
fn special_keys() {
    assert_eq!(encode_key(SKY_Z, INV_Z_MIN), SKY_KEY);
    assert_eq!(encode_key(-1.0e6, INV_Z_MIN), MAX_KEY);
    assert_eq!(encode_key(Z_MIN, INV_Z_MIN), MAX_KEY);
    assert_eq!(encode_key(0.5, INV_Z_MIN), 0);
    assert_eq!(encode_key(f32::NAN, INV_Z_MIN), 0);
}

/// The paper's literal split, `G = fix(256·key)/256` written to a UNORM8 channel, stores
/// `round(255·k/256)`: k = 128 and k = 129 both become 128, so the coarse byte cannot be decoded.
/// The byte split of this crate keeps every coarse value distinct.
#[test]
fn the_literal_split_collides_and_the_byte_split_does_not() {
    let literal = |k: u32| (255.0 * k as f32 / 256.0).round() as u8;
    assert_eq!(literal(128), literal(129));
    let hi = |k: u16| pack(0.0, k << 8)[1];
    assert_ne!(hi(128), hi(129));
    assert!((0..=255u16).all(|k| u16::from(hi(k)) == k));
}

/// A is stored as `round(255·A)`: 0 → 0, 1 → 255, ½ → 128; every byte survives the round trip;
/// values outside [0, 1] clamp.
#[test]
fn ao_bytes() {
    assert_eq!(quantise_ao(0.0), 0);
    assert_eq!(quantise_ao(1.0), 255);
    assert_eq!(quantise_ao(0.5), 128);
    assert_eq!(quantise_ao(-0.2), 0);
    assert_eq!(quantise_ao(7.0), 255);
    for a in 0..=255u8 {
        assert_eq!(quantise_ao(dequantise_ao(a)), a);
    }
    assert_eq!(pack(1.0, 0x1234), [255, 0x12, 0x34, 255]);
}
