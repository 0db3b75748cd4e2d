//! The gallery's CSV files, per model: every walk of the sweeps (`<model>_sweep.csv`), the held
//! gait on each slope with the friction it needs (`<model>_held.csv`), and that friction along
//! the held step (`<model>_friction.csv`). State columns are named after the model's
//! coordinates.

use std::fmt::Write as _;
use std::path::Path;

use walker::model::ImpactRegime;

use super::data::ModelRun;
use super::outcome::foot_at_failure;
use crate::reproduce::WriteError;
use crate::reproduce::csv::{fmt, write};

/// `stick`, `slide-forward`, ... for an impact regime.
fn regime(r: ImpactRegime) -> String {
    match r {
        ImpactRegime::Frictionless => "frictionless".to_owned(),
        ImpactRegime::Stick => "stick".to_owned(),
        ImpactRegime::Slide(s) => format!("slide-{}", slide(s)),
        ImpactRegime::Reverse(s) => format!("reverse-{}", slide(s)),
    }
}

fn slide(s: walker::model::Slide) -> &'static str {
    match s {
        walker::model::Slide::Forward => "forward",
        walker::model::Slide::Backward => "backward",
    }
}

/// The state's column names with `suffix` (`th_plus`).
fn state_columns(run: &ModelRun, suffix: &str) -> String {
    let names = run
        .entry
        .setup()
        .map(|s| s.walker.spec().state_names())
        .unwrap_or_default();
    names
        .iter()
        .map(|n| format!(",{n}{suffix}"))
        .collect::<String>()
}

/// Every walk: the laws, the slope, `mu0`, its outcome, where it failed, the last step.
fn sweep_csv(path: &Path, run: &ModelRun) -> Result<(), WriteError> {
    let states = state_columns(run, "_plus");
    let n_state = states.matches(',').count();
    let mut out = format!(
        "friction,impact,phi,mu0,outcome,steps,failure_step,failure_t,failure_foot_velocity,failure_foot_slide,T,dx,V,stuck_time,\
         impact_regime{states}\n"
    );
    for s in &run.sweeps {
        let (friction, impact) = s.laws.names();
        for (i, pts) in s.chains.iter().enumerate() {
            for p in pts {
                let phi = run.slopes[i].phi;
                let (fs, ft) = p
                    .failure
                    .as_ref()
                    .map_or((String::new(), String::new()), |f| {
                        (f.step.to_string(), fmt(Some(f.t)))
                    });
                let foot = foot_at_failure(p, if phi.is_nan() { 0.0 } else { phi });
                let (fv, fd) = (fmt(foot.map(|f| f.0)), fmt(foot.map(|f| f.1)));
                let last = p.last.as_ref().map_or_else(
                    || ",".repeat(5 + n_state),
                    |r| {
                        let mut row = format!(
                            "{},{},{},{},{}",
                            fmt(Some(r.period)),
                            fmt(Some(r.dx)),
                            fmt(Some(r.speed)),
                            fmt(Some(r.stuck_time)),
                            regime(r.impact)
                        );
                        for v in r.q_plus.iter().chain(r.qd_plus.iter()) {
                            let _ = write!(row, ",{}", fmt(Some(*v)));
                        }
                        row
                    },
                );
                let _ = writeln!(
                    out,
                    "{friction},{impact},{},{:.4},{},{},{fs},{ft},{fv},{fd},{last}",
                    fmt(Some(run.slopes[i].phi)),
                    p.value,
                    run.outcome(i, p).label(),
                    p.steps
                );
            }
        }
    }
    write(path, out)
}

/// The held gait per slope and the friction it needs (a slope without one: its reason).
fn held_csv(path: &Path, run: &ModelRun) -> Result<(), WriteError> {
    let states = state_columns(run, "_start");
    let mut out = format!(
        "phi,held,T,dx,V,stance_ratio,stance_at,impact_ratio,needs,frictionless_foot_velocity,\
         painleve_mu0{states}\n"
    );
    for s in &run.slopes {
        let phi = fmt(Some(s.phi));
        match &s.held {
            Ok(h) => {
                let _ = write!(
                    out,
                    "{phi},yes,{},{},{},{},{},{},{},{},{}",
                    fmt(Some(h.step.period)),
                    fmt(Some(h.step.dx)),
                    fmt(Some(h.step.speed)),
                    fmt(Some(h.stance_ratio)),
                    fmt(Some(h.stance_at)),
                    fmt(Some(h.impact_ratio())),
                    fmt(Some(h.needs())),
                    fmt(Some(h.painleve.foot_velocity)),
                    fmt(h.painleve.mu0)
                );
                for v in h.start.iter() {
                    let _ = write!(out, ",{}", fmt(Some(*v)));
                }
                out.push('\n');
            }
            Err(why) => {
                let _ = writeln!(out, "{phi},\"no: {}\"", why.replace('"', "'"));
            }
        }
    }
    write(path, out)
}

/// `lambda_t / lambda_n` along the held step, per slope.
fn friction_csv(path: &Path, run: &ModelRun) -> Result<(), WriteError> {
    let mut out = String::from("phi,t_over_T,lambda_t_over_lambda_n\n");
    for s in &run.slopes {
        if let Ok(h) = &s.held {
            for (t, r) in &h.profile {
                let _ = writeln!(
                    out,
                    "{},{},{}",
                    fmt(Some(s.phi)),
                    fmt(Some(*t)),
                    fmt(Some(*r))
                );
            }
        }
    }
    write(path, out)
}

/// Write the three CSV files of `run` into `out`.
///
/// # Errors
/// A file could not be written.
pub fn write_csvs(out: &Path, run: &ModelRun) -> Result<(), WriteError> {
    let m = run.entry.model;
    sweep_csv(&out.join(format!("{m}_sweep.csv")), run)?;
    held_csv(&out.join(format!("{m}_held.csv")), run)?;
    friction_csv(&out.join(format!("{m}_friction.csv")), run)
}
