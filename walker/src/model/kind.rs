//! Which floor and torso a model has.

use serde::Serialize;

/// Which floor and torso the model has.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Kind {
    /// The active walker on level ground (Sections 2-4).
    ActiveLevel,
    /// The passive wheel on a slope (Section 5).
    PassiveSlope,
}
