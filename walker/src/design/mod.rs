//! Gait design: the run-time parameters of a controller that make the best periodic gait on a
//! given floor, with the friction the gait needs as a constraint (`docs/design.md`).
//!
//! A design varies some run-time parameters `p` of a model within bounds and minimises an
//! [`Objective`] (specific resistance, mean input power, or the friction the gait needs; or
//! maximises its speed) of the periodic gait at `p`, subject to
//!
//! - a periodic gait: a fixed point `r*(p)` of the reduced Poincare map, found for each `p` by
//!   Newton's method with the map's state Jacobian ([`crate::poincare::newton`]: exact where the
//!   model's kernels differentiate every phase, else central differences), warm-started
//!   from the last design's fixed point (the *nested*, or reduced-space, formulation);
//! - stability with a margin: every multiplier's modulus `<= 1 - margin`;
//! - the foot held: the friction ratio `|lambda_t| / lambda_n` along the whole stance (sampled
//!   on the integrator's dense output) and the heel strike's impulse ratio `|Lambda_t| /
//!   Lambda_n`, each `<= mu0 - margin`;
//! - the normal force `lambda_n >= margin` along the stance;
//! - for a model with ramps in its desired trajectories, the strike at least a margin after
//!   the last ramp's end (`T - T_set >= margin`: a strike before it is no gait of the model);
//! - optionally, input bounds `max |u_i| <= U_i` along the stance (sampled as the friction);
//! - optionally, the swing foot's clearance: its height above the floor at least `H 4 s (1 -
//!   s)` at every interior stance sample, `s = t / T` ([`swing_height`]);
//! - optionally, a least mean speed `V >= V_min` and a most mean input power `p <= P` (the
//!   effort bound of the [`Objective::Speed`] objective, which maximises `V`).
//!
//! Under Coulomb friction the gait is that of the walker with its foot held (`mu0` raised out
//! of reach), so that the friction constraints are smooth in `p`; the stance's sampled ratios
//! enter as one Kreisselmeier-Steinhauser aggregate.
//!
//! The nonlinear program is solved by SLSQP (Kraft's sequential least squares programming, the
//! `slsqp` crate: NLopt's implementation in pure Rust). Its gradients are central differences
//! of the nested functions (each difference re-solves the fixed point): the module
//! [`crate::sensitivity`] gives `dr*/dp`, `dT/dp` and the multipliers' derivatives, but
//! neither the specific resistance's nor the path friction's, so the design takes all its
//! columns the same way (see `docs/design.md` for the argument and the cost). The result
//! ([`Design`]) carries the parameters, the gait, the objective, every constraint with its
//! slack, the solver's status and a KKT residual.

mod constraints;
mod error;
mod evaluate;
mod kkt;
mod request;
mod restarts;
mod result;
mod solve;
mod swing;

pub use error::DesignError;
pub use evaluate::{Evaluation, SAMPLES, evaluate};
pub use request::{DesignRequest, GaitBounds, Margins, Objective, Vary};
pub use restarts::{MAX_RESTARTS, design_with_restarts, restart_starts};
pub use result::{ConstraintSlack, Design, DesignStatus, Restart, VariedValue};
pub use solve::design;
pub use swing::{clearance_profile, rigid_strike_point, swing_height};
