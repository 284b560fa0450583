//! # ocean-bench
//!
//! The benchmark suites of `ocean bench` as a library: each technique's figures (BENCHMARKS.md)
//! measured on the scenes of the crates that own them (`ocean_wtb::scenarios`, the built-in
//! scene of `ocean_scene`), every ratio against a baseline measured in the same run. A suite
//! returns its report as JSON ([`Suite::report`]) and prints it as tables ([`Suite::print`]);
//! the command line adds argument parsing, interruption and the `all` document.
#![forbid(unsafe_code)]

pub mod ffi;
pub mod gerstner;
pub mod gpu;
pub mod lighting;
pub mod options;
pub mod plot;
pub mod relief;
pub mod relief_family;
pub mod sao;
pub mod suite;
pub mod timing;
pub mod wtb;

pub use options::BenchOptions;
pub use suite::Suite;
