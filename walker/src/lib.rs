//! `walker`: hybrid simulation and analysis of the underactuated rimless wheel with torso on
//! slippery ground, and of the passive wheel on a slippery slope (Asano, Kikuchi, Shibata),
//! built on kernels generated from the symbolic derivation.

pub mod kernels;
pub mod ode;
