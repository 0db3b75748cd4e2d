//! `walker fixed-point`: the JSON fields, no NaN, and bad input exits 2 naming the field.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_walker"))
        .arg("fixed-point")
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn json_has_the_fixed_point_and_its_multipliers() {
    let (code, out, err) = run(&[
        "--scene",
        "active-level",
        "--mu0",
        "0.4",
        "--t-set",
        "0.3",
        "--json",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(!out.contains("NaN") && !out.contains("null,\"s"), "{out}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["status"], "converged");
    assert_eq!(v["state_plus"].as_array().unwrap().len(), 8);
    assert!(v["T"].as_f64().unwrap() > 0.3);
    assert!(v["V"].as_f64().unwrap() > 0.0);
    let m = v["multipliers"].as_array().unwrap();
    assert_eq!(m.len(), 2);
    assert!(m[0]["re"].as_f64().unwrap().abs() < 1.0);
}

#[test]
fn frictionless_reports_the_family() {
    let (code, out, err) = run(&["--scene", "active-level", "--mu0", "0", "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["status"], "family");
    assert_eq!(v["structural_unit_multiplier"], true);
}

#[test]
fn bad_input_exits_2_naming_the_field() {
    for (args, field) in [
        (&["--scene", "active-level", "--omega0", "-1"][..], "omega0"),
        (&["--scene", "active-level", "--mu0", "-0.1"][..], "mu0"),
        (&["--scene", "active-level", "--t-set", "0"][..], "t-set"),
        (&["--scene", "passive-slope", "--phi", "2"][..], "phi"),
        (&["--scene", "nowhere"][..], "scene"),
    ] {
        let (code, _, err) = run(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(field), "{args:?}: {err}");
    }
}
