//! Placeholder.

/// Adaptive ODE integrators (DOPRI5, DOP853, RODAS) with dense output, events and breakpoints.
pub mod ode;
