//! Why a floor cannot carry a walker ([`FloorError`]).

use crate::model::NoKernels;

/// Why a walker cannot walk on a floor.
#[derive(Debug, thiserror::Error)]
pub enum FloorError {
    /// The model has no friction coefficient (no `[stance] mu0` parameter) for a floor to set.
    #[error("model `{model}` has no friction coefficient (`[stance] mu0`) for a floor to set")]
    NoFriction {
        /// The model.
        model: String,
    },
    /// The walk runs without friction (`--friction none`): a floor's `mu0` would be ignored.
    #[error(
        "the friction law is `none`: a floor sets `mu0`, which that law ignores; use tanh or coulomb"
    )]
    Frictionless,
    /// The scene fixes the friction coefficient at generation: it is no run-time parameter.
    #[error(
        "the scene fixes `{name}` = {value} at generation ([fix]); a floor sets `{name}` per \
         step, so it must be a run-time parameter: move it to the scene's [set]"
    )]
    Fixed {
        /// The parameter.
        name: String,
        /// Its fixed value.
        value: f64,
    },
    /// A value the floor gives a step is outside the range the model file gives the parameter.
    #[error(
        "floor field `{field}` = {value}: outside the range {range} of `{name}` in model `{model}`"
    )]
    OutOfRange {
        /// The floor's field (`mu0`, `mu0[2]`, `mu0.hi`).
        field: String,
        /// The value.
        value: f64,
        /// The parameter.
        name: String,
        /// Its valid range.
        range: String,
        /// The model.
        model: String,
    },
    /// The walker's kernels cannot take a value the floor gives (a compiled variant that fixes
    /// the friction coefficient).
    #[error("floor `mu0` = {value}: {source}")]
    Kernels {
        /// The value.
        value: f64,
        /// Why.
        #[source]
        source: NoKernels,
    },
}
