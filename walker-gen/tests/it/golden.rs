//! Golden copies of generated files: `tests/golden/<scene>.rs` must equal `Config::render()`,
//! for two of the paper's scenes and for one model file (`models/compass-gait.toml`, whose
//! stance and impact kernels are structured solves).
//!
//! After an intended change of the generated code, rewrite them with
//! `WALKER_GEN_BLESS=1 cargo test -p walker-gen --test it golden::` and review the diff.

use std::path::PathBuf;

use walker_gen::Config;

const BLESS: &str = "WALKER_GEN_BLESS=1 cargo test -p walker-gen --test it golden::";

fn check(scene: &str) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let mut config = Config::new();
    config.scene_file(root.join("../walker/scenes").join(format!("{scene}.toml")));
    compare(scene, &config);
}

fn compare(scene: &str, config: &Config) {
    let rendered = config.render().expect("the scene renders");
    check_text(scene, &rendered, "the rendered source");
}

/// `rendered` against `tests/golden/<name>.rs` (`what` names it in the failure message), or
/// written there when blessing.
fn check_text(name: &str, rendered: &str, what: &str) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let golden = root.join("tests/golden").join(format!("{name}.rs"));
    if std::env::var_os("WALKER_GEN_BLESS").is_some_and(|v| v == "1") {
        std::fs::create_dir_all(root.join("tests/golden")).expect("create tests/golden");
        std::fs::write(&golden, rendered).expect("write the golden file");
        return;
    }
    let expected = std::fs::read_to_string(&golden).unwrap_or_default();
    assert!(
        expected == rendered,
        "tests/golden/{name}.rs differs from {what}{}\nIf the change is intended, run \
         `{BLESS}` and review the diff.",
        first_difference(&expected, rendered)
    );
}

/// Where two texts first differ, for the failure message.
fn first_difference(expected: &str, rendered: &str) -> String {
    let (e, r): (Vec<&str>, Vec<&str>) = (expected.lines().collect(), rendered.lines().collect());
    let line = (0..e.len().max(r.len()))
        .find(|&i| e.get(i) != r.get(i))
        .unwrap_or(0);
    let show = |v: &[&str]| v.get(line).copied().unwrap_or("<end of file>").to_owned();
    format!(
        " at line {}:\n  golden:   {}\n  rendered: {}",
        line + 1,
        show(&e),
        show(&r)
    )
}

#[test]
fn active_level_matches_golden() {
    check("active-level");
}

#[test]
fn passive_slope_matches_golden() {
    check("passive-slope");
}

#[test]
fn compass_gait_model_matches_golden() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let mut config = Config::new();
    config.model_file(root.join("../models/compass-gait.toml"));
    compare("model-compass-gait", &config);
}

/// The registry and adapters `Compile` writes for `model` (its default variants, or a fast
/// variant fixing `scene`'s `[fix]` first), against `tests/golden/compiled-<model>.rs`.
fn check_compiled(model: &str, scene: Option<&str>) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("golden-compiled-{model}"));
    std::fs::create_dir_all(&out).expect("create the output directory");
    let mut compile = walker_gen::Compile::new();
    compile
        .model(root.join(format!("../models/{model}.toml")))
        .out_dir(&out);
    if let Some(scene) = scene {
        use walker_gen::{Friction, VariantSpec};
        compile
            .variant(
                VariantSpec::new(Friction::Tanh)
                    .fixed_by_scene(root.join(format!("../models/scenes/{scene}.toml")))
                    .jacobians(true),
            )
            .variant(VariantSpec::new(Friction::Tanh))
            .variant(VariantSpec::new(Friction::Coulomb));
    }
    compile.generate().expect("the model compiles");
    let rendered = std::fs::read_to_string(out.join("compiled.rs")).expect("compiled.rs");
    check_text(
        &format!("compiled-{model}"),
        &rendered,
        "the generated registry",
    );
}

/// The compass gait's adapters (a passive walker: the fused right-hand side without inputs),
/// one variant per friction law.
#[test]
fn compass_gait_adapters_match_golden() {
    check_compiled("compass-gait", None);
}

/// The paper's active walker's adapters (inputs: the fused tracking, power sign and lambda),
/// with its Table 1 variant first, as `walker/build.rs` compiles it.
#[test]
fn paper_active_adapters_match_golden() {
    check_compiled("paper-active", Some("active-level"));
}
