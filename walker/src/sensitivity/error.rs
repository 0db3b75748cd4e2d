//! Why sensitivities cannot be computed.

use crate::poincare::MapError;

/// Why [`super::sensitivities`] failed.
#[derive(Debug, thiserror::Error)]
pub enum SensitivityError {
    /// The name is not a run-time parameter of the model (unknown, a start parameter, or one
    /// the friction law does not use).
    #[error(
        "sensitivities: {name} is not a run-time parameter of model `{model}` (valid: {known})"
    )]
    NotAParameter {
        /// The name asked for.
        name: String,
        /// The model.
        model: String,
        /// The valid names, comma-separated.
        known: String,
    },
    /// The model at a shifted parameter value cannot be built (out of the parameter's range,
    /// or its kernels cannot be prepared).
    #[error("sensitivities: the model at {name} = {value} cannot be built: {message}")]
    Model {
        /// The parameter.
        name: String,
        /// The shifted value.
        value: f64,
        /// Why.
        message: String,
    },
    /// The map failed at a point of a difference.
    #[error("sensitivities: the Poincare map fails at {at}: {source}")]
    Map {
        /// Where: the parameter or section coordinate shifted, with the shift.
        at: String,
        /// The map's error.
        #[source]
        source: MapError,
    },
    /// `I - D P_r` is singular at the fixed point (a multiplier at 1: a family of cycles), so
    /// the fixed point has no derivative in the parameter.
    #[error(
        "sensitivities: the fixed point is not isolated (a multiplier at 1), so it has no derivative in {name}"
    )]
    NotIsolated {
        /// The parameter.
        name: String,
    },
}
