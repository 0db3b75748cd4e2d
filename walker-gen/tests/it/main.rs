//! The integration tests of this crate, one module per file, in one test binary. One binary
//! per file linked the crate and its dependencies and compiled their generic code once per
//! file: in a fresh `cargo test --workspace --no-run --timings`, those binaries were 771 s of
//! the 2676 s of compile time of all units. Run one file's tests with
//! `cargo test -p walker-gen --test it <file>::`.

mod cli;
mod cli_files;
mod compile;
mod fastmath_accuracy;
mod golden;
mod large;
mod model_cli;
mod render;
mod scene_errors;
mod scene_fuzz;
