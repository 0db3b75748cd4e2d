//! Results as columns for Python: the steps of a walk ([`steps_dict`]) and one row per walk
//! of a sweep or a grid ([`Rows`]), each a dict of lists that the Python package turns into
//! NumPy arrays. Descriptors a walk does not have (the passive wheel's `p` and `SR`, or any
//! descriptor of a walk that failed in its first step) are NaN there; the `status` column
//! always names the outcome (`ok`, `periodic` or the failure's name).

use pyo3::prelude::*;
use pyo3::types::PyDict;
use walker::sim::{Failure, StepResult, Walk};

/// The status of a walk as the command line prints it: the failure's name, else `periodic`
/// (stopped early with a periodic gait) or `ok`.
#[must_use]
pub fn status(failure: Option<&Failure>, periodic: bool) -> &'static str {
    failure.map_or(if periodic { "periodic" } else { "ok" }, Failure::name)
}

/// A failure as the command line's JSON object (`{"kind", "step", "t", "state", ..}`).
#[must_use]
pub fn failure_json(failure: Option<&Failure>) -> Option<String> {
    failure.and_then(|f| serde_json::to_string(f).ok())
}

/// The per-step columns of `steps`: `T`, `dx`, `V`, `p`, `SR` (one value a step) and
/// `q_plus`, `qd_plus` (four a step, row after row).
#[derive(Default)]
pub struct StepColumns {
    period: Vec<f64>,
    dx: Vec<f64>,
    speed: Vec<f64>,
    p: Vec<f64>,
    sr: Vec<f64>,
    q_plus: Vec<f64>,
    qd_plus: Vec<f64>,
}

impl StepColumns {
    /// Append `step`, or a row of NaN where there is none.
    pub fn push(&mut self, step: Option<&StepResult>) {
        let nan = f64::NAN;
        self.period.push(step.map_or(nan, |s| s.period));
        self.dx.push(step.map_or(nan, |s| s.dx));
        self.speed.push(step.map_or(nan, |s| s.speed));
        self.p.push(step.and_then(|s| s.p).unwrap_or(nan));
        self.sr.push(step.and_then(|s| s.sr).unwrap_or(nan));
        self.q_plus.extend(step.map_or([nan; 4], |s| s.q_plus));
        self.qd_plus.extend(step.map_or([nan; 4], |s| s.qd_plus));
    }

    /// Put the columns into `d` under their names.
    ///
    /// # Errors
    /// A Python error while filling the dict.
    pub fn fill(self, d: &Bound<'_, PyDict>) -> PyResult<()> {
        d.set_item("T", self.period)?;
        d.set_item("dx", self.dx)?;
        d.set_item("V", self.speed)?;
        d.set_item("p", self.p)?;
        d.set_item("SR", self.sr)?;
        d.set_item("q_plus", self.q_plus)?;
        d.set_item("qd_plus", self.qd_plus)?;
        Ok(())
    }
}

/// A walk as a dict: `status`, `failure` (JSON or None), `periodic` and its per-step columns.
///
/// # Errors
/// A Python error while filling the dict.
pub fn steps_dict<'py>(py: Python<'py>, walk: &Walk) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("status", status(walk.failure.as_ref(), walk.periodic))?;
    d.set_item("failure", failure_json(walk.failure.as_ref()))?;
    d.set_item("periodic", walk.periodic)?;
    let mut cols = StepColumns::default();
    for s in &walk.steps {
        cols.push(Some(s));
    }
    cols.fill(&d)?;
    Ok(d)
}

/// The outcome of one walk of a sweep or a grid: its number of steps, its last step, its
/// failure and whether it stopped early as periodic.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    /// Completed steps.
    pub steps: usize,
    /// The last completed step.
    pub last: Option<StepResult>,
    /// Why the walk ended early, if it did.
    pub failure: Option<Failure>,
    /// Stopped early with a periodic gait.
    pub periodic: bool,
}

impl Outcome {
    /// The outcome of `walk`.
    #[must_use]
    pub fn of(walk: Walk) -> Self {
        Outcome {
            steps: walk.steps.len(),
            last: walk.steps.last().copied(),
            failure: walk.failure,
            periodic: walk.periodic,
        }
    }
}

/// One row per walk: `steps`, `status`, `periodic`, `failure` and the last step's descriptors.
#[derive(Default)]
pub struct Rows {
    steps: Vec<usize>,
    status: Vec<&'static str>,
    periodic: Vec<bool>,
    failure: Vec<Option<String>>,
    last: StepColumns,
}

impl Rows {
    /// Append `o`.
    pub fn push(&mut self, o: &Outcome) {
        self.steps.push(o.steps);
        self.status.push(status(o.failure.as_ref(), o.periodic));
        self.periodic.push(o.periodic);
        self.failure.push(failure_json(o.failure.as_ref()));
        self.last.push(o.last.as_ref());
    }

    /// The rows as a dict of columns.
    ///
    /// # Errors
    /// A Python error while filling the dict.
    pub fn into_dict(self, py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("steps", self.steps)?;
        d.set_item("status", self.status)?;
        d.set_item("periodic", self.periodic)?;
        d.set_item("failure", self.failure)?;
        self.last.fill(&d)?;
        Ok(d)
    }
}
