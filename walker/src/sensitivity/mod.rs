//! Parameter sensitivities of the Poincare map and of a gait.
//!
//! For a run-time parameter `p` of a model (one that neither a compiled variant nor the tape
//! fixes: [`crate::continuation::WalkerProblem::new`] names them), [`sensitivities`] gives at a
//! fixed point `r*` of the reduced map `P_r(r; p)`:
//!
//! - the map's parameter column `dP_r/dp` and `dT/dp` at fixed `r*` ([`Sensitivity::map_d_state`],
//!   [`Sensitivity::map_d_period`]);
//! - by the implicit function theorem the gait's sensitivities: `dr*/dp = (I - D P_r)^{-1}
//!   dP_r/dp`, the total `dT/dp`, `d(dx)/dp`, `dV/dp` (`V = dx / T`), and the multipliers'
//!   derivatives `d lambda_i / dp = u_i^H (dJ/dp) w_i / (u_i^H w_i)` for each simple eigenvalue
//!   of `J = D P_r` (left and right eigenvectors `u_i`, `w_i`), where `dJ/dp` is the total
//!   derivative along the branch of fixed points.
//!
//! # Method: exact columns where the parameter has them, else differences
//!
//! A parameter that enters the walker only through the friction law, the desired trajectories,
//! the gains and the section has **exact columns** ([`crate::poincare::parameter_column`]:
//! the variational equations with its column beside `Phi`); `exact.rs` takes `dP_r/dp`,
//! `dr*/dp` and the totals `dT/dp`, `d(dx)/dp` from two such integrations, and `dJ/dp` along the
//! branch from one Richardson difference along `(dr*/dp, 1)`. Every other parameter (one of the
//! mechanics, or a step through a phase without a Jacobian kernel) is **differenced**
//! (`compute.rs`): Richardson-extrapolated central differences in `p` of the map
//! (`difference.rs`); each column costs four map evaluations (`p +- h`, `p +- h/2`), with the
//! state Jacobian from the variational equations at each; the same four give `dT/dp`,
//! `d(dx)/dp` and `dJ/dp` at fixed `r*`. The dependence of `T`, `dx` and `J` on `r` (needed for
//! the total derivatives) comes from the same differences in each section coordinate the gait
//! moves in (four more evaluations per coordinate, shared by the differenced parameters).
//!
//! Every value carries an error estimate: an exact value `2 |c - c'| + 10 rtol |c|` (`c'` at a
//! tenth of the tolerances, as the state Jacobian's); a difference the difference between the
//! central differences at `h` and at `h/2` (three times the usual Richardson estimate, so that
//! it also covers the integrator's noise amplified by the extrapolation); propagated linearly
//! through the implicit function theorem; a multiplier's derivative carries the estimate of
//! `dJ/dp` (Frobenius norm) times the eigenvalue's condition number `1 / |u^H w|`. The maps are
//! evaluated at `rtol = min(rtol, 1e-12)`, `atol = min(atol, 1e-14)`. Accuracy and cost:
//! `docs/poincare.md`, "Parameter sensitivities".

mod compute;
mod difference;
mod error;
mod exact;
mod result;

pub use compute::{check_parameters, sensitivities};
pub use error::SensitivityError;
pub use result::{Estimate, MultiplierSensitivity, Sensitivity};
