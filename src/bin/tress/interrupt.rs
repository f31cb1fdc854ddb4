//! SIGINT, SIGTERM and SIGHUP during a render: the first signal asks the render to stop and
//! write what it has; a second one ends the process at once.

use anyhow::Result;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Arc;

/// The signals received, as a flag the render polls and the signal's number.
pub struct Interrupt {
    flag: Arc<AtomicBool>,
    signal: Arc<AtomicUsize>,
}

impl Interrupt {
    /// Installs the handlers.
    pub fn install() -> Result<Interrupt> {
        use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
        let interrupt = Interrupt { flag: Arc::new(AtomicBool::new(false)), signal: Arc::new(AtomicUsize::new(0)) };
        for sig in [SIGINT, SIGTERM, SIGHUP] {
            // Registered first, so it sees the flag as the previous signal left it.
            signal_hook::flag::register_conditional_shutdown(sig, 128 + sig, interrupt.flag.clone())?;
            signal_hook::flag::register_usize(sig, interrupt.signal.clone(), sig as usize)?;
            signal_hook::flag::register(sig, interrupt.flag.clone())?;
        }
        Ok(interrupt)
    }

    /// True once a signal came.
    pub fn flag(&self) -> &AtomicBool {
        &self.flag
    }

    /// The signal received, if any.
    pub fn signal(&self) -> Option<i32> {
        match self.signal.load(Ordering::SeqCst) {
            0 => None,
            s => Some(s as i32),
        }
    }
}
