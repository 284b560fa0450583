//! Directed rounding from `f64` to `f32`: cone ratios are computed in `f64` and stored in
//! `f32` rounded towards the valid side (down for a cone, up for the rise that limits one).

/// `x` rounded down to `f32`.
pub(crate) fn down32(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) > x { f.next_down() } else { f }
}

/// `x` rounded up to `f32`.
pub(crate) fn up32(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) < x { f.next_up() } else { f }
}
