//! `walker animate` through the built binary: the animated SVG parses and has one keyframe per
//! frame (and the held last one) on every moving part, its drawn walker is the simulated one
//! at the frames' times, the GIF decodes with the frames and size it claims, the stick
//! diagrams are written, and bad arguments exit with code 2 naming the flag.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use walker::model::Model;
use walker::setup::Setup;
use walker::sim::{SimConfig, Trajectory, WalkLimits, trajectory};

fn walker(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_walker"))
        .args(args)
        .output()
        .expect("the walker binary runs")
}

/// A fresh path in the test's temporary directory.
fn tmp(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("animate");
    std::fs::create_dir_all(&dir).expect("the temporary directory can be made");
    let p = dir.join(name);
    let _ = std::fs::remove_file(&p);
    p
}

/// `walker animate --json` with `args` writing `out`; its report.
fn animate(out: &Path, args: &[&str]) -> serde_json::Value {
    let mut all = vec![
        "animate",
        "--json",
        "-o",
        out.to_str().expect("a UTF-8 path"),
    ];
    all.extend_from_slice(args);
    let o = walker(&all);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).expect("stdout is JSON")
}

/// The active walker of Fig. 5 (`mu0 = 0.4`, `T_set = 0.3`, `omega0 = 0.8`), sampled as
/// `walker animate --steps 2 --fps 20` samples it (dt = 1/20 s at speed 1).
fn fig5_two_steps() -> (Model, Trajectory) {
    let m = Setup::active_level()
        .and_then(|s| s.with("mu0", 0.4)?.with("T_set", 0.3))
        .and_then(|s| Ok(s.model()?))
        .expect("the built-in scene active-level");
    let limits = WalkLimits {
        max_steps: 2,
        ..WalkLimits::default()
    };
    let start = m
        .start_state_with("omega0", 0.8)
        .expect("omega0 is a start parameter");
    let tr = trajectory(&m, &SimConfig::default(), &start, &limits, 0.05, 3000);
    (m, tr)
}

const FIG5_ARGS: [&str; 10] = [
    "--scene",
    "active-level",
    "--mu0",
    "0.4",
    "--t-set",
    "0.3",
    "--steps",
    "2",
    "--fps",
    "20",
];

/// The `values` of the animation element of `kind` animating `attr` (`type` for
/// `animateTransform`), in document order, split at `;`.
fn animations<'a>(doc: &'a roxmltree::Document<'a>, kind: &str, attr: &str) -> Vec<Vec<&'a str>> {
    doc.descendants()
        .filter(|n| n.has_tag_name(kind))
        .filter(|n| n.attribute("type") == Some(attr) || n.attribute("attributeName") == Some(attr))
        .map(|n| n.attribute("values").unwrap_or("").split(';').collect())
        .collect()
}

/// The `d` of the wheel's spokes (the dark grey path around the hub).
fn spokes_path<'a>(doc: &'a roxmltree::Document<'a>) -> &'a str {
    doc.descendants()
        .filter(|n| n.has_tag_name("path") && n.attribute("stroke") == Some("#333"))
        .find_map(|n| n.attribute("d"))
        .expect("the spokes' path")
}

/// The lines of a stick figure's links (the dark grey group).
fn link_lines<'a, 'i>(doc: &'a roxmltree::Document<'i>) -> Vec<roxmltree::Node<'a, 'i>> {
    doc.descendants()
        .find(|n| n.has_tag_name("g") && n.attribute("stroke") == Some("#333"))
        .expect("the links' group")
        .children()
        .filter(|n| n.has_tag_name("line"))
        .collect()
}

/// `walker ARGS`, which must be refused with exit code 2: its standard error.
fn refused(args: &[&str]) -> String {
    let o = walker(args);
    let err = String::from_utf8_lossy(&o.stderr).into_owned();
    assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
    err
}

/// Two numbers of an `x z` value.
fn pair(v: &str) -> (f64, f64) {
    let mut it = v.split(' ').map(|s| s.parse::<f64>().expect("a number"));
    (it.next().expect("x"), it.next().expect("z"))
}

#[test]
fn the_svg_parses_with_one_keyframe_per_frame_on_every_moving_part() {
    let out = tmp("fig5.svg");
    let report = animate(&out, &FIG5_ARGS);
    let (_, tr) = fig5_two_steps();
    let n = tr.frames.len();
    assert_eq!(report["frames"].as_u64(), Some(n as u64));
    let text = std::fs::read_to_string(&out).expect("the SVG was written");
    let doc = roxmltree::Document::parse(&text).expect("the SVG is well-formed XML");
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    // Moving parts: the camera (the walk of two steps fits the picture, so it stands still),
    // the hub, the wheel's rotation, the torso's rotation, the foot; the two force arrows' tips.
    let translates = animations(&doc, "animateTransform", "translate");
    let rotates = animations(&doc, "animateTransform", "rotate");
    assert_eq!((translates.len(), rotates.len()), (2, 2));
    let tips = [
        animations(&doc, "animate", "x2"),
        animations(&doc, "animate", "y2"),
    ];
    // `x2` also grows the slip marks: one per stance foot of the frames.
    let feet = 1 + tr.frames.last().map_or(0, |f| f.step);
    assert_eq!(tips[0].len(), 2 + feet);
    assert_eq!(tips[1].len(), 2);
    for v in translates.iter().chain(&rotates).chain(&tips[1]) {
        // One keyframe a frame, and the last repeated for the hold at the end.
        assert_eq!(v.len(), n + 1);
        assert_eq!(v[n], v[n - 1]);
    }
    // All twelve spokes of alpha = pi/6 (Table 1) are drawn.
    let spokes = spokes_path(&doc);
    assert_eq!(spokes.matches("M0 0L").count(), 12);
}

/// The drawn walker at each frame is the simulated one at that frame's time: the drawn foot is
/// the state's `(x, z)`, the drawn hub is `(x + l sin th1, z + l cos th1)`, the drawn stance
/// spoke ends at the foot and the drawn fore spoke (the hub's translation and the wheel's
/// rotation applied to the spoke) at the fore foot of the model's `points` kernel (the point
/// `fore_foot` of `models/paper-active.toml`). The SVG writes metres and degrees with 4 decimals
/// (rounding by at most 5e-5); a point built from the rounded hub, the rounded spoke end and
/// the rounded angle (5e-5 deg is 9e-7 rad, times l = 1) is within 1.1e-4 of the exact one, so
/// 2e-4 bounds the difference while a frame off by one (dt = 0.05 s at about 0.5 m/s, 2.5 cm)
/// would fail.
#[test]
fn the_drawn_foot_hub_and_fore_foot_are_the_simulated_ones_at_the_frame_times() {
    let out = tmp("fig5_positions.svg");
    animate(&out, &FIG5_ARGS);
    let (model, tr) = fig5_two_steps();
    let text = std::fs::read_to_string(&out).expect("the SVG was written");
    let doc = roxmltree::Document::parse(&text).expect("the SVG is well-formed XML");
    let translates = animations(&doc, "animateTransform", "translate");
    let rotates = animations(&doc, "animateTransform", "rotate");
    let (hubs, feet, wheel) = (&translates[0], &translates[1], &rotates[0]);
    let spokes = spokes_path(&doc);
    // The spokes in the wheel's own frame, `M0 0L x z` each; the wheel turns on by one spoke a
    // step, so the fore leg of step `s` is spoke `s + 1` of the drawing.
    let body: Vec<(f64, f64)> = spokes.split("M0 0L").skip(1).map(pair).collect();
    let fore = model
        .spec()
        .points()
        .position(|p| p == "fore_foot")
        .expect("the model has a fore foot");
    let mut points = vec![0.0; 2 * model.spec().points().count()];
    let tol = 2e-4;
    for (i, f) in tr.frames.iter().enumerate() {
        let (x, z, th1) = (f.state[0], f.state[1], f.state[2]);
        let foot = pair(feet[i]);
        assert!(
            (foot.0 - x).abs() < tol && (foot.1 - z).abs() < tol,
            "frame {i}"
        );
        let hub = pair(hubs[i]);
        assert!((hub.0 - (x + th1.sin())).abs() < tol, "frame {i}");
        assert!((hub.1 - (z + th1.cos())).abs() < tol, "frame {i}");
        let a = wheel[i].parse::<f64>().expect("an angle").to_radians();
        let end = |k: usize| {
            let p = body[k % body.len()];
            (
                hub.0 + a.cos() * p.0 - a.sin() * p.1,
                hub.1 + a.sin() * p.0 + a.cos() * p.1,
            )
        };
        let stance = end(f.step);
        assert!(
            (stance.0 - x).abs() < tol && (stance.1 - z).abs() < tol,
            "frame {i}"
        );
        let drawn = end(f.step + 1);
        model.points(&f.state[..4], &mut points);
        let ff = [points[2 * fore], points[2 * fore + 1]];
        assert!((drawn.0 - ff[0]).abs() < tol, "frame {i}: {drawn:?} {ff:?}");
        assert!((drawn.1 - ff[1]).abs() < tol, "frame {i}: {drawn:?} {ff:?}");
    }
}

#[test]
fn the_gif_decodes_with_the_frames_and_size_it_reports() {
    let out = tmp("fig5.gif");
    let report = animate(&out, &FIG5_ARGS);
    let (_, tr) = fig5_two_steps();
    let file = std::fs::File::open(&out).expect("the GIF was written");
    let mut opts = gif::DecodeOptions::new();
    opts.set_color_output(gif::ColorOutput::Indexed);
    let mut dec = opts.read_info(file).expect("a GIF header");
    assert_eq!((dec.width(), dec.height()), (640, 360));
    let mut frames = 0;
    let mut centiseconds = 0u32;
    while let Some(f) = dec.read_next_frame().expect("a frame decodes") {
        assert_eq!((f.width, f.height), (640, 360));
        centiseconds += u32::from(f.delay);
        frames += 1;
    }
    assert_eq!(frames, tr.frames.len());
    assert_eq!(report["frames"].as_u64(), Some(frames as u64));
    // The delays add up to the playback time: (frames - 1) / fps and the 1 s hold, to the
    // centisecond the GIF counts in (the rounding is carried, not accumulated).
    let playback = (frames - 1) as f64 / 20.0 + 1.0;
    assert!((f64::from(centiseconds) / 100.0 - playback).abs() <= 0.005 + 1e-9);
}

#[test]
fn the_stick_diagrams_are_written_as_svg_and_png() {
    let png = tmp("fig14.png");
    let args = [
        "--scene",
        "passive-slope",
        "--mu0",
        "0.19",
        "--phi",
        "0.1",
        "--strobe",
    ];
    let report = animate(&png, &args);
    // Fig. 14 falls backward after the first impact (Section 5.3).
    assert_eq!(report["steps"].as_u64(), Some(1));
    assert!(
        report["failure"]
            .as_str()
            .is_some_and(|f| f.starts_with("fell-backward"))
    );
    let bytes = std::fs::read(&png).expect("the PNG was written");
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    let svg = tmp("fig14.svg");
    let report = animate(&svg, &args);
    let text = std::fs::read_to_string(&svg).expect("the SVG was written");
    let doc = roxmltree::Document::parse(&text).expect("the SVG is well-formed XML");
    // One path a pose (stance, fore and rear legs, torso) besides the floor.
    let poses = doc.descendants().filter(|n| n.has_tag_name("path")).count() - 1;
    assert_eq!(Some(poses as u64), report["frames"].as_u64());
    assert!(text.contains("fell-backward"));
}

/// Each bad argument exits with code 2 and a message naming its flag.
#[test]
fn bad_arguments_exit_2_naming_the_flag() {
    let svg = tmp("bad.svg");
    let svg = svg.to_str().expect("a UTF-8 path");
    let cases: [(&[&str], &str); 11] = [
        (&["--fps", "0"], "fps"),
        (&["--fps", "51"], "fps"),
        (&["--speed", "1000"], "speed"),
        (&["--speed", "nan"], "speed"),
        (&["--steps", "0"], "steps"),
        (&["--steps", "1001"], "steps"),
        (&["--duration", "-1"], "duration"),
        (&["--duration", "600", "--fps", "50"], "duration"),
        (&["--steps", "3", "--duration", "2"], "duration"),
        (&["--omega0", "inf"], "omega0"),
        (&["--mu0", "-1"], "mu0"),
    ];
    for (extra, flag) in cases {
        let mut args = vec!["animate", "--scene", "active-level", "-o", svg];
        args.extend_from_slice(extra);
        let err = refused(&args);
        assert!(err.contains(flag), "{extra:?}: {err}");
    }
    // The output's kind, and a walk too long for the frames a GIF may have.
    let err = refused(&["animate", "--scene", "active-level", "-o", "walk.txt"]);
    assert!(err.contains("output"), "{err}");
    let gif = tmp("long.gif");
    let err = refused(&[
        "animate",
        "--scene",
        "active-level",
        "--steps",
        "200",
        "--fps",
        "50",
        "-o",
        gif.to_str().expect("a UTF-8 path"),
    ]);
    assert!(err.contains("steps") && err.contains("600 frames"), "{err}");
    assert!(!gif.exists());
}

/// `walker reproduce` adds the animations of Fig. 5's gait and Fig. 14's fall, and the stick
/// diagram of the fall (its other outputs are tested in `reproduce_cli.rs`).
#[test]
fn reproduce_writes_the_animations_of_figs_5_and_14() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("animate_reproduce");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("the directory can be made");
    walker_cli::reproduce::animations::write_animations(&dir).expect("the animations are written");
    for name in [
        "fig5_animation.svg",
        "fig5_animation.gif",
        "fig14_animation.svg",
        "fig14_animation.gif",
        "fig14_strobe.svg",
        "fig14_strobe.png",
    ] {
        let len = std::fs::metadata(dir.join(name)).map_or(0, |m| m.len());
        assert!(len > 1000, "{name}: {len} bytes");
    }
    let fall = std::fs::read_to_string(dir.join("fig14_animation.svg")).expect("written");
    assert!(fall.contains("fell-backward in step 2"));
}

/// A walk that fails at once (`omega0 = 100` lifts the foot off at the start) is still drawn:
/// one frame, the failure's, with its name.
#[test]
fn a_walk_failing_at_its_start_is_drawn_as_its_failure() {
    let out = tmp("lift_off.svg");
    let report = animate(&out, &["--scene", "active-level", "--omega0", "100"]);
    assert_eq!(report["frames"].as_u64(), Some(1));
    assert!(
        report["failure"]
            .as_str()
            .is_some_and(|f| f.starts_with("lift-off"))
    );
    let text = std::fs::read_to_string(&out).expect("the SVG was written");
    let doc = roxmltree::Document::parse(&text).expect("the SVG is well-formed XML");
    for v in animations(&doc, "animateTransform", "translate") {
        assert_eq!(v.len(), 2);
    }
    assert!(text.contains("lift-off in step 1"));
}

/// `--mu0-steps` draws the floor as one patch per drawn step, in the list's order with its
/// last value after the list, the icy ones in another colour than the dry; the walk is the
/// one `walker simulate --mu0-steps` walks (the same number of steps), and the title gives
/// the range of `mu0` instead of the model's own value.
#[test]
fn a_floor_is_drawn_as_a_patch_per_step_with_its_mu0() {
    let out = tmp("floor.svg");
    let list = "0.4,0.4,0.05,0.05,0.4";
    let common = [
        "--scene",
        "active-level",
        "--t-set",
        "0.3",
        "--mu0-steps",
        list,
    ];
    let report = animate(&out, &[&common[..], &["--steps", "7"]].concat());
    assert_eq!(report["steps"], 7, "{report}");
    let svg = std::fs::read_to_string(&out).expect("the SVG is written");
    let doc = roxmltree::Document::parse(&svg).expect("the SVG parses");
    let patches: Vec<(String, String)> = doc
        .descendants()
        .filter(|n| n.attribute("class") == Some("floor-patch"))
        .map(|n| {
            let title = n
                .children()
                .find(|c| c.has_tag_name("title"))
                .and_then(|t| t.text())
                .unwrap_or_default();
            (
                title.to_owned(),
                n.attribute("stroke").unwrap_or_default().to_owned(),
            )
        })
        .collect();
    let expected = ["0.4", "0.4", "0.05", "0.05", "0.4", "0.4", "0.4"];
    assert_eq!(patches.len(), expected.len(), "{patches:?}");
    for (k, ((title, _), mu0)) in patches.iter().zip(expected).enumerate() {
        assert_eq!(title, &format!("step {}: mu0 = {mu0}", k + 1));
    }
    assert_eq!(patches[0].1, patches[1].1);
    assert_ne!(
        patches[1].1, patches[2].1,
        "icy and dry patches share a colour"
    );
    assert!(
        svg.contains("mu0 by step from 0.05 (blue) to 0.4 (brown)") && !svg.contains("mu0 = 0.4,"),
        "the title gives the floor's range"
    );
    let sim = walker(&[&["simulate", "--json", "--max-steps", "7"], &common[..]].concat());
    assert!(
        sim.status.success(),
        "{}",
        String::from_utf8_lossy(&sim.stderr)
    );
    let walk: serde_json::Value = serde_json::from_slice(&sim.stdout).expect("JSON");
    assert_eq!(walk["steps"].as_array().map(Vec::len), Some(7));
    let clash = walker(&[&["animate", "-o", "x.svg", "--mu0", "0.3"], &common[..]].concat());
    assert_eq!(clash.status.code(), Some(2));
}

#[test]
fn a_biped_is_drawn_as_the_links_of_its_points_at_the_simulated_positions() {
    // The three-link biped (`models/three-link.toml`: points hip, torso, swing_foot): its links
    // are read from its geometry (stance foot - hip, hip - torso, hip - swing foot; the stance
    // foot and the swing foot are not on one link), each a line whose ends move with the walk.
    use walker_cli::animate::sticks::Sticks;
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../models/three-link.toml");
    let setup = Setup::from_model_file(&path, &Default::default(), None).expect("compiled");
    let model = setup.model().expect("the model");
    let sticks = Sticks::of(&model).expect("a stick figure");
    assert_eq!(sticks.links, [(0, 1), (1, 2), (1, 3)]);

    let out = tmp("three-link.svg");
    let report = animate(
        &out,
        &[
            "--model",
            path.to_str().expect("UTF-8"),
            "--steps",
            "2",
            "--fps",
            "20",
        ],
    );
    let frames = report["frames"].as_u64().expect("frames") as usize;
    let text = std::fs::read_to_string(&out).expect("written");
    let doc = roxmltree::Document::parse(&text).expect("the SVG parses");
    // Three lines (the group of the links) whose four ends each have one keyframe per frame
    // and the held last one.
    let lines = link_lines(&doc);
    assert_eq!(lines.len(), 3);
    let keyed = |line: &roxmltree::Node<'_, '_>, attr: &str| -> Vec<f64> {
        line.children()
            .find(|n| n.attribute("attributeName") == Some(attr))
            .and_then(|n| n.attribute("values"))
            .expect("animated")
            .split(';')
            .map(|v| v.parse().expect("a number"))
            .collect()
    };
    for line in &lines {
        for attr in ["x1", "y1", "x2", "y2"] {
            assert_eq!(keyed(line, attr).len(), frames + 1, "{attr}");
        }
    }
    // The hip, the first end of the links from it, at frame 0 is the model's `hip` point at
    // the start (the SVG writes 4 decimals: to 5e-5 m).
    let hips: Vec<(f64, f64)> = lines[1..]
        .iter()
        .map(|l| (keyed(l, "x1")[0], keyed(l, "y1")[0]))
        .collect();
    let q = model.start_state();
    let mut p = [0.0; 6];
    model.points(&q.as_slice()[..model.n()], &mut p);
    for h in hips {
        assert!(
            (h.0 - p[0]).abs() <= 5e-5 && (h.1 - p[1]).abs() <= 5e-5,
            "{h:?} vs {p:?}"
        );
    }
}

#[test]
fn a_users_own_model_file_is_drawn_from_its_points_or_refused_naming_the_model() {
    // A model file of the user's own (the compass gait renamed, derived at run time), with a
    // knee point added half way down the swing leg: its links are read from its geometry as
    // for the shipped bipeds (stance foot - hip; hip - swing foot, hip - knee and knee - swing
    // foot, each turning with the swing leg's angle alone).
    let shipped = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../models/compass-gait.toml"),
    )
    .expect("the shipped model");
    let own = shipped.replacen("name = \"compass-gait\"", "name = \"my-walker\"", 1);
    let hip = "[[point]]\nname = \"hip\"\nat = [\"x + (a + b)*sin(th_st)\", \"z + (a + b)*cos(th_st)\"]\n";
    let swing = "[[point]]\nname = \"swing_foot\"\n";
    assert!(
        own.contains(hip) && own.contains(swing),
        "the points' text changed"
    );
    let knee = "[[point]]\nname = \"swing_knee\"\nat = [\"x + (a + b)*sin(th_st) - 0.5*(a + b)*sin(th_sw)\", \"z + (a + b)*cos(th_st) - 0.5*(a + b)*cos(th_sw)\"]\n";
    let kneed = own.replacen(swing, &format!("{knee}{swing}"), 1);
    let file = tmp("my-walker.toml");
    std::fs::write(&file, &kneed).expect("written");
    let setup = Setup::from_model_file(
        &file,
        &Default::default(),
        Some(&walker_load::runtime_source()),
    )
    .expect("derived at run time");
    let model = setup.model().expect("the model");
    let sticks = walker_cli::animate::sticks::Sticks::of(&model).expect("a stick figure");
    // Drawn points: 0 the stance foot, 1 hip, 2 swing_knee, 3 swing_foot.
    assert_eq!(sticks.links, [(0, 1), (1, 2), (1, 3), (2, 3)]);
    let out = tmp("my-walker.svg");
    let report = animate(
        &out,
        &["--model", file.to_str().expect("UTF-8"), "--steps", "1"],
    );
    assert!(report["frames"].as_u64().expect("frames") > 1, "{report}");
    let text = std::fs::read_to_string(&out).expect("written");
    let doc = roxmltree::Document::parse(&text).expect("the SVG parses");
    assert_eq!(link_lines(&doc).len(), 4);

    // Without its hip (and the fall that names it) the one point left, the swing foot, lies
    // on no link with the stance foot (their vector turns with both legs): nothing to draw,
    // refused with exit 2 naming the model, and no file written.
    let fall =
        "[[fall]]\nname = \"hip-down\"\npoint = \"hip\"\ndoc = \"the hip touched the floor\"\n";
    assert!(own.contains(fall), "the fall's text changed");
    let bare = own.replacen(hip, "", 1).replacen(fall, "", 1);
    let file = tmp("my-bare-walker.toml");
    std::fs::write(&file, &bare).expect("written");
    let out = tmp("my-bare-walker.svg");
    let err = refused(&[
        "animate",
        "--model",
        file.to_str().expect("UTF-8"),
        "--steps",
        "1",
        "-o",
        out.to_str().expect("UTF-8"),
    ]);
    assert!(
        err.contains("invalid model: model `my-walker` has no drawing"),
        "{err}"
    );
    assert!(!out.exists());
}
