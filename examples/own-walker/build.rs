//! Generates `no_std` `f32` kernels for `hopper.toml` into `OUT_DIR`.
fn main() -> Result<(), Box<dyn std::error::Error>> {
    walker_gen::Config::new()
        .model_file("hopper.toml")
        .fix("g", 9.81)
        .friction(walker_gen::Friction::Tanh)
        .float(walker_gen::Float::F32)
        .no_std(true)
        .emit_rerun_if_changed(true)
        .generate()?;
    Ok(())
}
