//! One step of a walk: a stance phase from a post-impact state, integrated segment by segment
//! between its events, and the impact that ends it, with the step's gait descriptors.
//!
//! The time is reset to zero at every impact; the ends of the desired trajectories' ramps
//! (`T_set`) are breakpoints of the integrator (the control switches there).

use crate::model::{Contact, Model, Reaction, Slide};
use crate::ode::{GaveUp, Integrator, Outcome, Stats};
use crate::vector::Vector;

use super::blowup::{blow_up, blown_up};
use super::config::SimConfig;
use super::failure::{Failure, FailureKind};
use super::foot::{
    Foot, at_rest, contact_at_rest, control_input, initial_contact, reaction_at_start,
};
use super::frame::Frames;
use super::gait::{Sample, StepResult};
use super::guard::{Guard, Guards};
use super::stance::{Recorder, Stance};
use super::state::{finite, integrated, mech};

/// Where samples of the motion go (none, either or both), and the time of the step's start
/// since the start of the walk.
pub(super) struct Record<'r> {
    /// Samples for plots ([`super::WalkLimits::record`]).
    pub(super) samples: Option<&'r mut Vec<Sample>>,
    /// Frames at given times ([`super::trajectory()`]).
    pub(super) frames: Option<&'r mut Frames>,
    /// The time of the step's start since the start of the walk.
    pub(super) t_offset: f64,
}

/// Integrate one stance phase from the post-impact state `s0` and apply the impact; append
/// samples and frames of the motion to those of `record`.
pub(super) fn one_step<const S: usize>(
    model: &Model,
    cfg: &SimConfig,
    integ: &mut Integrator<S>,
    step: usize,
    s0: &Vector,
    mut record: Record<'_>,
) -> Result<StepResult, Failure> {
    let (foot, y0, r0, lambda_max) = begin::<S>(model, cfg, step, s0, &mut record)?;
    let Record {
        samples: out,
        frames,
        t_offset,
    } = record;
    let obs = Recorder {
        foot: &foot,
        out,
        t_offset,
        step,
        interior: 3,
        frames,
    };
    let strike = stance_phase(cfg, integ, &foot, step, y0, r0.lambda, lambda_max, obs)?;
    impact(model, step, s0, &strike)
}

/// Whether the desired trajectories of an actuated walker's control, inputs of its kernels,
/// are finite at `t` (a ramp of `T_set` below about `1e-154` overflows `ydd_d`'s scale
/// `60 alpha / T_set^2`, and the ramp is then NaN at `t = 0`); always true for a passive
/// walker, which has no control.
fn desired_finite(model: &Model, t: f64) -> bool {
    model.desired_finite(t)
}

/// The start of a step's stance ([`start`], with the blow-up threshold `lambda_max` of `cfg`,
/// which it also returns) and the step's first sample, at the post-impact state `s0`, where
/// `record` takes samples.
pub(super) fn begin<'a, const S: usize>(
    model: &'a Model,
    cfg: &SimConfig,
    step: usize,
    s0: &Vector,
    record: &mut Record<'_>,
) -> Result<(Foot<'a>, [f64; S], Reaction, f64), Failure> {
    let lambda_max = cfg.lambda_blowup * model.total_mass() * model.gravity();
    let (foot, y0, r0) = start::<S>(model, step, s0, lambda_max)?;
    if let Some(samples) = record.samples.as_deref_mut() {
        samples.push(Sample {
            time: record.t_offset,
            step,
            state: *s0,
            lambda: r0.lambda,
            u: control_input(model, 0.0, &y0, foot.contact()),
        });
    }
    Ok((foot, y0, r0, lambda_max))
}

/// The checks at the start of a stance phase: a finite state and desired trajectory (the
/// kernels' inputs), a contact consistent with them, a finite `lambda` below the blow-up
/// threshold and a non-negative normal force. Returns the foot, the integrated initial state
/// and the ground reaction there.
fn start<'a, const S: usize>(
    model: &'a Model,
    step: usize,
    s0: &Vector,
    lambda_max: f64,
) -> Result<(Foot<'a>, [f64; S], Reaction), Failure> {
    if !finite(s0) || !desired_finite(model, 0.0) {
        return Err(FailureKind::NonFinite.at(step, 0.0, *s0));
    }
    let y0: [f64; S] = integrated(s0);
    let foot = Foot::new(model, initial_contact(model, &y0, step)?);

    let r0 = foot.reaction(0.0, &y0);
    if !r0.lambda.is_finite() || r0.lambda.abs() > lambda_max {
        // A pole, a huge numerator (spin whose square is huge or overflows), or non-finite.
        let kind = blow_up(&foot, 0.0, &y0, r0.lambda, lambda_max);
        return Err(kind.at(step, 0.0, *s0));
    }
    reaction_at_start(&foot, 0.0, &y0, step)?;
    Ok((foot, y0, r0))
}

/// The end of a stance phase: the heel strike at `t` with the integrated state `y`, the
/// smallest `lambda` seen and the time the foot spent stuck. On a floor of patches
/// (`super::patches`) also the end of a stance's piece on one patch, where the foot reaches a
/// boundary, and the start of the next piece; `kinks` says whether the power kink is still
/// watched there.
pub(super) struct Strike<const S: usize> {
    /// The time since the step's impact.
    pub(super) t: f64,
    /// The integrated state there.
    pub(super) y: [f64; S],
    /// The smallest `lambda` seen so far in the stance.
    pub(super) lambda_min: f64,
    /// The time the foot spent stuck so far.
    pub(super) stuck_time: f64,
    /// Whether the power kink is still watched.
    pub(super) kinks: bool,
}

/// What follows an integration segment.
enum Next<const S: usize> {
    /// Integrate on from `(t, y)`.
    Continue(f64, [f64; S]),
    /// The heel struck at `(t, y)`.
    Strike(f64, [f64; S]),
    /// The stance foot reached a boundary of its patch at `(t, y)` (a floor of patches).
    Boundary(f64, [f64; S]),
}

/// How the segments of a stance phase end: the heel strike, or (a floor of patches) the
/// stance foot at a boundary of its patch, the stance to go on on the next patch.
pub(super) enum Ended<const S: usize> {
    /// The heel struck.
    Strike(Strike<S>),
    /// The foot reached a boundary of its patch.
    Boundary(Strike<S>),
}

/// Integrate the stance phase from `y0` (time 0) segment by segment until the heel strikes:
/// segments end at the breakpoints (the ramps' ends, `T_set`), at a power kink, at a zero of
/// the strike guard with the striking point behind the stance foot, and at stick-slip
/// transitions.
///
/// The integrator's [`Config::max_steps`](crate::ode::Config::max_steps) is the budget of
/// attempted steps of the whole stance phase, not of each segment: every segment spends at
/// least one step, so a stance phase whose events follow each other ever more closely (the
/// power kink chattering under a stiff friction law, `c = 1e12`) ends with
/// [`GaveUp::TooManySteps`] instead of running on one budget per segment. The
/// integrator's setting is restored before returning.
#[allow(
    clippy::too_many_arguments,
    reason = "the pieces of one stance phase, prepared by `one_step`"
)]
fn stance_phase<const S: usize>(
    cfg: &SimConfig,
    integ: &mut Integrator<S>,
    foot: &Foot<'_>,
    step: usize,
    y0: [f64; S],
    lambda0: f64,
    lambda_max: f64,
    obs: Recorder<'_>,
) -> Result<Strike<S>, Failure> {
    let budget = integ.config().max_steps;
    let first = attempts(integ.stats());
    let from = Strike {
        t: 0.0,
        y: y0,
        lambda_min: lambda0,
        stuck_time: 0.0,
        kinks: foot.model.is_active(),
    };
    let (guards, within) = (Guards::new(foot, lambda_max), Budget { budget, first });
    let strike = segments(cfg, integ, &guards, step, from, lambda_max, obs, within);
    integ.config_mut().max_steps = budget;
    match strike? {
        Ended::Strike(s) | Ended::Boundary(s) => Ok(s),
    }
}

/// The budget of attempted integrator steps of a whole stance phase: `budget` in all from the
/// integrator's count `first` at the stance's start.
#[derive(Clone, Copy)]
pub(super) struct Budget {
    /// The most attempted steps of the whole stance.
    pub(super) budget: usize,
    /// The integrator's count of attempted steps at the stance's start.
    pub(super) first: u64,
}

/// Attempted steps (accepted and rejected) counted in `stats`.
pub(super) fn attempts(stats: &Stats) -> u64 {
    stats.accepted_steps + stats.rejected_steps
}

/// The segments of [`stance_phase`] from `from` (time, state, and what the stance saw so far),
/// watched by `guards`, with at most `within.budget` attempted steps in all since the
/// stance's start (each segment gets what its predecessors left as the integrator's
/// `max_steps`). On a floor of patches (`super::patches`) this is the stance's piece on one
/// patch, and also ends where the foot reaches the patch's boundary.
#[allow(
    clippy::too_many_arguments,
    reason = "the pieces of one stance phase, prepared by `one_step`"
)]
pub(super) fn segments<const S: usize>(
    cfg: &SimConfig,
    integ: &mut Integrator<S>,
    guards: &Guards<'_>,
    step: usize,
    from: Strike<S>,
    lambda_max: f64,
    mut obs: Recorder<'_>,
    within: Budget,
) -> Result<Ended<S>, Failure> {
    let foot = guards.foot();
    if !from.kinks {
        guards.end_power_kinks();
    }
    let mut events = guards.events::<S>();
    let mut sys = Stance::new(guards);
    let Strike {
        mut t,
        mut y,
        mut lambda_min,
        mut stuck_time,
        ..
    } = from;
    let t_limit = cfg.max_step_time;
    let Budget { budget, first } = within;
    loop {
        let spent = usize::try_from(attempts(integ.stats()) - first).unwrap_or(usize::MAX);
        integ.config_mut().max_steps = budget.saturating_sub(spent);
        let (t_start, contact) = (t, foot.contact());
        sys.in_contact();
        let out = integ.integrate(&mut sys, t, &y, t_limit, &mut events, &mut obs);
        if contact == Contact::Stuck {
            stuck_time += out.t() - t_start;
        }
        let lam = foot.reaction(out.t(), out.y()).lambda;
        if lam.is_finite() {
            lambda_min = lambda_min.min(lam);
        }
        let at = |t, y| Strike {
            t,
            y,
            lambda_min,
            stuck_time,
            kinks: guards.power_kinks(),
        };
        match after_segment(out, guards, foot, step, lam, lambda_max)? {
            Next::Continue(tn, yn) => (t, y) = (tn, yn),
            Next::Strike(t, y) => return Ok(Ended::Strike(at(t, y))),
            Next::Boundary(t, y) => return Ok(Ended::Boundary(at(t, y))),
        }
    }
}

/// The consequence of the outcome `out` of a segment (`lam` is `lambda` at its end): go on from
/// a breakpoint, a power kink or a stick-slip transition, stop at the heel strike, or fail.
fn after_segment<const S: usize>(
    out: Outcome<S>,
    guards: &Guards<'_>,
    foot: &Foot<'_>,
    step: usize,
    lam: f64,
    lambda_max: f64,
) -> Result<Next<S>, Failure> {
    match out {
        Outcome::Breakpoint { t, y } => {
            // A ramp's end: the input power may stop counting there (`T_set` in the paper).
            if !foot.model.power_counts(t) {
                guards.end_power_kinks();
            }
            Ok(Next::Continue(t, y))
        }
        Outcome::Event { index, t, y } => {
            on_guard(guards.of_event(index), foot, step, t, y, lam, lambda_max)
        }
        Outcome::Reached { t, y } => Err(FailureKind::NoImpact.at(step, t, mech(&y))),
        Outcome::NonFinite { t, y } => {
            let kind = if blown_up(lam, lambda_max) && desired_finite(foot.model, t) {
                blow_up(foot, t, &y, lam, lambda_max)
            } else {
                FailureKind::NonFinite
            };
            Err(kind.at(step, t, mech(&y)))
        }
        Outcome::StepSizeTooSmall { t, y, h } => {
            let stop = GaveUp::StepSizeTooSmall { h };
            Err(gave_up(stop, foot, t, &y, lam, lambda_max).at(step, t, mech(&y)))
        }
        Outcome::MaxSteps { t, y } => {
            let stop = GaveUp::TooManySteps;
            Err(gave_up(stop, foot, t, &y, lam, lambda_max).at(step, t, mech(&y)))
        }
        Outcome::InvalidInput { t, y, reason } => {
            let reason = GaveUp::InvalidInput(reason);
            Err(FailureKind::Integrator { reason }.at(step, t, mech(&y)))
        }
    }
}

/// Why the integrator gave up with `reason` at `(t, y)`: a blown-up `lambda` (`lam`) is the
/// cause where there is one ([`blow_up`] names which), otherwise the integrator's reason.
fn gave_up<const S: usize>(
    reason: GaveUp,
    foot: &Foot<'_>,
    t: f64,
    y: &[f64; S],
    lam: f64,
    lambda_max: f64,
) -> FailureKind {
    if blown_up(lam, lambda_max) {
        blow_up(foot, t, y, lam, lambda_max)
    } else {
        FailureKind::Integrator { reason }
    }
}

/// The consequence of the guard `guard` firing at `(t, y)` (`lam` is `lambda` there).
fn on_guard<const S: usize>(
    guard: Option<Guard>,
    foot: &Foot<'_>,
    step: usize,
    t: f64,
    y: [f64; S],
    lam: f64,
    lambda_max: f64,
) -> Result<Next<S>, Failure> {
    let model = foot.model;
    let kind = match guard {
        Some(Guard::Strike) if model.strike_ahead(&y[..model.n()]) => {
            return Ok(Next::Strike(t, y));
        }
        // The striking point passes the floor behind the stance foot (the compass gait's
        // swing foot at mid-stance): no strike.
        Some(Guard::Strike | Guard::PowerKink(_)) => return Ok(Next::Continue(t, y)),
        Some(Guard::FootStops) => {
            // The sliding foot stops: it sticks, or slides back if the cone cannot hold it.
            let y = at_rest(y, model.n());
            foot.set_contact(contact_at_rest(foot.model, t, &y, step)?);
            reaction_at_start(foot, t, &y, step)?;
            return Ok(Next::Continue(t, y));
        }
        Some(Guard::FootSlips) => {
            // The stuck foot slips, the way the force that held it no longer can.
            let held = foot.reaction(t, &y);
            foot.set_contact(Contact::Sliding(Slide::of(-held.tangential)));
            reaction_at_start(foot, t, &y, step)?;
            return Ok(Next::Continue(t, y));
        }
        // The foot slid onto the next patch: the stance goes on there (`super::patches`).
        Some(Guard::Boundary) => return Ok(Next::Boundary(t, y)),
        Some(Guard::LiftOff) if !blown_up(lam, lambda_max) => FailureKind::LiftOff { lambda: lam },
        Some(Guard::Fall(i)) => {
            let fall = &model.spec().model.falls[i];
            FailureKind::Fall {
                name: fall.name.name.clone(),
                doc: fall.doc.clone(),
            }
        }
        Some(Guard::LiftOff | Guard::LambdaBlowUp) | None => blow_up(foot, t, &y, lam, lambda_max),
    };
    Err(kind.at(step, t, mech(&y)))
}

/// The impact that ends the stance phase: the checks on the heel strike (not at the start, not
/// before `T_set`, no double support), the impact map, the change of stance leg and the gait
/// descriptors of the step that began at `s0`.
pub(super) fn impact<const S: usize>(
    model: &Model,
    step: usize,
    s0: &Vector,
    strike: &Strike<S>,
) -> Result<StepResult, Failure> {
    let (te, ye) = (strike.t, &strike.y);
    let pre = mech(ye);
    if te <= 0.0 {
        return Err(FailureKind::ImpactAtStart.at(step, 0.0, pre));
    }
    if let Some(t_set) = model.ramps_end()
        && te < t_set
    {
        return Err(FailureKind::ImpactBeforeTSet { t_set }.at(step, te, pre));
    }
    let imp = model
        .impact(&pre)
        .map_err(|jam| FailureKind::ImpactJam { slip: jam.slip }.at(step, te, pre))?;
    if imp.foot_impulse[1] < 0.0 {
        let normal_impulse = imp.foot_impulse[1];
        return Err(FailureKind::ImpactPulls { normal_impulse }.at(step, te, pre));
    }
    // The test applies where the model asks for it (`[impact] double_support`); a model without
    // it reports a zero impulse, which is no failure.
    if model.spec().double_support() && imp.rear_impulse >= 0.0 {
        let rear_impulse = imp.rear_impulse;
        return Err(FailureKind::DoubleSupport { rear_impulse }.at(step, te, pre));
    }
    let post = model.reset(&pre, &imp);
    let dx = (post.q_plus[0] - s0[0]) / model.phi().cos();
    let speed = dx / te;
    let (p, sr) = if model.is_active() {
        let p = ye[S - 1] / te;
        (
            Some(p),
            Some(p / (model.total_mass() * model.gravity() * speed)),
        )
    } else {
        (None, None)
    };
    let all = [
        dx,
        speed,
        p.unwrap_or(0.0),
        sr.unwrap_or(0.0),
        imp.foot_impulse[0],
        imp.foot_impulse[1],
        imp.rear_impulse,
    ];
    if !finite(&post.q_plus) || !finite(&post.qd_plus) || !finite(&all) {
        return Err(FailureKind::NonFinite.at(step, te, pre));
    }
    Ok(StepResult {
        period: te,
        dx,
        speed,
        p,
        sr,
        q_plus: post.q_plus,
        qd_plus: post.qd_plus,
        foot_normal_velocity: post.foot_normal_velocity,
        foot_impulse: imp.foot_impulse,
        rear_impulse: imp.rear_impulse,
        impact: imp.regime,
        lambda_min: strike.lambda_min,
        stuck_time: strike.stuck_time,
        floor: None,
    })
}
