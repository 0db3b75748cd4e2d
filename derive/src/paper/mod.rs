//! The paper's walker (Asano, Kikuchi, Shibata) in the paper's notation: its symbol table's
//! shorthands, the desired output `y_d`, the impact posture, and every quantity the paper
//! derives, taken from the model files `models/paper-active.toml` and
//! `models/paper-passive.toml` by the model derivation ([`crate::model`]), the one source of
//! the walker's mechanics.
//!
//! Files, imports one way: `table` (the paper's symbol table and its constants, `Sym::Th1`,
//! ...) stands alone; `notation` (symbols as expressions, constants, `m_t`, `I_t`, the time
//! derivative) uses it; `output` (the quintic `y_d` of Section 3.2) and `posture` (the impact
//! posture and the paper's pre-impact state) use `notation`; `quantities` (the model files'
//! derivation in the paper's table) uses the model derivation only; `derivation` (the paper's
//! kernels, the catalogue of its scenes and of `docs/equations.md`) uses `quantities` and
//! `notation`.

mod derivation;
mod notation;
mod output;
mod posture;
mod quantities;
mod table;

/// The floor the stance foot slides on: level ground `z = 0` (Section 3) or a slope of angle
/// `phi` descending towards `+x`, `z = -x tan phi` (Section 5). The shared vocabulary's
/// [`walker_scene::Floor`].
pub use walker_scene::Floor;

pub use crate::trig::{cos, sin};
pub use derivation::Derivation;
pub use notation::{
    Q_SYMS, QD_SYMS, QDD_SYMS, frac, int, sin_half_alpha, sym, tan_phi, time_derivative,
    total_inertia, total_mass,
};
pub use output::{check_desired_output, desired_output};
pub use posture::{at_impact_posture, paper_pre_impact};
pub use quantities::{Contact, Control, Dynamics, Geometry, PaperQuantities, Stance};
