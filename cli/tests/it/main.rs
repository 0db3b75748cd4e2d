//! The integration tests of this crate, one module per file, in one test binary. One binary
//! per file linked the crate and its dependencies and compiled their generic code once per
//! file: in a fresh `cargo test --workspace --no-run --timings`, those binaries were 771 s of
//! the 2676 s of compile time of all units. Run one file's tests with
//! `cargo test -p walker-cli --test it <file>::`.

mod animate_cli;
mod cli_extremes;
mod cli_fuzz;
mod common;
mod continue_cli;
mod design_bounds_cli;
mod design_cli;
mod design_rabbit_cli;
mod floor_cli;
mod floor_patches_cli;
mod floor_slopes_cli;
mod floor_study_cli;
mod front_end_checks;
mod gallery_cli;
mod impact_cli;
mod input_bounds;
mod mfpt_cli;
mod mfpt_slopes_cli;
mod poincare_cli;
mod poincare_continuation;
mod reproduce_cli;
mod request_checks;
mod sim_cli;
