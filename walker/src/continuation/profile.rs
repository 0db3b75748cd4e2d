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
use crate::sim::{MAX_FALLS, SimConfig};
use crate::vector::Vector;

use super::problem::ProblemError;

/// The stance dynamics of a smooth-friction model (`M = 2n` mechanical components).
struct Stance<'a> {
    model: &'a Model,
}

impl<const M: usize> OdeSystem<M> for Stance<'_> {
    fn rhs(&mut self, t: f64, y: &[f64; M], dy: &mut [f64; M]) {
        let n = M / 2;
        let mut out = [0.0; Model::STANCE_LEN];
        self.model.stance(t, y, Contact::Smooth, &mut out);
        dy[..n].copy_from_slice(&y[n..]);
        dy[n..].copy_from_slice(&out[..n]);
    }

    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        self.model.next_breakpoint(t)
    }
}

/// The step: the pre-impact state, the post-impact state measured from the new foot, and the
/// tests.
pub(super) struct Profile {
    /// The heel strike's time since the impact that began the step (s).
    pub(super) period: f64,
    /// The post-impact state `[q, qd]` with `x` of the new foot (the step's horizontal
    /// advance) before it is reduced to zero.
    pub(super) state_plus: Vector,
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
    fn normal(&self, t: f64, y: &[f64]) -> f64 {
        self.model.reaction(t, y, Contact::Smooth).normal
    }

    fn on_step<const M: usize>(&mut self, step: &Step<'_, M>) {
        let (t0, t1) = (step.t_start(), step.t_end());
        let mut y = [0.0; M];
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
/// No strike within [`SimConfig::max_step_time`], one of the model's falls (the paper's wheel
/// falling back onto its rear spoke), an integrator failure or a non-finite value.
pub(super) fn step(
    model: &Model,
    cfg: &SimConfig,
    s: &[f64],
    tests: bool,
) -> Result<Profile, ProblemError> {
    if s.len() != 2 * model.n() || !s.iter().all(|v| v.is_finite()) {
        return Err(MapError::NonFiniteStart.into());
    }
    match model.n() {
        3 => step_sized::<6>(model, cfg, s, tests),
        4 => step_sized::<8>(model, cfg, s, tests),
        5 => step_sized::<10>(model, cfg, s, tests),
        6 => step_sized::<12>(model, cfg, s, tests),
        7 => step_sized::<14>(model, cfg, s, tests),
        _ => step_sized::<16>(model, cfg, s, tests),
    }
}

/// [`step`] with the state's size `M = 2n`.
fn step_sized<const M: usize>(
    model: &Model,
    cfg: &SimConfig,
    s: &[f64],
    tests: bool,
) -> Result<Profile, ProblemError> {
    let n = model.n();
    let events_of = move |y: &[f64; M], i: usize| {
        let mut e = [0.0; 1 + MAX_FALLS];
        let k = model.event_count().min(e.len());
        model.events(&y[..n], &mut e[..k]);
        e[i]
    };
    let mut events: Vec<Event<'_, M>> = (0..model.event_count().min(1 + MAX_FALLS))
        .map(|i| Event::terminal(Direction::Falling, move |_, y: &[f64; M]| events_of(y, i)))
        .collect();
    let mut sys = Stance { model };
    let mut integ = Integrator::<M>::new(cfg.method, Tolerances::new(cfg.rtol, cfg.atol));
    let mut force = MinForce {
        model,
        min: model.reaction(0.0, s, Contact::Smooth).normal,
    };
    let mut observer = |st: &Step<'_, M>| {
        if tests {
            force.on_step(st);
        }
    };
    let mut t = 0.0;
    let mut y = [0.0; M];
    y.copy_from_slice(&s[..M]);
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
            // A zero of the strike guard with the striking point behind the stance foot.
            Outcome::Event {
                index: 0,
                t: te,
                y: ye,
            } if !model.strike_ahead(&ye[..n]) => (t, y) = (te, ye),
            Outcome::Event { index: 0, t, y } => break (t, y),
            Outcome::Event { index, t, .. } => {
                let name = model
                    .spec()
                    .falls()
                    .nth(index - 1)
                    .unwrap_or("fall")
                    .to_owned();
                return Err(ProblemError::Fall { name, t });
            }
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
    let state_plus = Vector::concat(&post.q_plus, &post.qd_plus);
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
