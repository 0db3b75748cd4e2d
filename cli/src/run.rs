//! The commands' work between parsing and printing: check the request with the library's
//! checks ([`walker::request`]: ranges, limits, each parameter once), build the setup and the
//! model, and call the library.

use walker::model::Model;
use walker::poincare::{FixedPoint, FixedPointError, FixedPointOptions, fixed_point};
use walker::request::{Field, Role, SweepRange};
use walker::setup::{Overrides, Setup, SetupError};
use walker::sim::{SimConfig, Walk, WalkLimits, walk};
use walker::sweep::sweep_chains;
use walker::vector::Vector;

use crate::args::Common;
use crate::input::{InputError, assignments, check};
use crate::progress::Progress;
use crate::report::Chain;

/// The most steps a walk of `walker simulate` or a point of `walker sweep` may take
/// (`--max-steps`), the library's bound: every step of a walk is kept (and printed by
/// `simulate`), so this bounds the memory of a request (a step is about 200 bytes).
pub use walker::request::MAX_STEPS;

/// The most chains (`--t-set` or `--phi` values) a sweep may have, the library's bound:
/// without `--restart` each chain runs on its own thread.
pub use walker::request::MAX_SWEEP_CHAINS;

/// The most points a sweep may have in all (chains times swept values), the library's bound.
pub use walker::request::MAX_SWEEP_POINTS;

/// The longest walk of `walker simulate` or a point of `walker sweep` (`--duration`, s), the
/// library's bound.
pub use walker::request::MAX_DURATION;

/// The setup of `--scene` or `--model` with the overrides `ov`. A model file that is not one
/// of the shipped models is derived here.
///
/// # Errors
/// The file is not a regular file or too long; the scene is unknown or invalid; the model file
/// is invalid or cannot be derived; an override is unknown or out of its range.
pub fn setup(common: &Common, ov: &Overrides) -> Result<Setup, InputError> {
    let runtime = walker_load::runtime_source();
    if let Some(path) = &common.model {
        return Ok(Setup::from_model_file(path, ov, Some(&runtime))?);
    }
    let scene = common.scene.as_deref().unwrap_or_default();
    Ok(Setup::resolve(scene, ov, Some(&runtime))?)
}

/// `--max-steps` as typed, if it is a whole number in `[0, MAX_STEPS]`.
///
/// # Errors
/// Not a whole number (`1e30`, `-1`, `1.5`), or more than [`MAX_STEPS`].
pub fn max_steps(text: &str) -> Result<usize, InputError> {
    Ok(walker::request::count_text(
        Field::MaxSteps,
        text,
        0,
        MAX_STEPS,
    )?)
}

/// The limits of a walk of `walker simulate` or of a point of `walker sweep`: `--max-steps`
/// as typed, `--duration` in (0, [`MAX_DURATION`]] (`None`: the steps bound the walk) and
/// `--until-periodic` in (0, 1).
///
/// # Errors
/// One of them outside its range (the error names the flag).
pub fn limits(
    max_steps_text: &str,
    duration: Option<f64>,
    until_periodic: Option<f64>,
) -> Result<WalkLimits, InputError> {
    let n = max_steps(max_steps_text)?;
    Ok(walker::request::walk_limits(
        duration,
        n as i128,
        until_periodic,
    )?)
}

/// Checks that `--omega0` and a `--set` of the same start parameter are not both given.
///
/// # Errors
/// Both are given (the error names both).
pub fn omega0_once(setup: &Setup, common: &Common, omega0: Option<f64>) -> Result<(), InputError> {
    if omega0.is_none() {
        return Ok(());
    }
    let mut fields: Vec<Field> = assignments("set", &common.set)?
        .into_iter()
        .map(|(name, _)| Field::Parameter(name))
        .collect();
    fields.push(Field::StartParameter("omega0".to_owned()));
    Ok(walker::request::distinct_fields(
        setup.walker.spec(),
        &fields,
    )?)
}

/// Sets the paper's initial angular velocity `omega0` (a parameter of the start) where the
/// flag gives it.
///
/// # Errors
/// Not finite, not `ok`, or the model has no start parameter `omega0`.
pub fn set_omega0(
    setup: &mut Setup,
    omega0: Option<f64>,
    ok: impl Fn(f64) -> bool,
    must_be: &str,
) -> Result<(), InputError> {
    if let Some(w) = omega0 {
        check("omega0", w, ok(w), must_be)?;
        setup.set_start("omega0", w).map_err(|e| match e {
            SetupError::NoStartParameter { .. } => {
                InputError::new("omega0", format!("{e}; use --init NAME=VALUE"))
            }
            e => e.into(),
        })?;
    }
    Ok(())
}

/// The model of `setup`.
///
/// # Errors
/// Its friction law has no kernels.
pub fn model(setup: &Setup) -> Result<Model, InputError> {
    Ok(setup.model()?)
}

/// The start of a walk: the model's `[start]` with `--init NAME=VALUE` replacing components
/// (a coordinate or a velocity by name).
///
/// # Errors
/// A malformed pair, an unknown component, a component given twice, a value that is not
/// finite, or a stance foot moved off the floor ([`walker::request::start()`]).
pub fn start(model: &Model, init: &[String]) -> Result<Vector, InputError> {
    let pairs = assignments("init", init)?;
    Ok(walker::request::start(model, &pairs)?)
}

/// The components `--init NAME=VALUE` replaces in the model's `[start]`, as (index into
/// `[q, qd]`, value), checked as [`start`] checks them (on `model`, the walker at the values
/// it starts from).
///
/// # Errors
/// As [`start`].
pub fn start_components(model: &Model, init: &[String]) -> Result<Vec<(usize, f64)>, InputError> {
    let pairs = assignments("init", init)?;
    let components = walker::request::start_components(model.spec(), &pairs)?;
    let start = model.start_state_replacing(&components);
    walker::request::on_the_floor(model, &start, &components)?;
    Ok(components)
}

/// Run `walker simulate` from `start`.
///
/// # Errors
/// `duration` is not positive or above [`MAX_DURATION`] (an infinite duration is no limit),
/// or `max_steps` is above [`MAX_STEPS`].
pub fn simulate(
    model: &Model,
    start: &Vector,
    limits: &WalkLimits,
    cfg: &SimConfig,
) -> Result<Walk, InputError> {
    if limits.duration != f64::INFINITY {
        walker::request::duration(limits.duration)?;
    }
    walker::request::max_steps(limits.max_steps as i128)?;
    Ok(walk(model, cfg, start, limits))
}

/// The swept values and where they chain: `walker sweep`'s request.
#[derive(Clone, Debug)]
pub struct SweepRequest<'a> {
    /// The swept parameter.
    pub param: &'a str,
    /// First value.
    pub from: f64,
    /// Last value.
    pub to: f64,
    /// Increment.
    pub step: f64,
    /// The chain parameter (`T_set` or `phi`) and its values (`--t-set`, `--phi`).
    pub chains: Option<(&'a str, &'a [f64])>,
    /// Start every value from the initial condition.
    pub restart: bool,
    /// The parameters given by `--set` (the swept one may not be among them).
    pub set: Vec<String>,
}

/// Run `walker sweep` of `req.param` for each chain value; a point that does not continue
/// starts from its own model's `[start]` with the components `init` (index, value) replaced.
///
/// # Errors
/// An unknown swept parameter, or one also given as the chains or by `--set`; a range flag is
/// out of range, a chain value is invalid, more than [`MAX_SWEEP_CHAINS`] chains, more than
/// [`MAX_SWEEP_POINTS`] points in all ([`SweepRange::grid`]), `max_steps` above
/// [`MAX_STEPS`], or a point's model cannot be built.
pub fn sweep(
    setup: &Setup,
    init: &[(usize, f64)],
    req: &SweepRequest<'_>,
    limits: &WalkLimits,
    cfg: &SimConfig,
) -> Result<Vec<Chain>, InputError> {
    let from = req.from;
    walker::request::max_steps(limits.max_steps as i128)?;
    let spec = setup.walker.spec();
    let swept = setup
        .params
        .index(req.param)
        .map_err(|e| InputError::new("param", e.to_string()))?;
    let explicit = req.chains.filter(|(_, values)| !values.is_empty());
    // The chain's field: `--t-set` for `T_set`, `--phi` for the slope.
    let chain_field = |name: &str| {
        if name == "T_set" {
            Field::Role(Role::TSet)
        } else {
            Field::Role(Role::Slope)
        }
    };
    // Each parameter once: the swept one is not also set or chained (one of the two values
    // would be dropped silently).
    let mut given: Vec<(Field, usize)> = req
        .set
        .iter()
        .filter_map(|n| spec.parameter(n).map(|i| (Field::Parameter(n.clone()), i)))
        .collect();
    if let Some(i) = explicit.and_then(|(name, _)| spec.parameter(name)) {
        given.push((chain_field(explicit.map_or("T_set", |(n, _)| n)), i));
    }
    given.push((Field::Param, swept));
    walker::request::distinct(spec, &given)?;
    let (chain_param, chain_values): (Option<String>, Vec<f64>) = match explicit {
        Some((name, values)) => (Some(name.to_owned()), values.to_vec()),
        // Without chains asked for, the default chain is the scene's own value; when the
        // swept parameter is that one, there is no chain.
        None => match setup.default_chain() {
            Some((name, v)) if spec.parameter(&name) != Some(swept) => (Some(name), vec![v]),
            _ => (None, vec![f64::NAN]),
        },
    };
    let range = SweepRange {
        from,
        to: req.to,
        step: req.step,
    };
    // Counted before it is made: the library refuses a grid beyond its bound.
    let grid = range.grid(
        chain_values.len(),
        chain_field(chain_param.as_deref().unwrap_or("T_set")),
    )?;
    // Every point's model, built before any walk: a value out of its range or kernels that
    // cannot be prepared are input errors, named by the flag.
    let mut models = Vec::with_capacity(chain_values.len());
    for &c in &chain_values {
        let mut base = setup.params.clone();
        if let Some(name) = &chain_param {
            base.set(name, c)?;
        }
        let mut row = Vec::with_capacity(grid.len());
        for &v in &grid {
            let params = base.with(req.param, v).map_err(|e| {
                let field = if v == from { "from" } else { "to" };
                InputError::new(field, e.to_string())
            })?;
            row.push(setup.model_with(&params)?);
        }
        models.push(row);
    }
    let index = |c: f64, v: f64| {
        let i = chain_values
            .iter()
            .position(|&x| x.to_bits() == c.to_bits())
            .unwrap_or(0);
        let j = grid
            .iter()
            .position(|&x| x.to_bits() == v.to_bits())
            .unwrap_or(0);
        (i, j)
    };
    let make = |c: f64, v: f64| {
        let (i, j) = index(c, v);
        models[i][j].clone()
    };
    let initial = |m: &Model| m.start_state_replacing(init);
    let bar = Progress::new("sweep", chain_values.len() * grid.len());
    let res = sweep_chains(
        &chain_values,
        make,
        cfg,
        &grid,
        initial,
        limits,
        req.restart,
        &|| bar.tick(),
    );
    bar.finish();
    Ok(chain_values
        .iter()
        .zip(res)
        .map(|(&value, points)| Chain {
            param: chain_param.clone(),
            value,
            swept: req.param.to_owned(),
            points,
        })
        .collect())
}

/// Run `walker fixed-point` from `start` (the warm-up walk's start). A failed search is a
/// result, not an input error.
pub fn fixed_point_search(
    model: &Model,
    start: &Vector,
    cfg: &SimConfig,
) -> Result<FixedPoint, FixedPointError> {
    let opts = FixedPointOptions {
        start: *start,
        refine: true,
        full_multipliers: true,
        ..FixedPointOptions::for_model(model)
    };
    fixed_point(model, cfg, &opts)
}

/// Check the names of `walker fixed-point --sensitivities` before the search: each a run-time
/// parameter of the walker.
///
/// # Errors
/// [`InputError`] on `--sensitivities` naming the parameter and the valid names.
pub fn check_sensitivities(
    setup: &Setup,
    cfg: &SimConfig,
    names: &[&str],
) -> Result<(), InputError> {
    walker::sensitivity::check_parameters(setup, cfg, names).map_err(|e| match e {
        walker::sensitivity::SensitivityError::NotAParameter { name, model, known } => {
            InputError::new(
                "sensitivities",
                format!(
                    "{} is not a run-time parameter of model `{model}`; valid: {known}",
                    walker::request::shown::name(&name)
                ),
            )
        }
        other => InputError::new("sensitivities", other.to_string()),
    })
}
