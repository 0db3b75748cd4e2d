//! Generates the walker's kernels into `OUT_DIR` with `walker-gen`.
//!
//! Reads: the scene files below (`walker/scenes/*.toml`). Writes: one Rust file per scene (named
//! by the scene, `<name with _>.rs`), all from one derivation, each rewritten only when its bytes
//! change, so cargo recompiles only when the derivation or a scene changes.

use std::path::PathBuf;

/// The scenes the simulator is built with: the paper's two setups with Table 1 fixed (the
/// fast path), the same structures with every parameter at run time (scene files), and both
/// under exact Coulomb friction with stick-slip (every parameter at run time).
const SCENES: [&str; 6] = [
    "active-level",
    "passive-slope",
    "general-level",
    "general-slope",
    "general-level-coulomb",
    "general-slope-coulomb",
];

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let scenes = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR")?).join("scenes");
    let out_dir = PathBuf::from(std::env::var("OUT_DIR")?);
    // One derivation for all six scenes; each file is named by its scene (`<name with _>.rs`).
    walker_gen::Config::new()
        .scene_files(SCENES.map(|scene| scenes.join(format!("{scene}.toml"))))
        .out_dir(out_dir)
        .emit_rerun_if_changed(true)
        .generate_all()?;
    Ok(())
}
