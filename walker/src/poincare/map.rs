//! The Poincare map on the post-impact section with its Jacobian: the stance phase with the
//! variational equations appended ([`Variational`]), the saltation correction at the heel
//! strike, and the Jacobians of the impact and of the reset.

use nalgebra::SMatrix;
use serde::Serialize;

use crate::jacobian::Jac;
use crate::model::{Contact, ImpactRegime, Model};
use crate::ode::{
    Direction, Event, GaveUp, Integrator, NoObserver, OdeSystem, Outcome, Tolerances,
};
use crate::sim::SimConfig;

use super::error::MapError;
use super::finite_difference::finite_difference_map;
use super::impact_jacobian::coulomb_impact_jacobian;

/// Size of the integrated state: 8 mechanical components and the 8x8 sensitivity matrix.
const NA: usize = 8 + 64;

/// An 8x8 matrix (nalgebra, on the stack).
type M8 = SMatrix<f64, 8, 8>;

/// The stance phase with the variational equations appended.
struct Variational<'a> {
    model: &'a Model,
    jac: Jac,
}

impl Variational<'_> {
    fn mech_rhs(&self, t: f64, y: &[f64]) -> [f64; 8] {
        let (qdd, _) = self.model.stance(t, y, Contact::Smooth);
        [y[4], y[5], y[6], y[7], qdd[0], qdd[1], qdd[2], qdd[3]]
    }
}

impl OdeSystem<NA> for Variational<'_> {
    fn rhs(&mut self, t: f64, y: &[f64; NA], dy: &mut [f64; NA]) {
        dy[..8].copy_from_slice(&self.mech_rhs(t, y));
        let a = self.jac.accel(self.model, t, y);
        for j in 0..8 {
            for i in 0..4 {
                dy[8 + 8 * i + j] = y[8 + 8 * (i + 4) + j];
                let mut s = 0.0;
                for (k, aik) in a[i].iter().enumerate() {
                    s += aik * y[8 + 8 * k + j];
                }
                dy[8 + 8 * (i + 4) + j] = s;
            }
        }
    }

    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        let ts = self.model.runtime.t_set;
        (self.model.is_active() && ts > t).then_some(ts)
    }
}

/// One evaluation of the Poincare map.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MapResult {
    /// The next post-impact state `[x, z, th1, th2, xd, zd, th1d, th2d]`, measured from the new
    /// stance foot (`x = z = 0`).
    pub state_plus: [f64; 8],
    /// The step period `T` (s).
    pub period: f64,
    /// The step length (Eq. 34; along the slope, Eq. 47) (m).
    pub dx: f64,
    /// `d state_plus_i / d state_j` (row `i`, column `j`).
    pub jacobian: [[f64; 8]; 8],
    /// How the Jacobian was computed.
    pub method: JacobianMethod,
    /// How the striking foot ended the impact.
    pub impact: ImpactRegime,
}

/// How the Poincare map's Jacobian is computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum JacobianMethod {
    /// Variational equations with the generated Jacobian kernels (the module documentation).
    Variational,
    /// Central differences of one simulated step ([`super::finite_difference`]).
    FiniteDifferences,
}

/// One step of the hybrid walker from the post-impact state `s` (time 0), with its Jacobian
/// (see the module documentation). Failures of the stance phase (no heel strike within
/// [`SimConfig::max_step_time`], integrator failures, non-finite values) are errors; the
/// physical validity tests of [`crate::sim`] (lift-off, double support) are not applied here.
/// Models without generated Jacobian kernels (exact Coulomb friction in stance, physical
/// parameters other than Table 1's) take one step of the simulator instead and their Jacobian by
/// central differences ([`super::finite_difference`]).
pub fn poincare_map(model: &Model, cfg: &SimConfig, s: &[f64; 8]) -> Result<MapResult, MapError> {
    if !s.iter().all(|v| v.is_finite()) {
        return Err(MapError::NonFiniteStart);
    }
    let Ok(jac) = Jac::new(model) else {
        return finite_difference_map(model, cfg, s);
    };
    let mut y = [0.0; NA];
    y[..8].copy_from_slice(s);
    for i in 0..8 {
        y[8 + 9 * i] = 1.0;
    }
    let heel = model.heel_strike_angle();
    let mut events = [Event::terminal(
        Direction::Rising,
        move |_, y: &[f64; NA]| y[2] - heel,
    )];
    let mut sys = Variational { model, jac };
    let mut integ = Integrator::<NA>::new(cfg.method, Tolerances::new(cfg.rtol, cfg.atol));
    let mut t = 0.0;
    // One budget of attempted steps for the whole stance phase, as in the simulation
    // (`sim/step.rs`): each call after a breakpoint gets what the earlier ones left, and every
    // call spends at least one attempt, so the loop ends with `TooManySteps` at the latest.
    let budget = integ.config().max_steps;
    let (te, ye) = loop {
        let spent = integ.stats().accepted_steps + integ.stats().rejected_steps;
        integ.config_mut().max_steps =
            budget.saturating_sub(usize::try_from(spent).unwrap_or(usize::MAX));
        match integ.integrate(
            &mut sys,
            t,
            &y,
            cfg.max_step_time,
            &mut events,
            &mut NoObserver,
        ) {
            Outcome::Breakpoint { t: tb, y: yb } => {
                t = tb;
                y = yb;
            }
            Outcome::Event { t, y, .. } => break (t, y),
            Outcome::Reached { t, .. } => return Err(MapError::NoHeelStrike { t }),
            Outcome::NonFinite { t, .. } => return Err(MapError::NonFinite { t }),
            Outcome::StepSizeTooSmall { t, h, .. } => {
                let cause = GaveUp::StepSizeTooSmall { h };
                return Err(MapError::Integrator { t, cause });
            }
            Outcome::MaxSteps { t, .. } => {
                let cause = GaveUp::TooManySteps;
                return Err(MapError::Integrator { t, cause });
            }
            Outcome::InvalidInput { t, reason, .. } => {
                let cause = GaveUp::InvalidInput(reason);
                return Err(MapError::Integrator { t, cause });
            }
        }
    };
    let mut pre = [0.0; 8];
    pre.copy_from_slice(&ye[..8]);
    let mut phi = M8::from_fn(|i, j| ye[8 + 8 * i + j]);
    // Saltation: g = th1 - heel, g_y = e_2, g_y . f = th1d.
    let f = sys.mech_rhs(te, &ye);
    if f[2].abs() < 1e-12 {
        return Err(MapError::GrazingHeelStrike { t: te });
    }
    let g_row = phi.row(2).into_owned();
    for i in 0..8 {
        for j in 0..8 {
            phi[(i, j)] -= f[i] * g_row[j] / f[2];
        }
    }
    // Impact: positions unchanged, velocities from the impact kernel.
    let imp = model
        .impact(&pre)
        .map_err(|_| MapError::NonFiniteImpact { t: te })?;
    let k = match imp.regime {
        ImpactRegime::Frictionless => sys.jac.impact(&pre),
        regime => coulomb_impact_jacobian(model, &pre, regime)
            .ok_or(MapError::NonFiniteImpact { t: te })?,
    };
    let mut dimp = M8::zeros();
    for i in 0..4 {
        dimp[(i, i)] = 1.0;
    }
    const COLS: [usize; 5] = [2, 4, 5, 6, 7];
    for i in 0..4 {
        for (c, &col) in COLS.iter().enumerate() {
            dimp[(4 + i, col)] = k[i][c];
        }
    }
    // Reset to the new stance leg (the simulator's own, `Model::reset`), then measured from the
    // new foot: `x` and `z` are cyclic and reduced to zero.
    let post = model.reset(&pre, &imp);
    let (th1, th1d) = (pre[2], imp.qd[2]);
    let (l, alpha) = (model.physical.l, model.physical.alpha);
    let cs = th1.cos() - (th1 - alpha).cos();
    let sn = th1.sin() - (th1 - alpha).sin();
    let mut dres = M8::zeros();
    dres[(2, 2)] = 1.0;
    dres[(3, 3)] = 1.0;
    dres[(4, 2)] = -l * th1d * sn;
    dres[(4, 4)] = 1.0;
    dres[(4, 6)] = l * cs;
    dres[(5, 2)] = -l * th1d * cs;
    dres[(5, 5)] = 1.0;
    dres[(5, 6)] = -l * sn;
    dres[(6, 6)] = 1.0;
    dres[(7, 7)] = 1.0;
    // nalgebra's product sums each entry over `k` in ascending order, as the hand-written loop
    // it replaced did (`walker/benches/linalg.rs`: as fast, 120 ns against 127 ns).
    let product = dres * (dimp * phi);
    let jacobian: [[f64; 8]; 8] = product.transpose().into();
    let [_, _, th1_plus, th2_plus] = post.q_plus;
    let [xd_plus, zd_plus, th1d_plus, th2d_plus] = post.qd_plus;
    let state_plus = [
        0.0, 0.0, th1_plus, th2_plus, xd_plus, zd_plus, th1d_plus, th2d_plus,
    ];
    let dx = (post.q_plus[0] - s[0]) / model.runtime.phi.cos();
    let ok = state_plus
        .iter()
        .chain(jacobian.iter().flatten())
        .all(|v| v.is_finite());
    if !ok || !dx.is_finite() {
        return Err(MapError::NonFiniteImpact { t: te });
    }
    Ok(MapResult {
        state_plus,
        period: te,
        dx,
        jacobian,
        method: JacobianMethod::Variational,
        impact: imp.regime,
    })
}
