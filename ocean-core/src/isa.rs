//! Which instruction set the `f32` grid kernels run on.
//!
//! The layers kernel (wave train boxes) and the plain trochoid grid kernel
//! ([`WaveSet::evaluate_grid`](crate::WaveSet::evaluate_grid)) run on [`Isa::best`]. The
//! scattered-points kernel stays with LLVM's vectorisation for AVX2.
//!
//! Every instruction set performs, lane by lane, the same IEEE operations in the same order,
//! with no fused multiply-add, so the output is bit-identical whichever runs: a machine with
//! AVX-512 and one without agree to the last bit (networked games depend on it). The choice
//! only changes speed. [`Isa::best`] is what the evaluators use;
//! [`evaluate_layers_isa`](crate::evaluate_layers_isa) forces one, for tests and benchmarks.

/// An instruction set for the layers and grid kernels.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Isa {
    /// Element-wise loops that LLVM vectorises for the compilation target (SSE2 on x86-64,
    /// NEON on AArch64): available everywhere.
    Portable,
    /// x86-64 with AVX2 (pulp's `V3`): kernels written with intrinsics, one 8-lane vector a
    /// half chunk.
    Avx2,
    /// x86-64 with AVX-512 F/BW/CD/DQ/VL (pulp's `V4`): a kernel written with intrinsics, one
    /// 16-lane vector a chunk.
    Avx512,
}

impl Isa {
    /// Every instruction set, slowest first.
    pub const ALL: [Isa; 3] = [Isa::Portable, Isa::Avx2, Isa::Avx512];

    /// Whether this CPU (and this build's target) can run `self`.
    pub fn is_available(self) -> bool {
        match self {
            Isa::Portable => true,
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2 => pulp::x86::V3::is_available(),
            #[cfg(target_arch = "x86_64")]
            Isa::Avx512 => pulp::x86::V4::is_available(),
            #[cfg(not(target_arch = "x86_64"))]
            Isa::Avx2 | Isa::Avx512 => false,
        }
    }

    /// The fastest instruction set available.
    pub fn best() -> Isa {
        Isa::ALL
            .into_iter()
            .rev()
            .find(|i| i.is_available())
            .unwrap_or(Isa::Portable)
    }
}

/// An available [`Isa`] with its token: what the layers kernel dispatches on.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Kernel {
    Portable,
    #[cfg(target_arch = "x86_64")]
    Avx2(pulp::x86::V3),
    #[cfg(target_arch = "x86_64")]
    Avx512(pulp::x86::V4),
}

impl Kernel {
    /// The kernel of [`Isa::best`].
    pub(crate) fn best() -> Kernel {
        Kernel::new(Isa::best()).unwrap_or(Kernel::Portable)
    }

    /// The kernel for `isa`, or `None` if this CPU cannot run it.
    pub(crate) fn new(isa: Isa) -> Option<Kernel> {
        match isa {
            Isa::Portable => Some(Kernel::Portable),
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2 => pulp::x86::V3::try_new().map(Kernel::Avx2),
            #[cfg(target_arch = "x86_64")]
            Isa::Avx512 => pulp::x86::V4::try_new().map(Kernel::Avx512),
            #[cfg(not(target_arch = "x86_64"))]
            Isa::Avx2 | Isa::Avx512 => None,
        }
    }
}
