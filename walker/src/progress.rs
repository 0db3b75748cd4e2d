//! A progress bar on standard error for long runs (`walker sweep`, `walker reproduce`), drawn only
//! when standard error is a terminal, so that pipes, logs and scripts see nothing of it.

use std::io::{IsTerminal, Write};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// Counts finished work items and redraws one line on standard error at most ten times a
/// second. Safe to tick from several threads.
#[derive(Debug)]
pub struct Progress {
    label: String,
    total: usize,
    done: AtomicUsize,
    enabled: bool,
    start: Instant,
    last_draw: Mutex<Option<Instant>>,
}

impl Progress {
    /// A bar for `total` items, drawn if standard error is a terminal.
    pub fn new(label: &str, total: usize) -> Self {
        Self::with_output(label, total, std::io::stderr().is_terminal())
    }

    /// A bar for `total` items that is drawn only if `enabled`.
    pub fn with_output(label: &str, total: usize, enabled: bool) -> Self {
        Self {
            label: label.to_owned(),
            total,
            done: AtomicUsize::new(0),
            enabled,
            start: Instant::now(),
            last_draw: Mutex::new(None),
        }
    }

    /// One more item is finished.
    pub fn tick(&self) {
        let done = self.done.fetch_add(1, Ordering::Relaxed) + 1;
        if !self.enabled {
            return;
        }
        let Ok(mut last) = self.last_draw.lock() else {
            return;
        };
        let now = Instant::now();
        if done < self.total && last.is_some_and(|t| now - t < Duration::from_millis(100)) {
            return;
        }
        *last = Some(now);
        let _ = write!(std::io::stderr(), "\r{}", self.line(done));
    }

    /// The number of finished items.
    pub fn done(&self) -> usize {
        self.done.load(Ordering::Relaxed)
    }

    /// Ends the bar's line (if it was drawn).
    pub fn finish(&self) {
        if self.enabled {
            let _ = writeln!(std::io::stderr(), "\r{}", self.line(self.done()));
        }
    }

    /// The bar's text for `done` items: `label [#####-----] done/total  elapsed`.
    pub fn line(&self, done: usize) -> String {
        const WIDTH: usize = 30;
        let filled = (done * WIDTH)
            .checked_div(self.total)
            .unwrap_or(WIDTH)
            .min(WIDTH);
        format!(
            "{} [{}{}] {done}/{} {:.1} s",
            self.label,
            "#".repeat(filled),
            "-".repeat(WIDTH - filled),
            self.total,
            self.start.elapsed().as_secs_f64()
        )
    }
}

#[cfg(test)]
mod tests {
    use super::Progress;

    #[test]
    fn counts_from_several_threads_and_draws_a_proportional_bar() {
        let p = Progress::with_output("sweep", 40, false);
        std::thread::scope(|s| {
            for _ in 0..4 {
                s.spawn(|| (0..10).for_each(|_| p.tick()));
            }
        });
        assert_eq!(p.done(), 40);
        assert!(
            p.line(20)
                .starts_with("sweep [###############---------------] 20/40")
        );
        assert!(
            p.line(0)
                .starts_with("sweep [------------------------------] 0/40")
        );
        let empty = Progress::with_output("x", 0, false);
        assert!(
            empty
                .line(0)
                .contains("[##############################] 0/0")
        );
    }
}
