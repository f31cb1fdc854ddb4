//! Progress of a render on stderr: a bar on a terminal; in a log (stderr a file or a pipe,
//! as on a farm) a line every few seconds with the percentage done, the rays per second and
//! the time left; nothing when quiet.

use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// How progress is shown.
enum Display {
    Hidden,
    Bar(ProgressBar),
    /// Log lines, the next one due at the instant held.
    Lines {
        every: Duration,
        next: Mutex<Instant>,
    },
}

/// Told of every finished tile by the render ([`tress::render::Progress`]).
pub struct Progress {
    display: Display,
    /// Printed before each log line (`frame 12: `), empty for a single image.
    label: String,
    /// Tiles of the image, and those already done when this run started (resumed).
    total: u64,
    done_before: u64,
    done: AtomicU64,
    rays: AtomicU64,
    start: Instant,
}

impl Progress {
    /// Progress of a render of `total` tiles of which `done` are done already; log lines
    /// every `every` when stderr is not a terminal.
    pub fn new(quiet: bool, every: Duration, label: String, total: u64, done: u64) -> Progress {
        let display = if quiet {
            Display::Hidden
        } else if std::io::stderr().is_terminal() {
            let bar = ProgressBar::new(total);
            bar.set_style(
                ProgressStyle::with_template("{spinner} [{elapsed_precise}] {wide_bar} {percent}% {msg} ETA {eta}")
                    .expect("static template"),
            );
            bar.set_position(done);
            bar.reset_eta();
            Display::Bar(bar)
        } else {
            Display::Lines { every, next: Mutex::new(Instant::now() + every) }
        };
        Progress {
            display,
            label,
            total,
            done_before: done,
            done: AtomicU64::new(0),
            rays: AtomicU64::new(0),
            start: Instant::now(),
        }
    }

    /// Prints a message without breaking the bar.
    pub fn println(&self, message: &str) {
        match &self.display {
            Display::Bar(bar) => bar.println(message),
            _ => eprintln!("{message}"),
        }
    }

    /// Removes the bar.
    pub fn finish(&self) {
        if let Display::Bar(bar) = &self.display {
            bar.finish_and_clear();
        }
    }

    /// The log line for `done` tiles of this run and `rays` traced so far.
    fn line(&self, done: u64, rays: u64) -> String {
        let elapsed = self.start.elapsed().as_secs_f64();
        let all_done = self.done_before + done;
        let percent = 100.0 * all_done as f64 / self.total.max(1) as f64;
        let left = self.total.saturating_sub(all_done) as f64 * elapsed / done.max(1) as f64;
        format!(
            "{}{percent:5.1} % ({all_done} of {} tiles), {:.2} M rays/s, ETA {}",
            self.label,
            self.total,
            rays as f64 / elapsed.max(1e-9) / 1e6,
            clock(left)
        )
    }
}

/// Seconds as `H:MM:SS`.
fn clock(seconds: f64) -> String {
    let s = seconds.round() as u64;
    format!("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60)
}

impl tress::render::Progress for Progress {
    fn advance(&self, tiles: u64, rays: u64) {
        let done = self.done.fetch_add(tiles, Ordering::Relaxed) + tiles;
        let rays = self.rays.fetch_add(rays, Ordering::Relaxed) + rays;
        match &self.display {
            Display::Hidden => {}
            Display::Bar(bar) => {
                bar.inc(tiles);
                bar.set_message(format!("{:.2} M rays/s", rays as f64 / self.start.elapsed().as_secs_f64() / 1e6));
            }
            Display::Lines { every, next } => {
                // One worker prints; the others do not wait for it.
                let Ok(mut next) = next.try_lock() else { return };
                let now = Instant::now();
                if now >= *next && self.done_before + done < self.total {
                    *next = now + *every;
                    eprintln!("{}", self.line(done, rays));
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_lines_tell_percent_rate_and_time_left() {
        assert_eq!(clock(3725.4), "1:02:05");
        let p = Progress::new(true, Duration::from_secs(1), "frame 3: ".into(), 200, 50);
        // 50 tiles resumed, 50 more in this run: half done, the other half as long again.
        let line = p.line(50, 2_000_000);
        assert!(line.starts_with("frame 3:  50.0 % (100 of 200 tiles), "), "{line}");
        assert!(line.ends_with("ETA 0:00:00"), "{line}");
    }
}
