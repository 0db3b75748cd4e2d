//! `design(...)`: the run-time parameters that make the best periodic gait of a walker on its
//! floor, as `walker design` (the library's [`walker::design`]; `docs/design.md`); the
//! result is the command line's JSON.

use pyo3::prelude::*;
use walker::design::{
    DesignError, DesignRequest, GaitBounds, MAX_RESTARTS, Margins, Objective, Vary,
};

use crate::error::ArgError;
use crate::options;
use crate::walker_args::{self, overrides};

/// The most objective evaluations of one solve (`max_evaluations`), as the command line's
/// `--max-evaluations`.
pub const MAX_EVALUATIONS: usize = 10_000;

/// The objective named `name`, as the command line's `--objective`.
///
/// # Errors
/// Another name.
fn objective(name: &str) -> Result<Objective, ArgError> {
    match name {
        "specific_resistance" => Ok(Objective::SpecificResistance),
        "power" => Ok(Objective::Power),
        "friction" => Ok(Objective::Friction),
        "speed" => Ok(Objective::Speed),
        other => Err(ArgError::new(
            "objective",
            format!(
                "`{}`: must be one of specific_resistance, power, friction, speed",
                crate::error::echo(other)
            ),
        )),
    }
}

/// The keyword argument a design error is about.
fn named(e: &DesignError) -> String {
    match e {
        DesignError::Margin { which, .. } => format!("{which}_margin"),
        DesignError::MaxInput { .. }
        | DesignError::MaxInputCount { .. }
        | DesignError::NoInputsToBound { .. } => "max_input".into(),
        DesignError::Restarts { .. } => "restarts".into(),
        DesignError::NoInputs { .. } => "objective".into(),
        DesignError::NoMu0 { .. } => "model".into(),
        DesignError::Bound { which, .. } | DesignError::BoundOnObjective { which, .. } => {
            which.replace('-', "_")
        }
        DesignError::SpeedNeedsEffort { .. } | DesignError::NoInputsForPower { .. } => {
            "max_power".into()
        }
        DesignError::SpeedRange { .. } => "max_speed".into(),
        DesignError::NoSwingFoot { .. } => "clearance".into(),
        _ => "vary".into(),
    }
}

/// Design the gait and return the command line's JSON report as a string (`walker design
/// --json`: `status`, `value`, `parameters`, `gait`, `constraints`, `kkt_residual`, ..), or
/// `{"status": "failed", "reason"}` where the start has no periodic gait (the command line's
/// exit code 1). `vary` lists `(name, lo, hi, start)`, the start `None` for the model's value.
///
/// # Errors
/// `ValueError` naming a bad argument and its valid range.
#[pyfunction]
#[pyo3(signature = (*, scene, model, set, friction, impact, method, rtol, atol, vary, objective,
    multiplier_margin, friction_margin, normal_margin, ramp_margin, max_input, clearance,
    min_speed, max_speed, max_power, max_evaluations, tol, restarts, seed))]
#[allow(clippy::too_many_arguments)]
pub fn design(
    py: Python<'_>,
    scene: Option<&str>,
    model: Option<&str>,
    set: Vec<(String, f64)>,
    friction: Option<&str>,
    impact: Option<&str>,
    method: &str,
    rtol: Option<f64>,
    atol: Option<f64>,
    vary: Vec<(String, f64, f64, Option<f64>)>,
    objective: &str,
    multiplier_margin: f64,
    friction_margin: f64,
    normal_margin: f64,
    ramp_margin: f64,
    max_input: Vec<f64>,
    clearance: Option<f64>,
    min_speed: Option<f64>,
    max_speed: Option<f64>,
    max_power: Option<f64>,
    max_evaluations: i64,
    tol: f64,
    restarts: i64,
    seed: u64,
) -> PyResult<String> {
    let ov = overrides(None, None, None, None, friction, impact)?;
    let setup = walker_args::setup_released(py, scene, model, &ov, &set)?;
    let cfg = options::config(method, rtol, atol)?;
    let objective = self::objective(objective)?;
    let range = |arg: &str, n: i64, hi: usize, lo: i64| {
        if n >= lo && n <= hi as i64 {
            Ok(n as usize)
        } else {
            Err(ArgError::out_of_range(
                arg,
                n,
                &format!("a whole number in [{lo}, {hi}]"),
            ))
        }
    };
    let max_evaluations = range("max_evaluations", max_evaluations, MAX_EVALUATIONS, 1)?;
    let restarts = range("restarts", restarts, MAX_RESTARTS, 0)?;
    let tol = crate::error::check("tol", tol, tol > 0.0 && tol < 1.0, "in (0, 1)")?;
    let vary = vary
        .into_iter()
        .map(|(name, lo, hi, start)| {
            let start = start
                .or_else(|| setup.params.get(&name))
                .unwrap_or(f64::NAN);
            Vary {
                name,
                lo,
                hi,
                start,
            }
        })
        .collect();
    let req = DesignRequest {
        vary,
        objective,
        margins: Margins {
            multiplier: multiplier_margin,
            friction: friction_margin,
            normal: normal_margin,
            ramp: ramp_margin,
        },
        max_evaluations,
        tol,
        max_input,
        bounds: GaitBounds {
            clearance,
            min_speed,
            max_speed,
            max_power,
        },
    };
    // The request is checked before the work starts, so that a bad one is a `ValueError`.
    req.check(&setup, &cfg)
        .map_err(|e| ArgError::new(&named(&e), e.to_string()))?;
    let json = crate::chunks::abandonable(py, move || {
        let d = if restarts == 0 {
            walker::design::design(&setup, &cfg, &req)
        } else {
            walker::design::design_with_restarts(&setup, &cfg, &req, restarts, seed)
        };
        match d {
            Ok(d) => serde_json::to_string(&d).map_err(|e| e.to_string()),
            Err(DesignError::NoGaitAtStart { at, message }) => Ok(serde_json::json!({
                "status": "failed",
                "reason": format!("no periodic gait at the start ({at}): {message}"),
            })
            .to_string()),
            Err(e) => Err(e.to_string()),
        }
    })?;
    json.map_err(|e| ArgError::new("vary", e).into())
}
