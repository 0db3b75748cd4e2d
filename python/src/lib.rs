//! `slippery_walker._core`: the walker library as a Python extension module (PyO3, abi3 for
//! Python 3.9 and later). The Python package `slippery_walker` (beside this crate) wraps these
//! functions into keyword-argument functions with docstrings and NumPy results.
//!
//! Every function checks its arguments as the `walker` command line checks its flags (the
//! parameter ranges come from the parameter table through [`walker::setup::Setup::resolve`])
//! and raises `ValueError` naming the argument and its valid range; a walker failure is a
//! result (a `status` and a `failure`), never an exception. Long work runs with the GIL
//! released.
//!
//! Files: `error.rs` (bad arguments), `options.rs` (the shared arguments), `table.rs` (results
//! as columns), `chunks.rs` (work in chunks between checks for Ctrl-C), then one file per
//! function: `simulate.rs`, `sweep.rs`, `points.rs`, `fixed_point.rs`.

pub mod chunks;
pub mod error;
pub mod fixed_point;
pub mod options;
pub mod points;
pub mod simulate;
pub mod sweep;
pub mod table;

use pyo3::prelude::*;

/// The extension module `slippery_walker._core`.
#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("MAX_STEPS", options::MAX_STEPS)?;
    m.add_function(wrap_pyfunction!(simulate::simulate, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep, m)?)?;
    m.add_function(wrap_pyfunction!(points::walk_points, m)?)?;
    m.add_function(wrap_pyfunction!(fixed_point::fixed_point, m)?)?;
    Ok(())
}
