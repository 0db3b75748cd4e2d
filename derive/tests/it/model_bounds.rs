//! A model's derivation is bounded in what it costs and names the place of what it refuses:
//! the angles' multiples are checked before any work, the work itself against the derivation
//! budget, and a singular matrix is reported at the declaration responsible (file, line and
//! column). Each model here is a shipped one with one edit, as found by the fuzz suite
//! (`load/tests/it/fuzz_models.rs`) or as issue 35 reported it.

use std::time::{Duration, Instant};

use walker_scene::model::Model;
use walker_symbolic::Error;
use walker_symbolic::budget::DERIVATION_BUDGET;
use walker_symbolic::model::{MAX_ANGLE_MULTIPLE, ModelDerivation};

fn shipped(name: &str) -> String {
    let path = format!("{}/../models/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(path).expect("shipped model")
}

/// `models/<name>.toml` with `from` replaced by `to` (which must occur), loaded as `edit.toml`.
fn edited(name: &str, from: &str, to: &str) -> Model {
    let text = shipped(name);
    assert!(text.contains(from), "{name} has `{from}`");
    let text = text.replacen(from, to, 1);
    Model::from_toml(&text, "edit.toml").expect("the loader accepts it")
}

fn refusal(model: &Model) -> String {
    ModelDerivation::new(model)
        .expect_err("the derivation refuses it")
        .to_string()
}

const COMPASS_GUARD: &str = "guard = \"2*phi - th_st - th_sw\"";

#[test]
fn a_huge_angle_multiple_is_refused_at_once_at_its_place() {
    // Issue 35: this guard ran for minutes (and at 1000 walked `non-finite` at t = 0).
    let model = edited(
        "compass-gait",
        COMPASS_GUARD,
        "guard = \"sin(1000000*th_st)\"",
    );
    let t = Instant::now();
    let err = refusal(&model);
    // Checked before any derivation: well under the time of the smallest derivation (20 ms).
    assert!(t.elapsed() < Duration::from_millis(20), "{:?}", t.elapsed());
    // The strike guard's line, and the `sin` at column 10 of the string's line.
    let line = shipped("compass-gait")
        .lines()
        .position(|l| l == COMPASS_GUARD)
        .expect("the guard's line")
        + 1;
    assert!(
        err.contains(&format!("edit.toml:{line}:10:"))
            && err.contains("`th_st` appears as 1000000 times its base angle")
            && err.contains(&format!("at most {MAX_ANGLE_MULTIPLE}")),
        "{err}"
    );
}

#[test]
fn an_angle_multiple_at_the_bound_derives() {
    let model = edited(
        "compass-gait",
        COMPASS_GUARD,
        &format!("guard = \"sin({MAX_ANGLE_MULTIPLE}*th_st)\""),
    );
    assert!(ModelDerivation::new(&model).is_ok());
}

#[test]
fn one_past_the_bound_is_refused() {
    let n = MAX_ANGLE_MULTIPLE + 1;
    let model = edited(
        "compass-gait",
        COMPASS_GUARD,
        &format!("guard = \"cos({n}*th_st - th_sw)\""),
    );
    let err = refusal(&model);
    assert!(err.contains(&format!("appears as {n} times")), "{err}");
}

#[test]
fn a_base_angle_divisor_past_the_bound_is_refused_at_its_place() {
    // th_st/7 and th_st/11: the base angle th_st/77, each multiple small.
    let model = edited(
        "compass-gait",
        COMPASS_GUARD,
        "guard = \"sin(th_st/7) + sin(th_st/11)\"",
    );
    let err = refusal(&model);
    assert!(
        err.contains("edit.toml:") && err.contains("the base angle of `th_st` is `th_st/77`"),
        "{err}"
    );
}

#[test]
fn the_shipped_models_derive_well_inside_the_budget() {
    for name in [
        "compass-gait",
        "rimless-wheel",
        "three-link",
        "five-link",
        "paper-active",
        "paper-passive",
    ] {
        let model = Model::from_toml(&shipped(name), name).expect("a shipped model");
        let m = ModelDerivation::measured(&model, DERIVATION_BUDGET);
        assert!(m.result.is_ok(), "{name}: {:?}", m.result.err());
        // The largest, the paper's passive walker, takes about 0.2 million term products:
        // a tenth of the budget leaves ten times the room for a user's larger model.
        assert!(m.work < DERIVATION_BUDGET / 10, "{name}: {}", m.work);
    }
}

#[test]
fn a_derivation_past_its_budget_ends_with_the_budget_error_naming_model_and_stage() {
    // Squared and multiplied trigonometric factors in a centre of mass: the inverse of M grows
    // without end (over 5 minutes unbounded); a small budget ends it at once.
    let model = edited(
        "compass-gait",
        "com = [\"x + a*sin(th_st)\", \"z + a*cos(th_st)\"]",
        "com = [\"x + a*sin(3*th_st)*cos(2*th_sw)^3\", \"z + a*cos(5*th_st - 3*th_sw)\"]",
    );
    let t = Instant::now();
    let m = ModelDerivation::measured(&model, 20_000);
    assert!(t.elapsed() < Duration::from_secs(5), "{:?}", t.elapsed());
    assert_eq!(
        m.result.err(),
        Some(Error::Budget {
            model: "compass-gait".into(),
            stage: "the inverse of the mass matrix M".into(),
            budget: 20_000,
        })
    );
}

#[test]
fn a_singular_mass_matrix_names_the_coordinates_that_move_nothing_together() {
    // x and z enter every position only as x + z: x - z moves nothing.
    let text = shipped("compass-gait")
        .replace("\"x + ", "\"x + z + ")
        .replace("\"z + ", "\"x + z + ");
    let model = Model::from_toml(&text, "edit.toml").expect("the loader accepts it");
    let err = refusal(&model);
    assert!(
        err.contains("edit.toml:")
            && err.contains("M is singular")
            && err.contains("a combination of `x`, `z`"),
        "{err}"
    );
}

#[test]
fn dependent_impact_locks_are_refused_at_the_first_lock() {
    let model = edited(
        "paper-active",
        "locks = [\"th1 - th2\"]",
        "locks = [\"th1 - th2\", \"2*th1 - 2*th2\"]",
    );
    let err = refusal(&model);
    let line = shipped("paper-active")
        .lines()
        .position(|l| l.starts_with("locks = "))
        .expect("the locks' line")
        + 1;
    assert!(
        err.contains(&format!("edit.toml:{line}:"))
            && err.contains("the impact's constraints")
            && err.contains("not independent"),
        "{err}"
    );
}

#[test]
fn an_output_that_the_inputs_cannot_move_is_refused_at_the_output() {
    // The paper's hip output replaced by the stance foot's position, which no input moves.
    let text = shipped("paper-active");
    let line = text
        .lines()
        .position(|l| l == "h = \"th1 - th2\"")
        .expect("the output's line")
        + 1;
    let model = edited("paper-active", "h = \"th1 - th2\"", "h = \"x\"");
    let err = refusal(&model);
    assert!(
        err.contains(&format!("edit.toml:{line}:")) && err.contains("singular at every posture"),
        "{err}"
    );
}
