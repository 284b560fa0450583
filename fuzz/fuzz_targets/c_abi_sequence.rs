//! `c_abi_sequence`: the input is a program of C ABI calls (waves, spectra, lightings, sky
//! maps, wave train box scenes, relief maps and cones, SAO, the sea colour), made through the
//! `ocean` crate (ocean-ffi) on a table of live handles; the invariants of `src/check.rs` hold
//! after every call. See `src/sequence.rs`.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| ocean_fuzz::sequence::c_abi_sequence(data));
