//! Numbers from C: finiteness checks and how numbers are printed in messages.

pub(crate) use ocean_core::Num;

use crate::status::{Error, OceanStatus};

/// `OCEAN_STATUS_NON_FINITE` unless `time` is finite seconds.
pub(crate) fn check_time(time: f64) -> Result<(), Error> {
    if time.is_finite() {
        Ok(())
    } else {
        Err(Error::new(
            OceanStatus::NonFinite,
            format!("`time` must be finite seconds, got {}", Num(time)),
        ))
    }
}

/// `OCEAN_STATUS_NON_FINITE` naming the first of `fields` that is NaN or infinite, as
/// `{prefix}{name}`.
/// A flag member: every flag of the header is a `uint32_t` that must be 0 or 1 (a `uint32_t`
/// and not C's `bool` or a byte, so structs hold no padding the caller cannot see and Rust
/// never reads a `bool` the caller filled with another value).
pub(crate) fn check_flag(name: &str, v: u32) -> Result<bool, Error> {
    match v {
        0 => Ok(false),
        1 => Ok(true),
        _ => Err(Error::new(
            OceanStatus::InvalidArgument,
            format!("{name} must be 0 or 1, got {v}"),
        )),
    }
}

/// A `reserved` member, which must be 0: so that a later version can give it a meaning without
/// misreading what an older caller left there.
pub(crate) fn check_reserved(name: &str, v: u32) -> Result<(), Error> {
    if v == 0 {
        Ok(())
    } else {
        Err(Error::new(
            OceanStatus::InvalidArgument,
            format!("{name} must be 0, got {v}"),
        ))
    }
}

pub(crate) fn check_finite(prefix: &str, fields: &[(&str, f64)]) -> Result<(), Error> {
    match fields.iter().find(|(_, v)| !v.is_finite()) {
        Some((name, v)) => Err(Error::new(
            OceanStatus::NonFinite,
            format!("{prefix}{name} must be finite, got {}", Num(*v)),
        )),
        None => Ok(()),
    }
}

/// A derived number (a limit, a product) as messages print it: six significant digits, then as
/// [`Num`].
#[derive(Clone, Copy, Debug)]
pub(crate) struct Approx(pub f64);

impl core::fmt::Display for Approx {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let rounded: f64 = format!("{:.5e}", self.0).parse().unwrap_or(self.0);
        Num(rounded).fmt(f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn derived_numbers_print_six_digits() {
        assert_eq!(Approx(569626991516026.3).to_string(), "5.69627e14");
        assert_eq!(Approx(1.7555347883683727).to_string(), "1.75553");
        assert_eq!(Approx(f64::INFINITY).to_string(), "inf");
    }
}
