//! `walker floor-study` end to end through the binary, at a reduced size: it succeeds, writes
//! every figure and CSV file and `summary.txt`, prints that summary, and every claim holds.
//!
//! The size (12 walks of at most 100 steps per law, floor and `T_set`, instead of 100 of 200)
//! keeps the test near 30 s of CPU. The claims still hold at it because none rests on a rare
//! event: the ice patch claim is deterministic (single walks of 10 + k + 20 steps, the same at
//! any size); the `T_set` that walks farthest on a random floor (0.5 or 0.55) is two to five
//! grid points from the uniform floor's (0.35 or 0.3), whose distances in the full run differ
//! by metres, far more than the spread of a 12-walk mean (docs/floors.md); and the walker that
//! falls on the rough floor but walks every uniform floor of its range (tanh friction,
//! `T_set = 0.55`) fell in 97 of 100 walks of the full run, 57 steps on average, so that 12
//! walks of 100 steps all survive with odds near 1e-9 (about one walk in six survives 100 steps).
//!
//! The passive part walks ten times the walks, ten times as long (120 walks of at most 1000
//! steps per case; about 5 s of CPU more). Its claims hold at this size too: the Monte Carlo
//! MFPTs of neighbouring slope spreads differ by factors of 2 to 12 (the wheel's 680, 56 and 25
//! steps, the compass gait's 21, 8.8 and 5.2 here), so their 95% intervals (about +-20% with
//! 90 to 120 failures) do not overlap; the mesh does not depend on the size (its pilot walks
//! are fixed), so its convergence is the same at any size, and its estimate with its error
//! lies inside the Monte Carlo interval here (and in the full run, whose interval is three
//! times narrower, docs/floors.md); the friction the gaits need is read from single walks on
//! uniform floors; and the kinds of failure are structural (on the slopes every strike holds,
//! so no failure is a slip; on random friction 70% and 100% of the failures are slips).

use std::path::PathBuf;
use std::process::Command;

/// The figures (each `.png` and `.svg`) and CSV files of the study.
const FIGURES: [&str; 4] = [
    "floor_study_distance",
    "floor_study_survival",
    "floor_study_patch",
    "floor_study_passive",
];
const CSVS: [&str; 3] = [
    "floor_study_random",
    "floor_study_uniform",
    "floor_study_patch",
];

/// Laws x random floors x `T_set` values (`cli/src/floor_study/cases.rs`).
const SURVEYS: usize = 2 * 2 * 9;

/// The passive cases: two walkers on three slope spreads and one friction range each
/// (`cli/src/floor_study/passive.rs`).
const PASSIVE: usize = 2 * (3 + 1);

#[test]
fn the_floor_study_writes_every_file_and_every_claim_holds() {
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("floor-study");
    let _ = std::fs::remove_dir_all(&out);
    let o = Command::new(env!("CARGO_BIN_EXE_walker"))
        .args([
            "floor-study",
            "--walks",
            "12",
            "--max-steps",
            "100",
            "--out",
        ])
        .arg(&out)
        .output()
        .expect("the walker binary runs");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for f in FIGURES {
        for ext in ["png", "svg"] {
            let len = std::fs::metadata(out.join(format!("{f}.{ext}"))).map_or(0, |m| m.len());
            assert!(len > 1000, "{f}.{ext}: {len} bytes");
        }
    }
    let read = |name: &str| std::fs::read_to_string(out.join(name)).expect("the file is written");
    for c in CSVS {
        assert!(
            read(&format!("{c}.csv")).lines().count() > SURVEYS,
            "{c}.csv"
        );
    }
    let random = read("floor_study_random.csv");
    assert_eq!(random.lines().count(), 1 + SURVEYS, "{random}");
    assert!(
        random.lines().skip(1).all(|l| l.contains(",12,100,")),
        "{random}"
    );
    // The passive part: a row per case, 120 walks of at most 1000 steps, the mesh on the
    // wheel's three slope spreads only (three refinements and the samples' check).
    let passive = read("floor_study_passive.csv");
    assert_eq!(passive.lines().count(), 1 + PASSIVE, "{passive}");
    assert!(
        passive.lines().skip(1).all(|l| l.contains(",120,1000,")),
        "{passive}"
    );
    let meshed = passive
        .lines()
        .skip(1)
        .filter(|l| l.split(',').nth(11).is_some_and(|m| !m.is_empty()))
        .count();
    assert_eq!(meshed, 3, "{passive}");
    let summary = read("summary.txt");
    assert_eq!(summary, String::from_utf8_lossy(&o.stdout));
    let claims: Vec<&str> = summary.lines().filter(|l| l.starts_with("- [")).collect();
    assert_eq!(claims.len(), 9, "{summary}");
    for c in &claims {
        assert!(c.starts_with("- [holds]"), "{c}");
    }
    assert!(summary.contains("9 of 9 claims hold"), "{summary}");
}

#[test]
fn a_bad_size_is_refused_by_name_with_exit_code_2() {
    for (flag, value, named) in [
        ("--walks", "0", "walks"),
        ("--walks", "2001", "walks"),
        ("--max-steps", "1.5", "max-steps"),
        ("--max-steps", "10001", "max-steps"),
    ] {
        let o = Command::new(env!("CARGO_BIN_EXE_walker"))
            .args(["floor-study", flag, value, "--out"])
            .arg(PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("floor-study-refused"))
            .output()
            .expect("the walker binary runs");
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{flag} {value}: {err}");
        assert!(
            err.contains(named) && err.contains(value),
            "{flag} {value}: {err}"
        );
    }
}
