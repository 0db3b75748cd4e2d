//! The stiff integrator takes its Jacobian from the generated kernels.

use crate::common;

use common::start;
use walker::ode::Method;
use walker::sim::{SimConfig, WalkLimits, walk_with_stats};

/// With Table 1 the state Jacobian comes from the model's `closed_loop_jacobian` kernel (no
/// finite-difference Jacobian is formed), and on a stiff friction law (`c = 1e4`, `mu0 = 1`)
/// RODAS4 needs far fewer right-hand sides than DOP853 for the same steps, with the same step
/// descriptors to the accuracy both were asked for. The input power `p` checks the Jacobian's row of the power
/// quadrature: a Rosenbrock method is only as accurate as its Jacobian (with that row zero,
/// RODAS4 does not even finish the walk: its error estimate of the quadrature stays too large).
#[test]
fn rodas4_uses_the_generated_jacobian_on_stiff_friction() {
    let m = common::active(&[("mu0", 1.0), ("c", 1e4), ("T_set", 0.3)]);
    let limits = WalkLimits {
        max_steps: 2,
        ..WalkLimits::default()
    };
    let explicit = SimConfig {
        rtol: 1e-9,
        atol: 1e-11,
        ..SimConfig::default()
    };
    let stiff = SimConfig {
        method: Method::Rodas4,
        ..explicit
    };
    let (a, sa) = walk_with_stats(&m, &explicit, &start(&m, 0.8), &limits);
    let (b, sb) = walk_with_stats(&m, &stiff, &start(&m, 0.8), &limits);
    assert_eq!(a.steps.len(), 2, "{:?}", a.failure);
    assert_eq!(b.steps.len(), 2, "{:?}", b.failure);
    assert_eq!(sb.fd_jacobians, 0, "{sb:?}");
    assert!(sb.jacobian_evals > 0, "{sb:?}");
    assert!(
        sb.rhs_evals * 4 < sa.rhs_evals,
        "RODAS4 {sb:?} vs DOP853 {sa:?}"
    );
    for (x, y) in a.steps.iter().zip(&b.steps) {
        // Both at rtol 1e-9: the descriptors agree to well within 1e-6 relative.
        assert!((x.period - y.period).abs() < 1e-6 * x.period, "{x:?} {y:?}");
        assert!((x.dx - y.dx).abs() < 1e-6 * x.dx.abs(), "{x:?} {y:?}");
        let (px, py) = (x.p.unwrap_or(f64::NAN), y.p.unwrap_or(f64::NAN));
        assert!((px - py).abs() < 1e-6 * px, "p: {px} vs {py}");
    }
}

/// Where the foot creeps (`|c xd| < 3` for most of the stance at these `mu0`), DOP853's step
/// size is set by stability, and its interpolant is far less accurate than its steps' ends.
/// Impacts and the power kinks are terminal events whose state comes from steps that end on
/// them, so at `rtol = atol = 1e-8` the first five steps' `T` and `p` are within 1e-8
/// (relative) of a `1e-12` run and the post-impact velocities (of size ~1, so a tolerance scale
/// of `atol + rtol |v| <= 3e-8`) within 3e-8. Measured: at most 1.1e-9, 2.8e-9 and 1.0e-8; with
/// the interpolated event states they were 4.9e-8, 2.2e-7 and 4.3e-7.
#[test]
fn creeping_gaits_are_as_accurate_as_the_tolerance_at_impacts_and_power_kinks() {
    for (mu0, t_set) in [(0.85, 0.4), (1.0, 0.3), (0.6, 0.3)] {
        let m = common::active(&[("mu0", mu0), ("T_set", t_set)]);
        let run = |tol: f64| {
            let cfg = SimConfig {
                rtol: tol,
                atol: tol,
                ..SimConfig::default()
            };
            let limits = WalkLimits {
                max_steps: 5,
                ..WalkLimits::default()
            };
            walk_with_stats(&m, &cfg, &start(&m, 0.8), &limits).0
        };
        let (loose, tight) = (run(1e-8), run(1e-12));
        assert_eq!(loose.steps.len(), 5, "{:?}", loose.failure);
        assert_eq!(tight.steps.len(), 5, "{:?}", tight.failure);
        for (a, b) in loose.steps.iter().zip(&tight.steps) {
            let rel = |x: f64, y: f64| ((x - y) / y).abs();
            let (pa, pb) = (a.p.unwrap_or(f64::NAN), b.p.unwrap_or(f64::NAN));
            let dv = (0..4)
                .map(|i| (a.qd_plus[i] - b.qd_plus[i]).abs())
                .fold(0.0, f64::max);
            let what = format!("mu0 = {mu0}, T_set = {t_set}");
            assert!(
                rel(a.period, b.period) < 1e-8,
                "{what}: T {} vs {}",
                a.period,
                b.period
            );
            assert!(rel(pa, pb) < 1e-8, "{what}: p {pa} vs {pb}");
            assert!(dv < 3e-8, "{what}: post-impact velocities off by {dv:e}");
        }
    }
}
