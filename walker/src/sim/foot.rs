//! The stance foot: its contact with the floor, the ground reaction and the input power's sign
//! function (remembered where several users ask about the same point), and the choice of
//! contact where a foot starts a stance phase or comes to rest under Coulomb friction.

use std::cell::{Cell, RefCell};

use crate::model::{Contact, FrictionLaw, Model, Reaction, Slide};
use crate::vector::{MAX_COORDINATES, Vector};

use super::failure::{Failure, FailureKind};
use super::state::mech;

/// The control inputs `u` of Eq. 31 (`u = A^-1 (v + B)`, `v` from Eq. 32) at `(t, y)` in the
/// contact `contact`; empty for a passive walker.
pub fn control_input(model: &Model, t: f64, y: &[f64], contact: Contact) -> Vector {
    model.control_input(t, y, contact)
}

/// The ground's force on the stance foot at `(t, y)` in the contact `contact`, with the control
/// input of that point.
pub fn ground_reaction(model: &Model, t: f64, y: &[f64], contact: Contact) -> Reaction {
    model.reaction(t, y, contact)
}

/// A remembered value of a function of `(t, mechanical state, contact)`.
#[derive(Clone, Copy, Debug)]
struct Memo<T> {
    t: f64,
    state: Vector,
    contact: Contact,
    value: T,
}

impl<T: Copy> Memo<T> {
    /// The value remembered for `(t, y, contact)`, if it is this point (compared in place:
    /// the memo is asked at every guard check, and copying it out costs more than the look).
    fn at<const S: usize>(&self, t: f64, y: &[f64; S], contact: Contact) -> Option<T> {
        (self.t == t && self.contact == contact && *self.state == y[..S - 1]).then_some(self.value)
    }
}

/// Two remembered points of a function, and the slot the next goes to.
type Remembered<T> = RefCell<([Option<Memo<T>>; 2], usize)>;

/// The value of `f` at `(t, y, contact)`, from the two points `memo` remembers if it is one of
/// them (the newer slot first), else computed and remembered in the older slot (slots are
/// overwritten in turn, not moved).
fn remembered<T: Copy, const S: usize>(
    memo: &Remembered<T>,
    t: f64,
    y: &[f64; S],
    contact: Contact,
    f: impl FnOnce() -> T,
) -> T {
    let mut memo = memo.borrow_mut();
    let (slots, next) = &mut *memo;
    let newer = *next ^ 1;
    if let Some(g) = [newer, *next]
        .into_iter()
        .find_map(|i| slots[i].as_ref().and_then(|m| m.at(t, y, contact)))
    {
        return g;
    }
    let value = f();
    slots[*next] = Some(Memo {
        t,
        state: mech(y),
        contact,
        value,
    });
    *next = newer;
    value
}

/// The stance foot during one stance phase: the model, the current contact (it changes only
/// between integration segments, at stick-slip transitions), and remembered values of what
/// several users evaluate at the same points.
pub(super) struct Foot<'a> {
    /// The model.
    pub(super) model: &'a Model,
    contact: Cell<Contact>,
    /// The last ground reaction: the lift-off, blow-up and slip guards share it.
    reaction: RefCell<Option<Memo<Reaction>>>,
    /// The last two values of the power's sign function (a step's start is the previous
    /// step's end, and the error test and the kink guard ask about the same ends), with the
    /// slot the next value goes to (the older one: slots are overwritten in turn, not moved).
    power: Remembered<f64>,
    /// The same for every input's power `u_i w_i` (a walker with several inputs).
    powers: Remembered<[f64; MAX_COORDINATES]>,
    /// Whether the model has several inputs, whose kinks are watched one by one.
    pub(super) several: bool,
}

impl<'a> Foot<'a> {
    /// The foot of `model` in the contact `contact`, nothing remembered yet.
    pub(super) fn new(model: &'a Model, contact: Contact) -> Self {
        Self {
            model,
            contact: Cell::new(contact),
            reaction: RefCell::new(None),
            power: RefCell::new(([None; 2], 0)),
            powers: RefCell::new(([None; 2], 0)),
            several: model.inputs() > 1,
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
    pub(super) fn reaction<const S: usize>(&self, t: f64, y: &[f64; S]) -> Reaction {
        let contact = self.contact();
        if let Some(r) = self
            .reaction
            .borrow()
            .as_ref()
            .and_then(|m| m.at(t, y, contact))
        {
            return r;
        }
        let value = ground_reaction(self.model, t, y, contact);
        *self.reaction.borrow_mut() = Some(Memo {
            t,
            state: mech(y),
            contact,
            value,
        });
        value
    }

    /// The power's sign function `prod u_i w_i` at `(t, y)` in the current contact (remembered
    /// for two points).
    pub(super) fn power<const S: usize>(&self, t: f64, y: &[f64; S]) -> f64 {
        // Written out, not through `remembered` (which every input's powers use): this is the
        // path of every walk of the paper's walker, and the generic one, even inlined, cost
        // 0.4 % of a walk's instructions.
        let contact = self.contact();
        let mut memo = self.power.borrow_mut();
        let (slots, next) = &mut *memo;
        // The newer slot first (a value is stored only where neither slot has its point).
        let newer = *next ^ 1;
        if let Some(g) = [newer, *next]
            .into_iter()
            .find_map(|i| slots[i].as_ref().and_then(|m| m.at(t, y, contact)))
        {
            return g;
        }
        let value = self.model.power_sign_function(t, y, contact);
        slots[*next] = Some(Memo {
            t,
            state: mech(y),
            contact,
            value,
        });
        *next = newer;
        value
    }

    /// Input `i`'s power `u_i w_i` at `(t, y)` in the current contact (every input's
    /// remembered for two points).
    #[inline(never)]
    pub(super) fn input_power<const S: usize>(&self, t: f64, y: &[f64; S], i: usize) -> f64 {
        self.input_powers(t, y)[i]
    }

    /// Every input's power `u_i w_i` at `(t, y)` in the current contact.
    fn input_powers<const S: usize>(&self, t: f64, y: &[f64; S]) -> [f64; MAX_COORDINATES] {
        let contact = self.contact();
        remembered(&self.powers, t, y, contact, || {
            let mut p = [0.0; MAX_COORDINATES];
            let m = self.model.inputs();
            self.model.input_powers(t, y, contact, &mut p[..m]);
            p
        })
    }

    /// Whether an input's power `u_i w_i` changes sign from `(t0, y0)` to `(t1, y1)` while the
    /// power counts (the kink of `|u_i w_i|` is then inside the step): the product's sign for
    /// a walker with one input, each input's for one with several (two of them changing sign
    /// in one step leave the product's unchanged).
    pub(super) fn crossed<const S: usize>(
        &self,
        t0: f64,
        y0: &[f64; S],
        t1: f64,
        y1: &[f64; S],
    ) -> bool {
        if !self.model.power_counts(t0) {
            return false;
        }
        if self.several {
            return self.an_input_crossed(t0, y0, t1, y1);
        }
        self.power(t0, y0) * self.power(t1, y1) < 0.0
    }

    /// [`Foot::crossed`] for a walker with several inputs: any input's power changes sign.
    #[inline(never)]
    fn an_input_crossed<const S: usize>(
        &self,
        t0: f64,
        y0: &[f64; S],
        t1: f64,
        y1: &[f64; S],
    ) -> bool {
        let m = self.model.inputs();
        let (a, b) = (self.input_powers(t0, y0), self.input_powers(t1, y1));
        a[..m].iter().zip(&b[..m]).any(|(x, y)| x * y < 0.0)
    }
}

/// The contact of a foot at rest (`xd = 0`) under Coulomb friction at `(t, y)`: stuck if the
/// tangential force that holds it is within the friction cone (`|lambda_t| <= mu0 lambda_n`),
/// otherwise sliding the way the unbalanced force pushes it, if that slide is consistent (the
/// foot accelerates in its own direction; Painleve's paradox otherwise). Forces or an
/// acceleration that are not finite (a spin whose square overflows) decide nothing: the
/// failure is [`FailureKind::NonFinite`], not an inconsistent contact.
pub(super) fn contact_at_rest<const S: usize>(
    model: &Model,
    t: f64,
    y: &[f64; S],
    step: usize,
) -> Result<Contact, Failure> {
    let held = ground_reaction(model, t, y, Contact::Stuck);
    if !(held.normal.is_finite() && held.tangential.is_finite()) {
        return Err(FailureKind::NonFinite.at(step, t, mech(y)));
    }
    if held.tangential.abs() <= model.mu0() * held.normal {
        return Ok(Contact::Stuck);
    }
    let slide = Slide::of(-held.tangential);
    let mut qdd = [0.0; Model::STANCE_LEN];
    model.stance(t, y, Contact::Sliding(slide), &mut qdd);
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
pub(super) fn reaction_at_start<const S: usize>(
    foot: &Foot<'_>,
    t: f64,
    y: &[f64; S],
    step: usize,
) -> Result<Reaction, Failure> {
    let r = foot.reaction(t, y);
    if r.normal >= 0.0 || r.normal.is_nan() {
        return Ok(r);
    }
    let kind = match foot.model.frictionless_normal(t, y) {
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
pub(super) fn initial_contact<const S: usize>(
    model: &Model,
    y: &[f64; S],
    step: usize,
) -> Result<Contact, Failure> {
    let xd = y[model.n()];
    match model.friction_law() {
        FrictionLaw::Tanh => Ok(Contact::Smooth),
        FrictionLaw::Coulomb if xd != 0.0 => Ok(Contact::Sliding(Slide::of(xd))),
        FrictionLaw::Coulomb => contact_at_rest(model, 0.0, y, step),
    }
}

/// A foot brought to rest: exactly zero velocity along the floor (`xd = 0`, and `zd = 0` with
/// it on the slope, where `zd = -xd tan phi`).
pub(super) fn at_rest<const S: usize>(mut y: [f64; S], n: usize) -> [f64; S] {
    y[n] = 0.0;
    y[n + 1] = 0.0;
    y
}
