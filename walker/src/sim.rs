//! The hybrid simulation: stance phases integrated with [`crate::ode`], heel strikes located as
//! events, the impact map and the change of stance leg, failure detection, and the per-step
//! gait descriptors of Section 4.2 (Eqs. 34, 47, the average input power and the specific
//! resistance).
//!
//! The integrated state is `[x, z, th1, th2, xd, zd, th1d, th2d, E]` where `E` is the quadrature
//! `int_0^t |ydot u| dt` accumulated while `t < T_set` (zero for the passive wheel), so that the
//! average input power is under the integrator's error control. The time is reset to zero at
//! every impact; `T_set` is a breakpoint of the integrator (the control switches there).

use serde::Serialize;

use crate::model::{Contact, FrictionLaw, Kind, Model, Reaction, Slide};
use std::cell::Cell;

use crate::ode::{
    Direction, Event, Integrator, Method, Observer, OdeSystem, Outcome, Stats, Step, Tolerances,
};

/// Size of the integrated state (8 mechanical components and the input-power quadrature).
pub const N: usize = 9;

/// Settings of the simulation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SimConfig {
    /// Integration method: DOP853 by default, RODAS4 for stiff friction (large `mu0 c`).
    pub method: Method,
    /// Relative tolerance of the integrator.
    pub rtol: f64,
    /// Absolute tolerance of the integrator.
    pub atol: f64,
    /// Longest stance phase before [`Failure::NoImpact`] is reported (s).
    pub max_step_time: f64,
    /// `|lambda|` above this many times `m_t g` counts as a vanishing denominator of Eq. 23
    /// ([`Failure::LambdaDenominatorZero`]).
    pub lambda_blowup: f64,
}

impl Default for SimConfig {
    fn default() -> Self {
        Self {
            method: Method::Dop853,
            rtol: 1e-10,
            atol: 1e-12,
            max_step_time: 10.0,
            lambda_blowup: 1e6,
        }
    }
}

/// Why a walk ended early. Every variant carries the step number (0 for the step that starts
/// at the initial condition), the time since the last impact and the mechanical state
/// `[x, z, th1, th2, xd, zd, th1d, th2d]` where it happened.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind")]
pub enum Failure {
    /// The vertical ground reaction `lambda` became negative during stance (Eq. 23).
    LiftOff {
        /// Step number.
        step: usize,
        /// Time since the last impact.
        t: f64,
        /// `lambda` where the crossing was located (about zero) or at the start of the step.
        lambda: f64,
        /// State.
        state: [f64; 8],
    },
    /// Coulomb friction (Eq. 25): the stance foot is at rest, the tangential force that would
    /// hold it exceeds `mu0` times the normal force, and sliding the way that force pushes
    /// would accelerate the foot the other way: no contact mode is consistent (Painleve's
    /// paradox of sliding friction).
    ContactInconsistent {
        /// Step number.
        step: usize,
        /// Time since the last impact.
        t: f64,
        /// The normal force with the foot held.
        normal: f64,
        /// The tangential force with the foot held.
        tangential: f64,
        /// State.
        state: [f64; 8],
    },
    /// The heel struck before the output-following control finished (`t < T_set`).
    ImpactBeforeTSet {
        /// Step number.
        step: usize,
        /// Time of the heel strike since the last impact.
        t: f64,
        /// The ramp duration `T_set`.
        t_set: f64,
        /// Pre-impact state.
        state: [f64; 8],
    },
    /// The rear foot's impulse with the rear foot kept on the floor is non-negative: the
    /// impact would lead to double support (Eq. 11 on level ground, Eq. 46 on the slope).
    DoubleSupport {
        /// Step number.
        step: usize,
        /// Time of the heel strike.
        t: f64,
        /// The rear-foot impulse (`impact3_level`'s or `impact2_slope`'s `lambda_I[1]`).
        rear_impulse: f64,
        /// Pre-impact state.
        state: [f64; 8],
    },
    /// `lambda` blew up (the denominator of Eq. 23 vanished: a Painleve-type singularity).
    LambdaDenominatorZero {
        /// Step number.
        step: usize,
        /// Time since the last impact.
        t: f64,
        /// `lambda` there (huge or not finite; non-finite values are reported as `null`).
        lambda: f64,
        /// State.
        state: [f64; 8],
    },
    /// The wheel rolled back until the rear spoke reached the floor.
    FellBackward {
        /// Step number.
        step: usize,
        /// Time since the last impact.
        t: f64,
        /// Stance-leg angle (the rear-contact angle).
        th1: f64,
        /// State.
        state: [f64; 8],
    },
    /// The heel strike happened at the very start of the step (a step of zero duration, so no
    /// step period, speed or power exists): the state began on the impact guard moving into
    /// the floor.
    ImpactAtStart {
        /// Step number.
        step: usize,
        /// Pre-impact state.
        state: [f64; 8],
    },
    /// No heel strike within [`SimConfig::max_step_time`].
    NoImpact {
        /// Step number.
        step: usize,
        /// The time limit.
        t: f64,
        /// State at the limit.
        state: [f64; 8],
    },
    /// A state, an acceleration or a descriptor was not finite.
    NonFinite {
        /// Step number.
        step: usize,
        /// Time of the last finite state.
        t: f64,
        /// Last finite state.
        state: [f64; 8],
    },
    /// The integrator gave up (step size too small or too many steps).
    Integrator {
        /// Step number.
        step: usize,
        /// Time reached.
        t: f64,
        /// What happened.
        reason: String,
        /// State reached.
        state: [f64; 8],
    },
}

impl Failure {
    /// The failure's name as printed by the CLI (`"lift-off"`, ...).
    pub fn name(&self) -> &'static str {
        match self {
            Failure::LiftOff { .. } => "lift-off",
            Failure::ContactInconsistent { .. } => "contact-inconsistent",
            Failure::ImpactBeforeTSet { .. } => "impact-before-t-set",
            Failure::DoubleSupport { .. } => "double-support",
            Failure::LambdaDenominatorZero { .. } => "lambda-denominator-zero",
            Failure::FellBackward { .. } => "fell-backward",
            Failure::ImpactAtStart { .. } => "impact-at-start",
            Failure::NoImpact { .. } => "no-impact",
            Failure::NonFinite { .. } => "non-finite",
            Failure::Integrator { .. } => "integrator",
        }
    }

    /// The step number at which the failure happened.
    pub fn step(&self) -> usize {
        match self {
            Failure::LiftOff { step, .. }
            | Failure::ContactInconsistent { step, .. }
            | Failure::ImpactBeforeTSet { step, .. }
            | Failure::DoubleSupport { step, .. }
            | Failure::LambdaDenominatorZero { step, .. }
            | Failure::FellBackward { step, .. }
            | Failure::ImpactAtStart { step, .. }
            | Failure::NoImpact { step, .. }
            | Failure::NonFinite { step, .. }
            | Failure::Integrator { step, .. } => *step,
        }
    }
}

/// Gait descriptors of one step (Section 4.2) and the state right after the impact that ends it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct StepResult {
    /// Step period `T` (s).
    #[serde(rename = "T")]
    pub period: f64,
    /// Step length `dx` (Eq. 34; on the slope the distance along the slope, Eq. 47) (m).
    pub dx: f64,
    /// Average walking speed `V = dx / T` (m/s).
    #[serde(rename = "V")]
    pub speed: f64,
    /// Average input power `p = (1/T) int_0^T_set |ydot u| dt` (W); `None` for the passive wheel.
    pub p: Option<f64>,
    /// Specific resistance `SR = p / (m_t g V)`; `None` for the passive wheel.
    #[serde(rename = "SR")]
    pub sr: Option<f64>,
    /// Post-impact position `[x, z, th1, th2]` in the new stance leg's coordinates.
    pub q_plus: [f64; 4],
    /// Post-impact velocity `[xd, zd, th1d, th2d]` in the new stance leg's coordinates.
    pub qd_plus: [f64; 4],
    /// The new stance foot's velocity normal to the floor right after the impact (should be 0).
    pub foot_normal_velocity: f64,
    /// The rear-foot impulse of the double-support test (negative: the rear leg leaves).
    pub rear_impulse: f64,
    /// Smallest `lambda` seen at the start of the stance phase, at `T_set` and at the heel strike.
    pub lambda_min: f64,
    /// Time the stance foot spent stuck during the step (Coulomb friction; 0 otherwise) (s).
    pub stuck_time: f64,
}

impl StepResult {
    /// The post-impact state `[q_plus, qd_plus]` (the next step's initial state).
    pub fn state_plus(&self) -> [f64; 8] {
        let mut s = [0.0; 8];
        s[..4].copy_from_slice(&self.q_plus);
        s[4..].copy_from_slice(&self.qd_plus);
        s
    }
}

/// A sample of the continuous motion (for plots).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Sample {
    /// Time since the start of the walk (s).
    pub time: f64,
    /// Step number.
    pub step: usize,
    /// State `[x, z, th1, th2, xd, zd, th1d, th2d]`.
    pub state: [f64; 8],
    /// Vertical ground reaction `lambda`.
    pub lambda: f64,
    /// Control input `u`.
    pub u: f64,
}

/// The result of a walk.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Walk {
    /// The completed steps, in order.
    pub steps: Vec<StepResult>,
    /// Why the walk ended early, if it did.
    pub failure: Option<Failure>,
    /// Sampled motion (empty unless asked for).
    #[serde(skip)]
    pub samples: Vec<Sample>,
    /// The walk stopped early because its gait became periodic ([`WalkLimits::periodic`]):
    /// every later step would repeat the last one within that tolerance.
    pub periodic: bool,
}

impl Walk {
    /// The post-impact state after the last completed step, if any.
    pub fn last_state(&self) -> Option<[f64; 8]> {
        self.steps.last().map(StepResult::state_plus)
    }
}

/// The control input `u` of Eq. 31 (`u = (v + B) / A`, `v` from Eq. 32) in the contact
/// `contact`; 0 for the passive wheel.
pub fn control_input(model: &Model, t: f64, y: &[f64], contact: Contact) -> f64 {
    model.stance(t, y, contact).1
}

/// The ground's force on the stance foot at `(t, y)` in the contact `contact`, with the control
/// input of that point.
pub fn ground_reaction(model: &Model, t: f64, y: &[f64], contact: Contact) -> Reaction {
    model.reaction(t, y, contact)
}

/// The integrand `ydot u` of the input power (Section 4.2), `ydot = th1d - th2d`.
fn power_integrand(model: &Model, t: f64, y: &[f64], contact: Contact) -> f64 {
    (y[6] - y[7]) * control_input(model, t, y, contact)
}

/// A remembered value of a function of `(t, mechanical state, contact)`.
type Memo<T> = Option<(f64, [f64; 8], Contact, T)>;

/// The stance foot during one stance phase: the model, the current contact (it changes only
/// between integration segments, at stick-slip transitions), and remembered values of what
/// several users evaluate at the same points.
struct Foot<'a> {
    model: &'a Model,
    contact: Cell<Contact>,
    /// The last ground reaction: the lift-off, blow-up and slip guards share it.
    reaction: Cell<Memo<Reaction>>,
    /// The last two values of `ydot u` (a step's start is the previous step's end, and the
    /// error test and the power observer ask about the same ends).
    power: Cell<[Memo<f64>; 2]>,
}

impl<'a> Foot<'a> {
    fn new(model: &'a Model, contact: Contact) -> Self {
        Self {
            model,
            contact: Cell::new(contact),
            reaction: Cell::new(None),
            power: Cell::new([None; 2]),
        }
    }

    fn contact(&self) -> Contact {
        self.contact.get()
    }

    fn reaction(&self, t: f64, y: &[f64; N]) -> Reaction {
        let (s, c) = (mech(y), self.contact());
        if let Some((tm, sm, cm, r)) = self.reaction.get()
            && (tm, sm, cm) == (t, s, c)
        {
            return r;
        }
        let r = ground_reaction(self.model, t, y, c);
        self.reaction.set(Some((t, s, c, r)));
        r
    }

    fn power(&self, t: f64, y: &[f64; N]) -> f64 {
        let (s, c) = (mech(y), self.contact());
        let mut memo = self.power.get();
        if let Some(&Some((_, _, _, g))) = memo
            .iter()
            .find(|m| m.is_some_and(|(tm, sm, cm, _)| (tm, sm, cm) == (t, s, c)))
        {
            return g;
        }
        let g = power_integrand(self.model, t, y, c);
        memo[1] = memo[0];
        memo[0] = Some((t, s, c, g));
        self.power.set(memo);
        g
    }

    /// Whether `ydot u` changes sign from `(t0, y0)` to `(t1, y1)` before `T_set` (the kink of
    /// `|ydot u|` is then inside the step).
    fn crossed(&self, t0: f64, y0: &[f64; N], t1: f64, y1: &[f64; N]) -> bool {
        self.model.is_active()
            && t0 < self.model.runtime.t_set
            && self.power(t0, y0) * self.power(t1, y1) < 0.0
    }
}

struct Stance<'a> {
    model: &'a Model,
    /// The generated Jacobian kernels (Table 1 models); `None` falls back to finite differences.
    jac: Option<crate::jacobian::Jac>,
    foot: &'a Foot<'a>,
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
    /// integration (the `power kink` in [`one_step`]), so the step is taken again ending on
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

fn mech(y: &[f64; N]) -> [f64; 8] {
    let mut s = [0.0; 8];
    s.copy_from_slice(&y[..8]);
    s
}

/// Records samples of the motion, if `out` is set: every accepted step's end and `interior`
/// points inside it.
struct Recorder<'a> {
    foot: &'a Foot<'a>,
    out: Option<&'a mut Vec<Sample>>,
    t_offset: f64,
    step: usize,
    interior: usize,
}

impl Observer<N> for Recorder<'_> {
    fn wants_step(&mut self, _: f64, _: &[f64; N], _: f64, _: &[f64; N]) -> bool {
        self.out.is_some()
    }

    fn on_step(&mut self, st: &Step<'_, N>) {
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

/// Limits of a walk.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WalkLimits {
    /// Stop after this many steps.
    pub max_steps: usize,
    /// Stop after the step during which the total time passes this value (s).
    pub duration: f64,
    /// Record samples of the motion (for plots).
    pub record: bool,
    /// Stop early once the gait is periodic, so that the last step stands for every later one:
    /// when the relative change of the descriptors `T`, `dx` and `p` (the largest of the three)
    /// from one step to the next has shrunk twice in a row by a ratio below 0.9 (over the last
    /// four steps), and the last change continued as a geometric series with the larger of the
    /// two ratios adds up to at most this value. Period-2 and chaotic gaits and slowly converging ones never stop
    /// early. `None`: walk to `max_steps` or `duration`.
    pub periodic: Option<f64>,
}

impl Default for WalkLimits {
    fn default() -> Self {
        Self {
            max_steps: 100,
            duration: f64::INFINITY,
            record: false,
            periodic: None,
        }
    }
}

/// The ratio below which step-to-step changes count as converging ([`WalkLimits::periodic`]).
const PERIODIC_RATIO: f64 = 0.9;

/// The largest relative change of `T`, `dx` and `p` from step `a` to step `b`.
fn descriptor_change(a: &StepResult, b: &StepResult) -> f64 {
    let rel = |x: f64, y: f64| ((y - x) / y).abs();
    let p = match (a.p, b.p) {
        (Some(x), Some(y)) if y != 0.0 => rel(x, y),
        _ => 0.0,
    };
    rel(a.period, b.period).max(rel(a.dx, b.dx)).max(p)
}

/// Whether the last steps of `steps` are periodic within `tol` ([`WalkLimits::periodic`]):
/// three consecutive changes `d1, d2, d3` shrinking at ratios `r = max(d2/d1, d3/d2) < 0.9`,
/// with the rest of the series, `d3 r / (1 - r)`, at most `tol`.
fn is_periodic(steps: &[StepResult], tol: f64) -> bool {
    let [.., s0, s1, s2, s3] = steps else {
        return false;
    };
    let (d1, d2, d3) = (
        descriptor_change(s0, s1),
        descriptor_change(s1, s2),
        descriptor_change(s2, s3),
    );
    if d3 == 0.0 {
        return d2 == 0.0;
    }
    let ratio = (d2 / d1).max(d3 / d2);
    ratio < PERIODIC_RATIO && d3 * ratio / (1.0 - ratio) <= tol
}

/// Simulate a walk of `model` from the post-impact state `initial`
/// (`[x, z, th1, th2, xd, zd, th1d, th2d]`, time 0 = the 0th impact).
pub fn walk(model: &Model, cfg: &SimConfig, initial: [f64; 8], limits: &WalkLimits) -> Walk {
    walk_with_stats(model, cfg, initial, limits).0
}

/// [`walk`], also returning the integrator's work counters summed over the whole walk
/// (right-hand-side evaluations, accepted and rejected steps, events; for benchmarks).
pub fn walk_with_stats(
    model: &Model,
    cfg: &SimConfig,
    initial: [f64; 8],
    limits: &WalkLimits,
) -> (Walk, Stats) {
    let mut integ = Integrator::<N>::new(cfg.method, Tolerances::new(cfg.rtol, cfg.atol));
    let mut steps = Vec::new();
    let mut samples = Vec::new();
    let mut state = initial;
    let mut time = 0.0;
    let mut failure = None;
    let mut periodic = false;
    for k in 0..limits.max_steps {
        let record = limits.record.then_some((&mut samples, time));
        let res = one_step(model, cfg, &mut integ, k, state, record);
        match res {
            Ok(r) => {
                time += r.period;
                state = r.state_plus();
                steps.push(r);
                if time >= limits.duration {
                    break;
                }
                if limits.periodic.is_some_and(|tol| is_periodic(&steps, tol)) {
                    periodic = true;
                    break;
                }
            }
            Err(f) => {
                failure = Some(f);
                break;
            }
        }
    }
    (
        Walk {
            steps,
            failure,
            samples,
            periodic,
        },
        *integ.stats(),
    )
}

fn finite(v: &[f64]) -> bool {
    v.iter().all(|x| x.is_finite())
}

/// The contact of a foot at rest (`xd = 0`) under Coulomb friction at `(t, y)`: stuck if the
/// tangential force that holds it is within the friction cone (`|lambda_t| <= mu0 lambda_n`),
/// otherwise sliding the way the unbalanced force pushes it, if that slide is consistent (the
/// foot accelerates in its own direction; Painleve's paradox otherwise).
fn contact_at_rest(model: &Model, t: f64, y: &[f64; N], step: usize) -> Result<Contact, Failure> {
    let held = ground_reaction(model, t, y, Contact::Stuck);
    if held.tangential.abs() <= model.runtime.mu0 * held.normal {
        return Ok(Contact::Stuck);
    }
    let slide = Slide::of(-held.tangential);
    let (qdd, _) = model.stance(t, y, Contact::Sliding(slide));
    if qdd[0] * slide.sigma() > 0.0 {
        Ok(Contact::Sliding(slide))
    } else {
        Err(Failure::ContactInconsistent {
            step,
            t,
            normal: held.normal,
            tangential: held.tangential,
            state: mech(y),
        })
    }
}

/// The ground reaction where a contact begins (a stance phase or a segment after a stick-slip
/// transition): a negative normal force there is a lift-off, or, where only the sliding
/// friction makes it negative, an inconsistent contact (Painleve's paradox: the foot could
/// neither slide nor leave the floor without a tangential impact, which the paper's impact model
/// does not have).
fn reaction_at_start(
    foot: &Foot<'_>,
    t: f64,
    y: &[f64; N],
    step: usize,
) -> Result<Reaction, Failure> {
    let r = foot.reaction(t, y);
    if r.normal >= 0.0 || r.normal.is_nan() {
        return Ok(r);
    }
    let model = foot.model;
    Err(match model.frictionless_normal(t, y) {
        Some(n) if n >= 0.0 => Failure::ContactInconsistent {
            step,
            t,
            normal: r.normal,
            tangential: r.tangential,
            state: mech(y),
        },
        _ => Failure::LiftOff {
            step,
            t,
            lambda: r.lambda,
            state: mech(y),
        },
    })
}

/// The contact at the start of a stance phase: the smooth law, or under Coulomb friction
/// sliding with the post-impact foot velocity, or at rest.
fn initial_contact(model: &Model, y: &[f64; N], step: usize) -> Result<Contact, Failure> {
    match model.friction_law() {
        FrictionLaw::Tanh => Ok(Contact::Smooth),
        FrictionLaw::Coulomb if y[4] != 0.0 => Ok(Contact::Sliding(Slide::of(y[4]))),
        FrictionLaw::Coulomb => contact_at_rest(model, 0.0, y, step),
    }
}

/// A foot brought to rest: exactly zero velocity along the floor (`xd = 0`, and `zd = 0` with
/// it on the slope, where `zd = -xd tan phi`).
fn at_rest(mut y: [f64; N]) -> [f64; N] {
    y[4] = 0.0;
    y[5] = 0.0;
    y
}

/// Integrate one stance phase from the post-impact state `s0` and apply the impact; with
/// `record`, append samples of the motion (times offset by the second element) to the vector.
fn one_step(
    model: &Model,
    cfg: &SimConfig,
    integ: &mut Integrator<N>,
    step: usize,
    s0: [f64; 8],
    record: Option<(&mut Vec<Sample>, f64)>,
) -> Result<StepResult, Failure> {
    if !finite(&s0) {
        return Err(Failure::NonFinite {
            step,
            t: 0.0,
            state: s0,
        });
    }
    let mut y0 = [0.0; N];
    y0[..8].copy_from_slice(&s0);
    let lambda_max = cfg.lambda_blowup * model.physical.total_mass() * model.physical.g;
    let foot = Foot::new(model, initial_contact(model, &y0, step)?);

    let r0 = foot.reaction(0.0, &y0);
    if !r0.lambda.is_finite() || r0.lambda.abs() > lambda_max {
        // Where the angular velocities alone overflow `lambda` (their squares exceed the
        // floating-point range) its denominator is regular: the state is the problem.
        let mut unspun = y0;
        unspun[6] = 0.0;
        unspun[7] = 0.0;
        let l_rest = foot.reaction(0.0, &unspun).lambda;
        return Err(if !r0.lambda.is_finite() && l_rest.abs() <= lambda_max {
            Failure::NonFinite {
                step,
                t: 0.0,
                state: s0,
            }
        } else {
            Failure::LambdaDenominatorZero {
                step,
                t: 0.0,
                lambda: r0.lambda,
                state: s0,
            }
        });
    }
    reaction_at_start(&foot, 0.0, &y0, step)?;
    let (record, t_offset) = match record {
        Some((out, t_offset)) => {
            out.push(Sample {
                time: t_offset,
                step,
                state: s0,
                lambda: r0.lambda,
                u: control_input(model, 0.0, &y0, foot.contact()),
            });
            (Some(out), t_offset)
        }
        None => (None, 0.0),
    };

    let heel = model.heel_strike_angle();
    let rear = model.rear_contact_angle();
    let mu0 = model.runtime.mu0;
    let kinks = Cell::new(model.is_active());
    let mut lambda_min = r0.lambda;
    let foot = &foot;
    let mut events = [
        Event::terminal(Direction::Rising, move |_, y: &[f64; N]| y[2] - heel),
        Event::terminal(Direction::Falling, |t, y: &[f64; N]| {
            foot.reaction(t, y).normal
        }),
        Event::terminal(Direction::Falling, move |_, y: &[f64; N]| y[2] - rear),
        Event::terminal(Direction::Rising, |t, y: &[f64; N]| {
            foot.reaction(t, y).lambda.abs() - lambda_max
        }),
        // The power kink: `ydot u` changes sign before `T_set` (where `|ydot u|`, the power
        // quadrature's integrand, has a kink; see `Stance::controlled_components`). Off from
        // the breakpoint at `T_set` on (a switch by time would be a jump at the breakpoint).
        Event::terminal(Direction::Either, |t, y: &[f64; N]| {
            if kinks.get() { foot.power(t, y) } else { 1.0 }
        }),
        // Coulomb: a sliding foot comes to rest (sigma xd reaches zero; zero while stuck).
        Event::terminal(Direction::Falling, |_, y: &[f64; N]| {
            foot.contact().sigma() * y[4]
        }),
        // Coulomb: a stuck foot starts to slip (the force that holds it leaves the cone).
        Event::terminal(Direction::Rising, |t, y: &[f64; N]| {
            if foot.contact() == Contact::Stuck {
                let r = foot.reaction(t, y);
                r.tangential.abs() - mu0 * r.normal
            } else {
                -1.0
            }
        }),
    ];
    let n_events = match model.friction_law() {
        FrictionLaw::Tanh => 5,
        FrictionLaw::Coulomb => 7,
    };
    let mut obs = Recorder {
        foot,
        out: record,
        t_offset,
        step,
        interior: 3,
    };
    let mut sys = Stance {
        model,
        jac: crate::jacobian::Jac::new(model).ok(),
        foot,
    };
    let mut t = 0.0;
    let mut y = y0;
    let mut stuck_time = 0.0;
    let t_limit = cfg.max_step_time;
    let (te, ye) = loop {
        let (t_start, contact) = (t, foot.contact());
        let out = integ.integrate(&mut sys, t, &y, t_limit, &mut events[..n_events], &mut obs);
        if contact == Contact::Stuck {
            stuck_time += out.t() - t_start;
        }
        let lam = foot.reaction(out.t(), out.y()).lambda;
        if lam.is_finite() {
            lambda_min = lambda_min.min(lam);
        }
        match out {
            Outcome::Breakpoint { t: tb, y: yb } => {
                // The only breakpoint is `T_set`, where the input power stops counting.
                kinks.set(false);
                t = tb;
                y = yb;
            }
            Outcome::Event { index: 0, t, y } => break (t, y),
            Outcome::Event {
                index: 4,
                t: tk,
                y: yk,
            } => (t, y) = (tk, yk),
            Outcome::Event {
                index: 5,
                t: te,
                y: ye,
            } => {
                // The sliding foot stops: it sticks, or slides back if the cone cannot hold it.
                y = at_rest(ye);
                t = te;
                foot.contact.set(contact_at_rest(model, t, &y, step)?);
                reaction_at_start(foot, t, &y, step)?;
            }
            Outcome::Event {
                index: 6,
                t: te,
                y: ye,
            } => {
                // The stuck foot slips, the way the force that held it no longer can.
                let held = foot.reaction(te, &ye);
                foot.contact
                    .set(Contact::Sliding(Slide::of(-held.tangential)));
                (t, y) = (te, ye);
                reaction_at_start(foot, t, &y, step)?;
            }
            Outcome::Event { index: 1, t, y } => {
                return Err(if lam.abs() > lambda_max * 1e-3 || !lam.is_finite() {
                    Failure::LambdaDenominatorZero {
                        step,
                        t,
                        lambda: lam,
                        state: mech(&y),
                    }
                } else {
                    Failure::LiftOff {
                        step,
                        t,
                        lambda: lam,
                        state: mech(&y),
                    }
                });
            }
            Outcome::Event { index: 2, t, y } => {
                return Err(Failure::FellBackward {
                    step,
                    t,
                    th1: y[2],
                    state: mech(&y),
                });
            }
            Outcome::Event { t, y, .. } => {
                return Err(Failure::LambdaDenominatorZero {
                    step,
                    t,
                    lambda: lam,
                    state: mech(&y),
                });
            }
            Outcome::Reached { t, y } => {
                return Err(Failure::NoImpact {
                    step,
                    t,
                    state: mech(&y),
                });
            }
            Outcome::NonFinite { t, y } => {
                return Err(if !lam.is_finite() || lam.abs() > lambda_max * 1e-3 {
                    Failure::LambdaDenominatorZero {
                        step,
                        t,
                        lambda: lam,
                        state: mech(&y),
                    }
                } else {
                    Failure::NonFinite {
                        step,
                        t,
                        state: mech(&y),
                    }
                });
            }
            Outcome::StepSizeTooSmall { t, y, .. } | Outcome::MaxSteps { t, y } => {
                if !lam.is_finite() || lam.abs() > lambda_max * 1e-3 {
                    return Err(Failure::LambdaDenominatorZero {
                        step,
                        t,
                        lambda: lam,
                        state: mech(&y),
                    });
                }
                let reason = if matches!(out, Outcome::MaxSteps { .. }) {
                    "too many steps"
                } else {
                    "step size too small"
                };
                return Err(Failure::Integrator {
                    step,
                    t,
                    reason: reason.to_owned(),
                    state: mech(&y),
                });
            }
            Outcome::InvalidInput { t, y, reason } => {
                return Err(Failure::Integrator {
                    step,
                    t,
                    reason: reason.to_owned(),
                    state: mech(&y),
                });
            }
        }
    };

    let pre = mech(&ye);
    if te <= 0.0 {
        return Err(Failure::ImpactAtStart { step, state: pre });
    }
    if model.is_active() && te < model.runtime.t_set {
        return Err(Failure::ImpactBeforeTSet {
            step,
            t: te,
            t_set: model.runtime.t_set,
            state: pre,
        });
    }
    let imp = model.impact(&pre);
    if imp.rear_impulse >= 0.0 {
        return Err(Failure::DoubleSupport {
            step,
            t: te,
            rear_impulse: imp.rear_impulse,
            state: pre,
        });
    }
    let [x, z, th1, th2, ..] = pre;
    let [xd, zd, th1d, th2d] = imp.qd;
    let [xf, zf, xdf, zdf] = model.fore_foot(x, z, th1, xd, zd, th1d);
    let (z_plus, normal_velocity) = match model.kind() {
        Kind::ActiveLevel => (0.0, zdf),
        Kind::PassiveSlope => (zf, zdf + xdf * model.runtime.phi.tan()),
    };
    let q_plus = [xf, z_plus, th1 - model.physical.alpha, th2];
    let qd_plus = [xdf, zdf, th1d, th2d];
    let dx = (xf - s0[0]) / model.runtime.phi.cos();
    let speed = dx / te;
    let (p, sr) = if model.is_active() {
        let p = ye[8] / te;
        (
            Some(p),
            Some(p / (model.physical.total_mass() * model.physical.g * speed)),
        )
    } else {
        (None, None)
    };
    let all = [
        dx,
        speed,
        p.unwrap_or(0.0),
        sr.unwrap_or(0.0),
        imp.rear_impulse,
    ];
    if !finite(&q_plus) || !finite(&qd_plus) || !finite(&all) {
        return Err(Failure::NonFinite {
            step,
            t: te,
            state: pre,
        });
    }
    Ok(StepResult {
        period: te,
        dx,
        speed,
        p,
        sr,
        q_plus,
        qd_plus,
        foot_normal_velocity: normal_velocity,
        rear_impulse: imp.rear_impulse,
        lambda_min,
        stuck_time,
    })
}

#[cfg(test)]
mod tests {
    use super::{StepResult, is_periodic};

    /// Steps whose `T`, `dx` and `p` approach 1 as `1 + d_k`.
    fn steps(d: &[f64]) -> Vec<StepResult> {
        d.iter()
            .map(|&d| StepResult {
                period: 1.0 + d,
                dx: 1.0 + d,
                speed: 1.0,
                p: Some(1.0 + d),
                sr: None,
                q_plus: [0.0; 4],
                qd_plus: [0.0; 4],
                foot_normal_velocity: 0.0,
                rear_impulse: 0.0,
                lambda_min: 0.0,
                stuck_time: 0.0,
            })
            .collect()
    }

    #[test]
    fn a_geometric_approach_is_periodic_once_its_tail_is_within_the_tolerance() {
        // Deviations 0.5^k: changes of about 0.5^(k+1), ratio 0.5, so the tail is about the
        // last change.
        let d: Vec<f64> = (0..40).map(|k| 0.5_f64.powi(k)).collect();
        let first = (4..=d.len())
            .find(|&n| is_periodic(&steps(&d[..n]), 1e-6))
            .expect("stops");
        // The change from step n-2 to n-1 is about 0.5^(n-1); its tail about the same.
        let last_change = 0.5_f64.powi(first as i32 - 2) - 0.5_f64.powi(first as i32 - 1);
        assert!(last_change <= 1.1e-6 && 2.0 * last_change > 1e-6, "{first}");
        // Exactly repeating steps are periodic.
        assert!(is_periodic(&steps(&[0.0; 4]), 1e-12));
    }

    #[test]
    fn slow_alternating_and_growing_changes_are_never_periodic() {
        // Ratio 0.95 (slow convergence), alternating deviations (period 2), growth.
        for d in [
            (0..60).map(|k| 1e-9 * 0.95_f64.powi(k)).collect::<Vec<_>>(),
            (0..60)
                .map(|k| if k % 2 == 0 { 1e-9 } else { -1e-9 })
                .collect(),
            (0..60).map(|k| 1e-12 * 1.1_f64.powi(k)).collect(),
        ] {
            assert!((4..=d.len()).all(|n| !is_periodic(&steps(&d[..n]), 1e-6)));
        }
    }
}
