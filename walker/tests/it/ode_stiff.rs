//! The Rosenbrock method on stiff problems, against the explicit methods.

#![allow(clippy::panic)] // tests report failures by panicking

use walker::ode::{
    Direction, Event, Integrator, Method, NoObserver, Observer, OdeSystem, Outcome, Step,
    Tolerances,
};

/// y' = -lambda (y - cos t), y(0) = 0 (Hairer & Wanner's Prothero–Robinson
/// type model problem), with exact solution
/// y = (lambda^2 cos t + lambda sin t) / (lambda^2 + 1) - lambda^2 / (lambda^2 + 1) e^{-lambda t}.
struct Relax {
    lambda: f64,
}

impl Relax {
    fn exact(&self, t: f64) -> f64 {
        let l = self.lambda;
        let d = l * l + 1.0;
        (l * l * t.cos() + l * t.sin()) / d - l * l / d * (-l * t).exp()
    }
}

impl OdeSystem<1> for Relax {
    fn rhs(&mut self, t: f64, y: &[f64; 1], dy: &mut [f64; 1]) {
        dy[0] = -self.lambda * (y[0] - t.cos());
    }
}

#[test]
fn stiff_relaxation_rosenbrock_takes_far_fewer_steps() {
    let t_end = 2.0;
    let tol = Tolerances::new(1e-6, 1e-8);
    let mut sys = Relax { lambda: 1e4 };
    let exact = sys.exact(t_end);

    let mut rodas = Integrator::new(Method::Rodas4, tol);
    let out = rodas.integrate(&mut sys, 0.0, &[0.0], t_end, &mut [], &mut NoObserver);
    let Outcome::Reached { y, .. } = out else {
        panic!("{out:?}")
    };
    let err_rodas = (y[0] - exact).abs();
    let s_rodas = *rodas.stats();

    let mut dopri = Integrator::new(Method::Dopri5, tol);
    let out = dopri.integrate(&mut sys, 0.0, &[0.0], t_end, &mut [], &mut NoObserver);
    let Outcome::Reached { y, .. } = out else {
        panic!("{out:?}")
    };
    let err_dopri = (y[0] - exact).abs();
    let s_dopri = *dopri.stats();

    eprintln!("RODAS: error {err_rodas:.2e}, {s_rodas:?}");
    eprintln!("DOPRI5: error {err_dopri:.2e}, {s_dopri:?}");
    assert!(err_rodas < 1e-6, "RODAS error {err_rodas:e}");
    assert!(err_dopri < 1e-6, "DOPRI5 error {err_dopri:e}");
    // DOPRI5 is limited by stability (h * lambda <= ~3.3, i.e. >= 6000
    // steps on [0, 2]); RODAS only follows the smooth solution.
    assert!(s_dopri.accepted_steps > 5000, "{s_dopri:?}");
    assert!(
        s_rodas.accepted_steps + s_rodas.rejected_steps < 100,
        "{s_rodas:?}"
    );
    assert!(s_dopri.accepted_steps > 50 * s_rodas.accepted_steps);
    // No Jacobian supplied: finite differences, one per accepted step.
    assert_eq!(s_rodas.jacobian_evals, 0);
    assert_eq!(s_rodas.fd_jacobians, s_rodas.accepted_steps);
}

/// Robertson's chemical kinetics (Hairer & Wanner, ROBER), optionally with
/// the analytic Jacobian.
struct Robertson {
    analytic: bool,
}

impl OdeSystem<3> for Robertson {
    fn rhs(&mut self, _t: f64, y: &[f64; 3], dy: &mut [f64; 3]) {
        dy[0] = -0.04 * y[0] + 1e4 * y[1] * y[2];
        dy[2] = 3e7 * y[1] * y[1];
        dy[1] = -dy[0] - dy[2];
    }
    fn jacobian(&mut self, _t: f64, y: &[f64; 3], jac: &mut [[f64; 3]; 3]) -> bool {
        jac[0] = [-0.04, 1e4 * y[2], 1e4 * y[1]];
        jac[2] = [0.0, 6e7 * y[1], 0.0];
        jac[1] = [0.04, -1e4 * y[2] - 6e7 * y[1], -1e4 * y[1]];
        self.analytic
    }
    fn time_derivative(&mut self, _t: f64, _y: &[f64; 3], dfdt: &mut [f64; 3]) -> bool {
        *dfdt = [0.0; 3];
        true
    }
}

#[test]
fn robertson_with_analytic_and_finite_difference_jacobians() {
    // Reference values at t = 40 (classic ROBER benchmark, agreeing with SciPy's Radau and
    // BDF in tests/data/ode_crosscheck.json, the cross-check of ode_crosscheck.rs).
    let reference = [0.715_827_068_7, 9.185_534_765e-6, 0.284_163_745_7];
    for analytic in [true, false] {
        let mut ig = Integrator::new(Method::Rodas4, Tolerances::new(1e-8, 1e-12));
        let mut sys = Robertson { analytic };
        let out = ig.integrate(
            &mut sys,
            0.0,
            &[1.0, 0.0, 0.0],
            40.0,
            &mut [],
            &mut NoObserver,
        );
        let Outcome::Reached { y, .. } = out else {
            panic!("{out:?}")
        };
        for i in 0..3 {
            let rel = (y[i] - reference[i]).abs() / reference[i];
            assert!(
                rel < 1e-6,
                "analytic={analytic} component {i}: {} vs {}",
                y[i],
                reference[i]
            );
        }
        // Mass conservation: a linear invariant, kept by Rosenbrock methods
        // (up to the Jacobian's error when it is approximated).
        let mass = y.iter().sum::<f64>() - 1.0;
        assert!(
            mass.abs() < 1e-12,
            "analytic={analytic}: mass defect {mass:e}"
        );
        let s = ig.stats();
        eprintln!("ROBER analytic={analytic}: {s:?}");
        assert!(s.accepted_steps < 300, "{s:?}");
        if analytic {
            assert_eq!((s.jacobian_evals, s.fd_jacobians), (s.accepted_steps, 0));
        } else {
            assert_eq!((s.jacobian_evals, s.fd_jacobians), (0, s.accepted_steps));
        }
    }
}

/// Van der Pol oscillator y'' = mu (1 - y^2) y' - y, as a first-order
/// system with the analytic Jacobian.
struct VanDerPol {
    mu: f64,
}

impl OdeSystem<2> for VanDerPol {
    fn rhs(&mut self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        dy[0] = y[1];
        dy[1] = self.mu * (1.0 - y[0] * y[0]) * y[1] - y[0];
    }
    fn jacobian(&mut self, _t: f64, y: &[f64; 2], jac: &mut [[f64; 2]; 2]) -> bool {
        jac[0] = [0.0, 1.0];
        jac[1] = [
            -2.0 * self.mu * y[0] * y[1] - 1.0,
            self.mu * (1.0 - y[0] * y[0]),
        ];
        true
    }
}

/// Collects non-terminal event times and the extreme |y0| seen on the dense
/// output.
#[derive(Default)]
struct Crossings {
    times: Vec<f64>,
    max_abs: f64,
}

impl Observer<2> for Crossings {
    fn on_step(&mut self, step: &Step<'_, 2>) {
        let mut y = [0.0; 2];
        for j in 0..=4 {
            let t = step.t_start() + (step.t_end() - step.t_start()) * f64::from(j) / 4.0;
            step.eval(t, &mut y);
            self.max_abs = self.max_abs.max(y[0].abs());
        }
    }
    fn on_event(&mut self, _index: usize, t: f64, _y: &[f64; 2]) {
        self.times.push(t);
    }
}

#[test]
fn van_der_pol_mu_1000_period() {
    // The relaxation oscillation has period (3 - 2 ln 2) mu + 7.014 mu^(-1/3)
    // + O(ln mu / mu) (Dorodnitsyn's asymptotics): 1614.4 for mu = 1000. The
    // period is measured between successive falling zero crossings of y0,
    // located on the dense output by a non-terminal event.
    let mu: f64 = 1000.0;
    let mut ig = Integrator::new(Method::Rodas4, Tolerances::new(1e-6, 1e-6));
    let mut events = [Event::non_terminal(
        Direction::Falling,
        |_, y: &[f64; 2]| y[0],
    )];
    let mut obs = Crossings::default();
    let out = ig.integrate(
        &mut VanDerPol { mu },
        0.0,
        &[2.0, 0.0],
        3500.0,
        &mut events,
        &mut obs,
    );
    assert!(matches!(out, Outcome::Reached { .. }), "{out:?}");
    assert_eq!(obs.times.len(), 2, "{:?}", obs.times);
    let period = obs.times[1] - obs.times[0];
    let asymptotic = (3.0 - 2.0 * 2f64.ln()) * mu + 7.014 * mu.powf(-1.0 / 3.0);
    assert!(
        (period - asymptotic).abs() < 1e-3 * asymptotic,
        "period {period}, asymptotic {asymptotic}"
    );
    assert!(obs.max_abs < 2.05, "overshoot to {}", obs.max_abs);
    let s = ig.stats();
    eprintln!("VdP mu=1000: period {period:.3}, {s:?}");
    assert!(s.accepted_steps < 3000, "{s:?}");
}
