//! Cross-check against independent solvers, on nonlinear problems without closed-form
//! solutions: the values of `tests/data/ode_crosscheck.json`, written by
//! `sympy_ref/ode_crosscheck.py` (mpmath's Taylor series at 40 digits for Lotka-Volterra,
//! SciPy's Radau IIA for Robertson's stiff kinetics, each checked there against a second
//! solver).
//!
//! Tolerances. Lotka-Volterra's reference is exact to far below double precision, so the
//! distance is DOP853's own global error at `rtol = atol = 1e-12`: about a hundred steps to
//! `t = 10`, each with a local error near `1e-12`, bound it by `1e-10` relative. Robertson's
//! reference carries SciPy's error, which its distance to SciPy's BDF bounds (written in the
//! file, about `1e-10`); RODAS at `rtol = 1e-10` adds its own global error of the same order over
//! the transient, so `1e-8` relative is a margin of about two orders. Both measured distances are
//! printed.

#![allow(clippy::panic, clippy::unwrap_used)] // tests report failures by panicking

use std::path::PathBuf;

use approx::assert_relative_eq;
use walker::ode::{Integrator, Method, NoObserver, OdeSystem, Outcome, Step, Tolerances};

/// The reference file's section `name`.
fn reference(name: &str) -> serde_json::Value {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../tests/data/ode_crosscheck.json");
    let s = std::fs::read_to_string(&p)
        .expect("tests/data/ode_crosscheck.json is committed (sympy_ref/ode_crosscheck.py)");
    let v: serde_json::Value = serde_json::from_str(&s).unwrap();
    v[name].clone()
}

/// The numbers of a JSON array.
fn numbers(v: &serde_json::Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

/// Lotka–Volterra predator–prey model (nonlinear, non-stiff, periodic).
struct LotkaVolterra;

const LV: [f64; 4] = [1.5, 1.0, 3.0, 1.0];

impl OdeSystem<2> for LotkaVolterra {
    fn rhs(&mut self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        let [a, b, c, d] = LV;
        dy[0] = a * y[0] - b * y[0] * y[1];
        dy[1] = -c * y[1] + d * y[0] * y[1];
    }
}

#[test]
fn dop853_dense_output_agrees_with_a_taylor_series_reference() {
    let r = reference("lotka_volterra");
    assert_eq!(numbers(&r["params_abcd"]), LV);
    let y0 = [1.0, 1.0];
    assert_eq!(numbers(&r["y0"]), y0);
    let t_eval = numbers(&r["t"]);
    let ys: Vec<Vec<f64>> = r["y"].as_array().unwrap().iter().map(numbers).collect();
    assert_eq!(ys.len(), t_eval.len());
    let t_end = *t_eval.last().unwrap();

    // DOP853, sampled on its dense output at the same times.
    let mut ig = Integrator::new(Method::Dop853, Tolerances::new(1e-12, 1e-12));
    let mut ours: Vec<(f64, [f64; 2])> = Vec::new();
    let mut next = 0;
    let mut obs = |s: &Step<'_, 2>| {
        while next < t_eval.len() && t_eval[next] <= s.t_end() {
            let mut y = [0.0; 2];
            s.eval(t_eval[next], &mut y);
            ours.push((t_eval[next], y));
            next += 1;
        }
    };
    let out = ig.integrate(&mut LotkaVolterra, 0.0, &y0, t_end, &mut [], &mut obs);
    assert!(matches!(out, Outcome::Reached { .. }), "{out:?}");
    assert_eq!(ours.len(), t_eval.len());

    let mut worst: f64 = 0.0;
    for ((_, y), theirs) in ours.iter().zip(&ys) {
        for (&yi, &theirs) in y.iter().zip(theirs) {
            worst = worst.max((yi - theirs).abs() / yi.abs());
            assert_relative_eq!(yi, theirs, max_relative = 1e-10, epsilon = 1e-12);
        }
    }
    eprintln!("Lotka-Volterra: DOP853 vs the Taylor series, worst relative difference {worst:.2e}");
    // The conserved quantity V = d x - c ln x + b y - a ln y is kept by DOP853.
    let v = |y: &[f64; 2]| {
        let [a, b, c, d] = LV;
        d * y[0] - c * y[0].ln() + b * y[1] - a * y[1].ln()
    };
    for (_, y) in &ours {
        assert_relative_eq!(v(y), v(&y0), max_relative = 1e-10);
    }
}

/// Robertson's stiff chemical kinetics.
struct Robertson;

impl OdeSystem<3> for Robertson {
    fn rhs(&mut self, _t: f64, y: &[f64; 3], dy: &mut [f64; 3]) {
        dy[0] = -0.04 * y[0] + 1e4 * y[1] * y[2];
        dy[2] = 3e7 * y[1] * y[1];
        dy[1] = -dy[0] - dy[2];
    }
}

#[test]
fn rodas_agrees_with_scipy_radau_on_robertson() {
    let r = reference("robertson");
    assert_eq!(numbers(&r["y0"]), [1.0, 0.0, 0.0]);
    let t_end = r["t_end"].as_f64().unwrap();
    let ys = numbers(&r["y"]);
    let mut ig = Integrator::new(Method::Rodas4, Tolerances::new(1e-10, 1e-14));
    let out = ig.integrate(
        &mut Robertson,
        0.0,
        &[1.0, 0.0, 0.0],
        t_end,
        &mut [],
        &mut NoObserver,
    );
    let Outcome::Reached { y, .. } = out else {
        panic!("{out:?}")
    };
    for (i, (&yi, &theirs)) in y.iter().zip(&ys).enumerate() {
        let rel = (yi - theirs).abs() / yi;
        eprintln!("Robertson component {i}: RODAS vs SciPy Radau relative difference {rel:.2e}");
        assert_relative_eq!(yi, theirs, max_relative = 1e-8);
    }
}
