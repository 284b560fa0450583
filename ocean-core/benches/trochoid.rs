//! Trochoid wave-sum benchmarks.
fn main() {}
