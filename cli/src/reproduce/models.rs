//! The paper's two walkers (the built-in scenes `active-level` and `passive-slope`: Table 1)
//! at a given friction coefficient `mu0` and ramp duration `T_set` (the active walker on level
//! ground) or slope angle `phi` (the passive wheel), the other settings those of Section 4; and
//! the models of a sweep's grid, built before any walk.

use walker::model::Model;
use walker::setup::Setup;
use walker::vector::Vector;

use super::error::WriteError;

/// A setup error of the built-in scenes (it would be a defect of the shipped files: a test
/// loads them).
fn setup_error(e: impl std::fmt::Display) -> WriteError {
    WriteError::Setup(e.to_string())
}

/// The active walker's setup at `mu0` and `T_set`, with other values `extra` by name.
///
/// # Errors
/// The built-in scene does not load, or a value is out of its range.
pub fn active_setup(mu0: f64, t_set: f64) -> Result<Setup, WriteError> {
    let mut s = Setup::active_level().map_err(setup_error)?;
    s.set("mu0", mu0).map_err(setup_error)?;
    s.set("T_set", t_set).map_err(setup_error)?;
    Ok(s)
}

/// The passive wheel's setup on the slope `phi` at `mu0`.
///
/// # Errors
/// As [`active_setup`].
pub fn passive_setup(mu0: f64, phi: f64) -> Result<Setup, WriteError> {
    let mut s = Setup::passive_slope().map_err(setup_error)?;
    s.set("mu0", mu0).map_err(setup_error)?;
    s.set("phi", phi).map_err(setup_error)?;
    Ok(s)
}

/// The model of `setup`.
///
/// # Errors
/// Its kernels cannot be prepared.
pub fn model(setup: &Setup) -> Result<Model, WriteError> {
    setup.model().map_err(setup_error)
}

/// The active walker on level ground at `mu0` and `T_set`.
///
/// # Errors
/// As [`active_setup`].
pub fn active(mu0: f64, t_set: f64) -> Result<Model, WriteError> {
    model(&active_setup(mu0, t_set)?)
}

/// The passive wheel on the slope `phi` at `mu0`.
///
/// # Errors
/// As [`active_setup`].
pub fn passive(mu0: f64, phi: f64) -> Result<Model, WriteError> {
    model(&passive_setup(mu0, phi)?)
}

/// The paper's start of a walk of `model` with the initial angular velocity `omega0` (Eq. 33
/// for the active walker, (P2b) for the passive wheel: the model files' `[start]` with its
/// parameter `omega0`).
///
/// # Errors
/// The model has no start parameter `omega0`.
pub fn start(model: &Model, omega0: f64) -> Result<Vector, WriteError> {
    model
        .start_state_with("omega0", omega0)
        .map_err(setup_error)
}

/// The models of every `(chain, value)` of a sweep, built by `make` before any walk, as the
/// closure [`walker::sweep::sweep_chains`] takes.
///
/// # Errors
/// The first model that `make` cannot build.
pub fn grid(
    chains: &[f64],
    values: &[f64],
    make: impl Fn(f64, f64) -> Result<Model, WriteError>,
) -> Result<Box<dyn Fn(f64, f64) -> Model + Sync>, WriteError> {
    let mut models = Vec::with_capacity(chains.len());
    for &c in chains {
        let row = values
            .iter()
            .map(|&v| make(c, v))
            .collect::<Result<Vec<_>, _>>()?;
        models.push(row);
    }
    let (chains, values) = (chains.to_vec(), values.to_vec());
    Ok(Box::new(move |c: f64, v: f64| {
        let at = |xs: &[f64], x: f64| xs.iter().position(|y| y.to_bits() == x.to_bits());
        let (i, j) = (at(&chains, c).unwrap_or(0), at(&values, v).unwrap_or(0));
        models[i][j].clone()
    }))
}

/// The paper's Table 1 (with `g`), as the built-in scenes fix it: what the claims and the
/// figures compute their closed forms and scales from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Table1 {
    /// Mass of the rimless wheel `m1` (kg).
    pub m1: f64,
    /// Mass of the torso `m2` (kg).
    pub m2: f64,
    /// Leg length `l` (m).
    pub l: f64,
    /// Inertia moment of the wheel `I1` (kg m^2).
    pub i1: f64,
    /// Inertia moment of the torso `I2` (kg m^2).
    pub i2: f64,
    /// Gravitational acceleration `g` (m/s^2).
    pub g: f64,
    /// Angle between neighbouring spokes `alpha` (rad).
    pub alpha: f64,
}

impl Table1 {
    /// Table 1 from the built-in scene `active-level`.
    ///
    /// # Errors
    /// The scene does not load or lacks a parameter (a defect of the shipped files).
    pub fn load() -> Result<Table1, WriteError> {
        let s = Setup::active_level().map_err(setup_error)?;
        let get = |name: &str| {
            s.params
                .get(name)
                .ok_or_else(|| WriteError::Setup(format!("active-level has no parameter {name}")))
        };
        Ok(Table1 {
            m1: get("m1")?,
            m2: get("m2")?,
            l: get("l")?,
            i1: get("I1")?,
            i2: get("I2")?,
            g: get("g")?,
            alpha: get("alpha")?,
        })
    }

    /// Total mass `m_t = m1 + m2` (Eq. 2).
    #[must_use]
    pub fn total_mass(&self) -> f64 {
        self.m1 + self.m2
    }
}
