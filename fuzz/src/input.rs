//! The fuzz input read as a stream of choices. Every read succeeds: past the end of the data it
//! yields zeros, so any byte string is a valid program and libFuzzer's mutations stay cheap.
//!
//! Floats are drawn half of the time from a table of values that break numerical code (NaN,
//! infinities, -0, subnormals, the extremes of f32 and f64, values just off 0 and 1), otherwise
//! from small "ordinary" values or raw bits, so that both the checks and the arithmetic behind
//! them are reached.
//!
//! Zero bytes choose the ordinary case everywhere (a typical value, the full buffer length, the
//! first handle), so a hand-written seed is a few operation bytes padded with zeros.

/// A cursor over the fuzz input.
pub struct Input<'a> {
    data: &'a [u8],
    at: usize,
}

/// Values at which floating-point code tends to go wrong.
const SPECIAL_F64: [f64; 32] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    0.5,
    2.0,
    10.0,
    100.0,
    1e-3,
    1e-6,
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    1e300,
    -1e300,
    f64::MAX,
    f64::MIN,
    f64::MIN_POSITIVE,
    5e-324,
    -5e-324,
    f32::MAX as f64,
    -(f32::MAX as f64),
    f32::MIN_POSITIVE as f64,
    1e-45,
    1e38,
    1e-300,
    1.0 + f64::EPSILON,
    1.0 - f64::EPSILON / 2.0,
    0.999_999,
    1e6,
    -1e6,
    std::f64::consts::PI,
];

/// The same for f32 (the C ABI's rays, SAO parameters, relief heights).
const SPECIAL_F32: [f32; 24] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    0.5,
    2.0,
    10.0,
    1e-3,
    1e-6,
    f32::NAN,
    f32::INFINITY,
    f32::NEG_INFINITY,
    f32::MAX,
    f32::MIN,
    f32::MIN_POSITIVE,
    1e-45,
    -1e-45,
    1e38,
    -1e38,
    1.0 + f32::EPSILON,
    1.0 - f32::EPSILON / 2.0,
    64.0,
    65504.0,
    1e6,
];

impl<'a> Input<'a> {
    /// A reader at the start of `data`.
    pub fn new(data: &'a [u8]) -> Self {
        Self { data, at: 0 }
    }

    /// Whether every byte has been read.
    pub fn is_empty(&self) -> bool {
        self.at >= self.data.len()
    }

    /// The next byte, 0 past the end.
    pub fn u8(&mut self) -> u8 {
        let b = self.data.get(self.at).copied().unwrap_or(0);
        self.at += 1;
        b
    }

    /// The next `N` bytes, zero-filled past the end.
    pub fn bytes<const N: usize>(&mut self) -> [u8; N] {
        let mut b = [0; N];
        for x in &mut b {
            *x = self.u8();
        }
        b
    }

    /// A flag: the low bit of the next byte.
    pub fn bool(&mut self) -> bool {
        self.u8() & 1 == 1
    }

    /// A value in `0..=max`.
    pub fn upto(&mut self, max: usize) -> usize {
        let raw = u16::from_le_bytes(self.bytes::<2>()) as usize;
        raw % (max + 1)
    }

    /// Any u32, a small one (0..=16) half of the time: most u32 parameters are enums, flags or
    /// counts whose interesting values are small.
    pub fn u32(&mut self) -> u32 {
        match self.u8() % 4 {
            0 | 1 => u32::from(self.u8() % 17),
            2 => [u32::MAX, u32::MAX - 1, 1 << 31, 1 << 16, 255, 256][self.upto(5)],
            _ => u32::from_le_bytes(self.bytes()),
        }
    }

    /// Any u64 (seeds).
    pub fn u64(&mut self) -> u64 {
        u64::from_le_bytes(self.bytes())
    }

    /// A flag member of the C ABI (a uint32_t): 0 or 1 mostly, sometimes another value (which the
    /// library must refuse).
    pub fn flag(&mut self) -> u32 {
        u32::from(match self.u8() {
            b @ 0..=250 => b & 1,
            b => b,
        })
    }

    /// A float: special, ordinary (a small multiple of 1/8 in [-16, 16)) or raw bits.
    pub fn f64(&mut self) -> f64 {
        match self.u8() % 8 {
            0..=3 => SPECIAL_F64[self.upto(SPECIAL_F64.len() - 1)],
            4..=6 => f64::from(self.u8() as i8) / 8.0,
            _ => f64::from_le_bytes(self.bytes()),
        }
    }

    /// A float near `typical` (scaled by a factor in [0, 2), 1 for a zero byte) three times out
    /// of four, else any [`Input::f64`]: keeps parameters mostly in range so that evaluation,
    /// not only validation, runs.
    pub fn f64_near(&mut self, typical: f64) -> f64 {
        if self.u8() % 4 == 3 {
            self.f64()
        } else {
            typical * (1.0 + f64::from(self.u8() as i8) / 128.0)
        }
    }

    /// An f32, as [`Input::f64`].
    pub fn f32(&mut self) -> f32 {
        match self.u8() % 8 {
            0..=3 => SPECIAL_F32[self.upto(SPECIAL_F32.len() - 1)],
            4..=6 => f32::from(self.u8() as i8) / 8.0,
            _ => f32::from_le_bytes(self.bytes()),
        }
    }

    /// An f32 near `typical`, as [`Input::f64_near`].
    pub fn f32_near(&mut self, typical: f32) -> f32 {
        if self.u8() % 4 == 3 {
            self.f32()
        } else {
            typical * (1.0 + f32::from(self.u8() as i8) / 128.0)
        }
    }

    /// A length to pass with a buffer of `capacity` elements: the capacity itself most of the
    /// time, else anything from 0 to it. Never larger: the library cannot know the size of the
    /// caller's buffer, so a larger length would be the harness's bug, not the library's.
    pub fn len_within(&mut self, capacity: usize) -> usize {
        if self.u8() % 4 == 3 {
            self.upto(capacity)
        } else {
            capacity
        }
    }
}
