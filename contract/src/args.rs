//! What a kernel call is given: the state and inputs ([`Args`]) and, for the output-following
//! control, what it tracks ([`Tracking`]).

use crate::desired::{Desired, aux_input};

/// The arguments of a kernel call: every kernel reads the ones it needs.
#[derive(Clone, Copy, Debug)]
pub struct Args<'a> {
    /// Coordinates `q`.
    pub q: &'a [f64],
    /// Velocities `qd`.
    pub qd: &'a [f64],
    /// Inputs `u` (the `accel` and `lambda` kernels of a model with inputs).
    pub u: &'a [f64],
    /// The sliding direction `sigma` under exact Coulomb friction (`mu = -mu0 sigma`); the
    /// tanh law reads the foot's velocity `qd[0]` instead.
    pub sigma: f64,
    /// The auxiliary inputs `v` of the output-following control (Eq. 32).
    pub v: &'a [f64],
}

impl<'a> Args<'a> {
    /// The state `(q, qd)` with no inputs, `sigma = 0` and no auxiliary inputs.
    #[must_use]
    pub fn state(q: &'a [f64], qd: &'a [f64]) -> Args<'a> {
        Args {
            q,
            qd,
            u: &[],
            sigma: 0.0,
            v: &[],
        }
    }
}

/// What the output-following control tracks at one instant (Eq. 32): the desired trajectories
/// (one per output), the time since the last impact and the gains.
#[derive(Clone, Copy, Debug)]
pub struct Tracking<'a> {
    /// The desired trajectories `y_d`, in output order.
    pub desired: &'a [Desired],
    /// The time `t` since the last impact.
    pub t: f64,
    /// The gains `(K_P, K_D)`.
    pub gains: (f64, f64),
}

impl Tracking<'_> {
    /// The auxiliary input `v_i` of output `i` at its value `y` and rate `ydot`:
    /// `ydd_d + K_D (yd_d - ydot) + K_P (y_d - y)` with `[y_d, yd_d, ydd_d] = desired[i](t)`.
    #[inline]
    #[must_use]
    pub fn aux_input(&self, i: usize, y: f64, ydot: f64) -> f64 {
        aux_input(
            self.desired[i].at(self.t),
            y,
            ydot,
            self.gains.0,
            self.gains.1,
        )
    }
}
