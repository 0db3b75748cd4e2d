//! With its foot held (exact Coulomb friction in stance, the plastic impact with Coulomb
//! friction, a large `mu0`) the passive wheel of Section 5 is the classic rimless wheel of
//! McGeer (*Passive dynamic walking*, IJRR 9(2), 1990) and Coleman, Chatterjee and Ruina
//! (*Motions of a rimless spoked wheel: a simple three-dimensional system with impacts*,
//! Dynamics and Stability of Systems 12(3), 1997), whose steady gait has closed forms.
//!
//! Derived here for this wheel: hub mass `m = m1 + m2`, inertia `I1` about the hub, spokes of
//! length `l` separated by `alpha`, slope `phi`; the torso turns freely about the hub, where its
//! centre of mass is, so nothing acts on it and it decouples (`th2d = 0` stays). In stance the
//! wheel is a rigid inverted pendulum about the stuck foot, `th1` measured from the vertical:
//! `(I1 + m l^2) th1dd = m g l sin th1`, so `th1d^2 = w0^2 + K (cos th_a - cos th1)` with
//! `K = 2 m g l / (I1 + m l^2)` from the post-impact angle `th_a = phi - alpha/2` to the
//! heel strike at `th_b = phi + alpha/2`. At the sticking impact the angular momentum about
//! the new foot is conserved (the old foot leaves without impulse):
//! `(I1 + m l^2) w0 = (I1 + m l^2 cos alpha) w1`, so `w0 = eta w1` with
//! `eta = (I1 + m l^2 cos alpha) / (I1 + m l^2)`. The fixed point is
//! `w1^2 = K (cos th_a - cos th_b) / (1 - eta^2)`, `cos th_a - cos th_b = 2 sin phi sin(alpha/2)`;
//! the step period is `T = integral from th_a to th_b of dth / th1d(th)`; the step length along
//! the slope is the chord `2 l sin(alpha/2)`; and the map `w0 -> eta sqrt(w0^2 + K (..))` has the
//! derivative `eta^2` at the fixed point: the gait's multiplier (the other one is 0, the foot's
//! velocity that every sticking impact removes).
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use crate::common;

use common::start;
use walker::model::{Friction, ImpactLaw, ImpactRegime};
use walker::poincare::{FixedPointOptions, JacobianMethod, Status, fixed_point};
use walker::setup::Setup;
use walker::sim::{SimConfig, WalkLimits, walk};

/// The closed-form gait: post-impact angular velocity, step period, step length, multiplier.
struct Closed {
    w0: f64,
    period: f64,
    dx: f64,
    multiplier: f64,
}

/// The closed form for the physical parameters of the paper's wheel `setup` on the slope
/// `phi`.
fn closed_form(setup: &Setup, phi: f64) -> Closed {
    let p = |name: &str| setup.params.get(name).unwrap();
    let (m, l, i1, g, alpha) = (p("m1") + p("m2"), p("l"), p("I1"), p("g"), p("alpha"));
    rimless(m, l, i1, g, alpha, phi)
}

/// The closed form for a hub of mass `m` and inertia `i1`, spokes `l` at `alpha`, gravity `g`,
/// slope `phi`.
fn rimless(m: f64, l: f64, i1: f64, g: f64, alpha: f64, phi: f64) -> Closed {
    let j = i1 + m * l * l;
    let eta = (i1 + m * l * l * alpha.cos()) / j;
    let k = 2.0 * m * g * l / j;
    let (th_a, th_b) = (phi - alpha / 2.0, phi + alpha / 2.0);
    let w1 = (k * (th_a.cos() - th_b.cos()) / (1.0 - eta * eta)).sqrt();
    let w0 = eta * w1;
    // Composite Simpson on a smooth integrand (th1d >= w0 > 0): with 4000 intervals of
    // 1.3e-4 rad the error is about h^4 |f''''| / 180, below 1e-15 relative.
    let f = |th: f64| 1.0 / (w0 * w0 + k * (th_a.cos() - th.cos())).sqrt();
    let n = 4000;
    let h = (th_b - th_a) / f64::from(n);
    let mut sum = f(th_a) + f(th_b);
    for i in 1..n {
        let w = if i % 2 == 1 { 4.0 } else { 2.0 };
        sum += w * f(th_a + h * f64::from(i));
    }
    Closed {
        w0,
        period: sum * h / 3.0,
        dx: 2.0 * l * (alpha / 2.0).sin(),
        multiplier: eta * eta,
    }
}

fn held_wheel(phi: f64, mu0: f64) -> Setup {
    let mut setup = common::setup("passive-slope", &[("phi", phi), ("mu0", mu0)]);
    setup.friction = Friction::Coulomb;
    setup.impact = ImpactLaw::Coulomb;
    setup
}

#[test]
fn the_held_passive_wheel_is_the_classic_rimless_wheel() {
    for phi in [0.05, 0.1, 0.2] {
        let setup = held_wheel(phi, 3.0);
        let model = common::model(&setup);
        let fp = fixed_point(
            &model,
            &SimConfig::default(),
            &FixedPointOptions::for_model(&model),
        )
        .unwrap();
        let c = closed_form(&setup, phi);
        assert_eq!(fp.status, Status::Converged, "phi = {phi}: {fp:?}");
        assert_eq!(fp.impact, ImpactRegime::Stick, "phi = {phi}");
        // The Coulomb variant is compiled with its Jacobian kernels (`stick_jacobian`): the
        // map's derivative comes from the variational equations.
        assert_eq!(fp.jacobian_method, JacobianMethod::Variational);
        // The foot stays put: stuck through the stance, stopped by the impact.
        assert!(fp.state_plus[4].abs() < 1e-15, "xd+ = {}", fp.state_plus[4]);
        // The map is evaluated at rtol 1e-12 and Newton stops at a residual of 1e-11: the
        // cycle's angular velocity and period are good to about 1e-11; 1e-9 leaves a margin
        // of 100 for the accumulation over the stance.
        let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
        assert!(
            rel(fp.state_plus[6], c.w0) < 1e-9,
            "phi = {phi}: {} vs {}",
            fp.state_plus[6],
            c.w0
        );
        assert!(
            rel(fp.period, c.period) < 1e-9,
            "phi = {phi}: T {} vs {}",
            fp.period,
            c.period
        );
        // The step is the chord between two spoke ends, to rounding.
        assert!(
            rel(fp.dx, c.dx) < 1e-12,
            "phi = {phi}: dx {} vs {}",
            fp.dx,
            c.dx
        );
        // The multiplier comes from the variational equations integrated with the step at
        // rtol 1e-12: its error is of the integration's, about 1e-11 relative; 1e-9 leaves a
        // margin of 100 (central differences with h = 1e-4 were good to 1e-8 only).
        let lead = fp.multipliers[0];
        assert!(
            lead.im == 0.0 && rel(lead.re, c.multiplier) < 1e-9,
            "phi = {phi}: {lead:?} vs {}",
            c.multiplier
        );
        assert!(fp.multipliers[1].modulus() < 1e-6, "{:?}", fp.multipliers);
    }
}

/// `models/rimless-wheel.toml` (no torso: `I = m rg^2` about the hub) with its foot held.
fn held_rimless_wheel(phi: f64) -> (Setup, walker::model::Model) {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../models/rimless-wheel.toml");
    let ov = walker::setup::Overrides {
        friction: Some(Friction::Coulomb),
        impact: Some(ImpactLaw::Coulomb),
        set: vec![("phi".into(), phi), ("mu0".into(), 3.0)],
        ..walker::setup::Overrides::default()
    };
    let setup = Setup::from_model_file(&path, &ov, None).unwrap();
    let model = setup.model().unwrap();
    (setup, model)
}

#[test]
fn the_rimless_wheel_model_walks_its_closed_form_gait() {
    for phi in [0.05, 0.1, 0.2] {
        let (setup, model) = held_rimless_wheel(phi);
        let p = |name: &str| setup.params.get(name).unwrap();
        let (m, rg) = (p("m"), p("rg"));
        let c = rimless(m, p("l"), m * rg * rg, p("g"), p("alpha"), phi);
        let cfg = SimConfig {
            rtol: 1e-12,
            atol: 1e-12,
            ..SimConfig::default()
        };
        let fp = fixed_point(&model, &cfg, &FixedPointOptions::for_model(&model)).unwrap();
        assert_eq!(fp.status, Status::Converged, "phi = {phi}: {fp:?}");
        assert_eq!(fp.impact, ImpactRegime::Stick, "phi = {phi}");
        // State [x, z, th, xd, zd, thd]; tolerances as for the paper's wheel above.
        let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
        assert!(rel(fp.state_plus[5], c.w0) < 1e-9, "phi = {phi}: {fp:?}");
        assert!(
            rel(fp.period, c.period) < 1e-9,
            "phi = {phi}: T {}",
            fp.period
        );
        assert!(rel(fp.dx, c.dx) < 1e-12, "phi = {phi}: dx {}", fp.dx);
        let lead = fp
            .multipliers
            .iter()
            .max_by(|a, b| a.modulus().total_cmp(&b.modulus()))
            .unwrap();
        assert!(
            lead.im == 0.0 && rel(lead.re, c.multiplier) < 1e-6,
            "phi = {phi}: {:?} vs {}",
            fp.multipliers,
            c.multiplier
        );
    }
}

#[test]
fn with_the_papers_frictionless_impact_the_held_wheel_cannot_walk() {
    // The frictionless impact lets the new foot slide on (here forward at 0.64 m/s), and under
    // exact Coulomb friction with mu0 = 3 a foot sliding forward would be pulled off the floor
    // by its own friction (Painleve's paradox): the first stance after an impact has no
    // consistent contact. With friction at the impact the foot is stopped and the wheel walks.
    let limits = WalkLimits {
        max_steps: 20,
        ..WalkLimits::default()
    };
    let mut setup = held_wheel(0.1, 3.0);
    setup.impact = ImpactLaw::Frictionless;
    let model = common::model(&setup);
    let w = walk(&model, &SimConfig::default(), &start(&model, 0.5), &limits);
    let failure = w.failure.expect("the frictionless impact fails");
    assert_eq!((failure.name(), failure.step), ("contact-inconsistent", 1));
    assert!(
        failure.state[4] > 0.5,
        "the new foot slides forward: {failure:?}"
    );
    let model = common::model(&held_wheel(0.1, 3.0));
    let w = walk(&model, &SimConfig::default(), &start(&model, 0.5), &limits);
    assert!(
        w.failure.is_none() && w.steps.len() == 20,
        "{:?}",
        w.failure
    );
    assert!(
        w.steps
            .iter()
            .all(|s| s.impact == ImpactRegime::Stick && s.stuck_time == s.period)
    );
}
