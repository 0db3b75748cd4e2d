//! A progress bar on standard error for long runs (`walker sweep`, `walker reproduce`), drawn
//! by indicatif only when standard error is a terminal, so that pipes, logs and scripts see
//! nothing of it.

use std::io::IsTerminal;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// Counts finished work items of one run; safe to tick from several threads.
#[derive(Debug)]
pub struct Progress {
    bar: ProgressBar,
}

impl Progress {
    /// A bar for `total` items, drawn if standard error is a terminal.
    #[must_use]
    pub fn new(label: &str, total: usize) -> Self {
        Self::with_output(label, total, std::io::stderr().is_terminal())
    }

    /// A bar for `total` items that is drawn (on standard error) only if `enabled`.
    #[must_use]
    pub fn with_output(label: &str, total: usize, enabled: bool) -> Self {
        let target = if enabled {
            ProgressDrawTarget::stderr()
        } else {
            ProgressDrawTarget::hidden()
        };
        let bar = ProgressBar::with_draw_target(Some(total as u64), target);
        if let Ok(style) = ProgressStyle::with_template(
            "{prefix} [{bar:30}] {pos}/{len} {elapsed_precise} (eta {eta})",
        ) {
            bar.set_style(style.progress_chars("#>-"));
        }
        bar.set_prefix(label.to_owned());
        Self { bar }
    }

    /// One more item is finished.
    pub fn tick(&self) {
        self.bar.inc(1);
    }

    /// The number of finished items.
    #[must_use]
    pub fn done(&self) -> usize {
        usize::try_from(self.bar.position()).unwrap_or(usize::MAX)
    }

    /// Ends the bar, leaving its last state on the terminal (if it was drawn).
    pub fn finish(&self) {
        self.bar.finish();
    }
}

#[cfg(test)]
mod tests {
    use super::Progress;

    #[test]
    fn counts_ticks_from_several_threads() {
        let p = Progress::with_output("sweep", 40, false);
        std::thread::scope(|s| {
            for _ in 0..4 {
                s.spawn(|| (0..10).for_each(|_| p.tick()));
            }
        });
        assert_eq!(p.done(), 40);
    }
}
