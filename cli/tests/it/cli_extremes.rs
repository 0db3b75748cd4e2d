//! Every numeric flag of every command at extreme values, systematically (not at random, as
//! `cli_fuzz.rs` does for `simulate`): `0`, `-0`, subnormal, tiny, huge, the largest `f64`,
//! negative, not finite, and each flag's own edges just inside and outside its range, for
//! `simulate`, `sweep` and `fixed-point` on both built-in scenes (the first two also under
//! Coulomb friction and under RODAS4). Every case ends, within a wall-time bound, with exit
//! code 0 and a JSON result (possibly a named failure) whose numbers are all finite, or with
//! exit code 2 and a message naming the flag; never a panic (101), a signal or a hang (issue
//! 21).
//!
//! The cases are a table: [`ROWS`] lists one line per (command, flag), with the command's
//! small budget in [`Command`]; a new flag is one more line.
#![allow(clippy::panic, reason = "tests report failures by panicking")]

use std::io::Read as _;
use std::process::{Command as Process, Stdio};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use serde_json::Value;

/// A command under test: its name, the flags it always gets (a small budget: two steps and
/// one second of walking, a sweep of one `mu0`), each left out where a row sets that flag, and
/// the variants of its other flags that every row is run with.
#[derive(Clone, Copy, Debug)]
struct Command {
    name: &'static str,
    defaults: &'static [(&'static str, &'static str)],
    variants: &'static [&'static [&'static str]],
}

/// The default method and friction law, exact Coulomb friction (other kernels, stick-slip
/// events) and the stiff method.
const VARIANTS: &[&[&str]] = &[
    &[],
    &["--friction", "coulomb"],
    &["--method", "rodas4"],
    &["--friction", "coulomb", "--impact", "coulomb"],
];

const SIMULATE: Command = Command {
    name: "simulate",
    defaults: &[("max-steps", "2"), ("duration", "1")],
    variants: VARIANTS,
};

/// The sweep's range by its flags' own names (`--mu0-from`, `--mu0-to`, `--mu0-step` are
/// aliases; a refusal names the flag, `invalid from:`).
const SWEEP: Command = Command {
    name: "sweep",
    defaults: &[
        ("from", "0.4"),
        ("to", "0.4"),
        ("step", "0.1"),
        ("max-steps", "2"),
        ("duration", "1"),
    ],
    variants: VARIANTS,
};

/// `fixed-point` has no budget flag: its work is bounded by the library (30 warm-up steps, at
/// most 30 Newton iterations of at most 8 map evaluations, each stance phase at most the
/// integrator's 100 000 attempted steps). Under RODAS4 its map (72 equations, the Jacobian by
/// finite differences) takes 6 to 12 s of a release build at extreme values
/// (`docs/stability.md`): the default method only, with the paper's impact, with friction at
/// the impact, and under exact Coulomb friction (the map by differences of simulated steps).
const FIXED_POINT: Command = Command {
    name: "fixed-point",
    defaults: &[],
    variants: &[&[], &["--impact", "coulomb"], &["--friction", "coulomb"]],
};

/// One numeric flag of one command, run on both built-in scenes with every value of
/// [`EXTREMES`] and its own `edges`.
#[derive(Clone, Copy, Debug)]
struct Row {
    command: Command,
    /// The flag under test, without `--`.
    flag: &'static str,
    /// Values at the edges of this flag's range (just inside and just outside).
    edges: &'static [&'static str],
    /// Other flags given the same value, where the flag's range depends on them
    /// (`--to` must be at least `--from`).
    same: &'static [&'static str],
    /// Defaults of the command replaced for this row.
    set: &'static [(&'static str, &'static str)],
}

const fn row(command: Command, flag: &'static str, edges: &'static [&'static str]) -> Row {
    Row {
        command,
        flag,
        edges,
        same: &[],
        set: &[],
    }
}

/// Values around a tolerance's range `(0, 1)`.
const UNIT: &[&str] = &["1", "0.9999999999999999", "1.0000000000000002"];
/// Values around the slope's range `[0, pi/2)`: `pi/2` rounded to `f64` is outside.
const SLOPE: &[&str] = &[
    "1.5707963267948966",
    "1.5707963267948963",
    "3.141592653589793",
];
/// Values around `--max-steps`' range `[0, 1 000 000]` and beyond `u64`.
const STEPS: &[&str] = &[
    "1000000",
    "1000001",
    "18446744073709551615",
    "18446744073709551616",
];
/// No values beyond [`EXTREMES`].
const NONE: &[&str] = &[];

/// Every (command, flag) under test.
const ROWS: &[Row] = &[
    row(SIMULATE, "c", NONE),
    row(SIMULATE, "rtol", UNIT),
    row(SIMULATE, "atol", UNIT),
    row(SIMULATE, "mu0", NONE),
    row(SIMULATE, "t-set", NONE),
    row(SIMULATE, "omega0", NONE),
    row(SIMULATE, "phi", SLOPE),
    row(SIMULATE, "duration", NONE),
    row(SIMULATE, "max-steps", STEPS),
    row(SWEEP, "c", NONE),
    row(SWEEP, "rtol", UNIT),
    row(SWEEP, "atol", UNIT),
    // A one-point grid at the value itself.
    Row {
        same: &["to"],
        ..row(SWEEP, "from", NONE)
    },
    // The grid `0, value` (two points).
    Row {
        same: &["step"],
        set: &[("from", "0")],
        ..row(SWEEP, "to", NONE)
    },
    row(SWEEP, "step", NONE),
    row(SWEEP, "t-set", NONE),
    row(SWEEP, "phi", SLOPE),
    row(SWEEP, "duration", NONE),
    row(SWEEP, "max-steps", STEPS),
    row(SWEEP, "until-periodic", UNIT),
    row(FIXED_POINT, "c", NONE),
    row(FIXED_POINT, "rtol", UNIT),
    row(FIXED_POINT, "atol", UNIT),
    row(FIXED_POINT, "mu0", NONE),
    row(FIXED_POINT, "t-set", NONE),
    row(FIXED_POINT, "phi", SLOPE),
    row(FIXED_POINT, "omega0", NONE),
];

/// The scenes every row runs on.
const SCENES: [&str; 2] = ["active-level", "passive-slope"];

/// Extreme values tried for every flag: zero of both signs, the smallest subnormal of both
/// signs, tiny, huge, the largest `f64`, negative, not finite.
const EXTREMES: &[&str] = &[
    "0",
    "-0",
    "5e-324",
    "-5e-324",
    "1e-300",
    "1e-100",
    "1e-12",
    "1e-5",
    "1e12",
    "1e300",
    "1.7976931348623157e308",
    "-1",
    "-1e300",
    "NaN",
    "inf",
    "-inf",
];

/// The wall-time bound of one case. Every case's work is bounded by its limits: a walk of
/// `simulate` or a sweep point at most two stance phases, each at most the integrator's 100 000
/// attempted steps (about 1.3 million evaluations of the right-hand side with DOP853, 0.3 s
/// here); `fixed-point` at most 30 warm-up steps and 30 Newton iterations of at most 8 map
/// evaluations. The slowest case measured took 0.95 s (`fixed-point --atol 1e-300`, whose
/// warm-up walk spends a budget of 100 000 steps; test profile, on two cores shared with other
/// builds; the 2336 cases took 12.3 s). 30 s is 30 times that: only a case that makes no
/// progress (the hangs of issue 21 ran for hours) or a thirty-fold slowdown reaches it.
const CASE_BOUND: Duration = Duration::from_secs(30);

/// One case: the arguments, the flags that carry the value under test, and its row's index.
struct Case {
    args: Vec<String>,
    flags: Vec<&'static str>,
    row: usize,
}

/// The command line of `row` (the `index`th) in `variant` on `scene` with `value`.
fn case(index: usize, row: &Row, variant: &[&str], scene: &str, value: &str) -> Case {
    let mut flags = vec![row.flag];
    flags.extend(row.same);
    let mut args: Vec<String> = vec![
        row.command.name.to_owned(),
        "--scene".to_owned(),
        scene.to_owned(),
        "--json".to_owned(),
    ];
    args.extend(variant.iter().map(|a| (*a).to_owned()));
    let fixed = row
        .command
        .defaults
        .iter()
        .filter(|(f, _)| !row.set.iter().any(|(g, _)| g == f))
        .chain(row.set);
    for (f, v) in fixed.filter(|(f, _)| !flags.contains(f)) {
        args.push(format!("--{f}"));
        args.push((*v).to_owned());
    }
    // `--flag=value`: a value starting with `-` is then the flag's, whatever clap's rules.
    args.extend(flags.iter().map(|f| format!("--{f}={value}")));
    Case {
        args,
        flags,
        row: index,
    }
}

/// Runs the binary with `args`: `(exit code, stdout, stderr, wall time)`, or `None` if it did
/// not end within `bound` (it is then killed).
fn run(args: &[String], bound: Duration) -> Option<(Option<i32>, String, String, Duration)> {
    let mut child = Process::new(env!("CARGO_BIN_EXE_walker"))
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start the walker binary");
    let start = Instant::now();
    // The outputs are small (a few kB), far below a pipe's buffer, so waiting first is safe.
    let status = loop {
        if let Some(status) = child.try_wait().expect("poll the walker binary") {
            break status;
        }
        if start.elapsed() > bound {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    let took = start.elapsed();
    let (mut out, mut err) = (String::new(), String::new());
    if let Some(mut s) = child.stdout.take() {
        s.read_to_string(&mut out).expect("read stdout");
    }
    if let Some(mut s) = child.stderr.take() {
        s.read_to_string(&mut err).expect("read stderr");
    }
    Some((status.code(), out, err, took))
}

/// Paths of `null`s that stand for a NaN or an infinity: every `null` except the documented
/// ones (no failure, no last or previous step of a sweep point, `p` and `SR` of the passive
/// wheel, the non-finite `lambda` of a pole). Also the path of any number that is not finite
/// (serde_json does not write them, but a reader would choke).
fn non_finite(v: &Value, path: &str, parent_kind: Option<&str>, bad: &mut Vec<String>) {
    match v {
        Value::Null => {
            let key = path.rsplit('.').next().unwrap_or("");
            let allowed = matches!(key, "failure" | "last" | "previous" | "p" | "SR")
                || (key == "lambda" && parent_kind == Some("LambdaDenominatorZero"));
            if !allowed {
                bad.push(path.to_owned());
            }
        }
        Value::Number(n) => {
            if !n.as_f64().is_some_and(f64::is_finite) {
                bad.push(path.to_owned());
            }
        }
        Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                non_finite(item, &format!("{path}[{i}]"), None, bad);
            }
        }
        Value::Object(map) => {
            let kind = map.get("kind").and_then(Value::as_str);
            for (k, item) in map {
                non_finite(item, &format!("{path}.{k}"), kind, bad);
            }
        }
        Value::Bool(_) | Value::String(_) => {}
    }
}

/// What is wrong with the outcome of `case`, if anything.
fn check(case: &Case, outcome: Option<(Option<i32>, String, String, Duration)>) -> Option<String> {
    let Some((code, stdout, stderr, _)) = outcome else {
        return Some(format!("did not end within {CASE_BOUND:?}"));
    };
    match code {
        Some(2) => {
            let named = case.flags.iter().any(|f| {
                stderr.contains(&format!("--{f}")) || stderr.contains(&format!("invalid {f}:"))
            });
            (!named || stderr.contains("panicked"))
                .then(|| format!("exit code 2 not naming {:?}:\n{stderr}", case.flags))
        }
        Some(0) => {
            let json: Value = match serde_json::from_str(stdout.trim()) {
                Ok(v) => v,
                Err(e) => return Some(format!("stdout is not JSON ({e}):\n{stdout}")),
            };
            if json.get("status").is_none() && json.get("chains").is_none() {
                return Some(format!("neither a status nor chains:\n{stdout}"));
            }
            let mut bad = Vec::new();
            non_finite(&json, "", None, &mut bad);
            (!bad.is_empty()).then(|| format!("non-finite values at {bad:?}:\n{stdout}"))
        }
        other => Some(format!(
            "exit code {other:?} (101 is a panic, None a signal)\nstdout:\n{stdout}\nstderr:\n{stderr}"
        )),
    }
}

#[test]
fn every_flag_at_every_extreme_value_gives_a_result_or_names_the_flag() {
    let mut cases = Vec::new();
    for (index, row) in ROWS.iter().enumerate() {
        for variant in row.command.variants {
            for scene in SCENES {
                for value in EXTREMES.iter().chain(row.edges) {
                    cases.push(case(index, row, variant, scene, value));
                }
            }
        }
    }
    // Cases that ran (exit code 0) per row: a row whose flag the command does not know (a
    // typo) would only ever be refused, naming the flag, and pass without testing anything.
    let ran: Vec<AtomicUsize> = ROWS.iter().map(|_| AtomicUsize::new(0)).collect();
    let next = AtomicUsize::new(0);
    let problems = Mutex::new(Vec::new());
    let times = Mutex::new(Vec::new());
    let start = Instant::now();
    // Two workers: the machine's two cores, each case a process of its own.
    std::thread::scope(|s| {
        for _ in 0..2 {
            s.spawn(|| {
                while let Some(c) = cases.get(next.fetch_add(1, Ordering::Relaxed)) {
                    let outcome = run(&c.args, CASE_BOUND);
                    if let Some((code, .., took)) = &outcome {
                        times.lock().expect("times").push((*took, c.args.join(" ")));
                        if *code == Some(0) {
                            ran[c.row].fetch_add(1, Ordering::Relaxed);
                        }
                    }
                    if let Some(p) = check(c, outcome) {
                        let line = format!("walker {}: {p}", c.args.join(" "));
                        problems.lock().expect("problems").push(line);
                    }
                }
            });
        }
    });
    let mut times = times.into_inner().expect("times");
    times.sort();
    for (took, args) in times.iter().rev().take(8) {
        eprintln!("{:>7.3} s  walker {args}", took.as_secs_f64());
    }
    eprintln!(
        "{} cases in {:.1} s",
        cases.len(),
        start.elapsed().as_secs_f64()
    );
    let problems = problems.into_inner().expect("problems");
    assert!(problems.is_empty(), "{}", problems.join("\n\n"));
    for (row, n) in ROWS.iter().zip(&ran) {
        let n = n.load(Ordering::Relaxed);
        assert!(n > 0, "{} --{}: no value ran", row.command.name, row.flag);
    }
}

/// The cases of issue 21, each with the failure it must name: a stiff `tanh` law spends the
/// integrator's budget ("too many steps", it used to run for hours), a ramp so short that the
/// control input is huge but finite is a huge numerator of Eq. 23 (it was named a pole), one
/// that overflows is non-finite, and so is a huge spin of a regular denominator. Each ends
/// within [`CASE_BOUND`] (each took under 0.4 s in the run of the table above).
#[test]
fn the_cases_of_issue_21_end_with_the_failure_of_their_cause() {
    for (args, status) in [
        (&["--c", "1e12"][..], "integrator"),
        (&["--c", "1e300"], "integrator"),
        (&["--t-set", "1e-5"], "lambda-numerator-huge"),
        (&["--t-set", "1e-100"], "lambda-numerator-huge"),
        (&["--t-set", "1e-300"], "non-finite"),
        (&["--omega0", "1e12"], "lambda-numerator-huge"),
    ] {
        let mut all: Vec<String> = ["simulate", "--scene", "active-level", "--duration", "1"]
            .map(str::to_owned)
            .to_vec();
        all.extend(args.iter().map(|a| (*a).to_owned()));
        all.push("--json".to_owned());
        let Some((code, stdout, stderr, _)) = run(&all, CASE_BOUND) else {
            panic!(
                "walker {}: did not end within {CASE_BOUND:?}",
                all.join(" ")
            );
        };
        assert_eq!(code, Some(0), "walker {}: {stderr}", all.join(" "));
        let json: Value = serde_json::from_str(stdout.trim()).expect("JSON");
        assert_eq!(json["status"], status, "walker {}: {stdout}", all.join(" "));
    }
}
