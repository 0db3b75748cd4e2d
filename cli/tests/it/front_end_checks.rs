//! What issue 35 left open at the command line, each a property of the `walker` binary:
//! a start moved off the floor by `--init` is refused as Python and a model's `[start]`
//! refuse it (the library's request layer, shared by both front ends); a bad value inside a
//! scene file names the file, the line, the field and its range; a number flag given text
//! that is not a number names the flag and its range. Each refusal is exit code 2 with no
//! output and no panic.

use std::process::{Command, Output, Stdio};

fn walker(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_walker"))
        .args(args)
        .stdin(Stdio::null())
        .output()
        .expect("the binary runs")
}

/// `args` is refused with exit code 2, no output and no panic; its message.
fn refused(args: &[&str]) -> String {
    let o = walker(args);
    let stderr = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(o.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    assert!(o.stdout.is_empty(), "{args:?}: output of a refused request");
    stderr
}

fn models() -> std::path::PathBuf {
    std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../models")
}

#[test]
fn a_start_moved_off_the_floor_by_init_is_refused_naming_the_component() {
    let e = refused(&["simulate", "--scene", "active-level", "--init", "z=1000"]);
    assert!(e.contains("invalid init:"), "{e}");
    assert!(
        e.contains("the stance foot (x = 0, z = 1000) must be on the floor (z = 0)"),
        "{e}"
    );
    let e = refused(&["simulate", "--scene", "active-level", "--init", "zd=1"]);
    assert!(e.contains("must be along the floor"), "{e}");
    // On the slope the floor is z = -x tan(phi): x alone moves the foot off it.
    let e = refused(&["simulate", "--scene", "passive-slope", "--init", "x=1"]);
    assert!(e.contains("-x tan(phi)"), "{e}");
}

#[test]
fn a_start_on_the_floor_given_by_init_walks() {
    let o = walker(&[
        "simulate",
        "--scene",
        "active-level",
        "--init",
        "z=0",
        "--max-steps",
        "1",
        "--json",
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}

#[test]
fn a_bad_value_inside_a_scene_file_names_the_file_the_line_the_field_and_the_range() {
    let dir = std::env::temp_dir().join(format!("walker-scene-values-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let model = models().join("compass-gait.toml");
    let scene = dir.join("steep.toml");
    let text = format!(
        "model = {:?}\n\n[set]\nphi = 5.0\n",
        model.display().to_string()
    );
    std::fs::write(&scene, text).expect("a scene file");
    let path = scene.display().to_string();
    let e = refused(&["simulate", "--scene", &path, "--max-steps", "1"]);
    assert!(e.contains(&path), "the file is not named: {e}");
    assert!(e.contains("line 4, column 7"), "the line is not named: {e}");
    assert!(
        e.contains("set.phi = 5: expected a value in ["),
        "field or range: {e}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_number_flag_given_text_names_the_flag_and_its_range() {
    for (args, flag, range) in [
        (
            &["simulate", "--scene", "active-level", "--mu0", "abc"][..],
            "--mu0",
            ">= 0",
        ),
        (
            &["simulate", "--scene", "active-level", "--rtol", "x"][..],
            "--rtol",
            "[2.2e-15, 1)",
        ),
        (
            &["simulate", "--scene", "active-level", "--duration", "1s"][..],
            "--duration",
            "(0, 1e9]",
        ),
        (
            &[
                "sweep",
                "--scene",
                "active-level",
                "--from",
                "a",
                "--to",
                "1",
                "--step",
                "0.1",
            ][..],
            "--from",
            "a finite number",
        ),
        (
            &[
                "continue",
                "--scene",
                "passive-slope",
                "--param",
                "phi",
                "--from",
                "0.1",
                "--to",
                "0.2",
                "--max-step",
                "big",
            ][..],
            "--max-step",
            "(0, 1]",
        ),
        (
            &[
                "animate",
                "--scene",
                "active-level",
                "-o",
                "x.svg",
                "--fps",
                "many",
            ][..],
            "--fps",
            "[1, 50]",
        ),
    ] {
        let e = refused(args);
        assert!(e.contains(flag), "{args:?}: the flag is not named: {e}");
        assert!(e.contains("not a number"), "{args:?}: {e}");
        assert!(e.contains(range), "{args:?}: the range is not named: {e}");
    }
}
