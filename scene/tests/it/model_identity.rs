//! The canonical text of a model (`Model::canonical`): the same for files that derive the same
//! kernels however they are laid out, different where a derivation would differ.

#![allow(clippy::panic, reason = "tests")]

use walker_scene::model::Model;

const COMPASS: &str = include_str!("../../../models/compass-gait.toml");

fn canonical(text: &str) -> String {
    Model::from_toml(text, "m.toml")
        .unwrap_or_else(|e| panic!("{e}"))
        .canonical()
}

#[test]
fn layout_comments_and_docs_leave_the_canonical_text_alone() {
    let spaced = COMPASS
        .replace('*', " * ")
        .replace("\n[", "\n# a comment\n[");
    assert_ne!(spaced, COMPASS);
    assert_eq!(canonical(&spaced), canonical(COMPASS));
    let (head, tail) = COMPASS.split_once("doc = \"").expect("a doc string");
    let redoc = format!("{head}doc = \"another text, {tail}");
    assert_eq!(canonical(&redoc), canonical(COMPASS));
}

#[test]
fn a_number_is_its_value_not_its_spelling() {
    let (head, tail) = COMPASS.split_once("mass = \"m\"").expect("the leg's mass");
    let one = format!("{head}mass = \"1*m\"{tail}");
    let one_point_oh = format!("{head}mass = \"1.000*m\"{tail}");
    assert_eq!(canonical(&one), canonical(&one_point_oh));
    assert_ne!(
        canonical(&one),
        canonical(COMPASS),
        "1*m is another tree than m"
    );
}

#[test]
fn a_changed_expression_or_default_changes_the_canonical_text() {
    let (head, tail) = COMPASS.split_once("mass = \"m\"").expect("the leg's mass");
    let heavier = format!("{head}mass = \"2*m\"{tail}");
    assert_ne!(canonical(&heavier), canonical(COMPASS));
    let (head, tail) = COMPASS.split_once("default = ").expect("a default");
    let moved = format!(
        "{head}default = 0.5{}",
        &tail[tail.find('\n').expect("a line")..]
    );
    assert_ne!(moved, COMPASS, "the first default is not 0.5");
    assert_ne!(canonical(&moved), canonical(COMPASS));
    assert_eq!(
        Model::from_toml(COMPASS, "m.toml")
            .map(|m| m.identity())
            .ok(),
        Model::from_toml(COMPASS, "other/path.toml")
            .map(|m| m.identity())
            .ok(),
        "the path is no part of the identity"
    );
}
