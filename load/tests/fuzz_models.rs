//! Model files as a careless or hostile user writes them: every shipped model file, mutated by a
//! seeded generator (numbers replaced by zero, negative, huge, tiny, non-numbers and long
//! literals; names swapped, duplicated or reserved; lines deleted or duplicated; expressions
//! replaced by others of the file, by velocities, by `sin(1000*th)`; `[start]` values changed;
//! sections duplicated; extra `[[point]]`s), each run through the library path of
//! `walker simulate` (load, derive for the tape, walk a few steps) and of `walker-gen emit`
//! (derive and emit the code). For every case:
//!
//! - the result is `Ok`, or an error that names its place: `file:line:column` of the model
//!   file, or the derivation budget's error (which names the model and what was being
//!   derived), or one of the library's errors that name the field (a parameter's range);
//! - nothing panics (each case runs under `catch_unwind`);
//! - no case runs past [`CASE_SECONDS`];
//! - a case that walks from a finite start does not fail as `non-finite` at `t = 0`.
//!
//! The generator is seeded (the cases are the same on every run); `FUZZ_CASES=N` runs `N`
//! cases per model instead of the default, `FUZZ_SEED=S` another seed, `FUZZ_VERBOSE=1`
//! prints every case (with `--nocapture`).
//!
//! The default counts (398 cases) keep the suite near a minute of CI on two cores: a case that
//! the loader refuses costs well under a millisecond, one that derives, walks and emits costs
//! two derivations and an emission, measured on a loaded machine at 0.2 s (compass gait,
//! three-link), 0.4 s (five-link, rimless wheel) and 1.3 to 1.7 s (the paper's walkers), so
//! the cheap models get most cases. Before a release, run a few thousand:
//! `FUZZ_CASES=1000 cargo test --release -p walker-load --test fuzz_models`.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use walker::setup::{Overrides, Setup};
use walker::sim::{FailureKind, SimConfig, WalkLimits, walk};

mod fuzz;

use fuzz::{Rng, mutate};

/// The longest a case may take, each of its two paths (simulate, emit). The derivation is
/// bounded by its budget (2 million term products): spending it takes 2.5 to 3.5 s on one
/// idle core of the reference machine and up to 13 s with the machine shared by five builds
/// (a model whose inertia is `sin(12*th1)`, case 1 of the paper's active walker, spends it);
/// the lowering, the tape and three steps of a walk of at most 3 s of model time add about a
/// second for the shipped models' sizes. Twice the loaded figure.
const CASE_SECONDS: f64 = 30.0;

/// The largest start value or parameter at which a walk must not be `non-finite` at `t = 0`.
/// The kernels are polynomials of degree at most five in the state and the parameters (the
/// kinetic energy `m l^2 thd^2` is of degree four, the controlled closed loop one more), so
/// values up to `1e60` keep every product below `1e300`; a larger value may overflow, and then
/// `non-finite` at `t = 0` is the documented result (docs/stability.md: `--omega0 1e300`), not
/// a bug. The fuzzer's numbers are `0`, negatives, `1e300` and the like, so this splits them.
const MODERATE: f64 = 1e60;

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

/// What one case did wrong, if anything; and whether it walked and emitted.
fn run_case(path: &Path) -> (Option<String>, [bool; 2]) {
    let p = path.display().to_string();
    let t = Instant::now();
    let simulate = catch_unwind(AssertUnwindSafe(|| -> Result<Option<String>, String> {
        let source = walker_load::runtime_source();
        let setup = Setup::from_model_file(path, &Overrides::default(), Some(&source))
            .map_err(|e| e.to_string())?;
        let model = setup.model().map_err(|e| e.to_string())?;
        let start = model.start_state();
        let limits = WalkLimits {
            max_steps: 3,
            duration: 3.0,
            ..WalkLimits::default()
        };
        let w = walk(&model, &SimConfig::default(), &start, &limits);
        let moderate = start
            .iter()
            .chain(setup.params.values())
            .all(|v| v.abs() <= MODERATE);
        Ok(w.failure.and_then(|f| {
            (matches!(f.kind, FailureKind::NonFinite) && f.t == 0.0 && moderate).then(|| {
                "walks non-finite at t = 0 from a start and parameters of moderate size".to_owned()
            })
        }))
    }));
    let simulate_time = t.elapsed();
    let t = Instant::now();
    let emit = catch_unwind(AssertUnwindSafe(|| {
        walker_gen::Config::new()
            .model_file(path)
            .render()
            .map(|_| ())
            .map_err(|e| e.to_string())
    }));
    let emit_time = t.elapsed();
    let mut problems = Vec::new();
    let accepted = [matches!(simulate, Ok(Ok(_))), matches!(emit, Ok(Ok(())))];
    if std::env::var_os("FUZZ_VERBOSE").is_some() {
        eprintln!(
            "{}: simulate {:?} ({:.2} s), emit {:?} ({:.2} s)",
            path.display(),
            simulate.as_ref().map(|r| r.as_ref().map(|_| "ok")),
            simulate_time.as_secs_f64(),
            emit.as_ref().map(|r| r.as_ref().map(|_| "ok")),
            emit_time.as_secs_f64()
        );
    }
    match simulate {
        Err(_) => problems.push("simulate panicked".to_owned()),
        Ok(Ok(Some(bad))) => problems.push(format!("simulate: {bad}")),
        Ok(Err(e)) if !located(&e, &p) && !field_error(&e) => {
            problems.push(format!("simulate: an error without a place: {e}"));
        }
        Ok(_) => {}
    }
    match emit {
        Err(_) => problems.push("emit panicked".to_owned()),
        Ok(Err(e)) if !located(&e, &p) && !field_error(&e) => {
            problems.push(format!("emit: an error without a place: {e}"));
        }
        Ok(_) => {}
    }
    for (what, d) in [("simulate", simulate_time), ("emit", emit_time)] {
        if d > Duration::from_secs_f64(CASE_SECONDS) {
            problems.push(format!("{what} took {:.1} s", d.as_secs_f64()));
        }
    }
    (
        (!problems.is_empty()).then(|| problems.join("; ")),
        accepted,
    )
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
    let mut failures = Vec::new();
    let mut walked_emitted = [0, 0];
    for case in 0..cases {
        let (mutated, what) = mutate(&text, &mut rng);
        let path = dir.join(format!("case{case}.toml"));
        std::fs::write(&path, &mutated).expect("a temporary file");
        let (problem, accepted) = run_case(&path);
        for (count, ok) in walked_emitted.iter_mut().zip(accepted) {
            *count += usize::from(ok);
        }
        if std::env::var_os("FUZZ_VERBOSE").is_some() {
            eprintln!("case {case}: {what}");
        }
        if let Some(problem) = problem {
            failures.push(format!("{name} case {case} ({what}): {problem}"));
        }
        let _ = std::fs::remove_file(&path);
    }
    let _ = std::fs::remove_dir(&dir);
    eprintln!(
        "{name}: {cases} cases, {} walked, {} emitted, {} failures",
        walked_emitted[0],
        walked_emitted[1],
        failures.len()
    );
    failures
}

fn cases(default: usize) -> usize {
    std::env::var("FUZZ_CASES")
        .ok()
        .and_then(|c| c.parse().ok())
        .unwrap_or(default)
}

fn seed() -> u64 {
    std::env::var("FUZZ_SEED")
        .ok()
        .and_then(|c| c.parse().ok())
        .unwrap_or(35)
}

fn check(name: &str, default_cases: usize) {
    let failures = fuzz(name, cases(default_cases), seed());
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn mutated_compass_gait_files_load_walk_and_emit_or_fail_with_a_place() {
    check("compass-gait", 150);
}

#[test]
fn mutated_rimless_wheel_files_load_walk_and_emit_or_fail_with_a_place() {
    check("rimless-wheel", 40);
}

#[test]
fn mutated_three_link_files_load_walk_and_emit_or_fail_with_a_place() {
    check("three-link", 120);
}

#[test]
fn mutated_five_link_files_load_walk_and_emit_or_fail_with_a_place() {
    check("five-link", 60);
}

#[test]
fn mutated_paper_passive_files_load_walk_and_emit_or_fail_with_a_place() {
    check("paper-passive", 12);
}

#[test]
fn mutated_paper_active_files_load_walk_and_emit_or_fail_with_a_place() {
    check("paper-active", 16);
}
