//! Walks on a floor of patches by position (`walker::floor`, `docs/floors.md`, "Patches by
//! position"): the friction is a function of the position along the floor, so the stance foot
//! feels the patch it stands on, a foot that slides across a boundary changes friction there
//! (an event located like the others), and a strike lands on the patch under the new foot.

use walker::floor::{FloorPatch, FloorSpec, FloorWalker};
use walker::model::{Contact, Friction, ImpactLaw, ImpactRegime, Model};
use walker::ode::{Direction, Event, Integrator, NoObserver, OdeSystem, Outcome, Tolerances};
use walker::setup::Setup;
use walker::sim::{SimConfig, StepResult, Walk, WalkLimits};

fn limits(max_steps: usize, record: bool) -> WalkLimits {
    WalkLimits {
        max_steps,
        record,
        ..WalkLimits::default()
    }
}

/// The paper's active walker (`T_set = 0.3`) under `friction`, and the impact law `impact`.
fn active(friction: Friction, impact: ImpactLaw) -> Setup {
    let mut s = Setup::active_level().expect("the built-in scene");
    s.friction = friction;
    s.impact = impact;
    s.set("T_set", 0.3).expect("T_set");
    s
}

fn on(setup: &Setup, floor: FloorSpec, cfg: &SimConfig, steps: usize, record: bool) -> Walk {
    let start = setup.model().expect("model").start_state();
    FloorWalker::new(setup, floor)
        .expect("a floor the walker takes")
        .walk(0, cfg, &start, &limits(steps, record))
        .expect("the walk's models")
}

fn patches(mu0: f64, list: &[(f64, f64, f64)]) -> FloorSpec {
    FloorSpec::Patches {
        mu0,
        patches: list
            .iter()
            .map(|&(from, to, mu0)| FloorPatch { from, to, mu0 })
            .collect(),
    }
}

/// The largest difference between two steps' numbers, relative to `max(1, |value|)`.
fn step_difference(a: &StepResult, b: &StepResult) -> f64 {
    let pairs = [(a.period, b.period), (a.dx, b.dx), (a.speed, b.speed)]
        .into_iter()
        .chain(a.q_plus.iter().copied().zip(b.q_plus.iter().copied()))
        .chain(a.qd_plus.iter().copied().zip(b.qd_plus.iter().copied()));
    pairs
        .map(|(x, y)| (x - y).abs() / x.abs().max(1.0))
        .fold(0.0, f64::max)
}

#[test]
fn a_walk_on_patches_that_no_stance_foot_slides_across_is_the_walk_on_each_steps_patch() {
    // Patches laid between footholds: every step stands on one patch from its start to its
    // strike, so the walk must be the walk on the `steps` floor of each step's patch (run as
    // that floor: a step on a floor is a walk of one step from the same state). The paper's
    // frictionless strike does not read mu0, so where the new foot lands does not matter.
    // The tolerance is 1e-12 relative: the same arithmetic but for the boundary guard's
    // evaluations (which change no step of the integrator), so in fact bit for bit.
    for friction in [Friction::Tanh, Friction::Coulomb] {
        let setup = active(friction, ImpactLaw::Frictionless);
        let floor = patches(0.4, &[(0.8, 2.2, 0.05), (2.2, 3.0, 0.6), (4.0, 5.5, 0.2)]);
        let cfg = SimConfig::default();
        let walk = on(&setup, floor.clone(), &cfg, 30, false);
        assert_eq!(walk.failure, None, "{friction:?}");
        let start = setup.model().expect("model").start_state();
        // Each step's patch: under its stance foot at its start.
        let mut feet = vec![start[0]];
        feet.extend(walk.steps.iter().map(|s| s.q_plus[0]));
        let per_step: Vec<f64> = feet
            .iter()
            .map(|&x| floor.mu0_at(x).expect("a floor of patches"))
            .collect();
        assert!(per_step.contains(&0.05) && per_step.contains(&0.6) && per_step.contains(&0.2));
        let by_step = on(
            &setup,
            FloorSpec::Steps {
                mu0: per_step.clone(),
            },
            &cfg,
            30,
            false,
        );
        assert_eq!(by_step.steps.len(), walk.steps.len());
        for (k, (a, b)) in walk.steps.iter().zip(&by_step.steps).enumerate() {
            let f = a.floor.expect("a floor's record");
            assert_eq!(
                f.crossings,
                Some(0),
                "{friction:?} step {k}: no boundary crossed"
            );
            assert_eq!(f.mu0, per_step[k]);
            assert_eq!(f.mu0_strike, Some(per_step[k + 1]));
            let d = step_difference(a, b);
            assert!(d <= 1e-12, "{friction:?} step {k}: {d:e}");
        }
    }
}

/// The stance of a passive walker under the tanh law (no control, no power, no stick-slip:
/// the plain equations of motion), integrated by hand.
struct Plain<'m> {
    model: &'m Model,
}

impl<const S: usize> OdeSystem<S> for Plain<'_> {
    fn rhs(&mut self, t: f64, y: &[f64; S], dy: &mut [f64; S]) {
        let n = self.model.n();
        self.model
            .stance_rhs(t, &y[..2 * n], Contact::Smooth, &mut dy[..2 * n]);
        dy[2 * n..].fill(0.0);
    }
}

/// Integrates the stance of `model` from `(t, y)` until the event `g` falls through zero (or
/// either way where `either`), returning where (or how the integration ended otherwise).
fn until<const S: usize>(
    model: &Model,
    cfg: &SimConfig,
    t: f64,
    y: [f64; S],
    either: bool,
    g: impl Fn(&[f64; S]) -> f64,
) -> Result<(f64, [f64; S]), String> {
    let mut integ = Integrator::<S>::new(cfg.method, Tolerances::new(cfg.rtol, cfg.atol));
    let dir = if either {
        Direction::Either
    } else {
        Direction::Falling
    };
    let mut events = vec![Event::terminal(dir, |_, y: &[f64; S]| g(y))];
    let (mut t, mut y) = (t, y);
    loop {
        match integ.integrate(
            &mut Plain { model },
            t,
            &y,
            10.0,
            &mut events,
            &mut NoObserver,
        ) {
            Outcome::Event { t: te, y: ye, .. }
                if either || model.strike_ahead(&ye[..model.n()]) =>
            {
                return Ok((te, ye));
            }
            Outcome::Event { t: te, y: ye, .. } => (t, y) = (te, ye),
            other => return Err(format!("the stance ends without its event: {other:?}")),
        }
    }
}

#[test]
fn a_foot_that_slides_across_a_boundary_switches_friction_there_as_a_piecewise_stance_does() {
    // The passive wheel on its slope under the tanh law (its foot always slides a little).
    // Step 3's foot is found sliding on a uniform floor (mu0 = 0.2); a boundary is laid at
    // the middle of the stretch it slides over, beyond it dry floor (0.6), so steps 0 to 2
    // are the uniform walk's and step 3 crosses once. By hand: from the state after step 2,
    // the stance on 0.2 to the boundary, then on 0.6 from that state to the strike, and the
    // frictionless strike. Tolerances: both are run at rtol = atol = 1e-12; the hand's
    // integration has its own step sequence (a fresh integrator, no other guards), so the two
    // agree to a few times the tolerance, and 1e-10 leaves a factor of 100. The located
    // boundary is on it to 1e-9 m (the root is located to about 2 ulp of t, times a foot speed
    // below 1 m/s, and the state there by steps that end on it).
    let setup = Setup::passive_slope().expect("the built-in scene");
    let cfg = SimConfig {
        rtol: 1e-12,
        atol: 1e-12,
        ..SimConfig::default()
    };
    let k = 3;
    let uniform = on(&setup, FloorSpec::Uniform { mu0: 0.2 }, &cfg, k + 1, true);
    assert_eq!(uniform.failure, None);
    let model_a = setup
        .with("mu0", 0.2)
        .and_then(|s| Ok(s.model()?))
        .expect("0.2");
    let model_b = setup
        .with("mu0", 0.6)
        .and_then(|s| Ok(s.model()?))
        .expect("0.6");
    let cos_phi = model_a.phi().cos();
    let xs: Vec<f64> = uniform
        .samples
        .iter()
        .filter(|s| s.step == k)
        .map(|s| s.state[0])
        .collect();
    let x0 = uniform.steps[k - 1].q_plus[0];
    let (lo, hi) = xs.iter().fold((x0, x0), |(a, b), &x| (a.min(x), b.max(x)));
    assert!(hi - lo > 1e-6, "the foot slides {} m", hi - lo);
    let b = 0.5 * (lo + hi) / cos_phi;
    // The dry patch starts at the boundary on the side the foot slides to.
    let forward = xs.last().is_some_and(|&x| x > x0);
    let floor = if forward {
        patches(0.2, &[(b, b + 0.05, 0.6)])
    } else {
        patches(0.2, &[(b - 0.05, b, 0.6)])
    };
    let walk = on(&setup, floor, &cfg, k + 1, false);
    assert_eq!(walk.failure, None);
    for j in 0..k {
        assert_eq!(walk.steps[j].q_plus, uniform.steps[j].q_plus, "step {j}");
        assert_eq!(walk.steps[j].floor.and_then(|f| f.crossings), Some(0));
    }
    let f = walk.steps[k].floor.expect("a floor's record");
    assert_eq!((f.crossings, f.mu0), (Some(1), 0.2));

    const S: usize = 9;
    let n = model_a.n();
    assert!(2 * n < S, "the wheel's state fits");
    let mut y0 = [0.0; S];
    y0[..2 * n].copy_from_slice(&uniform.steps[k - 1].state_plus());
    let (tb, yb) =
        until(&model_a, &cfg, 0.0, y0, true, |y| y[0] / cos_phi - b).expect("the boundary");
    assert!(
        (yb[0] / cos_phi - b).abs() <= 1e-9,
        "the switch at {} m, the boundary at {b} m",
        yb[0] / cos_phi
    );
    let strike = |y: &[f64; S]| {
        let mut e = vec![0.0; model_b.event_count()];
        model_b.events(&y[..n], &mut e);
        e[0]
    };
    let (te, ye) = until(&model_b, &cfg, tb, yb, false, strike).expect("the strike");
    let pre: Vec<f64> = ye[..2 * n].to_vec();
    let imp = model_a.impact(&pre).expect("the frictionless strike");
    let post = model_a.reset(&pre, &imp);
    let step = &walk.steps[k];
    let d = (step.period - te).abs().max(
        step.q_plus
            .iter()
            .zip(post.q_plus.iter())
            .chain(step.qd_plus.iter().zip(post.qd_plus.iter()))
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max),
    );
    assert!(
        d <= 1e-10,
        "the walk's step and the piecewise stance differ by {d:e}"
    );
    // And the switch mattered: the uniform walk's step differs by far more.
    assert!(step_difference(step, &uniform.steps[k]) > 1e3 * d.max(1e-14));
}

#[test]
fn a_strike_landing_on_a_patch_uses_that_patchs_friction() {
    // Coulomb friction in stance and at the strike: on the dry floor (0.4) step 4's strike
    // sticks or draws a friction ratio above 0.05. An icy patch (0.05) laid around where
    // that strike lands, and nowhere under step 4's stance foot, leaves step 4's stance as it
    // was (its period and the new foot's position bit for bit) and makes the strike slip at
    // the patch's friction: |Lambda_t| = 0.05 Lambda_n (to rounding: the plastic impact's
    // slip regime puts the impulse on the cone's edge). Step 5 then stands on the ice.
    let setup = active(Friction::Coulomb, ImpactLaw::Coulomb);
    let cfg = SimConfig::default();
    let k = 4;
    let dry = on(&setup, FloorSpec::Uniform { mu0: 0.4 }, &cfg, k + 2, false);
    assert_eq!(dry.failure, None);
    let landing = dry.steps[k].q_plus[0];
    let [lt, ln] = dry.steps[k].foot_impulse;
    assert!(
        lt.abs() > 0.05 * ln * 1.5,
        "the dry strike draws {}",
        lt.abs() / ln
    );
    let walk = on(
        &setup,
        patches(0.4, &[(landing - 0.01, landing + 0.2, 0.05)]),
        &cfg,
        k + 2,
        false,
    );
    let step = &walk.steps[k];
    assert_eq!(
        (step.period, step.q_plus),
        (dry.steps[k].period, dry.steps[k].q_plus)
    );
    let f = step.floor.expect("a floor's record");
    assert_eq!(
        (f.mu0, f.mu0_strike, f.crossings),
        (0.4, Some(0.05), Some(0))
    );
    assert!(matches!(
        step.impact,
        ImpactRegime::Slide(_) | ImpactRegime::Reverse(_)
    ));
    let [lt, ln] = step.foot_impulse;
    assert!(
        (lt.abs() - 0.05 * ln).abs() <= 1e-12 * ln,
        "the strike's friction ratio {} on the 0.05 patch",
        lt.abs() / ln
    );
    assert_eq!(walk.steps[k + 1].floor.map(|f| f.mu0), Some(0.05));
}
