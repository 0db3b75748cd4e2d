//! The stiff integrator takes its Jacobian from the generated kernels.

use walker::model::{Model, Runtime};
use walker::ode::Method;
use walker::sim::{SimConfig, WalkLimits, walk_with_stats};

/// With Table 1 the state Jacobian comes from `closed_loop_level_jacobian` (no finite-difference
/// Jacobian is formed), and on a stiff friction law (`c = 1e4`, `mu0 = 1`) RODAS4 needs far
/// fewer right-hand sides than DOP853 for the same steps, with the same step descriptors to the
/// accuracy both were asked for. The input power `p` checks the Jacobian's row of the power
/// quadrature: a Rosenbrock method is only as accurate as its Jacobian (with that row zero,
/// RODAS4 does not even finish the walk: its error estimate of the quadrature stays too large).
#[test]
fn rodas4_uses_the_generated_jacobian_on_stiff_friction() {
    let m = Model::active_level(Runtime {
        mu0: 1.0,
        c: 1e4,
        t_set: 0.3,
        ..Runtime::default()
    });
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
    let (a, sa) = walk_with_stats(&m, &explicit, m.initial_state(0.8), &limits);
    let (b, sb) = walk_with_stats(&m, &stiff, m.initial_state(0.8), &limits);
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
