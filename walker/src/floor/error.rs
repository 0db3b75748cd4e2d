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
    /// The floor sets the slope, and the model has no slope angle (no `[floor] slope`).
    #[error(
        "model `{model}` has no slope angle (`[floor] slope`) for a floor's `phi` to set: its \
         floor is level"
    )]
    NoSlope {
        /// The model.
        model: String,
    },
    /// The floor sets the slope, and the model's stance foot enters its dynamics other than by
    /// a translation, so a step cannot be moved onto the model's floor through the origin
    /// (`docs/floors.md`, "A slope per step").
    #[error(
        "model `{model}` cannot walk on a slope per step: {what} depends on the stance foot's \
         position (its first two coordinates) other than by moving with it"
    )]
    NotTranslationInvariant {
        /// The model.
        model: String,
        /// The expression that is not invariant.
        what: String,
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
    #[error("floor `{name}` = {value}: {source}")]
    Kernels {
        /// The parameter (`mu0`, `phi`).
        name: &'static str,
        /// The value.
        value: f64,
        /// Why.
        #[source]
        source: NoKernels,
    },
}
