//! `f64` functions that `core` lacks, from `libm` when that feature is on, else from `std`.
//!
//! With the `libm` feature the results are the same on every platform; `std` forwards to the
//! platform's C library, whose last bit may differ between platforms for `tanh` and friends
//! (`sqrt` is correctly rounded either way).

// The names say what each computes; only the provider differs.
#[cfg(feature = "libm")]
#[allow(missing_docs)]
mod imp {
    pub fn tanh(x: f64) -> f64 {
        libm::tanh(x)
    }
    pub fn sin(x: f64) -> f64 {
        libm::sin(x)
    }
    pub fn cos(x: f64) -> f64 {
        libm::cos(x)
    }
    pub fn tan(x: f64) -> f64 {
        libm::tan(x)
    }
    pub fn atan2(y: f64, x: f64) -> f64 {
        libm::atan2(y, x)
    }
    pub fn acos(x: f64) -> f64 {
        libm::acos(x)
    }
}

#[cfg(all(feature = "std", not(feature = "libm")))]
#[allow(missing_docs)]
mod imp {
    pub fn tanh(x: f64) -> f64 {
        x.tanh()
    }
    pub fn sin(x: f64) -> f64 {
        x.sin()
    }
    pub fn cos(x: f64) -> f64 {
        x.cos()
    }
    pub fn tan(x: f64) -> f64 {
        x.tan()
    }
    pub fn atan2(y: f64, x: f64) -> f64 {
        y.atan2(x)
    }
    pub fn acos(x: f64) -> f64 {
        x.acos()
    }
}

pub use imp::*;

/// Square root, correctly rounded (IEEE-754) whichever implementation serves it; `std`'s is
/// preferred because LLVM vectorises it.
#[cfg(feature = "std")]
#[inline(always)]
pub fn sqrt(x: f64) -> f64 {
    x.sqrt()
}

/// `f32` square root, correctly rounded.
#[cfg(feature = "std")]
#[inline(always)]
pub fn sqrtf(x: f32) -> f32 {
    x.sqrt()
}

/// Square root, correctly rounded.
#[cfg(not(feature = "std"))]
#[inline(always)]
pub fn sqrt(x: f64) -> f64 {
    libm::sqrt(x)
}

/// `f32` square root, correctly rounded.
#[cfg(not(feature = "std"))]
#[inline(always)]
pub fn sqrtf(x: f32) -> f32 {
    libm::sqrtf(x)
}

/// The largest whole number ≤ `x`, exact whichever implementation serves it.
#[cfg(feature = "std")]
#[inline(always)]
pub fn floor(x: f64) -> f64 {
    x.floor()
}

/// The largest whole number ≤ `x`, exact.
#[cfg(not(feature = "std"))]
#[inline(always)]
pub fn floor(x: f64) -> f64 {
    libm::floor(x)
}

/// w(a, b, x) = 3x̄² − 2x̄³ with x̄ = clamp((x − a)/(b − a), 0, 1): 0 up to a, 1 from b, C¹
/// between. The per-wave filter weight of Bruneton, Neyret & Holzschuch §3.2, which both the
/// lighting paper's ocean and the wave-train-box grids filter their waves with.
#[inline]
pub fn smooth_weight(a: f64, b: f64, x: f64) -> f64 {
    let t = ((x - a) / (b - a)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}
