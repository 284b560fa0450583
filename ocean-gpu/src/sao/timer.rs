//! GPU timestamps around each of the SAO passes (the paper's Table 2 and 3 break the time down
//! the same way).

use crate::readback::{GpuDuration, GpuTimer};
use crate::{GpuContext, GpuError};

/// One of the five passes of the paper, in order. Each is one compute pass (the MIP levels one
/// dispatch per level inside a single pass).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SaoStage {
    /// z from depth (Eq. 2) into level 0.
    Z,
    /// The z MIP levels (Table 1).
    Mips,
    /// The sample pass with the quad bilateral and the packing (§2.3).
    Ao,
    /// The horizontal blur (§2.4).
    BlurHorizontal,
    /// The vertical blur (§2.4), writing the final A.
    BlurVertical,
}

impl SaoStage {
    /// Every pass, in execution order.
    pub const ALL: [Self; 5] = [
        Self::Z,
        Self::Mips,
        Self::Ao,
        Self::BlurHorizontal,
        Self::BlurVertical,
    ];

    /// A short name for reports: `z`, `mips`, `ao`, `blur_h`, `blur_v`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Z => "z",
            Self::Mips => "mips",
            Self::Ao => "ao",
            Self::BlurHorizontal => "blur_h",
            Self::BlurVertical => "blur_v",
        }
    }

    fn index(self) -> usize {
        match self {
            Self::Z => 0,
            Self::Mips => 1,
            Self::Ao => 2,
            Self::BlurHorizontal => 3,
            Self::BlurVertical => 4,
        }
    }
}

/// A [`GpuTimer`] per pass, for [`crate::SaoPass::encode`].
///
/// Use: pass it to `encode`, call [`SaoTimer::resolve`] on the same encoder afterwards, submit,
/// then [`SaoTimer::read`].
#[derive(Debug)]
pub struct SaoTimer {
    timers: [GpuTimer; 5],
}

/// The GPU time of each pass of one run (`None` where the counter went backwards).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SaoTimes {
    times: [Option<GpuDuration>; 5],
}

impl SaoTimes {
    /// The time of `stage`.
    pub fn get(&self, stage: SaoStage) -> Option<GpuDuration> {
        self.times[stage.index()]
    }

    /// The sum over the passes, when every pass has a time.
    pub fn total(&self) -> Option<GpuDuration> {
        let mut ns = 0.0;
        for t in &self.times {
            ns += (*t)?.ns;
        }
        Some(GpuDuration { ns })
    }
}

impl SaoTimer {
    /// Timers for the five passes, or `None` when the device cannot write timestamps
    /// ([`GpuContext::supports_timestamps`]).
    pub fn new(ctx: &GpuContext) -> Option<Self> {
        Some(Self {
            timers: [
                GpuTimer::new(ctx)?,
                GpuTimer::new(ctx)?,
                GpuTimer::new(ctx)?,
                GpuTimer::new(ctx)?,
                GpuTimer::new(ctx)?,
            ],
        })
    }

    /// The timer of one pass.
    pub fn stage(&self, stage: SaoStage) -> &GpuTimer {
        &self.timers[stage.index()]
    }

    /// Records the copy of every pass's timestamps; call after `encode` on the same encoder.
    pub fn resolve(&self, encoder: &mut wgpu::CommandEncoder) {
        for t in &self.timers {
            t.resolve(encoder);
        }
    }

    /// Every pass's GPU time, after the resolving submission (waits for it).
    pub fn read(&self, ctx: &GpuContext) -> Result<SaoTimes, GpuError> {
        let mut times = [None; 5];
        for (t, timer) in times.iter_mut().zip(&self.timers) {
            *t = timer.read(ctx)?;
        }
        Ok(SaoTimes { times })
    }
}
