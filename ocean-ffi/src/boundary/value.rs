//! Numbers from C: finiteness checks and how numbers are printed in messages.

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

/// A number as messages print it: the shortest text that reads back as the same value, in
/// scientific notation outside [1e-4, 1e7) so that 5e-324 or 1e300 stay short. For the
/// caller's own inputs, which a message must show exactly.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Num<T>(pub T);

impl<T> core::fmt::Display for Num<T>
where
    T: Copy + core::fmt::Display + core::fmt::LowerExp + Into<f64>,
{
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let x: f64 = self.0.into();
        let a = x.abs();
        if x == 0.0 || !x.is_finite() || (1e-4..1e7).contains(&a) {
            write!(f, "{}", self.0)
        } else {
            write!(f, "{:e}", self.0)
        }
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
    fn numbers_print_briefly_and_read_back_exactly() {
        let cases: [(f64, &str); 10] = [
            (5e-324, "5e-324"),
            (1e300, "1e300"),
            (f64::MAX, "1.7976931348623157e308"),
            (0.25, "0.25"),
            (-0.0, "-0"),
            (1e-5, "1e-5"),
            (123456.5, "123456.5"),
            (1e15, "1e15"),
            (f64::NAN, "NaN"),
            (f64::NEG_INFINITY, "-inf"),
        ];
        for (x, text) in cases {
            assert_eq!(Num(x).to_string(), text);
            if x.is_finite() {
                assert_eq!(text.parse::<f64>().unwrap(), x);
            }
        }
        // f32 values print as f32, not as their f64 widening (0.1f32 is not 0.10000000149...).
        assert_eq!(Num(0.1f32).to_string(), "0.1");
        assert_eq!(Num(f32::MAX).to_string(), "3.4028235e38");
        assert_eq!(Num(1e-12f32).to_string(), "1e-12");
        assert_eq!(Approx(569626991516026.3).to_string(), "5.69627e14");
        assert_eq!(Approx(1.7555347883683727).to_string(), "1.75553");
        assert_eq!(Approx(f64::INFINITY).to_string(), "inf");
    }
}
