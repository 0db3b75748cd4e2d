//! `sweep(...)`: walks over a grid of `mu0` for one or more chains (`T_set` for the active
//! walker, `phi` for the passive wheel), procedures (P1a)-(P5a) and (P1b)-(P5b), with the
//! command line's checks and results: without `restart` each `mu0` starts from the previous
//! `mu0`'s last post-impact state moved to the origin (from the initial condition after a
//! failure), as `walker::sweep::sweep_chains`; with `restart` every point starts from the
//! initial condition. The work runs in chunks of `mu0` values (chains in parallel), so that
//! Ctrl-C is seen between chunks.

use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;
use walker::model::{Kind, Model, Runtime};
use walker::setup::{self, Overrides, Setup};
use walker::sim::{SimConfig, WalkLimits, walk};
use walker::sweep::mu0_grid;

use crate::chunks::in_chunks;
use crate::error::{ArgError, check};
use crate::options;
use crate::table::{Outcome, Rows};

/// The most chains a sweep may have, as the command line's.
pub const MAX_SWEEP_CHAINS: usize = 64;

/// The most points a sweep may have in all, as the command line's.
pub const MAX_SWEEP_POINTS: usize = 100_000;

/// `mu0` values walked per chain between two checks for Ctrl-C.
const CHUNK: usize = 4;

/// A chain of a sweep on its way along the `mu0` grid.
struct Chain {
    value: f64,
    initial: [f64; 8],
    state: [f64; 8],
    points: Vec<Outcome>,
}

/// The model of chain value `c` at `mu0`.
fn make(setup: &Setup, c: f64, mu0: f64) -> Model {
    let base = setup.runtime;
    let r = if setup.kind == Kind::ActiveLevel {
        Runtime {
            t_set: c,
            mu0,
            ..base
        }
    } else {
        Runtime {
            phi: c,
            mu0,
            ..base
        }
    };
    setup.model_with(r)
}

/// Walk `chain` over `mu0s`, each from the previous steady state (procedure P4a) or, with
/// `restart`, from the initial condition.
fn advance(
    setup: &Setup,
    cfg: &SimConfig,
    limits: &WalkLimits,
    restart: bool,
    chain: &mut Chain,
    mu0s: &[f64],
) {
    for &mu0 in mu0s {
        let start = if restart { chain.initial } else { chain.state };
        let w = walk(&make(setup, chain.value, mu0), cfg, start, limits);
        chain.state = match (&w.failure, w.last_state()) {
            (None, Some(mut s)) => {
                s[0] = 0.0;
                s[1] = 0.0;
                s
            }
            _ => chain.initial,
        };
        chain.points.push(Outcome::of(w));
    }
}

/// Run a sweep and return its rows (`chain`, `mu0`, then [`Rows`]' columns).
///
/// # Errors
/// `ValueError` naming a bad argument and its valid range.
#[pyfunction]
#[pyo3(signature = (*, scene, mu0_from, mu0_to, mu0_step, t_set, phi, restart, c, friction,
    impact, method, rtol, atol, duration, max_steps, until_periodic))]
#[allow(clippy::too_many_arguments)]
pub fn sweep<'py>(
    py: Python<'py>,
    scene: &str,
    mu0_from: f64,
    mu0_to: f64,
    mu0_step: f64,
    t_set: Vec<f64>,
    phi: Vec<f64>,
    restart: bool,
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
    let ov = Overrides {
        mu0: Some(mu0_from.max(0.0)),
        c,
        t_set: t_set.first().copied(),
        phi: phi.first().copied(),
        friction: options::friction(friction)?,
        impact: options::impact(impact)?,
    };
    let setup = options::setup(scene, &ov)?;
    let cfg = options::config(method, rtol, atol)?;
    let limits = options::limits(Some(duration), max_steps, until_periodic)?;
    check("mu0_from", mu0_from, mu0_from >= 0.0, "finite and >= 0")?;
    check(
        "mu0_to",
        mu0_to,
        mu0_to >= mu0_from,
        "finite and >= mu0_from",
    )?;
    check("mu0_step", mu0_step, mu0_step > 0.0, "finite and > 0")?;
    let active = setup.kind == Kind::ActiveLevel;
    let (chain_arg, chains) = if active {
        ("t_set", t_set)
    } else {
        ("phi", phi)
    };
    if chains.len() > MAX_SWEEP_CHAINS {
        return Err(ArgError::new(
            chain_arg,
            format!("{} values: at most {MAX_SWEEP_CHAINS} chains", chains.len()),
        )
        .into());
    }
    // Count the points before making them, as the command line does (`mu0_grid`'s count).
    let per_chain = ((mu0_to - mu0_from) / mu0_step + 1e-9).floor() + 1.0;
    let total = per_chain * chains.len().max(1) as f64;
    if total > MAX_SWEEP_POINTS as f64 {
        return Err(ArgError::new(
            "mu0_step",
            format!(
                "{mu0_step:e} gives {total:.3e} points; at most {MAX_SWEEP_POINTS} points in all"
            ),
        )
        .into());
    }
    let grid = mu0_grid(mu0_from, mu0_to, mu0_step);
    let base = setup.runtime;
    let values = if chains.is_empty() {
        vec![if active { base.t_set } else { base.phi }]
    } else {
        chains
    };
    let mut state: Vec<Chain> = Vec::with_capacity(values.len());
    for &value in &values {
        let r = if active {
            Runtime {
                t_set: value,
                ..base
            }
        } else {
            Runtime { phi: value, ..base }
        };
        setup::validate(&setup.physical, &r).map_err(ArgError::from)?;
        let m = make(&setup, value, 0.0);
        let initial = m.initial_state(m.default_omega0());
        state.push(Chain {
            value,
            initial,
            state: initial,
            points: Vec::with_capacity(grid.len()),
        });
    }
    in_chunks(py, &mut state, grid.len(), CHUNK, |chains, range| {
        chains
            .par_iter_mut()
            .for_each(|ch| advance(&setup, &cfg, &limits, restart, ch, &grid[range.clone()]));
    })?;
    let mut rows = Rows::default();
    let (mut chain_col, mut mu0_col) = (Vec::new(), Vec::new());
    for ch in &state {
        for (o, &mu0) in ch.points.iter().zip(&grid) {
            chain_col.push(ch.value);
            mu0_col.push(mu0);
            rows.push(o);
        }
    }
    let d = rows.into_dict(py)?;
    d.set_item("chain", chain_col)?;
    d.set_item("mu0", mu0_col)?;
    Ok(d)
}

#[cfg(test)]
mod tests {
    use super::*;
    use walker::sweep::sweep_chains;

    /// The chunked sweep walks exactly what `walker::sweep::sweep_chains` (the command line's
    /// sweep) walks, in both modes, across chunk boundaries and through failures: `T_set = 0.2`
    /// lifts off for `mu0 <= 0.4` over 5 s walks and walks from `mu0 = 0.5` on (measured), so the
    /// continuation's reset to the initial condition after a failure is exercised.
    #[test]
    fn chunked_chains_equal_the_librarys_sweep_with_and_without_restart() {
        let setup = Setup::active_level();
        let cfg = SimConfig::default();
        let limits = WalkLimits {
            max_steps: 1000,
            duration: 5.0,
            record: false,
            periodic: None,
        };
        let grid = mu0_grid(0.0, 1.0, 0.1);
        let chains = [0.2, 0.3];
        let initial = |c: f64| {
            let m = make(&setup, c, 0.0);
            m.initial_state(m.default_omega0())
        };
        for restart in [false, true] {
            let want = sweep_chains(
                &chains,
                |c, mu0| make(&setup, c, mu0),
                &cfg,
                &grid,
                initial,
                &limits,
                restart,
                &|| {},
            );
            for (&value, want) in chains.iter().zip(&want) {
                let mut ch = Chain {
                    value,
                    initial: initial(value),
                    state: initial(value),
                    points: Vec::new(),
                };
                for part in grid.chunks(CHUNK) {
                    advance(&setup, &cfg, &limits, restart, &mut ch, part);
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
