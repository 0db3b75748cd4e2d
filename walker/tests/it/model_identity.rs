//! A compiled variant is found by the model's canonical content, not by its file's bytes
//! (`walker_scene::model::Model::canonical`): a reformatted, commented or renamed copy of a
//! shipped model runs the compiled kernels, and a copy whose physics differs does not.

#![allow(clippy::panic, reason = "tests")]

use walker::compiled::MODELS;
use walker::setup::{SetupError, walker_of};
use walker_scene::model::Model;

/// `text` laid out anew as a user might: a comment on top and after every table header, the
/// products spaced, the model renamed and its doc rewritten. None of it is seen by a
/// derivation.
fn relaid(text: &str) -> String {
    let mut out = String::from("# my own copy, reformatted\n\n");
    let mut renamed = false;
    for line in text.lines() {
        // The model's own name is the first `name`; the later ones name bodies and points.
        if line.starts_with("name = ") && !renamed {
            renamed = true;
            out.push_str("name = \"my-copy\"   # renamed\n");
            continue;
        }
        out.push_str(&line.replace('*', " * "));
        if line.starts_with('[') {
            out.push_str("   # a table");
        }
        out.push('\n');
    }
    out
}

#[test]
fn a_reformatted_commented_renamed_copy_of_every_shipped_model_runs_compiled() {
    for c in MODELS {
        let copy = relaid(c.source);
        assert_ne!(
            copy, c.source,
            "{}: the copy must differ in its bytes",
            c.name
        );
        let model = Model::from_toml(&copy, "copy.toml").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(model.canonical(), c.canonical, "{}", c.name);
        // No run-time source: only the compiled kernels can serve it.
        let walker = walker_of(model, None).unwrap_or_else(|e| panic!("{}: {e}", c.name));
        assert_eq!(walker.spec().name(), "my-copy");
    }
}

#[test]
fn a_copy_with_other_physics_is_not_taken_for_the_compiled_model() {
    let c = MODELS
        .iter()
        .find(|c| c.name == "compass-gait")
        .expect("the compass gait is compiled in");
    // The first body's mass doubled: the same layout, another walker.
    let (head, tail) = c
        .source
        .split_once("mass = \"")
        .expect("a body with a mass");
    let changed = format!("{head}mass = \"2*{tail}");
    let model = Model::from_toml(&changed, "changed.toml").unwrap_or_else(|e| panic!("{e}"));
    assert_ne!(model.canonical(), c.canonical);
    assert!(matches!(
        walker_of(model, None),
        Err(SetupError::NotCompiled { .. })
    ));
}
