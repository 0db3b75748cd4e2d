//! The README's main command, `walker reproduce --out DIR`, end to end through the binary: it
//! succeeds, writes a PNG and an SVG of every figure and the CSV data next to them, and prints
//! the summary of the paper's claims that it also writes to `summary.txt`.

use crate::common;

use std::path::PathBuf;
use std::process::Command;

use common::decimals;

/// Every figure `reproduce` draws (each as `.png` and `.svg`).
const FIGURES: [&str; 21] = [
    "fig3",
    "fig4a",
    "fig4b",
    "fig5",
    "fig6a",
    "fig6b",
    "fig7",
    "fig8a",
    "fig8b",
    "fig8c",
    "fig8d",
    "fig8c_coulomb",
    "fig10a",
    "fig10b",
    "fig10b_continued",
    "fig11a",
    "fig11b",
    "fig12",
    "fig13",
    "fig14",
    "stability_active",
];

/// The data behind them.
const CSVS: [&str; 14] = [
    "fig3_motion_mu0_0",
    "fig5_motion_mu0_0.4",
    "fig4_steps_mu0_0",
    "fig6_steps_mu0_0.4",
    "fig7_convergence",
    "fig8_sweep",
    "fig8_sweep_coulomb",
    "fig8_sweep_coulomb_impact",
    "fig10_sweep",
    "fig10_sweep_continued",
    "passive_large_mu0",
    "passive_inertia",
    "fig12_step_length",
    "stability",
];

#[test]
fn reproduce_writes_every_figure_its_data_and_the_summary() {
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("reproduce");
    let _ = std::fs::remove_dir_all(&out);
    let o = Command::new(env!("CARGO_BIN_EXE_walker"))
        .args(["reproduce", "--out"])
        .arg(&out)
        .output()
        .expect("the walker binary runs");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let nonempty = |name: String| {
        let len = std::fs::metadata(out.join(&name)).map_or(0, |m| m.len());
        assert!(len > 100, "{name}: {len} bytes");
    };
    for f in FIGURES {
        nonempty(format!("{f}.png"));
        nonempty(format!("{f}.svg"));
    }
    for c in CSVS {
        nonempty(format!("{c}.csv"));
    }
    let summary = std::fs::read_to_string(out.join("summary.txt")).expect("summary.txt");
    assert_eq!(String::from_utf8_lossy(&o.stdout).trim(), summary.trim());
    for claim in [
        "limit cycles not unique",
        "T_set = 0.2 (Fig. 8): lift-off for mu0 in [0.00, ",
        "not periodic after 100 s for mu0 in [0.19, ",
        "exact Coulomb friction",
        "in stance and at the impact (docs/impacts.md), T_set = 0.3: max V at mu0 = 0.2",
        "(Fig. 14): fell-backward at step 1",
        "Stability from the Floquet multipliers",
    ] {
        assert!(summary.contains(claim), "missing {claim:?} in\n{summary}");
    }
    assert!(!summary.contains("NaN"), "{summary}");
    // The passive sweeps' CSV marks every point: `periodic` is `true` or `false` on every row.
    let sweep = std::fs::read_to_string(out.join("fig10_sweep.csv")).expect("fig10_sweep.csv");
    let mut rows = sweep.lines();
    let header: Vec<&str> = rows.next().unwrap_or_default().split(',').collect();
    let col = header
        .iter()
        .position(|h| *h == "periodic")
        .expect("a periodic column");
    let flags: Vec<&str> = rows
        .map(|r| r.split(',').nth(col).unwrap_or_default())
        .collect();
    assert_eq!(flags.len(), 3 * 71, "three phi, mu0 0 to 0.7 by 0.01");
    assert!(flags.iter().all(|f| *f == "true" || *f == "false"));
    assert!(flags.contains(&"true") && flags.contains(&"false"));
    readme_quotes_the_summary(&summary);
}

/// The README's claims table is quoted from `summary.txt`, not typed by hand: every decimal
/// number in its "found" column occurs in the summary this run wrote.
fn readme_quotes_the_summary(summary: &str) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let readme = std::fs::read_to_string(root.join("README.md")).expect("README.md");
    let table = readme
        .split_once("| claim (paper) | found |")
        .map(|(_, t)| t)
        .expect("the README's claims table");
    let rows: Vec<&str> = table
        .lines()
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .collect();
    assert!(rows.len() >= 15, "{} rows", rows.len());
    for row in rows {
        let found = row.split('|').nth(2).unwrap_or_default();
        for n in decimals(found) {
            assert!(
                summary.contains(&n),
                "README claims table quotes {n}, which summary.txt does not contain:\n{row}"
            );
        }
    }
}

/// The README's main command as a user types it (`cargo run --release -p walker-cli -- reproduce
/// --out out`, read from the README's first screen) reaches the `reproduce` subcommand: `cargo
/// run -p walker-cli` runs the package's `default-run` binary, so that must be the binary this
/// suite runs (`walker`), and its `reproduce` must take `--out`. Cargo's own metadata answers the
/// first half; running `cargo run` itself here would compile the whole workspace a second time
/// in another profile (3 minutes of CI) to learn the same thing. The end-to-end run is the test
/// above.
#[test]
fn the_readme_main_command_runs_the_cli() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let readme = std::fs::read_to_string(root.join("README.md")).expect("README.md");
    let line = readme
        .lines()
        .find(|l| l.starts_with("cargo run"))
        .expect("a `cargo run` line in the README");
    let command = line.split('#').next().unwrap_or_default();
    let words: Vec<&str> = command.split_whitespace().collect();
    assert_eq!(
        words,
        [
            "cargo",
            "run",
            "--release",
            "-p",
            "walker-cli",
            "--",
            "reproduce",
            "--out",
            "out"
        ],
        "the README's main command changed; update this test with it"
    );
    let o = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()))
        .current_dir(&root)
        .args(["metadata", "--no-deps", "--format-version", "1"])
        .output()
        .expect("cargo runs");
    assert!(
        o.status.success(),
        "cargo metadata failed: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    let metadata: serde_json::Value = serde_json::from_slice(&o.stdout).expect("metadata is JSON");
    let cli = metadata["packages"]
        .as_array()
        .and_then(|packages| packages.iter().find(|p| p["name"] == "walker-cli"))
        .expect("the walker-cli package");
    assert_eq!(
        cli["default_run"], "walker",
        "`cargo run -p walker-cli` must run `walker`"
    );
    let walker_bin = PathBuf::from(env!("CARGO_BIN_EXE_walker"));
    assert_eq!(
        walker_bin.file_stem().and_then(|s| s.to_str()),
        Some("walker")
    );
    let o = Command::new(&walker_bin)
        .args(["reproduce", "--help"])
        .output()
        .expect("walker runs");
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success() && stdout.contains("--out"),
        "`walker reproduce --help` failed:\n{}{}",
        stdout,
        String::from_utf8_lossy(&o.stderr)
    );
}
