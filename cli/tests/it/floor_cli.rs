//! `walker simulate --floor | --mu0-steps` and `walker survive` through the built binary:
//! a floor at the walker's own mu0 changes nothing but the records' `floor`, conflicting or
//! bad floors exit 2 naming the flag (and the file's line and column), a batch's report is
//! the same on one thread and on all cores, and a range of walks (`--first-walk`) has the
//! batch's walks of those indices.

use std::path::PathBuf;
use std::process::{Command, Output};

fn walker_env(args: &[&str], env: &[(&str, &str)]) -> Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_walker"));
    c.args(args);
    for (k, v) in env {
        c.env(k, v);
    }
    c.output().expect("the walker binary runs")
}

fn walker(args: &[&str]) -> Output {
    walker_env(args, &[])
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A floor file with `text` in a directory of this test's own.
fn floor_file(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("walker-floor-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("the floor file is written");
    path
}

const ACTIVE: [&str; 6] = [
    "simulate",
    "--scene",
    "active-level",
    "--t-set",
    "0.3",
    "--json",
];

#[test]
fn a_floor_at_the_walkers_mu0_prints_the_same_walk_with_each_steps_mu0() {
    let plain = walker(&[&ACTIVE[..], &["--mu0", "0.4", "--max-steps", "12"]].concat());
    let steps = walker(&[&ACTIVE[..], &["--mu0-steps", "0.4", "--max-steps", "12"]].concat());
    let file = floor_file("uniform.toml", "kind = \"uniform\"\nmu0 = 0.4\n");
    let file_arg = file.display().to_string();
    let uniform = walker(&[&ACTIVE[..], &["--floor", &file_arg, "--max-steps", "12"]].concat());
    let plain_json: serde_json::Value = serde_json::from_slice(&plain.stdout).expect("JSON");
    assert!(!String::from_utf8_lossy(&plain.stdout).contains("floor"));
    for o in [steps, uniform] {
        assert!(o.status.success(), "{}", stderr(&o));
        let mut v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
        for s in v["steps"].as_array_mut().expect("steps") {
            assert_eq!(s["floor"]["mu0"], 0.4);
            s.as_object_mut().expect("a step").remove("floor");
        }
        assert_eq!(v, plain_json);
    }
}

#[test]
fn the_text_table_gains_a_mu0_column_on_a_floor_only() {
    let text = |extra: &[&str]| {
        let o = walker(
            &[
                &["simulate", "--scene", "passive-slope", "--max-steps", "3"],
                extra,
            ]
            .concat(),
        );
        String::from_utf8_lossy(&o.stdout).into_owned()
    };
    assert!(!text(&[]).lines().next().unwrap_or_default().contains("mu0"));
    let floored = text(&["--mu0-steps", "0.2,0.25"]);
    assert!(
        floored.lines().next().unwrap_or_default().ends_with("mu0"),
        "{floored}"
    );
    assert!(
        floored
            .lines()
            .nth(2)
            .unwrap_or_default()
            .ends_with("0.250000"),
        "{floored}"
    );
}

#[test]
fn conflicting_and_bad_floors_exit_2_naming_the_flag_and_the_place() {
    let file = floor_file("bad.toml", "kind = \"steps\"\nmu0 = [0.4, -0.2]\n");
    let f = file.display().to_string();
    for (args, expected) in [
        (
            vec!["--floor", f.as_str(), "--mu0-steps", "0.4"],
            "invalid mu0-steps: cannot be given with --floor",
        ),
        (
            vec!["--mu0-steps", "0.4", "--mu0", "0.3"],
            "invalid mu0: cannot be given with --mu0-steps",
        ),
        (
            vec!["--mu0-steps", "0.4,,0.3"],
            "invalid mu0-steps: mu0[1] = \"\": not a number",
        ),
        (
            vec!["--mu0-steps", "0.4,0"],
            "invalid mu0-steps: mu0[1] = 0: must be > 0 and finite",
        ),
        (
            vec!["--floor", f.as_str()],
            ":2:13: field `mu0[1]`: -0.2: must be > 0 and finite",
        ),
        (
            vec!["--set", "mu0=0.3", "--mu0-steps", "0.4"],
            "invalid set: cannot be given with --mu0-steps: each sets mu0",
        ),
        (
            vec!["--friction", "none", "--mu0-steps", "0.4"],
            "invalid mu0-steps: the friction law is `none`",
        ),
    ] {
        let o = walker(&[&["simulate", "--scene", "active-level"], &args[..]].concat());
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(stderr(&o).contains(expected), "{args:?}: {}", stderr(&o));
    }
}

#[test]
fn survive_checks_its_counts_and_floor() {
    let file = floor_file(
        "ice.toml",
        "kind = \"random\"\nseed = 3\n[mu0]\ndistribution = \"uniform\"\nlo = 0.02\nhi = 0.1\n",
    );
    let f = file.display().to_string();
    for (args, expected) in [
        (
            vec!["--walks", "0"],
            "invalid walks: 0: must be a whole number in [1, 100000]",
        ),
        (
            vec!["--walks", "1e3"],
            "invalid walks: \"1e3\": must be a whole number",
        ),
        (
            vec!["--max-steps", "0"],
            "invalid max-steps: 0: must be a whole number in [1, 1000000]",
        ),
        (
            vec!["--set", "mu0=0.3"],
            "invalid set: cannot be given with --floor: each sets mu0",
        ),
        (
            vec!["--walks", "100000", "--max-steps", "1001"],
            "invalid walks: the request has 100100000 steps in all",
        ),
        (
            vec!["--first-walk", "-1"],
            "invalid first-walk: \"-1\": must be a whole number in [0, 9223372036854775807]",
        ),
        (
            vec!["--first-walk", "x"],
            "invalid first-walk: \"x\": must be a whole number",
        ),
        (
            // The last walk's index would be 2^63.
            vec!["--walks", "2", "--first-walk", "9223372036854775807"],
            "invalid first-walk: 9223372036854775807: must be a whole number in [0, 9223372036854775806]",
        ),
    ] {
        let o = walker(
            &[
                &["survive", "--scene", "passive-slope", "--floor", &f],
                &args[..],
            ]
            .concat(),
        );
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(stderr(&o).contains(expected), "{args:?}: {}", stderr(&o));
    }
}

#[test]
fn survive_reports_the_same_batch_on_one_thread_and_on_all_cores() {
    let file = floor_file(
        "markov.toml",
        "kind = \"random\"\nseed = 9\n[mu0]\ndistribution = \"markov\"\ndry = 0.3\nicy = 0.05\n\
         dry_length = 20\nicy_length = 1.5\n",
    );
    let f = file.display().to_string();
    let args = [
        "survive",
        "--scene",
        "passive-slope",
        "--floor",
        &f,
        "--walks",
        "16",
        "--max-steps",
        "30",
        "--json",
    ];
    let one = walker_env(&args, &[("RAYON_NUM_THREADS", "1")]);
    let all = walker(&args);
    assert!(one.status.success(), "{}", stderr(&one));
    assert_eq!(one.stdout, all.stdout);
    let v: serde_json::Value = serde_json::from_slice(&all.stdout).expect("JSON");
    let s = &v["survival"];
    assert_eq!(s["walks"], 16);
    let outcomes = v["outcomes"].as_array().expect("outcomes");
    assert_eq!(outcomes.len(), 16);
    let failed = outcomes.iter().filter(|o| !o["failure"].is_null()).count();
    assert_eq!(s["failures"].as_u64(), Some(failed as u64));
    assert_eq!(
        s["failures_by_kind"]["fell-backward"].as_u64(),
        Some(failed as u64)
    );
    // The text report states the counts and the interval.
    let text = walker(&args[..args.len() - 1]);
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(
        text.starts_with(&format!("16 walks of at most 30 steps: {failed} failed")),
        "{text}"
    );
    assert!(
        text.contains("95% interval") || text.contains("with 95% confidence"),
        "{text}"
    );
}

#[test]
fn survive_with_first_walk_runs_the_batchs_walks_of_those_indices() {
    let file = floor_file(
        "markov-range.toml",
        "kind = \"random\"\nseed = 9\n[mu0]\ndistribution = \"markov\"\ndry = 0.3\nicy = 0.05\n\
         dry_length = 20\nicy_length = 1.5\n",
    );
    let f = file.display().to_string();
    let run = |walks: &str, first: Option<&str>| -> serde_json::Value {
        let mut args = vec![
            "survive",
            "--scene",
            "passive-slope",
            "--floor",
            &f,
            "--walks",
            walks,
            "--max-steps",
            "30",
            "--json",
        ];
        if let Some(first) = first {
            args.extend(["--first-walk", first]);
        }
        let o = walker(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        serde_json::from_slice(&o.stdout).expect("JSON")
    };
    let whole = run("16", None);
    assert_eq!(run("16", Some("0")), whole);
    let part = run("5", Some("7"));
    let indices: Vec<u64> = part["outcomes"]
        .as_array()
        .expect("outcomes")
        .iter()
        .map(|o| o["walk"].as_u64().expect("an index"))
        .collect();
    assert_eq!(indices, (7..12).collect::<Vec<u64>>());
    let whole_outcomes = whole["outcomes"].as_array().expect("outcomes");
    assert_eq!(
        part["outcomes"].as_array(),
        Some(&whole_outcomes[7..12].to_vec())
    );
    assert_eq!(part["survival"]["walks"], 5);
}
