//! A slope per step through the built binary (`docs/floors.md`, "A slope per step"):
//! `--phi-steps` and a floor file's `phi` walk the passive wheel on each step's slope and
//! report it, `walker animate` draws each step on its slope's line, `walker survive` counts a
//! kink as a failure of its own, and a slope the walker cannot take exits 2 naming the flag,
//! the field and the range.

use std::path::PathBuf;
use std::process::{Command, Output};

fn walker(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_walker"))
        .args(args)
        .output()
        .expect("the walker binary runs")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn wheel() -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../models/rimless-wheel.toml")
        .display()
        .to_string()
}

/// A floor file with `text` in a directory of this test's own.
fn floor_file(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("walker-slope-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("the floor file is written");
    path.display().to_string()
}

/// The wheel under exact Coulomb friction with a strike that sticks.
fn held(cmd: &str) -> Vec<String> {
    [
        cmd,
        "--model",
        &wheel(),
        "--friction",
        "coulomb",
        "--impact",
        "coulomb",
        "--set",
        "mu0=0.8",
    ]
    .iter()
    .map(|s| (*s).to_owned())
    .collect()
}

fn run(base: &[String], more: &[&str]) -> Output {
    let args: Vec<&str> = base
        .iter()
        .map(String::as_str)
        .chain(more.iter().copied())
        .collect();
    walker(&args)
}

#[test]
fn phi_steps_walk_each_step_on_its_slope_and_the_json_reports_it() {
    let o = run(
        &held("simulate"),
        &["--phi-steps", "0.2,0.25,0.15", "--max-steps", "5", "--json"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let phi: Vec<f64> = v["steps"]
        .as_array()
        .expect("steps")
        .iter()
        .map(|s| s["floor"]["phi"].as_f64().expect("a slope"))
        .collect();
    assert_eq!(phi, [0.2, 0.25, 0.15, 0.15, 0.15]);
    // The same floor from a file is the same walk.
    let f = floor_file("steps.toml", "kind = \"steps\"\nphi = [0.2, 0.25, 0.15]\n");
    let by_file = run(
        &held("simulate"),
        &["--floor", &f, "--max-steps", "5", "--json"],
    );
    assert_eq!(by_file.stdout, o.stdout, "{}", stderr(&by_file));
}

#[test]
fn survive_names_a_kink_among_the_failures() {
    // The paper's frictionless strike leaves the foot sliding: the first change of slope ends
    // every walk as a kink.
    let f = floor_file(
        "random.toml",
        "kind = \"random\"\nseed = 1\n[phi]\ndistribution = \"uniform\"\nlo = 0.15\nhi = 0.25\n",
    );
    let o = walker(&[
        "survive",
        "--model",
        &wheel(),
        "--friction",
        "coulomb",
        "--impact",
        "frictionless",
        "--floor",
        &f,
        "--walks",
        "3",
        "--max-steps",
        "10",
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    assert_eq!(v["survival"]["failures_by_kind"]["slope-kink"], 3, "{v}");
}

#[test]
fn a_slope_the_walker_cannot_take_exits_2_naming_flag_field_and_range() {
    let cases: Vec<(Vec<String>, Vec<&str>, &str)> = vec![
        (
            held("simulate"),
            vec!["--phi-steps", "0.2,-0.1"],
            "invalid phi-steps: floor field `phi[1]` = -0.1: outside the range [0, pi/2) of \
             `phi` in model `rimless-wheel`",
        ),
        (
            held("simulate"),
            vec!["--phi-steps", "0.2,x"],
            "invalid phi-steps: phi[1] = \"x\": not a number",
        ),
        (
            held("simulate"),
            vec!["--phi-steps", "0.2", "--phi", "0.2"],
            "invalid phi: cannot be given with --phi-steps: each sets phi",
        ),
        (
            held("simulate"),
            vec!["--phi-steps", "0.2", "--set", "phi=0.2"],
            "invalid set: cannot be given with --phi-steps: each sets phi",
        ),
        (
            vec![
                "simulate".to_owned(),
                "--scene".to_owned(),
                "active-level".to_owned(),
            ],
            vec!["--phi-steps", "0.1"],
            "invalid phi-steps: model `paper-active` has no slope angle",
        ),
    ];
    let f = floor_file(
        "slopes.toml",
        "kind = \"random\"\nseed = 1\n[phi]\ndistribution = \"uniform\"\nlo = 0.15\nhi = 0.25\n",
    );
    for (base, more, text) in cases {
        let more: Vec<&str> = more
            .iter()
            .map(|a| if *a == "FLOOR" { f.as_str() } else { a })
            .collect();
        let o = run(&base, &more);
        assert_eq!(o.status.code(), Some(2), "{more:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(text), "{more:?}: {}", stderr(&o));
    }
}

/// The points of the broken line that opens the drawn floor's path (`M x z L x z ...`, before
/// the hatching's moves).
fn floor_line(svg: &str) -> Vec<(f64, f64)> {
    let doc = roxmltree::Document::parse(svg).expect("the SVG parses");
    let d = doc
        .descendants()
        .find(|n| {
            n.has_tag_name("path")
                && n.attribute("stroke") == Some("black")
                && n.attribute("fill") == Some("none")
        })
        .and_then(|n| n.attribute("d"))
        .expect("the floor's path");
    let line = d.split('M').nth(1).expect("a broken line");
    line.split('L')
        .map(|p| {
            let v: Vec<f64> = p
                .split_whitespace()
                .map(|x| x.parse().expect("a number"))
                .collect();
            (v[0], v[1])
        })
        .collect()
}

#[test]
fn a_walk_on_a_slope_per_step_is_drawn_on_the_line_of_each_steps_slope() {
    // The wheel on slopes 0.2, 0.25, 0.15 (then 0.15): the drawn floor breaks at the stance
    // foot of each step whose slope differs from the step before (where the simulator's floor
    // breaks), each piece at its step's slope, through the feet the simulator reports.
    let f = floor_file("drawn.toml", "kind = \"steps\"\nphi = [0.2, 0.25, 0.15]\n");
    let sim = run(
        &held("simulate"),
        &["--floor", &f, "--max-steps", "4", "--json"],
    );
    assert!(sim.status.success(), "{}", stderr(&sim));
    let v: serde_json::Value = serde_json::from_slice(&sim.stdout).expect("JSON");
    let feet: Vec<(f64, f64)> = v["steps"]
        .as_array()
        .expect("steps")
        .iter()
        .map(|s| {
            let q = &s["q_plus"];
            (q[0].as_f64().expect("x"), q[1].as_f64().expect("z"))
        })
        .collect();
    let out = std::env::temp_dir()
        .join(format!("walker-slope-cli-{}", std::process::id()))
        .join("drawn.svg");
    let o = run(
        &held("animate"),
        &[
            "--floor",
            &f,
            "--steps",
            "4",
            "-o",
            out.to_str().expect("UTF-8"),
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(&out).expect("written");
    assert!(
        svg.contains("slope phi by step from 0.15 to 0.25 rad"),
        "the title"
    );
    // Step 0 is on the wheel's own slope (0.2, through the origin); corners at the stance
    // foot of step 1 (0.25) and of step 2 (0.15). The SVG writes 4 decimals (5e-5 m).
    let line = floor_line(&svg);
    let corners = &line[1..line.len() - 1];
    let expected = [feet[0], feet[1]];
    assert_eq!(corners.len(), expected.len(), "{line:?}");
    for (c, e) in corners.iter().zip(expected) {
        assert!(
            (c.0 - e.0).abs() <= 5e-5 && (c.1 - e.1).abs() <= 5e-5,
            "{c:?} vs {e:?}"
        );
    }
    // Each piece falls at its step's slope: up to step 1's foot 0.2, from it 0.25, from step
    // 2's on (the feet of steps 3 and 4 on it) 0.15.
    let slope = |a: (f64, f64), b: (f64, f64)| (-(b.1 - a.1) / (b.0 - a.0)).atan();
    let pieces = [
        (line[0], line[1], 0.2),
        (line[1], line[2], 0.25),
        (line[2], line[3], 0.15),
    ];
    for (a, b, phi) in pieces {
        assert!((slope(a, b) - phi).abs() <= 1e-3, "{a:?} {b:?}: {phi}");
    }
    for foot in &feet[2..] {
        let z = line[2].1 - (foot.0 - line[2].0) * 0.15_f64.tan();
        assert!((foot.1 - z).abs() <= 1e-4, "{foot:?} off the last piece");
    }
    // The GIF and the stick diagram draw the same floor (they run).
    for ext in ["gif", "png"] {
        let out = out.with_extension(ext);
        let mut more = vec!["--floor", &f, "--steps", "4", "-o"];
        let p = out.to_str().expect("UTF-8").to_owned();
        more.push(&p);
        if ext == "png" {
            more.push("--strobe");
        }
        let o = run(&held("animate"), &more);
        assert!(o.status.success(), "{ext}: {}", stderr(&o));
    }
}
