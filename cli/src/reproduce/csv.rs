//! The CSV files of `walker reproduce`: sampled motions, per-step descriptors, the Fig. 7
//! convergence and the `mu0` sweeps, one file per figure's data.

use std::fmt::Write as _;
use std::fs;
use std::path::Path;

use walker::sim::{Sample, StepResult, Walk};
use walker::sweep::SweepPoint;

use super::data::Data;
use super::error::WriteError;

/// Write `contents` to `path`.
///
/// # Errors
/// The file could not be written.
pub fn write(path: &Path, contents: String) -> Result<(), WriteError> {
    fs::write(path, contents).map_err(WriteError::file(path))
}

/// A finite value in scientific notation with 12 digits, else an empty cell.
#[must_use]
pub fn fmt(v: Option<f64>) -> String {
    v.filter(|x| x.is_finite())
        .map_or_else(String::new, |x| format!("{x:.12e}"))
}

/// The samples of a motion: time, step, the state, `lambda` and `u`.
fn samples_csv(path: &Path, s: &[Sample]) -> Result<(), WriteError> {
    let mut out = String::from("time,step,x,z,th1,th2,xd,zd,th1d,th2d,lambda,u\n");
    for p in s {
        let _ = write!(out, "{:.9e},{}", p.time, p.step);
        for v in p.state.iter() {
            let _ = write!(out, ",{v:.9e}");
        }
        // The paper's walkers have one input or none (the passive wheel's `u` is 0).
        let u = p.u.first().copied().unwrap_or(0.0);
        let _ = writeln!(out, ",{:.9e},{u:.9e}", p.lambda);
    }
    write(path, out)
}

/// The columns of one step's descriptors ([`step_row`]).
fn steps_header() -> &'static str {
    "T,dx,V,p,SR,x_plus,z_plus,th1_plus,th2_plus,xd_plus,zd_plus,th1d_plus,th2d_plus"
}

/// One step's descriptors and post-impact state, in the order of [`steps_header`].
fn step_row(s: &StepResult) -> String {
    let mut r = format!(
        "{},{},{},{},{}",
        fmt(Some(s.period)),
        fmt(Some(s.dx)),
        fmt(Some(s.speed)),
        fmt(s.p),
        fmt(s.sr)
    );
    for v in s.q_plus.iter().chain(s.qd_plus.iter()) {
        let _ = write!(r, ",{}", fmt(Some(*v)));
    }
    r
}

/// The steps of several walks, each tagged by its `label` value (`omega0`, `mu0`).
fn series_csv(path: &Path, label: &str, walks: &[(f64, Walk)]) -> Result<(), WriteError> {
    let mut out = format!("{label},step,{}\n", steps_header());
    for (v, w) in walks {
        for (k, s) in w.steps.iter().enumerate() {
            let _ = writeln!(out, "{v},{k},{}", step_row(s));
        }
    }
    write(path, out)
}

/// The points of sweep chains, each tagged by its `label` value (`T_set`, `phi`): `mu0`, the
/// steps walked, the status, with `periodic` whether the walk settled to a periodic gait (the
/// passive sweeps, [`crate::reproduce::passive::PERIODIC_TOL`]; `false` for a failure or a walk
/// that reached its duration first), and the last step.
fn sweep_csv(
    path: &Path,
    label: &str,
    chains: &[(f64, Vec<SweepPoint>)],
    periodic: bool,
) -> Result<(), WriteError> {
    let periodic_col = if periodic { "periodic," } else { "" };
    let mut out = format!(
        "{label},mu0,steps,status,{periodic_col}{}\n",
        steps_header()
    );
    for (v, pts) in chains {
        for p in pts {
            let status = p.failure.as_ref().map_or("ok", |f| f.name());
            let row = p.last.as_ref().map_or_else(|| ",".repeat(12), step_row);
            let flag = if periodic {
                format!("{},", p.periodic)
            } else {
                String::new()
            };
            let _ = writeln!(out, "{v},{:.4},{},{status},{flag}{row}", p.value, p.steps);
        }
    }
    write(path, out)
}

/// Fig. 7's errors after each impact.
fn convergence_csv(path: &Path, rows: &[[f64; 3]]) -> Result<(), WriteError> {
    let mut c = String::from("impact,norm_dqd,d_xd,d_th1d\n");
    for (k, r) in rows.iter().enumerate() {
        let _ = writeln!(c, "{k},{:.12e},{:.12e},{:.12e}", r[0], r[1], r[2]);
    }
    write(path, c)
}

/// Write the data of every figure as CSV files into `out`.
///
/// # Errors
/// A file could not be written.
pub fn write_csvs(out: &Path, d: &Data) -> Result<(), WriteError> {
    samples_csv(&out.join("fig3_motion_mu0_0.csv"), &d.motion[0].samples)?;
    samples_csv(&out.join("fig5_motion_mu0_0.4.csv"), &d.motion[1].samples)?;
    series_csv(
        &out.join("fig4_steps_mu0_0.csv"),
        "omega0",
        &d.omega_series[0],
    )?;
    series_csv(
        &out.join("fig6_steps_mu0_0.4.csv"),
        "omega0",
        &d.omega_series[1],
    )?;
    convergence_csv(&out.join("fig7_convergence.csv"), &d.convergence)?;
    sweep_csv(&out.join("fig8_sweep.csv"), "T_set", &d.active_sweep, false)?;
    sweep_csv(&out.join("fig10_sweep.csv"), "phi", &d.passive_sweep, true)?;
    sweep_csv(
        &out.join("fig10_sweep_continued.csv"),
        "phi",
        &d.passive_continuation,
        true,
    )?;
    sweep_csv(
        &out.join("passive_large_mu0.csv"),
        "phi",
        &d.passive_large_mu0,
        true,
    )?;
    sweep_csv(
        &out.join("passive_inertia.csv"),
        "I1",
        &d.passive_inertia,
        true,
    )?;
    sweep_csv(
        &out.join("fig8_sweep_coulomb.csv"),
        "T_set",
        &d.coulomb_sweep,
        false,
    )?;
    sweep_csv(
        &out.join("fig8_sweep_coulomb_impact.csv"),
        "T_set",
        &d.coulomb_impact_sweep,
        false,
    )?;
    for (mu0, w) in &d.sticks {
        samples_csv(&out.join(format!("fig11_stick_mu0_{mu0}.csv")), &w.samples)?;
    }
    series_csv(&out.join("fig12_step_length.csv"), "mu0", &d.step_lengths)?;
    samples_csv(&out.join("fig14_fall.csv"), &d.fall.samples)?;
    Ok(())
}
