//! The flags of `walker continue` checked and turned into the library's continuation problem:
//! the free parameter, its range, the fixed values of `--set name=value`, user points
//! (`--at`), and the switch to period-two branches at period doublings (`--period-two`).

use walker::continuation::{
    Branch, ContinuationError, ContinuationOptions, LabelKind, WalkerProblem, continuation,
    period_two,
};
use walker::setup::Setup;
use walker::sim::SimConfig;

use crate::input::InputError;

/// Why `walker continue` produced no branch.
#[derive(Debug, thiserror::Error)]
pub enum ContinueError {
    /// Invalid input (exit code 2).
    #[error(transparent)]
    Input(#[from] InputError),
    /// No fixed point to start from anywhere in the range (exit code 1).
    #[error(transparent)]
    NoBranch(ContinuationError),
}

impl ContinueError {
    /// The process's exit code: 2 for invalid input, 1 when no branch was found.
    #[must_use]
    pub fn exit_code(&self) -> u8 {
        match self {
            ContinueError::Input(_) => 2,
            ContinueError::NoBranch(_) => 1,
        }
    }
}

/// A checked request.
#[derive(Clone, Debug)]
pub struct Request {
    /// The walker with its fixed values (`--set`).
    pub setup: Setup,
    /// The free parameter's name.
    pub param: String,
    /// Start of the range.
    pub from: f64,
    /// End of the range.
    pub to: f64,
    /// User points (`--at`).
    pub at: Vec<f64>,
    /// Follow the period-two branch born at each period doubling.
    pub period_two: bool,
    /// The largest continuation step in the scaled arclength (`--max-step`).
    pub max_step: Option<f64>,
    /// The components of the start `--init` replaces: (index into `[q, qd]`, value).
    pub init: Vec<(usize, f64)>,
}

impl Request {
    /// Check the flags of `walker continue` against the resolved scene `setup` (with the
    /// values of `--set` in it).
    ///
    /// # Errors
    /// An unknown parameter or one of the start, a range outside the parameter's valid range
    /// or empty, `--at` outside the range, `--max-step` outside (0, 1].
    pub fn new(
        setup: Setup,
        param: &str,
        from: f64,
        to: f64,
        at: &[f64],
        period_two: bool,
        max_step: Option<f64>,
    ) -> Result<Request, InputError> {
        let param = if param == "t-set" { "T_set" } else { param };
        let spec = setup.walker.spec();
        let Some(index) = spec.parameter(param) else {
            let known: Vec<&str> = spec.dynamic_parameters().collect();
            return Err(InputError::new(
                "param",
                format!(
                    "unknown parameter {param:?} of model `{}`; use one of {}",
                    spec.name(),
                    known.join(", ")
                ),
            ));
        };
        let p = &spec.model.parameters[index];
        if p.stage == walker_scene::model::Stage::Start {
            return Err(InputError::new(
                "param",
                format!(
                    "{param} is the start of a walk, not a parameter of the Poincare map; use \
                     one of {}",
                    spec.dynamic_parameters().collect::<Vec<_>>().join(", ")
                ),
            ));
        }
        for (field, v) in [("from", from), ("to", to)] {
            if !p.range.contains(v) {
                return Err(InputError::out_of_range(
                    field,
                    v,
                    &format!("in {}", p.range),
                ));
            }
        }
        if from == to {
            return Err(InputError::new(
                "to",
                format!("{to}: must differ from --from"),
            ));
        }
        let (lo, hi) = (from.min(to), from.max(to));
        for &a in at {
            if !(a.is_finite() && a >= lo && a <= hi) {
                return Err(InputError::out_of_range(
                    "at",
                    a,
                    &format!("in [{lo}, {hi}]"),
                ));
            }
        }
        if let Some(h) = max_step
            && !(h.is_finite() && h > 0.0 && h <= 1.0)
        {
            return Err(InputError::out_of_range("max-step", h, "in (0, 1]"));
        }
        Ok(Request {
            param: param.to_owned(),
            setup,
            from,
            to,
            at: at.to_vec(),
            period_two,
            max_step,
            init: Vec::new(),
        })
    }

    /// The same request, its branch started from the model's start with `components`
    /// (index into `[q, qd]`, value) replaced: `--init`, checked by the caller
    /// ([`crate::run::start_components`]).
    #[must_use]
    pub fn with_init(mut self, components: Vec<(usize, f64)>) -> Request {
        self.init = components;
        self
    }
}

/// Follow the branch of the request, and the period-two branches born at its period
/// doublings if asked.
///
/// # Errors
/// The parameter is not one of this walker's ([`ContinueError::Input`], naming `--param`); a
/// family of cycles throughout the range ([`ContinueError::Input`], naming `--set`); no
/// fixed point anywhere in the range ([`ContinueError::NoBranch`]).
pub fn run(req: &Request, cfg: &SimConfig) -> Result<Vec<Branch>, ContinueError> {
    let walker = WalkerProblem::new(req.setup.clone(), &req.param, *cfg)
        .map_err(|e| InputError::new("param", e.to_string()))?
        .with_start(req.init.clone());
    let mut opts = ContinuationOptions {
        user_points: req.at.clone(),
        ..ContinuationOptions::default()
    };
    if let Some(h) = req.max_step {
        // `--max-step` is documented as (0, 1]: below the default smallest step, the smallest
        // step follows it down.
        opts.max_step = h;
        opts.initial_step = opts.initial_step.min(h);
        opts.min_step = opts.min_step.min(h);
    }
    let branch = continuation(&walker, req.from, req.to, &opts).map_err(|e| match e {
        ContinuationError::FamilyEverywhere { .. } | ContinuationError::EmptyRange { .. } => {
            ContinueError::Input(InputError::new("set", e.to_string()))
        }
        ContinuationError::InvalidOptions { .. } => {
            ContinueError::Input(InputError::new("max-step", e.to_string()))
        }
        e @ ContinuationError::NoSeed { .. } => ContinueError::NoBranch(e),
    })?;
    let mut out = Vec::new();
    if req.period_two {
        for pd in branch.labelled(LabelKind::PeriodDoubling) {
            if let Ok(b) = period_two(&walker, pd, req.from, req.to, &opts) {
                out.push(b);
            }
        }
    }
    out.insert(0, branch);
    Ok(out)
}
