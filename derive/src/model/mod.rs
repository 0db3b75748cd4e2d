//! Any walker from its model file (`docs/model-format.md`): its symbol table, its expressions
//! in the canonical form, and its mechanics derived as the paper derives its own walker.
//!
//! Files, imports one way: `table` (the model's symbols interned in the engine's table) and
//! `lower` (expressions into rational functions, `sin`/`cos` by the addition formulas over the
//! model's base angles) know the model file's types; `mechanics` (energies, `M`, `h`, `S`,
//! points, the stance contact) uses them; `phases` (sliding and stuck stance, output control,
//! impact maps) uses `mechanics`; `kernels` (the named kernels the code generator reads) uses
//! `phases`.

mod kernels;
mod lower;
mod mechanics;
mod phases;
mod table;

pub use kernels::{MAX_INVERSE_TERMS, ModelDerivation};
pub use mechanics::{FloorGeometry, Mechanics, time_derivative};
pub use phases::{
    ImpactMap, OutputControl, Sliding, StrikeImpacts, Stuck, impact_map, output_control, sliding,
    strike_impacts, stuck,
};
pub use table::ModelSymbols;
