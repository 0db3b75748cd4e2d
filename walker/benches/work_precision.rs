//! Work-precision of the three integrators on the walker (a `harness = false` bench:
//! `cargo bench -p walker --bench work_precision`).
//!
//! Cases: the active walker (Table 1, `T_set = 0.3`, `omega0 = 0.8`, `c = 100`) at
//! `mu0 = 0, 0.4, 1.0` and the passive wheel (`phi = 0.2`, `omega0 = 0.5`) at `mu0 = 0.2, 0.5`,
//! each walked for `STEPS` steps from the paper's initial condition. Every method (DOPRI5,
//! DOP853, RODAS4) runs over `rtol = atol = 1e-4 ... 1e-13`; for each run: median wall time of
//! repeated runs, the integrator's counters, and the errors against a reference:
//!
//! - `err_desc`: the worst relative error of the step descriptors `T` and `dx` over all steps;
//! - `err_state`: the normwise relative error of the last post-impact state.
//!
//! The reference is DOP853 at `rtol = atol = 1e-14`; its agreement with DOP853 at `1e-13` and
//! with DOPRI5 at `1e-13` (independent method) is printed and written next to the CSV (the
//! high-precision one-step references `tests/data/step_*.json` are not in the repository yet).
//!
//! Writes `bench/out/work_precision.csv` and `bench/out/work_precision.svg`.

mod common;

use std::fmt::Write as _;
use std::path::PathBuf;

use common::{Curve, Panel, median, rel, rel_norm, svg_loglog, time_reps};
use walker::model::Model;
use walker::ode::Method;
use walker::setup::Setup;
use walker::sim::{SimConfig, Walk, WalkLimits, walk_with_stats};
use walker::vector::Vector;

const STEPS: usize = 10;

struct Case {
    name: &'static str,
    model: Model,
    initial: Vector,
}

/// The built-in scene `scene` with `params` set by name.
fn model(scene: &str, params: &[(&str, f64)]) -> Model {
    let mut setup = Setup::built_in(scene).expect("a built-in scene");
    for &(name, value) in params {
        setup.set(name, value).expect("a parameter in its range");
    }
    setup.model().expect("the scene's kernels are compiled in")
}

/// The model's start with the initial angular velocity `omega0`.
fn start(m: &Model, omega0: f64) -> Vector {
    m.start_state_with("omega0", omega0)
        .expect("omega0 is a start parameter")
}

fn cases() -> Vec<Case> {
    let mut v = Vec::new();
    for mu0 in [0.0, 0.4, 1.0] {
        let m = model(
            "active-level",
            &[("mu0", mu0), ("c", 100.0), ("T_set", 0.3)],
        );
        v.push(Case {
            name: match mu0 {
                0.0 => "active mu0=0",
                0.4 => "active mu0=0.4",
                _ => "active mu0=1.0",
            },
            initial: start(&m, 0.8),
            model: m,
        });
    }
    for mu0 in [0.2, 0.5] {
        let m = model("passive-slope", &[("mu0", mu0), ("c", 100.0), ("phi", 0.2)]);
        v.push(Case {
            name: if mu0 == 0.2 {
                "passive phi=0.2 mu0=0.2"
            } else {
                "passive phi=0.2 mu0=0.5"
            },
            initial: m.start_state(),
            model: m,
        });
    }
    v
}

fn cfg(method: Method, tol: f64) -> SimConfig {
    SimConfig {
        method,
        rtol: tol,
        atol: tol,
        ..SimConfig::default()
    }
}

fn limits() -> WalkLimits {
    WalkLimits {
        max_steps: STEPS,
        ..WalkLimits::default()
    }
}

/// `(err_desc, err_state)` of `w` against `r`; infinite if the step counts differ.
fn errors(w: &Walk, r: &Walk) -> (f64, f64) {
    if w.steps.len() != r.steps.len() || w.steps.is_empty() {
        return (f64::INFINITY, f64::INFINITY);
    }
    let d = w
        .steps
        .iter()
        .zip(&r.steps)
        .map(|(a, b)| rel(a.period, b.period).max(rel(a.dx, b.dx)))
        .fold(0.0, f64::max);
    let (sa, sb) = (
        w.last_state()
            .unwrap_or_else(|| Vector::from_slice(&[f64::NAN; 8])),
        r.last_state()
            .unwrap_or_else(|| Vector::from_slice(&[0.0; 8])),
    );
    (d, rel_norm(&sa, &sb))
}

fn method_name(m: Method) -> &'static str {
    match m {
        Method::Dopri5 => "DOPRI5",
        Method::Dop853 => "DOP853",
        Method::Rodas4 => "RODAS4",
    }
}

fn main() {
    let out_dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../bench/out");
    std::fs::create_dir_all(&out_dir).expect("create bench/out");
    let tols: Vec<f64> = (4..=13).map(|k| 10f64.powi(-k)).collect();
    let methods = [Method::Dopri5, Method::Dop853, Method::Rodas4];
    let mut csv = String::from(
        "case,method,tol,time_median_s,time_min_s,time_max_s,reps,rhs_evals,accepted,rejected,events,lu,steps,failure,err_desc,err_state\n",
    );
    let mut notes = String::new();
    let mut panels = Vec::new();
    for case in cases() {
        let lim = limits();
        let (reference, _) = walk_with_stats(
            &case.model,
            &cfg(Method::Dop853, 1e-14),
            &case.initial,
            &lim,
        );
        let (c13, _) = walk_with_stats(
            &case.model,
            &cfg(Method::Dop853, 1e-13),
            &case.initial,
            &lim,
        );
        let (d13, _) = walk_with_stats(
            &case.model,
            &cfg(Method::Dopri5, 1e-13),
            &case.initial,
            &lim,
        );
        let (a1, a2) = (errors(&c13, &reference), errors(&d13, &reference));
        let line = format!(
            "{}: reference DOP853 1e-14, {} steps{}; DOP853 1e-13 agrees to {:.1e} (desc) / {:.1e} (state), DOPRI5 1e-13 to {:.1e} / {:.1e}",
            case.name,
            reference.steps.len(),
            reference
                .failure
                .as_ref()
                .map(|f| format!(" (ended by {})", f.name()))
                .unwrap_or_default(),
            a1.0,
            a1.1,
            a2.0,
            a2.1
        );
        println!("{line}");
        notes.push_str(&line);
        notes.push('\n');
        let mut curves = Vec::new();
        for (method, color) in methods.into_iter().zip(["#1f77b4", "#d62728", "#2ca02c"]) {
            let mut pts = Vec::new();
            for &tol in &tols {
                let c = cfg(method, tol);
                let (w, st) = walk_with_stats(&case.model, &c, &case.initial, &lim);
                let mut t = time_reps(
                    || walk_with_stats(&case.model, &c, &case.initial, &lim),
                    3,
                    25,
                    0.15,
                );
                let reps = t.len();
                let tmin = t.iter().copied().fold(f64::INFINITY, f64::min);
                let tmax = t.iter().copied().fold(0.0, f64::max);
                let tm = median(&mut t);
                let (ed, es) = errors(&w, &reference);
                let _ = writeln!(
                    csv,
                    "{},{},{:e},{:.6e},{:.6e},{:.6e},{},{},{},{},{},{},{},{},{:.3e},{:.3e}",
                    case.name,
                    method_name(method),
                    tol,
                    tm,
                    tmin,
                    tmax,
                    reps,
                    st.rhs_evals,
                    st.accepted_steps,
                    st.rejected_steps,
                    st.events,
                    st.lu_decompositions,
                    w.steps.len(),
                    w.failure.as_ref().map_or("none", |f| f.name()),
                    ed,
                    es
                );
                println!(
                    "{:<26} {:<7} tol {:.0e}: {:>9.3} ms  rhs {:>7}  acc {:>6} rej {:>4}  err_desc {:.2e}  err_state {:.2e}",
                    case.name,
                    method_name(method),
                    tol,
                    tm * 1e3,
                    st.rhs_evals,
                    st.accepted_steps,
                    st.rejected_steps,
                    ed,
                    es
                );
                pts.push((tm, ed.max(1e-16)));
            }
            curves.push(Curve {
                label: method_name(method).to_owned(),
                color,
                points: pts,
            });
        }
        panels.push(Panel {
            title: case.name.to_owned(),
            curves,
        });
    }
    std::fs::write(out_dir.join("work_precision.csv"), csv).expect("write CSV");
    std::fs::write(out_dir.join("work_precision_reference.txt"), notes).expect("write notes");
    let svg = svg_loglog(
        &panels,
        "wall time per 10-step walk (s)",
        "max rel. error of T, dx",
    );
    std::fs::write(out_dir.join("work_precision.svg"), svg).expect("write SVG");
    println!(
        "wrote bench/out/work_precision.csv, work_precision.svg, work_precision_reference.txt"
    );
}
