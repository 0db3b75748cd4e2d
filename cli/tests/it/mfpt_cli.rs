//! `walker mfpt` through the built binary: the mesh's report in JSON with its two mean
//! first-passage times consistent with its eigenvalue, the Monte Carlo check from the same
//! fixed point, and bad settings refused with exit code 2, the flag named and the range given.

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

/// A floor file with `text` in a directory of this test's own.
fn floor_file(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("walker-mfpt-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("the floor file is written");
    path
}

/// `T_set = 0.2` lifts off below `mu0 = 0.47` on the steady gait: on `mu0` uniform on
/// `[0.44, 0.8)` it falls every few dozen steps.
const UNIFORM: &str =
    "kind = \"random\"\nseed = 5\n[mu0]\ndistribution = \"uniform\"\nlo = 0.44\nhi = 0.8\n";

#[test]
fn mfpt_reports_both_passage_times_and_its_own_walks_in_json() {
    let f = floor_file("uniform.toml", UNIFORM).display().to_string();
    let o = walker(&[
        "mfpt",
        "--scene",
        "active-level",
        "--t-set",
        "0.2",
        "--floor",
        &f,
        "--mesh",
        "5",
        "--samples",
        "16",
        "--walks",
        "50",
        "--max-steps",
        "2000",
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    assert_eq!(v["section"], serde_json::json!(["xd", "th1d"]));
    assert_eq!(v["points"], 5);
    assert_eq!(v["states"], 25);
    assert_eq!(v["steps_simulated"], 25 * 16);
    let lambda = v["lambda2"].as_f64().expect("lambda2");
    assert!(lambda > 0.0 && lambda < 1.0, "{lambda}");
    // The eigenvalue's MFPT is 1/(1 - lambda2) - 1, computed without the cancellation; the
    // printed lambda2 has 16 digits, so they agree to about 1e-16 / (1 - lambda2)^2 relative.
    let eigen = v["mfpt"]["eigen"].as_f64().expect("finite");
    assert!(
        (eigen - (1.0 / (1.0 - lambda) - 1.0)).abs() < 1e-9 * eigen,
        "{eigen} {lambda}"
    );
    assert!(
        v["mfpt"]["from_fixed_point"]
            .as_f64()
            .is_some_and(|t| t > 0.0)
    );
    let mc = &v["monte_carlo"];
    assert_eq!(mc["walks"], 50);
    assert!(mc["mfpt"]["exponential"]["estimate"].as_f64().is_some());
}

#[test]
fn mfpt_checks_its_settings_by_flag() {
    let f = floor_file("uniform.toml", UNIFORM).display().to_string();
    let steps = floor_file("steps.toml", "kind = \"steps\"\nmu0 = [0.5, 0.6]\n")
        .display()
        .to_string();
    for (args, expected) in [
        (vec!["--mesh", "1"], "invalid mesh: "),
        (vec!["--mesh", "1"], "must be a whole number in [2, 129]"),
        (
            vec!["--mesh", "65"],
            "invalid mesh: mesh field `points`: 4225 states",
        ),
        (vec!["--samples", "0"], "invalid samples: "),
        (
            vec!["--mesh", "45", "--samples", "256"],
            "invalid samples: mesh field `samples`",
        ),
        (
            vec!["--box-scale", "0"],
            "invalid box-scale: mesh field `box_scale` = 0: must be in (0, 100]",
        ),
        (
            vec!["--box-scale", "2", "--half-widths", "0.1,0.1"],
            "invalid half-widths: cannot be given with --box-scale",
        ),
        (
            vec!["--half-widths", "0.1"],
            "invalid half-widths: mesh field `half_widths` = 1 values: must be one per coordinate of the section, 2: xd, th1d",
        ),
        (
            vec!["--half-widths", "0.1,-1"],
            "invalid half-widths: mesh field `half_widths` = -1: must be > 0",
        ),
        (
            vec!["--walks", "0"],
            "invalid walks: 0: must be a whole number in [1, 100000]",
        ),
        (
            vec!["--set", "mu0=0.3"],
            "invalid set: cannot be given with --floor",
        ),
    ] {
        let o = walker(
            &[
                &[
                    "mfpt",
                    "--scene",
                    "active-level",
                    "--t-set",
                    "0.2",
                    "--floor",
                    &f,
                ],
                &args[..],
            ]
            .concat(),
        );
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(expected), "{args:?}: {}", stderr(&o));
    }
    let o = walker(&["mfpt", "--scene", "active-level", "--floor", &steps]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("invalid floor: a `steps` floor has no per-step distribution"),
        "{}",
        stderr(&o)
    );
}
