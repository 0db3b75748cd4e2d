//! The validation layer's regressions: each class of input that used to load and then end a
//! walk wrongly (or run without bound) is refused at load, with the kind, the file's line and
//! column of the field, and a message that names the field and what was expected. The inputs
//! are edits of the shipped models, as the issue that found them made them.

use std::path::Path;
use std::time::{Duration, Instant};

use walker_scene::limits::{MAX_COORDINATES, MAX_FALLS, MAX_FILE_BYTES, MAX_POINTS};
use walker_scene::model::{Model, ModelError, ModelErrorKind};
use walker_scene::{ModelSceneFile, Scene};

const COMPASS: &str = include_str!("../../../models/compass-gait.toml");
const ACTIVE: &str = include_str!("../../../models/paper-active.toml");
const RIMLESS: &str = include_str!("../../../models/rimless-wheel.toml");

/// How long a refusal may take. The checks are linear in the file and run in microseconds to a
/// few milliseconds; a second leaves room for a loaded machine and a debug build while still
/// telling them from the 20 s the unbounded cases took.
const PROMPT: Duration = Duration::from_secs(1);

/// `base` with `from` replaced by `to`, exactly once.
fn edit(base: &str, from: &str, to: &str) -> String {
    assert_eq!(base.matches(from).count(), 1, "`{from}` must occur once");
    base.replacen(from, to, 1)
}

/// The 1-based line and column of the first occurrence of `needle` in `text` (columns in
/// characters).
fn place(text: &str, needle: &str) -> (usize, usize) {
    let at = text.find(needle).expect("the needle is in the text");
    let before = &text[..at];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// Asserts that `text` is refused with `kind` at the place of `needle` (plus `shift` columns),
/// with a message containing every one of `fragments`.
fn assert_refused(
    text: &str,
    kind: ModelErrorKind,
    needle: &str,
    shift: usize,
    fragments: &[&str],
) {
    let (line, column) = place(text, needle);
    let started = Instant::now();
    let result = Model::from_toml(text, "edit.toml");
    assert!(started.elapsed() < PROMPT, "took {:?}", started.elapsed());
    assert!(
        result.is_err(),
        "accepted; expected {kind:?} at {line}:{}",
        column + shift
    );
    let Err(err) = result else { return };
    let message = err.to_string();
    assert_eq!(err.kind(), Some(kind), "{message}");
    assert!(
        message.starts_with(&format!("edit.toml:{line}:{}: ", column + shift)),
        "wrong place (expected {line}:{}): {message}",
        column + shift
    );
    for f in fragments {
        assert!(message.contains(f), "`{message}` lacks `{f}`");
    }
}

#[test]
fn every_shipped_model_and_scene_loads() -> Result<(), Box<dyn std::error::Error>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut models = 0;
    for entry in std::fs::read_dir(root.join("models"))? {
        let path = entry?.path();
        if path.extension().is_some_and(|e| e == "toml") {
            Model::from_file(&path)?;
            models += 1;
        }
    }
    Model::from_file(&root.join("examples/own-walker/hopper.toml"))?;
    let mut scenes = 0;
    for entry in std::fs::read_dir(root.join("models/scenes"))? {
        let path = entry?.path();
        if walker_scene::is_model_scene(&path) {
            ModelSceneFile::from_file(&path)?;
        } else {
            Scene::from_file(&path)?;
        }
        scenes += 1;
    }
    assert!(
        models >= 6 && scenes >= 3,
        "{models} models, {scenes} scenes"
    );
    Ok(())
}

#[test]
fn a_negative_mass_is_refused_naming_the_body() {
    let text = COMPASS.replacen("mass = \"m\"", "mass = \"-m\"", 1);
    assert_refused(
        &text,
        ModelErrorKind::Physics,
        "-m\"",
        0,
        &["body `stance_leg` mass", "-5", "a mass > 0"],
    );
}

#[test]
fn a_mass_parameter_whose_range_admits_zero_is_refused() {
    let text = edit(
        COMPASS,
        "doc = \"hip mass, a point\"\nrange = \"(0, inf)\"",
        "doc = \"hip mass, a point\"\nrange = \"[0, inf)\"",
    );
    assert_refused(
        &text,
        ModelErrorKind::Physics,
        "m_H\"\ncom",
        0,
        &["body `hip` mass", "m_H in [0, inf)", "not shown positive"],
    );
}

#[test]
fn a_mass_that_depends_on_a_coordinate_is_refused_at_the_coordinate() {
    let text = edit(COMPASS, "mass = \"m_H\"", "mass = \"m_H*(2 + sin(th_st))\"");
    assert_refused(
        &text,
        ModelErrorKind::SymbolNotAllowed,
        "th_st))\"",
        0,
        &[
            "body `hip` mass",
            "`th_st` is a coordinate",
            "parameters and numbers only",
        ],
    );
}

#[test]
fn a_negative_inertia_is_refused_naming_the_body() {
    let text = edit(RIMLESS, "inertia = \"m*rg^2\"", "inertia = \"-m*rg^2\"");
    assert_refused(
        &text,
        ModelErrorKind::Physics,
        "-m*rg^2",
        0,
        &["body `wheel` inertia", "a moment of inertia > 0"],
    );
}

#[test]
fn a_velocity_in_a_guard_is_refused_at_the_velocity() {
    let text = edit(
        COMPASS,
        "guard = \"2*phi - th_st - th_sw\"",
        "guard = \"2*phi - th_st - th_sw + th_std\"",
    );
    assert_refused(
        &text,
        ModelErrorKind::SymbolNotAllowed,
        "th_std\"",
        0,
        &[
            "strike guard",
            "`th_std` is",
            "expected a coordinate or a parameter",
        ],
    );
}

#[test]
fn a_strike_guard_that_is_zero_everywhere_is_refused() {
    let text = edit(
        COMPASS,
        "guard = \"2*phi - th_st - th_sw\"",
        "guard = \"(th_st - th_sw)^2 - th_st^2 - th_sw^2 + 2*th_st*th_sw\"",
    );
    assert_refused(
        &text,
        ModelErrorKind::Physics,
        "(th_st - th_sw)^2",
        0,
        &["strike guard", "zero at every configuration"],
    );
}

#[test]
fn a_guard_without_a_coordinate_is_refused() {
    let text = edit(
        COMPASS,
        "guard = \"2*phi - th_st - th_sw\"",
        "guard = \"phi\"",
    );
    assert_refused(
        &text,
        ModelErrorKind::Physics,
        "phi\"\nahead",
        0,
        &["strike guard", "has no coordinate"],
    );
}

#[test]
fn a_start_above_the_floor_is_refused_at_its_height() {
    let text = edit(
        COMPASS,
        "[start]\nth_st = \"-0.218669\"",
        "[start]\nz = \"1\"\nth_st = \"-0.218669\"",
    );
    assert_refused(
        &text,
        ModelErrorKind::Physics,
        "1\"\nth_st",
        0,
        &["start", "off the floor", "z = -x tan(phi)"],
    );
}

#[test]
fn a_start_moving_into_the_floor_is_refused() {
    let text = edit(
        COMPASS,
        "th_std = \"1.092384\"",
        "th_std = \"1.092384\"\nzd = \"-0.5\"",
    );
    assert_refused(
        &text,
        ModelErrorKind::Physics,
        "-0.5\"",
        0,
        &["start", "velocity", "zd = -xd tan(phi)"],
    );
}

#[test]
fn a_start_value_that_is_not_finite_is_refused() {
    let text = edit(COMPASS, "th_std = \"1.092384\"", "th_std = \"1e300*1e300\"");
    assert_refused(
        &text,
        ModelErrorKind::Physics,
        "1e300*1e300",
        0,
        &["start `th_std`", "inf", "expected a finite value"],
    );
}

#[test]
fn a_negative_power_until_is_refused() {
    let text = edit(ACTIVE, "power_until = \"T_set\"", "power_until = \"-1\"");
    assert_refused(
        &text,
        ModelErrorKind::Physics,
        "power_until = \"-1\"",
        "power_until = \"".len(),
        &["descriptors power_until", "-1", "> 0"],
    );
}

#[test]
fn a_ramp_duration_that_can_be_zero_is_refused() {
    let text = edit(ACTIVE, "duration = \"T_set\"", "duration = \"T_set - 0.3\"");
    assert_refused(
        &text,
        ModelErrorKind::Physics,
        "T_set - 0.3",
        0,
        &["output `y` desired duration", "a duration > 0"],
    );
}

#[test]
fn a_coordinate_named_sigma_is_refused_where_it_is_declared() {
    // Every use renamed too, so that the name is the only change.
    let text = COMPASS.replace("th_sw", "sigma");
    assert_refused(
        &text,
        ModelErrorKind::Reserved,
        "\"sigma\"\nunit",
        0,
        &["`sigma` is reserved", "Coulomb law's sliding direction"],
    );
}

#[test]
fn names_of_the_generated_code_and_rust_keywords_are_refused() {
    for (name, fragment) in [
        ("k3", "prepared constants"),
        ("K3", "in lower case, `k3`"),
        ("t12", "temporaries"),
        ("type", "Rust keyword"),
        ("tanh", "generated code"),
        ("p", "prepared parameters"),
    ] {
        let text = edit(COMPASS, "name = \"phi\"", &format!("name = \"{name}\""));
        assert_refused(
            &text,
            ModelErrorKind::Reserved,
            &format!("\"{name}\"\nunit = \"rad\""),
            0,
            &[&format!("`{name}` is reserved"), fragment],
        );
    }
}

#[test]
fn a_coordinate_whose_rate_is_a_keyword_is_refused() {
    let text = COMPASS.replace("th_sw", "mo");
    assert_refused(
        &text,
        ModelErrorKind::Reserved,
        "\"mo\"\nunit",
        0,
        &["gives the rate `mod`", "Rust keyword"],
    );
}

/// `n` `[[point]]` tables after the compass gait's own two.
fn with_points(n: usize) -> String {
    let extra: String = (0..n)
        .map(|k| format!("[[point]]\nname = \"extra{k}\"\nat = [\"x\", \"z\"]\n"))
        .collect();
    edit(COMPASS, "[stance]", &format!("{extra}[stance]"))
}

#[test]
fn more_points_than_the_simulator_holds_are_refused_at_the_first_extra() {
    assert!(Model::from_toml(&with_points(MAX_POINTS - 2), "edit.toml").is_ok());
    let text = with_points(31);
    let first_extra = format!("[[point]]\nname = \"extra{}\"", MAX_POINTS - 2);
    assert_refused(
        &text,
        ModelErrorKind::Limit,
        &first_extra,
        0,
        &["33 [[point]]", "at most 32"],
    );
}

#[test]
fn more_falls_than_the_event_table_holds_are_refused() {
    let extra: String = (0..MAX_FALLS)
        .map(|k| format!("[[fall]]\nname = \"fall-{k}\"\npoint = \"hip\"\ndoc = \"d\"\n"))
        .collect();
    let text = edit(COMPASS, "[relabel]", &format!("{extra}[relabel]"));
    assert_refused(
        &text,
        ModelErrorKind::Limit,
        &format!("[[fall]]\nname = \"fall-{}\"", MAX_FALLS - 1),
        0,
        &["17 [[fall]]", "at most 16"],
    );
}

#[test]
fn a_chain_of_152_coordinates_is_refused_promptly() {
    let extra: String = (0..148)
        .map(|k| format!("[[coordinate]]\nname = \"q{k}\"\nunit = \"rad\"\ndoc = \"link\"\n"))
        .collect();
    let text = edit(
        COMPASS,
        "\n[[parameter]]\nname = \"m\"\n",
        &format!("\n{extra}[[parameter]]\nname = \"m\"\n"),
    );
    assert_refused(
        &text,
        ModelErrorKind::Limit,
        &format!("[[coordinate]]\nname = \"q{}\"", MAX_COORDINATES - 4),
        0,
        &["152 [[coordinate]]", "at most 8"],
    );
}

#[test]
fn a_number_literal_of_5000_digits_is_refused_promptly() {
    let digits = "7".repeat(5000);
    let text = edit(
        COMPASS,
        "th_std = \"1.092384\"",
        &format!("th_std = \"1.{digits}\""),
    );
    assert_refused(
        &text,
        ModelErrorKind::Limit,
        &format!("1.{digits}"),
        0,
        &[
            "start `th_std`",
            "5001 significant digits",
            "at most 40 digits",
        ],
    );
    let text = edit(COMPASS, "th_std = \"1.092384\"", "th_std = \"1e-400\"");
    assert_refused(
        &text,
        ModelErrorKind::Limit,
        "1e-400",
        0,
        &["power of ten -400"],
    );
}

#[test]
fn a_name_with_control_characters_is_echoed_escaped() {
    let text = edit(COMPASS, "name = \"th_sw\"", "name = \"th\\u0007\\n\"");
    let err = Model::from_toml(&text, "edit.toml").expect_err("refused");
    let message = err.to_string();
    assert_eq!(err.kind(), Some(ModelErrorKind::BadName));
    assert!(message.contains("th\\u{7}\\n"), "{message}");
    assert!(!message.chars().any(char::is_control), "{message:?}");
}

#[test]
fn a_megabyte_name_is_refused_and_not_echoed_whole() {
    let long = "a".repeat(1 << 20);
    let text = edit(COMPASS, "name = \"th_sw\"", &format!("name = \"{long}\""));
    let err = Model::from_toml(&text, "edit.toml").expect_err("refused");
    assert_eq!(err.kind(), Some(ModelErrorKind::Limit));
    let message = err.to_string();
    assert!(message.len() < 400, "{} bytes", message.len());
    assert!(message.contains("1048576 bytes in all"), "{message}");
}

#[cfg(unix)]
#[test]
fn a_device_is_refused_before_it_is_read() {
    let started = Instant::now();
    let err = Model::from_file(Path::new("/dev/zero")).expect_err("refused");
    assert!(started.elapsed() < PROMPT);
    let message = err.to_string();
    assert!(
        message.starts_with("/dev/zero:")
            && message.contains("not a regular file (it is a device)"),
        "{message}"
    );
}

#[cfg(unix)]
#[test]
fn a_fifo_is_refused_without_blocking() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::env::temp_dir().join(format!("walker-scene-fifo-{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let fifo = dir.join("model.toml");
    let _ = std::fs::remove_file(&fifo);
    let made = std::process::Command::new("mkfifo").arg(&fifo).status()?;
    assert!(made.success(), "mkfifo");
    let started = Instant::now();
    let err = Model::from_file(&fifo).expect_err("refused");
    assert!(started.elapsed() < PROMPT);
    assert!(err.to_string().contains("it is a FIFO"), "{err}");
    // A scene naming the FIFO as its model: the scene's model path is read the same way.
    let scene = dir.join("scene.toml");
    std::fs::write(&scene, "model = \"model.toml\"\n")?;
    let err = ModelSceneFile::from_file(&scene).expect_err("refused");
    assert!(err.to_string().contains("it is a FIFO"), "{err}");
    std::fs::remove_dir_all(&dir)?;
    Ok(())
}

#[test]
fn a_file_longer_than_the_bound_is_refused() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::env::temp_dir().join(format!("walker-scene-long-{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let path = dir.join("long.toml");
    let len = usize::try_from(MAX_FILE_BYTES)? + 1;
    std::fs::write(
        &path,
        format!("{COMPASS}{}", "#".repeat(len - COMPASS.len())),
    )?;
    let err = Model::from_file(&path).expect_err("refused");
    assert!(
        matches!(err, ModelError::Read { .. }) && err.to_string().contains("at most 1048576"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir)?;
    Ok(())
}
