//! Bad input is refused, not run out of memory or aborted: every request either runs or is
//! refused with exit code 2 and a message naming the flag and its valid range; nothing is
//! allocated in proportion to a number the user typed without a bound (`--max-steps`, the
//! points of a sweep, its chains, the length of a scene file); an unwritable output is exit
//! code 1 naming the path.

use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use walker_cli::run::{MAX_STEPS, MAX_SWEEP_CHAINS, MAX_SWEEP_POINTS};

fn walker(args: &[String]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_walker"))
        .args(args)
        .stdin(Stdio::null())
        .output()
        .expect("the walker binary runs")
}

fn strings(args: &[&str]) -> Vec<String> {
    args.iter().map(|s| (*s).to_owned()).collect()
}

/// Runs `args` and checks the refusal: exit code 2, `flag` named in the message with what it
/// must be (`range_word`), no panic; returns how long it took.
fn assert_refused(args: &[String], flag: &str, range_word: &str) -> Duration {
    let start = Instant::now();
    let o = walker(args);
    let took = start.elapsed();
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(
        stderr.contains(&format!("invalid {flag}:")),
        "{args:?}: the message does not name {flag}: {stderr}"
    );
    assert!(
        stderr.contains(range_word),
        "{args:?}: no valid range ({range_word}) in: {stderr}"
    );
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    assert!(o.stdout.is_empty(), "{args:?}: output of a refused request");
    took
}

/// `walker sweep` over `mu0` from 0 to 1 with `extra`. The sweep's flags are given by their
/// names of the paper's sweeps (`--mu0-from`, `--mu0-to`, `--mu0-step`), aliases of `--from`,
/// `--to` and `--step`: a refusal names the flag by its own name (`invalid step:`).
fn sweep(extra: &[&str]) -> Vec<String> {
    let mut a = strings(&[
        "sweep",
        "--scene",
        "active-level",
        "--mu0-from",
        "0",
        "--mu0-to",
        "1",
    ]);
    a.extend(strings(extra));
    a
}

#[test]
fn simulate_max_steps_above_the_bound_is_refused_naming_the_range() {
    let bound = format!("[0, {MAX_STEPS}]");
    for n in [u64::MAX.to_string(), (MAX_STEPS + 1).to_string()] {
        let args = strings(&["simulate", "--scene", "active-level", "--max-steps", &n]);
        assert_refused(&args, "max-steps", &bound);
    }
}

#[test]
fn sweep_max_steps_above_the_bound_is_refused_even_with_a_short_duration() {
    let n = u64::MAX.to_string();
    let args = sweep(&["--mu0-step", "0.5", "--duration", "1", "--max-steps", &n]);
    assert_refused(&args, "max-steps", &format!("[0, {MAX_STEPS}]"));
}

#[test]
fn sweep_grid_beyond_the_bound_is_refused_within_a_second() {
    let args = sweep(&["--mu0-step", "1e-9"]);
    let took = assert_refused(&args, "step", &format!("at most {MAX_SWEEP_POINTS}"));
    assert!(took < Duration::from_secs(1), "took {took:?}");
}

#[test]
fn a_subnormal_step_over_a_huge_range_is_refused_within_a_second() {
    let args = strings(&[
        "sweep",
        "--scene",
        "active-level",
        "--mu0-from",
        "0",
        "--mu0-to",
        "1e308",
        "--mu0-step",
        "5e-324",
    ]);
    let took = assert_refused(&args, "step", &format!("at most {MAX_SWEEP_POINTS}"));
    assert!(took < Duration::from_secs(1), "took {took:?}");
}

/// Each chain alone is within the bound (10^4 + 1 points); the chains together are not.
#[test]
fn repeated_chains_count_towards_the_points_in_all_and_are_refused_within_a_second() {
    let mut extra = vec!["--mu0-step", "1e-4"];
    for _ in 0..20 {
        extra.extend(["--t-set", "0.3"]);
    }
    let took = assert_refused(
        &sweep(&extra),
        "step",
        &format!("at most {MAX_SWEEP_POINTS}"),
    );
    assert!(took < Duration::from_secs(1), "took {took:?}");
}

/// Without `--restart` every chain runs on its own thread: their number is bounded too.
#[test]
fn more_chains_than_the_bound_are_refused_naming_the_chain_flag() {
    let n = MAX_SWEEP_CHAINS + 1;
    let bound = format!("at most {MAX_SWEEP_CHAINS}");
    let mut active = vec!["--mu0-step", "0.5", "--max-steps", "1"];
    (0..n).for_each(|_| active.extend(["--t-set", "0.3"]));
    assert_refused(&sweep(&active), "t-set", &bound);

    let mut passive = strings(&[
        "sweep",
        "--scene",
        "passive-slope",
        "--mu0-from",
        "0",
        "--mu0-to",
        "1",
        "--mu0-step",
        "0.5",
        "--max-steps",
        "1",
    ]);
    (0..n).for_each(|_| passive.extend(strings(&["--phi", "0.1"])));
    assert_refused(&passive, "phi", &bound);
}

/// A scene "file" that is a device would be read without end.
#[cfg(unix)]
#[test]
fn a_scene_file_that_is_not_a_regular_file_is_refused() {
    let dir = std::env::temp_dir().join(format!("walker-input-bounds-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let link = dir.join("zero.toml");
    let _ = std::fs::remove_file(&link);
    std::os::unix::fs::symlink("/dev/zero", &link).expect("symlink");
    let scene = link.to_string_lossy().into_owned();
    let args = strings(&["simulate", "--scene", &scene]);
    let took = assert_refused(&args, "scene", "not a regular file");
    assert!(took < Duration::from_secs(1), "took {took:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The directory cannot be made (a file is in the way): exit code 1 naming the path, at once
/// (before the minute of computing).
#[test]
fn reproduce_into_an_unwritable_path_is_exit_1_naming_it() {
    let dir = std::env::temp_dir().join(format!("walker-unwritable-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let file = dir.join("a-file");
    std::fs::write(&file, "").expect("a file");
    let out = file.join("out");
    let out_arg = out.to_string_lossy().into_owned();
    let start = Instant::now();
    let o = walker(&strings(&["reproduce", "--out", &out_arg]));
    let took = start.elapsed();
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains(&out_arg), "the path is not named: {stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(took < Duration::from_secs(5), "took {took:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A reader that goes away (`walker ... | head -c 10`) is an I/O error (exit code 1), not a
/// panic. The output (about 120 kB) is larger than a pipe's buffer, so the write fails
/// whenever the reader closes.
#[test]
fn a_closed_standard_output_is_exit_1_not_a_panic() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_walker"))
        .args([
            "simulate",
            "--scene",
            "active-level",
            "--max-steps",
            "300",
            "--json",
        ])
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start the walker binary");
    drop(child.stdout.take());
    let o = child.wait_with_output().expect("wait for walker");
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("standard output"), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
}
