//! Limit cycles: the Poincare map on the post-impact section, its Jacobian by the variational
//! equations, fixed points by Newton's method, and their Floquet multipliers.
//!
//! # The map
//!
//! [`poincare_map`] takes the state right after an impact and reset (time 0 of a step) and
//! returns the state right after the next impact and reset: one step of the hybrid walker, the
//! same stance dynamics as [`crate::sim`] (`u` of Eq. 31, `qdd` from the model's kernels), the
//! same heel-strike event and the same impact and reset. The output is measured from the new
//! stance foot: `x` and `z` are cyclic (no acceleration, event or impact depends on them), so the
//! map sets them to zero (the reduction of the translation).
//!
//! # The Jacobian
//!
//! The sensitivity `Phi' = Df Phi` is integrated alongside the state with the same integrator,
//! under the same error control: the 8x8 `Phi` from `Phi(0) = I` for the full Jacobian
//! ([`poincare_map`], 64 extra components), or its columns along the section's tangent `E`
//! from `Phi(0) E` ([`Section::map`], 16 for the paper's walkers), all the reduced Jacobian
//! `Pi DP E` needs. `Df` comes from
//! the generated Jacobian kernels (`closed_loop_level_jacobian`, `accel_slope_jacobian`) with the
//! chain rule through `mu(xd)` (`dmu/dxd = -mu0 c (1 - tanh^2)`, with `c / cos phi` on the slope)
//! and through `v(t, y, ydot)` of Eq. 32 (`dv/dy = -K_P`, `dv/dydot = -K_D`). The `T_set`
//! breakpoint splits the integration; `Phi` is continuous there. At the heel strike
//! (`g = th1 - alpha/2 - phi`) the saltation correction `Phi+ = (I - f g_y^T / (g_y . f)) Phi`
//! is applied, then the Jacobian of the impact map (generated `impact2_level_jacobian` /
//! `impact_slope_jacobian`) and of the reset. The reset's Jacobian is analytic from the
//! fore-foot geometry of `docs/kernels.md` (`xd_f = xd + l th1d (cos th1 - cos(th1 - alpha))`,
//! `zd_f = zd - l th1d (sin th1 - sin(th1 - alpha))`; positions: `th1+ = th1 - alpha`,
//! `x+ = z+ = 0` after the reduction); a test checks it against the `fore_foot` kernel.
//!
//! Every other model and friction law takes the same path wherever its kernels differentiate
//! the phases a step goes through (`variational.rs`): exact Coulomb friction's sliding phases
//! (`mu = -mu0 sigma`, constant) and stuck phases (`stick_jacobian`), with the saltation matrix
//! at each event that switches the phase (a foot comes to rest, a foot starts to slip), and the
//! impact's Jacobian in the regime it takes (`impact_jacobian.rs`). Central differences
//! ([`poincare_map_with`] with [`JacobianMethod::FiniteDifferences`],
//! [`finite_difference_map_with_step`]) remain the independent check and the fallback where a
//! phase has no Jacobian kernel. Method and accuracy: `docs/poincare.md`.
//!
//! # Coordinates of the fixed-point problem
//!
//! The full 8x8 map has trivial multipliers: `x`, `z` (reduced to zero: multiplier 0), `th1`
//! (fixed by the event: 0), the impact constraints (`zd+ = 0` on level ground, `zd+ + xd+ tan phi
//! = 0` on the slope, the torso lock `th1d+ = th2d+` of the active walker: 0 each), and the torso
//! for the passive wheel (its centre of mass is at the hip, so nothing acts on it: `th2` and
//! `th2d` give a Jordan block at 1). For the active walker with `K_P = K_D = 0` (the paper) the
//! output offset `y + alpha/2` at the section is neutral (`yddot = yd_dd` exactly, so an offset
//! persists): a multiplier at 1 that belongs to the controller, not to the gait; with positive
//! gains it is the tracking error's contraction.
//!
//! Newton's method therefore works in the two independent coordinates `r = (xd+, th1d+)` of the
//! section restricted to the controller's invariant manifold `y = -alpha/2, ydot = 0`
//! (active walker: `th1 = -alpha/2`, `th2 = 0`, `th2d = th1d`, `z = zd = 0`; passive wheel:
//! `th1 = phi - alpha/2`, `th2 = th2d = 0`, `zd = -xd tan phi`), see [`Section::embed`]. The reduced
//! Jacobian `D P_r = Pi DP E` (`E` = [`Section::tangent`], `Pi` picks `xd`, `th1d`) has the gait's
//! two Floquet multipliers; [`FixedPoint::full_multipliers`] lists all eight for reference.
//!
//! For `mu0 = 0` the horizontal momentum is conserved in stance and at the impacts (no horizontal
//! force and a frictionless impulse), so the active walker has a one-parameter family of cycles
//! (Fig. 4: the speed depends on `omega0`) and `D P_r` has an exact multiplier at 1 everywhere.
//! This is detected (a multiplier within [`UNIT_MULTIPLIER_TOL`] of 1) and Newton's method takes
//! least-norm steps (truncated SVD), which converge to the family member nearest to the guess.

mod accuracy;
mod continuation;
mod error;
mod finite_difference;
mod fixed_point;
mod impact_jacobian;
mod map;
mod multipliers;
mod parameter;
mod result;
mod section;
mod variational;

pub(crate) use accuracy::error_estimate;
pub use accuracy::{
    EstimatedJacobian, MultiplierBound, jacobian_error, multiplier_bounds, multiplier_errors,
};
pub use continuation::{ContinuationPoint, continuation};
pub use error::{FixedPointError, MapError};
pub use finite_difference::finite_difference_map_with_step;
pub use fixed_point::{FixedPoint, FixedPointOptions, Status, fixed_point, newton};
pub use map::{
    ParameterColumn, parameter_column, poincare_map, poincare_map_along, poincare_map_with,
};
pub(crate) use multipliers::{Eigenvectors, eigenvectors};
pub use multipliers::{Multiplier, UNIT_MULTIPLIER_TOL, eigenvalues};
pub use result::{JacobianMethod, MapResult, StepCheck};
pub use section::Section;
