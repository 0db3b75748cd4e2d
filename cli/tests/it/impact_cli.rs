//! `--impact frictionless|coulomb` on `simulate`, `sweep` and `fixed-point`, and
//! `impact = "..."` in scene files: the same walk either way, the regime in the JSON, the
//! paper's impact by default, and bad values refused naming the flag or field.
#![allow(clippy::panic, clippy::unwrap_used, reason = "tests")]

use std::path::PathBuf;
use std::process::{Command, Output};

use serde_json::Value;

fn walker(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_walker"))
        .args(args)
        .output()
        .expect("the walker binary runs")
}

fn json(args: &[&str]) -> Value {
    let o = walker(args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).expect("JSON")
}

/// A scene file in the test's temporary directory.
fn scene_file(name: &str, body: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("impact-cli");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, body).unwrap();
    path
}

const PASSIVE: &str = "name = \"p\"\nfloor = \"slope\"\nfriction = \"tanh\"\ntorso = \"passive\"\n";

#[test]
fn the_flag_and_the_scene_field_give_the_same_walk() {
    let file = scene_file("coulomb.toml", &format!("{PASSIVE}impact = \"coulomb\"\n"));
    let file = file.to_str().unwrap();
    let base = [
        "simulate",
        "--phi",
        "0.1",
        "--mu0",
        "0.7",
        "--duration",
        "3",
        "--json",
    ];
    let by_flag = json(
        &[
            &base[..],
            &["--scene", "passive-slope", "--impact", "coulomb"],
        ]
        .concat(),
    );
    let by_file = json(&[&base[..], &["--scene", file]].concat());
    let paper = json(&[&base[..], &["--scene", "passive-slope"]].concat());
    let last = |v: &Value| {
        v["steps"]
            .as_array()
            .and_then(|s| s.last())
            .cloned()
            .unwrap()
    };
    // The built-in scene has Table 1 compiled in, the file takes it at run time: the same
    // kernels to rounding, so the same gait to the integration tolerance (1e-10).
    let (a, b) = (last(&by_flag), last(&by_file));
    let rel = |x: &Value, y: &Value| {
        let (x, y) = (x.as_f64().unwrap(), y.as_f64().unwrap());
        (x - y).abs() / y.abs()
    };
    assert!(rel(&a["T"], &b["T"]) < 1e-8, "{a} vs {b}");
    assert_eq!(a["impact"]["regime"], "stick", "{a}");
    assert_eq!(b["impact"]["regime"], "stick", "{b}");
    // The paper's impact is the default and leaves no regime in the JSON.
    let p = last(&paper);
    assert!(p.get("impact").is_none(), "{p}");
    assert!(
        p["qd_plus"][0].as_f64().unwrap() > 1.0,
        "the new foot slides: {p}"
    );
    assert_eq!(
        a["qd_plus"][0].as_f64(),
        Some(0.0),
        "the new foot is stopped: {a}"
    );
}

#[test]
fn sweep_and_fixed_point_take_the_flag() {
    let fp = json(&[
        "fixed-point",
        "--scene",
        "passive-slope",
        "--phi",
        "0.1",
        "--mu0",
        "0.7",
        "--impact",
        "coulomb",
        "--json",
    ]);
    assert_eq!(fp["status"], "converged", "{fp}");
    assert_eq!(fp["impact"]["regime"], "stick", "{fp}");
    let sw = json(&[
        "sweep",
        "--scene",
        "active-level",
        "--t-set",
        "0.3",
        "--mu0-from",
        "0.1",
        "--mu0-to",
        "0.3",
        "--mu0-step",
        "0.2",
        "--duration",
        "10",
        "--impact",
        "coulomb",
        "--json",
    ]);
    let pts = sw["chains"][0]["points"].as_array().unwrap();
    let regimes: Vec<&Value> = pts.iter().map(|p| &p["last"]["impact"]["regime"]).collect();
    assert_eq!(
        regimes,
        [&Value::from("reverse"), &Value::from("stick")],
        "{sw}"
    );
}

#[test]
fn bad_impact_values_are_refused_naming_the_flag_or_field() {
    let o = walker(&["simulate", "--scene", "active-level", "--impact", "sticky"]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("--impact") && err.contains("coulomb"), "{err}");
    let file = scene_file("sticky.toml", &format!("{PASSIVE}impact = \"sticky\"\n"));
    let o = walker(&["simulate", "--scene", file.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("impact"), "{err}");
    let none = "name = \"n\"\nfloor = \"level\"\nfriction = \"none\"\ntorso = \"actuated\"\n";
    let file = scene_file("none.toml", &format!("{none}impact = \"coulomb\"\n"));
    let o = walker(&["simulate", "--scene", file.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("impact") && err.contains("mu0"), "{err}");
}
