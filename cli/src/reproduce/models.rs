//! The paper's two walkers (Table 1) at a given friction coefficient `mu0` and ramp duration
//! `T_set` (the active walker on level ground) or slope angle `phi` (the passive wheel), the
//! other settings those of Section 4.

use walker::model::{Model, Runtime};

/// Section 4's settings with `mu0` and `T_set` as given.
#[must_use]
pub fn runtime(mu0: f64, t_set: f64) -> Runtime {
    Runtime {
        mu0,
        t_set,
        ..Runtime::default()
    }
}

/// The active walker on level ground at `mu0` and `T_set`.
#[must_use]
pub fn active(mu0: f64, t_set: f64) -> Model {
    Model::active_level(runtime(mu0, t_set))
}

/// The passive wheel on the slope `phi` at `mu0`.
#[must_use]
pub fn passive(mu0: f64, phi: f64) -> Model {
    Model::passive_slope(Runtime {
        mu0,
        phi,
        ..Runtime::default()
    })
}
