//! The hopper compiled by this crate's build script (`walker_gen::Compile`) runs in the walker
//! simulator as a first-class model: found by its content once registered, and walking bit for
//! bit as the same model file derived at run time and evaluated by walker-gen's tape
//! (`walker-load`), which performs the same IEEE operations on the same values (the tape's
//! module docs argue why; `tests/tests/it/tape_vs_compiled.rs` checks it kernel by kernel). Any
//! difference in a step's time, state or descriptors, down to the last bit, fails.

#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use std::path::Path;
use std::sync::Arc;

use own_walker::compiled::MODELS;
use walker::model::{Friction, KernelSource, Spec, Walker};
use walker::setup::{Setup, walker_of};
use walker::sim::{SimConfig, WalkLimits, walk};
use walker_scene::model::Model as ModelFile;

fn model_file() -> ModelFile {
    ModelFile::from_file(&Path::new(env!("CARGO_MANIFEST_DIR")).join("hopper.toml")).unwrap()
}

/// The walk of `setup` under `friction` for 100 s (at most 400 steps), as JSON: `serde_json`
/// writes every number in the shortest form that reads back to the same bits.
fn walk_json(setup: &Setup, friction: Friction) -> String {
    let mut setup = setup.clone();
    setup.friction = friction;
    let model = setup.model().unwrap();
    let limits = WalkLimits {
        max_steps: 400,
        duration: 100.0,
        record: false,
        periodic: None,
    };
    let w = walk(&model, &SimConfig::default(), &model.start_state(), &limits);
    assert!(w.steps.len() > 20, "{friction}: the hopper walks ({w:?})");
    serde_json::to_string(&w).unwrap()
}

#[test]
fn the_compiled_hopper_walks_bit_for_bit_as_the_tape() {
    let compiled = Setup::of(Walker::from_compiled(&MODELS[0]).unwrap());
    let file = model_file();
    let derived = walker_load::Derived::new(file.clone()).unwrap();
    let tape = Setup::of(Walker::new(
        Spec::new(file).unwrap(),
        Arc::new(derived) as Arc<dyn KernelSource>,
    ));
    for friction in [Friction::Tanh, Friction::Coulomb] {
        assert_eq!(
            walk_json(&compiled, friction),
            walk_json(&tape, friction),
            "{friction}"
        );
    }
}

#[test]
fn a_registered_model_serves_every_file_with_its_content() {
    // Without registration no compiled kernels serve the hopper (and no run-time source is
    // given): the library refuses it.
    assert!(walker_of(model_file(), None).is_err());
    walker::setup::register(MODELS);
    let walker = walker_of(model_file(), None).unwrap();
    assert_eq!(walker.spec().name(), "hopper");
}
