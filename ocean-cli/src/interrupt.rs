//! Interruption: Ctrl-C (SIGINT), SIGTERM and SIGHUP ask a running job to stop instead of
//! killing the process, so it can remove its temporary files and leave only complete outputs.
//! Jobs poll [`requested`] (the cone-map generator through its progress callback, file writers
//! before they rename). A second signal while the first is being honoured exits at once with
//! status 130, for a job that does not stop.

use std::sync::Once;
use std::sync::atomic::{AtomicBool, Ordering};

static INTERRUPTED: AtomicBool = AtomicBool::new(false);

/// Installs the handler (once per process; later calls do nothing).
///
/// # Errors
///
/// The platform refused the handler.
pub fn install() -> Result<(), String> {
    static ONCE: Once = Once::new();
    let mut result = Ok(());
    ONCE.call_once(|| {
        result = ctrlc::set_handler(|| {
            if INTERRUPTED.swap(true, Ordering::SeqCst) {
                std::process::exit(130);
            }
        })
        .map_err(|e| format!("cannot install the interrupt handler: {e}"));
    });
    result
}

/// Whether an interruption was asked for.
pub fn requested() -> bool {
    INTERRUPTED.load(Ordering::SeqCst)
}

/// The error a job returns when it stopped for an interruption.
pub const MESSAGE: &str = "interrupted";
