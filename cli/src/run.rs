//! The commands' work between parsing and printing: validate what the library does not (the
//! flags' own ranges), build the model, and call the library.

use walker::model::{Kind, Runtime};
use walker::poincare::{FixedPoint, FixedPointError, FixedPointOptions, fixed_point};
use walker::setup::{self, Overrides, Setup};
use walker::sim::{SimConfig, Walk, WalkLimits, walk};
use walker::sweep::{mu0_grid, sweep_chains};

use crate::input::{InputError, check};
use crate::progress::Progress;
use crate::report::Chain;

/// The most steps a walk of `walker simulate` or a point of `walker sweep` may take
/// (`--max-steps`): every step of a walk is kept (and printed by `simulate`), so this bounds
/// the memory of a request (a step is about 200 bytes).
pub const MAX_STEPS: usize = 1_000_000;

/// The most chains (`--t-set` or `--phi` values) a sweep may have: without `--restart` each
/// chain runs on its own thread.
pub const MAX_SWEEP_CHAINS: usize = 64;

/// The most points a sweep may have in all (chains times `mu0` values).
pub const MAX_SWEEP_POINTS: usize = 100_000;

/// The longest scene file read (bytes): a scene is a few hundred bytes.
pub const MAX_SCENE_BYTES: u64 = 1 << 20;

/// The scene of `--scene` with the overrides of the flags. A scene FILE.toml must be a
/// regular file of at most [`MAX_SCENE_BYTES`] (not a device or a pipe, which could be read
/// without end).
///
/// # Errors
/// The scene file is not a regular file or too long; the scene is unknown or invalid; an
/// override is out of its range.
pub fn setup(scene: &str, ov: &Overrides) -> Result<Setup, InputError> {
    if scene.ends_with(".toml") {
        // A file that cannot be inspected is left to the scene reader, which names it.
        if let Ok(meta) = std::fs::metadata(scene) {
            if !meta.is_file() {
                return Err(InputError::new(
                    "scene",
                    format!("{scene} is not a regular file"),
                ));
            }
            if meta.len() > MAX_SCENE_BYTES {
                return Err(InputError::new(
                    "scene",
                    format!(
                        "{scene} has {} bytes; a scene file has at most {MAX_SCENE_BYTES}",
                        meta.len()
                    ),
                ));
            }
        }
    }
    Ok(Setup::resolve(scene, ov)?)
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

/// Run `walker simulate`.
///
/// # Errors
/// `omega0` is not finite, `duration` is not positive, or `max_steps` is above
/// [`MAX_STEPS`].
pub fn simulate(
    setup: &Setup,
    omega0: Option<f64>,
    limits: &WalkLimits,
    cfg: &SimConfig,
) -> Result<Walk, InputError> {
    let model = setup.model();
    let w0 = omega0.unwrap_or_else(|| model.default_omega0());
    check("omega0", w0, true, "finite")?;
    if limits.duration.is_nan() || limits.duration <= 0.0 {
        return Err(InputError::out_of_range("duration", limits.duration, "> 0"));
    }
    max_steps(limits.max_steps)?;
    Ok(walk(&model, cfg, model.initial_state(w0), limits))
}

/// Run `walker sweep` over `mu0` for each of `chains` (`T_set` or `phi` values; empty: the
/// scene's value).
///
/// # Errors
/// A `mu0` flag is out of range, a chain value is invalid, more than [`MAX_SWEEP_CHAINS`]
/// chains, more than [`MAX_SWEEP_POINTS`] points in all, or `max_steps` above [`MAX_STEPS`].
#[allow(clippy::too_many_arguments)]
pub fn sweep(
    setup: &Setup,
    chains: &[f64],
    mu0_from: f64,
    mu0_to: f64,
    mu0_step: f64,
    restart: bool,
    limits: &WalkLimits,
    cfg: &SimConfig,
) -> Result<Vec<Chain>, InputError> {
    check("mu0-from", mu0_from, mu0_from >= 0.0, "finite and >= 0")?;
    check(
        "mu0-to",
        mu0_to,
        mu0_to >= mu0_from,
        "finite and >= mu0-from",
    )?;
    check("mu0-step", mu0_step, mu0_step > 0.0, "finite and > 0")?;
    max_steps(limits.max_steps)?;
    let active = setup.kind == Kind::ActiveLevel;
    let chain_flag = if active { "t-set" } else { "phi" };
    if chains.len() > MAX_SWEEP_CHAINS {
        return Err(InputError::new(
            chain_flag,
            format!(
                "given {} times; at most {MAX_SWEEP_CHAINS} chains",
                chains.len()
            ),
        ));
    }
    // Count the points before making them: the grid is allocated by the request (the inputs
    // are finite and the step positive, so the count is a number, possibly infinite). The
    // count is `mu0_grid`'s.
    let per_chain = ((mu0_to - mu0_from) / mu0_step + 1e-9).floor() + 1.0;
    let total = per_chain * chains.len().max(1) as f64;
    if total > MAX_SWEEP_POINTS as f64 {
        return Err(InputError::new(
            "mu0-step",
            format!(
                "{mu0_step:e} gives {per_chain:.3e} mu0 values from mu0-from to mu0-to, \
                 {total:.3e} points for {} chain(s) of --{chain_flag}; at most \
                 {MAX_SWEEP_POINTS} points in all",
                chains.len().max(1)
            ),
        ));
    }
    let grid = mu0_grid(mu0_from, mu0_to, mu0_step);
    let base = setup.runtime;
    let chains: Vec<f64> = if chains.is_empty() {
        vec![if active { base.t_set } else { base.phi }]
    } else {
        chains.to_vec()
    };
    for &c in &chains {
        let r = if active {
            Runtime { t_set: c, ..base }
        } else {
            Runtime { phi: c, ..base }
        };
        setup::validate(&setup.physical, &r)?;
    }
    let make = |c: f64, mu0: f64| {
        let r = if active {
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
    };
    let initial = |c: f64| {
        let m = make(c, 0.0);
        m.initial_state(m.default_omega0())
    };
    let bar = Progress::new("sweep", chains.len() * grid.len());
    let res = sweep_chains(&chains, make, cfg, &grid, initial, limits, restart, &|| {
        bar.tick()
    });
    bar.finish();
    Ok(chains
        .iter()
        .zip(res)
        .map(|(&value, points)| Chain { value, points })
        .collect())
}

/// Run `walker fixed-point`: validate `omega0` (finite, `> 0`) and the scene (the Jacobian
/// kernels exist for Table 1 and the tanh law only), then search the cycle. A failed search is
/// a result, not an input error.
///
/// # Errors
/// `omega0` is out of range.
pub fn fixed_point_search(
    setup: &Setup,
    omega0: Option<f64>,
    cfg: &SimConfig,
) -> Result<Result<FixedPoint, FixedPointError>, InputError> {
    let model = setup.model();
    let mut opts = FixedPointOptions::for_model(&model);
    if let Some(w) = omega0 {
        opts.omega0 = check("omega0", w, w > 0.0, "finite and > 0")?;
    }
    Ok(fixed_point(&model, cfg, &opts))
}
