//! The walkers of the gallery: each a shipped model (compiled into the `walker` library, so the
//! job reads no file), the slopes its sweeps chain over and where its walks start. Adding a
//! shipped model to the gallery is one line of [`ENTRIES`]; it gets the claims every model gets
//! ([`super::generic`]), and those of its own where [`super::summary`] names a module for it.

use walker::compiled::MODELS;
use walker::model::{Friction, ImpactLaw};
use walker::setup::{Setup, walker_of};

use crate::reproduce::WriteError;

/// Where every walk of a model's sweeps starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Start {
    /// The slope's held gait (its post-impact state, [`super::held`]): a passive walker's file
    /// starts it near its gait on one slope only, and the held gait is the gait on each.
    Held,
    /// The model's own `[start]`: for an actuated level walker whose file starts it on its gait
    /// at the defaults (the three-link biped's: its angles at their set values, its rates the
    /// cycle's to three digits; its gallery claims check that it lies on the cycle), the start
    /// its own tests walk from. Its stuck stance and sticking impact do not depend on `mu0`, so
    /// the held gait is the same cycle; from the file's start, the sweep sees where the walker
    /// the file describes fails.
    Own,
}

impl Start {
    /// The start in the text (`the slope's held gait`).
    #[must_use]
    pub fn phrase(self) -> &'static str {
        match self {
            Start::Held => "the slope's held gait",
            Start::Own => "its own start, on its gait",
        }
    }
}

/// One walker of the gallery.
#[derive(Clone, Copy, Debug)]
pub struct Entry {
    /// The shipped model's name (its file is `models/<name>.toml`).
    pub model: &'static str,
    /// Its name in the text (`compass gait`).
    pub title: &'static str,
    /// The slopes (rad) of the sweep's chains; empty, or a level walker: one chain at the
    /// model's own floor.
    pub slopes: &'static [f64],
    /// Where its walks start.
    pub start: Start,
}

impl Entry {
    /// The model `model`, called `title` in the text, on the slopes `slopes`, its walks
    /// started from the held gait.
    #[must_use]
    pub const fn new(model: &'static str, title: &'static str, slopes: &'static [f64]) -> Entry {
        Entry {
            model,
            title,
            slopes,
            start: Start::Held,
        }
    }

    /// The same entry with its walks started at `start`.
    #[must_use]
    pub const fn with_start(self, start: Start) -> Entry {
        Entry { start, ..self }
    }

    /// The model file's path in the repository, for the text.
    #[must_use]
    pub fn path(&self) -> String {
        format!("models/{}.toml", self.model)
    }

    /// The model as a scene of its own, its parameters at their defaults, under exact Coulomb
    /// friction in stance and at the impact (each sweep sets its laws).
    ///
    /// # Errors
    /// The model is not compiled in, or its file does not load (a defect of the shipped files).
    pub fn setup(&self) -> Result<Setup, WriteError> {
        let err = |e: &dyn std::fmt::Display| WriteError::Setup(format!("{}: {e}", self.model));
        let c = MODELS
            .iter()
            .find(|c| c.name == self.model)
            .ok_or_else(|| err(&"not a compiled model"))?;
        let file =
            walker_scene::model::Model::from_toml(c.source, &self.path()).map_err(|e| err(&e))?;
        let walker = walker_of(file, None).map_err(|e| err(&e))?;
        Ok(Setup {
            params: walker.defaults(),
            walker,
            name: self.model.to_owned(),
            friction: Friction::Coulomb,
            impact: ImpactLaw::Coulomb,
            fixed: Vec::new(),
        })
    }
}

/// Degrees to radians.
const fn deg(d: f64) -> f64 {
    d * std::f64::consts::PI / 180.0
}

/// The gallery's walkers, in the order of the summary: the two passive walkers on three slopes
/// each, and the three-link biped on its level floor from its own start.
pub const ENTRIES: &[Entry] = &[
    Entry::new("rimless-wheel", "rimless wheel", &[0.10, 0.15, 0.20]),
    Entry::new(
        "compass-gait",
        "compass gait",
        &[deg(2.0), deg(3.0), deg(4.0)],
    ),
    Entry::new("three-link", "three-link biped", &[]).with_start(Start::Own),
];
