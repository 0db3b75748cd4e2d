//! `walker mfpt` on a floor that sets the slope, through the built binary (`docs/floors.md`,
//! "The mesh on a floor of slopes"): the chain carries the slope of the step before, its
//! report lists the slope samples, its floor states and the held coordinate, and its own
//! walks start where the chain does; a `steps` floor of slopes is refused by name.

use std::path::PathBuf;
use std::process::{Command, Output};

fn walker(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_walker"))
        .args(args)
        .output()
        .expect("the walker binary runs")
}

/// A floor file with `text` in a directory of this test's own.
fn floor_file(name: &str, text: &str) -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("mfpt-slopes");
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("the floor file is written");
    path.display().to_string()
}

/// `walker mfpt` of the passive wheel under exact Coulomb friction with strikes that stick
/// (`mu0 = 0.8`), on the floor file `floor`, with `more` flags.
fn wheel_mfpt(floor: &str, more: &[&str]) -> Output {
    let model = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../models/rimless-wheel.toml")
        .display()
        .to_string();
    let mut args = vec![
        "mfpt",
        "--model",
        &model,
        "--friction",
        "coulomb",
        "--impact",
        "coulomb",
        "--set",
        "mu0=0.8",
        "--floor",
        floor,
    ];
    args.extend_from_slice(more);
    walker(&args)
}

/// The wheel on slopes uniform on `[0, 0.04)`, where it stalls every 30 steps or so: 33
/// points, 8 slope samples, and 200 walks from the chain's start. The chain has a floor state
/// per slope sample, the foot's `xd` held (every strike sticks), and its time lies within the
/// walks' interval widened by the mesh's own error (at most 2 steps at this mesh:
/// docs/floors.md's table, 27.95 against 29.77 at 129 points and 28.62 by 2000 walks).
#[test]
fn mfpt_on_random_slopes_carries_the_slope_before_and_agrees_with_its_walks() {
    let f = floor_file(
        "slopes.toml",
        "kind = \"random\"\nseed = 5\n[phi]\ndistribution = \"uniform\"\nlo = 0.0\nhi = 0.04\n",
    );
    let o = wheel_mfpt(
        &f,
        &[
            "--mesh",
            "33",
            "--samples",
            "8",
            "--walks",
            "200",
            "--max-steps",
            "5000",
            "--json",
        ],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    assert_eq!(v["slopes"].as_array().map(Vec::len), Some(8), "{v}");
    assert_eq!(v["samples"], serde_json::json!([]));
    assert_eq!(v["held"], serde_json::json!(["xd"]));
    assert_eq!(v["floor_states"][7], "phi[7]");
    assert_eq!(v["states"], 33 * 8);
    assert_eq!(v["steps_simulated"], 33 * 8 * 8);
    let t = v["mfpt"]["from_fixed_point"].as_f64().expect("finite");
    let mc = &v["monte_carlo"];
    assert_eq!(mc["failures"], 200, "{mc}");
    let e = &mc["mfpt"]["exponential"];
    let (lo, hi) = (e["lo"].as_f64().expect("lo"), e["hi"].as_f64().expect("hi"));
    assert!(
        t + 2.0 >= lo && t - 2.0 <= hi,
        "mesh {t}, walks [{lo}, {hi}]"
    );
    let text = wheel_mfpt(&f, &["--mesh", "9", "--samples", "4"]);
    let out = String::from_utf8_lossy(&text.stdout);
    assert!(out.contains("4 of phi, 4 floor states"), "{out}");
}

#[test]
fn a_steps_floor_of_slopes_is_refused_by_name() {
    let f = floor_file("steps.toml", "kind = \"steps\"\nphi = [0.2, 0.21]\n");
    let o = wheel_mfpt(&f, &[]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("floor") && err.contains("no per-step distribution"),
        "{err}"
    );
}
