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

/// `--sensitivities mu0,T_set` adds each parameter's derivatives of the gait to the JSON, and
/// they are the derivatives: `dT/dmu0` agrees with a central difference of two whole
/// `fixed-point` runs at `mu0 = 0.4 +- 1e-3`. Tolerance: the difference's truncation error
/// `h^2 T''' / 6` is about 1e-7 here (T changes by 1e-2 over the range of mu0 the gait spans),
/// each run's period carries the search's tolerance, about 1e-10 s, divided by `2h = 2e-3`:
/// 1e-7; 1e-5 leaves two orders of magnitude. `dV` is `d(dx/T)`: the quotient rule holds to
/// the reported errors. A name that is no run-time parameter exits 2 naming the flag.
#[test]
fn sensitivities_are_the_derivatives_of_the_gait() {
    let at = |mu0: &str, extra: &[&str]| {
        let (code, out, err) = run(&[
            &[
                "--scene",
                "active-level",
                "--mu0",
                mu0,
                "--t-set",
                "0.3",
                "--json",
            ][..],
            extra,
        ]
        .concat());
        assert_eq!(code, 0, "{err}");
        serde_json::from_str::<serde_json::Value>(&out).unwrap()
    };
    let v = at("0.4", &["--sensitivities", "mu0,T_set"]);
    let s = &v["sensitivities"];
    for p in ["mu0", "T_set"] {
        for key in ["dT", "dV", "d_dx"] {
            let d = &s[p][key];
            assert!(d["value"].as_f64().unwrap().is_finite(), "{p} {key}: {d}");
            assert!(d["error"].as_f64().unwrap() >= 0.0, "{p} {key}: {d}");
        }
    }
    let h = 1e-3;
    let t = |mu0: f64| at(&format!("{mu0}"), &[])["T"].as_f64().unwrap();
    let central = (t(0.4 + h) - t(0.4 - h)) / (2.0 * h);
    let reported = s["mu0"]["dT"]["value"].as_f64().unwrap();
    assert!(
        (reported - central).abs() <= 1e-5 * central.abs().max(1.0),
        "dT/dmu0 {reported} against the difference {central}"
    );
    let (big_t, dx) = (v["T"].as_f64().unwrap(), v["dx"].as_f64().unwrap());
    for p in ["mu0", "T_set"] {
        let g = |k: &str| s[p][k]["value"].as_f64().unwrap();
        let e = |k: &str| s[p][k]["error"].as_f64().unwrap();
        let quotient = (g("d_dx") - dx / big_t * g("dT")) / big_t;
        let allowed = e("dV") + (e("d_dx") + dx / big_t * e("dT")) / big_t + 1e-9;
        assert!(
            (g("dV") - quotient).abs() <= allowed,
            "{p}: dV {} against the quotient rule {quotient}",
            g("dV")
        );
    }
    let (code, _, err) = run(&[
        "--scene",
        "active-level",
        "--sensitivities",
        "omega0",
        "--json",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("sensitivities"), "{err}");
}
