//! Random flag values for `walker simulate --json`: every run ends with exit code 2 and a
//! message naming the flag, or with exit code 0 and one JSON object with a `"status"`; never a
//! panic (exit code 101), a signal, a hang, or a NaN in the JSON.
//!
//! The values come from a seeded xorshift generator written here (no dependency), so every
//! run tries the same 48 cases; a failure message prints the command line to repeat it.
//! `WALKER_FUZZ_SEED=<u64>` tries another 48 (for exploring; the default seed is the test).
#![allow(clippy::panic, reason = "tests report failures by panicking")]

use std::io::Read as _;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use serde_json::Value;

/// xorshift64* (Vigna): small, seeded, good enough to pick test inputs.
struct XorShift(u64);

impl XorShift {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// Uniform in `0..n` (`n > 0`; the modulo bias is irrelevant here).
    fn below(&mut self, n: usize) -> usize {
        usize::try_from(self.next() % u64::try_from(n).unwrap_or(1)).unwrap_or(0)
    }

    /// Uniform in `[0, 1)`.
    fn unit(&mut self) -> f64 {
        // The top 53 bits, exactly representable.
        #[allow(clippy::cast_precision_loss, reason = "53 bits fit an f64 exactly")]
        let v = (self.next() >> 11) as f64;
        v / (1_u64 << 53) as f64
    }

    fn pick<'a>(&mut self, items: &[&'a str]) -> &'a str {
        items.get(self.below(items.len())).copied().unwrap_or("")
    }
}

/// The flags under test (without `--`).
const FLAGS: [&str; 7] = [
    "mu0",
    "c",
    "t-set",
    "omega0",
    "phi",
    "duration",
    "max-steps",
];

/// Values that are not numbers, not finite, negative, huge, tiny or malformed.
const WEIRD: [&str; 28] = [
    "NaN",
    "nan",
    "-NaN",
    "inf",
    "-inf",
    "+inf",
    "infinity",
    "-Infinity",
    "-1",
    "-0.5",
    "-0",
    "0",
    "-1e308",
    "1e308",
    "1.7976931348623157e308",
    "1e300",
    "1e-300",
    "5e-324",
    "18446744073709551616",
    "-5",
    "",
    " ",
    "abc",
    "1.0.0",
    "0x10",
    "1e",
    "--",
    "\u{e9}",
];

/// A weird value for `flag`: a fixed one, or a random number over 600 decades of either sign.
fn weird(rng: &mut XorShift, flag: &str) -> String {
    if rng.below(4) == 0 {
        let exponent = rng.unit() * 600.0 - 300.0;
        let sign = if rng.below(2) == 0 { "-" } else { "" };
        if flag == "max-steps" {
            return format!("{sign}{}", rng.next());
        }
        return format!("{sign}{:e}", 10_f64.powf(exponent));
    }
    rng.pick(&WEIRD).to_owned()
}

/// A valid value for `flag` on `scene` (the extra flags of a case); `None` where the flag has
/// none: a flag that names a parameter the scene's model does not have is refused whatever its
/// value (the active walker's level floor has no slope `phi`, the passive wheel no ramp
/// `T_set`). Draws the same random number either way, so that the cases stay the same.
fn valid(rng: &mut XorShift, flag: &str, scene: &str) -> Option<String> {
    let u = rng.unit();
    let active = scene == "active-level";
    Some(match flag {
        "mu0" => format!("{}", 0.1 + 0.9 * u),
        "c" => format!("{}", 1.0 + 99.0 * u),
        "t-set" if active => format!("{}", 0.1 + 0.5 * u),
        "omega0" => format!("{}", 0.5 + u),
        "phi" if !active => format!("{}", 0.3 * u),
        "t-set" | "phi" => return None,
        "duration" => "2".to_owned(),
        _ => "3".to_owned(),
    })
}

/// Runs the binary with `args`; `(exit code, stdout, stderr)`. Fails the test after 120 s.
fn run(args: &[String]) -> (Option<i32>, String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_walker"))
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
        if start.elapsed() > Duration::from_secs(120) {
            let _ = child.kill();
            let _ = child.wait();
            panic!("walker {} did not finish within 120 s", args.join(" "));
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let (mut out, mut err) = (String::new(), String::new());
    if let Some(mut s) = child.stdout.take() {
        s.read_to_string(&mut out).expect("read stdout");
    }
    if let Some(mut s) = child.stderr.take() {
        s.read_to_string(&mut err).expect("read stderr");
    }
    (status.code(), out, err)
}

/// Where a JSON `null` is legitimate: no failure; `p` and `SR` of the passive wheel; the
/// documented non-finite `lambda` of `LambdaDenominatorZero`. Any other `null` is a NaN or an
/// infinity that serde_json wrote as `null`.
fn check_nulls(v: &Value, path: &str, failure_kind: Option<&str>, bad: &mut Vec<String>) {
    match v {
        Value::Null => {
            let key = path.rsplit('.').next().unwrap_or("");
            let allowed = path == ".failure"
                || (path.starts_with(".steps[") && (key == "p" || key == "SR"))
                || (path == ".failure.lambda" && failure_kind == Some("LambdaDenominatorZero"));
            if !allowed {
                bad.push(path.to_owned());
            }
        }
        Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                check_nulls(item, &format!("{path}[{i}]"), failure_kind, bad);
            }
        }
        Value::Object(map) => {
            for (k, item) in map {
                check_nulls(item, &format!("{path}.{k}"), failure_kind, bad);
            }
        }
        Value::Bool(_) | Value::Number(_) | Value::String(_) => {}
    }
}

#[test]
fn random_simulate_flags_give_exit_2_naming_the_flag_or_a_json_status() {
    let seed = std::env::var("WALKER_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse::<u64>().ok())
        .filter(|&s| s != 0)
        .unwrap_or(0x9E37_79B9_7F4A_7C15);
    let mut rng = XorShift(seed);
    let mut outcomes = [0_usize; 2];
    for case in 0..48 {
        let scene = if case % 2 == 0 {
            "active-level"
        } else {
            "passive-slope"
        };
        let target = FLAGS[(case / 2) % FLAGS.len()];
        let value = weird(&mut rng, target);
        let mut args: Vec<String> = ["simulate", "--scene", scene, "--json"]
            .map(str::to_owned)
            .to_vec();
        // `--flag=value` or `--flag value`: clap treats a value starting with `-` differently.
        if rng.below(2) == 0 {
            args.push(format!("--{target}={value}"));
        } else {
            args.push(format!("--{target}"));
            args.push(value.clone());
        }
        for flag in FLAGS.iter().filter(|f| **f != target) {
            let always = *flag == "duration" || *flag == "max-steps";
            if (always || rng.below(3) == 0)
                && let Some(v) = valid(&mut rng, flag, scene)
            {
                args.push(format!("--{flag}"));
                args.push(v);
            }
        }
        let shown = args
            .iter()
            .map(|a| format!("{a:?}"))
            .collect::<Vec<_>>()
            .join(" ");
        let (code, stdout, stderr) = run(&args);
        match code {
            Some(2) => {
                let named = stderr.contains(&format!("--{target}"))
                    || stderr.contains(&format!("invalid {target}:"));
                assert!(
                    named,
                    "case {case}: walker {shown}: exit code 2 but stderr does not name \
                     --{target}:\n{stderr}"
                );
                outcomes[0] += 1;
            }
            Some(0) => {
                for word in ["NaN", "nan", "inf", "Infinity"] {
                    assert!(
                        !stdout.contains(word),
                        "case {case}: walker {shown}: {word} in the JSON:\n{stdout}"
                    );
                }
                let json: Value = serde_json::from_str(stdout.trim()).unwrap_or_else(|e| {
                    panic!("case {case}: walker {shown}: stdout is not JSON ({e}):\n{stdout}")
                });
                assert!(
                    json.get("status").is_some_and(Value::is_string),
                    "case {case}: walker {shown}: no \"status\" string:\n{stdout}"
                );
                let kind = json
                    .get("failure")
                    .and_then(|f| f.get("kind"))
                    .and_then(Value::as_str);
                let mut bad = Vec::new();
                check_nulls(&json, "", kind, &mut bad);
                assert!(
                    bad.is_empty(),
                    "case {case}: walker {shown}: null (a NaN or an infinity) at {bad:?}:\n{stdout}"
                );
                outcomes[1] += 1;
            }
            other => panic!(
                "case {case}: walker {shown}: exit code {other:?} (101 is a panic, None a \
                 signal)\nstdout:\n{stdout}\nstderr:\n{stderr}"
            ),
        }
    }
    // Both outcomes occur, so neither branch is vacuous.
    assert!(outcomes[0] > 0 && outcomes[1] > 0, "{outcomes:?}");
}

/// Found by the fuzz test: `--max-steps -5` was taken for an unknown flag `-5` ("unexpected
/// argument '-5' found"), a message that does not name `--max-steps`; a negative count (also
/// `-0`) is refused with the flag's range.
#[test]
fn a_negative_max_steps_names_the_flag() {
    for form in [
        &["--max-steps", "-5"][..],
        &["--max-steps=-1"],
        &["--max-steps", "-0"],
    ] {
        let mut args: Vec<String> = ["simulate", "--scene", "active-level", "--json"]
            .map(str::to_owned)
            .to_vec();
        args.extend(form.iter().map(|s| (*s).to_owned()));
        let (code, _, stderr) = run(&args);
        assert_eq!(code, Some(2), "{form:?}: {stderr}");
        // Named as every refused flag is (`invalid max-steps:`), with its range.
        assert!(stderr.contains("invalid max-steps:"), "{form:?}: {stderr}");
        assert!(stderr.contains("[0, 1000000]"), "{form:?}: {stderr}");
    }
}
