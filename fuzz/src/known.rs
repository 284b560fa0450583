//! Non-finite outputs already found and reported, skipped so that a campaign can go past them.
//! Each entry names the function, says when it happens and how to reproduce it; remove the
//! entry when the library is fixed. FUZZING.md lists them too.

use std::any::Any;
use std::fmt::Debug;

/// The inputs of a checked call, as passed to `check::outputs`: printable, and typed, so that
/// an entry below can recognise its case.
pub trait Args: Debug + Any {}
impl<T: Debug + Any> Args for T {}

/// One known case of a successful call with a non-finite output.
pub struct Known {
    /// The C ABI function.
    pub function: &'static str,
    /// Whether `inputs` (the tuple the call site passes) is this case.
    pub matches: fn(&dyn Any) -> bool,
    /// What goes wrong, and a reproducing input.
    pub note: &'static str,
}

/// The known non-finite cases: none yet.
pub const KNOWN_NON_FINITE: &[Known] = &[];

/// Whether the non-finite output of `function` for `inputs` is a known case.
pub fn known_non_finite(function: &str, inputs: &dyn Args) -> bool {
    let inputs: &dyn Any = inputs;
    KNOWN_NON_FINITE
        .iter()
        .any(|k| k.function == function && (k.matches)(inputs))
}
