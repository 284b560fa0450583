//! `cone_params`: a small height map, then cone-map generation (relaxed, conservative,
//! quad-directional, encoded, quantised, mips) with fuzzed parameters and progress
//! cancellation, and rays and shadow tests traced through the result, all through the C ABI,
//! with the invariants of `src/check.rs`. See `src/sequence.rs`.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| ocean_fuzz::sequence::cone_params(data));
