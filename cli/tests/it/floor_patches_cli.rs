//! `walker simulate | animate | survive | mfpt --floor` on a floor of patches by position,
//! through the built binary: each step's record carries its floor (the `mu0` at its start,
//! the strike's, the boundaries crossed), the animation draws the patches, `survive` walks
//! the one deterministic walk, `mfpt` refuses by name, and every bad file exits 2 naming the
//! file, line, column and field.

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

/// A floor file with `text` in a directory of this test's own.
fn floor_file(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("walker-patches-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("the floor file is written");
    path
}

const ICE: &str = "kind = \"patches\"\nmu0 = 0.4\n[[patch]]\nfrom = 2.0\nto = 2.6\nmu0 = 0.05\n";

#[test]
fn simulate_reports_each_steps_floor_on_an_ice_patch_in_json_and_in_the_table() {
    let f = floor_file("ice.toml", ICE).display().to_string();
    let args = [
        "simulate",
        "--scene",
        "active-level",
        "--t-set",
        "0.3",
        "--floor",
        &f,
        "--max-steps",
        "10",
    ];
    let o = walker(&[&args[..], &["--json"]].concat());
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let steps = v["steps"].as_array().expect("steps");
    assert_eq!(steps.len(), 10);
    // Each step starts where the last one's strike landed, on that patch.
    for pair in steps.windows(2) {
        assert_eq!(pair[1]["floor"]["mu0"], pair[0]["floor"]["mu0_strike"]);
    }
    let icy = steps.iter().filter(|s| s["floor"]["mu0"] == 0.05).count();
    assert!(icy >= 1, "some step stands on the ice");
    assert!(steps.iter().all(|s| s["floor"]["crossings"].is_u64()));
    // Under the tanh law the walker's foot slides back across the ice's far edge.
    assert!(
        steps
            .iter()
            .any(|s| s["floor"]["crossings"].as_u64() > Some(0))
    );
    let table = walker(&args);
    let text = String::from_utf8_lossy(&table.stdout);
    assert!(text.contains("mu0 mu0_strike  crossings"), "{text}");
}

#[test]
fn animate_draws_the_patches_in_view_as_bands_with_their_friction() {
    let f = floor_file("ice-animate.toml", ICE).display().to_string();
    let out = std::env::temp_dir().join(format!("walker-patches-{}.svg", std::process::id()));
    let o = walker(&[
        "animate",
        "--scene",
        "active-level",
        "--t-set",
        "0.3",
        "--floor",
        &f,
        "--steps",
        "8",
        "-o",
        &out.display().to_string(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(&out).expect("the SVG");
    assert!(svg.contains("<title>2 m to 2.6 m: mu0 = 0.05</title>"));
    assert!(svg.contains("mu0 by position from 0.05 (blue) to 0.4 (brown)"));
    assert_eq!(svg.matches("class=\"floor-patch\"").count(), 3);
    std::fs::remove_file(&out).ok();
}

#[test]
fn survive_walks_the_one_walk_of_a_patches_floor_and_mfpt_refuses_it_by_name() {
    let f = floor_file("ice-survive.toml", ICE).display().to_string();
    let common = ["--scene", "active-level", "--t-set", "0.2", "--floor", &f];
    let o = walker(
        &[
            &["survive"],
            &common[..],
            &["--walks", "4", "--max-steps", "20", "--json"],
        ]
        .concat(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    let outcomes = v["outcomes"].as_array().expect("outcomes");
    assert_eq!(outcomes.len(), 4);
    // T_set = 0.2 lifts off on the ice (Fig. 8: below mu0 = 0.46): every walk, the same step.
    let simulate = walker(&[&["simulate"], &common[..], &["--max-steps", "20", "--json"]].concat());
    let w: serde_json::Value = serde_json::from_slice(&simulate.stdout).expect("JSON");
    assert_eq!(w["failure"]["kind"], "LiftOff", "{w}");
    for (i, out) in outcomes.iter().enumerate() {
        assert_eq!(out["walk"], i);
        assert_eq!(out["steps"], w["steps"].as_array().expect("steps").len());
        assert_eq!(out["failure"], "lift-off");
    }
    let o = walker(&[&["mfpt"], &common[..]].concat());
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("a `patches` floor gives mu0 by position, not per step"));
}

#[test]
fn every_bad_patches_file_exits_2_naming_the_place_and_the_field() {
    let head = "kind = \"patches\"\nmu0 = 0.4\n";
    let one = |from: &str, to: &str, mu0: &str| {
        format!("{head}[[patch]]\nfrom = {from}\nto = {to}\nmu0 = {mu0}\n")
    };
    let cases = [
        (
            "kind = \"patches\"\n[[patch]]\nfrom = 1.0\nto = 2.0\nmu0 = 0.1\n".to_owned(),
            ":1:1: field `mu0`: missing",
        ),
        (head.to_owned(), ":1:1: field `patch`: missing"),
        (
            format!("{head}patch = []\n"),
            ":3:9: field `patch`: 0 patches: must list 1 to 10000",
        ),
        (
            "kind = \"patches\"\nmu0 = -0.4\n[[patch]]\nfrom = 1.0\nto = 2.0\nmu0 = 0.1\n"
                .to_owned(),
            ":2:7: field `mu0`: -0.4: must be > 0 and finite",
        ),
        (
            one("1.0", "1.0", "0.1"),
            ":5:6: field `patch[0].to`: 1: must be > patch[0].from = 1",
        ),
        (
            one("nan", "1.0", "0.1"),
            ":4:8: field `patch[0].from`: NaN: must be finite",
        ),
        (
            one("1.0", "inf", "0.1"),
            ":5:6: field `patch[0].to`: inf: must be finite",
        ),
        (
            one("1.0", "2e9", "0.1"),
            ":5:6: field `patch[0].to`: 2000000000: must be finite, in",
        ),
        (
            one("1.0", "2.0", "0"),
            ":6:7: field `patch[0].mu0`: 0: must be > 0 and finite",
        ),
        (
            format!("{head}[[patch]]\nto = 2.0\nmu0 = 0.1\n"),
            ":3:1: field `patch[0].from`: missing",
        ),
        (
            format!("{head}[[patch]]\nfrom = 1.0\nmu0 = 0.1\n"),
            ":3:1: field `patch[0].to`: missing",
        ),
        (
            format!("{head}[[patch]]\nfrom = 1.0\nto = 2.0\n"),
            ":3:1: field `patch[0].mu0`: missing",
        ),
        (
            format!(
                "{}[[patch]]\nfrom = 1.5\nto = 3.0\nmu0 = 0.2\n",
                one("1.0", "2.0", "0.1")
            ),
            ":8:8: field `patch[1].from`: 1.5: must be >= patch[0].to = 2 (patches are listed in \
             order along the floor and do not overlap)",
        ),
        (
            format!(
                "{}[[patch]]\nfrom = 0.5\nto = 0.8\nmu0 = 0.2\n",
                one("1.0", "2.0", "0.1")
            ),
            ":8:8: field `patch[1].from`: 0.5: must be >= patch[0].to = 2",
        ),
        (
            format!("{}width = 3\n", one("1.0", "2.0", "0.1")),
            ":7:1: field `width`: unknown field `width`",
        ),
        (
            format!(
                "kind = \"patches\"\nmu0 = 0.4\nphi = 0.1\n{}",
                &one("1.0", "2.0", "0.1")[head.len()..]
            ),
            ":3:7: field `phi`: a patches floor sets the friction only",
        ),
        (
            one("\"a\"", "2.0", "0.1"),
            ":4:8: field `from`: invalid type: string \"a\"",
        ),
    ];
    for (i, (text, expected)) in cases.iter().enumerate() {
        let f = floor_file(&format!("bad-{i}.toml"), text);
        let shown = f.display().to_string();
        let o = walker(&[
            "simulate",
            "--scene",
            "active-level",
            "--floor",
            &shown,
            "--max-steps",
            "2",
        ]);
        assert_eq!(o.status.code(), Some(2), "{text}");
        let e = stderr(&o);
        assert!(
            e.contains(&format!("invalid floor: {shown}{expected}")),
            "{text}: {e}"
        );
    }
    // A floor of patches meets the walker as the other kinds do: a friction law that
    // ignores mu0 is refused by name.
    let f = floor_file("none.toml", &one("1.0", "2.0", "0.1"))
        .display()
        .to_string();
    let o = walker(&[
        "simulate",
        "--scene",
        "active-level",
        "--friction",
        "none",
        "--floor",
        &f,
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("the friction law is `none`"),
        "{}",
        stderr(&o)
    );
}
