//! Every number and name a command takes is checked against the range its help states, by the
//! library's request checks (`walker::request`) translated to the flags: a value outside
//! (NaN, infinite, negative, zero, huge, not a whole number where a count is asked) is exit
//! code 2 with a message naming the flag and the range; a parameter (or a start component)
//! given twice, by one name or by two (`--t-set` and `--set T_set=..`, the swept parameter
//! also chained), is refused naming both places; a user's text is echoed short and escaped.

use std::process::{Command, Output, Stdio};

use walker::request::{ATOL_MIN, MAX_DURATION, MAX_STEPS, RTOL_MIN};

fn run(bin: &str, args: &[&str]) -> Output {
    Command::new(bin)
        .args(args)
        .stdin(Stdio::null())
        .output()
        .expect("the binary runs")
}

fn walker(args: &[&str]) -> Output {
    run(env!("CARGO_BIN_EXE_walker"), args)
}

/// `args` is refused: exit code 2, no output, no panic, and stderr names `flag` (as
/// `invalid FLAG:`) and contains every one of `words` (the range, the other place).
fn assert_refused(args: &[&str], flag: &str, words: &[&str]) {
    let o = walker(args);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(
        stderr.contains(&format!("invalid {flag}:")),
        "{args:?}: the message does not name {flag}: {stderr}"
    );
    for w in words {
        assert!(stderr.contains(w), "{args:?}: {w:?} not in: {stderr}");
    }
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    assert!(o.stdout.is_empty(), "{args:?}: output of a refused request");
}

fn simulate_with(extra: &[&str]) -> Vec<String> {
    let mut a: Vec<String> = ["simulate", "--scene", "active-level", "--max-steps", "1"]
        .map(str::to_owned)
        .to_vec();
    a.extend(extra.iter().map(|s| (*s).to_owned()));
    a
}

fn refused_simulate(extra: &[&str], flag: &str, words: &[&str]) {
    let a = simulate_with(extra);
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    assert_refused(&a, flag, words);
}

const SWEEP: [&str; 9] = [
    "sweep",
    "--scene",
    "active-level",
    "--from",
    "0.4",
    "--to",
    "0.4",
    "--step",
    "0.1",
];

/// A small sweep (one value, one step, one second) with `extra`, whose flags replace these
/// defaults.
fn refused_sweep(extra: &[&str], flag: &str, words: &[&str]) {
    let mut a = SWEEP.to_vec();
    for (f, v) in [("--max-steps", "1"), ("--duration", "1")] {
        if !extra.iter().any(|e| e.starts_with(f)) {
            a.extend_from_slice(&[f, v]);
        }
    }
    a.extend_from_slice(extra);
    assert_refused(&a, flag, words);
}

#[test]
fn a_relative_tolerance_below_ten_epsilons_or_outside_one_is_refused_with_its_range() {
    let low = format!("[{RTOL_MIN:e}, 1)");
    for v in ["1e-16", "2e-15", "0", "-1e-10", "1", "NaN", "inf"] {
        refused_simulate(&[&format!("--rtol={v}")], "rtol", &[&low]);
    }
    refused_sweep(&["--rtol=1e-300"], "rtol", &[&low]);
}

#[test]
fn a_subnormal_or_unit_absolute_tolerance_is_refused_with_its_range() {
    let range = format!("[{ATOL_MIN:e}, 1)");
    for v in ["5e-324", "1e-310", "0", "1", "-inf"] {
        refused_simulate(&[&format!("--atol={v}")], "atol", &[&range]);
    }
}

#[test]
fn max_steps_that_is_not_a_whole_number_in_range_is_refused_with_its_range() {
    let range = format!("[0, {MAX_STEPS}]");
    for v in [
        "1e30",
        "-1",
        "1.5",
        "1000001",
        "abc",
        "340282366920938463463374607431768211456",
    ] {
        let a = ["simulate", "--scene", "active-level", "--max-steps", v];
        assert_refused(&a, "max-steps", &[&range]);
        refused_sweep(&["--max-steps", v], "max-steps", &[&range]);
    }
}

#[test]
fn a_duration_not_in_its_range_is_refused_with_the_range() {
    let range = format!("(0, {MAX_DURATION:e}]");
    for v in ["1e300", "1e10", "0", "-1", "NaN", "inf"] {
        refused_simulate(&[&format!("--duration={v}")], "duration", &[&range]);
        refused_sweep(&[&format!("--duration={v}")], "duration", &[&range]);
    }
}

#[test]
fn the_periodic_stop_outside_the_unit_interval_is_refused() {
    for v in ["0", "1", "NaN", "-0.5"] {
        refused_sweep(
            &[&format!("--until-periodic={v}")],
            "until-periodic",
            &["(0, 1)"],
        );
    }
}

#[test]
fn a_sweep_range_names_from_to_or_step() {
    let base = ["sweep", "--scene", "active-level", "--max-steps", "1"];
    let cases: [(&[&str], &str, &str); 4] = [
        (&["--from=NaN", "--to=1", "--step=0.1"], "from", "finite"),
        (
            &["--from=1", "--to=0", "--step=0.1"],
            "to",
            ">= the first value",
        ),
        (&["--from=0", "--to=1", "--step=0"], "step", "> 0"),
        (
            &["--from=0", "--to=1", "--step=1e-12"],
            "step",
            "at most 100000",
        ),
    ];
    for (extra, flag, word) in cases {
        let mut a = base.to_vec();
        a.extend_from_slice(extra);
        assert_refused(&a, flag, &[word]);
    }
}

#[test]
fn a_parameter_set_twice_by_name_is_refused_naming_it() {
    refused_simulate(
        &["--set", "K_P=1", "--set", "K_P=2"],
        "set",
        &["K_P is given twice", "--set K_P="],
    );
}

#[test]
fn t_set_by_its_flag_and_by_its_name_is_refused_naming_both() {
    refused_simulate(
        &["--t-set", "0.3", "--set", "T_set=0.2"],
        "set",
        &["T_set is given twice", "--t-set"],
    );
    refused_simulate(
        &["--mu0", "0.3", "--set", "mu0=0.2"],
        "set",
        &["mu0 is given twice", "--mu0"],
    );
}

#[test]
fn the_swept_parameter_may_not_also_be_chained_or_set() {
    refused_sweep(
        &["--param", "T_set", "--t-set", "0.3", "--t-set", "0.5"],
        "param",
        &["T_set is given twice", "--t-set"],
    );
    refused_sweep(
        &["--param", "mu0", "--set", "mu0=0.3"],
        "param",
        &["mu0 is given twice", "--set mu0="],
    );
}

#[test]
fn omega0_by_its_flag_and_by_set_is_refused_naming_both() {
    refused_simulate(
        &["--omega0", "0.8", "--set", "omega0=0.7"],
        "omega0",
        &["omega0 is given twice", "--set omega0="],
    );
}

#[test]
fn a_start_component_given_twice_is_refused() {
    refused_simulate(
        &["--init", "th1d=0.7", "--init", "th1d=0.8"],
        "init",
        &["th1d is given twice"],
    );
}

#[test]
fn unknown_names_are_refused_naming_the_flag_and_listing_the_known() {
    refused_simulate(&["--set", "gravity=9.8"], "set", &["T_set"]);
    refused_simulate(&["--init", "th9=0"], "init", &["th1d"]);
    refused_sweep(&["--param", "gravity"], "param", &["mu0"]);
}

#[test]
fn animate_steps_that_are_not_a_whole_number_in_range_are_refused() {
    for v in ["1e30", "-1", "0", "1001", "2.5"] {
        let a = [
            "animate",
            "--scene",
            "active-level",
            "-o",
            "x.svg",
            "--steps",
            v,
        ];
        assert_refused(&a, "steps", &["[1, 1000]"]);
    }
}

#[test]
fn stress_long_steps_out_of_range_is_exit_2_with_the_range() {
    for v in ["1e30", "0", "-5", "1000001"] {
        let o = run(env!("CARGO_BIN_EXE_stress"), &["--long-steps", v]);
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{v}: {stderr}");
        assert!(stderr.contains("long-steps"), "{v}: {stderr}");
        assert!(stderr.contains("[1, 1000000]"), "{v}: {stderr}");
    }
}

/// A name of 100 000 characters (control characters in it) is echoed as its first 80,
/// escaped: the message stays short and prints nothing a terminal would obey.
#[test]
fn a_huge_or_hostile_name_is_echoed_short_and_escaped() {
    let name = format!("\u{1b}[2J{}", "x".repeat(100_000));
    for flag in ["--set", "--init"] {
        let arg = format!("{name}=1");
        let a = simulate_with(&[flag, &arg]);
        let a: Vec<&str> = a.iter().map(String::as_str).collect();
        let o = walker(&a);
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{flag}");
        // The message, the model's list of names and 80 characters of the name.
        assert!(stderr.len() < 1000, "{flag}: {} bytes", stderr.len());
        assert!(!stderr.contains('\u{1b}'), "{flag}: {stderr}");
    }
    for scene in [name.clone(), format!("{name}.toml")] {
        let o = walker(&["simulate", "--scene", &scene]);
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{stderr}");
        assert!(stderr.contains("invalid scene:"), "{stderr}");
        assert!(stderr.len() < 1000, "--scene: {} bytes", stderr.len());
        assert!(!stderr.contains('\u{1b}'), "--scene: {stderr}");
    }
    // 300 digits: about 1e300, shown as such, not digit by digit.
    let huge = "9".repeat(300);
    refused_simulate(
        &[&format!("--duration={huge}")],
        "duration",
        &["1e300: must be"],
    );
}

/// Values inside every range still walk (each parameter once, every bound itself).
#[test]
fn requests_inside_every_range_still_walk() {
    let rtol = format!("--rtol={RTOL_MIN:e}");
    let max = format!("--duration={MAX_DURATION:e}");
    for extra in [
        &["--set", "K_P=1", "--set", "K_D=2", "--t-set", "0.3"][..],
        &["--init", "th1d=0.7", "--omega0", "0.8"],
        &[rtol.as_str(), "--atol=1e-300"],
        &[max.as_str()],
    ] {
        let a = simulate_with(extra);
        let a: Vec<&str> = a.iter().map(String::as_str).collect();
        let o = walker(&a);
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(0), "{extra:?}: {stderr}");
    }
    let o = walker(&["simulate", "--scene", "active-level", "--max-steps", "0"]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}
