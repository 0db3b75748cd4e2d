//! `walker gallery`: the shipped walkers that walk (the rimless wheel, the compass gait and the
//! three-link biped) on a slippery floor as `mu0` falls, in the manner of the paper's Figs. 8
//! and 10: where they still walk, how they fail and why, as CSV files, figures and a table of
//! claims that the run checks.
//!
//! One concept per file: the walkers and their slopes ([`entries`]), the contact laws
//! ([`laws`]), the held gait and the friction it needs ([`held`]), the sweeps ([`data`]), what
//! became of a walk ([`outcome`]), a designed gait beside the hand-made one ([`designed`]), a claim and its verdict ([`claims`]), the claims every model
//! gets ([`generic`]) and each model's own ([`rimless`], [`compass`], [`three_link`]), the CSV
//! files ([`csv`]), the figures ([`figures`]), the bifurcation diagrams by continuation and
//! their claims ([`bifurcation`]), the summary ([`mod@summary`]) and the whole job ([`job`]). The figures, CSV and error machinery are `walker reproduce`'s
//! ([`crate::reproduce`], [`crate::plot`]).
//!
//! Imports run one way: [`job`] -> [`mod@summary`] -> [`generic`], [`rimless`], [`compass`],
//! [`three_link`], [`bifurcation`] -> [`claims`] (and [`bifurcation`] -> [`entries`]); those and [`figures`], [`csv`] -> [`data`] -> [`entries`],
//! [`designed`], [`held`], [`outcome`], [`laws`] (and [`designed`] -> [`held`] -> [`laws`]).

pub mod bifurcation;
pub mod claims;
pub mod compass;
pub mod csv;
pub mod data;
pub mod designed;
pub mod entries;
pub mod figures;
pub mod generic;
pub mod held;
pub mod job;
pub mod laws;
pub mod outcome;
pub mod rimless;
pub mod summary;
pub mod three_link;

pub use job::run;
