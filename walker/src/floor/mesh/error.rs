//! Why the mesh cannot be built ([`MeshError`]).

use crate::poincare::FixedPointError;

use super::super::error::FloorError;

/// Why the Markov-chain approximation of a walker on a floor cannot be computed.
#[derive(Debug, thiserror::Error)]
pub enum MeshError {
    /// The floor cannot carry the walker.
    #[error(transparent)]
    Floor(#[from] FloorError),
    /// A `steps` floor lists values, it draws none: the chain needs a per-step distribution.
    #[error(
        "a `steps` floor has no per-step distribution for the mesh; give a `random` (or \
         `uniform`) floor"
    )]
    StepsFloor,
    /// The floor sets the slope per step: the section the mesh lives on depends on the slope
    /// of the step before (the rimless wheel's `th = phi - alpha/2`), which the chain's state
    /// does not carry yet.
    #[error(
        "the mesh takes a floor of friction only: a floor that sets `phi` per step moves the          Poincare section with the slope of the step before, which the chain does not carry;          use `walker survive` for it"
    )]
    SlopeFloor,
    /// A floor of patches gives `mu0` by position along the floor, not per step: the chain's
    /// step-to-step map has no floor sample to draw.
    #[error(
        "a `patches` floor gives mu0 by position, not per step: the mesh needs a per-step \
         distribution; it is deterministic, so `walker simulate` walks it (one walk is the \
         whole story)"
    )]
    PatchesFloor,
    /// A setting outside its range.
    #[error("mesh field `{field}` = {value}: must be {range}")]
    OutOfRange {
        /// The setting (`points`, `samples`, `box_scale`, `half_widths`).
        field: &'static str,
        /// The value given, as text.
        value: String,
        /// The valid range.
        range: String,
    },
    /// The mesh would be too large to build.
    #[error("mesh field `{field}`: {count} {what} (at most {limit}); use fewer points or samples")]
    TooLarge {
        /// The setting that makes it so (`points`, `samples`).
        field: &'static str,
        /// What is counted.
        what: &'static str,
        /// How many there would be.
        count: u128,
        /// The most allowed.
        limit: u64,
    },
    /// No gait to mesh around: the fixed-point search failed.
    #[error("no gait to mesh around at mu0 = {mu0}: {source}")]
    NoGait {
        /// The floor value the gait was sought at.
        mu0: f64,
        /// Why.
        #[source]
        source: FixedPointError,
    },
    /// No gait to mesh around: the fixed point did not converge or is not a valid gait.
    #[error("no gait to mesh around at mu0 = {mu0}: the fixed point is {status}")]
    NotAGait {
        /// The floor value the gait was sought at.
        mu0: f64,
        /// Its status (`not converged`, `not a valid gait`).
        status: &'static str,
    },
}
