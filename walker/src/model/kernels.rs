//! The kernels of a model as the simulator calls them: one interface ([`Kernels`]) whatever
//! produced them, code generated at build time (`walker/build.rs`, [`crate::compiled`]) or a
//! model file derived and evaluated at run time (the `walker-load` crate).
//!
//! A kernel is named by a [`KernelId`] (the model-independent names of `docs/model-format.md`);
//! its arguments come as one [`Args`] (coordinates, velocities, inputs, the sliding direction,
//! auxiliary inputs), from which each implementation takes the ones its kernel reads; its
//! outputs are written in the derivation's order, flattened row-major.
//!
//! Beside [`Kernels::eval`], the interface names what the simulator asks for at every point of
//! a stance phase: the right-hand side ([`Kernels::stance_rhs`]), the power's sign function
//! ([`Kernels::power_sign`]) and the sliding foot's ground reaction
//! ([`Kernels::sliding_lambda`]). Their provided methods assemble them from `eval`; a compiled
//! variant overrides each with one generated function of the same arithmetic
//! (`tests/compiled_fused.rs` holds them equal bit for bit), so that no argument struct, slice
//! or dispatch stands between the integrator and the kernels.

use super::desired::{Desired, aux_input};
use crate::vector::MAX_COORDINATES;

/// A model kernel (`docs/model-format.md`, "The kernels of a model").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum KernelId {
    /// `accel`: `qdd` of the sliding stance (inputs as arguments; `u = 0` for a passive walker).
    Accel,
    /// `closed_loop`: `[qdd, u]` under the output-following control (Eqs. 27, 31).
    ClosedLoop,
    /// `lambda`: the vertical ground reaction of the sliding stance foot (Eqs. 22-23).
    Lambda,
    /// `stick`: `[qdd, lambda_t, lambda_n]` with the stance foot stuck.
    Stick,
    /// `closed_loop_stick`: `[qdd, u, lambda_t, lambda_n]` stuck, under the control.
    ClosedLoopStick,
    /// `impact`: `[lambda_I, qd+]` of the frictionless impact (striking point and locks).
    Impact,
    /// `impact_double`: `[lambda_I, qd+]` with the old stance foot held too (the test).
    ImpactDouble,
    /// `impact_coulomb`: the ingredients of the impact with Coulomb friction
    /// (`[qdl, v_t, v_n, v_r, W_tt, W_tn, W_tr, W_nn, W_nr, W_rr, R]`).
    ImpactCoulomb,
    /// `events`: `[guard, fall_1, ..]`.
    Events,
    /// `relabel`: `[q+, qd+]` in the new stance leg's coordinates, from `q-` and `qd+`.
    Relabel,
    /// `points`: `[x_p, z_p]` of every named point.
    Points,
    /// `energy`: `[T, V]`.
    Energy,
    /// `output_rates`: `[y, yd]` of the controlled outputs.
    OutputRates,
    /// `input_rates`: `w_i = S_i^T qd`, the rate at which input `i` does work.
    InputRates,
    /// `accel_jacobian`: `d qdd / d [q, qd, mu]` of `accel` (n x (2n + 1)).
    AccelJacobian,
    /// `closed_loop_jacobian`: `d [qdd, u] / d [q, qd, mu, v]` of `closed_loop`
    /// ((n + m) x (2n + 1 + m)).
    ClosedLoopJacobian,
    /// `impact_jacobian`: `d qd+ / d [q, qd]` of `impact` (n x 2n).
    ImpactJacobian,
    /// `output_rates_jacobian`: `d [y, yd] / d [q, qd]` of `output_rates` (2m x 2n).
    OutputRatesJacobian,
    /// `input_rates_jacobian`: `d w / d [q, qd]` of `input_rates` (m x 2n).
    InputRatesJacobian,
    /// `relabel_jacobian`: `d [q+, qd+] / d [q-, qd+ of the old coordinates]` of `relabel`
    /// (2n x 2n).
    RelabelJacobian,
    /// `stick_jacobian`: `d [qdd, lambda_t, lambda_n] / d [q, qd]` of `stick`
    /// ((n + 2) x 2n; a model without inputs whose stuck stance has a closed form).
    StickJacobian,
}

impl KernelId {
    /// Every kernel, in the order of `docs/model-format.md`.
    pub const ALL: [KernelId; 21] = [
        KernelId::Accel,
        KernelId::ClosedLoop,
        KernelId::Lambda,
        KernelId::Stick,
        KernelId::ClosedLoopStick,
        KernelId::Impact,
        KernelId::ImpactDouble,
        KernelId::ImpactCoulomb,
        KernelId::Events,
        KernelId::Relabel,
        KernelId::Points,
        KernelId::Energy,
        KernelId::OutputRates,
        KernelId::InputRates,
        KernelId::AccelJacobian,
        KernelId::ClosedLoopJacobian,
        KernelId::ImpactJacobian,
        KernelId::OutputRatesJacobian,
        KernelId::InputRatesJacobian,
        KernelId::RelabelJacobian,
        KernelId::StickJacobian,
    ];

    /// The kernel's name in model files and generated code.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            KernelId::Accel => "accel",
            KernelId::ClosedLoop => "closed_loop",
            KernelId::Lambda => "lambda",
            KernelId::Stick => "stick",
            KernelId::ClosedLoopStick => "closed_loop_stick",
            KernelId::Impact => "impact",
            KernelId::ImpactDouble => "impact_double",
            KernelId::ImpactCoulomb => "impact_coulomb",
            KernelId::Events => "events",
            KernelId::Relabel => "relabel",
            KernelId::Points => "points",
            KernelId::Energy => "energy",
            KernelId::OutputRates => "output_rates",
            KernelId::InputRates => "input_rates",
            KernelId::AccelJacobian => "accel_jacobian",
            KernelId::ClosedLoopJacobian => "closed_loop_jacobian",
            KernelId::ImpactJacobian => "impact_jacobian",
            KernelId::OutputRatesJacobian => "output_rates_jacobian",
            KernelId::InputRatesJacobian => "input_rates_jacobian",
            KernelId::RelabelJacobian => "relabel_jacobian",
            KernelId::StickJacobian => "stick_jacobian",
        }
    }

    /// The kernel called `name`.
    #[must_use]
    pub fn from_name(name: &str) -> Option<KernelId> {
        KernelId::ALL.into_iter().find(|k| k.name() == name)
    }
}

/// The arguments of a kernel call: every kernel reads the ones it needs.
#[derive(Clone, Copy, Debug)]
pub struct Args<'a> {
    /// Coordinates `q`.
    pub q: &'a [f64],
    /// Velocities `qd`.
    pub qd: &'a [f64],
    /// Inputs `u` (the `accel` and `lambda` kernels of a model with inputs).
    pub u: &'a [f64],
    /// The sliding direction `sigma` under exact Coulomb friction (`mu = -mu0 sigma`); the
    /// tanh law reads the foot's velocity `qd[0]` instead.
    pub sigma: f64,
    /// The auxiliary inputs `v` of the output-following control (Eq. 32).
    pub v: &'a [f64],
}

impl<'a> Args<'a> {
    /// The state `(q, qd)` with no inputs, `sigma = 0` and no auxiliary inputs.
    #[must_use]
    pub fn state(q: &'a [f64], qd: &'a [f64]) -> Args<'a> {
        Args {
            q,
            qd,
            u: &[],
            sigma: 0.0,
            v: &[],
        }
    }
}

/// What the output-following control tracks at one instant (Eq. 32): the desired trajectories
/// (one per output), the time since the last impact and the gains.
#[derive(Clone, Copy, Debug)]
pub struct Tracking<'a> {
    /// The desired trajectories `y_d`, in output order.
    pub desired: &'a [Desired],
    /// The time `t` since the last impact.
    pub t: f64,
    /// The gains `(K_P, K_D)`.
    pub gains: (f64, f64),
}

impl Tracking<'_> {
    /// The auxiliary input `v_i` of output `i` at its value `y` and rate `ydot`:
    /// `ydd_d + K_D (yd_d - ydot) + K_P (y_d - y)` with `[y_d, yd_d, ydd_d] = desired[i](t)`.
    #[inline]
    #[must_use]
    pub fn aux_input(&self, i: usize, y: f64, ydot: f64) -> f64 {
        aux_input(
            self.desired[i].at(self.t),
            y,
            ydot,
            self.gains.0,
            self.gains.1,
        )
    }
}

/// A model's kernels, prepared for one set of run-time parameters.
pub trait Kernels: Send + Sync {
    /// Whether the model has kernel `k` (the control kernels need inputs, `impact_double` the
    /// double-support test, the Jacobians a closed form).
    fn has(&self, k: KernelId) -> bool;

    /// Evaluates kernel `k` at `args` into `out`, its outputs in the derivation's order
    /// (flattened row-major). A kernel the model does not have fills `out` with NaN.
    fn eval(&self, k: KernelId, args: &Args<'_>, out: &mut [f64]);

    /// The auxiliary inputs `v` of Eq. 32 at `args`, one per output (`m = v.len()`): the
    /// outputs and their rates `[y, ydot]` (`output_rates`), then
    /// `v_i = ydd_d + K_D (yd_d - ydot_i) + K_P (y_d - y_i)` from `control`
    /// ([`Tracking::aux_input`]).
    fn aux_inputs(&self, args: &Args<'_>, control: &Tracking<'_>, v: &mut [f64]) {
        let m = v.len();
        let mut rates = [0.0; 2 * MAX_COORDINATES];
        self.eval(KernelId::OutputRates, args, &mut rates[..2 * m]);
        for (i, vi) in v.iter_mut().enumerate() {
            *vi = control.aux_input(i, rates[i], rates[m + i]);
        }
    }

    /// The controlled stance of a model with `m = w.len()` inputs, in one call: the outputs
    /// and their rates `[y, ydot]` (`output_rates` at `args`), the auxiliary inputs
    /// `v_i = ydd_d + K_D (yd_d - ydot_i) + K_P (y_d - y_i)` of Eq. 32 from `control`
    /// ([`Tracking::aux_input`]), the closed loop `k` (`ClosedLoop` or
    /// `ClosedLoopStick`) at those `v` into `out`, and the inputs' rates (`input_rates`) into
    /// `w`.
    ///
    /// The default makes the three [`Kernels::eval`] calls; a compiled variant calls its
    /// functions directly (the right-hand side of every actuated walk goes through here), with
    /// the same arithmetic.
    fn tracking(
        &self,
        k: KernelId,
        args: &Args<'_>,
        control: &Tracking<'_>,
        out: &mut [f64],
        w: &mut [f64],
    ) {
        let m = w.len();
        let mut v = [0.0; MAX_COORDINATES];
        self.aux_inputs(args, control, &mut v[..m]);
        self.eval(
            k,
            &Args {
                v: &v[..m],
                ..*args
            },
            out,
        );
        self.eval(KernelId::InputRates, args, w);
    }

    /// The stance kernel at the state `y = [q, qd]` (`n = y.len() / 2`), for a model with
    /// `m = control.desired.len()` inputs: into `out`, the outputs of `accel` (`[qdd]`) or,
    /// `stuck`, of `stick` (`[qdd, lambda_t, lambda_n]`) for a passive walker, and for one with
    /// inputs those of the closed loop under the output-following control
    /// ([`Kernels::tracking`]: `closed_loop`, `[qdd, u]`, or `closed_loop_stick`,
    /// `[qdd, u, lambda_t, lambda_n]`), with the inputs' rates into `w`; returns how many
    /// outputs it wrote. `sigma` is the sliding direction under exact Coulomb friction. `out`
    /// must hold `n + m + 2` numbers, `w` `m`.
    fn stance(
        &self,
        stuck: bool,
        sigma: f64,
        y: &[f64],
        control: &Tracking<'_>,
        out: &mut [f64],
        w: &mut [f64],
    ) -> usize {
        let (n, m) = (y.len() / 2, control.desired.len());
        let args = Args {
            sigma,
            ..Args::state(&y[..n], &y[n..2 * n])
        };
        let (k, len) = match (m, stuck) {
            (0, false) => (KernelId::Accel, n),
            (0, true) => (KernelId::Stick, n + 2),
            (_, false) => (KernelId::ClosedLoop, n + m),
            (_, true) => (KernelId::ClosedLoopStick, n + m + 2),
        };
        if m == 0 {
            self.eval(k, &args, &mut out[..len]);
        } else {
            self.tracking(k, &args, control, &mut out[..len], &mut w[..m]);
        }
        len
    }

    /// The stance phase's right-hand side at the state `y = [q, qd]` (`n = y.len() / 2`), in
    /// one call: `dy = [qd, qdd]` with `qdd` of [`Kernels::stance`], and the input power's
    /// integrand `sum |u_i w_i|` ([`power`]; 0 without inputs).
    ///
    /// The default assembles it from [`Kernels::stance`]; a compiled variant writes it as one
    /// function with the same arithmetic (every stage of every integration step calls it, and
    /// the layers between the calls were 7 % of a walk's instructions).
    fn stance_rhs(
        &self,
        stuck: bool,
        sigma: f64,
        y: &[f64],
        control: &Tracking<'_>,
        dy: &mut [f64],
    ) -> f64 {
        let (n, m) = (y.len() / 2, control.desired.len());
        let (mut out, mut w) = ([0.0; 2 * MAX_COORDINATES + 2], [0.0; MAX_COORDINATES]);
        self.stance(stuck, sigma, y, control, &mut out, &mut w);
        dy[..n].copy_from_slice(&y[n..]);
        dy[n..2 * n].copy_from_slice(&out[..n]);
        power(&out[n..n + m], &w[..m])
    }

    /// The product of the inputs' powers `prod u_i w_i` at the state `y = [q, qd]` under the
    /// output-following control ([`Kernels::stance`]); 1 without inputs. It changes sign where
    /// one of the powers does, at a kink of the power's integrand `sum |u_i w_i|` (the error
    /// test and the kink guard ask at every step's ends).
    ///
    /// The default assembles it from [`Kernels::stance`]; a compiled variant writes it as one
    /// function with the same arithmetic.
    fn power_sign(&self, stuck: bool, sigma: f64, y: &[f64], control: &Tracking<'_>) -> f64 {
        let (n, m) = (y.len() / 2, control.desired.len());
        let (mut out, mut w) = ([0.0; 2 * MAX_COORDINATES + 2], [0.0; MAX_COORDINATES]);
        self.stance(stuck, sigma, y, control, &mut out, &mut w);
        w[..m]
            .iter()
            .zip(&out[n..n + m])
            .map(|(wi, ui)| wi * ui)
            .product()
    }

    /// The vertical ground reaction `lambda` of the sliding stance foot (Eqs. 22-23) at the
    /// state `y = [q, qd]` (`n = y.len() / 2`) with the control inputs of that point: for a
    /// model with `m = control.desired.len()` inputs, `u` of the closed loop
    /// ([`Kernels::tracking`] with `closed_loop`), then `lambda` at that `u`; `sigma` is the
    /// sliding direction under exact Coulomb friction. The lift-off guard asks for it at every
    /// step's end.
    ///
    /// The default assembles it from [`Kernels::tracking`] and [`Kernels::eval`]; a compiled
    /// variant writes it as one function with the same arithmetic.
    fn sliding_lambda(&self, sigma: f64, y: &[f64], control: &Tracking<'_>) -> f64 {
        let (n, m) = (y.len() / 2, control.desired.len());
        let args = Args {
            sigma,
            ..Args::state(&y[..n], &y[n..2 * n])
        };
        let mut u = [0.0; MAX_COORDINATES];
        if m > 0 {
            let (mut out, mut w) = ([0.0; 2 * MAX_COORDINATES], [0.0; MAX_COORDINATES]);
            self.tracking(
                KernelId::ClosedLoop,
                &args,
                control,
                &mut out[..n + m],
                &mut w[..m],
            );
            u[..m].copy_from_slice(&out[n..n + m]);
        }
        let mut lambda = [0.0; 1];
        self.eval(KernelId::Lambda, &Args { u: &u[..m], ..args }, &mut lambda);
        lambda[0]
    }
}

/// The integrand of the input power, `sum |u_i w_i|` over the inputs' values `u` and rates `w`.
#[must_use]
#[inline]
pub fn power(u: &[f64], w: &[f64]) -> f64 {
    let mut sum = 0.0;
    for (wi, ui) in w.iter().zip(u) {
        sum += (wi * ui).abs();
    }
    sum
}
