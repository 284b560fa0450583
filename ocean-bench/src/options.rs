//! What every suite of `ocean bench` reads.

/// What every suite reads: sizes, repetitions, whether to measure on the GPU, where to plot.
#[derive(Clone, Debug)]
#[cfg_attr(feature = "clap", derive(clap::Args))]
pub struct BenchOptions {
    /// Grid side length (points per side; `gerstner` only).
    #[cfg_attr(feature = "clap", arg(long, default_value_t = 1024, value_parser = clap::value_parser!(u32).range(8..=8192)))]
    pub size: u32,
    /// Timed repetitions per figure (the median is reported).
    #[cfg_attr(feature = "clap", arg(long, default_value_t = 15, value_parser = clap::value_parser!(u32).range(1..=1000)))]
    pub runs: u32,
    /// Skip the GPU figures.
    #[cfg_attr(feature = "clap", arg(long))]
    pub no_gpu: bool,
    /// `lighting` only: draw the validation's per-row curves (Fig. 10) into this PNG file.
    #[cfg_attr(feature = "clap", arg(long))]
    pub plot: Option<std::path::PathBuf>,
}

impl Default for BenchOptions {
    /// A 1024² grid, 15 timed rounds per figure, the GPU figures, no plot: what `ocean bench`
    /// runs without options.
    fn default() -> Self {
        Self {
            size: 1024,
            runs: 15,
            no_gpu: false,
            plot: None,
        }
    }
}
