//! Placeholder.

pub mod ode;
