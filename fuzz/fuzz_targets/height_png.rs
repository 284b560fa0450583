//! `height_png`: the height-map PNG reader of `ocean cone-map` (`decode_heights` in
//! ocean-cli/src/cone_map.rs) on bytes in memory. Invariants: no panic, a bad file is an
//! `Err(String)`, and a success is a square of `side²` heights within the supported sides. Huge
//! allocations from small inputs are caught by libFuzzer's `-malloc_limit_mb` (FUZZING.md).
#![no_main]

use libfuzzer_sys::fuzz_target;
use ocean_cli::cone_map::{Heights, decode_heights};

fuzz_target!(|data: &[u8]| {
    let Ok(image) = decode_heights(std::io::Cursor::new(data), "fuzz.png") else {
        return;
    };
    let n = match &image.heights {
        Heights::U8(v) => v.len(),
        Heights::U16(v) => v.len(),
    };
    assert_eq!(n, image.side * image.side, "a decoded height map is square");
    assert!((2..=ocean_relief::MAX_SIDE).contains(&image.side));
});
