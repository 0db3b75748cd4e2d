//! The stance phase of the Poincare map with the variational equations appended
//! ([`Variational`]), integrated phase by phase: under exact Coulomb friction the stance foot
//! slides or sticks, and each event that switches the phase (a sliding foot comes to rest, a
//! stuck foot starts to slip) applies its saltation matrix to the sensitivity `Phi`.
//!
//! # Saltation
//!
//! At an event `g(y) = 0` crossed with the field `f-`, followed by the reset `y+ = R(y)` and the
//! field `f+`, a perturbed trajectory reaches the event earlier or later by
//! `dt = -g_y dy / (g_y f-)`, so the sensitivity jumps by the saltation matrix
//! `Xi = DR + (f+ - DR f-) g_y^T / (g_y f-)`, `Phi+ = Xi Phi` (Aizerman and Gantmacher 1958;
//! Hiskens and Pai 2000):
//!
//! - the foot comes to rest (`g = sigma xd`, `g_y = sigma e_xd`): `R` sets `xd = zd = 0`
//!   (`DR` the identity with those rows zero), `f+` the stuck field (or the slide back, where
//!   the cone cannot hold the foot). A stuck foot has `xd = zd = 0` exactly, so the rows of
//!   `xd`, `zd` of `Phi` are zero after it, and stay zero (the stuck field's `xdd = zdd = 0`);
//! - the stuck foot starts to slip (`g = |lambda_t| - mu0 lambda_n`, its gradient from the rows
//!   of the ground force in `stick_jacobian`; for a model with inputs `g = lambda_n (|mu*| -
//!   mu0)` with the held foot's friction ratio `mu*`, whose gradient there is `lambda_n
//!   sign(mu*) d mu*/dy`, `jacobian.rs`): no reset; the force is continuous across the
//!   switch (on the cone's edge the held force is the sliding one), so `f+ - f-` is zero up to
//!   the event's location and `Xi` is the identity to that accuracy; it is applied as computed.
//!   With inputs the guard depends on time too, through the desired trajectories in `v(t, y)`:
//!   the crossing moves by `dt = -g_y dy / (g_y f- + g_t)`, so `g_t = lambda_n sign(mu*) d
//!   mu*/dt` joins the denominator.
//! - the strike: in [`super::map`], before the impact's Jacobian (`f+` is replaced by the
//!   impact, `Xi = I - f- g_y^T / (g_y f-)`).
//!
//! The ends of the desired trajectories' ramps (`T_set`) are breakpoints where the field jumps
//! in time only: the guard `g = t - T_set` has `g_y = 0`, so `Xi = I` and `Phi` is continuous
//! there. The power kink the simulator stops at concerns the input power's quadrature only (the
//! mechanical field is smooth there), which the map does not integrate.
//!
//! A stance phase that starts with the foot at rest and stuck (after a sticking impact) starts
//! with the rows of `xd` and `zd` of `Phi(0)` zero: a perturbation off `xd = 0` is no motion of
//! the walker there (the map exists only with the foot at rest), as the finite differences
//! leave those columns zero.

use std::cell::Cell;

use crate::jacobian::{Scratch, StanceJacobian};
use crate::model::{Contact, FrictionLaw, Model, Slide};
use crate::ode::{Direction, Event, GaveUp, Integrator, NoObserver, OdeSystem, Outcome};
use crate::sim::SimConfig;
use crate::vector::MAX_LEN;

use super::error::MapError;
use super::parameter::ParameterRates;

/// Why the variational stance could not be integrated: a failure of the map, or a contact whose
/// Jacobian the model's kernels do not give (the caller falls back to finite differences).
#[derive(Debug)]
pub(super) enum PhaseError {
    /// The map failed.
    Map(MapError),
    /// No Jacobian for a contact the stance reaches: no kernel, or a held foot of a model with
    /// inputs where its friction ratio has no derivative (`NoJacobian::HeldRatioSingular`).
    NoKernel,
}

impl From<MapError> for PhaseError {
    fn from(e: MapError) -> Self {
        PhaseError::Map(e)
    }
}

/// The stance phase with the variational equations appended: `[s, Phi S, psi, 0...]`, `s =
/// [q, qd]` (`2n` numbers), then the `cols` columns of `Phi S` (`Phi` the `2n x 2n` sensitivity,
/// `S` the seeds the map follows: the identity for the full Jacobian, the section's tangent
/// `E` for the reduced one), each `2n` numbers, then the parameter's column `psi` if any;
/// the rest of the array (a size rounded up, `map.rs`) stays zero and out of the error test.
pub(super) struct Variational<'a> {
    pub(super) model: &'a Model,
    pub(super) jac: StanceJacobian<'a>,
    pub(super) contact: &'a Cell<Contact>,
    /// The kernels' outputs, kept from one right-hand side to the next.
    pub(super) scratch: Scratch,
    /// `d qdd / d y`, `n x 2n` row-major.
    pub(super) a: [f64; MAX_LEN * MAX_LEN],
    /// The number of columns of `Phi S`.
    pub(super) cols: usize,
    /// The parameter whose column `psi = d s / dp` rides after `Phi S` (`2n` more numbers), if
    /// any (`parameter.rs`).
    pub(super) param: Option<&'a ParameterRates>,
    /// Set where a right-hand side found no Jacobian (a held foot whose friction ratio has no
    /// derivative): the phase's integration is then abandoned for differences.
    pub(super) singular: bool,
}

impl Variational<'_> {
    /// `[qd, qdd]` at `(t, y)` in the current contact.
    pub(super) fn mech_rhs(&self, t: f64, y: &[f64], out: &mut [f64]) {
        field(self.model, t, y, self.contact.get(), out);
    }
}

/// `[qd, qdd]` at `(t, y)` in the contact `contact` (`2n` numbers into `out`).
pub(super) fn field(model: &Model, t: f64, y: &[f64], contact: Contact, out: &mut [f64]) {
    let n = model.n();
    let mut a = [0.0; Model::STANCE_LEN];
    model.stance(t, y, contact, &mut a);
    out[..n].copy_from_slice(&y[n..2 * n]);
    out[n..2 * n].copy_from_slice(&a[..n]);
}

impl<const NA: usize> OdeSystem<NA> for Variational<'_> {
    fn rhs(&mut self, t: f64, y: &[f64; NA], dy: &mut [f64; NA]) {
        let n = self.model.n();
        let m = 2 * n;
        self.mech_rhs(t, y, &mut dy[..m]);
        if self
            .jac
            .accel_with(
                t,
                y,
                self.contact.get(),
                &mut self.a[..n * m],
                &mut self.scratch,
            )
            .is_err()
        {
            // `a` keeps its last (finite) values; the caller gives up on the phase.
            self.singular = true;
        }
        // Each column c of Phi S and psi: d c / dt = [0 I; A] c (+ [0; d qdd / dp] for psi):
        // the rows of q take the column's rows of qd, the rows of qd are A (n x 2n) times it.
        let mut b = [0.0; MAX_LEN];
        if let Some(rates) = self.param {
            rates.field_rate(
                self.model,
                t,
                y,
                self.contact.get(),
                &self.scratch.k,
                &mut b[..n],
            );
        }
        let used = self.cols + usize::from(self.param.is_some());
        let columns = y[m..m + m * used].chunks_exact(m);
        let rates = dy[m..m + m * used].chunks_exact_mut(m);
        for (j, (c, dc)) in columns.zip(rates).enumerate() {
            dc[..n].copy_from_slice(&c[n..]);
            let forced = j == self.cols;
            for (i, a_i) in self.a[..n * m].chunks_exact(m).enumerate() {
                let mut d = if forced { b[i] } else { 0.0 };
                for (&a_ik, &c_k) in a_i.iter().zip(c) {
                    d += a_ik * c_k;
                }
                dc[n + i] = d;
            }
        }
        dy[m + m * used..].fill(0.0);
    }

    fn controlled_components(&mut self, _: f64, _: &[f64; NA], _: f64, _: &[f64; NA]) -> usize {
        2 * self.model.n() * (1 + self.cols + usize::from(self.param.is_some()))
    }

    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        self.model.next_breakpoint(t)
    }
}

/// The contact of a foot at rest (`xd = 0`) under exact Coulomb friction at `(t, y)`, as the
/// simulator chooses it (`sim/foot.rs`): stuck where the force that holds it lies in the cone,
/// else sliding the way the unbalanced force pushes it where that slide is consistent.
///
/// # Errors
/// [`MapError::ContactInconsistent`]: neither (Painleve's paradox), or non-finite forces.
pub(super) fn contact_at_rest(model: &Model, t: f64, y: &[f64]) -> Result<Contact, MapError> {
    let held = model.reaction(t, y, Contact::Stuck);
    if !(held.normal.is_finite() && held.tangential.is_finite()) {
        return Err(MapError::NonFinite { t });
    }
    if held.tangential.abs() <= model.mu0() * held.normal {
        return Ok(Contact::Stuck);
    }
    let slide = Slide::of(-held.tangential);
    let mut qdd = [0.0; Model::STANCE_LEN];
    model.stance(t, y, Contact::Sliding(slide), &mut qdd);
    if qdd[0] * slide.sigma() > 0.0 {
        Ok(Contact::Sliding(slide))
    } else {
        Err(MapError::ContactInconsistent { t })
    }
}

/// The contact at the start of a stance phase from the state `y`, as the simulator's.
fn initial_contact(model: &Model, y: &[f64]) -> Result<Contact, MapError> {
    let xd = y[model.n()];
    match model.friction_law() {
        FrictionLaw::Tanh => Ok(Contact::Smooth),
        FrictionLaw::Coulomb if xd != 0.0 => Ok(Contact::Sliding(Slide::of(xd))),
        FrictionLaw::Coulomb => contact_at_rest(model, 0.0, y),
    }
}

/// `Phi <- DR Phi + (f+ - DR f-) (g_y^T Phi + g_p) / (g_y f- + g_t)` on the columns `phi`
/// (each `m` numbers, one after the other), `DR` the identity with the rows `reset_rows` zero;
/// `g_t` the guard's explicit rate in time (zero for a guard of the state alone), `g_p` its own
/// rate in a parameter (for a parameter's column `psi`; zero for `Phi S`).
///
/// # Errors
/// [`MapError::GrazingEvent`]: `g_y f- + g_t` vanishes (the event is grazed).
fn saltation(
    phi: &mut [f64],
    m: usize,
    reset_rows: &[usize],
    f_minus: &[f64],
    f_plus: &[f64],
    (g, g_t, g_p): (&[f64], f64, f64),
    t: f64,
) -> Result<(), MapError> {
    let mut gf: f64 = (0..m).map(|k| g[k] * f_minus[k]).sum();
    if g_t != 0.0 {
        gf += g_t;
    }
    if gf.abs() < 1e-12 || !gf.is_finite() {
        return Err(MapError::GrazingEvent { t });
    }
    for column in phi.chunks_exact_mut(m) {
        let s: f64 = (0..m).map(|k| g[k] * column[k]).sum();
        let g_c = if g_p == 0.0 { s } else { s + g_p };
        for (i, c) in column.iter_mut().enumerate() {
            let reset = reset_rows.contains(&i);
            let d = f_plus[i] - if reset { 0.0 } else { f_minus[i] };
            let kept = if reset { 0.0 } else { *c };
            *c = kept + d * g_c / gf;
        }
    }
    Ok(())
}

/// What the variational stance carries besides the state ([`stance`]).
pub(super) struct Columns<'a> {
    /// The seeds' columns, one after the other (`2n` numbers each): `Phi(0) S`.
    pub(super) seeds: &'a [f64],
    /// A parameter's rates and its start rate, where its column rides after the seeds'.
    pub(super) param: Option<(&'a ParameterRates, &'a [f64])>,
}

/// The end of the stance phase: the strike's time, the state with `Phi` there, and the contact
/// of the last phase.
pub(super) struct StanceEnd<const NA: usize> {
    pub(super) t: f64,
    pub(super) y: [f64; NA],
    pub(super) contact: Contact,
}

/// Integrates the stance phase from the post-impact state `s` with the variational equations,
/// phase by phase, until the strike (see the module documentation): `Phi S` from `Phi(0) S =
/// seeds` (the seeds' columns one after the other, `2n` numbers each), and the parameter's
/// column from its start rate, if any. `NA` holds them all (`map.rs`).
///
/// # Errors
/// [`PhaseError::NoKernel`] for a contact without Jacobian kernels, [`PhaseError::Map`] where
/// the map fails.
pub(super) fn stance<const NA: usize>(
    model: &Model,
    cfg: &SimConfig,
    s: &[f64],
    columns: &Columns<'_>,
    jac: StanceJacobian<'_>,
) -> Result<StanceEnd<NA>, PhaseError> {
    let Columns { seeds, param } = *columns;
    let n = model.n();
    let m = 2 * n;
    let cols = seeds.len() / m;
    let psi_at = m + m * cols;
    let used = psi_at + if param.is_some() { m } else { 0 };
    assert!(
        used <= NA,
        "{used} variational components in an array of {NA}"
    );
    let mut y = [0.0; NA];
    y[..m].copy_from_slice(s);
    y[m..psi_at].copy_from_slice(seeds);
    if let Some((_, psi0)) = param {
        y[psi_at..psi_at + m].copy_from_slice(psi0);
    }
    let rates = param.map(|(r, _)| r);
    let contact = Cell::new(initial_contact(model, &y)?);
    if !jac.has_contact(contact.get()) {
        return Err(PhaseError::NoKernel);
    }
    if contact.get() == Contact::Stuck {
        // The foot at rest: no perturbation of its velocity (the module documentation).
        for column in y[m..used].chunks_exact_mut(m) {
            column[n..n + 2].fill(0.0);
        }
    }
    let coulomb = model.friction_law() == FrictionLaw::Coulomb;
    let mu0 = model.mu0();
    let mut guard_values = [0.0; 1 + crate::sim::MAX_FALLS];
    let k = model.event_count().min(guard_values.len());
    let lambda_max = cfg.lambda_blowup * model.total_mass() * model.gravity();
    let mut events = vec![
        Event::terminal(Direction::Falling, move |_, y: &[f64; NA]| {
            model.events(&y[..n], &mut guard_values[..k]);
            guard_values[0]
        }),
        // The ground reaction blows up (the simulator's threshold, `sim/blowup.rs`): a
        // singular control or contact, where the integration would otherwise crawl to its
        // step limit (the three-link biped's sliding stance, whose control is singular: 100 000
        // steps and 1.5 s per map before this guard).
        Event::terminal(Direction::Rising, |t, y: &[f64; NA]| {
            model.reaction(t, &y[..m], contact.get()).lambda.abs() - lambda_max
        }),
    ];
    // The model's falls, as the simulator and the continuation's map watch them: a walker
    // that falls has no next step (and one integrated on past its fall, legs through the
    // floor, can turn stiff: the three-link biped's did, 100 000 steps in 1.5 s per map).
    let falls = k.saturating_sub(1);
    for i in 1..k {
        events.push(Event::terminal(
            Direction::Falling,
            move |_, y: &[f64; NA]| {
                let mut e = [0.0; 1 + crate::sim::MAX_FALLS];
                model.events(&y[..n], &mut e[..k]);
                e[i]
            },
        ));
    }
    let (rest, slip) = (2 + falls, 3 + falls);
    events.extend([
        // The sliding foot comes to rest (zero while stuck).
        Event::terminal(Direction::Falling, |_, y: &[f64; NA]| {
            contact.get().sigma() * y[n]
        }),
        // The stuck foot's force leaves the friction cone.
        Event::terminal(Direction::Rising, |t, y: &[f64; NA]| {
            if contact.get() == Contact::Stuck {
                let r = model.reaction(t, &y[..m], Contact::Stuck);
                r.tangential.abs() - mu0 * r.normal
            } else {
                -1.0
            }
        }),
    ]);
    let watched = if coulomb { slip + 1 } else { rest };
    let mut sys = Variational {
        model,
        jac,
        contact: &contact,
        scratch: Scratch::new(),
        a: [0.0; MAX_LEN * MAX_LEN],
        cols,
        param: rates,
        singular: false,
    };
    let mut integ =
        Integrator::<NA>::new(cfg.method, crate::ode::Tolerances::new(cfg.rtol, cfg.atol));
    let mut t = 0.0;
    // One budget of attempted steps for the whole stance phase, as in the simulation
    // (`sim/step.rs`): each call after a breakpoint gets what the earlier ones left, and every
    // call spends at least one attempt, so the loop ends with `TooManySteps` at the latest.
    let budget = integ.config().max_steps;
    loop {
        let spent = integ.stats().accepted_steps + integ.stats().rejected_steps;
        integ.config_mut().max_steps =
            budget.saturating_sub(usize::try_from(spent).unwrap_or(usize::MAX));
        let outcome = integ.integrate(
            &mut sys,
            t,
            &y,
            cfg.max_step_time,
            &mut events[..watched],
            &mut NoObserver,
        );
        if sys.singular {
            return Err(PhaseError::NoKernel);
        }
        match outcome {
            Outcome::Breakpoint { t: tb, y: mut yb } => {
                if let Some(r) = rates {
                    // The ramps' end moves with p: psi jumps by (f- - f+) d tb / dp.
                    let d_tb = r.breakpoint_rate(model, tb).ok_or(PhaseError::NoKernel)?;
                    if d_tb != 0.0 {
                        let before = f64::from_bits(tb.to_bits() - 1);
                        let (mut f_minus, mut f_plus) = ([0.0; MAX_LEN], [0.0; MAX_LEN]);
                        field(model, before, &yb, contact.get(), &mut f_minus[..m]);
                        field(model, tb, &yb, contact.get(), &mut f_plus[..m]);
                        for i in 0..m {
                            yb[psi_at + i] += (f_minus[i] - f_plus[i]) * d_tb;
                        }
                    }
                }
                (t, y) = (tb, yb);
            }
            // A zero of the guard with the striking point behind the stance foot is no strike.
            Outcome::Event {
                index: 0,
                t: te,
                y: ye,
            } if !model.strike_ahead(&ye[..n]) => (t, y) = (te, ye),
            Outcome::Event {
                index: 0,
                t: te,
                y: ye,
            } => {
                return Ok(StanceEnd {
                    t: te,
                    y: ye,
                    contact: contact.get(),
                });
            }
            Outcome::Event { index: 1, t: te, y } => {
                let lambda = model.reaction(te, &y[..m], contact.get()).lambda;
                return Err(MapError::BlowUp { t: te, lambda }.into());
            }
            Outcome::Event { index, t: te, .. } if index < rest => {
                let name = model.spec().model.falls[index - 2].name.name.clone();
                return Err(MapError::Fall { name, t: te }.into());
            }
            Outcome::Event {
                index,
                t: te,
                y: mut ye,
            } if index == rest => {
                // The foot comes to rest: xd = zd = 0, then stuck or sliding back.
                let before = contact.get();
                let mut f_minus = [0.0; MAX_LEN];
                field(model, te, &ye, before, &mut f_minus[..m]);
                ye[n] = 0.0;
                ye[n + 1] = 0.0;
                let after = contact_at_rest(model, te, &ye)?;
                if !sys.jac.has_contact(after) {
                    return Err(PhaseError::NoKernel);
                }
                let mut f_plus = [0.0; MAX_LEN];
                field(model, te, &ye, after, &mut f_plus[..m]);
                let mut g = [0.0; MAX_LEN];
                g[n] = before.sigma();
                saltation(
                    &mut ye[m..psi_at],
                    m,
                    &[n, n + 1],
                    &f_minus[..m],
                    &f_plus[..m],
                    (&g[..m], 0.0, 0.0),
                    te,
                )?;
                if rates.is_some() {
                    saltation(
                        &mut ye[psi_at..psi_at + m],
                        m,
                        &[n, n + 1],
                        &f_minus[..m],
                        &f_plus[..m],
                        (&g[..m], 0.0, 0.0),
                        te,
                    )?;
                }
                contact.set(after);
                (t, y) = (te, ye);
            }
            Outcome::Event {
                t: te, y: mut ye, ..
            } => {
                // The stuck foot slips, the way the force that held it no longer can.
                let held = model.reaction(te, &ye[..m], Contact::Stuck);
                let after = Contact::Sliding(Slide::of(-held.tangential));
                if !sys.jac.has_contact(after) {
                    return Err(PhaseError::NoKernel);
                }
                let mut f_minus = [0.0; MAX_LEN];
                field(model, te, &ye, Contact::Stuck, &mut f_minus[..m]);
                let mut f_plus = [0.0; MAX_LEN];
                field(model, te, &ye, after, &mut f_plus[..m]);
                let sign = held.tangential.signum();
                let (g, g_t, g_p) = if model.inputs() == 0 {
                    let mut dforce = [0.0; (MAX_LEN / 2 + 2) * MAX_LEN];
                    sys.jac.stick(&ye, &mut dforce[..(n + 2) * m]);
                    let g: Vec<f64> = (0..m)
                        .map(|j| sign * dforce[n * m + j] - mu0 * dforce[(n + 1) * m + j])
                        .collect();
                    // g = |lambda_t| - mu0 lambda_n moves with mu0: g_p = -lambda_n d mu0/dp.
                    let g_p = rates.map_or(0.0, |r| -held.normal * r.d_mu0);
                    (g, 0.0, g_p)
                } else {
                    // g = lambda_n (|mu*| - mu0), |mu*| = mu0 here (module documentation).
                    let ratio = sys
                        .jac
                        .held_ratio(te, &ye[..m], &mut sys.scratch)
                        .map_err(|_| PhaseError::NoKernel)?;
                    let scale = held.normal * sign;
                    let g: Vec<f64> = ratio.d_y[..m].iter().map(|d| scale * d).collect();
                    let g_p = rates.map_or(0.0, |r| {
                        let d_mu = r.held_ratio_rate(model, te, &ye[..m], &sys.scratch.k);
                        held.normal * (sign * d_mu - r.d_mu0)
                    });
                    (g, scale * ratio.d_t, g_p)
                };
                saltation(
                    &mut ye[m..psi_at],
                    m,
                    &[],
                    &f_minus[..m],
                    &f_plus[..m],
                    (&g, g_t, 0.0),
                    te,
                )?;
                if rates.is_some() {
                    saltation(
                        &mut ye[psi_at..psi_at + m],
                        m,
                        &[],
                        &f_minus[..m],
                        &f_plus[..m],
                        (&g, g_t, g_p),
                        te,
                    )?;
                }
                contact.set(after);
                (t, y) = (te, ye);
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
    }
}
