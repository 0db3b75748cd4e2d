//! A slope per step through the built binary (`docs/floors.md`, "A slope per step"):
//! `--phi-steps` and a floor file's `phi` walk the passive wheel on each step's slope and
//! report it, `walker survive` counts a kink as a failure of its own, and a slope the walker
//! cannot take exits 2 naming the flag, the field and the range.

use std::path::PathBuf;
use std::process::{Command, Output};

fn walker(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_walker"))
        .args(args)
        .output()
        .expect("the walker binary runs")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn wheel() -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../models/rimless-wheel.toml")
        .display()
        .to_string()
}

/// A floor file with `text` in a directory of this test's own.
fn floor_file(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("walker-slope-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("the floor file is written");
    path.display().to_string()
}

/// The wheel under exact Coulomb friction with a strike that sticks.
fn held(cmd: &str) -> Vec<String> {
    [
        cmd,
        "--model",
        &wheel(),
        "--friction",
        "coulomb",
        "--impact",
        "coulomb",
        "--set",
        "mu0=0.8",
    ]
    .iter()
    .map(|s| (*s).to_owned())
    .collect()
}

fn run(base: &[String], more: &[&str]) -> Output {
    let args: Vec<&str> = base
        .iter()
        .map(String::as_str)
        .chain(more.iter().copied())
        .collect();
    walker(&args)
}

#[test]
fn phi_steps_walk_each_step_on_its_slope_and_the_json_reports_it() {
    let o = run(
        &held("simulate"),
        &["--phi-steps", "0.2,0.25,0.15", "--max-steps", "5", "--json"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let phi: Vec<f64> = v["steps"]
        .as_array()
        .expect("steps")
        .iter()
        .map(|s| s["floor"]["phi"].as_f64().expect("a slope"))
        .collect();
    assert_eq!(phi, [0.2, 0.25, 0.15, 0.15, 0.15]);
    // The same floor from a file is the same walk.
    let f = floor_file("steps.toml", "kind = \"steps\"\nphi = [0.2, 0.25, 0.15]\n");
    let by_file = run(
        &held("simulate"),
        &["--floor", &f, "--max-steps", "5", "--json"],
    );
    assert_eq!(by_file.stdout, o.stdout, "{}", stderr(&by_file));
}

#[test]
fn survive_names_a_kink_among_the_failures() {
    // The paper's frictionless strike leaves the foot sliding: the first change of slope ends
    // every walk as a kink.
    let f = floor_file(
        "random.toml",
        "kind = \"random\"\nseed = 1\n[phi]\ndistribution = \"uniform\"\nlo = 0.15\nhi = 0.25\n",
    );
    let o = walker(&[
        "survive",
        "--model",
        &wheel(),
        "--friction",
        "coulomb",
        "--impact",
        "frictionless",
        "--floor",
        &f,
        "--walks",
        "3",
        "--max-steps",
        "10",
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    assert_eq!(v["survival"]["failures_by_kind"]["slope-kink"], 3, "{v}");
}

#[test]
fn a_slope_the_walker_cannot_take_exits_2_naming_flag_field_and_range() {
    let cases: Vec<(Vec<String>, Vec<&str>, &str)> = vec![
        (
            held("simulate"),
            vec!["--phi-steps", "0.2,-0.1"],
            "invalid phi-steps: floor field `phi[1]` = -0.1: outside the range [0, pi/2) of \
             `phi` in model `rimless-wheel`",
        ),
        (
            held("simulate"),
            vec!["--phi-steps", "0.2,x"],
            "invalid phi-steps: phi[1] = \"x\": not a number",
        ),
        (
            held("simulate"),
            vec!["--phi-steps", "0.2", "--phi", "0.2"],
            "invalid phi: cannot be given with --phi-steps: each sets phi",
        ),
        (
            held("simulate"),
            vec!["--phi-steps", "0.2", "--set", "phi=0.2"],
            "invalid set: cannot be given with --phi-steps: each sets phi",
        ),
        (
            vec![
                "simulate".to_owned(),
                "--scene".to_owned(),
                "active-level".to_owned(),
            ],
            vec!["--phi-steps", "0.1"],
            "invalid phi-steps: model `paper-active` has no slope angle",
        ),
    ];
    let f = floor_file(
        "slopes.toml",
        "kind = \"random\"\nseed = 1\n[phi]\ndistribution = \"uniform\"\nlo = 0.15\nhi = 0.25\n",
    );
    for (base, more, text) in cases {
        let more: Vec<&str> = more
            .iter()
            .map(|a| if *a == "FLOOR" { f.as_str() } else { a })
            .collect();
        let o = run(&base, &more);
        assert_eq!(o.status.code(), Some(2), "{more:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(text), "{more:?}: {}", stderr(&o));
    }
}
