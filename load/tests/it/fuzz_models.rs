//! Model files as a careless or hostile user writes them: every shipped model file, mutated by a
//! seeded generator (numbers replaced by zero, negative, huge, tiny, non-numbers and long
//! literals; names swapped, duplicated or reserved; lines deleted or duplicated; expressions
//! replaced by others of the file, by velocities, by `sin(1000*th)`; `[start]` values changed;
//! sections duplicated; extra `[[point]]`s). For every case:
//!
//! - the result is `Ok`, or an error that names its place: `file:line:column` of the model
//!   file, or the derivation budget's error (which names the model and what was being
//!   derived), or one of the library's errors that name the field (a parameter's range);
//! - nothing panics (each stage runs under `catch_unwind`);
//! - no case runs past [`CASE_SECONDS`];
//! - a case that walks from a finite start does not fail as `non-finite` at `t = 0` (where
//!   its numbers are of a size the kernels cannot overflow with, [`MODERATE`]).
//!
//! Where a case's time goes (measured on the two-core CI machine's equal, test profile, the
//! machine shared with two other builds): parsing and validating a mutant costs 0.1 to 1 ms;
//! deriving it 0.05 s (compass gait) to 1 s (the paper's walkers), and up to the derivation
//! budget's 3 to 13 s for the mutants that exhaust it; lowering its kernels to the tape about
//! as much again; three steps of a walk on the tape a few milliseconds; emitting the Rust
//! source (`walker-gen emit`: a derivation, a lowering and the emission) the sum of those. So a
//! case costs its derivation, and the suite runs a few thousand of them in a minute or two by
//! doing each derivation once:
//!
//! 1. every mutant is parsed and validated ([`Model::from_toml`], the loader every tool
//!    shares); most are refused there, each refusal checked for its place;
//! 2. an accepted mutant whose canonical content ([`Model::canonical`]: what the generated
//!    code depends on; comments, layout and doc strings are not in it) equals an earlier
//!    case's gets that case's result: the same model, the same path through the library;
//! 3. the others go the library path of `walker simulate` (load, derive, lower, walk three
//!    steps of at most 3 s of model time), with the derivation shared by the mutants that
//!    differ only in what it does not see (`fuzz/shared.rs`: the parameters' ranges);
//! 4. `walker-gen emit` (the library path: `Config::model_file(..).render()`) runs for the
//!    first mutant of every [`EMIT_EVERY`]-th derivation. Its reading, derivation and
//!    lowering are the code the walk path runs (the same loader, `derive_model`,
//!    `lower_model`); what only it runs is the emission of a lowered module to Rust, whose
//!    input is the lowered graph, not the file: a sample of the distinct derivations covers
//!    it, and every emission is checked as the walks are.
//!
//! The generator is seeded (the cases are the same on every run); `FUZZ_CASES=N` runs `N`
//! cases per model instead of the default, `FUZZ_SEED=S` another seed, `FUZZ_EMIT_EVERY=K`
//! emits every `K`-th derivation (1: all), `FUZZ_VERBOSE=1` prints every case (with
//! `--nocapture`). Each model's test prints its counts and where its time went.
//!
//! The default counts (3300 cases in all) keep the suite near a minute and a half of CI on two
//! cores (measured: see `docs/stability.md`); the cheap models get most cases. Before a
//! release, run more: `FUZZ_CASES=3000 cargo test --release -p walker-load --test it fuzz_models::`.

use std::collections::HashMap;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use walker::setup::{Overrides, RuntimeSource, Setup};
use walker::sim::{FailureKind, SimConfig, WalkLimits, walk};
use walker_gen::scene::model::Model;

use crate::fuzz;

use fuzz::shared::{SharedSource, derivation_key};
use fuzz::{Rng, mutate};

/// The longest a case may take, each of its stages (load, simulate, emit). The derivation is
/// bounded by its budget (2 million term products): spending it takes 2.5 to 3.5 s on one
/// idle core of the reference machine and up to 13 s with the machine shared by five builds
/// (a model whose inertia is `sin(12*th1)`, case 1 of the paper's active walker, spends it);
/// the lowering, the tape and three steps of a walk of at most 3 s of model time add about a
/// second for the shipped models' sizes. Twice the loaded figure.
const CASE_SECONDS: f64 = 30.0;

/// The bounds on the size of a model's numbers (its parameters, its start, the literals of its
/// expressions) within which a walk must not be `non-finite` at `t = 0`. The kernels are
/// polynomials of degree at most five in the state and the parameters (the kinetic energy
/// `m l^2 thd^2` is of degree four, the controlled closed loop one more), divided by at most
/// the fifth power of a parameter (the quintic ramp's `1 / T_set^5`), so magnitudes in
/// `[1e-60, 1e60]` (and zero) keep every product below `1e300`; a larger or smaller one may
/// overflow, and then `non-finite` at `t = 0` is the documented result (docs/stability.md:
/// `--omega0 1e300`, a ramp of `1e-300` s), not a bug. The fuzzer's numbers are `0`,
/// negatives, `1e300`, `1e-300` and the like, so this splits them.
const MODERATE: f64 = 1e60;

/// Whether `x` is zero or of a magnitude within `[1 / MODERATE, MODERATE]`.
fn moderate(x: f64) -> bool {
    x == 0.0 || (1.0 / MODERATE..=MODERATE).contains(&x.abs())
}

/// Whether every number written in `text` outside comments (digits with an optional
/// fraction and exponent) is [`moderate`].
fn moderate_literals(text: &str) -> bool {
    text.lines().all(|line| {
        let code = line.split('#').next().unwrap_or("").as_bytes();
        let mut i = 0;
        while i < code.len() {
            let starts = (code[i].is_ascii_digit() || code[i] == b'.')
                && (i == 0 || !(code[i - 1].is_ascii_alphanumeric() || code[i - 1] == b'_'));
            if !starts {
                i += 1;
                continue;
            }
            let s = i;
            while i < code.len()
                && (code[i].is_ascii_digit()
                    || code[i] == b'.'
                    || ((code[i] == b'e' || code[i] == b'E')
                        && code
                            .get(i + 1)
                            .is_some_and(|c| c.is_ascii_digit() || *c == b'-' || *c == b'+'))
                    || ((code[i] == b'-' || code[i] == b'+') && matches!(code[i - 1], b'e' | b'E')))
            {
                i += 1;
            }
            let token = std::str::from_utf8(&code[s..i]).unwrap_or("0");
            if token.parse::<f64>().is_ok_and(|x| !moderate(x)) {
                return false;
            }
        }
        true
    })
}

/// Emission is checked for the first mutant of every `EMIT_EVERY`-th distinct derivation (the
/// module documentation argues the sample): an emission repeats its derivation, so emitting
/// every one would double the suite's time.
const EMIT_EVERY: usize = 8;

fn models_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../models")
}

/// Whether `message` names a place: `file:line:column` of `path`, or the derivation's budget
/// (the model and what was being derived).
fn located(message: &str, path: &str) -> bool {
    if message.contains("derivation budget of") {
        return true;
    }
    let mut rest = message;
    while let Some(i) = rest.find(path) {
        let after = &rest[i + path.len()..];
        let mut parts = after.splitn(3, ':');
        let _ = parts.next();
        let line = parts.next().unwrap_or("");
        let column: String = parts
            .next()
            .unwrap_or("")
            .chars()
            .take_while(char::is_ascii_digit)
            .collect();
        if !line.is_empty() && line.chars().all(|c| c.is_ascii_digit()) && !column.is_empty() {
            return true;
        }
        rest = after;
    }
    false
}

/// Whether a stage's outcome is acceptable: `Ok`, or an error with a place; the problem if
/// not. `None`: the stage panicked.
fn judge(what: &str, outcome: Option<Result<(), &str>>, path: &str) -> Option<String> {
    match outcome {
        None => Some(format!("{what} panicked")),
        Some(Err(e)) if !located(e, path) && !field_error(e) => {
            Some(format!("{what}: an error without a place: {e}"))
        }
        Some(_) => None,
    }
}

/// A stage's outcome as [`judge`] takes it.
fn outcome<T>(r: &std::thread::Result<Result<T, String>>) -> Option<Result<(), &str>> {
    r.as_ref()
        .ok()
        .map(|r| r.as_ref().map(|_| ()).map_err(String::as_str))
}

/// The simulate path of one accepted mutant at `path`: load it as `walker simulate --model`
/// does (its derivation from `source`), walk three steps; an error, or the reason a walk is
/// wrong (`non-finite` at `t = 0` from a moderate start).
fn simulate(path: &Path, text: &str, source: &RuntimeSource) -> Result<Option<String>, String> {
    let setup = Setup::from_model_file(path, &Overrides::default(), Some(source))
        .map_err(|e| e.to_string())?;
    let model = setup.model().map_err(|e| e.to_string())?;
    let start = model.start_state();
    let limits = WalkLimits {
        max_steps: 3,
        duration: 3.0,
        ..WalkLimits::default()
    };
    let w = walk(&model, &SimConfig::default(), &start, &limits);
    let within = start
        .iter()
        .chain(setup.params.values())
        .all(|&v| moderate(v))
        && moderate_literals(text);
    Ok(w.failure.and_then(|f| {
        (matches!(f.kind, FailureKind::NonFinite) && f.t == 0.0 && within).then(|| {
            "walks non-finite at t = 0 from a start and parameters of moderate size".to_owned()
        })
    }))
}

/// The counts of one model's run, and where its time went.
#[derive(Default)]
struct Tally {
    refused: usize,
    repeated: usize,
    walked: usize,
    emitted: usize,
    emit_checked: usize,
    load: Duration,
    simulate: Duration,
    emit: Duration,
}

/// The library's errors that name the field without a file place: a parameter outside its
/// documented range (the model's defaults are checked as a request's values are).
fn field_error(message: &str) -> bool {
    message.contains("is outside") && message.contains("range")
}

/// Runs `cases` mutations of `models/<name>.toml`; the failures.
fn fuzz(name: &str, cases: usize, seed: u64) -> Vec<String> {
    let text = std::fs::read_to_string(models_dir().join(format!("{name}.toml")))
        .expect("a shipped model");
    let mut rng = Rng(seed
        ^ name
            .bytes()
            .fold(0u64, |h, b| h.wrapping_mul(31).wrapping_add(u64::from(b))));
    let dir = std::env::temp_dir().join(format!("walker-fuzz-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let emit_every = env("FUZZ_EMIT_EVERY").unwrap_or(EMIT_EVERY as u64).max(1) as usize;
    let verbose = std::env::var_os("FUZZ_VERBOSE").is_some();
    // `Setup` takes a run-time source that lives for the program; the derivations are this
    // model's, counted after its cases.
    let shared = std::sync::Arc::new(SharedSource::default());
    let source = {
        let shared = std::sync::Arc::clone(&shared);
        move |m: &Model| shared.source(m)
    };
    // The result of each canonical content run so far, by the case that ran it.
    let mut ran: HashMap<String, usize> = HashMap::new();
    // The derivations seen so far, in order (the emission's sample).
    let mut derivations: HashMap<String, usize> = HashMap::new();
    let mut failures = Vec::new();
    let mut tally = Tally::default();
    for case in 0..cases {
        let (mutated, what) = mutate(&text, &mut rng);
        let path = dir.join(format!("case{case}.toml"));
        let p = path.display().to_string();
        let mut problems = Vec::new();
        // 1. Parse and validate: the loader every tool shares.
        let t = Instant::now();
        let loaded = catch_unwind(AssertUnwindSafe(|| {
            Model::from_toml(&mutated, &p).map_err(|e| e.to_string())
        }));
        let load_time = t.elapsed();
        tally.load += load_time;
        let mut times = vec![("load", load_time)];
        problems.extend(judge("load", outcome(&loaded), &p));
        let model = match loaded {
            Ok(Ok(model)) => model,
            _ => {
                tally.refused += 1;
                report(&mut failures, name, case, &what, problems, &times);
                continue;
            }
        };
        // 2. The same canonical content as an earlier case: its result.
        let canonical = model.canonical();
        if let Some(first) = ran.get(&canonical) {
            tally.repeated += 1;
            if verbose {
                eprintln!("case {case}: {what}: as case {first}");
            }
            continue;
        }
        ran.insert(canonical, case);
        std::fs::write(&path, &mutated).expect("a temporary file");
        // 3. The simulate path, its derivation shared.
        let t = Instant::now();
        let walked = catch_unwind(AssertUnwindSafe(|| simulate(&path, &mutated, &source)));
        let simulate_time = t.elapsed();
        tally.simulate += simulate_time;
        times.push(("simulate", simulate_time));
        if let Ok(Ok(Some(bad))) = &walked {
            problems.push(format!("simulate: {bad}"));
        }
        tally.walked += usize::from(matches!(walked, Ok(Ok(None))));
        problems.extend(judge("simulate", outcome(&walked), &p));
        // 4. The emit path, on the first mutant of every `emit_every`-th derivation.
        let key = derivation_key(&model);
        let seen = derivations.len();
        if let std::collections::hash_map::Entry::Vacant(e) = derivations.entry(key) {
            e.insert(case);
            if seen.is_multiple_of(emit_every) {
                let t = Instant::now();
                let emitted = catch_unwind(AssertUnwindSafe(|| {
                    walker_gen::Config::new()
                        .model_file(&path)
                        .render()
                        .map(|_| ())
                        .map_err(|e| e.to_string())
                }));
                let emit_time = t.elapsed();
                tally.emit += emit_time;
                times.push(("emit", emit_time));
                tally.emit_checked += 1;
                tally.emitted += usize::from(matches!(emitted, Ok(Ok(()))));
                problems.extend(judge("emit", outcome(&emitted), &p));
            }
        }
        if verbose {
            let times: Vec<String> = times
                .iter()
                .map(|(s, d)| format!("{s} {:.3} s", d.as_secs_f64()))
                .collect();
            eprintln!("case {case}: {what}: {}", times.join(", "));
        }
        report(&mut failures, name, case, &what, problems, &times);
        let _ = std::fs::remove_file(&path);
    }
    let _ = std::fs::remove_dir(&dir);
    let derived = shared.derived.lock().map_or(0, |d| *d);
    let derive_time = shared.time.lock().map_or(Duration::ZERO, |d| *d);
    eprintln!(
        "{name}: {cases} cases: {} refused at load ({:.2} s), {} repeated an earlier case, {} \
         simulated ({:.1} s, of which deriving {derived} models {:.1} s), {} walked, {} of {} \
         emitted ({:.1} s); {} failures",
        tally.refused,
        tally.load.as_secs_f64(),
        tally.repeated,
        cases - tally.refused - tally.repeated,
        tally.simulate.as_secs_f64(),
        derive_time.as_secs_f64(),
        tally.walked,
        tally.emitted,
        tally.emit_checked,
        tally.emit.as_secs_f64(),
        failures.len()
    );
    failures
}

/// Records the problems of a case, with the time bound checked on each of its stages.
fn report(
    failures: &mut Vec<String>,
    name: &str,
    case: usize,
    what: &str,
    mut problems: Vec<String>,
    times: &[(&str, Duration)],
) {
    for (stage, d) in times {
        if *d > Duration::from_secs_f64(CASE_SECONDS) {
            problems.push(format!("{stage} took {:.1} s", d.as_secs_f64()));
        }
    }
    if !problems.is_empty() {
        failures.push(format!(
            "{name} case {case} ({what}): {}",
            problems.join("; ")
        ));
    }
}

fn env(name: &str) -> Option<u64> {
    std::env::var(name).ok().and_then(|c| c.parse().ok())
}

/// The most memory the fuzzing process may have held at once (its peak resident set, bytes).
/// A derivation is bounded by its budget of 2 million weighted term products; a polynomial's
/// term (its exponent vector over at most a few dozen symbols and an exact rational
/// coefficient) takes of the order of 100 to 200 bytes, so a derivation that spends its whole
/// budget holds at most a few hundred megabytes, and the test harness runs at most one model's
/// cases per core (two here) beside walks and tapes of a few megabytes. 2 GiB is that with a
/// margin; a read of `/dev/zero` or a grid built whole would pass it.
const MEMORY_BYTES: u64 = 2 << 30;

/// The process's peak resident set so far (Linux: `VmHWM` of `/proc/self/status`), in bytes.
fn peak_resident_bytes() -> u64 {
    let status = std::fs::read_to_string("/proc/self/status").expect("/proc/self/status");
    let kb = status
        .lines()
        .find_map(|l| l.strip_prefix("VmHWM:"))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse::<u64>().ok())
        .expect("VmHWM in /proc/self/status");
    kb * 1024
}

fn check(name: &str, default_cases: usize) {
    let cases = env("FUZZ_CASES").map_or(default_cases, |c| c as usize);
    let failures = fuzz(name, cases, env("FUZZ_SEED").unwrap_or(35));
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
    let peak = peak_resident_bytes();
    println!(
        "{name}: peak resident set of the process so far {} MiB",
        peak >> 20
    );
    assert!(
        peak <= MEMORY_BYTES,
        "{name}: the process held {} MiB at its peak, over the bound of {} MiB",
        peak >> 20,
        MEMORY_BYTES >> 20
    );
}

#[test]
fn mutated_compass_gait_files_load_walk_and_emit_or_fail_with_a_place() {
    check("compass-gait", 1100);
}

#[test]
fn mutated_rimless_wheel_files_load_walk_and_emit_or_fail_with_a_place() {
    check("rimless-wheel", 400);
}

#[test]
fn mutated_three_link_files_load_walk_and_emit_or_fail_with_a_place() {
    check("three-link", 900);
}

#[test]
fn mutated_five_link_files_load_walk_and_emit_or_fail_with_a_place() {
    check("five-link", 500);
}

#[test]
fn mutated_paper_passive_files_load_walk_and_emit_or_fail_with_a_place() {
    check("paper-passive", 150);
}

#[test]
fn mutated_paper_active_files_load_walk_and_emit_or_fail_with_a_place() {
    check("paper-active", 250);
}
