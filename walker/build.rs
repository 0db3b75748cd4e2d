//! Compiles the shipped model files into the library with `walker-gen` (`walker_gen::Compile`,
//! the builder a user's own build script calls too): per variant (a friction law, some
//! parameters fixed at generation) the kernels and their adapter to the kernel contract, and
//! the registry `MODELS` (`OUT_DIR/compiled.rs`, included by `src/compiled.rs`).
//!
//! Which models and variants are compiled is this file's choice; the values a fast variant
//! fixes are those of a built-in scene's `[fix]` table (`models/scenes/`), so that Table 1 is
//! written there only. Variants fixing parameters come first: the registry takes the first
//! that fits a run.

use walker_gen::{Compile, Friction, VariantSpec};

/// The shipped models compiled into the library, each with the built-in scene (if any) whose
/// fixed values make its fast variant.
const MODELS: &[(&str, Option<&str>)] = &[
    ("paper-active", Some("active-level")),
    ("paper-passive", Some("passive-slope")),
    ("rimless-wheel", None),
    ("compass-gait", None),
    ("three-link", None),
];

fn main() {
    if let Err(e) = run() {
        eprintln!("walker build script: {e}");
        std::process::exit(1);
    }
}

fn run() -> Result<(), walker_gen::Error> {
    let mut compile = Compile::new();
    compile.emit_rerun_if_changed(true);
    for (name, scene) in MODELS {
        compile.model(format!("../models/{name}.toml"));
        if let Some(scene) = scene {
            // The Jacobian kernels are compiled where the parameters are fixed (with every
            // parameter symbolic they are large): the stiff integrator and the Poincare map.
            compile.variant(
                VariantSpec::new(Friction::Tanh)
                    .fixed_by_scene(format!("../models/scenes/{scene}.toml"))
                    .jacobians(true),
            );
        }
        // Under exact Coulomb friction the Jacobians are compiled too: the Poincare map's
        // variational equations need them (the stuck stance's `stick_jacobian`, the sliding
        // stance's), and no integrator reads them, so no walk changes. The tanh variants with
        // every parameter at run time go without (the stiff integrator would read them and
        // change its walks; their maps take differences).
        compile
            .variant(VariantSpec::new(Friction::Tanh))
            .variant(VariantSpec::new(Friction::Coulomb).jacobians(true));
    }
    compile.generate()?;
    Ok(())
}
