//! `walker simulate --floor FILE | --mu0-steps LIST` and `walker survive`: the floor of a
//! walk (its friction and slope per step) from its flags, walks on it, and the survival report of a batch (`docs/floors.md`).
//! The library checks the floor ([`walker::floor`], the file's own checks in
//! `walker_scene::floor`) and the counts ([`walker::request::survive_counts`]); errors are
//! named here by their flags (exit code 2).

use std::fmt::Write as _;
use std::path::Path;

use walker::floor::{
    FloorError, FloorFile, FloorPlan, FloorSpec, FloorWalker, SurviveReport, survive,
};
use walker::request::{Field, MAX_STEPS, MAX_WALK_INDEX, MAX_WALKS};
use walker::setup::Setup;
use walker::sim::{SimConfig, Walk, WalkLimits};
use walker::vector::Vector;

use crate::input::InputError;

/// The floor of `--floor FILE`, or of `--mu0-steps LIST` and `--phi-steps LIST` (either or
/// both), not with `--mu0` ([`walker::request::floor_once`]); `None` without any.
///
/// # Errors
/// A file with a list; `--mu0` with a floor; a floor file that cannot be read or has a bad
/// value (named by file, line, column and field); a list that is not numbers each `> 0` (mu0)
/// or finite (phi).
pub fn floor_of(
    floor: Option<&Path>,
    mu0_steps: Option<&str>,
    phi_steps: Option<&str>,
    mu0: Option<f64>,
) -> Result<Option<FloorPlan>, InputError> {
    walker::request::floor_once(floor.is_some(), mu0_steps.is_some(), mu0.is_some())?;
    if let Some(path) = floor {
        if phi_steps.is_some() {
            return Err(InputError::new(
                "phi-steps",
                "cannot be given with --floor: each sets the floor; give one (a floor file \
                 may give phi)",
            ));
        }
        let file =
            FloorFile::from_file(path).map_err(|e| InputError::new("floor", e.to_string()))?;
        return Ok(Some(file.spec));
    }
    let list = |flag: &str, name: &str, text: &str| {
        text.split(',')
            .enumerate()
            .map(|(i, t)| {
                t.trim().parse::<f64>().map_err(|_| {
                    InputError::new(
                        flag,
                        format!(
                            "{name}[{i}] = {}: not a number; give {name} per step as \
                             0.4,0.4,0.05 (each {})",
                            walker::request::shown::text(t),
                            if name == "mu0" { "> 0" } else { "finite" }
                        ),
                    )
                })
            })
            .collect::<Result<Vec<f64>, _>>()
    };
    let mu0 = mu0_steps
        .map(|t| {
            FloorSpec::steps(&list("mu0-steps", "mu0", t)?)
                .map_err(|e| InputError::new("mu0-steps", e.to_string()))
        })
        .transpose()?;
    let phi = phi_steps
        .map(|t| {
            FloorSpec::phi_steps(&list("phi-steps", "phi", t)?)
                .map_err(|e| InputError::new("phi-steps", e.to_string()))
        })
        .transpose()?;
    Ok((mu0.is_some() || phi.is_some()).then_some(FloorPlan { mu0, phi }))
}

/// The flag that gave a walk's floor (`--floor` if `from_file`, else `--mu0-steps` or
/// `--phi-steps`), after checking that `--set` and `--phi` do not also give what the floor
/// sets ([`params_once`]).
///
/// # Errors
/// As [`params_once`].
pub fn flag_of(
    setup: &Setup,
    set: &[String],
    phi: Option<f64>,
    floor: &FloorPlan,
    from_file: bool,
) -> Result<&'static str, InputError> {
    let (flag, field) = if from_file {
        ("floor", Field::Floor)
    } else if floor.mu0.is_some() {
        ("mu0-steps", Field::Mu0Steps)
    } else {
        ("phi-steps", Field::Mu0Steps)
    };
    params_once(setup, set, phi, floor, field)?;
    Ok(flag)
}

/// Checks that `--set` does not also give the friction coefficient or the slope that the
/// floor (given by `field`: [`Field::Floor`] or a list) sets per step, nor `--phi` (`phi`) the
/// slope. What the floor does not set, the flags may give.
///
/// # Errors
/// `--set` gives the model's `mu0` or slope parameter that the floor sets, or `--phi` the
/// slope (the error names the flag and the floor's).
pub fn params_once(
    setup: &Setup,
    set: &[String],
    phi: Option<f64>,
    floor: &FloorPlan,
    field: Field,
) -> Result<(), InputError> {
    let spec = setup.walker.spec();
    let assigned = crate::input::assignments("set", set)?;
    // The flag that gave what conflicts: the file, or the list of that quantity.
    let other = |list: &str| match field {
        Field::Floor => "--floor".to_owned(),
        _ => format!("--{list}"),
    };
    let parts = [
        (
            floor.mu0.is_some(),
            spec.mu0,
            "each sets mu0; give one",
            "mu0-steps",
        ),
        (
            floor.phi.is_some(),
            spec.slope,
            "each sets phi; give one",
            "phi-steps",
        ),
    ];
    for (sets, index, why, list) in parts {
        let Some(i) = index.filter(|_| sets) else {
            continue;
        };
        let name = &spec.model.parameters[i].name.name;
        if assigned.iter().any(|(n, _)| n == name) {
            return Err(InputError::new(
                "set",
                format!("cannot be given with {}: {why}", other(list)),
            ));
        }
    }
    if floor.phi.is_some() && phi.is_some() {
        return Err(InputError::new(
            "phi",
            format!(
                "cannot be given with {}: each sets phi; give one",
                other("phi-steps")
            ),
        ));
    }
    Ok(())
}

/// A floor the walker cannot take, named by the flag that gave the floor.
fn floor_error(flag: &str, e: &FloorError) -> InputError {
    InputError::new(flag, e.to_string())
}

/// The walker of `setup` on `floor` (given by the flag `flag`).
///
/// # Errors
/// The floor cannot set the walker's friction ([`FloorWalker::new`]).
pub fn walker_on<'s>(
    setup: &'s Setup,
    floor: FloorPlan,
    flag: &str,
) -> Result<FloorWalker<'s>, InputError> {
    FloorWalker::new(setup, floor).map_err(|e| floor_error(flag, &e))
}

/// `walker simulate` on a floor: walk 0 of the floor (a random floor's first stream).
///
/// # Errors
/// As [`walker_on`].
pub fn simulate_on(
    setup: &Setup,
    floor: FloorPlan,
    flag: &str,
    start: &Vector,
    limits: &WalkLimits,
    cfg: &SimConfig,
) -> Result<Walk, InputError> {
    walker_on(setup, floor, flag)?
        .walk(0, cfg, start, limits)
        .map_err(|e| floor_error(flag, &e))
}

/// The counts of `walker survive` as typed: `--walks`, `--max-steps`, `--first-walk`.
#[derive(Clone, Copy, Debug)]
pub struct SurviveCounts<'a> {
    /// The number of walks.
    pub walks: &'a str,
    /// Each walk's step limit.
    pub max_steps: &'a str,
    /// The first walk's index.
    pub first_walk: &'a str,
}

/// `walker survive`: the walks `first_walk .. first_walk + walks` of at most `max_steps`
/// steps each on the floor, on all cores.
///
/// # Errors
/// A count out of its range or too many steps in all, or as [`walker_on`].
pub fn survive_on(
    setup: &Setup,
    floor: FloorPlan,
    start: &Vector,
    counts: &SurviveCounts<'_>,
    cfg: &SimConfig,
) -> Result<SurviveReport, InputError> {
    let walks = walker::request::count_text(Field::Walks, counts.walks, 1, MAX_WALKS)?;
    let steps = walker::request::count_text(Field::MaxSteps, counts.max_steps, 1, MAX_STEPS)?;
    let (walks, steps) = walker::request::survive_counts(walks as i128, steps as i128)?;
    let first = walker::request::count_text(
        Field::FirstWalk,
        counts.first_walk,
        0,
        MAX_WALK_INDEX as usize,
    )?;
    let range = walker::request::walk_range(first as i128, walks)?;
    let walker = walker_on(setup, floor, "floor")?;
    survive(&walker, cfg, start, range, steps).map_err(|e| floor_error("floor", &e))
}

/// The JSON report of `walker survive`: `{"max_steps", "outcomes": [{"walk", "steps",
/// "failure"}], "survival": {"walks", "failures", "censored", "curve", "mfpt",
/// "failures_by_kind"}}`.
#[must_use]
pub fn survive_json(r: &SurviveReport) -> serde_json::Value {
    serde_json::to_value(r).unwrap_or_default()
}

/// The most points of the survival curve the text report prints.
const TEXT_CURVE_POINTS: usize = 12;

/// A short text report of `walker survive`.
#[must_use]
pub fn survive_text(r: &SurviveReport) -> String {
    let s = &r.survival;
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{} walks of at most {} steps: {} failed, {} reached the limit",
        s.walks, r.max_steps, s.failures, s.censored
    );
    let _ = writeln!(
        out,
        "survival (Kaplan-Meier: fraction alive after k steps):"
    );
    let every = s.curve.len().div_ceil(TEXT_CURVE_POINTS).max(1);
    for (i, p) in s.curve.iter().enumerate() {
        if i % every == 0 || i + 1 == s.curve.len() {
            let _ = writeln!(
                out,
                "  k = {:7}  alive {:.4}  at risk {}",
                p.step, p.alive, p.at_risk
            );
        }
    }
    let m = &s.mfpt;
    let _ = writeln!(
        out,
        "mean first-passage time (steps before a failure):\n  restricted mean (lower bound): {:.2}",
        m.restricted_mean
    );
    if let Some(e) = &m.sample_mean {
        let _ = writeln!(
            out,
            "  sample mean: {:.2}, 95% interval [{:.2}, {:.2}]",
            e.estimate.unwrap_or(f64::NAN),
            e.lo,
            e.hi.unwrap_or(f64::INFINITY)
        );
    }
    let e = &m.exponential;
    match e.estimate {
        Some(x) => {
            let _ = writeln!(
                out,
                "  constant failure rate: {x:.2}, 95% interval [{:.2}, {:.2}] ({} failures in {} step attempts)",
                e.lo,
                e.hi.unwrap_or(f64::INFINITY),
                s.failures,
                m.attempts
            );
        }
        None => {
            let _ = writeln!(
                out,
                "  no failure in {} step attempts: above {:.2} with 95% confidence",
                m.attempts, e.lo
            );
        }
    }
    if !s.failures_by_kind.is_empty() {
        let _ = writeln!(out, "failures by kind: {}", s.failures_text(" ", ", "));
    }
    out
}
