//! `walker-gen emit|stats --model`: kernels generated from a model file. The paper's active
//! walker from its model file gives kernels with at most the operation counts of the paper's
//! scene (`walker/scenes/general-level.toml`, the same quantities lowered by the scene path); generation is deterministic; bad choices
//! exit 2 naming the parameter or flag.

use std::collections::BTreeMap;
use std::path::Path;
use std::process::{Command, Output};

fn walker_gen(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_walker-gen"))
        .args(args)
        .output()
        .expect("run walker-gen")
}

fn file(dir: &str, name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join(dir)
        .join(name)
        .display()
        .to_string()
}

/// Every model file in `models/`.
const SHIPPED: [&str; 7] = [
    "rimless-wheel",
    "paper-active",
    "paper-passive",
    "compass-gait",
    "three-link",
    "five-link",
    "simplest-walker",
];

/// The `total` column of `walker-gen stats` by kernel, and the form the generator chose (empty
/// where it had no choice).
fn totals(args: &[&str]) -> BTreeMap<String, (u64, String)> {
    let out = walker_gen(args);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    text.lines()
        .take_while(|l| !l.starts_with("prepare"))
        .filter_map(|l| {
            let cols: Vec<&str> = l.split_whitespace().collect();
            let total = cols.get(8)?.parse().ok()?;
            let form = l.split_once("; ").map_or("", |(_, f)| f).to_owned();
            Some(((*cols.first()?).to_owned(), (total, form)))
        })
        .collect()
}

/// The paper's walkers from their model files cost no more than the paper's scene kernels
/// (the "operation counts no larger than today's"): the same where the generator keeps
/// the closed form, fewer where it chose the structured solve.
#[test]
fn the_papers_model_files_cost_at_most_what_the_papers_scene_kernels_cost() {
    // The model's kernel names are model-independent; the scene's carry the floor.
    type Pairs = &'static [(&'static str, &'static str)];
    let cases: [(&str, &str, Pairs); 2] = [
        (
            "paper-active.toml",
            "general-level.toml",
            &[
                ("mass_matrix", "mass_matrix"),
                ("bias", "bias"),
                ("lambda", "lambda_level"),
                ("accel", "accel_level"),
                ("control", "control_level"),
                ("closed_loop", "closed_loop_level"),
                ("impact", "impact2_level"),
                ("impact_double", "impact3_level"),
                ("impact_coulomb", "impact_coulomb_level"),
                ("energy", "energy"),
            ],
        ),
        (
            "paper-passive.toml",
            "general-slope.toml",
            &[
                ("mass_matrix", "mass_matrix"),
                ("bias", "bias"),
                ("lambda", "lambda_slope"),
                ("accel", "accel_slope"),
                ("impact", "impact_slope"),
                ("impact_double", "impact2_slope"),
                ("impact_coulomb", "impact_coulomb_slope"),
                ("energy", "energy"),
            ],
        ),
    ];
    for (model_file, scene_file, pairs) in cases {
        let model = totals(&["stats", "--model", &file("models", model_file)]);
        let scene = totals(&["stats", "--scene", &file("walker/scenes", scene_file)]);
        for &(m, s) in pairs {
            let ((model, form), (scene, _)) = (&model[m], &scene[s]);
            // The impacts are evaluated once per step and keep the closed form (`walker_contract::KernelId::once_per_step`).
            assert_eq!(
                m.starts_with("impact"),
                form.contains("once per step"),
                "{model_file}: {m}: {form}"
            );
            if form.starts_with("structured solve") {
                assert!(model < scene, "{m} ({form}): {model} against {s}: {scene}");
            } else {
                assert_eq!(model, scene, "{model_file}: {m} ({form}) against {s}");
            }
        }
    }
}

/// Every shipped model generates, each stance and impact kernel in the form with the smaller
/// estimated time (critical path plus half the operation count, in cycles; `walker-gen`'s
/// `model.rs`): the models whose closed forms are too large (the compass gait, the three- and
/// five-link bipeds) by structured solves, and every choice is reported with both forms' costs.
#[test]
fn every_shipped_model_generates_and_reports_its_forms() {
    // "closed form, 94 cycles (structured solve: 64 ops, 124 cycles)": (94, 64, 124).
    let costs = |form: &str| -> Option<(u64, u64, u64)> {
        let number = |s: &str| s.trim().parse::<u64>().ok();
        let (chosen, other) = form.split_once(" (")?;
        let path = number(chosen.split_once(", ")?.1.strip_suffix(" cycles")?)?;
        let (ops, other_path) = other.split_once(": ")?.1.split_once(" ops, ")?;
        Some((
            path,
            number(ops)?,
            number(other_path.strip_suffix(" cycles)")?)?,
        ))
    };
    let mut compared = 0;
    for name in SHIPPED {
        let kernels = totals(&["stats", "--model", &file("models", &format!("{name}.toml"))]);
        for k in ["lambda", "accel", "stick", "impact"] {
            let (total, form) = &kernels[k];
            assert!(*total > 0, "{name}: {k} is generated");
            // A kernel evaluated once per step keeps its closed form.
            if form.contains("once per step") {
                assert!(form.starts_with("closed form"), "{name}: {k}: {form}");
            } else if let Some((path, other_ops, other_path)) = costs(form) {
                let time = |path: u64, ops: u64| (path + ops.div_ceil(2), ops);
                assert!(
                    time(path, *total) <= time(other_path, other_ops),
                    "{name}: {k}: {total} ops against {form}"
                );
                compared += 1;
            } else {
                assert_eq!(form, "structured solve (no closed form)", "{name}: {k}");
            }
        }
    }
    assert!(compared >= 6, "the forms of {compared} kernels compared");
}

#[test]
fn model_generation_is_deterministic_and_stamped() {
    let args = [
        "emit",
        "--model",
        &file("models", "rimless-wheel.toml"),
        "--fix",
        "alpha=0.5",
    ];
    let text = emitted_twice(&args);
    assert!(
        text.contains("pub fn impact_double"),
        "the double-support impact is generated"
    );
    // alpha is fixed, so it is no field of Params.
    assert!(!text.contains("pub alpha: f64"), "alpha is substituted");
}

/// Emits twice, checks that both runs succeed and agree byte for byte and that the file is
/// stamped as generated, and returns it.
fn emitted_twice(args: &[&str]) -> String {
    let (a, b) = (walker_gen(args), walker_gen(args));
    assert_eq!(
        a.status.code(),
        Some(0),
        "{args:?}: {}",
        String::from_utf8_lossy(&a.stderr)
    );
    assert_eq!(a.stdout, b.stdout, "{args:?}: two runs differ");
    let text = String::from_utf8_lossy(&a.stdout).into_owned();
    assert!(
        text.contains("@generated"),
        "{args:?}: stamped as generated"
    );
    text
}

#[test]
fn every_shipped_model_generates_deterministically() {
    let mut in_dir: Vec<String> = std::fs::read_dir(file("models", ""))
        .expect("models/")
        .filter_map(|e| {
            let name = e.ok()?.file_name().into_string().ok()?;
            name.strip_suffix(".toml").map(str::to_owned)
        })
        .collect();
    in_dir.sort();
    let mut listed: Vec<String> = SHIPPED.iter().map(|s| (*s).to_owned()).collect();
    listed.sort();
    assert_eq!(in_dir, listed, "SHIPPED lists every file of models/");
    for name in SHIPPED {
        let text = emitted_twice(&["emit", "--model", &file("models", &format!("{name}.toml"))]);
        assert!(
            text.contains("pub fn accel("),
            "{name}: the stance is generated"
        );
    }
}

/// Exit 2 and a message that names `what`, without a panic.
fn fails_naming(args: &[&str], what: &str) {
    let out = walker_gen(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(
        stderr.contains(what),
        "{args:?}: does not name `{what}`: {stderr}"
    );
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
}

#[test]
fn bad_model_choices_exit_2_naming_what_is_wrong() {
    let rw = file("models", "rimless-wheel.toml");
    fails_naming(&["stats", "--model", &rw, "--fix", "m3=1"], "m3");
    fails_naming(&["stats", "--model", &rw, "--fix", "alpha=4"], "alpha");
    fails_naming(&["stats", "--model", &rw, "--fix", "alpha"], "name=value");
    fails_naming(&["stats", "--model", &rw, "--fix", "alpha=nan"], "alpha");
    fails_naming(
        &[
            "stats",
            "--model",
            &rw,
            "--scene",
            &file("walker/scenes", "general-level.toml"),
        ],
        "--scene",
    );
    fails_naming(
        &["stats", "--model", "no/such/model.toml"],
        "no/such/model.toml",
    );
}

/// A model scene (a scene file naming a model) generates only its kernels, with its parameters
/// fixed and its friction law.
#[test]
fn a_model_scene_file_selects_kernels_fixes_parameters_and_friction() {
    let scene = file("models/scenes", "compass-gait-3deg.toml");
    let kernels = totals(&["stats", "--scene", &scene]);
    let names: Vec<&str> = kernels.keys().map(String::as_str).collect();
    assert_eq!(
        names,
        [
            "accel",
            "energy",
            "impact",
            "impact_double",
            "lambda",
            "mass_matrix",
            "points",
            "stick"
        ],
        "exactly the listed kernels"
    );
    let text = emitted_twice(&["emit", "--scene", &scene]);
    assert!(!text.contains("pub phi: F"), "phi is fixed");
    assert!(
        text.contains("pub fn accel(") && text.contains("sigma: F"),
        "Coulomb friction"
    );
    assert!(!text.contains("pub fn bias("), "bias is not listed");
}

/// Writes a model scene into a fresh directory beside a copy of the rimless wheel's model.
fn model_scene(body: &str) -> String {
    static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let dir = std::env::temp_dir().join(format!(
        "walker-gen-model-scene-{}-{}",
        std::process::id(),
        NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed)
    ));
    std::fs::create_dir_all(&dir).expect("temp dir");
    std::fs::copy(file("models", "rimless-wheel.toml"), dir.join("wheel.toml")).expect("copy");
    let path = dir.join("scene.toml");
    std::fs::write(&path, body).expect("write the scene");
    path.display().to_string()
}

#[test]
fn bad_model_scenes_exit_2_naming_the_field() {
    let s = model_scene("model = \"wheel.toml\"\nkernels = [\"accel\", \"nope\"]\n");
    fails_naming(
        &["stats", "--scene", &s],
        "`nope` is not a kernel of the model",
    );
    let s = model_scene("model = \"wheel.toml\"\nfriction = \"sticky\"\n");
    fails_naming(&["stats", "--scene", &s], "friction = \"sticky\"");
    let s = model_scene("model = \"wheel.toml\"\ncolour = \"red\"\n");
    fails_naming(&["stats", "--scene", &s], "colour");
    let s = model_scene("model = \"no-such-model.toml\"\n");
    fails_naming(&["stats", "--scene", &s], "no-such-model.toml");
    let s = model_scene("model = \"wheel.toml\"\n[fix]\nalpha = 9.0\n");
    fails_naming(&["stats", "--scene", &s], "alpha");
    let s = model_scene("model = \"wheel.toml\"\nkernels = []\n");
    fails_naming(&["stats", "--scene", &s], "kernels = []");
}

#[test]
fn parameters_that_differ_only_in_case_are_fields_of_their_own() {
    // The compass gait in the notation of much of the literature: `M` the hip mass beside `m`
    // the legs' (docs/model-format.md, "Names": the field of `M` is `mm`).
    let text = std::fs::read_to_string(file("models", "compass-gait.toml"))
        .expect("the compass gait")
        .replace("\"m_H\"", "\"M\"");
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"));
    let path = dir.join("compass-gait-big-m.toml");
    std::fs::write(&path, text).expect("write the model");
    let code = emitted_twice(&["emit", "--model", &path.display().to_string()]);
    let file = syn::parse_file(&code).expect("the generated code parses");
    let fields: Vec<String> = file
        .items
        .iter()
        .find_map(|item| match item {
            syn::Item::Struct(s) if s.ident == "Params" => Some(s),
            _ => None,
        })
        .expect("a Params struct")
        .fields
        .iter()
        .filter_map(|f| f.ident.as_ref().map(ToString::to_string))
        .collect();
    assert!(fields.contains(&"m".to_owned()), "{fields:?}");
    assert!(fields.contains(&"mm".to_owned()), "{fields:?}");
    // Values are looked up by the parameter's own name.
    assert!(code.contains("mm: value(\"M\")"), "M is read by its name");
}
