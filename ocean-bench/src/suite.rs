//! The suites of `ocean bench`: which there are, their names, and running and printing each.

use serde_json::Value;

use crate::gerstner;
use crate::options::BenchOptions;

/// A benchmark suite.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Suite {
    /// The trochoid (Gerstner) wave sum on a grid: CPU single-thread, all threads, GPU.
    Gerstner,
    /// Wave train boxes: scenario 1 from 64² to 2048², scaling, culling, effect
    /// costs, height queries.
    Wtb,
    /// Ocean lighting: CPU sea-colour evaluations and the paper's validation
    /// (Fig. 10) against a detailed-geometry reference.
    Lighting,
    /// Scalable ambient obscurance: GPU time against the radius, with and without the z
    /// hierarchy, per pass at four resolutions with guard bands, and the CPU reference.
    Sao,
    /// Relief mapping: relaxed cone-map generation at 256², 512² and 1024², the
    /// brute-force oracle at 128², progress overhead, GPU generation, CPU tracer rays per second
    /// per method, the level of detail's draw time and shimmer on the GPU, and the accuracy
    /// table.
    Relief,
    /// The C ABI's cost per call against the Rust call it wraps (batches of 1024: the wave sum,
    /// the scene's height query, the sea colour) and of an empty crossing (handle checks).
    Ffi,
    /// Every suite above in turn; with `--json`, one document holding each suite's report with
    /// the date and the machine.
    All,
}

impl Suite {
    /// Every suite, in the order of `ocean bench all`.
    pub const ALL: [Suite; 6] = [
        Suite::Gerstner,
        Suite::Wtb,
        Suite::Lighting,
        Suite::Sao,
        Suite::Relief,
        Suite::Ffi,
    ];

    /// Its name on the command line and in JSON reports.
    pub fn name(self) -> &'static str {
        match self {
            Suite::Gerstner => "gerstner",
            Suite::Wtb => "wtb",
            Suite::Lighting => "lighting",
            Suite::Sao => "sao",
            Suite::Relief => "relief",
            Suite::Ffi => "ffi",
            Suite::All => "all",
        }
    }

    /// Runs the suite and returns its report.
    ///
    /// # Errors
    ///
    /// A message for a measurement that cannot be made (a device that fails), or for `All`.
    pub fn report(self, args: &BenchOptions) -> Result<Value, String> {
        match self {
            Suite::Gerstner => gerstner::gerstner(args),
            Suite::Wtb => crate::wtb::wtb(args),
            Suite::Lighting => crate::lighting::lighting(args),
            Suite::Sao => crate::sao::sao(args),
            Suite::Relief => crate::relief::relief(args),
            Suite::Ffi => crate::ffi::ffi(args),
            Suite::All => Err("`all` is not one suite".to_owned()),
        }
    }

    /// Prints a report of this suite as tables.
    pub fn print(self, doc: &Value) {
        match self {
            Suite::Gerstner => gerstner::print(doc),
            Suite::Wtb => crate::wtb::print(doc),
            Suite::Lighting => crate::lighting::print(doc),
            Suite::Sao => crate::sao::print(doc),
            Suite::Relief => crate::relief::print(doc),
            Suite::Ffi => crate::ffi::print(doc),
            Suite::All => {}
        }
    }
}
