//! The Poincare map and the fixed-point search fail with typed errors that keep the time and
//! the cause: a non-finite state, a state or seeds of the wrong shape, a heel strike that does not come in time (also in the map by
//! finite differences of a model without Jacobian kernels), and a warm-up walk that falls.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use crate::common;

use common::start;
use walker::model::Model;
use walker::poincare::{
    FixedPointError, FixedPointOptions, JacobianMethod, MapError, Section, StepCheck,
    finite_difference_map_with_step, fixed_point, poincare_map, poincare_map_along,
    poincare_map_with,
};
use walker::sim::SimConfig;
use walker::vector::Vector;

/// The active walker's friction and control settings.
const RUNTIME: [(&str, f64); 2] = [("mu0", 0.4), ("T_set", 0.3)];

fn active() -> Model {
    common::active(&RUNTIME)
}

/// A post-impact state near the Table 1 cycle.
fn near_cycle(model: &Model) -> Vector {
    Section::of(model).embed(&[0.55, 0.75])
}

#[test]
fn a_non_finite_state_is_refused_before_integrating() {
    let model = active();
    let mut s = near_cycle(&model);
    s[6] = f64::NAN;
    let err = poincare_map(&model, &SimConfig::default(), &s).unwrap_err();
    assert_eq!(err, MapError::NonFiniteStart);
    assert!(err.to_string().contains("non-finite"), "{err}");
}

#[test]
fn a_state_or_seeds_of_the_wrong_shape_are_refused_by_name() {
    let model = active();
    let cfg = SimConfig::default();
    let s = near_cycle(&model);
    let short = &s[..7];
    for err in [
        poincare_map(&model, &cfg, short).unwrap_err(),
        finite_difference_map_with_step(&model, &cfg, short, 1e-4).unwrap_err(),
    ] {
        assert_eq!(
            err,
            MapError::Shape {
                what: "the state",
                got: 7,
                expected: 8
            }
        );
        assert!(err.to_string().contains("the state has 7 entries"), "{err}");
    }
    let seeds = vec![vec![1.0, 0.0]; 8];
    let along = |seeds: &[Vec<f64>]| {
        let method = JacobianMethod::Variational;
        poincare_map_along(&model, &cfg, &s, seeds, method, StepCheck::Through).unwrap_err()
    };
    assert!(matches!(
        along(&seeds[..5]),
        MapError::Shape {
            what: "the seeds",
            got: 5,
            ..
        }
    ));
    let mut ragged = seeds.clone();
    ragged[3].push(0.0);
    assert!(matches!(
        along(&ragged),
        MapError::Shape {
            what: "a seed row",
            got: 3,
            ..
        }
    ));
    let mut nan = seeds;
    nan[2][1] = f64::NAN;
    assert_eq!(along(&nan), MapError::NonFiniteStart);
}

#[test]
fn no_heel_strike_within_the_step_time_reports_that_time() {
    let model = active();
    let cfg = SimConfig {
        max_step_time: 0.01,
        ..SimConfig::default()
    };
    let err = poincare_map(&model, &cfg, &near_cycle(&model)).unwrap_err();
    assert_eq!(err, MapError::NoHeelStrike { t: 0.01 });
    assert!(err.to_string().contains("no heel strike"), "{err}");
}

#[test]
fn a_step_that_fails_in_the_finite_difference_map_is_named() {
    // The map by finite differences walks one step of the simulator, and a failure of that
    // step (here no heel strike within 0.01 s) keeps its name. (The exact-Coulomb variant
    // now has Jacobian kernels, so the differences are asked for by name.)
    let model = common::active_coulomb(&RUNTIME);
    let cfg = SimConfig {
        max_step_time: 0.01,
        ..SimConfig::default()
    };
    let err = poincare_map_with(
        &model,
        &cfg,
        &near_cycle(&model),
        JacobianMethod::FiniteDifferences,
    )
    .unwrap_err();
    let MapError::Walk(failure) = &err else {
        panic!("expected a failed step, got {err:?}");
    };
    assert_eq!(failure.name(), "no-impact");
    assert!(err.to_string().contains("no-impact"), "{err}");
}

#[test]
fn a_warm_up_walk_that_fails_reports_the_failure_by_value() {
    let model = active();
    let opts = FixedPointOptions {
        start: start(&model, -1.0),
        ..FixedPointOptions::for_model(&model)
    };
    let err = fixed_point(&model, &SimConfig::default(), &opts).unwrap_err();
    let FixedPointError::Warmup(failure) = &err else {
        panic!("expected a warm-up failure, got {err:?}");
    };
    assert!(err.to_string().contains(failure.name()), "{err}");
}

#[test]
fn the_map_error_passes_through_the_fixed_point_search() {
    let model = active();
    let cfg = SimConfig {
        max_step_time: 0.01,
        ..SimConfig::default()
    };
    let err = walker::poincare::newton(
        &model,
        &cfg,
        &Section::of(&model).reduce(&near_cycle(&model)),
        &FixedPointOptions::for_model(&model),
    )
    .unwrap_err();
    assert_eq!(
        err,
        FixedPointError::Map(MapError::NoHeelStrike { t: 0.01 })
    );
}

#[test]
fn a_fall_within_the_stance_is_the_maps_failure_and_the_step_check_is_the_walks() {
    // The passive wheel on phi = 0.1 with mu0 = 0.19 falls back onto its rear spoke in a
    // step of its walk from (P2b) (Fig. 14, `walker reproduce`): the map of that step stops
    // there with the model's fall, as the simulator does, instead of integrating the wheel on
    // through the floor.
    let model = common::passive(&[("mu0", 0.19), ("phi", 0.1)]);
    let cfg = SimConfig::default();
    let limits = walker::sim::WalkLimits {
        max_steps: 5,
        ..walker::sim::WalkLimits::default()
    };
    let w = walker::sim::walk(&model, &cfg, &start(&model, 0.8), &limits);
    let fell = w.failure.as_ref().expect("the wheel falls");
    assert_eq!(fell.name(), "fell-backward");
    let s = w.last_state().expect("a step before the fall");
    let got = poincare_map(&model, &cfg, &s);
    let Err(MapError::Fall { name, t }) = got else {
        panic!("expected the fall, got {got:?}");
    };
    assert_eq!(name, "fell-backward");
    assert!(t > 0.0 && t < cfg.max_step_time, "{t}");
    // With the simulator's step checked first, its failure is the map's (as for differences).
    let section = Section::of(&model);
    let r = section.reduce(&s);
    let err = section
        .map_with(&cfg, &r, JacobianMethod::Variational, StepCheck::Walk)
        .unwrap_err();
    let MapError::Walk(failure) = &err else {
        panic!("expected the walk's failure, got {err:?}");
    };
    assert_eq!(failure.name(), "fell-backward", "{err}");
}
