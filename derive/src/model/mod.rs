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
//! `control_check` (`A` regular at the start posture and somewhere at all); `events` (the
//! strike guard, the falls and the relabelling as kernels) uses `mechanics`.

mod assemble;
mod control_check;
mod events;
mod kernels;
mod lower;
mod maps;
mod mechanics;
mod phases;
mod program;
mod structured;
mod table;

pub use kernels::{MAX_INVERSE_TERMS, ModelDerivation};
pub use mechanics::{FloorGeometry, MAX_CLOSED_COORDINATES, Mechanics, time_derivative};
pub use phases::{
    ImpactMap, OutputControl, OutputMaps, Sliding, StrikeImpacts, StrikeRows, Stuck, impact_map,
    output_control, output_maps, sliding, strike_impacts, strike_rows, stuck,
};
pub use program::{Ldlt, Program};
pub use structured::{StructuredKernels, structured_kernels};
pub use table::ModelSymbols;
