//! The commands' work between parsing and printing: validate what the library does not (the
//! flags' own ranges), build the setup and the model, and call the library.

use walker::model::InitError;
use walker::model::Model;
use walker::poincare::{FixedPoint, FixedPointError, FixedPointOptions, fixed_point};
use walker::setup::{Overrides, Setup, SetupError};
use walker::sim::{SimConfig, Walk, WalkLimits, walk};
use walker::sweep::{mu0_grid, sweep_chains};
use walker::vector::Vector;

use crate::args::Common;
use crate::input::{InputError, assignments, check};
use crate::progress::Progress;
use crate::report::Chain;

/// The most steps a walk of `walker simulate` or a point of `walker sweep` may take
/// (`--max-steps`): every step of a walk is kept (and printed by `simulate`), so this bounds
/// the memory of a request (a step is about 200 bytes).
pub const MAX_STEPS: usize = 1_000_000;

/// The most chains (`--t-set` or `--phi` values) a sweep may have: without `--restart` each
/// chain runs on its own thread.
pub const MAX_SWEEP_CHAINS: usize = 64;

/// The most points a sweep may have in all (chains times swept values).
pub const MAX_SWEEP_POINTS: usize = 100_000;

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

/// `--max-steps` if it is at most [`MAX_STEPS`].
///
/// # Errors
/// More than [`MAX_STEPS`].
pub fn max_steps(n: usize) -> Result<usize, InputError> {
    if n > MAX_STEPS {
        return Err(InputError::new(
            "max-steps",
            format!("{n}: must be in [0, {MAX_STEPS}]"),
        ));
    }
    Ok(n)
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
/// A malformed pair, an unknown component, or a value that is not finite.
pub fn start(model: &Model, init: &[String]) -> Result<Vector, InputError> {
    let pairs = assignments("init", init)?;
    let components = model.spec().start_components(&pairs).map_err(|e| match e {
        InitError::NotFinite { value, .. } => InputError::out_of_range("init", value, "finite"),
        e => InputError::new("init", e.to_string()),
    })?;
    Ok(model.start_state_replacing(&components))
}

/// Run `walker simulate` from `start`.
///
/// # Errors
/// `duration` is not positive, or `max_steps` is above [`MAX_STEPS`].
pub fn simulate(
    model: &Model,
    start: &Vector,
    limits: &WalkLimits,
    cfg: &SimConfig,
) -> Result<Walk, InputError> {
    if limits.duration.is_nan() || limits.duration <= 0.0 {
        return Err(InputError::out_of_range("duration", limits.duration, "> 0"));
    }
    max_steps(limits.max_steps)?;
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
}

/// Run `walker sweep` of `req.param` for each chain value; a point that does not continue
/// starts from its own model's `[start]` with the components `init` (index, value) replaced.
///
/// # Errors
/// A range flag is out of range, a chain value is invalid, more than [`MAX_SWEEP_CHAINS`]
/// chains, more than [`MAX_SWEEP_POINTS`] points in all, `max_steps` above [`MAX_STEPS`], or a
/// point's model cannot be built.
pub fn sweep(
    setup: &Setup,
    init: &[(usize, f64)],
    req: &SweepRequest<'_>,
    limits: &WalkLimits,
    cfg: &SimConfig,
) -> Result<Vec<Chain>, InputError> {
    let (from, to, step) = (req.from, req.to, req.step);
    check("from", from, true, "finite")?;
    check("to", to, to >= from, "finite and >= from")?;
    check("step", step, step > 0.0, "finite and > 0")?;
    max_steps(limits.max_steps)?;
    let (chain_param, chain_values): (Option<String>, Vec<f64>) = match req.chains {
        Some((name, values)) if !values.is_empty() => (Some(name.to_owned()), values.to_vec()),
        _ => match setup.default_chain() {
            Some((name, v)) => (Some(name), vec![v]),
            None => (None, vec![f64::NAN]),
        },
    };
    if chain_values.len() > MAX_SWEEP_CHAINS {
        return Err(InputError::new(
            crate::input::flag(chain_param.as_deref().unwrap_or("chain")),
            format!(
                "given {} times; at most {MAX_SWEEP_CHAINS} chains",
                chain_values.len()
            ),
        ));
    }
    // Count the points before making them: the grid is allocated by the request (the inputs
    // are finite and the step positive, so the count is a number, possibly infinite). The
    // count is `mu0_grid`'s.
    let per_chain = ((to - from) / step + 1e-9).floor() + 1.0;
    let total = per_chain * chain_values.len() as f64;
    if total > MAX_SWEEP_POINTS as f64 {
        return Err(InputError::new(
            "step",
            format!(
                "{step:e} gives {per_chain:.3e} values from --from to --to, {total:.3e} points \
                 for {} chain(s); at most {MAX_SWEEP_POINTS} points in all",
                chain_values.len()
            ),
        ));
    }
    let grid = mu0_grid(from, to, step);
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
        ..FixedPointOptions::for_model(model)
    };
    fixed_point(model, cfg, &opts)
}
