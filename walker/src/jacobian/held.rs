//! The held foot of a model with inputs (the module documentation of [`super`]): the friction
//! ratio `mu*` that holds it, its derivatives by the implicit function theorem, and the stuck
//! stance's rows with `mu*`'s derivative eliminated, from the sliding kernels at `mu*`.

use walker_contract::Desired;

use crate::model::{Args, Contact, KernelId};
use crate::vector::MAX_COORDINATES;

use super::{NoJacobian, Scratch, StanceJacobian, plus_through_v};

/// The friction ratio that holds the stance foot of a model with inputs, with its derivatives
/// ([`StanceJacobian::held_ratio`]).
#[derive(Clone, Copy, Debug)]
pub struct HeldRatio {
    /// The ground's force along the floor (`lambda_t`, the stuck kernel's).
    pub tangential: f64,
    /// The ground's force normal to the floor (`lambda_n`, positive).
    pub normal: f64,
    /// `mu* = lambda_t / lambda_n`.
    pub mu: f64,
    /// `d mu* / d y` (`2n` numbers used).
    pub d_y: [f64; 2 * MAX_COORDINATES],
    /// `d mu* / dt` at a fixed state: through the desired trajectories in `v(t, y)`.
    pub d_t: f64,
}

impl StanceJacobian<'_> {
    /// The stuck stance's rows of a model with inputs (module documentation): the sliding
    /// rows at `mu*` into `out` (with `d mu*/dy` and `d mu*/dt` returned), then
    /// `D_i - (K_mu,i / K_mu,0) D_0` on every row asked for (row 0 becomes exactly zero).
    pub(super) fn held_rows(
        &self,
        t: f64,
        y: &[f64],
        out: &mut [f64],
        scratch: &mut Scratch,
    ) -> Result<HeldRatio, NoJacobian> {
        let m = self.model;
        let (n, inputs) = (m.n(), m.inputs());
        let rows = (out.len() / (2 * n)).min(n + inputs);
        let mut d = [0.0; 2 * MAX_COORDINATES * 2 * MAX_COORDINATES];
        let held = self.held_ratio_into(t, y, &mut d[..rows * 2 * n], scratch)?;
        let cols = 2 * n + 1 + inputs;
        let k = &scratch.k;
        let pivot = k[2 * n];
        let (d0, rest) = d.split_at(2 * n);
        for (i, o) in out[..rows * 2 * n].chunks_exact_mut(2 * n).enumerate() {
            let ratio = k[i * cols + 2 * n] / pivot;
            let di = if i == 0 {
                d0
            } else {
                &rest[(i - 1) * 2 * n..i * 2 * n]
            };
            for ((o, &dij), &d0j) in o.iter_mut().zip(di).zip(d0) {
                *o = dij - ratio * d0j;
            }
        }
        Ok(held)
    }

    /// The stuck stance's rows of a model with inputs from `closed_loop_stick_jacobian` (a
    /// model whose stance has no closed form: the structured solve differentiated), chained
    /// through `v`: as many rows as `out` holds (`n`, or `n + m` with the inputs), row stride
    /// `2n`. The kernel's output is left in `scratch` (columns `[q, qd, v]`; rows `[qdd, u,
    /// lambda_t, lambda_n]`), which a parameter's column reads
    /// ([`crate::poincare::parameter_column`]).
    pub(super) fn held_stick_rows(
        &self,
        t: f64,
        y: &[f64],
        out: &mut [f64],
        scratch: &mut Scratch,
    ) {
        let m = self.model;
        let (n, inputs) = (m.n(), m.inputs());
        let Scratch { k, rates } = scratch;
        let v = self.inputs_at(t, y, rates);
        let cols = 2 * n + inputs;
        m.kernels().eval(
            KernelId::ClosedLoopStickJacobian,
            &Args {
                v: &v[..inputs],
                ..Args::state(&y[..n], &y[n..2 * n])
            },
            &mut k[..(n + inputs + 2) * cols],
        );
        let rows = (out.len() / (2 * n)).min(n + inputs);
        let gains = m.gains();
        for (i, o) in out[..rows * 2 * n].chunks_exact_mut(2 * n).enumerate() {
            let row = &k[i * cols..(i + 1) * cols];
            for (j, o) in o.iter_mut().enumerate() {
                *o = plus_through_v(row[j], &row[2 * n..], rates, (n, inputs), gains, j);
            }
        }
    }

    /// The friction ratio `mu* = lambda_t / lambda_n` that holds the stance foot of a model
    /// with inputs at `(t, y)`, with `d mu*/dy = -D_0 / K_mu,0` and `d mu*/dt = -(sum_k K_v,0k
    /// d v_k/dt) / K_mu,0` (`d v_k/dt = yddd_d + K_D ydd_d + K_P yd_d` at a fixed state), from
    /// the sliding kernel `closed_loop_jacobian` at `mu = mu*` (the kernel's argument `sigma =
    /// -mu*/mu0`), which is left in `scratch` (module documentation). The slip guard
    /// `|lambda_t| - mu0 lambda_n = lambda_n (|mu*| - mu0)` has, where it vanishes, the
    /// gradient `lambda_n sign(mu*) d mu*/dy` and the time rate `lambda_n sign(mu*) d mu*/dt`.
    ///
    /// # Errors
    /// [`NoJacobian::HeldRatioSingular`]: the normal force or `mu0` is not positive, or the
    /// foot's acceleration does not depend on the friction (`K_mu,0` zero or not finite).
    pub fn held_ratio(
        &self,
        t: f64,
        y: &[f64],
        scratch: &mut Scratch,
    ) -> Result<HeldRatio, NoJacobian> {
        let n = self.model.n();
        let mut d = [0.0; 2 * MAX_COORDINATES];
        self.held_ratio_into(t, y, &mut d[..2 * n], scratch)
    }

    /// [`StanceJacobian::held_ratio`], with the sliding rows `D` at `mu*` (as many rows as `d`
    /// holds, at least one) written into `d`.
    fn held_ratio_into(
        &self,
        t: f64,
        y: &[f64],
        d: &mut [f64],
        scratch: &mut Scratch,
    ) -> Result<HeldRatio, NoJacobian> {
        let m = self.model;
        let (n, inputs) = (m.n(), m.inputs());
        let mu0 = m.mu0();
        let force = m.reaction(t, y, Contact::Stuck);
        let mu = force.tangential / force.normal;
        if !(force.normal > 0.0 && mu.is_finite() && mu0 > 0.0 && mu0.is_finite()) {
            return Err(NoJacobian::HeldRatioSingular);
        }
        // Sliding at mu*, chained through v, without the `mu` term: mu* is eliminated below.
        self.sliding_rows(t, y, -mu / mu0, true, d, scratch);
        let k = &scratch.k;
        let pivot = k[2 * n];
        if pivot == 0.0 || !pivot.is_finite() || !d.iter().all(|x| x.is_finite()) {
            return Err(NoJacobian::HeldRatioSingular);
        }
        let mut d_y = [0.0; 2 * MAX_COORDINATES];
        for (o, &d0j) in d_y[..2 * n].iter_mut().zip(&d[..2 * n]) {
            *o = -d0j / pivot;
        }
        let (k_p, k_d) = m.gains();
        let mut dv_dt = 0.0;
        for i in 0..inputs {
            let [_, yd, ydd] = m.desired(i, t);
            let rate = jerk(m.desired_trajectory(i), t) + k_d * ydd + k_p * yd;
            dv_dt += k[2 * n + 1 + i] * rate;
        }
        Ok(HeldRatio {
            tangential: force.tangential,
            normal: force.normal,
            mu,
            d_y,
            d_t: -dv_dt / pivot,
        })
    }
}

/// The third derivative `yddd_d` of the desired trajectory `d` at `t` (zero for a constant and
/// from the ramp's end on): the time rate of `v` at a fixed state needs it.
fn jerk(d: &Desired, t: f64) -> f64 {
    match d {
        Desired::Quintic(r) => r.jerk(t),
        Desired::Hold(_) => 0.0,
        Desired::Bezier(b) => b.jerk(t),
    }
}
