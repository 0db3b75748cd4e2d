//! One step of a smooth-friction walker from a post-impact state without the variational
//! equations (the cheap map of the corrector), with the smallest normal force over the stance
//! phase located on the dense output, the double-support test and the heel strike's time.
//!
//! Unlike [`crate::sim::walk`] nothing stops the step where it stops being physical (a negative
//! normal force, double support, a heel strike before `T_set`): those are the test functions
//! whose zeros bound the walking region, so they must be evaluated on both sides.

use crate::model::{Contact, Model};
use crate::ode::{Direction, Event, GaveUp, Integrator, OdeSystem, Outcome, Step, Tolerances};
use crate::poincare::MapError;
use crate::sim::SimConfig;

use super::problem::ProblemError;

/// The stance dynamics of a smooth-friction model (8 mechanical components).
struct Stance<'a> {
    model: &'a Model,
}

impl OdeSystem<8> for Stance<'_> {
    fn rhs(&mut self, t: f64, y: &[f64; 8], dy: &mut [f64; 8]) {
        let (qdd, _) = self.model.stance(t, y, Contact::Smooth);
        *dy = [y[4], y[5], y[6], y[7], qdd[0], qdd[1], qdd[2], qdd[3]];
    }

    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        let ts = self.model.runtime.t_set;
        (self.model.is_active() && ts > t).then_some(ts)
    }
}

/// The step: the pre-impact state, the post-impact state measured from the new foot, and the
/// tests.
pub(super) struct Profile {
    /// The heel strike's time since the impact that began the step (s).
    pub(super) period: f64,
    /// The post-impact state `[x, z, th1, th2, xd, zd, th1d, th2d]` with `x` of the new foot
    /// (the step's horizontal advance) before it is reduced to zero.
    pub(super) state_plus: [f64; 8],
    /// The smallest normal force over the stance phase.
    pub(super) min_normal_force: f64,
    /// The rear foot's impulse of the double-support test.
    pub(super) rear_impulse: f64,
    /// How the striking foot ended the impact.
    pub(super) impact: crate::model::ImpactRegime,
}

/// Samples per accepted step at which the normal force is evaluated on the dense output
/// before the smallest is refined.
const SAMPLES: usize = 8;

/// Golden-section iterations refining a sampled minimum: the bracket shrinks by
/// `0.618^40 = 4e-9` of two sample intervals, far below where the normal force's curvature
/// would make the located value differ from the true minimum by more than rounding.
const GOLDEN_ITERATIONS: usize = 40;

/// The smallest normal force seen so far, kept up to date by the observer.
struct MinForce<'a> {
    model: &'a Model,
    min: f64,
}

impl MinForce<'_> {
    fn normal(&self, t: f64, y: &[f64; 8]) -> f64 {
        self.model.reaction(t, y, Contact::Smooth).normal
    }

    fn on_step(&mut self, step: &Step<'_, 8>) {
        let (t0, t1) = (step.t_start(), step.t_end());
        let mut y = [0.0; 8];
        let at = |k: usize| t0 + (t1 - t0) * k as f64 / SAMPLES as f64;
        let mut best = (f64::INFINITY, 0);
        for k in 0..=SAMPLES {
            step.eval(at(k), &mut y);
            let f = self.normal(at(k), &y);
            if f < best.0 {
                best = (f, k);
            }
        }
        if best.0 >= self.min {
            return;
        }
        self.min = best.0;
        if best.1 == 0 || best.1 == SAMPLES {
            return;
        }
        // Golden section on the two sample intervals around the sampled minimum.
        let (mut a, mut b) = (at(best.1 - 1), at(best.1 + 1));
        let g = 0.5 * (5f64.sqrt() - 1.0);
        let mut f_at = |t: f64| {
            step.eval(t, &mut y);
            self.model.reaction(t, &y, Contact::Smooth).normal
        };
        let (mut c, mut d) = (b - g * (b - a), a + g * (b - a));
        let (mut fc, mut fd) = (f_at(c), f_at(d));
        for _ in 0..GOLDEN_ITERATIONS {
            if fc < fd {
                (b, d, fd) = (d, c, fc);
                c = b - g * (b - a);
                fc = f_at(c);
            } else {
                (a, c, fc) = (c, d, fd);
                d = a + g * (b - a);
                fd = f_at(d);
            }
        }
        self.min = self.min.min(fc).min(fd);
    }
}

/// One step from the post-impact state `s` (time 0) of a smooth-friction model. With `tests`
/// false the normal force is not followed over the stance (`min_normal_force` is then its value
/// at the start): the integration, and so the post-impact state, is the same either way.
///
/// # Errors
/// No heel strike within [`SimConfig::max_step_time`], the wheel falling back onto its rear
/// spoke, an integrator failure or a non-finite value.
pub(super) fn step(
    model: &Model,
    cfg: &SimConfig,
    s: &[f64; 8],
    tests: bool,
) -> Result<Profile, ProblemError> {
    if !s.iter().all(|v| v.is_finite()) {
        return Err(MapError::NonFiniteStart.into());
    }
    let heel = model.heel_strike_angle();
    let rear = model.rear_contact_angle();
    let mut events = [
        Event::terminal(Direction::Rising, move |_, y: &[f64; 8]| y[2] - heel),
        Event::terminal(Direction::Falling, move |_, y: &[f64; 8]| y[2] - rear),
    ];
    let mut sys = Stance { model };
    let mut integ = Integrator::<8>::new(cfg.method, Tolerances::new(cfg.rtol, cfg.atol));
    let mut force = MinForce {
        model,
        min: model.reaction(0.0, s, Contact::Smooth).normal,
    };
    let mut observer = |st: &Step<'_, 8>| {
        if tests {
            force.on_step(st);
        }
    };
    let mut t = 0.0;
    let mut y = *s;
    let budget = integ.config().max_steps;
    let (te, pre) = loop {
        let spent = integ.stats().accepted_steps + integ.stats().rejected_steps;
        integ.config_mut().max_steps =
            budget.saturating_sub(usize::try_from(spent).unwrap_or(usize::MAX));
        match integ.integrate(
            &mut sys,
            t,
            &y,
            cfg.max_step_time,
            &mut events,
            &mut observer,
        ) {
            Outcome::Breakpoint { t: tb, y: yb } => (t, y) = (tb, yb),
            Outcome::Event { index: 0, t, y } => break (t, y),
            Outcome::Event { t, .. } => return Err(ProblemError::FellBackward { t }),
            Outcome::Reached { t, .. } => return Err(MapError::NoHeelStrike { t }.into()),
            Outcome::NonFinite { t, .. } => return Err(MapError::NonFinite { t }.into()),
            Outcome::StepSizeTooSmall { t, h, .. } => {
                let cause = GaveUp::StepSizeTooSmall { h };
                return Err(MapError::Integrator { t, cause }.into());
            }
            Outcome::MaxSteps { t, .. } => {
                let cause = GaveUp::TooManySteps;
                return Err(MapError::Integrator { t, cause }.into());
            }
            Outcome::InvalidInput { t, reason, .. } => {
                let cause = GaveUp::InvalidInput(reason);
                return Err(MapError::Integrator { t, cause }.into());
            }
        }
    };
    let min_normal_force = force.min;
    let imp = model
        .impact(&pre)
        .map_err(|_| ProblemError::ImpactJam { t: te })?;
    let post = model.reset(&pre, &imp);
    let mut state_plus = [0.0; 8];
    state_plus[..4].copy_from_slice(&post.q_plus);
    state_plus[4..].copy_from_slice(&post.qd_plus);
    if !state_plus.iter().all(|v| v.is_finite()) || !min_normal_force.is_finite() {
        return Err(MapError::NonFiniteImpact { t: te }.into());
    }
    Ok(Profile {
        period: te,
        state_plus,
        min_normal_force,
        rear_impulse: imp.rear_impulse,
        impact: imp.regime,
    })
}
