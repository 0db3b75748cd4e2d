//! The output-following control must be applicable: `A = H M^-1 Y S` (Eq. 30) regular at the
//! model's start posture and not singular identically; otherwise the derivation stops with an
//! error that names the model file, line and column.

use walker_scene::model::Model;
use walker_symbolic::model::ModelDerivation;

fn three_link() -> String {
    let path = format!("{}/../models/three-link.toml", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(path).expect("shipped model")
}

fn derive_error(text: &str) -> String {
    let model = Model::from_toml(text, "mutated.toml").expect("the loader accepts it");
    ModelDerivation::new(&model)
        .expect_err("the derivation refuses it")
        .to_string()
}

#[test]
fn the_shipped_three_link_biped_can_start() {
    let model = Model::from_toml(&three_link(), "three-link.toml").expect("loads");
    assert_eq!(model.start.len(), 6, "th_st, th_sw, th_t and their rates");
    ModelDerivation::new(&model).expect("A is regular at the start");
}

#[test]
fn two_outputs_the_inputs_cannot_move_apart_are_refused() {
    let text = three_link().replacen("h = \"th_st + th_sw\"", "h = \"th_t\"", 1);
    // The error points at the first of the two outputs that are now the same, `y_torso`'s
    // `h = "th_t"`: its line, column 6 (after `h = `).
    let line = 1 + text
        .lines()
        .position(|l| l.starts_with("h = \"th_t\""))
        .expect("the changed output");
    let err = derive_error(&text);
    assert!(
        err.contains(&format!("mutated.toml:{line}:6"))
            && err.contains("singular at every posture"),
        "{err}"
    );
}

#[test]
fn an_output_whose_gradient_vanishes_at_the_start_is_refused_there() {
    // y = cos(th_t) has dy/dth_t = -sin(th_t) = 0 at the start's th_t = 0, so A's first row
    // vanishes there; elsewhere it is regular.
    let text = three_link()
        .replacen("h = \"th_t\"", "h = \"cos(th_t)\"", 1)
        .replacen("th_t = \"th_T\"\n", "", 1);
    let err = derive_error(&text);
    assert!(
        err.contains("mutated.toml:") && err.contains("singular at the start posture"),
        "{err}"
    );
}
