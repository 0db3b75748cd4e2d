//! `walker reproduce`: the data of the paper's Figs. 3-8 and 10-14 as CSV files, the figures
//! as PNG and SVG, and a summary of the paper's claims with the values found.
//!
//! One concept per file: the paper's walkers at a given `mu0` ([`models`]), the experiments
//! behind the figures ([`data`], the passive wheel's sweeps in [`passive`]), their CSV files
//! ([`csv`]), one function per figure ([`figures`]), the animations of Figs. 5 and 14
//! ([`animations`]), the claims text ([`mod@summary`], with the claims of Sections 4 and 5 in
//! [`claims_active`] and [`claims_passive`] and the sweeps stated as ranges of `mu0` by
//! [`ranges`]), the Floquet stability along `mu0` ([`stability`]), the bifurcation diagrams by
//! continuation ([`bifurcation`]), the figure beside Fig. 8 (d) of `walker design --fig8`
//! ([`design_fig8`], not part of the job) and the whole job, writing
//! everything into one directory ([`job`]), or why it could not ([`error`]).
//!
//! Imports run one way: [`job`] -> [`bifurcation`], [`stability`], [`mod@summary`], [`figures`], [`csv`] ->
//! [`data`] -> [`passive`] -> [`models`] (and [`stability`] -> [`figures`], [`models`]; [`mod@summary`] ->
//! [`claims_passive`] -> [`claims_active`] -> [`ranges`]); the writers -> [`error`].

pub mod animations;
pub mod bifurcation;
pub mod claims_active;
pub mod claims_passive;
pub mod csv;
pub mod data;
pub mod design_fig8;
pub mod error;
pub mod figures;
pub mod job;
pub mod models;
pub mod passive;
pub mod ranges;
pub mod stability;
pub mod summary;

pub use data::{Data, OMEGAS, PHIS, T_SETS, collect};
pub use error::WriteError;
pub use job::run;
pub use summary::summary;
