//! How a run-time parameter `p` moves the stance field, the section and the strike
//! ([`ParameterRates`]): what the Poincare map's exact parameter column needs
//! ([`super::parameter_column`]).
//!
//! The model's kernels differentiate the stance in the state, in the friction coefficient `mu`
//! and in the auxiliary inputs `v` (`jacobian.rs`), not in the model's parameters. A parameter
//! that enters the walker only through those, through the friction law `mu(xd)` (`mu0`, the
//! tanh law's `c`), the desired trajectories, the gains of Eq. 32 and the section's given
//! components, has its derivative of the field by the chain rule:
//!
//! `d qdd / dp = (d qdd / d mu) (d mu / dp) + sum_k (d qdd / d v_k) (d v_k / dp)`, with
//! `d v_k / dp = d ydd_d / dp + K_D d yd_d / dp + K_P d y_d / dp + (dK_P / dp) (y_d - y) +
//! (dK_D / dp) (yd_d - ydot)` (`Desired::rate`).
//!
//! A parameter in the mechanics (a mass, a length, the slope, gravity, an output's `h(q)`, the
//! strike guard, the impact's locks) has no such column: [`ParameterRates::of`] says so and the
//! caller differences the map.

use std::collections::BTreeSet;

use walker_contract::Desired;
use walker_scene::model::{FallCondition, ModelExpr};

use crate::model::{Contact, KernelId, Model};
use crate::vector::MAX_COORDINATES;

/// The derivatives in one run-time parameter `p` of what it moves (module documentation).
#[derive(Clone, Debug)]
pub(crate) struct ParameterRates {
    /// `d mu0 / dp`.
    pub(crate) d_mu0: f64,
    /// `d c / dp` (the tanh law's sharpness).
    d_c: f64,
    /// `(d K_P / dp, d K_D / dp)`.
    d_gains: (f64, f64),
    /// The desired trajectories' rates (`Desired::rate`), in output order.
    desired: Vec<Desired>,
    /// Whether any desired trajectory moves with `p`.
    moves_desired: bool,
}

impl ParameterRates {
    /// The rates of the parameter `name` of `model`; `None` where it is not a parameter or
    /// enters the mechanics (module documentation).
    #[must_use]
    pub(crate) fn of(model: &Model, name: &str) -> Option<ParameterRates> {
        let spec = model.spec();
        let index = spec.parameter(name)?;
        if mechanical_symbols(spec).contains(name) {
            return None;
        }
        let values = model.params().values();
        let is = |i: Option<usize>| if i == Some(index) { 1.0 } else { 0.0 };
        let d_gains = spec
            .gains
            .map_or((0.0, 0.0), |(p, d)| (is(Some(p)), is(Some(d))));
        let rate = |e: &ModelExpr| {
            e.expr
                .derivative(name)
                .eval(&|s| spec.parameter(s).and_then(|i| values.get(i).copied()))
                .unwrap_or(f64::NAN)
        };
        let desired = spec
            .model
            .outputs
            .iter()
            .map(|o| Desired::new(&o.desired, rate))
            .collect();
        let moves_desired = spec.model.outputs.iter().any(|o| {
            desired_expressions(&o.desired)
                .iter()
                .any(|e| e.expr.symbols().iter().any(|(s, _)| *s == name))
        });
        Some(ParameterRates {
            d_mu0: is(spec.mu0),
            d_c: is(spec.c),
            d_gains,
            desired,
            moves_desired,
        })
    }

    /// `d qdd / dp` (`n` numbers into `out`) at `(t, y)` in the contact `contact`, from the
    /// stance Jacobian kernel's rows `k` (`n` rows or more of `2n + 1 + m` columns: the state,
    /// `mu`, the auxiliary inputs `v`). A passive walker's stuck field does not depend on `mu`
    /// (nor on anything else a parameter with a column moves): zero. A held foot of a model
    /// with inputs has the sliding field at the friction ratio `mu*(p)` that holds it (`k` the
    /// sliding kernel's rows there, as [`crate::jacobian::StanceJacobian::accel_with`] leaves
    /// them): the rate through `v` with `mu*`'s own rate eliminated, `b_i - (K_mu,i / K_mu,0)
    /// b_0` (row 0, the foot's, exactly zero); where the model has `closed_loop_stick_jacobian`
    /// (no closed forms), `k` is that kernel's rows and the rate is theirs through `v`.
    pub(crate) fn field_rate(
        &self,
        model: &Model,
        t: f64,
        y: &[f64],
        contact: Contact,
        k: &[f64],
        out: &mut [f64],
    ) {
        let (n, inputs) = (model.n(), model.inputs());
        out[..n].fill(0.0);
        let held = model.is_stuck(contact);
        if held && inputs == 0 {
            return;
        }
        let d_mu = match contact {
            _ if held => 0.0,
            Contact::Smooth => {
                let cphi = model.phi().cos();
                let (mu0, c, xd) = (model.mu0(), model.sharpness(), y[n]);
                let th = (c * xd / cphi).tanh();
                -self.d_mu0 * th - self.d_c * mu0 * (1.0 - th * th) * xd / cphi
            }
            _ => -self.d_mu0 * contact.sigma(),
        };
        let mut d_v = [0.0; MAX_COORDINATES];
        self.input_rates(model, t, y, &mut d_v[..inputs]);
        if held && model.kernels().has(KernelId::ClosedLoopStickJacobian) {
            // `k` holds `closed_loop_stick_jacobian` (columns `[q, qd, v]`): the held field's
            // own rate through `v`, no friction ratio to eliminate.
            let cols = 2 * n + inputs;
            for (i, o) in out[..n].iter_mut().enumerate() {
                let row = &k[i * cols + 2 * n..(i + 1) * cols];
                *o = row.iter().zip(&d_v[..inputs]).map(|(a, b)| a * b).sum();
            }
            return;
        }
        let cols = 2 * n + 1 + inputs;
        for (i, o) in out[..n].iter_mut().enumerate() {
            let row = &k[i * cols..(i + 1) * cols];
            let mut d = row[2 * n] * d_mu;
            for (kk, dv) in d_v[..inputs].iter().enumerate() {
                d += row[2 * n + 1 + kk] * dv;
            }
            *o = d;
        }
        if held {
            let (pivot, b0) = (k[2 * n], out[0]);
            for (i, o) in out[..n].iter_mut().enumerate() {
                *o -= k[i * cols + 2 * n] / pivot * b0;
            }
        }
    }

    /// `d mu*/dp` of the friction ratio that holds the foot of a model with inputs at `(t, y)`,
    /// from the sliding kernel's rows `k` at `mu*` (as [`ParameterRates::field_rate`]): `-b_0 /
    /// K_mu,0`, `b_0` the foot's acceleration's rate through `v`. The slip guard's rate in `p`
    /// is then `lambda_n (sign(mu*) d mu*/dp - d mu0/dp)`, on the scale of its gradient
    /// `lambda_n sign(mu*) d mu*/dy`.
    pub(crate) fn held_ratio_rate(&self, model: &Model, t: f64, y: &[f64], k: &[f64]) -> f64 {
        let (n, inputs) = (model.n(), model.inputs());
        let mut d_v = [0.0; MAX_COORDINATES];
        self.input_rates(model, t, y, &mut d_v[..inputs]);
        let mut b0 = 0.0;
        for (kk, dv) in d_v[..inputs].iter().enumerate() {
            b0 += k[2 * n + 1 + kk] * dv;
        }
        -b0 / k[2 * n]
    }

    /// `d v_k / dp` at `(t, y)` (`m` numbers into `out`; module documentation).
    fn input_rates(&self, model: &Model, t: f64, y: &[f64], out: &mut [f64]) {
        let inputs = out.len();
        if inputs == 0 {
            return;
        }
        let (k_p, k_d) = model.gains();
        if self.moves_desired {
            for (i, dv) in out.iter_mut().enumerate() {
                let desired = model.desired_trajectory(i);
                let r = desired.rate(&self.desired[i], t).unwrap_or([f64::NAN; 3]);
                *dv = r[2] + k_d * r[1] + k_p * r[0];
            }
        }
        if self.d_gains != (0.0, 0.0) {
            let mut rates = [0.0; 2 * MAX_COORDINATES];
            model.output_rates(y, &mut rates[..2 * inputs]);
            for (i, dv) in out.iter_mut().enumerate() {
                let [y_d, yd_d, _] = model.desired(i, t);
                *dv +=
                    self.d_gains.0 * (y_d - rates[i]) + self.d_gains.1 * (yd_d - rates[inputs + i]);
            }
        }
    }

    /// The rate of the breakpoint at `tb` (the end of the ramps that end there: `d T / dp` of
    /// their duration); `None` where no ramp ends at `tb`, or ramps ending together move at
    /// different rates (their switches would part).
    pub(crate) fn breakpoint_rate(&self, model: &Model, tb: f64) -> Option<f64> {
        let mut rate: Option<f64> = None;
        for (i, r) in self.desired.iter().enumerate() {
            if model.desired_trajectory(i).ramp_end() != Some(tb) {
                continue;
            }
            let d = r.ramp_end().unwrap_or(0.0);
            match rate {
                Some(x) if x != d => return None,
                _ => rate = Some(d),
            }
        }
        rate
    }
}

/// The expressions of a desired trajectory.
fn desired_expressions(d: &walker_scene::model::Desired) -> Vec<&ModelExpr> {
    use walker_scene::model::Desired as Spec;
    match d {
        Spec::Quintic { from, to, duration } => vec![from, to, duration],
        Spec::Hold { value } => vec![value],
        Spec::Bezier { points, duration } => points.iter().chain([duration]).collect(),
    }
}

/// The parameters the model's mechanics use: the floor's, every body's, point's, fall's,
/// relabelling's, lock's, input force's and output's `h(q)`, and the strike guard's.
fn mechanical_symbols(spec: &crate::model::Spec) -> BTreeSet<String> {
    let file = &spec.model;
    let mut exprs: Vec<&ModelExpr> = Vec::new();
    for b in &file.bodies {
        exprs.push(&b.mass);
        exprs.extend(&b.com);
        if let Some((inertia, angle)) = &b.rotation {
            exprs.extend([inertia, angle]);
        }
    }
    for p in &file.points {
        exprs.extend(&p.at);
    }
    exprs.extend(&file.strike.guard);
    for f in &file.falls {
        if let FallCondition::Guard(e) = &f.condition {
            exprs.push(e);
        }
    }
    exprs.extend(file.relabel.iter().map(|r| &r.value));
    exprs.extend(&file.impact.locks);
    for i in &file.inputs {
        exprs.extend(&i.force);
    }
    exprs.extend(file.outputs.iter().map(|o| &o.h));
    let mut out: BTreeSet<String> = exprs
        .iter()
        .flat_map(|e| e.expr.symbols())
        .map(|(s, _)| s.to_owned())
        .collect();
    out.insert(file.floor.gravity.name.clone());
    if let Some(s) = &file.floor.slope {
        out.insert(s.name.clone());
    }
    out
}
