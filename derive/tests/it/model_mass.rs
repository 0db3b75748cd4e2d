//! A model whose mass matrix is singular is refused at derivation, naming the coordinate that
//! moves no body (file, line and column of its declaration), for the closed-form path (up to
//! four coordinates) and the structured one alike.

use walker_scene::model::Model;
use walker_symbolic::model::ModelDerivation;

fn with_idle_coordinates(model: &str, idle: usize) -> String {
    let path = format!("{}/../models/{model}.toml", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(path).expect("shipped model");
    let extra: String = (0..idle)
        .map(|k| {
            format!("[[coordinate]]\nname = \"idle{k}\"\nunit = \"rad\"\ndoc = \"moves nothing\"\n")
        })
        .collect();
    // After the last coordinate: the first [[parameter]]; a section, if any, takes them free.
    let idle_names: String = (0..idle)
        .map(|k| format!("\"idle{k}\", \"idle{k}d\", "))
        .collect();
    text.replacen("[[parameter]]", &format!("{extra}[[parameter]]"), 1)
        .replacen("\nfree = [", &format!("\nfree = [{idle_names}"), 1)
}

fn refusal(model: &str, idle: usize) -> String {
    let text = with_idle_coordinates(model, idle);
    let model = Model::from_toml(&text, "idle.toml").expect("the loader accepts it");
    ModelDerivation::new(&model)
        .expect_err("refused")
        .to_string()
}

#[test]
fn a_coordinate_that_moves_nothing_is_named_with_closed_forms() {
    // The rimless wheel's three coordinates and one idle: M^-1 in closed form fails.
    let err = refusal("rimless-wheel", 1);
    assert!(
        err.contains("idle.toml:") && err.contains("coordinate `idle0` moves no body"),
        "{err}"
    );
}

#[test]
fn a_coordinate_that_moves_nothing_is_named_without_closed_forms() {
    // The compass gait's four and two idle: no closed-form M^-1, the structured path's check.
    let err = refusal("compass-gait", 2);
    assert!(err.contains("coordinate `idle0` moves no body"), "{err}");
}
