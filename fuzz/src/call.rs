//! Small helpers shared by the operations: an out-parameter call checked in one line, and the
//! fuzzed variations of the library's default parameter structs.

use std::fmt::Debug;

use ocean::OceanStatus;

use crate::check;
use crate::finite::Finite;
use crate::input::Input;
use crate::known::Args;

/// Calls `f` with a pointer to a default `T`, checks the status and, on success, that the
/// output is finite; returns it on success.
pub fn query<T: Default + Finite + Debug>(
    function: &str,
    inputs: &dyn Args,
    f: impl FnOnce(*mut T) -> OceanStatus,
) -> Option<T> {
    let mut out = T::default();
    let st = f(&mut out);
    check::outputs(function, inputs, st, &out).then_some(out)
}

/// Replaces `v` one time in four: by any float half of those times, else by `v` scaled by a
/// factor in [0, 2) (a value still in range, mostly). A zero byte keeps `v`, so that a
/// hand-written seed of zeros means the defaults.
pub fn tweak(inp: &mut Input, v: &mut f64) {
    match inp.u8() % 8 {
        6 => *v = inp.f64(),
        7 => *v *= f64::from(inp.u8()) / 128.0,
        _ => {}
    }
}

/// [`tweak`] for f32.
pub fn tweak32(inp: &mut Input, v: &mut f32) {
    match inp.u8() % 8 {
        6 => *v = inp.f32(),
        7 => *v *= f32::from(inp.u8()) / 128.0,
        _ => {}
    }
}

/// Replaces a u32 (an enum, a count) one time in four by any [`Input::u32`].
pub fn tweak_u32(inp: &mut Input, v: &mut u32) {
    if inp.u8() % 4 == 3 {
        *v = inp.u32();
    }
}

/// Replaces a u8 flag one time in four by any [`Input::flag`].
pub fn tweak_flag(inp: &mut Input, v: &mut u32) {
    if inp.u8() % 4 == 3 {
        *v = inp.flag();
    }
}

/// A column-major 4x4 f32 matrix: a plausible perspective * view (the default camera of the
/// tests) with some elements replaced, or 16 arbitrary floats.
pub fn matrix_f32(inp: &mut Input) -> [f32; 16] {
    if inp.u8() % 4 == 3 {
        return std::array::from_fn(|_| inp.f32());
    }
    // A perspective projection (60°, aspect 1.5, near 0.5, far 500) of a camera 10 m up
    // looking down -z; column-major.
    let f = 1.0 / (30f32.to_radians()).tan();
    let (n, fa) = (0.5f32, 500.0f32);
    let mut m = [
        f / 1.5,
        0.0,
        0.0,
        0.0,
        0.0,
        f,
        0.0,
        0.0,
        0.0,
        0.0,
        fa / (n - fa),
        -1.0,
        0.0,
        -10.0 * f,
        n * fa / (n - fa),
        0.0,
    ];
    for v in &mut m {
        tweak32(inp, v);
    }
    m
}
