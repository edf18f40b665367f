//! Ctrl-C (SIGINT) and SIGTERM ask `weft serve` to stop, so it can remove
//! its build cache folder rather than die by the default handler and leave
//! it in the temporary folder.

use signal_hook::consts::{SIGINT, SIGTERM};
use std::sync::Arc;
use std::sync::atomic::AtomicBool;

/// A flag set by the first SIGINT or SIGTERM; a second one while the flag
/// is set ends the process at once (exit status 1), should stopping hang.
pub fn stop_flag() -> Result<Arc<AtomicBool>, String> {
    let flag = Arc::new(AtomicBool::new(false));
    for signal in [SIGINT, SIGTERM] {
        // The shutdown hook first: it sees the flag as the previous signal
        // left it (the documented signal-hook pattern).
        signal_hook::flag::register_conditional_shutdown(signal, 1, flag.clone())
            .and_then(|_| signal_hook::flag::register(signal, flag.clone()))
            .map_err(|e| format!("cannot handle signal {signal}: {e}"))?;
    }
    Ok(flag)
}
