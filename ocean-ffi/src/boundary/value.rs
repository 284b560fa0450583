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
