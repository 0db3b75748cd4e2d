//! The walker models: which generated kernels describe the stance phase and the impact, and the
//! parameters that go with them.
//!
//! Two setups of the paper are modelled: the active walker on level ground (Sections 2-4) and the
//! passive wheel on a slope (Section 5). Each exists in a fast variant with Table 1 compiled into
//! the kernels ([`crate::kernels::active_level`], [`crate::kernels::passive_slope`]) and a general
//! variant that takes every parameter at run time ([`crate::kernels::general_level`],
//! [`crate::kernels::general_slope`]) for scene files; both with the smooth friction law of
//! Eqs. 26 and 37. With exact Coulomb friction (Eq. 25, [`FrictionLaw::Coulomb`]) the foot
//! slides or sticks ([`Contact`]); those models use [`crate::kernels::general_level_coulomb`]
//! and [`crate::kernels::general_slope_coulomb`].
//!
//! Every physical quantity comes from a kernel; this module only dispatches.
//!
//! Files: [`Model`] and its dispatch (`dispatch.rs`), the contact vocabulary (`contact.rs`), the
//! impact map's result (`impact.rs`), the plastic impact with Coulomb friction at the striking
//! foot (`friction_impact.rs`), the change of stance leg after an impact (`reset.rs`).

mod contact;
mod dispatch;
mod friction_impact;
mod impact;
mod kind;
mod reset;

pub use crate::params::{Physical, Runtime};
pub use contact::{Contact, FrictionLaw, Reaction, Slide};
pub use dispatch::Model;
pub use friction_impact::{
    ImpactJam, ImpactRegime, Ingredients, in_regime, plastic_coulomb, rear_test,
};
pub use impact::ImpactResult;
pub use kind::Kind;
pub use reset::PostImpact;
pub use walker_scene::ImpactLaw;
