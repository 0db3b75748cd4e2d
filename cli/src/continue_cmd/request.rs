//! The flags of `walker continue` checked and turned into the library's continuation problem:
//! the free parameter, its range, the fixed values of `--set name=value`, user points
//! (`--at`), and the switch to period-two branches at period doublings (`--period-two`).

use walker::continuation::{
    Branch, ContinuationError, ContinuationOptions, LabelKind, PaperWalker, continuation,
    period_two,
};
use walker::setup::Setup;
use walker::sim::SimConfig;
use walker_scene::Param;

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
    /// The walker with its fixed values.
    pub setup: Setup,
    /// The free parameter.
    pub param: Param,
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
}

/// The parameters that `--param` and `--set` accept, in words.
const NAMES: &str = "mu0, c, T_set, K_P, K_D, phi, m1, m2, l, I1, I2, g, alpha";

/// The parameter called `name` (its scene name, or `t-set`), named as `field` in errors.
fn param_named(field: &str, name: &str) -> Result<Param, InputError> {
    if name == "omega0" {
        return Err(InputError::new(
            field,
            "omega0 is the start of a walk, not a parameter of the Poincare map; use one of "
                .to_owned()
                + NAMES,
        ));
    }
    let name = if name == "t-set" { "T_set" } else { name };
    Param::from_name(name).ok_or_else(|| {
        InputError::new(
            field,
            format!("unknown parameter {name:?}; use one of {NAMES}"),
        )
    })
}

/// Set `param` to `value` in `setup` (the general kernels for a physical parameter, whose
/// fast kernels have Table 1 compiled in).
fn set(setup: &mut Setup, param: Param, value: f64) {
    if setup.physical.set(param, value) {
        setup.fast = false;
    } else {
        setup.runtime.set(param, value);
    }
}

impl Request {
    /// Check the flags of `walker continue` against the resolved scene `setup`.
    ///
    /// # Errors
    /// An unknown or absent parameter, a range outside the parameter's valid range or empty,
    /// a malformed or invalid `--set`, `--at` outside the range, `--max-step` outside (0, 1].
    #[allow(clippy::too_many_arguments, reason = "one argument per flag")]
    pub fn new(
        mut setup: Setup,
        param: &str,
        from: f64,
        to: f64,
        sets: &[String],
        at: &[f64],
        period_two: bool,
        max_step: Option<f64>,
    ) -> Result<Request, InputError> {
        let param = param_named("param", param)?;
        for (field, v) in [("from", from), ("to", to)] {
            if !param.accepts(v) {
                return Err(InputError::out_of_range(field, v, param.valid_range()));
            }
        }
        if from == to {
            return Err(InputError::new(
                "to",
                format!("{to}: must differ from --from"),
            ));
        }
        for s in sets {
            let Some((name, value)) = s.split_once('=') else {
                return Err(InputError::new("set", format!("{s:?}: must be NAME=VALUE")));
            };
            let p = param_named("set", name.trim())?;
            if p == param {
                return Err(InputError::new(
                    "set",
                    format!("{name} is the continued parameter (--param)"),
                ));
            }
            let v: f64 = value
                .trim()
                .parse()
                .map_err(|_| InputError::new("set", format!("{s:?}: {value:?} is not a number")))?;
            if !p.accepts(v) {
                return Err(InputError::new(
                    "set",
                    format!("{name}={v}: must be {}", p.valid_range()),
                ));
            }
            set(&mut setup, p, v);
        }
        setup
            .validate()
            .map_err(|e| InputError::new("set", e.to_string()))?;
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
            setup,
            param,
            from,
            to,
            at: at.to_vec(),
            period_two,
            max_step,
        })
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
    let walker = PaperWalker::new(req.setup.clone(), req.param, *cfg)
        .map_err(|e| InputError::new("param", e.to_string()))?;
    let mut opts = ContinuationOptions {
        user_points: req.at.clone(),
        ..ContinuationOptions::default()
    };
    if let Some(h) = req.max_step {
        opts.max_step = h;
        opts.initial_step = opts.initial_step.min(h);
    }
    let branch = continuation(&walker, req.from, req.to, &opts).map_err(|e| match e {
        ContinuationError::FamilyEverywhere { .. } | ContinuationError::EmptyRange { .. } => {
            ContinueError::Input(InputError::new("set", e.to_string()))
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
