//! `walker mfpt`: the mean first-passage time of a walker on a random floor by the
//! Markov-chain (mesh) approximation ([`walker::floor::mesh`], `docs/floors.md`). The library
//! checks the settings and names them in its own words; errors are named here by their flags
//! (exit code 2).

use std::fmt::Write as _;

use walker::floor::mesh::{
    MAX_POINTS, MAX_SAMPLES, MeshBox, MeshError, MeshOptions, MeshReport, mesh_mfpt, start_setup,
};
use walker::floor::{FloorPlan, Survival, survive};
use walker::poincare::Section;
use walker::request::{Field, MAX_STEPS, MAX_WALKS, shown};
use walker::setup::Setup;
use walker::sim::SimConfig;

use crate::floor::walker_on;
use crate::input::InputError;

/// The flag of a mesh setting (the library's `points` is `--mesh`).
fn flag(field: &str) -> &str {
    match field {
        "points" => "mesh",
        "samples" => "samples",
        "box_scale" => "box-scale",
        "half_widths" => "half-widths",
        _ => "floor",
    }
}

/// A mesh error named by its flag.
fn named(e: &MeshError) -> InputError {
    let field = match e {
        MeshError::OutOfRange { field, .. } | MeshError::TooLarge { field, .. } => flag(field),
        _ => "floor",
    };
    InputError::new(field, e.to_string())
}

/// A whole number of `--flag` in `[low, high]`.
fn count(name: &str, text: &str, low: usize, high: usize) -> Result<usize, InputError> {
    let t = text.trim();
    t.parse::<usize>()
        .ok()
        .filter(|n| !t.starts_with('+') && (low..=high).contains(n))
        .ok_or_else(|| {
            InputError::new(
                name,
                format!(
                    "{}: must be a whole number in [{low}, {high}]",
                    shown::text(text)
                ),
            )
        })
}

/// A number of `--flag`.
fn number(name: &str, text: &str, must_be: &str) -> Result<f64, InputError> {
    text.trim()
        .parse::<f64>()
        .map_err(|_| InputError::new(name, format!("{}: must be {must_be}", shown::text(text))))
}

/// The mesh settings of the flags `--mesh`, `--samples`, `--box-scale`, `--half-widths`.
///
/// # Errors
/// A value that is not a number or is outside its range, or both box flags given.
pub fn options(
    mesh: &str,
    samples: &str,
    box_scale: Option<&str>,
    half_widths: Option<&str>,
) -> Result<MeshOptions, InputError> {
    let bounds = match (box_scale, half_widths) {
        (Some(_), Some(_)) => {
            return Err(InputError::new(
                "half-widths",
                "cannot be given with --box-scale: each sets the box; give one",
            ));
        }
        (_, Some(list)) => MeshBox::HalfWidths(
            list.split(',')
                .map(|t| number("half-widths", t, "a number > 0 (one per coordinate)"))
                .collect::<Result<_, _>>()?,
        ),
        (Some(s), None) => MeshBox::Spread {
            scale: number("box-scale", s, "a number in (0, 100]")?,
        },
        (None, None) => MeshOptions::default().bounds,
    };
    let opts = MeshOptions {
        points: count("mesh", mesh, 2, MAX_POINTS)?,
        samples: count("samples", samples, 1, MAX_SAMPLES)?,
        bounds,
    };
    opts.check().map_err(|e| named(&e))?;
    Ok(opts)
}

/// The walks and the step limit of `--walks` and `--max-steps`.
///
/// # Errors
/// A count outside its range, or too many steps in all.
pub fn walk_counts(walks: &str, max_steps: &str) -> Result<(usize, usize), InputError> {
    let walks = walker::request::count_text(Field::Walks, walks, 1, MAX_WALKS)?;
    let steps = walker::request::count_text(Field::MaxSteps, max_steps, 1, MAX_STEPS)?;
    Ok(walker::request::survive_counts(
        walks as i128,
        steps as i128,
    )?)
}

/// `walker mfpt`: the mesh estimate of the walker of `setup` on `floor`, and, with `check`
/// (walks, step limit), the statistics of that many walks from the mesh's fixed point.
///
/// On a floor that sets the slope the walker's own `phi` is set to the slope the chain starts
/// on ([`start_setup`]), so that the walks start from the chain's start.
///
/// # Errors
/// The floor cannot carry the walker, a `steps` floor, a mesh too large, or no gait.
pub fn mfpt_on(
    setup: &Setup,
    floor: FloorPlan,
    opts: &MeshOptions,
    check: Option<(usize, usize)>,
    cfg: &SimConfig,
) -> Result<(MeshReport, Option<Survival>), InputError> {
    // On a floor that sets the slope, the walker stands on the slope the chain starts on
    // (the central sample): the pilot walks and the check's walks start where the chain does.
    let setup = &start_setup(setup, &floor, opts.samples);
    let walker = walker_on(setup, floor, "floor")?;
    let r = mesh_mfpt(&walker, cfg, opts).map_err(|e| named(&e))?;
    let Some((walks, steps)) = check else {
        return Ok((r, None));
    };
    let model = crate::run::model(setup)?;
    let start = Section::of(&model).embed(&r.centre);
    let mc = survive(&walker, cfg, &start, 0..walks as u64, steps)
        .map_err(|e| InputError::new("floor", e.to_string()))?;
    Ok((r, Some(mc.survival)))
}

/// The JSON report of `walker mfpt`: the fields of [`MeshReport`] (`null` for an infinite
/// time), and with `--walks` `"monte_carlo"`, the statistics of those walks (`walks`,
/// `failures`, `censored`, `mfpt`, `failures_by_kind`; no curve).
#[must_use]
pub fn mfpt_json(r: &MeshReport, mc: Option<&Survival>) -> serde_json::Value {
    let mut v = serde_json::to_value(r).unwrap_or_default();
    if let (Some(mc), Some(map)) = (mc, v.as_object_mut()) {
        map.insert(
            "monte_carlo".to_owned(),
            serde_json::to_value(mc.summary()).unwrap_or_default(),
        );
    }
    v
}

/// A number of steps, or "infinite".
fn steps(x: Option<f64>) -> String {
    x.map_or_else(|| "infinite".to_owned(), |x| format!("{x:.6e}"))
}

/// A short text report of `walker mfpt`.
#[must_use]
pub fn mfpt_text(r: &MeshReport, mc: Option<&Survival>) -> String {
    let mut out = String::new();
    let coords: Vec<String> = r
        .section
        .iter()
        .zip(&r.centre)
        .zip(&r.half_widths)
        .map(|((n, c), w)| format!("{n} = {c:.6} +- {w:.3e}"))
        .collect();
    let _ = writeln!(
        out,
        "mesh of {} points per coordinate around the fixed point: {}",
        r.points,
        coords.join(", ")
    );
    match &r.slopes {
        None => {
            let _ = writeln!(
                out,
                "floor: {} sample(s) of mu0, floor states {}; {} states, {} reachable; {} steps simulated",
                r.samples.len(),
                r.floor_states.join("/"),
                r.states,
                r.reachable,
                r.steps_simulated
            );
        }
        Some(slopes) => {
            let _ = writeln!(
                out,
                "floor: {} sample(s) of mu0, {} of phi, {} floor states (the slope before); {} \
                 states, {} reachable; {} steps simulated",
                r.samples.len(),
                slopes.len(),
                r.floor_states.len(),
                r.states,
                r.reachable,
                r.steps_simulated
            );
        }
    }
    let _ = writeln!(
        out,
        "second eigenvalue: {:.12} (bracket [{:.12}, {:.12}])",
        r.lambda2, r.lambda2_bounds[0], r.lambda2_bounds[1]
    );
    let _ = writeln!(
        out,
        "mean first-passage time (steps before a failure):\n  from the eigenvalue, 1/(1 - lambda2) - 1: {}\n  from the fixed point, (I - Q) t = 1: {}",
        steps(r.mfpt.eigen),
        steps(r.mfpt.from_fixed_point)
    );
    let _ = writeln!(
        out,
        "absorption by a fall (not by leaving the box): {:.4}; largest distance from the section: {:.1e}",
        r.fall_share, r.off_section
    );
    if r.mfpt.from_fixed_point.is_some() && r.fall_share < 0.5 {
        let _ = writeln!(
            out,
            "note: most walks leave the box rather than fall: the times above are the box's, not \
             the walker's; widen it (--box-scale, --half-widths)"
        );
    }
    if let Some(mc) = mc {
        let e = &mc.mfpt.exponential;
        let _ = writeln!(
            out,
            "Monte Carlo from the fixed point: {} walks, {} failed; constant failure rate: {}, 95% interval [{:.2}, {}]",
            mc.walks,
            mc.failures,
            e.estimate
                .map_or_else(|| "-".to_owned(), |x| format!("{x:.2}")),
            e.lo,
            e.hi.map_or_else(|| "unbounded".to_owned(), |x| format!("{x:.2}"))
        );
    }
    out
}
