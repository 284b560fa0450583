//! The range checks of a scene description's values. A failed check is the key and why; the
//! description adds the line ([`crate::description::SceneDescription::parse`]).

/// A value out of range: its key (`section.key`) and why, with the value.
pub type Bad = (&'static str, String);

/// Fails unless `v` is finite and in `[min, max]`.
pub(crate) fn range(key: &'static str, v: f64, min: f64, max: f64) -> Result<(), Bad> {
    if v.is_finite() && (min..=max).contains(&v) {
        Ok(())
    } else {
        Err((key, format!("= {v} is outside [{min}, {max}]")))
    }
}
