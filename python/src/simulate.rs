//! `simulate(...)`: one walk from the model's start, as `walker simulate`, with its per-step
//! descriptors and, on request, the motion sampled at exact times
//! ([`walker::sim::trajectory`]).

use pyo3::prelude::*;
use pyo3::types::PyDict;
use walker::sim::{trajectory_stoppable, walk_stoppable};

use crate::chunks::{asked, stoppable};
use crate::error::ArgError;
use crate::options;
use crate::table::steps_dict;
use crate::walker_args::{self, overrides};

/// Simulate one walk (see the Python docstring of `slippery_walker.simulate`).
///
/// # Errors
/// `ValueError` naming a bad argument and its valid range; a walker failure is a result.
#[pyfunction]
#[pyo3(signature = (*, scene, model, set, init, mu0, t_set, omega0, phi, c, friction, impact,
    method, rtol, atol, duration, max_steps, trajectory_dt, max_frames, floor=None))]
#[allow(clippy::too_many_arguments)]
pub fn simulate<'py>(
    py: Python<'py>,
    scene: Option<&str>,
    model: Option<&str>,
    set: Vec<(String, f64)>,
    init: Vec<(String, f64)>,
    mu0: Option<f64>,
    t_set: Option<f64>,
    omega0: Option<f64>,
    phi: Option<f64>,
    c: Option<f64>,
    friction: Option<&str>,
    impact: Option<&str>,
    method: &str,
    rtol: Option<f64>,
    atol: Option<f64>,
    duration: Option<f64>,
    max_steps: i64,
    trajectory_dt: Option<f64>,
    max_frames: i64,
    floor: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let floor = floor.map(crate::floor::floor_spec).transpose()?;
    let ov = overrides(mu0, c, t_set, phi, friction, impact)?;
    let mut setup = walker_args::setup_released(py, scene, model, &ov, &set)?;
    walker_args::set_omega0(&mut setup, omega0, |_| true, "finite")?;
    let cfg = options::config(method, rtol, atol)?;
    let limits = options::limits(duration, max_steps, None)?;
    let model = walker_args::model(&setup)?;
    let start = walker_args::start(&model, &init)?;
    if let Some(floor) = floor {
        crate::floor::mu0_once(&setup, &floor, mu0, phi, &set)?;
        if trajectory_dt.is_some() {
            return Err(ArgError::new(
                "trajectory",
                "a walk on a floor is not sampled (give trajectory=False with floor=)",
            )
            .into());
        }
        let fw = crate::floor::walker_on(&setup, floor)?;
        let w = stoppable(py, |stop| {
            fw.walk_stoppable(0, &cfg, &start, &limits, &|| asked(stop))
        })?
        .map_err(|e| ArgError::new("floor", e.to_string()))?;
        let Some(w) = w else {
            return Err(pyo3::exceptions::PyKeyboardInterrupt::new_err(()));
        };
        let d = steps_dict(py, &model, &w)?;
        d.set_item(
            "floor_mu0",
            w.steps
                .iter()
                .map(|s| s.floor.map_or(f64::NAN, |f| f.mu0))
                .collect::<Vec<_>>(),
        )?;
        // A floor of patches by position: each strike's patch and each stance's crossings.
        let floors: Vec<_> = w.steps.iter().filter_map(|s| s.floor).collect();
        if floors.len() == w.steps.len()
            && let Some(strike) = floors
                .iter()
                .map(|f| f.mu0_strike)
                .collect::<Option<Vec<f64>>>()
            && let Some(crossings) = floors
                .iter()
                .map(|f| f.crossings)
                .collect::<Option<Vec<u32>>>()
        {
            d.set_item("floor_mu0_strike", strike)?;
            d.set_item("floor_crossings", crossings)?;
        }
        return Ok(d);
    }
    let Some(dt) = trajectory_dt else {
        let w = stoppable(py, |stop| {
            walk_stoppable(&model, &cfg, &start, &limits, &|| asked(stop))
        })?;
        // Stopped only after a signal, whose error `stoppable` returns first.
        let Ok(w) = w else {
            return Err(pyo3::exceptions::PyKeyboardInterrupt::new_err(()));
        };
        return steps_dict(py, &model, &w);
    };
    let (dt, max_frames) = walker::request::trajectory(duration, dt, i128::from(max_frames))
        .map_err(ArgError::from)?;
    let tr = stoppable(py, |stop| {
        trajectory_stoppable(&model, &cfg, &start, &limits, dt, max_frames, &|| {
            asked(stop)
        })
    })?;
    let Ok(tr) = tr else {
        return Err(pyo3::exceptions::PyKeyboardInterrupt::new_err(()));
    };
    let d = steps_dict(py, &model, &tr.walk)?;
    d.set_item(
        "times",
        tr.frames.iter().map(|f| f.time).collect::<Vec<_>>(),
    )?;
    d.set_item(
        "states",
        tr.frames
            .iter()
            .flat_map(|f| f.state.iter().copied())
            .collect::<Vec<_>>(),
    )?;
    d.set_item(
        "u",
        tr.frames
            .iter()
            .flat_map(|f| f.u.iter().copied())
            .collect::<Vec<_>>(),
    )?;
    d.set_item(
        "frame_steps",
        tr.frames.iter().map(|f| f.step).collect::<Vec<_>>(),
    )?;
    d.set_item("truncated", tr.truncated)?;
    d.set_item("end_time", tr.end_time())?;
    Ok(d)
}
