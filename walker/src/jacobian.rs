//! The state Jacobians of the stance dynamics and of the impact map, from the model's Jacobian
//! kernels (`accel_jacobian` or `closed_loop_jacobian`, `output_rates_jacobian`,
//! `input_rates_jacobian`, `impact_jacobian`; generated where the model has closed forms and
//! its parameters are fixed): what the stiff integrator and the Poincare map's variational
//! equations need.
//!
//! The kernels differentiate with respect to the friction coefficient `mu` and the auxiliary
//! inputs `v` as symbols of their own; the chain rule through `mu(xd) = -mu0 tanh(c xd / cos
//! phi)` (Eqs. 26, 37) and through `v = ydd_d + K_D (yd_d - ydot) + K_P (y_d - y)` (Eq. 32) is
//! applied here. Under exact Coulomb friction a sliding phase has `mu = -mu0 sigma`, constant,
//! and a stuck phase its own kernel (`stick_jacobian`, with the ground force's rows for the
//! slip guard): [`StanceJacobian::any_law`], [`StanceJacobian::accel_in`], for the Poincare
//! map's variational equations (`docs/poincare.md`).
//!
//! A model with inputs has no `stick_jacobian`: its stuck stance is differentiated through the
//! sliding one ([`StanceJacobian::held_ratio`]). The held foot's force is the sliding foot's at
//! the friction ratio `mu*(t, y) = lambda_t / lambda_n` (the stuck system's solution solves the
//! sliding system at that `mu`), the one at which the foot's acceleration `xdd` vanishes. With
//! `D` the sliding rows chained through `v` at `mu*` (no `mu` term) and `K_mu` the kernel's `mu`
//! column, the implicit function theorem gives `d mu*/dy = -D_0 / K_mu,0` and the stuck field's
//! rows `D_i + K_mu,i d mu*/dy = D_i - (K_mu,i / K_mu,0) D_0` (row 0 vanishes exactly).

use crate::model::{Args, Contact, FrictionLaw, KernelId, Model};
use crate::vector::MAX_COORDINATES;

mod held;

pub use held::HeldRatio;

/// The largest output of a Jacobian kernel the chain rule reads: `closed_loop_jacobian` or
/// `closed_loop_stick_jacobian` of a model with [`MAX_COORDINATES`] coordinates and as many
/// inputs.
const MAX_JAC: usize = (2 * MAX_COORDINATES + 2) * (3 * MAX_COORDINATES + 1);

/// The kernels' outputs [`StanceJacobian::accel_with`] works in (`5.3` kB: zeroed once by
/// [`Scratch::new`], then overwritten where read).
#[derive(Clone)]
pub struct Scratch {
    /// The stance Jacobian kernel's output (after [`StanceJacobian::accel_with`] in a contact
    /// that is not stuck, or stuck for a model with inputs: its rows with the columns `[q, qd,
    /// mu, v]`).
    pub(crate) k: [f64; MAX_JAC],
    /// `output_rates_jacobian`'s output.
    rates: [f64; 4 * MAX_COORDINATES * MAX_COORDINATES],
}

impl Scratch {
    /// A zeroed scratch.
    #[must_use]
    pub fn new() -> Self {
        Self {
            k: [0.0; MAX_JAC],
            rates: [0.0; 4 * MAX_COORDINATES * MAX_COORDINATES],
        }
    }
}

impl Default for Scratch {
    fn default() -> Self {
        Self::new()
    }
}

/// Why a model's stance has no analytic Jacobian.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum NoJacobian {
    /// The kernels have no Jacobian kernels (every parameter at run time, or no closed form).
    #[error(
        "the model's kernels have no Jacobian kernels (they are generated with the parameters fixed, for models with closed forms)"
    )]
    NoKernels,
    /// The friction law is not the smooth one.
    #[error("the Jacobian kernels are used for the tanh friction law only")]
    NotTanh,
    /// A held foot of a model with inputs whose friction ratio `lambda_t / lambda_n` the
    /// sliding kernels cannot take: the normal force is not positive, `mu0` is not, or the
    /// foot's acceleration does not depend on the friction there (`d xdd / d mu = 0`), so
    /// [`StanceJacobian::held_ratio`] has no implicit function to differentiate.
    #[error(
        "the held foot's friction ratio has no derivative here (its normal force or d xdd / d mu vanishes)"
    )]
    HeldRatioSingular,
}

/// The analytic state Jacobian of a model's stance phase.
pub struct StanceJacobian<'a> {
    model: &'a Model,
}

impl<'a> StanceJacobian<'a> {
    /// The Jacobian of `model`'s stance, if its kernels give one.
    ///
    /// # Errors
    /// [`NoJacobian`]: no Jacobian kernels, or exact Coulomb friction.
    pub fn new(model: &'a Model) -> Result<Self, NoJacobian> {
        if model.friction_law() != FrictionLaw::Tanh {
            return Err(NoJacobian::NotTanh);
        }
        let k = model.kernels();
        let needed: &[KernelId] = if model.is_active() {
            &[
                KernelId::ClosedLoopJacobian,
                KernelId::OutputRatesJacobian,
                KernelId::InputRatesJacobian,
                KernelId::ImpactJacobian,
            ]
        } else {
            &[KernelId::AccelJacobian, KernelId::ImpactJacobian]
        };
        if !needed.iter().all(|id| k.has(*id)) {
            return Err(NoJacobian::NoKernels);
        }
        Ok(Self { model })
    }

    /// The Jacobian of `model`'s stance for the Poincare map's variational equations under
    /// either friction law: no kernel is required here; [`StanceJacobian::has_contact`] says
    /// which contacts the model's kernels differentiate (the simulator's stiff integrator keeps
    /// [`StanceJacobian::new`], so that its walks do not change).
    #[must_use]
    pub fn any_law(model: &'a Model) -> Self {
        Self { model }
    }

    /// Whether the model's kernels give the stance Jacobian in the contact `contact`: the
    /// sliding (or smooth) stance from `accel_jacobian` (`closed_loop_jacobian` with
    /// `output_rates_jacobian` for a model with inputs), the stuck stance from `stick_jacobian`
    /// (a model without inputs) or, for a model with inputs, from the sliding kernels at the
    /// held foot's friction ratio (module documentation; `mu0` positive, as `mu = -mu0 sigma`
    /// must reach every ratio).
    #[must_use]
    pub fn has_contact(&self, contact: Contact) -> bool {
        let k = self.model.kernels();
        if self.model.is_stuck(contact) && self.model.inputs() == 0 {
            return k.has(KernelId::StickJacobian);
        }
        if self.model.is_stuck(contact) && k.has(KernelId::ClosedLoopStickJacobian) {
            return k.has(KernelId::OutputRatesJacobian);
        }
        if self.model.is_stuck(contact) && !(self.model.mu0() > 0.0 && self.model.mu0().is_finite())
        {
            return false;
        }
        if self.model.is_active() {
            k.has(KernelId::ClosedLoopJacobian) && k.has(KernelId::OutputRatesJacobian)
        } else {
            k.has(KernelId::AccelJacobian)
        }
    }

    /// `d mu / d xd` of the tanh law at the foot's velocity `xd`.
    fn dmu(&self, xd: f64) -> f64 {
        let m = self.model;
        let cphi = m.phi().cos();
        let c = m.sharpness();
        let th = (c * xd / cphi).tanh();
        -m.mu0() * c / cphi * (1.0 - th * th)
    }

    /// `d [qdd, u]_i / d y_j` (`y = [q, qd]`, `2n` columns; `n + m` rows, the inputs' rows
    /// after the accelerations) at `(t, y)`, the chain rule through `mu(xd)` and `v(t, y)`
    /// applied, written row-major into `out` with row stride `2n`.
    ///
    /// # Errors
    /// As [`StanceJacobian::accel_with`] (only for a Coulomb model, which treats
    /// [`Contact::Smooth`] as stuck).
    pub fn accel(&self, t: f64, y: &[f64], out: &mut [f64]) -> Result<(), NoJacobian> {
        self.accel_in(t, y, Contact::Smooth, out)
    }

    /// [`StanceJacobian::accel`] in the contact `contact`: the smooth law's chain rule through
    /// `mu(xd)`; sliding under exact Coulomb friction `mu = -mu0 sigma` is constant (no `mu`
    /// term); stuck, the `n` rows of `qdd` from `stick_jacobian` (its rows of `x`, `z` are
    /// zero: the foot is held), or for a model with inputs the sliding rows at the held
    /// foot's friction ratio with `mu*`'s derivative eliminated (module documentation). The
    /// contact's kernels must exist ([`StanceJacobian::has_contact`]).
    ///
    /// # Errors
    /// As [`StanceJacobian::accel_with`].
    pub fn accel_in(
        &self,
        t: f64,
        y: &[f64],
        contact: Contact,
        out: &mut [f64],
    ) -> Result<(), NoJacobian> {
        self.accel_with(t, y, contact, out, &mut Scratch::new())
    }

    /// [`StanceJacobian::accel_in`] with the kernels' outputs in `scratch`: a caller that
    /// evaluates the Jacobian at every right-hand side (the variational equations) keeps one
    /// [`Scratch`] instead of zeroing a new one per call. The rows written are those `out`
    /// holds: `n` (the accelerations' only) or `n + m`. After a stuck contact of a model with
    /// inputs, `scratch` holds the sliding kernel's rows at the held foot's friction ratio (what
    /// a parameter's column eliminates the same way).
    ///
    /// # Errors
    /// [`NoJacobian::HeldRatioSingular`]: the foot of a model with inputs is held where its
    /// friction ratio has no derivative (`out` is then left as it was: never a NaN).
    pub fn accel_with(
        &self,
        t: f64,
        y: &[f64],
        contact: Contact,
        out: &mut [f64],
        scratch: &mut Scratch,
    ) -> Result<(), NoJacobian> {
        let m = self.model;
        let n = m.n();
        if m.is_stuck(contact) && m.inputs() == 0 {
            let k = &mut scratch.k;
            self.stick(y, &mut k[..(n + 2) * 2 * n]);
            out[..n * 2 * n].copy_from_slice(&k[..n * 2 * n]);
            return Ok(());
        }
        if m.is_stuck(contact) && m.kernels().has(KernelId::ClosedLoopStickJacobian) {
            self.held_stick_rows(t, y, out, scratch);
            Ok(())
        } else if m.is_stuck(contact) {
            self.held_rows(t, y, out, scratch).map(|_| ())
        } else {
            self.sliding_rows(
                t,
                y,
                contact.sigma(),
                contact != Contact::Smooth,
                out,
                scratch,
            );
            Ok(())
        }
    }

    /// The rows of [`StanceJacobian::accel_with`] for a sliding (or smooth, `sliding` false)
    /// contact at the kernel argument `sigma` (`mu = -mu0 sigma` under Coulomb friction).
    fn sliding_rows(
        &self,
        t: f64,
        y: &[f64],
        sigma: f64,
        sliding: bool,
        out: &mut [f64],
        scratch: &mut Scratch,
    ) {
        let m = self.model;
        let (n, inputs) = (m.n(), m.inputs());
        let (q, qd) = (&y[..n], &y[n..2 * n]);
        let Scratch { k, rates } = scratch;
        let cols = 2 * n + 1 + inputs;
        let dmu = if sliding { 0.0 } else { self.dmu(qd[0]) };
        if inputs == 0 {
            m.kernels().eval(
                KernelId::AccelJacobian,
                &Args {
                    sigma,
                    ..Args::state(q, qd)
                },
                &mut k[..n * cols],
            );
            for i in 0..n {
                let row = &k[i * cols..(i + 1) * cols];
                for j in 0..2 * n {
                    out[i * 2 * n + j] = row[j];
                }
                if !sliding {
                    out[i * 2 * n + n] = row[n] + row[2 * n] * dmu;
                }
            }
            return;
        }
        let v = self.inputs_at(t, y, rates);
        let gains = m.gains();
        let args = Args {
            v: &v[..inputs],
            sigma,
            ..Args::state(q, qd)
        };
        m.kernels().eval(
            KernelId::ClosedLoopJacobian,
            &args,
            &mut k[..(n + inputs) * cols],
        );
        // The rows the caller asks for: `n` (the accelerations) or `n + m` (with the inputs).
        let rows = (out.len() / (2 * n)).min(n + inputs);
        for i in 0..rows {
            let row = &k[i * cols..(i + 1) * cols];
            for j in 0..2 * n {
                let mut d = row[j];
                // Sliding under exact Coulomb friction, mu = -mu0 sigma does not depend on
                // the state.
                if !sliding {
                    if j == n {
                        d += row[2 * n] * dmu;
                    } else {
                        d += row[2 * n] * 0.0;
                    }
                }
                out[i * 2 * n + j] =
                    plus_through_v(d, &row[2 * n + 1..], rates, (n, inputs), gains, j);
            }
        }
    }

    /// The auxiliary inputs `v` at `(t, y)` (Eq. 32), with `output_rates_jacobian` (`d [y,
    /// yd] / d [q, qd]`, `2m x 2n`) evaluated into `rates` for [`plus_through_v`].
    fn inputs_at(&self, t: f64, y: &[f64], rates: &mut [f64]) -> [f64; MAX_COORDINATES] {
        let m = self.model;
        let (n, inputs) = (m.n(), m.inputs());
        let mut v = [0.0; MAX_COORDINATES];
        m.aux_inputs(t, y, &mut v[..inputs]);
        m.kernels().eval(
            KernelId::OutputRatesJacobian,
            &Args::state(&y[..n], &y[n..2 * n]),
            &mut rates[..2 * inputs * 2 * n],
        );
        v
    }

    /// `d [qdd, lambda_t, lambda_n] / d [q, qd]` of the stuck stance (`stick_jacobian`) at
    /// `y = [q, qd, ..]`, row-major with row stride `2n` (`n + 2` rows): the accelerations'
    /// rows, then the ground force's along and normal to the floor (the slip guard's gradient).
    pub fn stick(&self, y: &[f64], out: &mut [f64]) {
        let n = self.model.n();
        self.model.kernels().eval(
            KernelId::StickJacobian,
            &Args::state(&y[..n], &y[n..2 * n]),
            &mut out[..(n + 2) * 2 * n],
        );
    }

    /// Fills the stance system's Jacobian `jac` (`S = 2n + 1` components: the state and the
    /// power quadrature) at `(t, y)`: `d qd / d y` is the identity block, `d qdd / d y` comes
    /// from [`StanceJacobian::accel`], and the power row is `sum_i sign(u_i w_i) (w_i du_i/dy +
    /// u_i dw_i/dy)` while the power counts (zero after). Returns whether it was filled
    /// (`false` where [`StanceJacobian::accel`] fails).
    pub fn fill<const S: usize>(
        &self,
        t: f64,
        y: &[f64; S],
        contact: Contact,
        jac: &mut [[f64; S]; S],
    ) -> bool {
        let m = self.model;
        let (n, inputs) = (m.n(), m.inputs());
        let mut a = [0.0; 2 * MAX_COORDINATES * 2 * MAX_COORDINATES];
        if self.accel(t, y, &mut a[..(n + inputs) * 2 * n]).is_err() {
            return false;
        }
        for row in jac.iter_mut() {
            *row = [0.0; S];
        }
        for i in 0..n {
            jac[i][n + i] = 1.0;
            jac[n + i][..2 * n].copy_from_slice(&a[i * 2 * n..(i + 1) * 2 * n]);
        }
        if inputs > 0 && m.power_counts(t) {
            let u = m.control_input(t, y, contact);
            let mut w = [0.0; MAX_COORDINATES];
            let (q, qd) = (&y[..n], &y[n..2 * n]);
            m.kernels()
                .eval(KernelId::InputRates, &Args::state(q, qd), &mut w[..inputs]);
            let mut dw = [0.0; 2 * MAX_COORDINATES * MAX_COORDINATES];
            m.kernels().eval(
                KernelId::InputRatesJacobian,
                &Args::state(q, qd),
                &mut dw[..inputs * 2 * n],
            );
            for i in 0..inputs {
                let sign = (u[i] * w[i]).signum();
                for j in 0..2 * n {
                    let du = a[(n + i) * 2 * n + j];
                    jac[2 * n][j] += sign * (w[i] * du + u[i] * dw[i * 2 * n + j]);
                }
            }
        }
        true
    }

    /// `d qd+ / d [q, qd]` of the frictionless impact map at the pre-impact state `s`, row-major
    /// with row stride `2n`.
    pub fn impact(&self, s: &[f64], out: &mut [f64]) {
        let n = self.model.n();
        self.model.kernels().eval(
            KernelId::ImpactJacobian,
            &Args::state(&s[..n], &s[n..2 * n]),
            &mut out[..n * 2 * n],
        );
    }
}

/// `d + sum_k K_v,k d v_k / d y_j` for a kernel row's `v` columns `row_v` (`inputs` of them):
/// the chain rule through `d v_k / d y_j = -(K_P d y_k / d y_j) - K_D d yd_k / d y_j` (Eq. 32),
/// `rates` from [`StanceJacobian::inputs_at`] for a model of `n` coordinates, `gains` `(K_P,
/// K_D)`.
#[inline]
fn plus_through_v(
    mut d: f64,
    row_v: &[f64],
    rates: &[f64],
    (n, inputs): (usize, usize),
    (k_p, k_d): (f64, f64),
    j: usize,
) -> f64 {
    for kk in 0..inputs {
        let dy = rates[kk * 2 * n + j];
        let dyd = rates[(inputs + kk) * 2 * n + j];
        d += row_v[kk] * (-(k_p * dy) - k_d * dyd);
    }
    d
}
