//! What the integration tests share: the paper's two walkers from their built-in scenes
//! (`models/scenes/active-level.toml`, `models/scenes/passive-slope.toml`) with parameters set by
//! name, the same walkers with every parameter at run time, their starts, and Table 1.
//!
//! Each test file uses some of these; the rest are dead code in that file's crate.
#![allow(
    dead_code,
    reason = "each test crate uses a part of the shared helpers"
)]
#![allow(
    clippy::panic,
    reason = "a test helper reports a broken setup by panicking"
)]

use std::sync::Arc;

use walker::compiled::MODELS;
use walker::model::{Compiled, Friction, Model, Variant, Walker};
use walker::setup::Setup;
use walker::vector::Vector;

/// The built-in scene `scene` with the parameters `params` set by name (checked).
pub fn setup(scene: &str, params: &[(&str, f64)]) -> Setup {
    let mut s = Setup::built_in(scene).unwrap_or_else(|e| panic!("{scene}: {e}"));
    for &(name, value) in params {
        s.set(name, value)
            .unwrap_or_else(|e| panic!("{scene}: {name} = {value}: {e}"));
    }
    s
}

/// The model of `setup`.
pub fn model(setup: &Setup) -> Model {
    setup
        .model()
        .unwrap_or_else(|e| panic!("{}: {e}", setup.name))
}

/// The paper's active walker (`active-level`: Table 1, `mu0 = 0.4`, `c = 100`, `T_set = 0.3`,
/// `K_P = K_D = 0`, the tanh law) with `params` set.
pub fn active(params: &[(&str, f64)]) -> Model {
    model(&setup("active-level", params))
}

/// The paper's passive wheel (`passive-slope`: Table 1, `phi = 0.2`, `mu0 = 0.2`, `c = 100`, the
/// tanh law) with `params` set.
pub fn passive(params: &[(&str, f64)]) -> Model {
    model(&setup("passive-slope", params))
}

/// The active walker with `params` under exact Coulomb friction (Eq. 25) and stick-slip.
pub fn active_coulomb(params: &[(&str, f64)]) -> Model {
    let mut s = setup("active-level", params);
    s.friction = Friction::Coulomb;
    model(&s)
}

/// The passive wheel with `params` under exact Coulomb friction (Eq. 25) and stick-slip.
pub fn passive_coulomb(params: &[(&str, f64)]) -> Model {
    let mut s = setup("passive-slope", params);
    s.friction = Friction::Coulomb;
    model(&s)
}

/// The model of `setup` with its kernels from the compiled variants that fix no parameter (every
/// parameter at run time), even where the parameters are those a faster variant fixes: the
/// paper's "general" kernels (`general_level`, `general_slope`).
pub fn run_time(setup: &Setup) -> Model {
    let name = setup.walker.spec().name();
    let compiled = MODELS
        .iter()
        .find(|c| c.name == name)
        .unwrap_or_else(|| panic!("{name} is not compiled in"));
    let variants: Vec<Variant> = compiled
        .variants
        .iter()
        .filter(|v| v.fixed.is_empty())
        .copied()
        .collect();
    let source = Compiled {
        variants: Vec::leak(variants),
        ..*compiled
    };
    let walker = Walker::new(Arc::clone(setup.walker.spec()), Arc::new(source));
    walker
        .model(&setup.params, setup.friction, setup.impact)
        .unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// The active walker with `params` and every parameter at run time (the paper's
/// `general_level`).
pub fn active_run_time(params: &[(&str, f64)]) -> Model {
    run_time(&setup("active-level", params))
}

/// The passive wheel with `params` and every parameter at run time (`general_slope`).
pub fn passive_run_time(params: &[(&str, f64)]) -> Model {
    run_time(&setup("passive-slope", params))
}

/// The model's start (Eq. 33 for the active walker, (P2b) for the passive wheel) with the
/// initial angular velocity `omega0`.
pub fn start(model: &Model, omega0: f64) -> Vector {
    model
        .start_state_with("omega0", omega0)
        .unwrap_or_else(|e| panic!("omega0 = {omega0}: {e}"))
}

/// The value of the Table 1 parameter `name` (`m1`, `m2`, `l`, `I1`, `I2`, `g`, `alpha`) as the
/// built-in scenes fix it.
pub fn table1(name: &str) -> f64 {
    let s = setup("active-level", &[]);
    s.params
        .get(name)
        .unwrap_or_else(|| panic!("{name} is not a parameter"))
}

/// The total mass `m_t = m1 + m2` of Table 1 (Eq. 2).
pub fn table1_total_mass() -> f64 {
    table1("m1") + table1("m2")
}

/// The stance-leg angle at which the rear spoke touches the floor, also the post-impact angle:
/// `phi - alpha/2` (`-alpha/2` on level ground; Eqs. 18, 45).
pub fn rear_contact_angle(model: &Model) -> f64 {
    model.phi() - model.param("alpha") / 2.0
}

/// The stance-leg angle at the heel strike: `alpha/2 + phi` (Eq. 3 on level ground, Section
/// 5.1 on the slope).
pub fn heel_strike_angle(model: &Model) -> f64 {
    model.param("alpha") / 2.0 + model.phi()
}
