//! Accuracy of the integrators on problems with exact solutions, and the
//! empirical orders of convergence (fixed step, tolerance sweep, dense
//! output).

#![allow(clippy::panic)] // tests report failures by panicking

use walker::ode::{Config, Integrator, Method, NoObserver, OdeSystem, Outcome, Step, Tolerances};

const METHODS: [Method; 3] = [Method::Dopri5, Method::Dop853, Method::Rodas4];

/// y' = -k y, componentwise decay rates.
struct Decay([f64; 3]);

impl OdeSystem<3> for Decay {
    fn rhs(&mut self, _t: f64, y: &[f64; 3], dy: &mut [f64; 3]) {
        for i in 0..3 {
            dy[i] = -self.0[i] * y[i];
        }
    }
}

/// x'' = -x as a first-order system: x = cos t, v = -sin t.
struct Oscillator;

impl OdeSystem<2> for Oscillator {
    fn rhs(&mut self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        dy[0] = y[1];
        dy[1] = -y[0];
    }
}

/// A manufactured nonlinear, non-autonomous problem without special
/// structure (so that no error term cancels by symmetry):
/// `y' = u'(t) + G(y) - G(u(t))` has the exact solution `y = u(t)` with
/// `u = (sin t + cos(2t)/2, exp(-t/2) (1 + t/3))` and the dissipative
/// nonlinearity `G(y) = (-y0^3 - y1 + y0 y1 / 2, y0 - y1 - y1^3 / 2)`.
/// Jacobian and `df/dt` are provided analytically (the Rosenbrock method
/// needs an exact Jacobian for its full order).
struct Manufactured;

fn u(t: f64) -> [f64; 2] {
    [
        t.sin() + 0.5 * (2.0 * t).cos(),
        (-0.5 * t).exp() * (1.0 + t / 3.0),
    ]
}

fn du(t: f64) -> [f64; 2] {
    [
        t.cos() - (2.0 * t).sin(),
        (-0.5 * t).exp() * (-0.5 * (1.0 + t / 3.0) + 1.0 / 3.0),
    ]
}

fn ddu(t: f64) -> [f64; 2] {
    [
        -t.sin() - 2.0 * (2.0 * t).cos(),
        (-0.5 * t).exp() * ((1.0 + t / 3.0) / 4.0 - 1.0 / 3.0),
    ]
}

fn g_nl(y: &[f64; 2]) -> [f64; 2] {
    [
        -y[0] * y[0] * y[0] - y[1] + 0.5 * y[0] * y[1],
        y[0] - y[1] - 0.5 * y[1] * y[1] * y[1],
    ]
}

fn g_jac(y: &[f64; 2]) -> [[f64; 2]; 2] {
    [
        [-3.0 * y[0] * y[0] + 0.5 * y[1], -1.0 + 0.5 * y[0]],
        [1.0, -1.0 - 1.5 * y[1] * y[1]],
    ]
}

impl OdeSystem<2> for Manufactured {
    fn rhs(&mut self, t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        let (d, a, b) = (du(t), g_nl(y), g_nl(&u(t)));
        for i in 0..2 {
            dy[i] = d[i] + a[i] - b[i];
        }
    }
    fn jacobian(&mut self, _t: f64, y: &[f64; 2], jac: &mut [[f64; 2]; 2]) -> bool {
        *jac = g_jac(y);
        true
    }
    fn time_derivative(&mut self, t: f64, _y: &[f64; 2], dfdt: &mut [f64; 2]) -> bool {
        let (dd, d, j) = (ddu(t), du(t), g_jac(&u(t)));
        for i in 0..2 {
            dfdt[i] = dd[i] - (j[i][0] * d[0] + j[i][1] * d[1]);
        }
        true
    }
}

fn max_err(y: &[f64; 2], t: f64) -> f64 {
    let e = u(t);
    (y[0] - e[0]).abs().max((y[1] - e[1]).abs())
}

/// Non-autonomous: y' = y cos t, y(0) = 1: y = exp(sin t). Optionally
/// provides df/dt analytically.
struct ExpSin {
    analytic_dt: bool,
}

impl OdeSystem<1> for ExpSin {
    fn rhs(&mut self, t: f64, y: &[f64; 1], dy: &mut [f64; 1]) {
        dy[0] = y[0] * t.cos();
    }
    fn jacobian(&mut self, t: f64, _y: &[f64; 1], jac: &mut [[f64; 1]; 1]) -> bool {
        jac[0][0] = t.cos();
        true
    }
    fn time_derivative(&mut self, t: f64, y: &[f64; 1], dfdt: &mut [f64; 1]) -> bool {
        dfdt[0] = -y[0] * t.sin();
        self.analytic_dt
    }
}

fn reached<const N: usize>(out: Outcome<N>, t_end: f64) -> [f64; N] {
    match out {
        Outcome::Reached { t, y } => {
            assert_eq!(t, t_end, "Reached must land exactly on t_end");
            y
        }
        other => panic!("expected Reached, got {other:?}"),
    }
}

#[test]
fn exponential_decay_all_methods() {
    // Once |y_i| < atol / rtol the error control of component i is absolute,
    // so the check is against the tolerance scale atol + rtol |y_i|, with a
    // factor 100 for the accumulation over the steps.
    let k = [0.5, 1.0, 3.0];
    let t_end = 5.0;
    let (rtol, atol) = (1e-10, 1e-12);
    for m in METHODS {
        let mut ig = Integrator::new(m, Tolerances::new(rtol, atol));
        let y = reached(
            ig.integrate(
                &mut Decay(k),
                0.0,
                &[1.0; 3],
                t_end,
                &mut [],
                &mut NoObserver,
            ),
            t_end,
        );
        for i in 0..3 {
            let exact = (-k[i] * t_end).exp();
            let err = (y[i] - exact).abs();
            let scale = atol + rtol * exact;
            assert!(
                err < 100.0 * scale,
                "{m:?} component {i}: error {err:e}, scale {scale:e}"
            );
        }
        let s = ig.stats();
        assert!(s.accepted_steps > 0 && s.rhs_evals > 0, "{m:?}: {s:?}");
    }
}

#[test]
fn harmonic_oscillator_all_methods() {
    let t_end: f64 = 20.0;
    for (m, bound) in [
        (Method::Dopri5, 1e-8),
        (Method::Dop853, 1e-9),
        (Method::Rodas4, 1e-7),
    ] {
        let mut ig = Integrator::new(m, Tolerances::new(1e-11, 1e-11));
        let y = reached(
            ig.integrate(
                &mut Oscillator,
                0.0,
                &[1.0, 0.0],
                t_end,
                &mut [],
                &mut NoObserver,
            ),
            t_end,
        );
        let ex = [t_end.cos(), -t_end.sin()];
        let err = (y[0] - ex[0]).abs().max((y[1] - ex[1]).abs());
        assert!(err < bound, "{m:?}: error {err:e}");
    }
}

#[test]
fn non_autonomous_problem_all_methods() {
    let t_end: f64 = 10.0;
    let exact = t_end.sin().exp();
    for m in METHODS {
        for analytic_dt in [false, true] {
            let mut ig = Integrator::new(m, Tolerances::new(1e-10, 1e-10));
            let mut sys = ExpSin { analytic_dt };
            let y = reached(
                ig.integrate(&mut sys, 0.0, &[1.0], t_end, &mut [], &mut NoObserver),
                t_end,
            );
            let rel = (y[0] - exact).abs() / exact;
            assert!(
                rel < 1e-8,
                "{m:?} analytic_dt={analytic_dt}: rel error {rel:e}"
            );
        }
    }
}

/// Error at t = 6 of the manufactured problem with fixed steps of size h.
fn fixed_step_error(m: Method, h: f64) -> f64 {
    let mut cfg = Config::for_method(m);
    cfg.fixed_step = Some(h);
    let mut ig = Integrator::with_config(m, Tolerances::new(1e-6, 1e-6), cfg);
    let y = reached(
        ig.integrate(
            &mut Manufactured,
            0.0,
            &u(0.0),
            6.0,
            &mut [],
            &mut NoObserver,
        ),
        6.0,
    );
    max_err(&y, 6.0)
}

/// Observed orders log2(e(h) / e(h/2)) over a sequence of halvings.
fn observed_orders(errors: &[f64]) -> Vec<f64> {
    errors.windows(2).map(|w| (w[0] / w[1]).log2()).collect()
}

/// Assert that every observed order lies in `band`.
fn assert_orders(what: &str, m: Method, hs: &[f64], errors: &[f64], band: (f64, f64)) {
    let orders = observed_orders(errors);
    let errs: Vec<String> = errors.iter().map(|e| format!("{e:.2e}")).collect();
    eprintln!("{m:?} {what}: h {hs:?}, errors {errs:?}, orders {orders:.2?}");
    for q in orders {
        assert!(
            (band.0..=band.1).contains(&q),
            "{m:?} {what}: observed order {q:.3} outside {band:?} (errors {errors:?})"
        );
    }
}

#[test]
fn fixed_step_convergence_orders() {
    // Global error at t = 6 for step halvings, in the asymptotic range and
    // well above rounding (errors from ~1e-6 down to >= 1e-13). The observed
    // order must lie in [p - 0.3, p + 0.6]. Why this band: the error is
    // C_p h^p + C_{p+1} h^{p+1} + ..., and on this problem the correction
    // term makes the ratio approach p from above (RODAS only gets there at
    // small steps, hence its finer step sizes); a wrong coefficient drops
    // the order by at least one, which the lower bound catches.
    let cases: [(Method, [f64; 4]); 3] = [
        (
            Method::Dopri5,
            [0.75 / 8.0, 0.75 / 16.0, 0.75 / 32.0, 0.75 / 64.0],
        ),
        (Method::Dop853, [0.375, 0.1875, 0.09375, 0.046875]),
        (
            Method::Rodas4,
            [0.75 / 64.0, 0.75 / 128.0, 0.75 / 256.0, 0.75 / 512.0],
        ),
    ];
    for (m, hs) in cases {
        let p = f64::from(m.order());
        let errors: Vec<f64> = hs.iter().map(|&h| fixed_step_error(m, h)).collect();
        assert_orders("fixed-step global", m, &hs, &errors, (p - 0.3, p + 0.6));
    }
}

#[test]
fn tolerance_sweep_orders() {
    // With error-per-step control the global error behaves like C W^(-p) in
    // the work W (rhs evaluations): steps scale like tol^(1/(q+1)) and the
    // propagated solution has global error O(h^p). The slope of log(error)
    // against log(W) is fitted by least squares over tolerances in the
    // asymptotic range. It is less clean than at fixed steps (the step
    // sequence changes discretely; the first steps and the truncated last
    // one do not scale), so the band is [p - 1, p + 1.5]. The sweep also
    // checks tolerance proportionality: on this dissipative problem the
    // global error stays below the tolerance.
    let cases: [(Method, &[f64]); 3] = [
        (Method::Dopri5, &[1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13]),
        (Method::Dop853, &[1e-9, 1e-10, 1e-11, 1e-12, 1e-13]),
        (Method::Rodas4, &[1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12]),
    ];
    for (m, tols) in cases {
        let mut pts = Vec::new();
        for &tol in tols {
            let mut ig = Integrator::new(m, Tolerances::new(tol, tol));
            let y = reached(
                ig.integrate(
                    &mut Manufactured,
                    0.0,
                    &u(0.0),
                    6.0,
                    &mut [],
                    &mut NoObserver,
                ),
                6.0,
            );
            let err = max_err(&y, 6.0);
            assert!(err < tol, "{m:?}: error {err:e} at tolerance {tol:e}");
            pts.push(((ig.stats().rhs_evals as f64).ln(), err.ln()));
        }
        let n = pts.len() as f64;
        let mx = pts.iter().map(|p| p.0).sum::<f64>() / n;
        let my = pts.iter().map(|p| p.1).sum::<f64>() / n;
        let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
        let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
        let slope = -sxy / sxx;
        let p = f64::from(m.order());
        eprintln!("{m:?}: work-precision slope {slope:.3} over tolerances {tols:?}");
        assert!(
            (p - 1.0..=p + 1.5).contains(&slope),
            "{m:?}: work-precision slope {slope:.3}, expected about {p}"
        );
    }
}

/// One fixed step of size h from the exact initial value: errors of the
/// dense output at theta = 0.5 and of the step end.
fn one_step_errors(m: Method, h: f64) -> (f64, f64) {
    let mut cfg = Config::for_method(m);
    cfg.fixed_step = Some(h);
    let mut ig = Integrator::with_config(m, Tolerances::new(1e-6, 1e-6), cfg);
    let mut mid = [f64::NAN; 2];
    let mut obs = |s: &Step<'_, 2>| s.eval(0.5 * h, &mut mid);
    let y = reached(
        ig.integrate(&mut Manufactured, 0.0, &u(0.0), h, &mut [], &mut obs),
        h,
    );
    (max_err(&mid, 0.5 * h), max_err(&y, h))
}

#[test]
fn local_orders_of_step_and_dense_output() {
    // Local errors of one step from the exact value: O(h^(p*+1)) for the
    // dense output of order p* (at theta = 1/2) and O(h^(p+1)) at the step
    // end. Same band reasoning as for the fixed-step test, [order - 0.3,
    // order + 0.6], except the DOP853 step end, whose 9th-order local error
    // reaches rounding before the ratio settles: there the ratio approaches
    // 9 from below (8.6, 8.8, 8.9 observed), so the band is [8.4, 9.6].
    let cases: [(Method, [f64; 3], [f64; 3], f64); 3] = [
        (
            Method::Dopri5,
            [0.1, 0.05, 0.025],
            [0.05, 0.025, 0.0125],
            0.3,
        ),
        (Method::Dop853, [0.8, 0.4, 0.2], [0.8, 0.4, 0.2], 0.6),
        (
            Method::Rodas4,
            [0.1, 0.05, 0.025],
            [0.05, 0.025, 0.0125],
            0.3,
        ),
    ];
    for (m, hd, he, below) in cases {
        let dense: Vec<f64> = hd.iter().map(|&h| one_step_errors(m, h).0).collect();
        let end: Vec<f64> = he.iter().map(|&h| one_step_errors(m, h).1).collect();
        let pd = f64::from(m.dense_order()) + 1.0;
        let pe = f64::from(m.order()) + 1.0;
        assert_orders("dense-output local", m, &hd, &dense, (pd - 0.3, pd + 0.6));
        assert_orders("step local", m, &he, &end, (pe - below, pe + 0.6));
    }
}

#[test]
fn dense_output_between_steps_is_accurate() {
    // Adaptive run on the oscillator; sample the interpolant at 7 interior
    // points of every step and compare with cos t. The interpolation error
    // is of the order of the local error per step, i.e. about the
    // tolerance; the derivative of the interpolant is one order less
    // accurate.
    for (m, bound, dbound) in [
        (Method::Dopri5, 1e-8, 1e-6),
        (Method::Dop853, 1e-8, 1e-6),
        (Method::Rodas4, 1e-6, 1e-4),
    ] {
        let mut ig = Integrator::new(m, Tolerances::new(1e-9, 1e-9));
        let mut worst: f64 = 0.0;
        let mut worst_d: f64 = 0.0;
        let mut steps = 0;
        let mut obs = |s: &Step<'_, 2>| {
            steps += 1;
            for j in 1..8 {
                let t = s.t_start() + (s.t_end() - s.t_start()) * f64::from(j) / 8.0;
                let mut y = [0.0; 2];
                s.eval(t, &mut y);
                worst = worst
                    .max((y[0] - t.cos()).abs())
                    .max((y[1] + t.sin()).abs());
                s.eval_derivative(t, &mut y);
                worst_d = worst_d
                    .max((y[0] + t.sin()).abs())
                    .max((y[1] + t.cos()).abs());
            }
        };
        let out = ig.integrate(&mut Oscillator, 0.0, &[1.0, 0.0], 10.0, &mut [], &mut obs);
        assert!(matches!(out, Outcome::Reached { .. }));
        assert_eq!(steps as u64, ig.stats().accepted_steps);
        assert!(worst < bound, "{m:?}: dense error {worst:e}");
        assert!(
            worst_d < dbound,
            "{m:?}: dense derivative error {worst_d:e}"
        );
    }
}

/// Oscillator with a quadrature component q' = v^2.
struct OscillatorWithWork;

impl OdeSystem<3> for OscillatorWithWork {
    fn rhs(&mut self, _t: f64, y: &[f64; 3], dy: &mut [f64; 3]) {
        dy[0] = y[1];
        dy[1] = -y[0];
        dy[2] = y[1] * y[1];
    }
}

#[test]
fn quadrature_as_state_and_by_observer() {
    // Integral of v^2 = sin^2 over [0, T]: T/2 - sin(2T)/4. Computed once as
    // an extra state component (under error control) and once by the
    // observer with 5-point Gauss-Legendre on the dense output of each step.
    let t_end: f64 = 7.0;
    let exact = t_end / 2.0 - (2.0 * t_end).sin() / 4.0;
    const GL_X: [f64; 5] = [
        -0.906_179_845_938_664,
        -0.538_469_310_105_683,
        0.0,
        0.538_469_310_105_683,
        0.906_179_845_938_664,
    ];
    const GL_W: [f64; 5] = [
        0.236_926_885_056_189,
        0.478_628_670_499_366,
        0.568_888_888_888_889,
        0.478_628_670_499_366,
        0.236_926_885_056_189,
    ];
    for m in [Method::Dopri5, Method::Dop853] {
        let mut ig = Integrator::new(m, Tolerances::new(1e-11, 1e-11));
        let mut by_observer = 0.0;
        let mut obs = |s: &Step<'_, 3>| {
            let (a, b) = (s.t_start(), s.t_end());
            let mut y = [0.0; 3];
            for (x, w) in GL_X.iter().zip(GL_W.iter()) {
                s.eval(0.5 * (a + b) + 0.5 * (b - a) * x, &mut y);
                by_observer += 0.5 * (b - a) * w * y[1] * y[1];
            }
        };
        let y = reached(
            ig.integrate(
                &mut OscillatorWithWork,
                0.0,
                &[1.0, 0.0, 0.0],
                t_end,
                &mut [],
                &mut obs,
            ),
            t_end,
        );
        assert!(
            (y[2] - exact).abs() < 1e-9,
            "{m:?}: state quadrature {:e}",
            y[2] - exact
        );
        assert!(
            (by_observer - exact).abs() < 1e-8,
            "{m:?}: observer quadrature {:e}",
            by_observer - exact
        );
    }
}

#[test]
fn stats_count_work() {
    // DOPRI5 is FSAL: 6 evaluations per attempted step, plus 1 for f(t0)
    // and 1 for the initial step size guess.
    let mut ig = Integrator::new(Method::Dopri5, Tolerances::new(1e-8, 1e-8));
    let out = ig.integrate(
        &mut Oscillator,
        0.0,
        &[1.0, 0.0],
        3.0,
        &mut [],
        &mut NoObserver,
    );
    assert!(matches!(out, Outcome::Reached { .. }));
    let s = *ig.stats();
    assert_eq!(s.rhs_evals, 2 + 6 * (s.accepted_steps + s.rejected_steps));
    // Stats accumulate over calls until reset.
    let _ = ig.integrate(
        &mut Oscillator,
        0.0,
        &[1.0, 0.0],
        3.0,
        &mut [],
        &mut NoObserver,
    );
    assert_eq!(ig.stats().rhs_evals, 2 * s.rhs_evals);
    ig.reset_stats();
    assert_eq!(ig.stats().rhs_evals, 0);
}
