//! Cross-check against an independent solver: diffsol 0.18 (nalgebra
//! backend), on nonlinear problems without closed-form solutions.

#![allow(clippy::panic, clippy::unwrap_used)] // tests report failures by panicking

use approx::assert_relative_eq;
use diffsol::{DenseMatrix, NalgebraLU, NalgebraMat, OdeBuilder, OdeSolverMethod};
use walker::ode::{Integrator, Method, NoObserver, OdeSystem, Outcome, Step, Tolerances};

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
fn dop853_dense_output_agrees_with_diffsol_tsit45() {
    let y0 = [1.0, 1.0];
    let t_eval: Vec<f64> = (1..=20).map(|k| 0.5 * f64::from(k)).collect();
    let t_end = *t_eval.last().unwrap();

    // diffsol, Tsitouras 5(4) at a tight tolerance.
    let problem = OdeBuilder::<NalgebraMat<f64>>::new()
        .rtol(1e-12)
        .atol([1e-12])
        .rhs(|x: &[f64], _p: &[f64], _t: f64, y: &mut [f64]| {
            let [a, b, c, d] = LV;
            y[0] = a * x[0] - b * x[0] * x[1];
            y[1] = -c * x[1] + d * x[0] * x[1];
        })
        .init(
            move |_p: &[f64], _t: f64, y: &mut [f64]| {
                y[0] = y0[0];
                y[1] = y0[1];
            },
            2,
        )
        .build()
        .unwrap();
    let mut solver = problem.tsit45().unwrap();
    let (ys, _stop) = solver.solve_dense(&t_eval).unwrap();

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
    for (j, (_, y)) in ours.iter().enumerate() {
        for (i, &yi) in y.iter().enumerate() {
            let theirs = ys.get_index(i, j);
            worst = worst.max((yi - theirs).abs() / yi.abs());
            assert_relative_eq!(yi, theirs, max_relative = 1e-10, epsilon = 1e-12);
        }
    }
    eprintln!("Lotka-Volterra: DOP853 vs diffsol tsit45, worst relative difference {worst:.2e}");
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
fn rodas_agrees_with_diffsol_bdf_on_robertson() {
    let t_end = 40.0;
    let problem = OdeBuilder::<NalgebraMat<f64>>::new()
        .rtol(1e-10)
        .atol([1e-14])
        .rhs_implicit(
            |x: &[f64], _p: &[f64], _t: f64, y: &mut [f64]| {
                y[0] = -0.04 * x[0] + 1e4 * x[1] * x[2];
                y[2] = 3e7 * x[1] * x[1];
                y[1] = -y[0] - y[2];
            },
            // Jacobian-vector product.
            |x: &[f64], _p: &[f64], _t: f64, v: &[f64], y: &mut [f64]| {
                y[0] = -0.04 * v[0] + 1e4 * x[2] * v[1] + 1e4 * x[1] * v[2];
                y[2] = 6e7 * x[1] * v[1];
                y[1] = -y[0] - y[2];
            },
        )
        .init(
            |_p: &[f64], _t: f64, y: &mut [f64]| {
                y[0] = 1.0;
                y[1] = 0.0;
                y[2] = 0.0;
            },
            3,
        )
        .build()
        .unwrap();
    let mut solver = problem.bdf::<NalgebraLU<f64>>().unwrap();
    let (ys, _stop) = solver.solve_dense(&[t_end]).unwrap();

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
    for (i, &yi) in y.iter().enumerate() {
        let theirs = ys.get_index(i, 0);
        let rel = (yi - theirs).abs() / yi;
        eprintln!("Robertson component {i}: RODAS vs diffsol BDF relative difference {rel:.2e}");
        assert_relative_eq!(yi, theirs, max_relative = 1e-8);
    }
}
