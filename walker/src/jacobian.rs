//! The state Jacobians of the stance dynamics and of the impact map, from the generated
//! Jacobian kernels: what the stiff integrator and the Poincare map's variational equations
//! need.

use crate::control;
use crate::kernels::{active_level, passive_slope};
use crate::model::{FrictionLaw, Kind, Model, Physical};
use crate::params;

/// Why a model has no generated Jacobian kernels.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum NoJacobian {
    /// The physical parameters are not Table 1's.
    #[error("the Jacobian kernels are generated for the Table 1 parameters only")]
    NotTable1,
    /// The friction law is not the tanh law.
    #[error("the Jacobian kernels are generated for the tanh friction law only")]
    NotTanh,
}

/// The Jacobian kernels matching a model. They are generated for the Table 1 scenes only
/// (`active_level`, `passive_slope`), so models with other physical parameters are refused; a
/// general-kernel model with Table 1 values uses them (they agree with the general kernels to
/// rounding).
#[allow(
    clippy::large_enum_variant,
    reason = "built once per map evaluation and read on every right-hand side"
)]
#[derive(Clone, Copy, Debug)]
pub(crate) enum Jac {
    ActiveLevel(active_level::Prepared),
    PassiveSlope(passive_slope::Prepared),
}

impl Jac {
    pub(crate) fn new(m: &Model) -> Result<Self, NoJacobian> {
        let r = m.runtime;
        if m.physical != Physical::TABLE1 {
            return Err(NoJacobian::NotTable1);
        }
        if m.friction_law() != FrictionLaw::Tanh {
            return Err(NoJacobian::NotTanh);
        }
        Ok(match m.kind() {
            Kind::ActiveLevel => Jac::ActiveLevel(active_level::prepare(
                &active_level::Params::from_fn(|name| params::by_name(&Physical::TABLE1, &r, name)),
            )),
            Kind::PassiveSlope => {
                Jac::PassiveSlope(passive_slope::prepare(&passive_slope::Params::from_fn(
                    |name| params::by_name(&Physical::TABLE1, &r, name),
                )))
            }
        })
    }

    /// `d qdd_i / d y_j` (`y` the mechanical state) at `(t, y)`, chain rule through `mu(xd)` and
    /// `v(t, y, ydot)` included.
    pub(crate) fn accel(&self, model: &Model, t: f64, y: &[f64]) -> [[f64; 8]; 4] {
        let (th1, th2, xd, th1d, th2d) = (y[2], y[3], y[4], y[6], y[7]);
        let r = model.runtime;
        let mut out = [[0.0; 8]; 4];
        let level = |j: [[f64; 4]; 4], out: &mut [[f64; 8]; 4]| {
            let th = (r.c * xd).tanh();
            let dmu = -r.mu0 * r.c * (1.0 - th * th);
            for (row, ji) in out.iter_mut().zip(j) {
                row[2] = ji[0] - ji[3] * r.k_p;
                row[3] = ji[3] * r.k_p;
                row[4] = ji[2] * dmu;
                row[6] = ji[1] - ji[3] * r.k_d;
                row[7] = ji[3] * r.k_d;
            }
        };
        let slope = |j: [[f64; 3]; 4], out: &mut [[f64; 8]; 4]| {
            let cphi = r.phi.cos();
            let th = (r.c * xd / cphi).tanh();
            let dmu = -r.mu0 * r.c / cphi * (1.0 - th * th);
            for (row, ji) in out.iter_mut().zip(j) {
                row[2] = ji[0];
                row[4] = ji[2] * dmu;
                row[6] = ji[1];
            }
        };
        let v = || {
            let d = model.desired(t);
            control::aux_input(d, th1 - th2, th1d - th2d, r.k_p, r.k_d)
        };
        match self {
            Jac::ActiveLevel(p) => level(
                active_level::closed_loop_level_jacobian(p, th1, th1d, xd, v()),
                &mut out,
            ),
            Jac::PassiveSlope(p) => slope(
                passive_slope::accel_slope_jacobian(p, th1, th1d, xd),
                &mut out,
            ),
        }
        out
    }

    /// `d qd+_i / d (th1, xd, zd, th1d, th2d)` of the applied impact map.
    pub(crate) fn impact(&self, s: &[f64; 8]) -> [[f64; 5]; 4] {
        let (th1, xd, zd, th1d, th2d) = (s[2], s[4], s[5], s[6], s[7]);
        match self {
            Jac::ActiveLevel(p) => active_level::impact2_level_jacobian(p, th1, xd, zd, th1d, th2d),
            Jac::PassiveSlope(p) => {
                passive_slope::impact_slope_jacobian(p, th1, xd, zd, th1d, th2d)
            }
        }
    }
}
