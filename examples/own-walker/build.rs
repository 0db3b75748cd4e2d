//! Compiles `hopper.toml` twice, from one model file: `no_std` `f32` kernels for a controller
//! (`walker_gen::Config`, into `OUT_DIR/hopper.rs`), and, with the `simulate` feature, the
//! `f64` variants the walker simulator runs (`walker_gen::Compile`: kernels, their adapter to
//! the kernel contract and the registry `MODELS`, into `OUT_DIR/compiled.rs`).
fn main() -> Result<(), Box<dyn std::error::Error>> {
    walker_gen::Config::new()
        .model_file("hopper.toml")
        .fix("g", 9.81)
        .friction(walker_gen::Friction::Tanh)
        .float(walker_gen::Float::F32)
        .no_std(true)
        .emit_rerun_if_changed(true)
        .generate()?;
    if std::env::var_os("CARGO_FEATURE_SIMULATE").is_some() {
        // One variant per friction law the model lists, every parameter at run time; the
        // adapters name the contract through `walker`, so this crate needs no other dependency.
        walker_gen::Compile::new()
            .model("hopper.toml")
            .contract_path("::walker::contract")
            .emit_rerun_if_changed(true)
            .generate()?;
    }
    Ok(())
}
