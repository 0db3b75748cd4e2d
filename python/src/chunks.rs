//! Long work in chunks: each chunk runs with the GIL released (other Python threads go on),
//! and between chunks pending signals are handled, so that Ctrl-C stops a sweep or a grid
//! within one chunk with `KeyboardInterrupt`.

use std::ops::Range;

use pyo3::prelude::*;

/// Run `work` over `0..n` in consecutive ranges of at most `chunk` items, with the GIL released
/// during each, checking for signals after each.
///
/// # Errors
/// A signal handler raised (Ctrl-C: `KeyboardInterrupt`); the work done so far is dropped.
pub fn in_chunks<S: Send>(
    py: Python<'_>,
    state: &mut S,
    n: usize,
    chunk: usize,
    work: impl Fn(&mut S, Range<usize>) + Sync,
) -> PyResult<()> {
    let chunk = chunk.max(1);
    let mut start = 0;
    while start < n {
        let end = (start + chunk).min(n);
        py.detach(|| work(state, start..end));
        py.check_signals()?;
        start = end;
    }
    Ok(())
}
