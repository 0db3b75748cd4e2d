//! `own-walker`: the whole `walker` command line (simulate, sweep, fixed-point, continue,
//! animate, ..) with the hopper compiled in: `own-walker simulate --model hopper.toml` runs
//! the compiled kernels, any other model file as `walker` would.

fn main() -> std::process::ExitCode {
    walker_cli::main_with(own_walker::compiled::MODELS)
}
