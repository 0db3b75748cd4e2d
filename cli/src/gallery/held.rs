//! The held gait of a model on one slope: the periodic gait whose stance foot never moves (stuck
//! through every stance, the impact sticking), found by walking under exact Coulomb friction at a
//! friction coefficient so large that nothing slips ([`HELD_MU0`]); and the friction it needs,
//! from the simulator's ground reaction ([`walker::model::Model::reaction`]) along one step and
//! the heel strike's impulse in the stick regime. The same trajectory is a gait at every `mu0`
//! at least that ratio, and at none below: this is why a sweep holds the foot where it does.
//!
//! With the paper's frictionless impact the foot leaves the heel strike sliding; where the
//! sliding friction makes the normal force's denominator vanish (Painleve's paradox) no contact
//! is consistent at the start of the next stance ([`Painleve`]), unless that heel strike keeps
//! the old stance foot on the floor and the walk ends there ([`Painleve::double_support`]).

use walker::model::{Contact, ImpactRegime, Model, Slide, in_regime};
use walker::setup::Setup;
use walker::sim::{SimConfig, StepResult, WalkLimits, trajectory, walk};
use walker::vector::Vector;
use walker_scene::ImpactLaw;

use super::laws::{EXACT, Laws};

use crate::reproduce::passive::PERIODIC_TOL;

/// The friction coefficient of the walk that finds the held gait: far above what any shipped
/// model's gait needs, so the foot never slips.
pub const HELD_MU0: f64 = 10.0;

/// The most steps of that walk (its gait is periodic by [`PERIODIC_TOL`] in a few dozen).
const HELD_STEPS: usize = 2000;

/// The ground reaction is evaluated at this many equally spaced times of the held step.
const FRAMES: usize = 20_000;

/// Points of the friction profile kept for the figure and the CSV.
const PROFILE_POINTS: usize = 400;

/// The friction the frictionless impact leaves unable to hold the foot on the floor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Painleve {
    /// The new stance foot's velocity along the floor right after the frictionless heel strike
    /// of the held gait (m/s, positive forward).
    pub foot_velocity: f64,
    /// The `mu0` at which the normal force of the foot sliding that way changes sign through a
    /// pole (its denominator is affine in `mu0`): above it, sliding is inconsistent; `None` if it
    /// has none (the friction only presses the foot on the floor).
    pub mu0: Option<f64>,
    /// The frictionless heel strike's normal impulse on the new foot (N s).
    pub normal_impulse: f64,
    /// The old stance foot's impulse in the double-support test of that heel strike (N s;
    /// [`walker::model::ImpactResult::rear_impulse`]): non-negative, the walker would stay in
    /// double support and the simulator ends the walk at the strike.
    pub rear_impulse: f64,
}

impl Painleve {
    /// Whether the frictionless heel strike keeps the old stance foot on the floor (the
    /// simulator's `double-support`): then no next stance begins, with its foot sliding or not.
    #[must_use]
    pub fn double_support(&self) -> bool {
        self.rear_impulse >= 0.0
    }
}

/// The held gait on one slope and the friction it needs.
#[derive(Clone, Debug, PartialEq)]
pub struct Held {
    /// The gait's step (period, length, speed; the post-impact state).
    pub step: StepResult,
    /// The post-impact state, the stance foot at the origin: where the sweeps start.
    pub start: Vector,
    /// The largest `|lambda_t / lambda_n|` over the stance (the tangential over the normal
    /// ground force that holds the foot).
    pub stance_ratio: f64,
    /// Where in the step it is largest (`t / T`).
    pub stance_at: f64,
    /// The state `[q, qd]` right before the heel strike that ends the step.
    pub pre: Vector,
    /// The striking foot's impulse `[Lambda_t, Lambda_n]` in the stick regime (N s; `t`
    /// forward, down the slope).
    pub impulse: [f64; 2],
    /// `(t / T, lambda_t / lambda_n)` along the step, for the figure.
    pub profile: Vec<(f64, f64)>,
    /// The frictionless impact's sliding foot and its Painleve threshold.
    pub painleve: Painleve,
}

impl Held {
    /// The friction coefficient the held gait needs: the larger of the stance's and the heel
    /// strike's ratio.
    #[must_use]
    pub fn needs(&self) -> f64 {
        self.stance_ratio.max(self.impact_ratio())
    }

    /// `|Lambda_t / Lambda_n|` of the heel strike's impulse in the stick regime.
    #[must_use]
    pub fn impact_ratio(&self) -> f64 {
        (self.impulse[0] / self.impulse[1]).abs()
    }
}

/// A state with the stance foot moved to the origin (the dynamics do not depend on it).
fn at_origin(mut s: Vector) -> Vector {
    s[0] = 0.0;
    s[1] = 0.0;
    s
}

/// The held gait of `setup` on the slope `phi` (NaN: its own floor), or why there is none (the
/// walk failed, or its foot moved).
///
/// # Errors
/// The model cannot be built, the walk fails, or its last step is not held.
pub fn held(setup: &Setup, phi: f64) -> Result<Held, String> {
    let cfg = SimConfig::default();
    let exact = EXACT.model(setup, phi, HELD_MU0)?;
    let limits = WalkLimits {
        max_steps: HELD_STEPS,
        duration: f64::INFINITY,
        record: false,
        periodic: Some(PERIODIC_TOL),
    };
    let w = walk(&exact, &cfg, &exact.start_state(), &limits);
    if let Some(f) = &w.failure {
        return Err(format!(
            "{} at step {} (t = {:.4} s)",
            f.name(),
            f.step,
            f.t
        ));
    }
    let step = *w.steps.last().ok_or("no step")?;
    if !(step.stuck_time >= step.period && step.impact == ImpactRegime::Stick) {
        return Err(format!(
            "the foot moves at mu0 = {HELD_MU0} (stuck {:.4} s of {:.4} s)",
            step.stuck_time, step.period
        ));
    }
    let start = at_origin(step.state_plus());
    let one = WalkLimits {
        max_steps: 1,
        ..limits
    };
    let tr = trajectory(
        &exact,
        &cfg,
        &start,
        &one,
        step.period / FRAMES as f64,
        2 * FRAMES,
    );
    let ratio = |f: &walker::sim::Frame| f.reaction.tangential / f.reaction.normal;
    let (mut stance_ratio, mut stance_at) = (0.0_f64, 0.0);
    for f in &tr.frames {
        if ratio(f).abs() > stance_ratio {
            (stance_ratio, stance_at) = (ratio(f).abs(), f.t / step.period);
        }
    }
    let every = (tr.frames.len() / PROFILE_POINTS).max(1);
    let profile = tr
        .frames
        .iter()
        .step_by(every)
        .map(|f| (f.t / step.period, ratio(f)))
        .collect();
    let pre = pre_impact(&exact, &tr.frames)?;
    let stick = in_regime(
        &exact.impact_ingredients(&pre),
        HELD_MU0,
        ImpactRegime::Stick,
    )
    .ok_or("no stick impulse")?;
    Ok(Held {
        step,
        start,
        stance_ratio,
        stance_at,
        pre,
        impulse: stick,
        profile,
        painleve: painleve(setup, phi, &pre)?,
    })
}

/// The state where the strike guard reaches zero, extrapolated linearly from the last two
/// frames of the step (a step is [`FRAMES`] frames long, so they are within `T / FRAMES` of it).
fn pre_impact(m: &Model, frames: &[walker::sim::Frame]) -> Result<Vector, String> {
    let [.., a, b] = frames else {
        return Err("too few frames".to_owned());
    };
    let n = m.n();
    let guard = |s: &Vector| {
        let mut out = vec![0.0; m.event_count()];
        m.events(&s[..n], &mut out);
        out[0]
    };
    let (ga, gb) = (guard(&a.state), guard(&b.state));
    let tau = if ga == gb { 0.0 } else { gb / (ga - gb) };
    let mut pre = b.state;
    for (p, x) in pre.iter_mut().zip(a.state.iter()) {
        *p += tau * (*p - x);
    }
    Ok(pre)
}

/// The frictionless heel strike from the held gait's pre-impact state `pre`: the new foot's
/// velocity along the floor, and where sliding that way stops being consistent. The normal
/// force of a sliding foot is `N / D(mu)` with `D` affine in the friction coefficient and `N`
/// free of it, so `1 / lambda_n` is affine in `mu0`: from its values at 0 and 1 its zero.
fn painleve(setup: &Setup, phi: f64, pre: &Vector) -> Result<Painleve, String> {
    let frictionless = Laws {
        impact: ImpactLaw::Frictionless,
        ..EXACT
    };
    let m = frictionless.model(setup, phi, 1.0)?;
    let imp = m.impact(pre).map_err(|e| e.to_string())?;
    let post = m.reset(pre, &imp);
    let y = Vector::concat(&post.q_plus, &post.qd_plus);
    let xd = y[m.n()];
    let (normal_impulse, rear_impulse) = (imp.foot_impulse[1], imp.rear_impulse);
    if xd == 0.0 {
        return Ok(Painleve {
            foot_velocity: 0.0,
            mu0: None,
            normal_impulse,
            rear_impulse,
        });
    }
    let at_1 = m.reaction(0.0, &y, Contact::Sliding(Slide::of(xd))).normal;
    let at_0 = m
        .frictionless_normal(0.0, &y)
        .ok_or("no frictionless normal force")?;
    let mu0 = (1.0 / at_0) / (1.0 / at_0 - 1.0 / at_1);
    Ok(Painleve {
        foot_velocity: xd,
        mu0: (mu0.is_finite() && mu0 > 0.0).then_some(mu0),
        normal_impulse,
        rear_impulse,
    })
}
