//! The [`Model`]: one walker's kernels prepared for one set of parameters, with the friction law
//! and impact law of the walk, and every physical quantity the simulator asks for, each computed
//! from the kernels and the model file (nothing here knows a particular walker).
//!
//! States are slices `[q, qd, ..]`: the coordinates, their velocities, and whatever the caller
//! integrates after them (the input-power quadrature), of which only the first `2n` are read.

use std::sync::Arc;

use walker_scene::ImpactLaw;
use walker_scene::model::Stage;

use super::contact::{Contact, FrictionLaw, Reaction};
use super::friction_impact::{ImpactJam, ImpactRegime, Ingredients, plastic_coulomb, rear_test};
use super::impact::{ImpactResult, PostImpact};
use super::parameters::{ParamError, Parameters};
use super::spec::Spec;
use crate::vector::{MAX_COORDINATES, MAX_LEN, Vector};
use walker_contract::{Args, Desired, KernelId, Kernels, Tracking, power};

/// A walker model: its kernels prepared for `params`, the laws of its contacts, and what the
/// simulator needs from the model file, evaluated once.
#[derive(Clone)]
pub struct Model {
    spec: Arc<Spec>,
    params: Parameters,
    kernels: Arc<dyn Kernels>,
    friction: FrictionLaw,
    /// The law of the impact at the strike.
    pub impact_law: ImpactLaw,
    /// The desired trajectories of the outputs, in output order.
    desired: Vec<Desired>,
    /// `(phi, cos phi, sin phi, tan phi)` of the floor (zeros and one on level ground).
    slope: [f64; 4],
    mu0: f64,
    c: f64,
    gains: (f64, f64),
    /// The total mass `m_t` and gravity `g`.
    mass: f64,
    gravity: f64,
    power_until: f64,
}

impl std::fmt::Debug for Model {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Model")
            .field("model", &self.spec.name())
            .field("params", &self.params.values())
            .field("friction", &self.friction)
            .field("impact_law", &self.impact_law)
            .finish_non_exhaustive()
    }
}

/// The largest number of outputs of a kernel the simulator calls per point (the Coulomb
/// impact's ingredients of a model with [`MAX_COORDINATES`] coordinates, `3 n + 9`).
const MAX_OUT: usize = 3 * MAX_COORDINATES + 9;

impl Model {
    /// The model of `spec` with `kernels` prepared for `params`, under the friction law
    /// `friction` (the law the kernels were generated for) and the model's default impact law.
    #[must_use]
    pub fn new(params: Parameters, kernels: Arc<dyn Kernels>, friction: FrictionLaw) -> Model {
        let spec = Arc::clone(params.spec());
        let values = params.values();
        let eval = |e: &walker_scene::model::ModelExpr| spec.eval(e, values);
        let desired = spec
            .model
            .outputs
            .iter()
            .map(|o| Desired::new(&o.desired, eval))
            .collect();
        let phi = params.at_opt(spec.slope).unwrap_or(0.0);
        let (sphi, cphi) = phi.sin_cos();
        let mass: f64 = spec.model.bodies.iter().map(|b| eval(&b.mass)).sum();
        let power_until = spec.model.power_until.as_ref().map_or(f64::INFINITY, eval);
        Model {
            impact_law: spec.default_impact(),
            desired,
            slope: [phi, cphi, sphi, phi.tan()],
            mu0: params.at_opt(spec.mu0).unwrap_or(0.0),
            c: params.at_opt(spec.c).unwrap_or(0.0),
            gains: spec
                .gains
                .map_or((0.0, 0.0), |(p, d)| (params.at(p), params.at(d))),
            mass,
            gravity: params.at(spec.gravity),
            power_until,
            spec,
            params,
            kernels,
            friction,
        }
    }

    /// The same model with the impact law `law` at the strike.
    #[must_use]
    pub fn with_impact_law(self, law: ImpactLaw) -> Self {
        Self {
            impact_law: law,
            ..self
        }
    }

    /// The model file's spec.
    #[must_use]
    pub fn spec(&self) -> &Arc<Spec> {
        &self.spec
    }

    /// The parameters the kernels are prepared for.
    #[must_use]
    pub fn params(&self) -> &Parameters {
        &self.params
    }

    /// The prepared kernels.
    #[must_use]
    pub fn kernels(&self) -> &Arc<dyn Kernels> {
        &self.kernels
    }

    /// The number of coordinates `n`.
    #[must_use]
    pub fn n(&self) -> usize {
        self.spec.n
    }

    /// The number of inputs `m` (0 for a passive walker).
    #[must_use]
    pub fn inputs(&self) -> usize {
        self.spec.inputs
    }

    /// Whether the walker is driven by the output-following control.
    #[must_use]
    pub fn is_active(&self) -> bool {
        self.spec.is_actuated()
    }

    /// The friction law of the stance foot.
    #[must_use]
    pub fn friction_law(&self) -> FrictionLaw {
        self.friction
    }

    /// The slope angle `phi` (0 on level ground).
    #[must_use]
    pub fn phi(&self) -> f64 {
        self.slope[0]
    }

    /// The friction coefficient `mu0` (0 for a frictionless model).
    #[must_use]
    pub fn mu0(&self) -> f64 {
        self.mu0
    }

    /// The total mass `m_t` (the sum of the bodies' masses).
    #[must_use]
    pub fn total_mass(&self) -> f64 {
        self.mass
    }

    /// The gravitational acceleration `g`.
    #[must_use]
    pub fn gravity(&self) -> f64 {
        self.gravity
    }

    /// The value of the parameter called `name` (NaN if there is none).
    #[must_use]
    pub fn param(&self, name: &str) -> f64 {
        self.params.get(name).unwrap_or(f64::NAN)
    }

    fn eval(&self, k: KernelId, args: Args<'_>, out: &mut [f64]) {
        self.kernels.eval(k, &args, out);
    }

    /// `[y_d, yd_d, ydd_d]` of output `i` at time `t` since the last impact.
    #[must_use]
    pub fn desired(&self, i: usize, t: f64) -> [f64; 3] {
        self.desired.get(i).map_or([f64::NAN; 3], |d| d.at(t))
    }

    /// The desired trajectory of output `i`.
    pub(crate) fn desired_trajectory(&self, i: usize) -> &Desired {
        &self.desired[i]
    }

    /// The outputs and their rates `[y, ydot]` (`output_rates`, `2m` numbers into `out`) at the
    /// state `y`.
    pub(crate) fn output_rates(&self, y: &[f64], out: &mut [f64]) {
        let n = self.n();
        self.kernels.eval(
            KernelId::OutputRates,
            &Args::state(&y[..n], &y[n..2 * n]),
            out,
        );
    }

    /// Whether every desired trajectory is finite at `t` (a ramp so short that its second
    /// derivative's scale overflows is not); always for a passive walker.
    #[must_use]
    pub fn desired_finite(&self, t: f64) -> bool {
        self.desired.iter().all(|d| d.is_finite_at(t))
    }

    /// The first end of a ramp strictly after `t` (where the control switches: a breakpoint of
    /// the integration).
    #[must_use]
    pub fn next_breakpoint(&self, t: f64) -> Option<f64> {
        self.desired
            .iter()
            .filter_map(Desired::ramp_end)
            .filter(|&e| e > t)
            .min_by(f64::total_cmp)
    }

    /// The end of the last ramp (the paper's `T_set`): the output-following control is assumed
    /// complete by the next impact (Section 3.2). `None` without ramps.
    #[must_use]
    pub fn ramps_end(&self) -> Option<f64> {
        self.desired
            .iter()
            .filter_map(Desired::ramp_end)
            .max_by(f64::total_cmp)
    }

    /// Whether the input power is counted at `t` since the last impact (an actuated walker,
    /// before the model's `power_until`).
    #[must_use]
    pub fn power_counts(&self, t: f64) -> bool {
        self.is_active() && t < self.power_until
    }

    /// Whether the stance foot is held in the contact `contact`: under exact Coulomb friction,
    /// a foot that does not slide (its sliding direction `sigma` is 0; [`Contact::Smooth`] is
    /// held too). The smooth law's kernels ignore the contact.
    #[must_use]
    pub fn is_stuck(&self, contact: Contact) -> bool {
        self.friction == FrictionLaw::Coulomb && contact.sigma() == 0.0
    }

    /// The sharpness `c` of the tanh law (0 for a model without it).
    #[must_use]
    pub fn sharpness(&self) -> f64 {
        self.c
    }

    /// The gains `(K_P, K_D)` of the output-following control (zeros without inputs).
    #[must_use]
    pub fn gains(&self) -> (f64, f64) {
        self.gains
    }

    /// Writes the auxiliary inputs `v` of Eq. 32 at time `t` and state `y` (`m` numbers).
    pub(crate) fn aux_inputs(&self, t: f64, y: &[f64], v: &mut [f64]) {
        let (n, m) = (self.n(), self.inputs());
        self.kernels.aux_inputs(
            &Args::state(&y[..n], &y[n..2 * n]),
            &self.tracking_at(t),
            &mut v[..m],
        );
    }

    /// What the output-following control tracks at time `t` since the last impact.
    fn tracking_at(&self, t: f64) -> Tracking<'_> {
        Tracking {
            desired: &self.desired,
            t,
            gains: self.gains,
        }
    }

    /// Stance accelerations `qdd` and control inputs `u` at time `t` since the last impact and
    /// state `y` in the contact `contact`, written to `out` as `[qdd, u]` (`n + m` numbers; it
    /// must hold [`Model::STANCE_LEN`]): for an actuated walker under the output control of
    /// Eqs. 31-32 (`closed_loop`; stuck, `closed_loop_stick`, the control recomputed with both
    /// foot coordinates held), for a passive one Eq. 27 with `u = 0` (`accel`; stuck, `stick`,
    /// whose ground forces follow the accelerations in `out`). The smooth law's kernels ignore
    /// `contact`; a Coulomb model given [`Contact::Smooth`] is treated as stuck.
    pub fn stance(&self, t: f64, y: &[f64], contact: Contact, out: &mut [f64]) {
        let mut w = [0.0; MAX_COORDINATES];
        self.kernels.stance(
            self.is_stuck(contact),
            contact.sigma(),
            &y[..2 * self.n()],
            &self.tracking_at(t),
            out,
            &mut w,
        );
    }

    /// The stance phase's right-hand side at time `t` since the last impact and state
    /// `y = [q, qd, ..]` in the contact `contact`: `dy = [qd, qdd]` (`2n` numbers, `qdd` as in
    /// [`Model::stance`]), and the input power's integrand `sum |u_i w_i|` where the power
    /// counts ([`Model::power_counts`]; 0 elsewhere and for a passive walker).
    pub fn stance_rhs(&self, t: f64, y: &[f64], contact: Contact, dy: &mut [f64]) -> f64 {
        self.stance_rhs_in(contact).eval(t, &y[..dy.len()], dy)
    }

    /// [`Model::stance_rhs`] in the contact `contact`, with what does not change while the
    /// contact holds (the stuck or sliding kernel, the trajectories and gains, where the
    /// power stops counting) looked up once: the integrator evaluates it at every stage.
    #[must_use]
    pub fn stance_rhs_in(&self, contact: Contact) -> StanceRhs<'_> {
        StanceRhs {
            kernels: &*self.kernels,
            stuck: self.is_stuck(contact),
            sigma: contact.sigma(),
            control: self.tracking_at(0.0),
            power_until: if self.is_active() {
                self.power_until
            } else {
                f64::NEG_INFINITY
            },
        }
    }

    /// The length a buffer for [`Model::stance`] needs: the accelerations, the inputs and the
    /// stuck foot's two ground forces of a model with [`MAX_COORDINATES`] coordinates and as
    /// many inputs.
    pub const STANCE_LEN: usize = 2 * MAX_COORDINATES + 2;

    /// The control inputs `u` at `(t, y)` in the contact `contact` (empty for a passive walker).
    #[must_use]
    pub fn control_input(&self, t: f64, y: &[f64], contact: Contact) -> Vector {
        let (n, m) = (self.n(), self.inputs());
        if m == 0 {
            return Vector::EMPTY;
        }
        let mut out = [0.0; Model::STANCE_LEN];
        self.stance(t, y, contact, &mut out);
        Vector::from_slice(&out[n..n + m])
    }

    /// The rates `w_i = S_i^T qd` at which the inputs do work at state `y`.
    fn input_rates(&self, y: &[f64], w: &mut [f64]) {
        let n = self.n();
        self.eval(KernelId::InputRates, Args::state(&y[..n], &y[n..2 * n]), w);
    }

    /// The input power's integrand `sum |u_i w_i|` at state `y` with inputs `u` (Section 4.2:
    /// `|ydot u|` for the paper's walker, whose input rate is `ydot`).
    #[must_use]
    pub fn power_integrand(&self, y: &[f64], u: &[f64]) -> f64 {
        let mut w = [0.0; MAX_COORDINATES];
        let m = self.inputs();
        self.input_rates(y, &mut w[..m]);
        power(u, &w[..m])
    }

    /// Each input's power `u_i w_i` at `(t, y)` in the contact `contact`, into `out` (one per
    /// input): the factors of [`Model::power_sign_function`], each of which changes sign at a
    /// kink of the integrand `sum |u_i w_i|` (the simulator watches them one by one on a walker
    /// with several inputs).
    pub fn input_powers(&self, t: f64, y: &[f64], contact: Contact, out: &mut [f64]) {
        let (n, m) = (self.n(), self.inputs());
        let (mut k, mut w) = ([0.0; 2 * MAX_COORDINATES + 2], [0.0; MAX_COORDINATES]);
        self.kernels.stance(
            self.is_stuck(contact),
            contact.sigma(),
            &y[..2 * n],
            &self.tracking_at(t),
            &mut k,
            &mut w[..m],
        );
        for (o, (wi, ui)) in out.iter_mut().zip(w[..m].iter().zip(&k[n..n + m])) {
            *o = wi * ui;
        }
    }

    /// The product of the inputs' powers `prod u_i w_i` at `(t, y)` in the contact `contact`:
    /// it changes sign where one of them does (a kink of the integrand `sum |u_i w_i|`).
    #[must_use]
    pub fn power_sign_function(&self, t: f64, y: &[f64], contact: Contact) -> f64 {
        if self.inputs() == 0 {
            return 1.0;
        }
        self.kernels.power_sign(
            self.is_stuck(contact),
            contact.sigma(),
            &y[..2 * self.n()],
            &self.tracking_at(t),
        )
    }

    /// The friction coefficient `mu` of the smooth law at the foot's velocity `xd`:
    /// `-mu0 tanh(c xd / cos phi)` (Eqs. 26, 37).
    fn tanh_mu(&self, xd: f64) -> f64 {
        -self.mu0 * (self.c * (xd / self.slope[1])).tanh()
    }

    /// The sliding foot's reaction from `lambda` (the vertical component of the normal force,
    /// as the paper's) and `mu`: the normal force `lambda / cos phi` and `mu` times it along
    /// the floor (Eqs. 24, 38).
    fn sliding_reaction(&self, lambda: f64, mu: f64) -> Reaction {
        let cphi = self.slope[1];
        Reaction {
            lambda,
            normal: lambda / cphi,
            tangential: mu * lambda / cphi,
        }
    }

    /// `lambda` (the `lambda` kernel) at `(q, qd)` with inputs `u` and sliding direction
    /// `sigma`.
    fn lambda(&self, q: &[f64], qd: &[f64], u: &[f64], sigma: f64) -> f64 {
        let mut out = [0.0; 1];
        self.eval(
            KernelId::Lambda,
            Args {
                u,
                sigma,
                ..Args::state(q, qd)
            },
            &mut out,
        );
        out[0]
    }

    /// The ground's force on the stance foot at `(t, y)` in the contact `contact`, with the
    /// control input of that point: sliding, `lambda` of Eqs. 22-23 and `mu` times the normal
    /// force along the floor (Eqs. 24, 38); stuck, the two forces of `stick` /
    /// `closed_loop_stick`.
    #[must_use]
    pub fn reaction(&self, t: f64, y: &[f64], contact: Contact) -> Reaction {
        let (n, m) = (self.n(), self.inputs());
        let (q, qd) = (&y[..n], &y[n..2 * n]);
        if self.is_stuck(contact) {
            let mut out = [0.0; MAX_OUT];
            if m == 0 {
                self.eval(KernelId::Stick, Args::state(q, qd), &mut out[..n + 2]);
            } else {
                let mut v = [0.0; MAX_COORDINATES];
                self.aux_inputs(t, y, &mut v[..m]);
                self.eval(
                    KernelId::ClosedLoopStick,
                    Args {
                        v: &v[..m],
                        ..Args::state(q, qd)
                    },
                    &mut out[..n + m + 2],
                );
            }
            let (tangential, normal) = (out[n + m], out[n + m + 1]);
            let (cphi, sphi) = (self.slope[1], self.slope[2]);
            return Reaction {
                lambda: normal * cphi - tangential * sphi,
                normal,
                tangential,
            };
        }
        let lambda =
            self.kernels
                .sliding_lambda(contact.sigma(), &y[..2 * n], &self.tracking_at(t));
        let mu = match contact {
            Contact::Sliding(s) => -self.mu0 * s.sigma(),
            Contact::Smooth | Contact::Stuck => self.tanh_mu(qd[0]),
        };
        self.sliding_reaction(lambda, mu)
    }

    /// For a Coulomb model, the normal force at `(t, y)` with the friction switched off
    /// (`sigma = 0`, so `mu = 0`, the control recomputed for it); `None` for smooth-law models.
    /// Where a sliding foot's normal force is negative but this one is not, it is the sliding
    /// friction that pulls the foot off the floor: Painleve's paradox, not a lift-off.
    #[must_use]
    pub fn frictionless_normal(&self, t: f64, y: &[f64]) -> Option<f64> {
        if self.friction != FrictionLaw::Coulomb {
            return None;
        }
        let (n, m) = (self.n(), self.inputs());
        let mut u = [0.0; MAX_COORDINATES];
        if m > 0 {
            let mut v = [0.0; MAX_COORDINATES];
            self.aux_inputs(t, y, &mut v[..m]);
            let mut out = [0.0; MAX_OUT];
            self.eval(
                KernelId::ClosedLoop,
                Args {
                    v: &v[..m],
                    ..Args::state(&y[..n], &y[n..2 * n])
                },
                &mut out[..n + m],
            );
            u[..m].copy_from_slice(&out[n..n + m]);
        }
        Some(self.lambda(&y[..n], &y[n..2 * n], &u[..m], 0.0) / self.slope[1])
    }

    /// `lambda` of Eqs. 22-23 at the configuration and foot velocity of `y` (the sliding
    /// direction of `contact` under Coulomb friction) with gravity alone in the numerator: every
    /// other velocity and every input zero. Where the denominator `D` of Eq. 23 is regular this
    /// is of the order of the body weight; near a zero of `D` it grows without bound, whatever
    /// the spin and the inputs. `None` for a stuck foot, whose reaction has no such denominator.
    #[must_use]
    pub fn gravity_lambda(&self, y: &[f64], contact: Contact) -> Option<f64> {
        if self.is_stuck(contact) {
            return None;
        }
        let n = self.n();
        let mut qd = [0.0; MAX_COORDINATES];
        qd[0] = y[n];
        let u = [0.0; MAX_COORDINATES];
        Some(self.lambda(&y[..n], &qd[..n], &u[..self.inputs()], contact.sigma()))
    }

    /// The strike guard and each fall's value at the coordinates `q` (`events`): the guard is
    /// positive during the stance and falls through zero at the strike; a fall happens where
    /// its value reaches zero.
    pub fn events(&self, q: &[f64], out: &mut [f64]) {
        self.eval(KernelId::Events, Args::state(q, &[]), out);
    }

    /// The number of values [`Model::events`] writes (the guard and the falls).
    #[must_use]
    pub fn event_count(&self) -> usize {
        1 + self.spec.model.falls.len()
    }

    /// The named points `[x_p, z_p, ..]` at the coordinates `q`.
    pub fn points(&self, q: &[f64], out: &mut [f64]) {
        self.eval(KernelId::Points, Args::state(q, &[]), out);
    }

    /// Whether the striking point is ahead of the stance foot along the floor at `q` (a strike
    /// counts only then where the model says so, `[strike] ahead`).
    #[must_use]
    pub fn strike_ahead(&self, q: &[f64]) -> bool {
        if !self.spec.model.strike.ahead {
            return true;
        }
        // The loader refuses more points than this (walker_scene::limits::MAX_POINTS).
        let mut p = [0.0; 2 * walker_scene::limits::MAX_POINTS];
        let k = self.spec.model.points.len();
        if 2 * k > p.len() {
            return true;
        }
        self.points(q, &mut p[..2 * k]);
        let i = self.spec.strike_point;
        let (cphi, sphi) = (self.slope[1], self.slope[2]);
        (p[2 * i] - q[0]) * cphi - (p[2 * i + 1] - q[1]) * sphi > 0.0
    }

    /// Kinetic and potential energy `[T, V]` of the mechanical state `s = [q, qd]`.
    #[must_use]
    pub fn energy(&self, s: &[f64]) -> [f64; 2] {
        let n = self.n();
        let mut out = [0.0; 2];
        self.eval(
            KernelId::Energy,
            Args::state(&s[..n], &s[n..2 * n]),
            &mut out,
        );
        out
    }

    /// The impact map at the pre-impact state `s = [q, qd]` under the model's [`ImpactLaw`].
    /// Frictionless (the paper's): `impact`, with the test `impact_double` where the model asks
    /// for it. With Coulomb friction: `impact_coulomb` and Stronge's plastic impact
    /// ([`plastic_coulomb`](crate::model::plastic_coulomb)).
    ///
    /// # Errors
    /// [`ImpactJam`]: the impact with friction has no rigid-body solution (never for the
    /// frictionless law).
    pub fn impact(&self, s: &[f64]) -> Result<ImpactResult, ImpactJam> {
        let n = self.n();
        let (q, qd) = (&s[..n], &s[n..2 * n]);
        let cphi = self.slope[1];
        if self.impact_law == ImpactLaw::Coulomb {
            let ing = self.impact_ingredients(s);
            let (lambda, regime) = plastic_coulomb(&ing, self.mu0)?;
            let rear = if self.spec.double_support() {
                rear_test(&ing, self.mu0, lambda, regime) * cphi
            } else {
                0.0
            };
            return Ok(ImpactResult {
                foot_impulse: lambda,
                rear_impulse: rear,
                qd: ing.velocity(lambda),
                regime,
            });
        }
        let rows = self.spec.impact_rows;
        let mut out = [0.0; MAX_OUT];
        self.eval(KernelId::Impact, Args::state(q, qd), &mut out[..rows + n]);
        let applied = out;
        let rear = if self.spec.double_support() {
            self.eval(
                KernelId::ImpactDouble,
                Args::state(q, qd),
                &mut out[..rows + 1 + n],
            );
            out[1] * cphi
        } else {
            0.0
        };
        Ok(ImpactResult {
            foot_impulse: [0.0, applied[0]],
            rear_impulse: rear,
            qd: Vector::from_slice(&applied[rows..rows + n]),
            regime: ImpactRegime::Frictionless,
        })
    }

    /// The rigid-body part of the impact with friction at the pre-impact state `s`
    /// (`impact_coulomb`), whatever the model's impact law.
    #[must_use]
    pub fn impact_ingredients(&self, s: &[f64]) -> Ingredients {
        let n = self.n();
        let mut out = [0.0; MAX_OUT];
        let len = Ingredients::kernel_len(n);
        self.eval(
            KernelId::ImpactCoulomb,
            Args::state(&s[..n], &s[n..2 * n]),
            &mut out[..len],
        );
        Ingredients::from_kernel(n, &out[..len])
    }

    /// The relabelling after an impact at the pre-impact state `pre = [q, qd]` whose impact map
    /// gave `imp` (velocities of the old coordinates): the striking point becomes the stance
    /// foot, the other coordinates by the model's relabelling (`relabel`). After a sticking
    /// impact ([`ImpactRegime::Stick`]) the new foot is at rest, so its velocity is set to
    /// exactly zero (the kernels give it to rounding, and exact Coulomb friction tells a stuck
    /// foot from a sliding one by `xd = 0`). On level ground the new foot's height is set to
    /// exactly zero (the strike happens on the floor; the kernel gives it to rounding).
    #[must_use]
    pub fn reset(&self, pre: &[f64], imp: &ImpactResult) -> PostImpact {
        let n = self.n();
        let mut out = [0.0; MAX_LEN];
        self.eval(
            KernelId::Relabel,
            Args::state(&pre[..n], &imp.qd),
            &mut out[..2 * n],
        );
        let mut q_plus = Vector::from_slice(&out[..n]);
        let mut qd_plus = Vector::from_slice(&out[n..2 * n]);
        if imp.regime == ImpactRegime::Stick {
            (qd_plus[0], qd_plus[1]) = (0.0, 0.0);
        }
        if self.spec.slope.is_none() {
            q_plus[1] = 0.0;
        }
        PostImpact {
            q_plus,
            qd_plus,
            foot_normal_velocity: qd_plus[1] + qd_plus[0] * self.slope[3],
        }
    }

    /// The model's start (`[start]`, its values at these parameters; zero where it names
    /// nothing) as a mechanical state `[q, qd]`.
    #[must_use]
    pub fn start_state(&self) -> Vector {
        self.start_at(&self.params)
    }

    /// The model's start at the parameters `params` (of the same model).
    fn start_at(&self, params: &Parameters) -> Vector {
        let n = self.n();
        let mut s = Vector::zeros(2 * n);
        for v in &self.spec.model.start {
            let i = v.coordinate + if v.velocity { n } else { 0 };
            s[i] = self.spec.eval(&v.value, params.values());
        }
        s
    }

    /// The model's start with the start parameter `name` (stage `start`: the paper's
    /// `omega0`) set to `value`.
    ///
    /// # Errors
    /// `name` is not a parameter, or `value` is out of its range.
    pub fn start_state_with(&self, name: &str, value: f64) -> Result<Vector, ParamError> {
        Ok(self.start_at(&self.params.with(name, value)?))
    }

    /// The model's start with the components `(index, value)` replaced (from
    /// [`Spec::start_components`]).
    #[must_use]
    pub fn start_state_replacing(&self, components: &[(usize, f64)]) -> Vector {
        let mut s = self.start_state();
        for &(i, v) in components {
            s[i] = v;
        }
        s
    }

    /// The parameters of the start (stage `start`: the paper's `omega0`), by name.
    pub fn start_parameters(&self) -> impl Iterator<Item = &str> {
        self.spec
            .model
            .parameters
            .iter()
            .filter(|p| p.stage == Stage::Start)
            .map(|p| p.name.name.as_str())
    }
}

/// The stance phase's right-hand side in one contact ([`Model::stance_rhs_in`]): the kernels
/// and everything the right-hand side reads besides `(t, y)`, resolved for the contact.
#[derive(Clone, Copy)]
pub struct StanceRhs<'a> {
    kernels: &'a dyn Kernels,
    stuck: bool,
    sigma: f64,
    /// What the control tracks (the trajectories and gains), its time set at each call: the
    /// kernels are handed this one, not a copy built per call.
    control: Tracking<'a>,
    /// The input power counts for `t` below this (minus infinity for a passive walker).
    power_until: f64,
}

impl StanceRhs<'_> {
    /// [`Model::stance_rhs`] at `(t, y)`: `dy = [qd, qdd]` (`2n = y.len()` numbers), and the
    /// input power's integrand where the power counts (0 elsewhere).
    #[inline]
    pub fn eval(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> f64 {
        self.control.t = t;
        let p = self
            .kernels
            .stance_rhs(self.stuck, self.sigma, y, &self.control, dy);
        if t < self.power_until { p } else { 0.0 }
    }
}
