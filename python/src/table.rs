//! Results as columns for Python: the steps of a walk ([`steps_dict`]) and one row per walk
//! of a sweep or a grid ([`Rows`]), each a dict of lists that the Python package turns into
//! NumPy arrays. Descriptors a walk does not have (`p` and `SR` of a walker without inputs, or
//! any descriptor of a walk that failed in its first step) are NaN there; the `status` column
//! always names the outcome (`ok`, `periodic` or the failure's name). A model with `n`
//! coordinates has `n` values of `q_plus` and of `qd_plus` per row, row after row, named by
//! [`names_dict`].

use pyo3::prelude::*;
use pyo3::types::PyDict;
use walker::model::{Model, Spec};
use walker::sim::{Failure, StepResult, Walk};

/// The columns of a sweep's or a grid's results: a swept parameter or a grid column may not
/// have one of these names (its values would be lost among the results).
pub const RESULT_COLUMNS: [&str; 12] = [
    "chain", "steps", "status", "periodic", "failure", "T", "dx", "V", "p", "SR", "q_plus",
    "qd_plus",
];

/// The status of a walk as the command line prints it: the failure's name, else `periodic`
/// (stopped early with a periodic gait) or `ok`.
#[must_use]
pub fn status(failure: Option<&Failure>, periodic: bool) -> &str {
    failure.map_or(if periodic { "periodic" } else { "ok" }, Failure::name)
}

/// A failure as the command line's JSON object (`{"kind", "step", "t", "state", ..}`).
#[must_use]
pub fn failure_json(failure: Option<&Failure>) -> Option<String> {
    failure.and_then(|f| serde_json::to_string(f).ok())
}

/// The names of a model's state components (`state_names`: the coordinates, then their
/// velocities) and inputs (`input_names`), put into `d`.
///
/// # Errors
/// A Python error while filling the dict.
pub fn names_dict(d: &Bound<'_, PyDict>, spec: &Spec) -> PyResult<()> {
    d.set_item("state_names", spec.state_names())?;
    let inputs: Vec<&str> = spec
        .model
        .inputs
        .iter()
        .map(|i| i.name.name.as_str())
        .collect();
    d.set_item("input_names", inputs)?;
    Ok(())
}

/// The per-step columns of `steps`: `T`, `dx`, `V`, `p`, `SR` (one value a step) and
/// `q_plus`, `qd_plus` (`n` a step, row after row).
pub struct StepColumns {
    n: usize,
    period: Vec<f64>,
    dx: Vec<f64>,
    speed: Vec<f64>,
    p: Vec<f64>,
    sr: Vec<f64>,
    q_plus: Vec<f64>,
    qd_plus: Vec<f64>,
}

impl StepColumns {
    /// No rows yet, of a model with `n` coordinates.
    #[must_use]
    pub fn new(n: usize) -> Self {
        StepColumns {
            n,
            period: Vec::new(),
            dx: Vec::new(),
            speed: Vec::new(),
            p: Vec::new(),
            sr: Vec::new(),
            q_plus: Vec::new(),
            qd_plus: Vec::new(),
        }
    }

    /// Append `step`, or a row of NaN where there is none.
    pub fn push(&mut self, step: Option<&StepResult>) {
        let nan = f64::NAN;
        let row = |v: Option<&[f64]>| {
            let mut r = vec![nan; self.n];
            if let Some(v) = v {
                for (x, y) in r.iter_mut().zip(v) {
                    *x = *y;
                }
            }
            r
        };
        self.period.push(step.map_or(nan, |s| s.period));
        self.dx.push(step.map_or(nan, |s| s.dx));
        self.speed.push(step.map_or(nan, |s| s.speed));
        self.p.push(step.and_then(|s| s.p).unwrap_or(nan));
        self.sr.push(step.and_then(|s| s.sr).unwrap_or(nan));
        let (q, qd) = (
            row(step.map(|s| &s.q_plus[..])),
            row(step.map(|s| &s.qd_plus[..])),
        );
        self.q_plus.extend(q);
        self.qd_plus.extend(qd);
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

/// A walk of `model` as a dict: `status`, `failure` (JSON or None), `periodic`, its per-step
/// columns, each heel strike's `foot_impulse` `[Lambda_t, Lambda_n]` (two a step, row after
/// row) and the names of its state components and inputs.
///
/// # Errors
/// A Python error while filling the dict.
pub fn steps_dict<'py>(
    py: Python<'py>,
    model: &Model,
    walk: &Walk,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("status", status(walk.failure.as_ref(), walk.periodic))?;
    d.set_item("failure", failure_json(walk.failure.as_ref()))?;
    d.set_item("periodic", walk.periodic)?;
    names_dict(&d, model.spec())?;
    let mut cols = StepColumns::new(model.n());
    for s in &walk.steps {
        cols.push(Some(s));
    }
    cols.fill(&d)?;
    let impulses: Vec<f64> = walk.steps.iter().flat_map(|s| s.foot_impulse).collect();
    d.set_item("foot_impulse", impulses)?;
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
pub struct Rows {
    steps: Vec<usize>,
    status: Vec<String>,
    periodic: Vec<bool>,
    failure: Vec<Option<String>>,
    last: StepColumns,
}

impl Rows {
    /// No rows yet, of a model with `n` coordinates.
    #[must_use]
    pub fn new(n: usize) -> Self {
        Rows {
            steps: Vec::new(),
            status: Vec::new(),
            periodic: Vec::new(),
            failure: Vec::new(),
            last: StepColumns::new(n),
        }
    }

    /// Append `o`.
    pub fn push(&mut self, o: &Outcome) {
        self.steps.push(o.steps);
        self.status
            .push(status(o.failure.as_ref(), o.periodic).to_owned());
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
