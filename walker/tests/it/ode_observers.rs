//! The hooks for quadratures with kinks: [`OdeSystem::controlled_components`] (a component the
//! error test leaves out on some steps), [`Observer::wants_step`] (only the steps asked for are
//! shown, and only they pay for the dense output).

#![allow(clippy::panic)] // tests report failures by panicking

use walker::ode::{Integrator, Method, NoObserver, Observer, OdeSystem, Outcome, Step, Tolerances};

const METHODS: [Method; 3] = [Method::Dopri5, Method::Dop853, Method::Rodas4];

/// `x' = -x` (smooth) and the quadrature `q' = |sin(w t)|`, whose integrand has a kink at every
/// multiple of `pi / w`. With `watch_q == false` the error test leaves `q` out on the steps
/// that contain a kink (a sign change of `sin(w t)` between the step's ends), as the walker's
/// power quadrature does.
struct Kinked {
    w: f64,
    watch_q: bool,
}

impl OdeSystem<2> for Kinked {
    fn rhs(&mut self, t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        dy[0] = -y[0];
        dy[1] = (self.w * t).sin().abs();
    }

    fn jacobian(&mut self, _t: f64, _y: &[f64; 2], jac: &mut [[f64; 2]; 2]) -> bool {
        *jac = [[-1.0, 0.0], [0.0, 0.0]];
        true
    }

    fn controlled_components(&mut self, t0: f64, _y0: &[f64; 2], t1: f64, _y1: &[f64; 2]) -> usize {
        let crossed = (self.w * t0).sin() * (self.w * t1).sin() < 0.0;
        if self.watch_q || !crossed { 2 } else { 1 }
    }
}

fn run<O: Observer<2>>(method: Method, watch_q: bool, obs: &mut O) -> ([f64; 2], u64, u64) {
    let mut sys = Kinked { w: 10.0, watch_q };
    let mut integ = Integrator::<2>::new(method, Tolerances::new(1e-9, 1e-9));
    let out = integ.integrate(&mut sys, 0.0, &[1.0, 0.0], 2.0, &mut [], obs);
    let Outcome::Reached { y, .. } = out else {
        panic!("{method:?}: {out:?}");
    };
    let st = integ.stats();
    (y, st.rejected_steps, st.rhs_evals)
}

/// Leaving the kinked quadrature out of the error test on the kink steps removes the
/// rejections that the kinks cause, and the watched component stays as accurate as the
/// tolerance asks (it does not depend on the quadrature).
#[test]
fn an_unwatched_component_causes_no_rejections_at_its_kinks() {
    for method in METHODS {
        let (y_all, rej_all, _) = run(method, true, &mut NoObserver);
        let (y_some, rej_some, _) = run(method, false, &mut NoObserver);
        // 6 kinks in [0, 2] for w = 10: each costs rejections when watched.
        assert!(
            rej_some + 6 <= rej_all,
            "{method:?}: rejections {rej_some} (kinks unwatched) vs {rej_all} (watched)"
        );
        let exact = (-2.0f64).exp();
        for y in [y_all, y_some] {
            assert!((y[0] - exact).abs() < 1e-7, "{method:?}: x(2) = {}", y[0]);
        }
    }
}

/// An observer that asks only for the steps containing a kink and integrates `|sin(w t)|`
/// exactly on them (a closed form, standing in for a quadrature on the dense output), keeping
/// the difference to the method's value: the corrected quadrature is then as accurate as the
/// rest, while without the correction it is not.
struct KinkCorrection {
    w: f64,
    asked: usize,
    shown: usize,
    correction: f64,
}

impl KinkCorrection {
    /// `int_a^b |sin(w t)| dt` for an interval with at most one kink.
    fn exact(&self, a: f64, b: f64) -> f64 {
        let w = self.w;
        let prim = |t: f64| -(w * t).cos() / w;
        let k = (b * w / std::f64::consts::PI).floor();
        let kink = k * std::f64::consts::PI / w;
        if kink > a && kink < b {
            (prim(kink) - prim(a)).abs() + (prim(b) - prim(kink)).abs()
        } else {
            (prim(b) - prim(a)).abs()
        }
    }
}

impl Observer<2> for KinkCorrection {
    fn wants_step(&mut self, t0: f64, _y0: &[f64; 2], t1: f64, _y1: &[f64; 2]) -> bool {
        self.asked += 1;
        (self.w * t0).sin() * (self.w * t1).sin() < 0.0
    }

    fn on_step(&mut self, step: &Step<'_, 2>) {
        self.shown += 1;
        let (a, b) = (step.t_start(), step.t_end());
        let method = step.y_end()[1] - step.y_start()[1];
        self.correction += self.exact(a, b) - method;
    }
}

/// `int_0^2 |sin(10 t)| dt`.
fn quadrature_exact() -> f64 {
    let w = 10.0f64;
    let full = (2.0 * w / std::f64::consts::PI).floor();
    let rest = 2.0 * w - full * std::f64::consts::PI;
    (2.0 * full + (1.0 - rest.cos())) / w
}

#[test]
fn observers_see_only_the_steps_they_ask_for_and_the_correction_makes_the_kinks_exact() {
    for method in METHODS {
        let mut obs = KinkCorrection {
            w: 10.0,
            asked: 0,
            shown: 0,
            correction: 0.0,
        };
        let (y, _, _) = run(method, false, &mut obs);
        assert!(obs.asked > obs.shown, "{method:?}: every step was shown");
        assert_eq!(obs.shown, 6, "{method:?}: one step per kink");
        let q = quadrature_exact();
        let corrected = (y[1] + obs.correction - q).abs();
        let raw = (y[1] - q).abs();
        assert!(
            corrected < 1e-8,
            "{method:?}: corrected error {corrected:e}"
        );
        assert!(
            raw > 100.0 * corrected,
            "{method:?}: uncorrected error {raw:e} is as small"
        );
    }
}

/// Asking for no step saves the dense output: DOP853 builds its 7th-order interpolant with
/// three extra right-hand sides only for the steps shown.
#[test]
fn steps_not_asked_for_cost_no_dense_output() {
    struct All;
    impl Observer<2> for All {
        fn on_step(&mut self, _: &Step<'_, 2>) {}
    }
    struct None_;
    impl Observer<2> for None_ {
        fn wants_step(&mut self, _: f64, _: &[f64; 2], _: f64, _: &[f64; 2]) -> bool {
            false
        }
        fn on_step(&mut self, _: &Step<'_, 2>) {
            panic!("a step nobody asked for was shown");
        }
    }
    let (_, _, rhs_all) = run(Method::Dop853, true, &mut All);
    let (_, _, rhs_none) = run(Method::Dop853, true, &mut None_);
    let (_, _, rhs_no_observer) = run(Method::Dop853, true, &mut NoObserver);
    assert_eq!(rhs_none, rhs_no_observer);
    assert!(rhs_all > rhs_none, "{rhs_all} vs {rhs_none}");
}
