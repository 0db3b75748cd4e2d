//! `walker continue`: the flags turned into a continuation problem of the library
//! ([`request`]), the branches as text, JSON and CSV ([`output`]), and bifurcation diagrams
//! ([`diagram`], also drawn by `walker reproduce`).

pub mod diagram;
pub mod output;
pub mod request;

pub use request::{ContinueError, Request, run};
