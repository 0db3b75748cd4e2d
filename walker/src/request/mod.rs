//! What a request may ask, checked once for every front end: the integrator and its
//! tolerances, the limits of a walk and of a trajectory, the range of a sweep and its chains,
//! parameter assignments (by role, by name, swept, chained: each parameter once) and the
//! components of a start. Every check returns a [`RequestError`] that names the [`Field`] in
//! the library's words (`max_steps`, `T_set`); the command line translates a field to its flag
//! (`--max-steps`, `--t-set`), Python to its keyword (`max_steps`, `t_set`), with
//! [`RequestError::field`] and [`RequestError::detail`]. A user's text is echoed at most
//! [`shown::MAX_ECHO`] characters long with control characters escaped, a number in short
//! form.
//!
//! The inputs, their ranges and their bounds (what each front end did before these checks is
//! in the last column):
//!
//! | input | command line | Python | valid | before |
//! |---|---|---|---|---|
//! | integration method | `--method` | `method` | `dop853`, `rodas4` | checked |
//! | friction, impact law | `--friction`, `--impact` | `friction`, `impact` | their names | checked |
//! | relative tolerance | `--rtol` | `rtol` | `[10 eps, 1)` ([`RTOL_MIN`]) | `(0, 1)`: `1e-300` walked |
//! | absolute tolerance | `--atol` | `atol` | `[2.2e-308, 1)` ([`ATOL_MIN`]) | `(0, 1)`: subnormals walked |
//! | steps of a walk | `--max-steps` | `max_steps` | whole, `[0, 10^6]` ([`MAX_STEPS`]) | bound checked; `1e30`, `-1` refused by the parser without the range |
//! | length of a walk | `--duration` | `duration` | `(0, 1e9]` s ([`MAX_DURATION`]) | `> 0`: `1e300` accepted |
//! | periodic-gait stop | `--until-periodic` | `until_periodic` | `(0, 1)` | checked |
//! | trajectory sampling | (animate: `--fps`, `--speed`) | `trajectory_dt` | `(0, 1e9]` s, at most `10^6` samples over a finite duration | `> 0`, named `dt`; more samples cut silently |
//! | trajectory samples | (animate: frames of the format) | `max_frames` | `[1, 10^6]` ([`MAX_FRAMES`]) | checked |
//! | sweep range | `--from`, `--to`, `--step` | `from_`, `to`, `step` | finite, `to >= from`, `step > 0` | checked |
//! | sweep size | (the range and chains) | (the same) | `<= 10^5` points ([`MAX_SWEEP_POINTS`]) | checked |
//! | sweep chains | `--t-set`, `--phi` (repeat) | `t_set`, `phi` lists | `<= 64` ([`MAX_SWEEP_CHAINS`]) | checked |
//! | swept parameter | `--param` | `param` | a parameter, not also chained or set | also chained or set: silently overridden |
//! | parameter by role | `--mu0`, `--c`, `--t-set`, `--phi` | `mu0`, `c`, `t_set`, `phi` | the model file's range, once | also by `--set`: the later won silently |
//! | parameter by name | `--set NAME=VALUE` | `set={name: value}` | a parameter, its range, once | repeated: the last won silently |
//! | start component | `--init NAME=VALUE` | `init={name: value}` | a coordinate or velocity, finite, once; the stance foot on the floor and moving along it | repeated: the last won silently; the command line walked a foot off the floor |
//! | start parameter | `--omega0` | `omega0` | finite (`> 0` for a fixed point), its range | checked |
//! | walks of a batch | `--walks` (survive) | | whole, `[1, 10^5]` ([`MAX_WALKS`]), at most `10^8` steps in all ([`MAX_SURVIVE_STEPS`]) | new |
//! | first walk of a batch | `--first-walk` (survive) | `first_walk` | whole, the last walk's index at most `2^63 - 1` ([`walk_range`]) | new |
//! | a floor | `--floor`, `--mu0-steps` | | one of them, not with `--mu0` ([`floor_once`]); the file's own checks in `walker_scene::floor` | new |
//!
//! Inputs only one front end has are checked there: `walker animate`'s `--steps`, `--speed`,
//! `--fps` and its `--duration` (`cli/src/animate/request.rs`), `walker continue`'s flags,
//! a grid's columns in Python.

//! A front end's part, in order (the command line's is `cli/src/run.rs` and `cli/src/input.rs`):
//!
//! 1. The integrator: [`method_named`], [`friction_named`], [`impact_named`] for names given
//!    as text, then [`sim_config`]`(method, rtol, atol)`.
//! 2. The limits: [`walk_limits`]`(duration, max_steps, until_periodic)` (a count as `i128`,
//!    so that a negative or huge one is named here; [`count_text`] for a count given as
//!    text), and for a sampled walk [`trajectory`]`(duration, dt, max_frames)`.
//! 3. The parameters: [`crate::setup::Setup::apply`] refuses one parameter given twice among
//!    the roles and the by-name list of its [`crate::setup::Overrides`]
//!    ([`crate::setup::SetupError::Request`]); values set another way (one by one, a grid's
//!    columns, the swept parameter, chains, the start parameter `omega0`) are checked with
//!    [`distinct_fields`] (fields by role or by name) or [`distinct`] (a field and the
//!    parameter's index, as for [`Field::Param`]).
//! 4. A sweep: [`SweepRange::grid`]`(chains, chain_field)` checks the range and counts the
//!    points before making the grid.
//! 5. The start: [`start()`]`(model, init)` ([`start_components`] and [`on_the_floor`]).
//!
//! Each error's [`RequestError::field`] is the input to name (the command line's
//! `flag_of`, Python's keyword), [`RequestError::detail`] the message with every other field
//! named by the front end's own function.

pub mod error;
pub mod field;
pub mod integrator;
pub mod limits;
pub mod parameters;
pub mod shown;
pub mod start;
pub mod survive;
pub mod sweep;

pub use error::RequestError;
pub use field::{Field, Role};
pub use integrator::{
    ATOL_MIN, RTOL_MIN, atol, default_tolerances, friction_named, impact_named, method_named, rtol,
    sim_config,
};
pub use limits::{
    MAX_DURATION, MAX_FRAMES, MAX_STEPS, at_most, count, count_text, duration, max_frames,
    max_steps, trajectory, trajectory_dt, until_periodic, values_in, walk_limits,
};
pub use parameters::{distinct, distinct_fields, parameter_of, role_parameter};
pub use start::{on_the_floor, start, start_components};
pub use survive::{
    MAX_SURVIVE_STEPS, MAX_WALK_INDEX, MAX_WALKS, floor_once, survive_counts, walk_range,
};
pub use sweep::{MAX_SWEEP_CHAINS, MAX_SWEEP_POINTS, SweepRange};
