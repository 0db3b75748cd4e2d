//! Generates the walker's kernels into `OUT_DIR` with `walker-gen`.
//!
//! Reads: the scene files below (`walker/scenes/*.toml`). Writes: one Rust file per scene, rewritten
//! only when its bytes change, so cargo recompiles only when the derivation or a scene changes.

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
    let root = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR")?);
    let out_dir = PathBuf::from(std::env::var("OUT_DIR")?);
    for scene in SCENES {
        walker_gen::Config::new()
            .scene_file(root.join("scenes").join(format!("{scene}.toml")))
            .out_file(out_dir.join(format!("{}.rs", scene.replace('-', "_"))))
            .emit_rerun_if_changed(true)
            .generate()?;
    }
    Ok(())
}
