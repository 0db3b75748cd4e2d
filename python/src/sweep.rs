//! `sweep(...)`: walks over a grid of one run-time parameter (`mu0` by default: procedures
//! (P1a)-(P5a) and (P1b)-(P5b)) for one or more chains (`T_set` or the slope `phi`), with the
//! command line's checks and results (`walker sweep`, `cli/src/run.rs`): without `restart` each
//! value starts from the previous value's last post-impact state moved to the origin (from the
//! start after a failure), as `walker::sweep::sweep_chains`; with `restart` every point starts
//! from the start. Every point's model is built before any walk (a value out of its range is an
//! input error). The chains walk in parallel with the GIL released; every walk asks before each
//! of its steps whether Ctrl-C was pressed (`crate::chunks`), so that it is seen within a step.
//! The swept parameter cannot also be a chain's.

use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;
use walker::model::Model;
use walker::request::{Field, Role, SweepRange};
use walker::setup::Setup;
use walker::sim::{SimConfig, Stopped, WalkLimits};
use walker::sweep::Carry;
use walker::vector::Vector;

use crate::chunks::{asked, stoppable};
use crate::error::{ArgError, keyword_of, mention};
use crate::options;
use crate::table::{Outcome, RESULT_COLUMNS, Rows, names_dict};
use crate::walker_args::{self, overrides};

/// A chain of a sweep on its way along the grid.
struct Chain {
    /// Where the next value starts.
    carry: Carry,
    points: Vec<Outcome>,
}

/// Walks `chain` through the models of consecutive values, as `walker::sweep::sweep_chains`
/// walks one chain ([`Carry`]: each value from the previous steady state moved to the origin,
/// from `initial(model)` at the first value, after a failure, and always with `restart`).
///
/// # Errors
/// `stop()` answered true (Ctrl-C): the chain stops where it is.
fn advance(
    models: &[Model],
    cfg: &SimConfig,
    limits: &WalkLimits,
    restart: bool,
    initial: &(dyn Fn(&Model) -> Vector + Sync),
    chain: &mut Chain,
    stop: &dyn Fn() -> bool,
) -> Result<(), Stopped> {
    for model in models {
        let w = chain
            .carry
            .walk_stoppable(model, cfg, limits, restart, initial, stop)?;
        chain.points.push(Outcome::of(w));
    }
    Ok(())
}

/// The names a caller gave the range's three values (`from_`, `to`, `step`, or the paper's
/// `mu0_from`, `mu0_to`, `mu0_step`): errors about them name them so.
#[derive(Clone, Debug, FromPyObject)]
pub struct RangeNames(pub String, pub String, pub String);

/// The chain parameter and its values: `t_set` chains `T_set`, `phi` the slope; neither, as
/// the command line: `T_set` where the model has one (Fig. 8), else its slope (Fig. 10), else
/// one chain without a parameter (its value NaN).
fn chains(
    setup: &Setup,
    t_set: Vec<f64>,
    phi: Vec<f64>,
) -> Result<(Option<String>, &'static str, Vec<f64>), ArgError> {
    let spec = setup.walker.spec();
    match (t_set.is_empty(), phi.is_empty()) {
        (false, false) => Err(ArgError::new(
            "phi",
            "give either t_set or phi values: they chain the sweep",
        )),
        (false, true) => Ok((Some("T_set".to_owned()), "t_set", t_set)),
        (true, false) => {
            let slope = spec.slope.ok_or_else(|| {
                ArgError::new(
                    "phi",
                    format!("model `{}` has no slope (its floor is level)", spec.name()),
                )
            })?;
            Ok((
                Some(spec.model.parameters[slope].name.name.clone()),
                "phi",
                phi,
            ))
        }
        (true, true) => Ok(match setup.default_chain() {
            Some((name, value)) => (Some(name), "chain", vec![value]),
            None => (None, "chain", vec![f64::NAN]),
        }),
    }
}

/// Run a sweep and return its rows (`chain`, `value`, then [`Rows`]' columns), the swept
/// parameter's name (`param`), the chain's (`chain_param`, or None) and the model's names.
///
/// # Errors
/// `ValueError` naming a bad argument and its valid range.
#[pyfunction]
#[pyo3(signature = (*, scene, model, set, init, param, from_, to, step, range_names, t_set,
    phi, restart, omega0, c, friction, impact, method, rtol, atol, duration, max_steps,
    until_periodic))]
#[allow(clippy::too_many_arguments)]
pub fn sweep<'py>(
    py: Python<'py>,
    scene: Option<&str>,
    model: Option<&str>,
    set: Vec<(String, f64)>,
    init: Vec<(String, f64)>,
    param: Option<String>,
    from_: f64,
    to: f64,
    step: f64,
    range_names: RangeNames,
    t_set: Vec<f64>,
    phi: Vec<f64>,
    restart: bool,
    omega0: Option<f64>,
    c: Option<f64>,
    friction: Option<&str>,
    impact: Option<&str>,
    method: &str,
    rtol: Option<f64>,
    atol: Option<f64>,
    duration: f64,
    max_steps: i64,
    until_periodic: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let RangeNames(from_name, to_name, step_name) = &range_names;
    let ov = overrides(None, c, None, None, friction, impact)?;
    let mut setup = walker_args::setup_released(py, scene, model, &ov, &set)?;
    walker_args::set_omega0(&mut setup, omega0, |_| true, "finite")?;
    let cfg = options::config(method, rtol, atol)?;
    let limits = options::limits(Some(duration), max_steps, until_periodic)?;
    let spec = std::sync::Arc::clone(setup.walker.spec());
    let param = param.unwrap_or_else(|| {
        spec.mu0.map_or_else(
            || "mu0".to_owned(),
            |i| spec.model.parameters[i].name.name.clone(),
        )
    });
    setup
        .params
        .index(&param)
        .map_err(|e| ArgError::new("param", e.to_string()))?;
    if RESULT_COLUMNS.contains(&param.as_str()) {
        return Err(ArgError::new(
            "param",
            format!("{param:?} is the name of a result column; it cannot be swept here"),
        )
        .into());
    }
    let (mut chain_param, chain_arg, mut values) = chains(&setup, t_set, phi)?;
    if chain_param.as_deref() == Some(param.as_str()) {
        // The swept parameter cannot also be held at the chains' values: each chain would
        // walk the same values and report a chain value it did not walk.
        if chain_arg != "chain" {
            return Err(ArgError::new(
                chain_arg,
                format!(
                    "{param} is the swept parameter (param); it cannot also be given as {chain_arg}"
                ),
            )
            .into());
        }
        (chain_param, values) = (None, vec![f64::NAN]);
    }
    // The ends in the parameter's range before the count, so that a value far out of it is
    // named as itself, not as a step that would give too many points.
    for (name, v) in [(from_name, from_), (to_name, to)] {
        if v.is_finite() {
            setup
                .params
                .with(&param, v)
                .map_err(|e| ArgError::new(name, ArgError::from(e).message))?;
        }
    }
    // The range and the count of points, checked before any is made (the library's check
    // for every front end), named by the caller's names of the range.
    let chain_field = Field::Role(if chain_arg == "phi" {
        Role::Slope
    } else {
        Role::TSet
    });
    let grid = SweepRange {
        from: from_,
        to,
        step,
    }
    .grid(values.len(), chain_field)
    .map_err(|e| {
        let arg = match e.field() {
            Field::From => from_name.clone(),
            Field::To => to_name.clone(),
            Field::Step => step_name.clone(),
            Field::Role(_) => chain_arg.to_owned(),
            other => keyword_of(other),
        };
        ArgError::new(&arg, e.detail(&mention))
    })?;
    let init = walker_args::check_init(&spec, &init)?;
    let initial = |m: &Model| m.start_state_replacing(&init);
    // Every point's model, built before any walk: a value out of its range or kernels that
    // cannot be prepared are input errors.
    let mut models: Vec<Vec<Model>> = Vec::with_capacity(values.len());
    for &value in &values {
        let mut base = setup.params.clone();
        if let Some(name) = &chain_param {
            base.set(name, value)
                .map_err(|e| ArgError::from(e).named(chain_arg))?;
        }
        let mut row = Vec::with_capacity(grid.len());
        for &v in &grid {
            let params = base.with(&param, v).map_err(|e| {
                let arg = if v == from_ { from_name } else { to_name };
                ArgError::new(arg, e.to_string())
            })?;
            let model = setup.model_with(&params).map_err(ArgError::from)?;
            walker_args::on_the_floor(&model, &initial(&model), &init)?;
            row.push(model);
        }
        models.push(row);
    }
    let mut state: Vec<Chain> = values
        .iter()
        .map(|_| Chain {
            carry: Carry::default(),
            points: Vec::with_capacity(grid.len()),
        })
        .collect();
    let done = stoppable(py, |stop| {
        state
            .par_iter_mut()
            .zip(&models)
            .map(|(ch, row)| advance(row, &cfg, &limits, restart, &initial, ch, &|| asked(stop)))
            .collect::<Result<Vec<()>, Stopped>>()
    })?;
    if done.is_err() {
        return Err(pyo3::exceptions::PyKeyboardInterrupt::new_err(()));
    }
    let mut rows = Rows::new(spec.n);
    let (mut chain_col, mut value_col) = (Vec::new(), Vec::new());
    for (ch, &c) in state.iter().zip(&values) {
        for (o, &v) in ch.points.iter().zip(&grid) {
            chain_col.push(c);
            value_col.push(v);
            rows.push(o);
        }
    }
    let d = rows.into_dict(py)?;
    d.set_item("chain", chain_col)?;
    d.set_item("value", value_col)?;
    d.set_item("param", &param)?;
    d.set_item("chain_param", chain_param)?;
    names_dict(&d, &spec)?;
    Ok(d)
}

#[cfg(test)]
mod tests {
    use super::*;
    use walker::setup::Overrides;
    use walker::sweep::{mu0_grid, sweep_chains};

    /// The chunked sweep walks exactly what `walker::sweep::sweep_chains` (the command line's
    /// sweep) walks, in both modes, across chunk boundaries and through failures: `T_set = 0.2`
    /// lifts off for `mu0 <= 0.4` over 5 s walks and walks from `mu0 = 0.5` on (measured), so the
    /// continuation's reset to the start after a failure is exercised.
    #[test]
    fn chunked_chains_equal_the_librarys_sweep_with_and_without_restart() {
        let setup = walker_args::setup(None, None, &Overrides::default(), &[]).expect("scene");
        let cfg = SimConfig::default();
        let limits = WalkLimits {
            max_steps: 1000,
            duration: 5.0,
            record: false,
            periodic: None,
        };
        let grid = mu0_grid(0.0, 1.0, 0.1);
        let chains = [0.2, 0.3];
        let make = |c: f64, mu0: f64| {
            let p = setup
                .params
                .with("T_set", c)
                .and_then(|p| p.with("mu0", mu0));
            setup
                .model_with(&p.expect("in range"))
                .expect("compiled kernels")
        };
        let start = make(0.3, 0.4).start_state();
        for restart in [false, true] {
            let want = sweep_chains(
                &chains,
                make,
                &cfg,
                &grid,
                |_| start,
                &limits,
                restart,
                &|| {},
            );
            for (&value, want) in chains.iter().zip(&want) {
                let models: Vec<Model> = grid.iter().map(|&v| make(value, v)).collect();
                let mut ch = Chain {
                    carry: Carry::default(),
                    points: Vec::new(),
                };
                // In parts, as a sweep that goes on after being asked whether to stop.
                for part in models.chunks(3) {
                    advance(part, &cfg, &limits, restart, &|_| start, &mut ch, &|| false)
                        .expect("never stopped");
                }
                let got: Vec<_> = ch
                    .points
                    .iter()
                    .map(|o| (o.steps, o.last, o.failure.clone(), o.periodic))
                    .collect();
                let want: Vec<_> = want
                    .iter()
                    .map(|p| (p.steps, p.last, p.failure.clone(), p.periodic))
                    .collect();
                assert_eq!(got, want, "T_set = {value}, restart = {restart}");
            }
            let low = &want[0];
            assert!(low[0].failure.is_some() && low[10].failure.is_none());
        }
    }
}
