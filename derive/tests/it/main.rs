//! The integration tests of this crate, one module per file, in one test binary. One binary
//! per file linked the crate and its dependencies and compiled their generic code once per
//! file: in a fresh `cargo test --workspace --no-run --timings`, those binaries were 771 s of
//! the 2676 s of compile time of all units. Run one file's tests with
//! `cargo test -p walker-symbolic --test it <file>::`.

mod common;
mod equations_doc;
mod model_bounds;
mod model_compass;
mod model_coulomb;
mod model_mass;
mod model_paper;
mod model_start;
mod model_stick_jacobian;
mod model_sympy;
mod paper;
mod stick;
mod sympy_reference;
