//! Why a walk ended early: a [`Failure`] is where and when (step, time, state), its
//! [`FailureKind`] is the cause with only the cause's own data.
//!
//! The JSON of a failure is one flat object, `{"kind": "LiftOff", "step": .., "t": .., "state":
//! [..], "lambda": ..}`: the kind's tag and data sit beside the common fields.

use serde::Serialize;

use crate::ode::GaveUp;
use crate::vector::Vector;

/// Why a walk ended early, and where: the step number (0 for the step that starts at the initial
/// condition), the time since the last impact and the mechanical state `[q, qd]` where it
/// happened.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Failure {
    /// Step number.
    pub step: usize,
    /// Time since the last impact (see each [`FailureKind`] for which time).
    pub t: f64,
    /// State `[q, qd]` (see each [`FailureKind`] for which state).
    pub state: Vector,
    /// The cause.
    #[serde(flatten)]
    pub kind: FailureKind,
}

impl Failure {
    /// The failure's name as printed by the CLI (`"lift-off"`, a fall's name in its model
    /// file, ...).
    pub fn name(&self) -> &str {
        self.kind.name()
    }
}

/// The cause of a [`Failure`], with the data that belongs to it.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind")]
pub enum FailureKind {
    /// The vertical ground reaction `lambda` became negative during stance (Eq. 23).
    LiftOff {
        /// `lambda` where the crossing was located (about zero) or at the start of the step.
        lambda: f64,
    },
    /// Coulomb friction (Eq. 25): the stance foot is at rest, the tangential force that would
    /// hold it exceeds `mu0` times the normal force, and sliding the way that force pushes
    /// would accelerate the foot the other way: no contact mode is consistent (Painleve's
    /// paradox of sliding friction).
    ContactInconsistent {
        /// The normal force with the foot held.
        normal: f64,
        /// The tangential force with the foot held.
        tangential: f64,
    },
    /// The strike came before the output-following control finished its ramps (`t < T_set`
    /// in the paper, which assumes the control complete by the next impact, Section 3.2); `t`
    /// is the time of the strike and the state the pre-impact state.
    ImpactBeforeTSet {
        /// The end of the last ramp (`T_set`).
        t_set: f64,
    },
    /// The rear foot's impulse with the rear foot kept on the floor is non-negative: the
    /// impact would lead to double support (Eq. 11 on level ground, Eq. 46 on the slope); `t`
    /// is the time of the heel strike and the state the pre-impact state.
    DoubleSupport {
        /// The rear-foot impulse (`impact3_level`'s or `impact2_slope`'s `lambda_I[1]`; with
        /// friction at the impact, `walker::model::rear_test`).
        rear_impulse: f64,
    },
    /// The heel strike's normal impulse `Lambda_n` is negative: the striking foot was not
    /// approaching the floor (a kinematic strike guard, such as the three-link biped's
    /// `beta - th_st`, can be met with the foot rising), and the impact map, which stops the
    /// foot's normal velocity whatever its sign, would pull it onto the floor. No impact
    /// happens there; `t` is the time of the strike and the state the pre-impact state.
    ImpactPulls {
        /// The normal impulse `Lambda_n` (N s, negative).
        normal_impulse: f64,
    },
    /// The impact with Coulomb friction at the striking foot has no rigid-body solution: while
    /// the foot slips, more normal impulse makes it approach the floor faster and the slip
    /// never stops (Painleve's paradox at an impact, `docs/impacts.md`); `t` is the time of the heel strike and the
    /// state the pre-impact state.
    ImpactJam {
        /// The slip direction in which the impact jams.
        slip: crate::model::Slide,
    },
    /// `lambda` blew up because the denominator `D` of Eq. 23 vanished (a Painleve-type
    /// singularity): `|D|` is at most `1e3 / lambda_blowup` times its constant term `I1`
    /// (`1e-3 I1` by default; see `sim/blowup.rs`).
    LambdaDenominatorZero {
        /// `lambda` there (huge or not finite; non-finite values are reported as `null`).
        lambda: f64,
    },
    /// `|lambda|` exceeded the blow-up threshold
    /// ([`super::SimConfig::lambda_blowup`] `m_t g`; a thousandth of it where the integrator
    /// gave up or met a non-finite value) with a regular denominator of Eq. 23: its
    /// numerator `m_t (I1 (g - l th1d^2 cos th1) - l u sin th1)` is huge, through the control
    /// input `u` (a ramp `T_set` so short that `ydd_d = 60 alpha / T_set^2` is huge: from
    /// about `1e-100` to `1e-4` s with Table 1; shorter ramps overflow the kernels, which is
    /// [`FailureKind::NonFinite`]) or the spin `th1d^2` (`omega0 = 1e5` to `1e150`). Also a
    /// stuck foot's reaction beyond the threshold (it has no pole).
    LambdaNumeratorHuge {
        /// `lambda` there (finite).
        lambda: f64,
        /// The control input `u` of Eq. 31 there, the largest in magnitude of several (finite;
        /// 0 for a passive walker).
        u: f64,
    },
    /// One of the model's falls (`[[fall]]`): a point touched the floor or a guard reached zero
    /// (the paper's wheel rolling back onto its rear spoke is the fall `fell-backward`).
    Fall {
        /// The fall's name in the model file.
        name: String,
        /// What happened, from the model file.
        doc: String,
    },
    /// The heel strike happened at the very start of the step (a step of zero duration, so no
    /// step period, speed or power exists): the state began on the impact guard moving into
    /// the floor. `t` is 0 and the state the pre-impact state.
    ImpactAtStart,
    /// The stance foot slides at the start of a step whose floor has another slope than the
    /// floor it slid on (a floor that sets the slope per step, `crate::floor`): its velocity
    /// along the old floor has a part normal to the new one, a kink the model has no impact
    /// for. `t` is 0 and the state the post-impact state of the step before.
    SlopeKink {
        /// The slope of the floor the foot slid on (rad).
        from: f64,
        /// The slope of the step's floor (rad).
        to: f64,
        /// The foot's speed (m/s).
        speed: f64,
    },
    /// No heel strike within [`super::SimConfig::max_step_time`]; `t` is that limit.
    NoImpact,
    /// A state, an acceleration, a descriptor or the active walker's desired trajectory (its
    /// `ydd_d` overflows for `T_set` below about `1e-154`) was not finite; `t` and the state are
    /// the last finite ones.
    NonFinite,
    /// The integrator gave up; `t` and the state are where it stopped.
    Integrator {
        /// Why (serialised as its text, `"too many steps"`, ...).
        reason: GaveUp,
    },
}

impl FailureKind {
    /// The failure's name as printed by the CLI (`"lift-off"`, a fall's name in its model
    /// file, ...).
    pub fn name(&self) -> &str {
        match self {
            FailureKind::LiftOff { .. } => "lift-off",
            FailureKind::ContactInconsistent { .. } => "contact-inconsistent",
            FailureKind::ImpactBeforeTSet { .. } => "impact-before-t-set",
            FailureKind::DoubleSupport { .. } => "double-support",
            FailureKind::ImpactPulls { .. } => "impact-pulls",
            FailureKind::ImpactJam { .. } => "impact-jam",
            FailureKind::LambdaDenominatorZero { .. } => "lambda-denominator-zero",
            FailureKind::LambdaNumeratorHuge { .. } => "lambda-numerator-huge",
            FailureKind::Fall { name, .. } => name,
            FailureKind::ImpactAtStart => "impact-at-start",
            FailureKind::SlopeKink { .. } => "slope-kink",
            FailureKind::NoImpact => "no-impact",
            FailureKind::NonFinite => "non-finite",
            FailureKind::Integrator { .. } => "integrator",
        }
    }

    /// This cause at step `step`, time `t` and state `state`.
    pub fn at(self, step: usize, t: f64, state: Vector) -> Failure {
        Failure {
            step,
            t,
            state,
            kind: self,
        }
    }
}
