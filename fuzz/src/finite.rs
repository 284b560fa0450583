//! Whether every floating-point number of a C ABI output is finite (NaN and ±infinity are not).

use ocean::{
    OceanDVec2, OceanDVec3, OceanDrawnSample, OceanFrameStats, OceanHeightSample, OceanIrradiance,
    OceanReliefHit, OceanReliefPoint, OceanReliefRay, OceanRgb, OceanSaoInfo, OceanSeaLight,
    OceanSlopeVariance, OceanVec3, OceanWaveDesc,
};

/// Every float in it is finite.
pub trait Finite {
    fn is_finite(&self) -> bool;
}

impl Finite for f64 {
    fn is_finite(&self) -> bool {
        f64::is_finite(*self)
    }
}

impl Finite for f32 {
    fn is_finite(&self) -> bool {
        f32::is_finite(*self)
    }
}

/// Integers are always finite: lets integer outputs go through the same check as floats.
macro_rules! always_finite {
    ($($t:ty),*) => {$(
        impl Finite for $t {
            fn is_finite(&self) -> bool {
                true
            }
        }
    )*};
}
always_finite!(u8, u16, u32, usize);

impl<T: Finite> Finite for [T] {
    fn is_finite(&self) -> bool {
        self.iter().all(Finite::is_finite)
    }
}

impl<T: Finite, const N: usize> Finite for [T; N] {
    fn is_finite(&self) -> bool {
        self.iter().all(Finite::is_finite)
    }
}

impl<T: Finite + ?Sized> Finite for &T {
    fn is_finite(&self) -> bool {
        (**self).is_finite()
    }
}

impl<T: Finite> Finite for Vec<T> {
    fn is_finite(&self) -> bool {
        self.as_slice().is_finite()
    }
}

impl<A: Finite, B: Finite> Finite for (A, B) {
    fn is_finite(&self) -> bool {
        self.0.is_finite() && self.1.is_finite()
    }
}

/// Structs whose fields are all checked: `name { field, ... }`.
macro_rules! finite_fields {
    ($($t:ty { $($f:ident),* })*) => {$(
        impl Finite for $t {
            fn is_finite(&self) -> bool {
                true $(&& self.$f.is_finite())*
            }
        }
    )*};
}

finite_fields! {
    OceanVec3 { x, y, z }
    OceanDVec2 { x, z }
    OceanDVec3 { x, y, z }
    OceanRgb { r, g, b }
    OceanIrradiance { k }
    OceanSeaLight { sun, sky, sea }
    OceanSlopeVariance { sigma_x2, sigma_y2 }
    OceanDrawnSample { height, normal, shading_normal, rest, weights }
    OceanHeightSample { height, normal, rest, residual }
    OceanReliefPoint { u, v, depth }
    OceanReliefHit { pos }
    OceanReliefRay { start_u, start_v, dir_x, dir_y, dir_z }
    OceanFrameStats { estimated_seconds, filtered_slope_variance }
}

/// A depth or a distance that include/ocean.h allows to be `INFINITY` (deep water, an infinite
/// far plane): finite or +infinity, never NaN nor -infinity.
fn finite_or_plus_infinity(v: f64) -> bool {
    v.is_finite() || v == f64::INFINITY
}

impl Finite for OceanWaveDesc {
    fn is_finite(&self) -> bool {
        [
            self.amplitude,
            self.wavelength,
            self.direction_x,
            self.direction_z,
            self.phase,
        ]
        .is_finite()
            && finite_or_plus_infinity(self.depth)
    }
}

impl Finite for OceanSaoInfo {
    fn is_finite(&self) -> bool {
        [self.near].is_finite()
            && finite_or_plus_infinity(self.far)
            && [
                self.z_constants[0],
                self.z_constants[1],
                self.z_constants[2],
                self.z_constants[3],
                self.near_depth,
                self.far_depth,
                self.pixels_per_metre,
            ]
            .is_finite()
    }
}

/// A binary16 bit pattern (the F16 cone encoding) is finite unless its exponent is all ones.
pub fn half_is_finite(bits: u16) -> bool {
    bits & 0x7c00 != 0x7c00
}
