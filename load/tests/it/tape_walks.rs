//! A model file that is not compiled in walks exactly as the compiled one: every shipped model
//! that `walker` compiles, copied with its first mass written `1*(...)` (another parsed tree, so
//! another canonical content, and `walker-load` derives it at run time; the derivation's
//! polynomial is the same), walks the same steps bit for bit under
//! each friction law it is compiled for. The tape computes what the generated Rust computes
//! (walker-gen's `tape_vs_compiled`), so nothing may differ, not even in the last bit.

use std::path::PathBuf;

use walker::model::Friction;
use walker::setup::{Overrides, Setup};
use walker::sim::{SimConfig, WalkLimits, walk};

fn shipped(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../models")
        .join(format!("{name}.toml"))
}

/// A copy of `models/<name>.toml` in a temporary file, its first mass `1*(...)`: the same
/// walker, but not the compiled model's canonical content (`Model::canonical`).
fn copy(name: &str) -> PathBuf {
    let text = std::fs::read_to_string(shipped(name)).expect("a shipped model");
    let (head, tail) = text.split_once("mass = \"").expect("a body with a mass");
    let (mass, rest) = tail.split_once('"').expect("the mass's closing quote");
    let changed = format!("{head}mass = \"1*({mass})\"{rest}");
    let path = std::env::temp_dir().join(format!("walker-load-{}-{name}.toml", std::process::id()));
    std::fs::write(&path, changed).expect("a temporary file");
    path
}

/// `steps` steps of the model file at `path` with the overrides `ov`, from its start; derived
/// at run time if `runtime`, else compiled.
fn walk_with(
    path: &std::path::Path,
    ov: &Overrides,
    runtime: bool,
    steps: usize,
) -> walker::sim::Walk {
    let source = walker_load::runtime_source();
    let setup = Setup::from_model_file(path, ov, runtime.then_some(&source as &_))
        .expect("the model sets up");
    let model = setup.model().expect("kernels");
    let limits = WalkLimits {
        max_steps: steps,
        ..WalkLimits::default()
    };
    walk(&model, &SimConfig::default(), &model.start_state(), &limits)
}

fn walk_of(path: &std::path::Path, friction: Friction, runtime: bool) -> walker::sim::Walk {
    let ov = Overrides {
        friction: Some(friction),
        ..Overrides::default()
    };
    walk_with(path, &ov, runtime, 3)
}

#[test]
fn a_derived_copy_of_every_compiled_model_walks_bit_for_bit_as_the_compiled_one() {
    for name in [
        "paper-active",
        "paper-passive",
        "rimless-wheel",
        "compass-gait",
        "three-link",
    ] {
        let copied = copy(name);
        for friction in [Friction::Tanh, Friction::Coulomb] {
            let compiled = walk_of(&shipped(name), friction, false);
            let derived = walk_of(&copied, friction, true);
            let json = |w: &walker::sim::Walk| serde_json::to_string(w).expect("json");
            assert_eq!(json(&compiled), json(&derived), "{name} {friction:?}");
        }
        let _ = std::fs::remove_file(copied);
    }
}

#[test]
fn a_model_that_is_not_compiled_needs_the_run_time_source() {
    let copied = copy("rimless-wheel");
    let ov = Overrides::default();
    let err = Setup::from_model_file(&copied, &ov, None).expect_err("not compiled");
    assert!(
        err.to_string()
            .contains("not one of the models compiled into this program"),
        "{err}"
    );
    let _ = std::fs::remove_file(copied);
}

/// `[impact] double_support = false` turns the test off: the walk must not end at the first
/// heel strike (the impact then reports a zero rear impulse, which once read as the failure
/// `double-support`), and where the test never fires it walks the shipped file's steps.
#[test]
fn a_model_without_the_double_support_test_walks() {
    let text = std::fs::read_to_string(shipped("compass-gait")).expect("a shipped model");
    let changed = text.replacen("double_support = true", "double_support = false", 1);
    assert_ne!(text, changed, "compass-gait states its test");
    let path = std::env::temp_dir().join(format!(
        "walker-load-{}-no-double-support.toml",
        std::process::id()
    ));
    std::fs::write(&path, changed).expect("a temporary file");
    // Goswami's gait with the foot held: exact Coulomb friction in stance and at the impact,
    // mu0 = 5; its rear foot leaves the floor at every heel strike.
    let ov = Overrides {
        friction: Some(Friction::Coulomb),
        impact: Some(walker::model::ImpactLaw::Coulomb),
        set: vec![("mu0".to_owned(), 5.0)],
        ..Overrides::default()
    };
    let walk_held = |path: &std::path::Path, runtime: bool| walk_with(path, &ov, runtime, 5);
    let with_test = walk_held(&shipped("compass-gait"), false);
    let without = walk_held(&path, true);
    let _ = std::fs::remove_file(&path);
    assert!(with_test.failure.is_none(), "{:?}", with_test.failure);
    assert!(without.failure.is_none(), "{:?}", without.failure);
    assert_eq!(without.steps.len(), 5);
    for (a, b) in with_test.steps.iter().zip(&without.steps) {
        assert!(
            a.rear_impulse < 0.0,
            "the shipped test passes: {}",
            a.rear_impulse
        );
        assert_eq!(b.rear_impulse, 0.0);
        assert_eq!(
            (a.period, &a.q_plus, &a.qd_plus),
            (b.period, &b.q_plus, &b.qd_plus)
        );
    }
}
