//! How every crate's messages print a number.

use core::fmt;

/// A number as messages print it: the shortest text that reads back as the same value, in
/// scientific notation outside [1e-4, 1e7), so that 5e-324 or 1e300 stay a few characters long
/// (plain `{}` prints 5e-324 with 324 digits). `f32` values print as `f32` (0.1, not
/// 0.10000000149011612).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Num<T>(pub T);

impl<T> fmt::Display for Num<T>
where
    T: Copy + fmt::Display + fmt::LowerExp + Into<f64>,
{
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x: f64 = self.0.into();
        let a = if x < 0.0 { -x } else { x };
        if x == 0.0 || !x.is_finite() || (1e-4..1e7).contains(&a) {
            write!(f, "{}", self.0)
        } else {
            write!(f, "{:e}", self.0)
        }
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::string::ToString;

    #[test]
    fn numbers_print_briefly_and_read_back_exactly() {
        let cases: [(f64, &str); 11] = [
            (5e-324, "5e-324"),
            (1e300, "1e300"),
            (f64::MAX, "1.7976931348623157e308"),
            (0.25, "0.25"),
            (-0.0, "-0"),
            (1e-5, "1e-5"),
            (123456.5, "123456.5"),
            (1e15, "1e15"),
            (-2.5e9, "-2.5e9"),
            (f64::NAN, "NaN"),
            (f64::NEG_INFINITY, "-inf"),
        ];
        for (x, text) in cases {
            assert_eq!(Num(x).to_string(), text);
            if x.is_finite() {
                assert_eq!(text.parse::<f64>().unwrap(), x);
            }
        }
        assert_eq!(Num(0.1f32).to_string(), "0.1");
        assert_eq!(Num(f32::MAX).to_string(), "3.4028235e38");
        assert_eq!(Num(1e-12f32).to_string(), "1e-12");
        assert_eq!(Num(7u32).to_string(), "7");
    }
}
