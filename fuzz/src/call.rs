//! Small helpers shared by the operations: an out-parameter call checked in one line, and the
//! fuzzed variations of the library's default parameter structs.

use std::fmt::Debug;

use ocean::{OceanCamera, OceanDepthConvention, OceanStatus};

use crate::check;
use crate::cmem::{CMem, enum_below};
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

/// Replaces a flag one time in four by any [`Input::flag`].
pub fn tweak_flag(inp: &mut Input, v: &mut u32) {
    if inp.u8() % 4 == 3 {
        *v = inp.flag();
    }
}

/// A camera 10 m above the sea looking along -z: a perspective (60°, aspect 1.5, near 0.5,
/// far 500 or infinite) or an orthographic box, in one of the three depth conventions, built
/// as GLM builds them, then some elements, the convention and the reserved member fuzzed; or
/// 32 arbitrary doubles.
pub fn camera(inp: &mut Input) -> CMem<OceanCamera> {
    let mut c = OceanCamera {
        view: [
            1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, -10.0, 0.0, 1.0,
        ],
        ..OceanCamera::default()
    };
    if inp.u8() % 8 == 7 {
        c.view = std::array::from_fn(|_| inp.f64());
        c.projection = std::array::from_fn(|_| inp.f64());
    } else {
        c.depth_convention = enum_below::<OceanDepthConvention>(inp, 3);
        let convention = c.depth_convention as u32;
        let (n, far) = (0.5, if inp.bool() { f64::INFINITY } else { 500.0 });
        let p = &mut c.projection;
        if inp.u8() % 4 == 3 {
            // glm::ortho(-20, 20, -10, 10, n, 500): [-1, 1] or [0, 1] depth.
            let (l, r, b, t, f) = (-20.0, 20.0, -10.0, 10.0, 500.0);
            p[0] = 2.0 / (r - l);
            p[5] = 2.0 / (t - b);
            p[12] = -(r + l) / (r - l);
            p[13] = -(t + b) / (t - b);
            p[15] = 1.0;
            if convention == 2 {
                p[10] = -2.0 / (f - n);
                p[14] = -(f + n) / (f - n);
            } else {
                p[10] = -1.0 / (f - n);
                p[14] = -n / (f - n);
            }
        } else {
            let t = 30f64.to_radians().tan();
            p[0] = 1.0 / (1.5 * t);
            p[5] = 1.0 / t;
            p[11] = -1.0;
            let (a, b) = match (convention, far.is_finite()) {
                (0, true) => (far / (n - far), -(far * n) / (far - n)),
                (0, false) => (-1.0, -n),
                (1, true) => (n / (far - n), far * n / (far - n)),
                (1, false) => (0.0, n),
                (_, true) => (-(far + n) / (far - n), -2.0 * far * n / (far - n)),
                (_, false) => (-1.0, -2.0 * n),
            };
            p[10] = a;
            p[14] = b;
        }
        for v in c.view.iter_mut().chain(c.projection.iter_mut()) {
            if inp.u8() % 16 == 15 {
                tweak(inp, v);
            }
        }
    }
    tweak_u32(inp, &mut c.reserved);
    let mut c = CMem::new(c);
    c.tweak_u32(inp, std::mem::offset_of!(OceanCamera, depth_convention));
    c
}
