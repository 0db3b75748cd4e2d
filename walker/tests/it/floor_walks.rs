//! Walks on floors that change under the walker (`walker::floor`, `docs/floors.md`): a uniform
//! floor is no floor, a step's friction acts in that step only, a walk equals itself run piece
//! by piece, random floors are a pure function of (seed, walk, step), and the checks of a
//! floor against a walker.

use walker::floor::{Distribution, FloorError, FloorSpec, FloorWalker};
use walker::model::Friction;
use walker::setup::Setup;
use walker::sim::{SimConfig, StepResult, Walk, WalkLimits, walk};

fn limits(max_steps: usize) -> WalkLimits {
    WalkLimits {
        max_steps,
        ..WalkLimits::default()
    }
}

fn active(friction: Friction) -> Setup {
    let mut s = Setup::active_level().expect("the built-in scene");
    s.friction = friction;
    s.set("T_set", 0.3).expect("T_set");
    s
}

fn passive() -> Setup {
    Setup::passive_slope().expect("the built-in scene")
}

/// A walk's JSON without the floor of its steps: equal strings are equal numbers bit for bit
/// (serde_json writes the shortest digits that read back to the same double).
fn json_without_floor(w: &Walk) -> String {
    let mut w = w.clone();
    for s in &mut w.steps {
        s.floor = None;
    }
    serde_json::to_string(&w).expect("a walk serialises")
}

fn on_floor(setup: &Setup, floor: FloorSpec, walk_index: u64, steps: usize) -> Walk {
    let model = setup.model().expect("model");
    FloorWalker::new(setup, floor)
        .expect("a floor the walker takes")
        .walk(
            walk_index,
            &SimConfig::default(),
            &model.start_state(),
            &limits(steps),
        )
        .expect("the walk's models")
}

#[test]
fn a_uniform_floor_at_the_walkers_mu0_is_the_walk_without_a_floor_bit_for_bit() {
    for setup in [active(Friction::Tanh), active(Friction::Coulomb), passive()] {
        let model = setup.model().expect("model");
        let plain = walk(
            &model,
            &SimConfig::default(),
            &model.start_state(),
            &limits(40),
        );
        let mu0 = model.mu0();
        let floored = on_floor(&setup, FloorSpec::Uniform { mu0 }, 0, 40);
        assert_eq!(json_without_floor(&floored), json_without_floor(&plain));
        assert_eq!(floored.steps.len(), 40);
        assert!(
            floored
                .steps
                .iter()
                .all(|s| s.floor.map(|f| f.mu0) == Some(mu0))
        );
        // Without a floor the records carry none (and the JSON has no `floor` key).
        assert!(plain.steps.iter().all(|s| s.floor.is_none()));
        assert!(
            !serde_json::to_string(&plain)
                .expect("json")
                .contains("floor")
        );
    }
}

#[test]
fn an_icy_step_makes_the_papers_walker_slip_through_its_whole_stance_where_dry_it_sticks() {
    // Coulomb friction shows slipping plainly: on the dry floor (mu0 = 0.4) the stance foot
    // sticks for part of every step; on the icy step 3 (mu0 = 0.05) it slides throughout.
    let setup = active(Friction::Coulomb);
    let dry = on_floor(&setup, FloorSpec::Uniform { mu0: 0.4 }, 0, 8);
    let icy = on_floor(
        &setup,
        FloorSpec::Steps {
            mu0: vec![0.4, 0.4, 0.4, 0.05, 0.4],
        },
        0,
        8,
    );
    assert_eq!((dry.failure.as_ref(), icy.failure.as_ref()), (None, None));
    assert!(dry.steps.iter().all(|s| s.stuck_time > 0.0));
    assert_eq!(icy.steps[3].stuck_time, 0.0);
    assert_eq!(icy.steps[3].floor.map(|f| f.mu0), Some(0.05));
    // The last value holds after the list: step 7 walks on 0.4.
    assert_eq!(icy.steps[7].floor.map(|f| f.mu0), Some(0.4));
    // The steps before the icy one are the dry walk's, bit for bit.
    let before = |w: &Walk| serde_json::to_string(&w.steps[..3]).expect("json");
    assert_eq!(before(&icy), before(&dry));
    assert_ne!(icy.steps[3].q_plus, dry.steps[3].q_plus);
}

#[test]
fn an_icy_step_makes_the_passive_wheel_fall_where_the_dry_slope_carries_it() {
    let setup = passive();
    let dry = on_floor(&setup, FloorSpec::Uniform { mu0: 0.2 }, 0, 10);
    assert_eq!((dry.steps.len(), dry.failure.as_ref()), (10, None));
    let icy = on_floor(
        &setup,
        FloorSpec::Steps {
            mu0: vec![0.2, 0.2, 0.2, 0.2, 0.05, 0.2],
        },
        0,
        10,
    );
    let failure = icy.failure.as_ref().expect("it falls on the ice");
    assert_eq!((failure.step, icy.steps.len()), (4, 4));
}

/// Step `k` of a walk on a changing floor, run alone from the state after step `k - 1` on the
/// model of its own `mu0`.
fn piecewise(setup: &Setup, mu0: &[f64]) -> Vec<StepResult> {
    let mut state = setup.model().expect("model").start_state();
    let mut steps = Vec::new();
    for &m in mu0 {
        let model = setup.with("mu0", m).expect("mu0").model().expect("model");
        let w = walk(&model, &SimConfig::default(), &state, &limits(1));
        let step = w.steps[0];
        state = step.state_plus();
        steps.push(step);
    }
    steps
}

#[test]
fn a_walk_on_a_changing_floor_is_the_same_walk_run_one_step_at_a_time() {
    let setup = active(Friction::Tanh);
    let mu0 = [0.4, 0.1, 0.05, 0.3, 0.02, 0.4];
    let floored = on_floor(&setup, FloorSpec::Steps { mu0: mu0.to_vec() }, 0, mu0.len());
    let pieces = piecewise(&setup, &mu0);
    assert_eq!(floored.steps.len(), pieces.len());
    for (k, (a, b)) in floored.steps.iter().zip(&pieces).enumerate() {
        // The integrator starts each step afresh, so the two are the same arithmetic; the
        // issue's bound 1e-12 (relative to the state's size, about 1) is what is promised.
        let (sa, sb) = (a.state_plus(), b.state_plus());
        let err = sa
            .iter()
            .zip(sb.iter())
            .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()));
        assert!(err <= 1e-12, "step {k}: {err:e}");
        assert!((a.period - b.period).abs() <= 1e-12, "step {k}");
    }
}

fn markov() -> FloorSpec {
    FloorSpec::Random {
        seed: 11,
        mu0: Distribution::Markov {
            dry: 0.3,
            icy: 0.05,
            dry_length: 6.0,
            icy_length: 2.0,
        },
    }
}

#[test]
fn a_random_floor_is_the_same_for_the_same_seed_and_walk_and_differs_between_walks() {
    let setup = passive();
    let walker = FloorWalker::new(&setup, markov()).expect("floor");
    let a: Vec<f64> = walker.steps(3).take(200).collect();
    assert_eq!(a, walker.steps(3).take(200).collect::<Vec<_>>());
    assert_ne!(a, walker.steps(4).take(200).collect::<Vec<_>>());
    assert!(a.iter().all(|&x| x == 0.3 || x == 0.05));
    // Patches: the mean length of the icy runs is about 2 steps, of the dry ones about 6.
    let values: Vec<f64> = walker.steps(0).take(20_000).collect();
    let icy_share = values.iter().filter(|&&x| x == 0.05).count() as f64 / values.len() as f64;
    // Stationary share 2 / 8 = 0.25; with runs of ~8 steps, 20000 steps are ~2500 runs, so
    // the share's sd is about 0.25 * 0.75 * sqrt(8 / 20000) / 0.43 = 0.01: 0.05 is 5 sd.
    assert!((icy_share - 0.25).abs() < 0.05, "{icy_share}");
}

#[test]
fn on_a_markov_floor_the_passive_wheel_falls_only_on_icy_steps() {
    let setup = passive();
    let walker = FloorWalker::new(&setup, markov()).expect("floor");
    let model = setup.model().expect("model");
    let mut falls = 0;
    for i in 0..6 {
        let w = walker
            .walk(i, &SimConfig::default(), &model.start_state(), &limits(40))
            .expect("walk");
        let mu0: Vec<f64> = walker.steps(i).take(41).collect();
        // Every completed step records the floor's value for it.
        for (k, s) in w.steps.iter().enumerate() {
            assert_eq!(s.floor.map(|f| f.mu0), Some(mu0[k]));
        }
        if let Some(f) = &w.failure {
            falls += 1;
            assert_eq!(mu0[f.step], 0.05, "walk {i} fails on a dry step {}", f.step);
        }
    }
    assert!(falls > 0, "some walk meets the ice within 40 steps");
}

#[test]
fn a_floor_the_walker_cannot_take_is_refused_by_name() {
    // The friction law `none` ignores mu0.
    let mut none = active(Friction::Tanh);
    none.friction = Friction::None;
    assert!(matches!(
        FloorWalker::new(&none, FloorSpec::Uniform { mu0: 0.4 }),
        Err(FloorError::Frictionless)
    ));
    // A scene that fixes mu0 at generation.
    let mut fixed = active(Friction::Tanh);
    fixed.fixed.push(("mu0".to_owned(), 0.4));
    let e = FloorWalker::new(&fixed, FloorSpec::Uniform { mu0: 0.4 }).expect_err("fixed");
    assert!(
        matches!(e, FloorError::Fixed { ref name, .. } if name == "mu0"),
        "{e}"
    );
    assert!(
        e.to_string().contains("must be a run-time parameter"),
        "{e}"
    );
}
