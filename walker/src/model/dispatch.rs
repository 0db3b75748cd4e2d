//! The [`Model`]: one walker's prepared kernels behind one type, and the dispatch of every
//! physical quantity (stance accelerations, ground reaction, impact map, fore foot, energy) to
//! the kernel of its variant.

use crate::control;
use crate::kernels::{
    active_level, general_level, general_level_coulomb, general_slope, general_slope_coulomb,
    passive_slope,
};
use crate::params::{self, Physical, Runtime};

use super::contact::{Contact, FrictionLaw, Reaction};
use super::friction_impact::{ImpactJam, Ingredients};
use super::impact::{ImpactResult, coulomb_impact, level_impact, slope_impact};
use super::kind::Kind;
use walker_scene::ImpactLaw;

#[allow(
    clippy::large_enum_variant,
    reason = "one model per walk; the prepared constants are read on every kernel call, so they stay inline"
)]
#[derive(Clone, Copy, Debug)]
enum Kernels {
    ActiveLevel(active_level::Prepared),
    GeneralLevel(general_level::Prepared),
    PassiveSlope(passive_slope::Prepared),
    GeneralSlope(general_slope::Prepared),
    CoulombLevel(general_level_coulomb::Prepared),
    CoulombSlope(general_slope_coulomb::Prepared),
}

/// A walker model: kernels plus the parameters the simulator needs outside the kernels.
#[derive(Clone, Copy, Debug)]
pub struct Model {
    kernels: Kernels,
    /// Physical parameters (the values compiled into the kernels for the fast variants).
    pub physical: Physical,
    /// Friction, control and slope parameters.
    pub runtime: Runtime,
    /// The law of the impact at heel strike (the paper's frictionless one unless
    /// [`Model::with_impact_law`] says otherwise).
    pub impact_law: ImpactLaw,
    /// `y_d` of Section 3.2 for `physical.alpha` and `runtime.t_set`.
    ramp: control::Ramp,
}

impl Model {
    /// The active walker on level ground with Table 1 compiled in (`phi` is ignored).
    pub fn active_level(runtime: Runtime) -> Self {
        let p = active_level::prepare(&active_level::Params::from_fn(|name| {
            params::by_name(&Physical::TABLE1, &runtime, name)
        }));
        Self::with(Kernels::ActiveLevel(p), Physical::TABLE1, runtime, 0.0)
    }

    /// The passive wheel on a slope with Table 1 compiled in.
    pub fn passive_slope(runtime: Runtime) -> Self {
        let p = passive_slope::prepare(&passive_slope::Params::from_fn(|name| {
            params::by_name(&Physical::TABLE1, &runtime, name)
        }));
        Self::with(
            Kernels::PassiveSlope(p),
            Physical::TABLE1,
            runtime,
            runtime.phi,
        )
    }

    /// The active walker on level ground with every parameter at run time.
    pub fn general_level(physical: Physical, runtime: Runtime) -> Self {
        let p = general_level::prepare(&general_level::Params::from_fn(|name| {
            params::by_name(&physical, &runtime, name)
        }));
        Self::with(Kernels::GeneralLevel(p), physical, runtime, 0.0)
    }

    /// The passive wheel on a slope with every parameter at run time.
    pub fn general_slope(physical: Physical, runtime: Runtime) -> Self {
        let p = general_slope::prepare(&general_slope::Params::from_fn(|name| {
            params::by_name(&physical, &runtime, name)
        }));
        Self::with(Kernels::GeneralSlope(p), physical, runtime, runtime.phi)
    }

    fn with(kernels: Kernels, physical: Physical, runtime: Runtime, phi: f64) -> Self {
        Self {
            kernels,
            physical,
            runtime: Runtime { phi, ..runtime },
            impact_law: ImpactLaw::Frictionless,
            ramp: control::Ramp::new(physical.alpha, runtime.t_set),
        }
    }

    /// The same model with the impact law `law` at heel strike.
    #[must_use]
    pub fn with_impact_law(self, law: ImpactLaw) -> Self {
        Self {
            impact_law: law,
            ..self
        }
    }

    /// `[y_d, yd_d, ydd_d]` (Section 3.2) at time `t` since the last impact.
    pub fn desired(&self, t: f64) -> [f64; 3] {
        self.ramp.at(t)
    }

    /// The active walker on level ground with exact Coulomb friction (Eq. 25) and stick-slip,
    /// every parameter at run time (`c` is not used).
    pub fn coulomb_level(physical: Physical, runtime: Runtime) -> Self {
        let p = general_level_coulomb::prepare(&general_level_coulomb::Params::from_fn(|name| {
            params::by_name(&physical, &runtime, name)
        }));
        Self::with(Kernels::CoulombLevel(p), physical, runtime, 0.0)
    }

    /// The passive wheel on a slope with exact Coulomb friction (Eq. 25) and stick-slip, every
    /// parameter at run time (`c` is not used).
    pub fn coulomb_slope(physical: Physical, runtime: Runtime) -> Self {
        let p = general_slope_coulomb::prepare(&general_slope_coulomb::Params::from_fn(|name| {
            params::by_name(&physical, &runtime, name)
        }));
        Self::with(Kernels::CoulombSlope(p), physical, runtime, runtime.phi)
    }

    /// The friction law of the model's kernels.
    pub fn friction_law(&self) -> FrictionLaw {
        match self.kernels {
            Kernels::CoulombLevel(_) | Kernels::CoulombSlope(_) => FrictionLaw::Coulomb,
            _ => FrictionLaw::Tanh,
        }
    }

    /// Level/active or slope/passive.
    pub fn kind(&self) -> Kind {
        match self.kernels {
            Kernels::ActiveLevel(_) | Kernels::GeneralLevel(_) | Kernels::CoulombLevel(_) => {
                Kind::ActiveLevel
            }
            Kernels::PassiveSlope(_) | Kernels::GeneralSlope(_) | Kernels::CoulombSlope(_) => {
                Kind::PassiveSlope
            }
        }
    }

    /// Whether the torso is driven by the output-following control.
    pub fn is_active(&self) -> bool {
        self.kind() == Kind::ActiveLevel
    }

    /// The stance-leg angle at heel strike: `alpha/2` (level, Eq. 3) or `alpha/2 + phi`
    /// (slope, Section 5.1).
    pub fn heel_strike_angle(&self) -> f64 {
        self.physical.alpha / 2.0 + self.runtime.phi
    }

    /// The stance-leg angle at which the rear spoke touches the floor: `-alpha/2` (level) or
    /// `phi - alpha/2` (slope); also the post-impact angle (Eqs. 18, 45 corrected).
    pub fn rear_contact_angle(&self) -> f64 {
        self.runtime.phi - self.physical.alpha / 2.0
    }

    /// The auxiliary input `v` of Eq. 32 at time `t` since the last impact and state `y`
    /// (`y = th1 - th2`, `y_d` of Section 3.2).
    fn aux_input(&self, t: f64, y: &[f64]) -> f64 {
        let r = &self.runtime;
        control::aux_input(self.ramp.at(t), y[2] - y[3], y[6] - y[7], r.k_p, r.k_d)
    }

    /// Stance accelerations `qdd` and control input `u` at time `t` since the last impact and
    /// state `y = [x, z, th1, th2, xd, zd, th1d, th2d, ..]` in the contact `contact`: for the
    /// active walker under the output control of Eqs. 31-32 with `y_d` of Section 3.2 (one
    /// `closed_loop_level` call, Eq. 27 with `u = (v + B) / A`; stuck, `closed_loop_stick_level`,
    /// the same control with both foot coordinates held), for the passive wheel Eq. 27 with
    /// `u = 0` (stuck: `stick_slope`). Smooth-law models ignore `contact`; a Coulomb model given
    /// [`Contact::Smooth`] is treated as stuck.
    pub fn stance(&self, t: f64, y: &[f64], contact: Contact) -> ([f64; 4], f64) {
        let (th1, xd, th1d) = (y[2], y[4], y[6]);
        let v = || self.aux_input(t, y);
        let closed = |o: [f64; 5]| ([o[0], o[1], o[2], o[3]], o[4]);
        let head = |o: &[f64]| [o[0], o[1], o[2], o[3]];
        match (&self.kernels, contact) {
            (Kernels::ActiveLevel(p), _) => {
                closed(active_level::closed_loop_level(p, th1, th1d, xd, v()))
            }
            (Kernels::GeneralLevel(p), _) => {
                closed(general_level::closed_loop_level(p, th1, th1d, xd, v()))
            }
            (Kernels::PassiveSlope(p), _) => (passive_slope::accel_slope(p, th1, th1d, xd), 0.0),
            (Kernels::GeneralSlope(p), _) => (general_slope::accel_slope(p, th1, th1d, xd), 0.0),
            (Kernels::CoulombLevel(p), Contact::Sliding(s)) => closed(
                general_level_coulomb::closed_loop_level(p, th1, th1d, s.sigma(), v()),
            ),
            (Kernels::CoulombLevel(p), Contact::Stuck | Contact::Smooth) => {
                let o = general_level_coulomb::closed_loop_stick_level(p, th1, th1d, v());
                (head(&o), o[4])
            }
            (Kernels::CoulombSlope(p), Contact::Sliding(s)) => (
                general_slope_coulomb::accel_slope(p, th1, th1d, s.sigma()),
                0.0,
            ),
            (Kernels::CoulombSlope(p), Contact::Stuck | Contact::Smooth) => {
                (head(&general_slope_coulomb::stick_slope(p, th1, th1d)), 0.0)
            }
        }
    }

    /// For a Coulomb model, the normal force at `(t, y)` with the friction switched off (`mu = 0`,
    /// the control recomputed for it); `None` for smooth-law models. Where a sliding foot's
    /// normal force is negative but this one is not, it is the sliding friction that pulls the
    /// foot off the floor: Painleve's paradox, not a lift-off.
    pub fn frictionless_normal(&self, t: f64, y: &[f64]) -> Option<f64> {
        let (th1, th1d) = (y[2], y[6]);
        match &self.kernels {
            Kernels::CoulombLevel(p) => {
                let u = general_level_coulomb::closed_loop_level(
                    p,
                    th1,
                    th1d,
                    0.0,
                    self.aux_input(t, y),
                )[4];
                Some(general_level_coulomb::lambda_level(p, th1, th1d, u, 0.0))
            }
            Kernels::CoulombSlope(p) => Some(
                general_slope_coulomb::lambda_slope(p, th1, th1d, 0.0) / self.runtime.phi.cos(),
            ),
            _ => None,
        }
    }

    /// `lambda` of Eqs. 22-23 at the angle `th1` and foot velocity `xd` of `y` (the sliding
    /// direction of `contact` under Coulomb friction) with gravity alone in the numerator: the
    /// stance leg at rest and no control input (`th1d = u = 0`), so `m_t I1 g / D` on level
    /// ground and `m_t I1 g cos^2 phi / D` on the slope, `D` the denominator of Eq. 23. Where
    /// `D` is regular (of the size of `I1 + m_t l^2 sin^2 th1`) this is of the order of the body
    /// weight `m_t g`; near a zero of `D` it grows without bound, whatever the spin and the
    /// control input of the state. `None` for a stuck foot, whose reaction (`stick_level`,
    /// `stick_slope`) has no such denominator.
    pub fn gravity_lambda(&self, y: &[f64], contact: Contact) -> Option<f64> {
        let (th1, xd) = (y[2], y[4]);
        match (&self.kernels, contact) {
            (Kernels::ActiveLevel(p), _) => Some(active_level::lambda_level(p, th1, 0.0, 0.0, xd)),
            (Kernels::GeneralLevel(p), _) => {
                Some(general_level::lambda_level(p, th1, 0.0, 0.0, xd))
            }
            (Kernels::PassiveSlope(p), _) => Some(passive_slope::lambda_slope(p, th1, 0.0, xd)),
            (Kernels::GeneralSlope(p), _) => Some(general_slope::lambda_slope(p, th1, 0.0, xd)),
            (Kernels::CoulombLevel(p), Contact::Sliding(s)) => Some(
                general_level_coulomb::lambda_level(p, th1, 0.0, 0.0, s.sigma()),
            ),
            (Kernels::CoulombSlope(p), Contact::Sliding(s)) => {
                Some(general_slope_coulomb::lambda_slope(p, th1, 0.0, s.sigma()))
            }
            (Kernels::CoulombLevel(_) | Kernels::CoulombSlope(_), _) => None,
        }
    }

    /// The ground's force on the stance foot at `(t, y)` in the contact `contact`, with the
    /// control input of that point: sliding, `lambda` of Eqs. 22-23 (`lambda_level`,
    /// `lambda_slope`) and `mu` times the normal force along the floor (Eqs. 24, 38); stuck, the
    /// two forces of `stick_level` / `stick_slope`.
    pub fn reaction(&self, t: f64, y: &[f64], contact: Contact) -> Reaction {
        let (th1, xd, th1d) = (y[2], y[4], y[6]);
        let r = &self.runtime;
        let u = || self.stance(t, y, contact).1;
        let level = |lambda: f64, mu: f64| Reaction {
            lambda,
            normal: lambda,
            tangential: mu * lambda,
        };
        let (sphi, cphi) = r.phi.sin_cos();
        let slope = |lambda: f64, mu: f64| Reaction {
            lambda,
            normal: lambda / cphi,
            tangential: mu * lambda / cphi,
        };
        let tanh_mu = |arg: f64| -r.mu0 * (r.c * arg).tanh();
        let stuck = |tangential: f64, normal: f64| Reaction {
            lambda: normal * cphi - tangential * sphi,
            normal,
            tangential,
        };
        match (&self.kernels, contact) {
            (Kernels::ActiveLevel(p), _) => level(
                active_level::lambda_level(p, th1, th1d, u(), xd),
                tanh_mu(xd),
            ),
            (Kernels::GeneralLevel(p), _) => level(
                general_level::lambda_level(p, th1, th1d, u(), xd),
                tanh_mu(xd),
            ),
            (Kernels::PassiveSlope(p), _) => slope(
                passive_slope::lambda_slope(p, th1, th1d, xd),
                tanh_mu(xd / cphi),
            ),
            (Kernels::GeneralSlope(p), _) => slope(
                general_slope::lambda_slope(p, th1, th1d, xd),
                tanh_mu(xd / cphi),
            ),
            (Kernels::CoulombLevel(p), Contact::Sliding(s)) => level(
                general_level_coulomb::lambda_level(p, th1, th1d, u(), s.sigma()),
                -r.mu0 * s.sigma(),
            ),
            (Kernels::CoulombLevel(p), Contact::Stuck | Contact::Smooth) => {
                let o = general_level_coulomb::closed_loop_stick_level(
                    p,
                    th1,
                    th1d,
                    self.aux_input(t, y),
                );
                stuck(o[5], o[6])
            }
            (Kernels::CoulombSlope(p), Contact::Sliding(s)) => slope(
                general_slope_coulomb::lambda_slope(p, th1, th1d, s.sigma()),
                -r.mu0 * s.sigma(),
            ),
            (Kernels::CoulombSlope(p), Contact::Stuck | Contact::Smooth) => {
                let o = general_slope_coulomb::stick_slope(p, th1, th1d);
                stuck(o[4], o[5])
            }
        }
    }

    /// The impact map at the pre-impact state `[x, z, th1, th2, xd, zd, th1d, th2d]` under the
    /// model's [`ImpactLaw`]. Frictionless (the paper's): `impact2_level` with the test
    /// `impact3_level` (level), `impact_slope` with the test `impact2_slope` (slope). With
    /// Coulomb friction: `impact_coulomb_level` / `impact_coulomb_slope` and Stronge's plastic
    /// impact ([`super::friction_impact`]).
    ///
    /// # Errors
    /// [`ImpactJam`]: the impact with friction has no rigid-body solution (never for the
    /// frictionless law).
    pub fn impact(&self, s: &[f64; 8]) -> Result<ImpactResult, ImpactJam> {
        if self.impact_law == ImpactLaw::Coulomb {
            return coulomb_impact(self.impact_kernel(s), self.runtime.mu0);
        }
        let (th1, xd, zd, th1d, th2d) = (s[2], s[4], s[5], s[6], s[7]);
        let cphi = self.runtime.phi.cos();
        Ok(match &self.kernels {
            Kernels::ActiveLevel(p) => level_impact(
                active_level::impact3_level(p, th1, xd, zd, th1d, th2d),
                active_level::impact2_level(p, th1, xd, zd, th1d, th2d),
            ),
            Kernels::GeneralLevel(p) => level_impact(
                general_level::impact3_level(p, th1, xd, zd, th1d, th2d),
                general_level::impact2_level(p, th1, xd, zd, th1d, th2d),
            ),
            Kernels::PassiveSlope(p) => slope_impact(
                passive_slope::impact_slope(p, th1, xd, zd, th1d, th2d),
                passive_slope::impact2_slope(p, th1, xd, zd, th1d, th2d),
                cphi,
            ),
            Kernels::GeneralSlope(p) => slope_impact(
                general_slope::impact_slope(p, th1, xd, zd, th1d, th2d),
                general_slope::impact2_slope(p, th1, xd, zd, th1d, th2d),
                cphi,
            ),
            Kernels::CoulombLevel(p) => level_impact(
                general_level_coulomb::impact3_level(p, th1, xd, zd, th1d, th2d),
                general_level_coulomb::impact2_level(p, th1, xd, zd, th1d, th2d),
            ),
            Kernels::CoulombSlope(p) => slope_impact(
                general_slope_coulomb::impact_slope(p, th1, xd, zd, th1d, th2d),
                general_slope_coulomb::impact2_slope(p, th1, xd, zd, th1d, th2d),
                cphi,
            ),
        })
    }

    /// The rigid-body part of the impact with friction at the pre-impact state `s`
    /// (`impact_coulomb_level` / `impact_coulomb_slope`), whatever the model's impact law.
    pub fn impact_ingredients(&self, s: &[f64; 8]) -> Ingredients {
        Ingredients::from_kernel(self.impact_kernel(s))
    }

    fn impact_kernel(&self, s: &[f64; 8]) -> [f64; 21] {
        let (th1, xd, zd, th1d, th2d) = (s[2], s[4], s[5], s[6], s[7]);
        match &self.kernels {
            Kernels::ActiveLevel(p) => {
                active_level::impact_coulomb_level(p, th1, xd, zd, th1d, th2d)
            }
            Kernels::GeneralLevel(p) => {
                general_level::impact_coulomb_level(p, th1, xd, zd, th1d, th2d)
            }
            Kernels::PassiveSlope(p) => {
                passive_slope::impact_coulomb_slope(p, th1, xd, zd, th1d, th2d)
            }
            Kernels::GeneralSlope(p) => {
                general_slope::impact_coulomb_slope(p, th1, xd, zd, th1d, th2d)
            }
            Kernels::CoulombLevel(p) => {
                general_level_coulomb::impact_coulomb_level(p, th1, xd, zd, th1d, th2d)
            }
            Kernels::CoulombSlope(p) => {
                general_slope_coulomb::impact_coulomb_slope(p, th1, xd, zd, th1d, th2d)
            }
        }
    }

    /// Position and velocity of the fore foot `[x_f, z_f, xd_f, zd_f]` (Eqs. 3, 39).
    pub fn fore_foot(&self, x: f64, z: f64, th1: f64, xd: f64, zd: f64, th1d: f64) -> [f64; 4] {
        match &self.kernels {
            Kernels::ActiveLevel(p) => active_level::fore_foot(p, x, z, th1, xd, zd, th1d),
            Kernels::GeneralLevel(p) => general_level::fore_foot(p, x, z, th1, xd, zd, th1d),
            Kernels::PassiveSlope(p) => passive_slope::fore_foot(p, x, z, th1, xd, zd, th1d),
            Kernels::GeneralSlope(p) => general_slope::fore_foot(p, x, z, th1, xd, zd, th1d),
            Kernels::CoulombLevel(p) => {
                general_level_coulomb::fore_foot(p, x, z, th1, xd, zd, th1d)
            }
            Kernels::CoulombSlope(p) => {
                general_slope_coulomb::fore_foot(p, x, z, th1, xd, zd, th1d)
            }
        }
    }

    /// Kinetic and potential energy `[T, V]` of the state `[x, z, th1, th2, xd, zd, th1d, th2d]`.
    pub fn energy(&self, s: &[f64; 8]) -> [f64; 2] {
        let (z, th1, xd, zd, th1d, th2d) = (s[1], s[2], s[4], s[5], s[6], s[7]);
        match &self.kernels {
            Kernels::ActiveLevel(p) => active_level::energy(p, z, th1, xd, zd, th1d, th2d),
            Kernels::GeneralLevel(p) => general_level::energy(p, z, th1, xd, zd, th1d, th2d),
            Kernels::PassiveSlope(p) => passive_slope::energy(p, z, th1, xd, zd, th1d, th2d),
            Kernels::GeneralSlope(p) => general_slope::energy(p, z, th1, xd, zd, th1d, th2d),
            Kernels::CoulombLevel(p) => {
                general_level_coulomb::energy(p, z, th1, xd, zd, th1d, th2d)
            }
            Kernels::CoulombSlope(p) => {
                general_slope_coulomb::energy(p, z, th1, xd, zd, th1d, th2d)
            }
        }
    }

    /// The paper's initial condition: Eq. 33 with `omega0` for the active walker, (P2b)
    /// (`q = 0`, `qd = [0, 0, 0.5, 0]`; `omega0` replaces the 0.5) for the passive wheel.
    pub fn initial_state(&self, omega0: f64) -> [f64; 8] {
        match self.kind() {
            Kind::ActiveLevel => [
                0.0,
                0.0,
                -self.physical.alpha / 2.0,
                0.0,
                0.0,
                0.0,
                omega0,
                omega0,
            ],
            Kind::PassiveSlope => [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, omega0, 0.0],
        }
    }

    /// The default initial angular velocity: `omega0 = 0.8` (Section 4.1) for the active walker,
    /// 0.5 (P2b) for the passive wheel.
    pub fn default_omega0(&self) -> f64 {
        match self.kind() {
            Kind::ActiveLevel => 0.8,
            Kind::PassiveSlope => 0.5,
        }
    }
}
