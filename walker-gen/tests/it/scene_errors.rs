//! Malformed scenes are rejected with an error that names the field.

use walker_gen::{Scene, SceneError};

const BASE: &str = "name = \"t\"\nfloor = \"level\"\nfriction = \"tanh\"\ntorso = \"actuated\"\n";
const SLOPE: &str = "name = \"t\"\nfloor = \"slope\"\nfriction = \"tanh\"\ntorso = \"passive\"\n";

fn error(src: &str) -> SceneError {
    match Scene::from_toml_str(src, "test.toml") {
        Ok(scene) => SceneError::BadKernelList {
            reason: format!("UNEXPECTEDLY ACCEPTED: {scene:?}"),
        },
        Err(e) => e,
    }
}

/// Asserts that `src` is rejected for `field`, and that the message names the field's last
/// component.
fn rejects(src: &str, field: &str) {
    let e = error(src);
    let message = e.to_string();
    assert_eq!(
        e.field(),
        field,
        "wrong field for:\n{src}\nerror: {message}"
    );
    let leaf = field.rsplit('.').next().unwrap_or(field);
    assert!(
        message.contains(leaf),
        "message does not name `{leaf}`: {message}"
    );
    assert!(!message.contains("UNEXPECTEDLY"), "{message}");
}

fn fixed(base: &str, body: &str) -> String {
    format!("{base}[fixed]\n{body}\n")
}

#[test]
fn valid_scene_files_load() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../walker/scenes");
    for name in [
        "active-level",
        "passive-slope",
        "active-level-frictionless",
        "general-level",
        "general-slope",
        "general-level-coulomb",
        "general-slope-coulomb",
    ] {
        let scene = Scene::from_file(dir.join(format!("{name}.toml")));
        assert!(scene.is_ok(), "{name}: {scene:?}");
    }
}

#[test]
fn unknown_top_level_key() {
    rejects(&format!("{BASE}colour = \"red\"\n"), "colour");
}

#[test]
fn unknown_fixed_key() {
    rejects(&fixed(BASE, "mass = 2.0"), "fixed.mass");
}

#[test]
fn unknown_table() {
    rejects(&format!("{BASE}[fixd]\nm1 = 2.0\n"), "fixd");
}

#[test]
fn missing_required_key() {
    rejects(
        "name = \"t\"\nfloor = \"level\"\ntorso = \"passive\"\n",
        "friction",
    );
}

#[test]
fn wrong_type_number() {
    rejects(&fixed(BASE, "m1 = \"heavy\""), "fixed.m1");
}

#[test]
fn wrong_type_enum() {
    rejects(&BASE.replace("\"level\"", "\"flat\""), "floor");
}

#[test]
fn wrong_type_kernel_list() {
    rejects(&format!("{BASE}kernels = \"accel_level\"\n"), "kernels");
}

#[test]
fn out_of_range_values() {
    for (body, field) in [
        ("m1 = -1.0", "fixed.m1"),
        ("m2 = 0.0", "fixed.m2"),
        ("l = 0", "fixed.l"),
        ("I1 = nan", "fixed.I1"),
        ("I2 = -2.0", "fixed.I2"),
        ("g = inf", "fixed.g"),
        ("alpha = 3.2", "fixed.alpha"),
        ("alpha = 0.0", "fixed.alpha"),
        ("alpha_deg = 180.0", "fixed.alpha_deg"),
        ("mu0 = -0.1", "fixed.mu0"),
        ("c = 0.0", "fixed.c"),
        ("T_set = 0.0", "fixed.T_set"),
        ("K_P = -1.0", "fixed.K_P"),
        ("K_D = -1.0", "fixed.K_D"),
    ] {
        rejects(&fixed(BASE, body), field);
    }
    rejects(&fixed(SLOPE, "phi = 1.6"), "fixed.phi");
    rejects(&fixed(SLOPE, "phi = -0.1"), "fixed.phi");
}

#[test]
fn invalid_name() {
    rejects(&BASE.replace("\"t\"", "\"a b\""), "name");
    rejects(&BASE.replace("\"t\"", "\"\""), "name");
}

#[test]
fn level_floor_with_phi() {
    rejects(&fixed(BASE, "phi = 0.1"), "fixed.phi");
}

#[test]
fn no_friction_with_friction_parameters() {
    let none = BASE.replace("\"tanh\"", "\"none\"");
    rejects(&fixed(&none, "mu0 = 0.4"), "fixed.mu0");
    rejects(&fixed(&none, "c = 100.0"), "fixed.c");
}

#[test]
fn coulomb_friction_with_c() {
    let coulomb = BASE.replace("\"tanh\"", "\"coulomb\"");
    rejects(&fixed(&coulomb, "c = 100.0"), "fixed.c");
    assert!(Scene::from_toml_str(&fixed(&coulomb, "mu0 = 0.4"), "t").is_ok());
}

#[test]
fn the_old_sign_law_is_gone() {
    // Renamed to "coulomb" (stick-slip and a sliding-direction argument), with no alias.
    rejects(&BASE.replace("\"tanh\"", "\"sign\""), "friction");
}

#[test]
fn passive_torso_with_control_parameters() {
    let passive = BASE.replace("\"actuated\"", "\"passive\"");
    for (body, field) in [
        ("T_set = 0.3", "fixed.T_set"),
        ("K_P = 1.0", "fixed.K_P"),
        ("K_D = 1.0", "fixed.K_D"),
    ] {
        rejects(&fixed(&passive, body), field);
    }
}

#[test]
fn slope_with_actuated_torso() {
    rejects(&SLOPE.replace("\"passive\"", "\"actuated\""), "torso");
}

#[test]
fn alpha_and_alpha_deg() {
    rejects(
        &fixed(BASE, "alpha = 0.5\nalpha_deg = 30.0"),
        "fixed.alpha_deg",
    );
}

#[test]
fn unknown_kernel() {
    rejects(&format!("{BASE}kernels = [\"accel\"]\n"), "kernels");
}

#[test]
fn kernel_of_another_structure() {
    rejects(&format!("{BASE}kernels = [\"accel_slope\"]\n"), "kernels");
    let passive = BASE.replace("\"actuated\"", "\"passive\"");
    rejects(
        &format!("{passive}kernels = [\"control_level\"]\n"),
        "kernels",
    );
    rejects(
        &format!("{SLOPE}kernels = [\"impact3_level\"]\n"),
        "kernels",
    );
    // The stick kernels exist only with Coulomb friction, each for its floor and torso.
    for kernel in ["stick_level", "closed_loop_stick_level"] {
        rejects(&format!("{BASE}kernels = [\"{kernel}\"]\n"), "kernels");
    }
    rejects(&format!("{SLOPE}kernels = [\"stick_slope\"]\n"), "kernels");
    let coulomb = BASE.replace("\"tanh\"", "\"coulomb\"");
    assert!(
        Scene::from_toml_str(
            &format!("{coulomb}kernels = [\"stick_level\", \"closed_loop_stick_level\"]\n"),
            "t"
        )
        .is_ok()
    );
    rejects(
        &format!("{coulomb}kernels = [\"stick_slope\"]\n"),
        "kernels",
    );
    let passive = coulomb.replace("\"actuated\"", "\"passive\"");
    assert!(Scene::from_toml_str(&format!("{passive}kernels = [\"stick_level\"]\n"), "t").is_ok());
    rejects(
        &format!("{passive}kernels = [\"closed_loop_stick_level\"]\n"),
        "kernels",
    );
    let slope = SLOPE.replace("\"tanh\"", "\"coulomb\"");
    assert!(Scene::from_toml_str(&format!("{slope}kernels = [\"stick_slope\"]\n"), "t").is_ok());
}

#[test]
fn empty_or_duplicate_kernel_list() {
    rejects(&format!("{BASE}kernels = []\n"), "kernels");
    rejects(
        &format!("{BASE}kernels = [\"bias\", \"bias\"]\n"),
        "kernels",
    );
}

#[test]
fn scene_says_what_it_needs() {
    let scene = Scene::from_toml_str(&fixed(BASE, "m1 = 2.0\nT_set = 0.3"), "t");
    let scene = scene.expect("valid");
    let runtime: Vec<&str> = scene.runtime_params().iter().map(|p| p.name()).collect();
    assert_eq!(
        runtime,
        [
            "m2", "l", "I1", "I2", "g", "alpha", "mu0", "c", "K_P", "K_D"
        ]
    );
    let kernels: Vec<&str> = scene.kernels().iter().map(|k| k.name()).collect();
    assert!(kernels.contains(&"control_level") && !kernels.contains(&"accel_slope"));
}
