//! The kernels of a model as the simulator calls them: one interface ([`Kernels`]) whatever
//! produced them, code generated at build time (walker-gen's adapter, [`crate::Compiled`]) or a
//! model file derived and evaluated at run time (the `walker-load` crate).
//!
//! A kernel is named by a [`KernelId`]; its arguments come as one [`Args`] (coordinates,
//! velocities, inputs, the sliding direction, auxiliary inputs), from which each implementation
//! takes the ones its kernel reads ([`crate::Binding`]); its outputs are written in the
//! derivation's order, flattened row-major.
//!
//! Beside [`Kernels::eval`], the interface names what the simulator asks for at every point of
//! a stance phase: the right-hand side ([`Kernels::stance_rhs`]), the power's sign function
//! ([`Kernels::power_sign`]) and the sliding foot's ground reaction
//! ([`Kernels::sliding_lambda`]). Their provided methods assemble them from `eval`; a compiled
//! variant overrides each with one generated function of the same arithmetic
//! (`walker/tests/it/compiled_fused.rs` holds them equal bit for bit), so that no argument struct,
//! slice or dispatch stands between the integrator and the kernels.

use crate::MAX_COORDINATES;
use crate::args::{Args, Tracking};
use crate::kernel_id::KernelId;

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
