//! `walker-gen emit|stats --model`: kernels generated from a model file. The paper's active
//! walker written as a model file gives kernels with exactly the operation counts of the
//! hand-derived scene (one source of truth, no cost); generation is deterministic; bad choices
//! exit 2 naming the parameter or flag.

use std::collections::BTreeMap;
use std::path::Path;
use std::process::{Command, Output};

fn walker_gen(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_walker-gen"))
        .args(args)
        .output()
        .expect("run walker-gen")
}

fn file(dir: &str, name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join(dir)
        .join(name)
        .display()
        .to_string()
}

/// The `total` column of `walker-gen stats` by kernel.
fn totals(args: &[&str]) -> BTreeMap<String, u64> {
    let out = walker_gen(args);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    text.lines()
        .take_while(|l| !l.starts_with("prepare"))
        .filter_map(|l| {
            let cols: Vec<&str> = l.split_whitespace().collect();
            let total = cols.get(8)?.parse().ok()?;
            Some(((*cols.first()?).to_owned(), total))
        })
        .collect()
}

#[test]
fn the_active_model_file_costs_what_the_hand_derived_kernels_cost() {
    let model = totals(&["stats", "--model", &file("models", "paper-active.toml")]);
    let scene = totals(&[
        "stats",
        "--scene",
        &file("walker/scenes", "general-level.toml"),
    ]);
    // The model's kernel names are model-independent; the scene's carry the floor.
    for (m, s) in [
        ("mass_matrix", "mass_matrix"),
        ("bias", "bias"),
        ("lambda", "lambda_level"),
        ("accel", "accel_level"),
        ("control", "control_level"),
        ("closed_loop", "closed_loop_level"),
        ("impact", "impact2_level"),
        ("impact_double", "impact3_level"),
        ("energy", "energy"),
    ] {
        assert_eq!(model.get(m), scene.get(s), "{m} against {s}");
        assert!(model.contains_key(m), "{m} is generated");
    }
}

#[test]
fn model_generation_is_deterministic_and_stamped() {
    let args = [
        "emit",
        "--model",
        &file("models", "rimless-wheel.toml"),
        "--fix",
        "alpha=0.5",
    ];
    let (a, b) = (walker_gen(&args), walker_gen(&args));
    assert_eq!(
        a.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&a.stderr)
    );
    assert_eq!(a.stdout, b.stdout);
    let text = String::from_utf8_lossy(&a.stdout);
    assert!(text.contains("@generated"), "stamped as generated");
    assert!(
        text.contains("pub fn impact_double"),
        "the double-support impact is generated"
    );
    // alpha is fixed, so it is no field of Params.
    assert!(!text.contains("pub alpha: f64"), "alpha is substituted");
}

/// Exit 2 and a message that names `what`, without a panic.
fn fails_naming(args: &[&str], what: &str) {
    let out = walker_gen(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(
        stderr.contains(what),
        "{args:?}: does not name `{what}`: {stderr}"
    );
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
}

#[test]
fn bad_model_choices_exit_2_naming_what_is_wrong() {
    let rw = file("models", "rimless-wheel.toml");
    fails_naming(&["stats", "--model", &rw, "--fix", "m3=1"], "m3");
    fails_naming(&["stats", "--model", &rw, "--fix", "alpha=4"], "alpha");
    fails_naming(&["stats", "--model", &rw, "--fix", "alpha"], "name=value");
    fails_naming(&["stats", "--model", &rw, "--fix", "alpha=nan"], "alpha");
    fails_naming(
        &[
            "stats",
            "--model",
            &rw,
            "--scene",
            &file("walker/scenes", "general-level.toml"),
        ],
        "--scene",
    );
    fails_naming(
        &["stats", "--model", "no/such/model.toml"],
        "no/such/model.toml",
    );
}
