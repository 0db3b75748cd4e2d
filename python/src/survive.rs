//! Many seeded walks on a floor for Python (`docs/floors.md`): `survive(...)`, as `walker
//! survive --json`, with the GIL released and Ctrl-C seen; a range of a batch's walks
//! (`first_walk`) on a pool of threads of the caller's size (a Dask task walks on one core);
//! and `survival(...)`, the statistics of outcomes gathered from such ranges, computed by the
//! same library function as a whole batch's.

use pyo3::prelude::*;
use walker::floor::{SurviveOutcome, survival as survival_of, survive_stoppable};
use walker::request::{MAX_STEPS, MAX_WALK_INDEX};

use crate::chunks::{asked, stoppable};
use crate::error::ArgError;
use crate::floor::{floor_spec, mu0_once, walker_on};
use crate::options;
use crate::walker_args::{self, overrides};

/// The most threads a batch may be given (`threads`).
const MAX_THREADS: usize = 1024;

/// Many seeded walks on a floor (see the Python docstring of `slippery_walker.survive`): the
/// JSON text of `walker survive --json`. `first_walk` starts the batch at that walk (walk `i`
/// runs on the floor's stream `i`, so the walks `a..b` of a batch are a batch of their own);
/// `threads` runs it on a pool of that many threads (default: all cores); `check_only` checks
/// every argument and the floor against the walker and returns an empty string without walking.
///
/// # Errors
/// `ValueError` naming a bad argument and its valid range; `KeyboardInterrupt` on Ctrl-C.
#[pyfunction]
#[pyo3(signature = (*, scene, model, set, init, floor, t_set, omega0, phi, c, friction,
    impact, method, rtol, atol, walks, max_steps, first_walk = 0, threads = None,
    check_only = false))]
#[allow(clippy::too_many_arguments)]
pub fn survive(
    py: Python<'_>,
    scene: Option<&str>,
    model: Option<&str>,
    set: Vec<(String, f64)>,
    init: Vec<(String, f64)>,
    floor: &Bound<'_, PyAny>,
    t_set: Option<f64>,
    omega0: Option<f64>,
    phi: Option<f64>,
    c: Option<f64>,
    friction: Option<&str>,
    impact: Option<&str>,
    method: &str,
    rtol: Option<f64>,
    atol: Option<f64>,
    walks: i64,
    max_steps: i64,
    first_walk: i64,
    threads: Option<i64>,
    check_only: bool,
) -> PyResult<String> {
    let spec = floor_spec(floor)?;
    let (walks, max_steps) =
        walker::request::survive_counts(i128::from(walks), i128::from(max_steps))
            .map_err(ArgError::from)?;
    let range =
        walker::request::walk_range(i128::from(first_walk), walks).map_err(ArgError::from)?;
    let threads = match threads {
        None => None,
        Some(n) => Some(
            usize::try_from(n)
                .ok()
                .filter(|n| (1..=MAX_THREADS).contains(n))
                .ok_or_else(|| {
                    ArgError::out_of_range(
                        "threads",
                        n,
                        &format!("a whole number in [1, {MAX_THREADS}]"),
                    )
                })?,
        ),
    };
    let ov = overrides(None, c, t_set, phi, friction, impact)?;
    let mut setup = walker_args::setup_released(py, scene, model, &ov, &set)?;
    mu0_once(&setup, &spec, None, phi, &set)?;
    walker_args::set_omega0(&mut setup, omega0, |_| true, "finite")?;
    let cfg = options::config(method, rtol, atol)?;
    let m = walker_args::model(&setup)?;
    let start = walker_args::start(&m, &init)?;
    let fw = walker_on(&setup, spec)?;
    if check_only {
        return Ok(String::new());
    }
    let report = stoppable(py, |stop| {
        let run = || survive_stoppable(&fw, &cfg, &start, range, max_steps, &|| asked(stop));
        match threads {
            None => Ok(run()),
            Some(n) => rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map(|pool| pool.install(run))
                .map_err(|e| ArgError::new("threads", format!("cannot start {n} threads: {e}"))),
        }
    })??
    .map_err(|e| ArgError::new("floor", e.to_string()))?;
    let Some(report) = report else {
        return Err(pyo3::exceptions::PyKeyboardInterrupt::new_err(()));
    };
    serde_json::to_string(&report)
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))
}

/// The survival statistics (`survive`'s `survival`, as JSON text) of the walks whose indices
/// are `walks`, steps completed `steps` and failures `failures` (a name, or `None` at the step
/// limit), in walk order: the same library function that a batch's statistics come from.
///
/// # Errors
/// `ValueError` for lists of different lengths, no walk, or a value out of its range (named
/// `outcomes[i]['steps']`).
#[pyfunction]
#[pyo3(signature = (*, walks, steps, failures))]
pub fn survival(
    walks: Vec<i64>,
    steps: Vec<i64>,
    failures: Vec<Option<String>>,
) -> PyResult<String> {
    if walks.len() != steps.len() || walks.len() != failures.len() {
        return Err(ArgError::new(
            "outcomes",
            format!(
                "{} walks, {} steps and {} failures: must be as many of each",
                walks.len(),
                steps.len(),
                failures.len()
            ),
        )
        .into());
    }
    if walks.is_empty() {
        return Err(
            ArgError::new("outcomes", "empty: must hold at least one walk's outcome").into(),
        );
    }
    let mut outcomes = Vec::with_capacity(walks.len());
    for (i, ((walk, steps), failure)) in walks.into_iter().zip(steps).zip(failures).enumerate() {
        let walk = u64::try_from(walk)
            .ok()
            .filter(|w| *w <= MAX_WALK_INDEX)
            .ok_or_else(|| {
                ArgError::out_of_range(
                    &format!("outcomes[{i}]['walk']"),
                    walk,
                    &format!("a whole number in [0, {MAX_WALK_INDEX}]"),
                )
            })?;
        let steps = usize::try_from(steps)
            .ok()
            .filter(|s| *s <= MAX_STEPS)
            .ok_or_else(|| {
                ArgError::out_of_range(
                    &format!("outcomes[{i}]['steps']"),
                    steps,
                    &format!("a whole number in [0, {MAX_STEPS}]"),
                )
            })?;
        outcomes.push(SurviveOutcome {
            walk,
            steps,
            failure,
        });
    }
    serde_json::to_string(&survival_of(&outcomes))
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))
}
