//! Long work with the GIL released and Ctrl-C seen within a fraction of a second: the work runs
//! on a thread of its own while the calling thread, every [`POLL`], takes the GIL for a moment
//! and handles pending signals (`py.check_signals()`). The chunks of work are bounded by work,
//! not by count: a walk asks its stop flag before every step of the walker
//! ([`walker::sim::walk_stoppable`]), so that one walk of a million steps is abandoned as
//! promptly as a grid of a million short walks.
//!
//! Two forms: [`stoppable`] for work that watches its stop flag (walks), which is waited for
//! after the flag is set; [`abandonable`] for work that cannot be asked to stop (deriving a
//! model file that is not shipped, reading a file, a fixed-point search), which is left to end
//! on its own thread (bounded by the derivation's budget and the file limits) while the caller
//! gets `KeyboardInterrupt` at once.

use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::time::Duration;

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;

/// How often the calling thread checks for signals while work runs: well below the second
/// within which Ctrl-C must be seen, and rare enough (a GIL round trip each) to cost nothing.
pub const POLL: Duration = Duration::from_millis(20);

/// The stack of a work thread: deriving a model recurses through its expressions, so it gets
/// the room of a main thread and more (reserved address space, not memory used).
const STACK: usize = 64 << 20;

/// A flag that work asks to know whether it should stop.
pub type Stop = AtomicBool;

/// True when `stop` is set (for [`walker::sim::walk_stoppable`]'s closure).
#[must_use]
pub fn asked(stop: &Stop) -> bool {
    stop.load(Ordering::Relaxed)
}

/// The receiving end of a work thread's value, shareable with the thread that waits with the
/// GIL released (a `Receiver` alone is not `Sync`).
type Inbox<T> = Mutex<mpsc::Receiver<T>>;

/// Waits up to `timeout` for `rx`'s value.
fn receive<T>(rx: &Inbox<T>, timeout: Duration) -> Result<T, RecvTimeoutError> {
    match rx.lock() {
        Ok(r) => r.recv_timeout(timeout),
        Err(_) => Err(RecvTimeoutError::Disconnected),
    }
}

/// Waits for `rx`'s one value with the GIL released, handling signals every [`POLL`]; on a
/// signal's error calls `on_signal` and returns the error.
fn wait<T: Send>(
    py: Python<'_>,
    rx: &Inbox<T>,
    on_signal: impl FnOnce(),
) -> PyResult<Result<T, RecvTimeoutError>> {
    loop {
        match py.detach(|| receive(rx, POLL)) {
            Err(RecvTimeoutError::Timeout) => {}
            other => return Ok(other),
        }
        if let Err(e) = py.check_signals() {
            on_signal();
            return Err(e);
        }
    }
}

/// Runs `work(stop)` on a thread of its own with the GIL released and returns its value. A
/// signal handler that raises (Ctrl-C: `KeyboardInterrupt`) sets `stop`; the work is waited for
/// (it must watch `stop`: a walk does before every step) and the handler's error is returned.
///
/// # Errors
/// A signal handler raised; the work's value is dropped. The work thread panicked or could
/// not be started (`RuntimeError`).
pub fn stoppable<T: Send>(py: Python<'_>, work: impl FnOnce(&Stop) -> T + Send) -> PyResult<T> {
    let stop = AtomicBool::new(false);
    let (tx, rx) = mpsc::channel();
    let rx = Mutex::new(rx);
    std::thread::scope(|s| {
        let stop = &stop;
        std::thread::Builder::new()
            .stack_size(STACK)
            .spawn_scoped(s, move || {
                // The receiver is gone only after a signal, when nobody waits for the value.
                let _ = tx.send(work(stop));
            })
            .map_err(|e| PyRuntimeError::new_err(format!("cannot start a thread: {e}")))?;
        match wait(py, &rx, || stop.store(true, Ordering::Relaxed)) {
            Ok(Ok(v)) => Ok(v),
            Ok(Err(_)) => Err(PyRuntimeError::new_err("the work thread panicked")),
            // The work sees `stop` within one step of a walk; wait for its end with the GIL
            // released, so that the scope's join does not hold it.
            Err(e) => {
                let _ = py.detach(|| receive(&rx, Duration::MAX));
                Err(e)
            }
        }
    })
}

/// Runs `work` on a thread of its own with the GIL released and returns its value. A signal
/// handler that raises (Ctrl-C) returns its error at once: the work cannot be asked to stop,
/// so it is left to end on its own thread and its value is dropped.
///
/// # Errors
/// A signal handler raised. The work thread panicked or could not be started
/// (`RuntimeError`).
pub fn abandonable<T: Send + 'static>(
    py: Python<'_>,
    work: impl FnOnce() -> T + Send + 'static,
) -> PyResult<T> {
    let (tx, rx) = mpsc::channel();
    let rx = Mutex::new(rx);
    std::thread::Builder::new()
        .stack_size(STACK)
        .spawn(move || {
            let _ = tx.send(work());
        })
        .map_err(|e| PyRuntimeError::new_err(format!("cannot start a thread: {e}")))?;
    match wait(py, &rx, || {})? {
        Ok(v) => Ok(v),
        Err(_) => Err(PyRuntimeError::new_err("the work thread panicked")),
    }
}
