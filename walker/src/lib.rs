//! `walker`: hybrid simulation and analysis of the underactuated rimless wheel with torso on
//! slippery ground, and of the passive wheel on a slope (Asano, Kikuchi, Shibata),
//! built on kernels generated from the symbolic derivation.

pub mod app;
pub mod control;
pub mod kernels;
pub mod model;
pub mod ode;
pub mod plot;
pub mod poincare;
pub mod progress;
pub mod reproduce;
pub mod sim;
pub mod sweep;
