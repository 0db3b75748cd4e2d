//! `slippery_walker._core`: the walker library as a Python extension module (PyO3, abi3 for
//! Python 3.9 and later). The Python package `slippery_walker` (beside this crate) wraps these
//! functions into keyword-argument functions with docstrings and NumPy results.
//!
//! Every function takes the walker as the `walker` command line does: a scene or a model file
//! (any planar walker of `docs/model-format.md`; one that is not shipped is derived when the
//! call starts, by `walker-load`), its run-time parameters by keyword or by name (`set`), and
//! its start (`omega0`, `init`). Arguments are checked as the command line checks its flags
//! (a parameter's range is the one its model file gives) and a bad one raises `ValueError`
//! naming it and its valid range; a walker failure is a result (a `status` and a `failure`),
//! never an exception. Long work runs with the GIL released.
//!
//! Files: `error.rs` (bad arguments), `options.rs` (the laws, the integrator, the limits),
//! `walker_args.rs` (the walker: scene or model, parameters, start), `table.rs` (results as
//! columns), `chunks.rs` (work in chunks between checks for Ctrl-C), then one file per
//! function: `simulate.rs`, `sweep.rs`, `points.rs`, `fixed_point.rs`, `describe.rs`,
//! `floor.rs` (`floor=` of `simulate` and `survive`), `survive.rs` (`survive`, and `survival`
//! of outcomes gathered from ranges of a batch), `mfpt.rs` (`mfpt`, the mesh estimate),
//! `design.rs` (`design`, the gait design of `walker design`).

pub mod chunks;
pub mod describe;
pub mod design;
pub mod error;
pub mod fixed_point;
pub mod floor;
pub mod mfpt;
pub mod options;
pub mod points;
pub mod simulate;
pub mod survive;
pub mod sweep;
pub mod table;
pub mod walker_args;

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
    m.add_function(wrap_pyfunction!(describe::describe, m)?)?;
    m.add_function(wrap_pyfunction!(survive::survive, m)?)?;
    m.add_function(wrap_pyfunction!(survive::survival, m)?)?;
    m.add_function(wrap_pyfunction!(mfpt::mfpt, m)?)?;
    m.add_function(wrap_pyfunction!(design::design, m)?)?;
    Ok(())
}
