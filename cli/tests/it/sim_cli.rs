//! Tests of the `walker` command line (through the built binary).

use std::process::{Command, Output};

fn walker(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_walker"))
        .args(args)
        .output()
        .expect("the walker binary runs")
}

#[test]
fn simulate_json_is_one_object_with_steps() {
    let o = walker(&[
        "simulate",
        "--scene",
        "active-level",
        "--mu0",
        "0.4",
        "--t-set",
        "0.3",
        "--max-steps",
        "3",
        "--json",
    ]);
    assert!(o.status.success());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("stdout is JSON");
    assert_eq!(v["status"], "ok");
    assert!(v["failure"].is_null());
    let steps = v["steps"].as_array().expect("steps");
    assert_eq!(steps.len(), 3);
    for s in steps {
        for k in ["T", "dx", "V", "p", "SR"] {
            assert!(s[k].as_f64().is_some_and(f64::is_finite), "{k}");
        }
        assert_eq!(s["q_plus"].as_array().map(Vec::len), Some(4));
        assert_eq!(s["qd_plus"].as_array().map(Vec::len), Some(4));
    }
}

#[test]
fn simulate_reports_lift_off_and_passive_has_no_power() {
    let o = walker(&[
        "simulate",
        "--scene",
        "active-level",
        "--mu0",
        "0.05",
        "--t-set",
        "0.2",
        "--json",
    ]);
    assert!(o.status.success());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    assert_eq!(v["status"], "lift-off");
    assert_eq!(v["failure"]["kind"], "LiftOff");

    let o = walker(&[
        "simulate",
        "--scene",
        "passive-slope",
        "--phi",
        "0.2",
        "--mu0",
        "0.2",
        "--max-steps",
        "2",
        "--json",
    ]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    assert_eq!(v["status"], "ok");
    assert!(v["steps"][0]["p"].is_null() && v["steps"][0]["SR"].is_null());
}

#[test]
fn scene_files_use_the_general_kernels_and_agree_with_the_fast_path() {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../walker/scenes/");
    let run = |scene: &str| {
        let o = walker(&[
            "simulate",
            "--scene",
            scene,
            "--mu0",
            "0.2",
            "--phi",
            "0.2",
            "--max-steps",
            "2",
            "--json",
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
        v["steps"][1]["T"].as_f64().unwrap_or(f64::NAN)
    };
    let a = run("passive-slope");
    let b = run(&format!("{root}general-slope.toml"));
    assert!((a - b).abs() < 1e-8, "{a} {b}");
}

#[test]
fn bad_input_exits_2_naming_the_field() {
    let cases: &[(&[&str], &str)] = &[
        (&["simulate", "--scene", "nowhere"], "scene"),
        (
            &["simulate", "--scene", "active-level", "--mu0", "-1"],
            "mu0",
        ),
        (
            &["simulate", "--scene", "active-level", "--mu0", "NaN"],
            "mu0",
        ),
        (&["simulate", "--scene", "active-level", "--c", "0"], "c"),
        (
            &["simulate", "--scene", "active-level", "--rtol", "0"],
            "rtol",
        ),
        (
            &["simulate", "--scene", "active-level", "--atol", "NaN"],
            "atol",
        ),
        (
            &[
                "sweep",
                "--scene",
                "active-level",
                "--mu0-from",
                "0",
                "--mu0-to",
                "0.1",
                "--mu0-step",
                "0.1",
                "--rtol",
                "2",
            ],
            "rtol",
        ),
        (
            &["simulate", "--scene", "active-level", "--t-set", "0"],
            "t-set",
        ),
        (
            &["simulate", "--scene", "passive-slope", "--phi", "1.6"],
            "phi",
        ),
        (
            &["simulate", "--scene", "active-level", "--duration", "inf"],
            "duration",
        ),
        (
            &[
                "sweep",
                "--scene",
                "active-level",
                "--mu0-from",
                "0",
                "--mu0-to",
                "0.1",
                "--mu0-step",
                "0",
            ],
            // `--mu0-step` is an alias of `--step`, which the message names.
            "invalid step:",
        ),
        (
            &[
                "sweep",
                "--scene",
                "active-level",
                "--mu0-from",
                "0",
                "--mu0-to",
                "0.1",
                "--mu0-step",
                "0.1",
                "--until-periodic",
                "0",
            ],
            "until-periodic",
        ),
    ];
    for (args, field) in cases {
        let o = walker(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(field), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}

#[test]
fn sweep_restart_runs_in_parallel_and_reports_json() {
    let o = walker(&[
        "sweep",
        "--scene",
        "active-level",
        "--mu0-from",
        "0.3",
        "--mu0-to",
        "0.4",
        "--mu0-step",
        "0.05",
        "--t-set",
        "0.3",
        "--restart",
        "--duration",
        "5",
        "--json",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let pts = v["chains"][0]["points"].as_array().expect("points");
    assert_eq!(pts.len(), 3);
    assert!(pts.iter().all(|p| p["failure"].is_null()));
}

/// Three `T_set` chains with continuation, as Fig. 8: one chain per thread, the chains in the
/// order given, and (stderr not being a terminal here) no progress bar in the output.
#[test]
fn sweep_chains_keep_their_order_and_a_pipe_gets_no_progress_bar() {
    let o = walker(&[
        "sweep",
        "--scene",
        "active-level",
        "--mu0-from",
        "0.3",
        "--mu0-to",
        "0.4",
        "--mu0-step",
        "0.1",
        "--t-set",
        "0.4",
        "--t-set",
        "0.2",
        "--t-set",
        "0.3",
        "--duration",
        "3",
        "--json",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(
        o.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let chains = v["chains"].as_array().expect("chains");
    let values: Vec<f64> = chains.iter().filter_map(|c| c["value"].as_f64()).collect();
    assert_eq!(values, [0.4, 0.2, 0.3]);
    for c in chains {
        let mu0: Vec<f64> = c["points"]
            .as_array()
            .expect("points")
            .iter()
            .filter_map(|p| p["mu0"].as_f64())
            .collect();
        assert_eq!(mu0.len(), 2);
        assert!((mu0[0] - 0.3).abs() < 1e-12 && (mu0[1] - 0.4).abs() < 1e-12);
    }
}

/// `--friction coulomb` on a built-in scene and `friction = "coulomb"` in a scene file give the
/// same walker; the JSON reports the stuck time; `fixed-point` finds its cycle with the map's
/// Jacobian by differences of simulated steps.
#[test]
fn coulomb_friction_from_the_flag_or_a_scene_file() {
    let run = |args: &[&str]| {
        let mut all = vec!["simulate", "--max-steps", "3", "--json"];
        all.extend_from_slice(args);
        let o = walker(&all);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
        assert_eq!(v["status"], "ok", "{v}");
        let s = &v["steps"][2];
        (s["T"].as_f64(), s["stuck_time"].as_f64())
    };
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../walker/scenes/general-level-coulomb.toml"
    );
    let (t_flag, stuck) = run(&[
        "--scene",
        "active-level",
        "--friction",
        "coulomb",
        "--mu0",
        "0.4",
    ]);
    let (t_file, _) = run(&["--scene", file, "--mu0", "0.4"]);
    let (t_tanh, stuck_tanh) = run(&["--scene", "active-level", "--mu0", "0.4"]);
    assert_eq!(t_flag, t_file);
    assert!(stuck.is_some_and(|s| s > 0.0) && stuck_tanh == Some(0.0));
    assert!(t_flag != t_tanh);
    let o = walker(&[
        "fixed-point",
        "--scene",
        "active-level",
        "--friction",
        "coulomb",
    ]);
    // Under exact Coulomb friction the map's Jacobian is exact too (the held foot through the
    // sliding kernels, `docs/poincare.md`), and the cycle is the tanh law's within a few
    // percent.
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("converged"), "{text}");
    let o = walker(&[
        "fixed-point",
        "--scene",
        "active-level",
        "--friction",
        "coulomb",
        "--json",
    ]);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    assert_eq!(v["jacobian_method"], "variational", "{v}");
    assert!(
        v["T"].as_f64().is_some_and(|t| (t - 0.54).abs() < 0.02),
        "{v}"
    );
}

/// `--until-periodic`: the walks stop once their gaits are periodic (at `mu0 = 0.4` and 1 after
/// well under half of the 100 s), and the JSON and the text say so.
#[test]
fn sweep_until_periodic_stops_converged_walks_and_says_so() {
    let args = [
        "sweep",
        "--scene",
        "active-level",
        "--mu0-from",
        "0.4",
        "--mu0-to",
        "1",
        "--mu0-step",
        "0.6",
        "--t-set",
        "0.3",
        "--until-periodic",
        "1e-9",
    ];
    let o = walker(&[&args[..], &["--json"]].concat());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let pts = v["chains"][0]["points"].as_array().expect("points");
    assert_eq!(pts.len(), 2);
    for p in pts {
        assert_eq!(p["periodic"], true, "{p}");
        assert!(p["steps"].as_u64().is_some_and(|n| n < 90), "{p}");
    }
    let text = walker(&args);
    let out = String::from_utf8_lossy(&text.stdout);
    assert_eq!(out.matches(" periodic").count(), 2, "{out}");
}
