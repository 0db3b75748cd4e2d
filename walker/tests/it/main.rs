//! The integration tests of this crate, one module per file, in one test binary. One binary
//! per file linked the crate and its dependencies and compiled their generic code once per
//! file: in a fresh `cargo test --workspace --no-run --timings`, those binaries were 771 s of
//! the 2676 s of compile time of all units. Run one file's tests with
//! `cargo test -p walker --test it <file>::`.

mod common;
mod compass_gait;
mod compiled_fused;
mod continuation_constructed;
mod continuation_held;
mod continuation_walkers;
mod design_clearance;
mod floor_patches;
mod floor_slopes;
mod floor_survive;
mod floor_walks;
mod model_identity;
mod multiplier_bounds;
mod ode_accuracy;
mod ode_crosscheck;
mod ode_events;
mod ode_observers;
mod ode_stiff;
mod parameter_column;
mod poincare_errors;
mod poincare_exact;
mod poincare_fixed;
mod poincare_friction_impact;
mod poincare_map;
mod rimless_wheel;
mod sensitivity;
mod sim_blowup;
mod sim_coulomb;
mod sim_extreme;
mod sim_failure_json;
mod sim_periodic;
mod sim_reference;
mod sim_start;
mod sim_stiff;
mod sim_walk;
mod stress_kernels;
mod stuck_actuated;
mod three_link;
