//! Any walker from its model file (`docs/model-format.md`): its symbol table, its expressions
//! in the canonical form, and its mechanics derived as the paper derives its own walker.
//!
//! Files, imports one way: `table` (the model's symbols interned in the engine's table) and
//! `lower` (expressions into rational functions, `sin`/`cos` by the addition formulas over the
//! model's base angles) know the model file's types; `mechanics` (energies, `M`, `h`, `S`,
//! points, the stance contact) uses them; `phases` (sliding and stuck stance, output control,
//! impact maps) uses `mechanics`; `program` (a structured solve as a straight-line program of
//! locals: `L D L^T`, substitutions) knows only the engine; `structured` (the stance and impact
//! kernels as structured solves) uses `mechanics`, `phases` and `program`; `kernels` (the named
//! kernels the code generator reads, closed form and structured solve) uses `phases`,
//! `structured`, `maps` (the matrices `S`, `J_I`, `H` as kernels, for users and for checks
//! by generic linear algebra), `assemble` (output names and arguments of a kernel) and
//! `control_check` (`A` regular at the start posture and somewhere at all), and the kernels of
//! their own files: `stick_control` (the control with the foot stuck, `closed_loop_stick`, both
//! forms), `coulomb` (the impact with Coulomb friction's ingredients, `impact_coulomb`, both
//! forms), `jacobians` (the closed forms' partial derivatives, and the structured solves' by
//! `forward`, forward-mode differentiation of a program) and `descriptors` (output and
//! input rates, the total mass); `events` (the strike guard, the falls and the relabelling as
//! kernels) uses `mechanics`.

mod assemble;
mod control_check;
mod coulomb;
mod descriptors;
mod events;
mod forward;
mod jacobians;
mod kernels;
mod located;
mod lower;
mod maps;
mod mechanics;
mod multiples;
mod phases;
mod program;
mod stick_control;
mod structured;
mod table;

pub(crate) use assemble::named;
pub(crate) use coulomb::coulomb_outputs;
pub use coulomb::{CoulombImpact, CoulombRows, coulomb_impact, coulomb_rows};
pub use jacobians::MAX_STRUCTURED_JACOBIAN_COORDINATES;
pub use kernels::{MAX_INVERSE_TERMS, ModelDerivation};
pub use mechanics::{FloorGeometry, MAX_CLOSED_COORDINATES, Mechanics, time_derivative};
pub use multiples::{MAX_ANGLE_MULTIPLE, check_angle_multiples};
pub use phases::{
    ImpactMap, OutputControl, OutputMaps, Sliding, StrikeImpacts, StrikeRows, Stuck, impact_map,
    output_control, output_maps, sliding, strike_impacts, strike_rows, stuck,
};
pub use program::{Ldlt, Program};
pub use stick_control::stuck_control;
pub use structured::{StructuredKernels, structured_kernels};
pub use table::ModelSymbols;
