//! The stance foot: its contact with the floor, the ground reaction and the control input
//! (remembered where several users ask about the same point), and the choice of contact where a
//! foot starts a stance phase or comes to rest under Coulomb friction.

use std::cell::Cell;

use crate::model::{Contact, FrictionLaw, Model, Reaction, Slide};

use super::failure::{Failure, FailureKind};
use super::state::{N, mech};

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
pub(super) struct Foot<'a> {
    /// The model.
    pub(super) model: &'a Model,
    contact: Cell<Contact>,
    /// The last ground reaction: the lift-off, blow-up and slip guards share it.
    reaction: Cell<Memo<Reaction>>,
    /// The last two values of `ydot u` (a step's start is the previous step's end, and the
    /// error test and the power observer ask about the same ends).
    power: Cell<[Memo<f64>; 2]>,
}

impl<'a> Foot<'a> {
    /// The foot of `model` in the contact `contact`, nothing remembered yet.
    pub(super) fn new(model: &'a Model, contact: Contact) -> Self {
        Self {
            model,
            contact: Cell::new(contact),
            reaction: Cell::new(None),
            power: Cell::new([None; 2]),
        }
    }

    /// The current contact.
    pub(super) fn contact(&self) -> Contact {
        self.contact.get()
    }

    /// Change the contact (at a stick-slip transition, between integration segments).
    pub(super) fn set_contact(&self, contact: Contact) {
        self.contact.set(contact);
    }

    /// The ground reaction at `(t, y)` in the current contact (remembered for one point).
    pub(super) fn reaction(&self, t: f64, y: &[f64; N]) -> Reaction {
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

    /// The input-power integrand `ydot u` at `(t, y)` in the current contact (remembered for
    /// two points).
    pub(super) fn power(&self, t: f64, y: &[f64; N]) -> f64 {
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
    pub(super) fn crossed(&self, t0: f64, y0: &[f64; N], t1: f64, y1: &[f64; N]) -> bool {
        self.model.is_active()
            && t0 < self.model.runtime.t_set
            && self.power(t0, y0) * self.power(t1, y1) < 0.0
    }
}

/// The contact of a foot at rest (`xd = 0`) under Coulomb friction at `(t, y)`: stuck if the
/// tangential force that holds it is within the friction cone (`|lambda_t| <= mu0 lambda_n`),
/// otherwise sliding the way the unbalanced force pushes it, if that slide is consistent (the
/// foot accelerates in its own direction; Painleve's paradox otherwise). Forces or an
/// acceleration that are not finite (a spin whose square overflows) decide nothing: the
/// failure is [`FailureKind::NonFinite`], not an inconsistent contact.
pub(super) fn contact_at_rest(
    model: &Model,
    t: f64,
    y: &[f64; N],
    step: usize,
) -> Result<Contact, Failure> {
    let held = ground_reaction(model, t, y, Contact::Stuck);
    if !(held.normal.is_finite() && held.tangential.is_finite()) {
        return Err(FailureKind::NonFinite.at(step, t, mech(y)));
    }
    if held.tangential.abs() <= model.runtime.mu0 * held.normal {
        return Ok(Contact::Stuck);
    }
    let slide = Slide::of(-held.tangential);
    let (qdd, _) = model.stance(t, y, Contact::Sliding(slide));
    if !qdd[0].is_finite() {
        return Err(FailureKind::NonFinite.at(step, t, mech(y)));
    }
    if qdd[0] * slide.sigma() > 0.0 {
        Ok(Contact::Sliding(slide))
    } else {
        Err(FailureKind::ContactInconsistent {
            normal: held.normal,
            tangential: held.tangential,
        }
        .at(step, t, mech(y)))
    }
}

/// The ground reaction where a contact begins (a stance phase or a segment after a stick-slip
/// transition): a negative normal force there is a lift-off, or, where only the sliding
/// friction makes it negative, an inconsistent contact (Painleve's paradox: the foot could
/// neither slide nor leave the floor without a tangential impact, which the paper's impact model
/// does not have).
pub(super) fn reaction_at_start(
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
    let kind = match model.frictionless_normal(t, y) {
        Some(n) if n >= 0.0 => FailureKind::ContactInconsistent {
            normal: r.normal,
            tangential: r.tangential,
        },
        _ => FailureKind::LiftOff { lambda: r.lambda },
    };
    Err(kind.at(step, t, mech(y)))
}

/// The contact at the start of a stance phase: the smooth law, or under Coulomb friction
/// sliding with the post-impact foot velocity, or at rest.
pub(super) fn initial_contact(
    model: &Model,
    y: &[f64; N],
    step: usize,
) -> Result<Contact, Failure> {
    match model.friction_law() {
        FrictionLaw::Tanh => Ok(Contact::Smooth),
        FrictionLaw::Coulomb if y[4] != 0.0 => Ok(Contact::Sliding(Slide::of(y[4]))),
        FrictionLaw::Coulomb => contact_at_rest(model, 0.0, y, step),
    }
}

/// A foot brought to rest: exactly zero velocity along the floor (`xd = 0`, and `zd = 0` with
/// it on the slope, where `zd = -xd tan phi`).
pub(super) fn at_rest(mut y: [f64; N]) -> [f64; N] {
    y[4] = 0.0;
    y[5] = 0.0;
    y
}
