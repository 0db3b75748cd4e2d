//! Why the mesh cannot be built ([`MeshError`]).

use crate::poincare::FixedPointError;

use super::super::error::FloorError;

/// Why the Markov-chain approximation of a walker on a floor cannot be computed.
#[derive(Debug, thiserror::Error)]
pub enum MeshError {
    /// The floor cannot carry the walker.
    #[error(transparent)]
    Floor(#[from] FloorError),
    /// A `steps` floor (of `mu0` or of `phi`) lists values, it draws none: the chain needs a
    /// per-step distribution.
    #[error(
        "a `steps` floor has no per-step distribution for the mesh; give a `random` (or \
         `uniform`) floor"
    )]
    StepsFloor,
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
    #[error("no gait to mesh around at {quantity} = {value}: {source}")]
    NoGait {
        /// The floor's quantity the gait was sought at a value of (`phi` on a floor that sets
        /// the slope, else `mu0`).
        quantity: &'static str,
        /// Its value.
        value: f64,
        /// Why.
        #[source]
        source: FixedPointError,
    },
    /// No gait to mesh around: the fixed point did not converge or is not a valid gait.
    #[error("no gait to mesh around at {quantity} = {value}: the fixed point is {status}")]
    NotAGait {
        /// The floor's quantity the gait was sought at a value of (`phi`, `mu0`).
        quantity: &'static str,
        /// Its value.
        value: f64,
        /// Its status (`not converged`, `not a valid gait`).
        status: &'static str,
    },
}
