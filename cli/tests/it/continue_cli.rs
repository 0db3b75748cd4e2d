//! `walker continue`: the JSON lists points and labelled special points, the CSV and the
//! diagram are written, and bad input exits 2 naming the flag and its valid range.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_walker"))
        .arg("continue")
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
fn json_lists_the_points_and_the_lift_off_boundary_of_t_set_0_2() {
    let dir = std::env::temp_dir().join(format!("continue-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (csv, svg) = (dir.join("b.csv"), dir.join("b.svg"));
    let (code, out, err) = run(&[
        "--scene",
        "active-level",
        "--param",
        "mu0",
        "--from",
        "0.3",
        "--to",
        "0.7",
        "--set",
        "T_set=0.2",
        "--at",
        "0.5",
        "--json",
        "--csv",
        csv.to_str().unwrap(),
        "--plot",
        svg.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(!out.contains("NaN"), "{out}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["parameter"], "mu0");
    let b = &v["branches"][0];
    assert_eq!(b["period"], 1);
    let points = b["points"].as_array().unwrap();
    assert!(points.len() > 3);
    let tags: Vec<&str> = points
        .iter()
        .filter_map(|p| p["label"]["tag"].as_str())
        .collect();
    assert_eq!(tags.first(), Some(&"EP"));
    assert_eq!(tags.last(), Some(&"EP"));
    assert!(tags.contains(&"LO") && tags.contains(&"UZ"), "{tags:?}");
    let lo = points.iter().find(|p| p["label"]["tag"] == "LO").unwrap();
    // The boundary of `continuation_walkers.rs`: mu0 = 0.4729 (located to 1e-9).
    assert!((lo["parameter"].as_f64().unwrap() - 0.4729).abs() < 1e-3);
    for key in [
        "T",
        "V",
        "dx",
        "multipliers",
        "stability",
        "physical",
        "tests",
        "state",
    ] {
        assert!(!points[1][key].is_null(), "{key}");
    }
    assert_eq!(b["ends"][0]["reason"], "parameter-bound");
    let csv = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(csv.lines().count(), points.len() + 1);
    assert!(csv.starts_with("branch,period,index,parameter,V,T,dx"));
    let svg = std::fs::read_to_string(&svg).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("LO"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn mu0_zero_ends_the_branch_on_a_labelled_family() {
    let (code, out, err) = run(&[
        "--scene",
        "active-level",
        "--param",
        "mu0",
        "--from",
        "0",
        "--to",
        "0.1",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("FAM1 Family at mu0 = 0.0000000000"), "{out}");
    assert!(out.contains("a family of cycles (multiplier 1)"), "{out}");
}

#[test]
fn bad_input_exits_2_naming_the_flag_and_its_range() {
    for (args, flag, says) in [
        // The valid range of `mu0` as its model file writes it.
        (
            vec!["--param", "mu0", "--from", "-0.1", "--to", "1"],
            "from",
            "must be in [0, inf)",
        ),
        (
            vec!["--param", "mu0", "--from", "0.5", "--to", "0.5"],
            "to",
            "must differ",
        ),
        (
            vec!["--param", "omega0", "--from", "0.5", "--to", "1"],
            "param",
            "not a parameter of the Poincare map",
        ),
        (
            vec!["--param", "speed", "--from", "0.5", "--to", "1"],
            "param",
            "unknown parameter",
        ),
        // The active walker's model file has no slope parameter.
        (
            vec!["--param", "phi", "--from", "0", "--to", "0.1"],
            "param",
            "unknown parameter \"phi\" of model `paper-active`",
        ),
        // A value of `--set` out of its range is named by the parameter's flag, with the range.
        (
            vec![
                "--param", "mu0", "--from", "0.1", "--to", "0.2", "--set", "T_set=-1",
            ],
            "t-set",
            "-1: must be in (0, inf)",
        ),
        (
            vec![
                "--param", "mu0", "--from", "0.1", "--to", "0.2", "--set", "T_set",
            ],
            "set",
            "NAME=VALUE",
        ),
        (
            vec![
                "--param", "mu0", "--from", "0.1", "--to", "0.2", "--at", "0.5",
            ],
            "at",
            "in [0.1, 0.2]",
        ),
        (
            vec![
                "--param",
                "mu0",
                "--from",
                "0.1",
                "--to",
                "0.2",
                "--max-step",
                "0",
            ],
            "max-step",
            "in (0, 1]",
        ),
        (
            vec![
                "--param", "T_set", "--from", "0.25", "--to", "0.35", "--set", "mu0=0",
            ],
            "set",
            "family",
        ),
        // Non-finite and out-of-range values of every number flag.
        (
            vec!["--param", "mu0", "--from", "NaN", "--to", "1"],
            "from",
            "must be in [0, inf)",
        ),
        (
            vec!["--param", "mu0", "--from", "0.1", "--to", "inf"],
            "to",
            "must be in [0, inf)",
        ),
        (
            vec![
                "--param", "mu0", "--from", "0.1", "--to", "0.2", "--at", "NaN",
            ],
            "at",
            "in [0.1, 0.2]",
        ),
        (
            vec![
                "--param",
                "mu0",
                "--from",
                "0.1",
                "--to",
                "0.2",
                "--max-step",
                "1.5",
            ],
            "max-step",
            "in (0, 1]",
        ),
        (
            vec![
                "--param",
                "mu0",
                "--from",
                "0.1",
                "--to",
                "0.2",
                "--max-step",
                "-1e-7",
            ],
            "max-step",
            "in (0, 1]",
        ),
        (
            vec![
                "--param",
                "mu0",
                "--from",
                "0.1",
                "--to",
                "0.2",
                "--max-step",
                "NaN",
            ],
            "max-step",
            "in (0, 1]",
        ),
    ] {
        let mut all = vec!["--scene", "active-level"];
        all.extend(args.iter());
        let (code, out, err) = run(&all);
        assert_eq!(code, 2, "{args:?}: {out} {err}");
        assert!(err.contains(&format!("invalid {flag}:")), "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}

/// Issue 35: `--max-step` below the default smallest step (1e-6) panicked in `f64::clamp`
/// (min > max). It is in the documented range (0, 1], so the branch is followed with the
/// smallest step brought down to it; the run is bounded by the steps' count, and the first
/// steps' branch is the rimless wheel's, starting at `phi = 0.1`.
#[test]
fn a_max_step_below_the_default_smallest_step_is_followed_not_a_panic() {
    let (code, out, err) = run(&[
        "--model",
        "../models/rimless-wheel.toml",
        "--param",
        "phi",
        "--from",
        "0.1",
        "--to",
        "0.2",
        "--max-step",
        "1e-7",
        "--json",
    ]);
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(code, 0, "{out} {err}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    let points = j["branches"][0]["points"].as_array().unwrap();
    assert!(points.len() > 2, "{out}");
    let p0 = points[0]["parameter"].as_f64().unwrap();
    assert!((p0 - 0.1).abs() < 1e-12, "{p0}");
}

/// `--init` reaches the branch's start: the simplest walking model's own start finds its gait,
/// the same start with the stance leg's rate reversed (a walker falling backwards) finds none,
/// and the error lists that start among the tries; an unknown name or a foot lifted off the
/// slope is refused before any work, naming `init`.
#[test]
fn init_replaces_the_start_the_branch_is_sought_from() {
    let base = [
        "--model",
        "../models/simplest-walker.toml",
        "--param",
        "phi",
        "--from",
        "0.009",
        "--to",
        "0.01",
    ];
    let with = |extra: &[&str]| run(&[&base[..], extra].concat());
    let (code, out, err) = with(&["--init", "th_std=0.1998325"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("EP"), "{out}");
    let (code, _, err) = with(&["--init", "th_std=-0.2"]);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("no fixed point found") && err.contains("from the start guess"),
        "{err}"
    );
    for bad in ["bogus=1", "z=1", "th_std"] {
        let (code, _, err) = with(&["--init", bad]);
        assert_eq!(code, 2, "--init {bad}: {err}");
        assert!(err.contains("init"), "--init {bad}: {err}");
    }
}
