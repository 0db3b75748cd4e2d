//! `walker gallery --out DIR` end to end through the binary: it succeeds, writes every figure
//! (PNG and SVG) and CSV file of each model and `summary.txt`, prints that summary, and every
//! claim of it holds; the README's gallery figures are the ones it draws, and their captions
//! quote its numbers.

use crate::common;

use std::path::PathBuf;
use std::process::Command;

use common::decimals;

/// The gallery's models (`cli/src/gallery/entries.rs`) and the chains (slopes) of each one's
/// sweeps (the three-link biped is level: one chain).
const MODELS: [(&str, usize); 3] = [("rimless-wheel", 3), ("compass-gait", 3), ("three-link", 1)];

/// Each model's figures (each as `.png` and `.svg`), `{}` the model's name.
const FIGURES: [&str; 3] = ["{}", "{}_sweep", "{}_friction"];

/// Each model's CSV files.
const CSVS: [&str; 3] = ["{}_sweep", "{}_held", "{}_friction"];

/// The bifurcation diagrams (`cli/src/gallery/bifurcation.rs`), each `bifurcation_<stem>` as
/// `.png`, `.svg` and `.csv`.
const DIAGRAMS: [&str; 5] = [
    "compass_gait_phi",
    "compass_gait_mu0",
    "rimless_wheel_phi",
    "simplest_walker_phi",
    "three_link_k_p",
];

#[test]
fn gallery_writes_every_file_and_every_claim_holds() {
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("gallery");
    let _ = std::fs::remove_dir_all(&out);
    let o = Command::new(env!("CARGO_BIN_EXE_walker"))
        .args(["gallery", "--out"])
        .arg(&out)
        .output()
        .expect("the walker binary runs");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let nonempty = |name: String| {
        let len = std::fs::metadata(out.join(&name)).map_or(0, |m| m.len());
        assert!(len > 100, "{name}: {len} bytes");
    };
    for (m, _) in MODELS {
        for f in FIGURES {
            nonempty(format!("{}.png", f.replace("{}", m)));
            nonempty(format!("{}.svg", f.replace("{}", m)));
        }
        for c in CSVS {
            nonempty(format!("{}.csv", c.replace("{}", m)));
        }
    }
    // The three-link biped's designed gait beside its hand-made one (`gallery/designed.rs`).
    nonempty("three-link_designed.png".to_owned());
    nonempty("three-link_designed.svg".to_owned());
    for d in DIAGRAMS {
        for ext in ["png", "svg", "csv"] {
            nonempty(format!("bifurcation_{d}.{ext}"));
        }
    }
    let summary = std::fs::read_to_string(out.join("summary.txt")).expect("summary.txt");
    assert_eq!(String::from_utf8_lossy(&o.stdout).trim(), summary.trim());
    // Every claim holds, and there are claims of every model (generic and their own).
    let claims: Vec<&str> = summary.lines().filter(|l| l.starts_with("- [")).collect();
    assert!(claims.len() >= 20, "{} claims:\n{summary}", claims.len());
    for c in &claims {
        assert!(c.starts_with("- [holds] "), "a claim fails:\n{c}");
    }
    let tally = format!("{n} of {n} claims hold", n = claims.len());
    assert!(summary.contains(&tally), "no {tally:?} in\n{summary}");
    for needle in [
        "rimless wheel, phi = 0.2, Coulomb stance, Coulomb impact: the held gait",
        "Goswami et al.'s 3-degree gait with its foot held for mu0 >= 0.28",
        "T = 0.734346 s, V = 0.729146 m/s",
        "doubles its period",
        "does the splits",
        "Painleve's paradox",
        "slides away",
        "three-link biped, level, at its defaults",
        "stable period-one gait with its foot held",
        "W_nn/|W_tn|",
        "the tanh law in stance",
        "the paper's frictionless impact: it stops only",
        "Bifurcation diagrams by continuation",
        "period doubling at phi = 0.015073100216016674 rad",
        "period one doubles at 4.3909 degrees, stable before it: true",
    ] {
        assert!(summary.contains(needle), "missing {needle:?} in\n{summary}");
    }
    assert!(!summary.contains("NaN"), "{summary}");
    // Every walk of every sweep is in the CSV: 4 laws, each chain, mu0 0 to 1 by 0.02.
    for (m, chains) in MODELS {
        let csv = std::fs::read_to_string(out.join(format!("{m}_sweep.csv"))).expect("csv");
        assert_eq!(csv.lines().count(), 1 + 4 * chains * 51, "{m}_sweep.csv");
    }
    readme_shows_the_gallery(&out, &summary);
}

/// The README's "Models as data" section shows each model's gallery figure, committed in
/// `docs/figures/` as the run draws it, and its captions quote the summary's numbers.
fn readme_shows_the_gallery(out: &std::path::Path, summary: &str) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let readme = std::fs::read_to_string(root.join("README.md")).expect("README.md");
    let section = readme
        .split_once("## Models as data")
        .and_then(|(_, s)| s.split_once("\n## "))
        .map(|(s, _)| s)
        .expect("the README's Models as data section");
    assert!(
        section.contains("gallery --out"),
        "the section names the command"
    );
    for (m, _) in MODELS {
        let figure = format!("docs/figures/{m}.svg");
        assert!(
            section.contains(&format!("]({figure})")),
            "{figure} not shown"
        );
        // The committed figure is the one the run draws (the same file, or one whose every
        // line but the numbers' last digits agree: the same marks where they are drawn).
        let committed = std::fs::read_to_string(root.join(&figure)).expect("committed figure");
        let drawn = std::fs::read_to_string(out.join(format!("{m}.svg"))).expect("drawn figure");
        assert_eq!(
            committed.lines().count(),
            drawn.lines().count(),
            "{figure} is not the figure `walker gallery` draws; copy it from its output"
        );
    }
    // The captions (the paragraphs that begin with `*The gallery`) quote the summary.
    let captions: Vec<&str> = section
        .split("\n\n")
        .filter(|p| p.starts_with("*The gallery"))
        .collect();
    assert_eq!(captions.len(), MODELS.len(), "one caption per model");
    for c in captions {
        for n in decimals(c) {
            assert!(
                summary.contains(&n),
                "a gallery caption quotes {n}, which summary.txt does not contain:\n{c}"
            );
        }
    }
}
