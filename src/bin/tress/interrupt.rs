//! SIGINT, SIGTERM and SIGHUP: while a scene loads (reading files, growing fur, building
//! the BVH) nothing has been rendered and nothing is being written, so a signal ends the
//! process at once; during a render the first signal asks it to stop and write what it
//! has, and a second one ends the process at once.

use anyhow::Result;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Arc;

/// The signals received, as a flag the render polls and the signal's number.
pub struct Interrupt {
    flag: Arc<AtomicBool>,
    signal: Arc<AtomicUsize>,
    loading: Arc<AtomicBool>,
}

impl Interrupt {
    /// Installs the handlers.
    pub fn install() -> Result<Interrupt> {
        use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
        let interrupt = Interrupt {
            flag: Arc::new(AtomicBool::new(false)),
            signal: Arc::new(AtomicUsize::new(0)),
            loading: Arc::new(AtomicBool::new(false)),
        };
        for sig in [SIGINT, SIGTERM, SIGHUP] {
            let loading = interrupt.loading.clone();
            // SAFETY: the action only loads an atomic, writes a constant message with
            // write(2) and calls _exit(2), all async-signal-safe.
            unsafe {
                signal_hook::low_level::register(sig, move || {
                    if loading.load(Ordering::SeqCst) {
                        let message = b"interrupted while loading the scene; nothing written\n";
                        libc::write(2, message.as_ptr().cast(), message.len());
                        libc::_exit(128 + sig);
                    }
                })?;
            }
            // Registered first, so it sees the flag as the previous signal left it.
            signal_hook::flag::register_conditional_shutdown(sig, 128 + sig, interrupt.flag.clone())?;
            signal_hook::flag::register_usize(sig, interrupt.signal.clone(), sig as usize)?;
            signal_hook::flag::register(sig, interrupt.flag.clone())?;
        }
        Ok(interrupt)
    }

    /// Marks whether the scene is loading (a signal then ends the process at once) or
    /// rendering (a signal asks the render to stop).
    pub fn set_loading(&self, loading: bool) {
        self.loading.store(loading, Ordering::SeqCst);
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
