//! The stance phase as an ODE system ([`Stance`]: the mechanical equations of motion and the
//! input-power quadrature, with their Jacobian) and the observer that samples the motion
//! ([`Recorder`]).

use crate::model::Model;
use crate::ode::{Observer, OdeSystem, Step};

use super::foot::{Foot, control_input, ground_reaction};
use super::frame::Frames;
use super::gait::Sample;
use super::state::{N, mech};

/// The stance phase of `model` with the foot `foot`, as an ODE system for [`crate::ode`].
pub(super) struct Stance<'a> {
    /// The model.
    pub(super) model: &'a Model,
    /// The generated Jacobian kernels (Table 1 models); `None` falls back to finite differences.
    pub(super) jac: Option<crate::jacobian::Jac>,
    /// The stance foot.
    pub(super) foot: &'a Foot<'a>,
}

impl OdeSystem<N> for Stance<'_> {
    fn rhs(&mut self, t: f64, y: &[f64; N], dy: &mut [f64; N]) {
        let (qdd, u) = self.model.stance(t, y, self.foot.contact());
        dy[..4].copy_from_slice(&y[4..8]);
        dy[4..8].copy_from_slice(&qdd);
        dy[8] = if self.model.is_active() && t < self.model.runtime.t_set {
            ((y[6] - y[7]) * u).abs()
        } else {
            0.0
        };
    }

    /// The error test watches the power quadrature (component 8) too, except on a step in
    /// which `ydot u` changes sign: its absolute value has a kink there, which would only
    /// cause rejections. Such a step is not kept: the kink is a terminal event of the stance
    /// integration ([`super::Guard::PowerKink`]), so the step is taken again ending on
    /// the kink, and the integration goes on from there, with a smooth integrand on each side.
    fn controlled_components(&mut self, t0: f64, y0: &[f64; N], t1: f64, y1: &[f64; N]) -> usize {
        if self.foot.crossed(t0, y0, t1, y1) {
            8
        } else {
            N
        }
    }

    /// The state Jacobian for the stiff integrator: `d qd / d y` is the identity block, and
    /// `d qdd / d y` comes from the generated kernels (`closed_loop_level_jacobian`,
    /// `accel_slope_jacobian`) with the chain rule through `mu(xd)` and `v(t, y, ydot)`. The
    /// power quadrature's row is `sign(ydot u) d(ydot u)/dy` with `u = -I2 th2dd` (the torso's
    /// only torque is `-u`, Eqs. 19-20; the derivation's tests check it).
    fn jacobian(&mut self, t: f64, y: &[f64; N], jac: &mut [[f64; N]; N]) -> bool {
        let Some(j) = self.jac else {
            return false;
        };
        let a = j.accel(self.model, t, y);
        for row in jac.iter_mut() {
            *row = [0.0; N];
        }
        for i in 0..4 {
            jac[i][4 + i] = 1.0;
            jac[4 + i][..8].copy_from_slice(&a[i]);
        }
        if self.model.is_active() && t < self.model.runtime.t_set {
            let ydot = y[6] - y[7];
            let u = control_input(self.model, t, y, self.foot.contact());
            let sign = (ydot * u).signum();
            let i2 = self.model.physical.i2;
            for k in 0..8 {
                jac[8][k] = -sign * ydot * i2 * a[3][k];
            }
            jac[8][6] += sign * u;
            jac[8][7] -= sign * u;
        }
        true
    }

    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        let ts = self.model.runtime.t_set;
        (self.model.is_active() && ts > t).then_some(ts)
    }
}

/// Records samples of the motion, if `out` is set: every accepted step's end and `interior`
/// points inside it; and frames at given times, if `frames` is set.
pub(super) struct Recorder<'a> {
    /// The stance foot.
    pub(super) foot: &'a Foot<'a>,
    /// Where the samples go.
    pub(super) out: Option<&'a mut Vec<Sample>>,
    /// The time of the step's start since the start of the walk.
    pub(super) t_offset: f64,
    /// The step number.
    pub(super) step: usize,
    /// Samples inside each accepted step.
    pub(super) interior: usize,
    /// Where the frames at given times go ([`super::trajectory()`]).
    pub(super) frames: Option<&'a mut Frames>,
}

impl Observer<N> for Recorder<'_> {
    fn wants_step(&mut self, _: f64, _: &[f64; N], _: f64, _: &[f64; N]) -> bool {
        self.out.is_some() || self.frames.is_some()
    }

    fn on_step(&mut self, st: &Step<'_, N>) {
        if let Some(frames) = self.frames.as_deref_mut() {
            frames.on_step(self.foot, self.t_offset, self.step, st);
        }
        let Some(out) = self.out.as_deref_mut() else {
            return;
        };
        let (model, contact) = (self.foot.model, self.foot.contact());
        let mut y = [0.0; N];
        for k in 1..=self.interior + 1 {
            let t =
                st.t_start() + (st.t_end() - st.t_start()) * k as f64 / (self.interior + 1) as f64;
            st.eval(t, &mut y);
            let u = control_input(model, t, &y, contact);
            let lambda = ground_reaction(model, t, &y, contact).lambda;
            if y.iter().all(|v| v.is_finite()) && lambda.is_finite() {
                out.push(Sample {
                    time: self.t_offset + t,
                    step: self.step,
                    state: mech(&y),
                    lambda,
                    u,
                });
            }
        }
    }
}
