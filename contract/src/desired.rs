//! The desired output trajectories `y_d(t)` of the output-following control (Section 3.2,
//! generalised to the model's outputs) and the auxiliary input `v` of Eq. 32.
//!
//! The paper's ramp is the quintic from `-alpha/2` to `alpha/2` in `T_set`,
//! `y_d = alpha (6 s^5 - 15 s^4 + 10 s^3) - alpha/2` with `s = t / T_set`, then held; a model
//! file writes it `{ shape = "quintic", from = "-alpha/2", to = "alpha/2", duration = "T_set" }`
//! and may give any ends and duration, or hold a constant. The time `t` is reset to zero at
//! every impact. The quintic has zero first and second derivatives at both ends (the
//! derivation checks these boundary conditions symbolically).

use walker_scene::model::{Desired as DesiredSpec, MAX_BEZIER_POINTS};

/// A desired trajectory, evaluated for one set of parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Desired {
    /// The quintic ramp (with its coefficients computed once: it is evaluated at every
    /// right-hand side of an actuated walker).
    Quintic(Ramp),
    /// A constant.
    Hold(f64),
    /// A Bezier polynomial in time, then held at its last point.
    Bezier(Bezier),
}

impl Desired {
    /// The trajectory `spec` with its expressions evaluated by `eval`.
    pub fn new(spec: &DesiredSpec, eval: impl Fn(&walker_scene::model::ModelExpr) -> f64) -> Self {
        match spec {
            DesiredSpec::Quintic { from, to, duration } => {
                Desired::Quintic(Ramp::new(eval(from), eval(to), eval(duration)))
            }
            DesiredSpec::Hold { value } => Desired::Hold(eval(value)),
            DesiredSpec::Bezier { points, duration } => {
                let a: Vec<f64> = points.iter().map(&eval).collect();
                Desired::Bezier(Bezier::new(&a, eval(duration)))
            }
        }
    }

    /// `[y_d, yd_d, ydd_d]` at time `t` since the last impact.
    #[inline]
    #[must_use]
    pub fn at(&self, t: f64) -> [f64; 3] {
        match self {
            Desired::Quintic(r) => r.at(t),
            Desired::Hold(v) => [*v, 0.0, 0.0],
            Desired::Bezier(b) => b.at(t),
        }
    }

    /// `d [y_d, yd_d, ydd_d] / dp` at time `t` for a parameter `p` that moves this
    /// trajectory's values at the rates `rate` (the same shape, its values the derivatives in
    /// `p` of this one's: `from`, `to`, the points or the constant, and the duration). `None`
    /// where the shapes differ.
    ///
    /// The values enter linearly at a fixed duration `T`, so their part is the trajectory of
    /// the rates over `T`; the duration scales time, `y_d(t) = Y(t / T)`, so its part is
    /// `-(dT / T) [t yd_d, t ydd_d + yd_d, t yddd_d + 2 ydd_d]` before the ramp's end and zero
    /// after it (the switch itself moves with `T`: a breakpoint whose time has the rate `dT`).
    #[must_use]
    pub fn rate(&self, rate: &Desired, t: f64) -> Option<[f64; 3]> {
        let (values, duration, d_duration, jerk) = match (self, rate) {
            (Desired::Hold(_), Desired::Hold(dv)) => return Some([*dv, 0.0, 0.0]),
            (Desired::Quintic(r), Desired::Quintic(dr)) => (
                Ramp::new(dr.from, dr.to, r.duration).at(t),
                r.duration,
                dr.duration,
                r.jerk(t),
            ),
            (Desired::Bezier(b), Desired::Bezier(db)) if b.len == db.len => (
                Bezier::new(&db.points[..db.len], b.duration).at(t),
                b.duration,
                db.duration,
                b.jerk(t),
            ),
            _ => return None,
        };
        if t >= duration || d_duration == 0.0 {
            return Some(values);
        }
        let [_, yd, ydd] = self.at(t);
        let k = d_duration / duration;
        Some([
            values[0] - k * t * yd,
            values[1] - k * (t * ydd + yd),
            values[2] - k * (t * jerk + 2.0 * ydd),
        ])
    }

    /// The end of the ramp (`None` for a constant): the control switches there, so it is a
    /// breakpoint of the integration.
    #[must_use]
    pub fn ramp_end(&self) -> Option<f64> {
        match self {
            Desired::Quintic(r) => Some(r.duration),
            Desired::Hold(_) => None,
            Desired::Bezier(b) => Some(b.duration),
        }
    }

    /// Whether the trajectory is finite at `t` (a ramp so short that `60 (to - from) /
    /// duration^2` overflows is NaN at `t = 0`).
    #[must_use]
    pub fn is_finite_at(&self, t: f64) -> bool {
        self.at(t).iter().all(|v| v.is_finite())
    }
}

/// The quintic ramp from `from` at `t = 0` to `to` at `t = duration`, then held.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ramp {
    from: f64,
    to: f64,
    duration: f64,
    /// `to - from`.
    span: f64,
    inv_duration: f64,
    /// `30 (to - from) / duration`, the scale of `yd_d`.
    c1: f64,
    /// `60 (to - from) / duration^2`, the scale of `ydd_d`.
    c2: f64,
}

impl Ramp {
    /// The ramp from `from` to `to` in `duration`.
    #[must_use]
    pub fn new(from: f64, to: f64, duration: f64) -> Self {
        let span = to - from;
        Self {
            from,
            to,
            duration,
            span,
            inv_duration: 1.0 / duration,
            c1: 30.0 * span / duration,
            c2: 60.0 * span / (duration * duration),
        }
    }

    /// `[y_d, yd_d, ydd_d]` at time `t` since the last impact: with `s = t / duration` and
    /// `a = to - from`, `y_d = a s^3 (10 - 15 s + 6 s^2) + from`,
    /// `yd_d = (30 a / duration) s^2 (1 - s)^2`,
    /// `ydd_d = (60 a / duration^2) s (1 - s) (1 - 2 s)`; `[to, 0, 0]` from `duration` on.
    #[inline]
    #[must_use]
    pub fn at(&self, t: f64) -> [f64; 3] {
        if t >= self.duration {
            return [self.to, 0.0, 0.0];
        }
        let s = t.max(0.0) * self.inv_duration;
        let s2 = s * s;
        let s3 = s2 * s;
        let y = self.span * s3 * (10.0 + s * (-15.0 + 6.0 * s)) + self.from;
        let yd = self.c1 * s2 * (1.0 - 2.0 * s + s2);
        let ydd = self.c2 * s * (1.0 - 3.0 * s + 2.0 * s2);
        [y, yd, ydd]
    }

    /// The third derivative `yddd_d = (60 a / duration^3) (1 - 6 s + 6 s^2)` at `t` (zero from
    /// `duration` on): what the derivative in the duration needs ([`Desired::rate`]).
    #[must_use]
    pub fn jerk(&self, t: f64) -> f64 {
        if t >= self.duration {
            return 0.0;
        }
        let s = t.max(0.0) * self.inv_duration;
        self.c2 * self.inv_duration * (1.0 - 6.0 * s + 6.0 * s * s)
    }
}

/// A Bezier polynomial of order `M` (`M + 1` control points `a_k`, at most
/// [`MAX_BEZIER_POINTS`]) in `s = t / duration`: `y_d = sum_k a_k B_k^M(s)` with the Bernstein
/// basis `B_k^M(s) = C(M, k) s^k (1 - s)^(M - k)`, then held at `a_M` from `duration` on. The
/// derivatives are the Bezier polynomials of the differences: `yd_d = (M / duration) sum_k
/// (a_{k+1} - a_k) B_k^{M-1}(s)`, `ydd_d = (M (M - 1) / duration^2) sum_k (a_{k+2} - 2 a_{k+1}
/// + a_k) B_k^{M-2}(s)`, each evaluated by de Casteljau's algorithm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bezier {
    /// The control points (the first `len` used).
    points: [f64; MAX_BEZIER_POINTS],
    /// `M + 1`.
    len: usize,
    duration: f64,
    inv_duration: f64,
}

impl Bezier {
    /// The Bezier with control points `points` (2 to [`MAX_BEZIER_POINTS`]; more are ignored,
    /// which the model file's check rules out) over `duration`.
    #[must_use]
    pub fn new(points: &[f64], duration: f64) -> Self {
        let len = points.len().clamp(1, MAX_BEZIER_POINTS);
        let mut p = [0.0; MAX_BEZIER_POINTS];
        p[..len].copy_from_slice(&points[..len]);
        Self {
            points: p,
            len,
            duration,
            inv_duration: 1.0 / duration,
        }
    }

    /// `[y_d, yd_d, ydd_d]` at time `t` since the last impact; `[a_M, 0, 0]` from `duration`
    /// on.
    ///
    /// Never inlined: inlined into [`Desired::at`], its loops made the auxiliary input too large
    /// to be inlined into the generated stance right-hand side, and the paper's quintic walk
    /// (which never takes this branch) then took 217.3 M instructions instead of 209.7 M
    /// (`valgrind --tool=callgrind`, BENCHMARKS section 9).
    #[inline(never)]
    #[must_use]
    pub fn at(&self, t: f64) -> [f64; 3] {
        let n = self.len;
        if t >= self.duration {
            return [self.points[n - 1], 0.0, 0.0];
        }
        let s = t.max(0.0) * self.inv_duration;
        let m = (n - 1) as f64;
        let p = &self.points;
        let mut d1 = [0.0; MAX_BEZIER_POINTS];
        let mut d2 = [0.0; MAX_BEZIER_POINTS];
        for k in 0..n - 1 {
            d1[k] = p[k + 1] - p[k];
        }
        for k in 0..n.saturating_sub(2) {
            d2[k] = d1[k + 1] - d1[k];
        }
        let inv = self.inv_duration;
        [
            casteljau(&p[..n], s),
            m * inv * casteljau(&d1[..n - 1], s),
            m * (m - 1.0) * inv * inv * casteljau(&d2[..n.saturating_sub(2)], s),
        ]
    }
}

impl Bezier {
    /// The third derivative `yddd_d = (M (M - 1) (M - 2) / duration^3) sum_k (third
    /// difference of the points)_k B_k^{M-3}(s)` at `t` (zero from `duration` on, and for an
    /// order below 3): what the derivative in the duration needs ([`Desired::rate`]).
    #[must_use]
    pub fn jerk(&self, t: f64) -> f64 {
        let n = self.len;
        if t >= self.duration || n < 4 {
            return 0.0;
        }
        let s = t.max(0.0) * self.inv_duration;
        let mut d = self.points;
        for r in 1..=3 {
            for k in 0..n - r {
                d[k] = d[k + 1] - d[k];
            }
        }
        let m = (n - 1) as f64;
        let inv = self.inv_duration;
        m * (m - 1.0) * (m - 2.0) * inv * inv * inv * casteljau(&d[..n - 3], s)
    }
}

/// The Bezier polynomial with control points `c` at `s` by de Casteljau's algorithm (0 for no
/// points).
#[inline]
fn casteljau(c: &[f64], s: f64) -> f64 {
    let mut b = [0.0; MAX_BEZIER_POINTS];
    let n = c.len();
    if n == 0 {
        return 0.0;
    }
    b[..n].copy_from_slice(c);
    for r in 1..n {
        for k in 0..n - r {
            b[k] = (1.0 - s) * b[k] + s * b[k + 1];
        }
    }
    b[0]
}

/// The auxiliary input `v = ydd_d + K_D (yd_d - ydot) + K_P (y_d - y)` (Eq. 32).
#[inline]
#[must_use]
pub fn aux_input(desired: [f64; 3], y: f64, ydot: f64, k_p: f64, k_d: f64) -> f64 {
    desired[2] + k_d * (desired[1] - ydot) + k_p * (desired[0] - y)
}

#[cfg(test)]
mod tests {
    use super::Ramp;

    /// `rate` is the derivative in a parameter: for the quintic and a Bezier whose values and
    /// duration all move with `p`, against central differences of the trajectories built at
    /// `p +- h` (`h = 1e-5`: truncation about `h^2` times the third derivative in `p`, rounding
    /// about `1e-16 / h`; both below `1e-8` of the scales the test divides by), at times
    /// before and after the ramp's end.
    #[test]
    fn rate_is_the_derivative_in_a_parameter() {
        use super::Desired;
        // p moves from, to, the points and the duration (T = 0.3 + 0.2 p).
        let quintic = |p: f64| Desired::Quintic(Ramp::new(-0.2 - p, 0.3 + 2.0 * p, 0.3 + 0.2 * p));
        let bezier = |p: f64| {
            Desired::Bezier(super::Bezier::new(
                &[-0.2, 0.1 * p, 0.4 - p, 0.2, 0.5 + p * p, 0.3],
                0.3 + 0.2 * p,
            ))
        };
        let rates = [
            Desired::Quintic(Ramp::new(-1.0, 2.0, 0.2)),
            Desired::Bezier(super::Bezier::new(
                &[0.0, 0.1, -1.0, 0.0, 2.0 * 0.7, 0.0],
                0.2,
            )),
        ];
        let (p, h) = (0.7, 1e-5);
        for (traj, rate) in [
            (&quintic as &dyn Fn(f64) -> Desired, rates[0]),
            (&bezier, rates[1]),
        ] {
            for k in 0..=24 {
                let t = 0.5 * f64::from(k) / 24.0;
                let (up, down) = (traj(p + h).at(t), traj(p - h).at(t));
                let exact = traj(p).rate(&rate, t).expect("same shape");
                for i in 0..3 {
                    let fd = (up[i] - down[i]) / (2.0 * h);
                    let scale = 1.0 + up[i].abs().max(fd.abs());
                    // A time within h of the moving ramp's end is not differentiable there.
                    if (t - (0.3 + 0.2 * p)).abs() > 1e-3 {
                        assert!(
                            (exact[i] - fd).abs() < 1e-6 * scale,
                            "t = {t}, {i}: {exact:?} {fd}"
                        );
                    }
                }
            }
        }
    }

    /// The paper's boundary conditions (Section 3.2): `y_d(0) = -alpha/2`, `y_d(T_set) =
    /// alpha/2`, both derivatives zero at both ends; the derivatives are those of `y_d`
    /// (central differences, step 1e-6: truncation about 1e-12 times the third derivative,
    /// rounding about 1e-16 / 1e-6 = 1e-10 times the values).
    #[test]
    fn the_papers_ramp_meets_its_boundary_conditions() {
        let (a, ts) = (0.5, 0.3);
        let r = Ramp::new(-a / 2.0, a / 2.0, ts);
        let d0 = r.at(0.0);
        assert!((d0[0] + a / 2.0).abs() < 1e-15 && d0[1] == 0.0 && d0[2] == 0.0);
        let d1 = r.at(ts * (1.0 - 1e-12));
        assert!((d1[0] - a / 2.0).abs() < 1e-10);
        assert!(d1[1].abs() < 1e-9 && d1[2].abs() < 1e-8);
        assert_eq!(r.at(ts), [a / 2.0, 0.0, 0.0]);
        let (t, e) = (0.1, 1e-6);
        let (dp, dm, d) = (r.at(t + e), r.at(t - e), r.at(t));
        assert!(((dp[0] - dm[0]) / (2.0 * e) - d[1]).abs() < 1e-6);
        assert!(((dp[1] - dm[1]) / (2.0 * e) - d[2]).abs() < 1e-5);
    }

    /// The paper's quintic is the Bezier of order 5 with the points `from` three times and
    /// `to` three times (`10 s^3 - 15 s^4 + 6 s^5 = B_3 + B_4 + B_5`): the same values and
    /// derivatives to rounding (1e-12 relative to the scales `a`, `30 a / T`, `60 a / T^2`:
    /// a few ulps of sums of terms of those sizes).
    #[test]
    fn the_quintic_is_a_bezier_of_order_five() {
        let (a, ts) = (0.5235987755982988, 0.3);
        let r = Ramp::new(-a / 2.0, a / 2.0, ts);
        let b = super::Bezier::new(
            &[-a / 2.0, -a / 2.0, -a / 2.0, a / 2.0, a / 2.0, a / 2.0],
            ts,
        );
        for k in 0..=40 {
            let t = ts * 1.1 * f64::from(k) / 40.0;
            let (x, y) = (r.at(t), b.at(t));
            let scale = [a, 30.0 * a / ts, 60.0 * a / (ts * ts)];
            for i in 0..3 {
                assert!(
                    (x[i] - y[i]).abs() <= 1e-12 * scale[i],
                    "t = {t}, {i}: {x:?} {y:?}"
                );
            }
        }
    }

    /// A Bezier of order 1 is the straight line between its points, with the constant slope
    /// and no curvature.
    #[test]
    fn a_bezier_of_order_one_is_a_line() {
        let b = super::Bezier::new(&[1.0, 3.0], 2.0);
        assert_eq!(b.at(0.0), [1.0, 1.0, 0.0]);
        assert_eq!(b.at(1.0), [2.0, 1.0, 0.0]);
        assert_eq!(b.at(2.0), [3.0, 0.0, 0.0]);
    }

    /// A ramp between any two values is the paper's shape shifted and scaled.
    #[test]
    fn a_ramp_is_the_unit_ramp_scaled() {
        let unit = Ramp::new(0.0, 1.0, 2.0);
        let r = Ramp::new(3.0, -1.0, 2.0);
        for k in 0..=20 {
            let t = 0.1 * f64::from(k);
            let (u, v) = (unit.at(t), r.at(t));
            assert!((v[0] - (3.0 - 4.0 * u[0])).abs() < 1e-14, "{t}");
            assert!((v[1] + 4.0 * u[1]).abs() < 1e-13 && (v[2] + 4.0 * u[2]).abs() < 1e-12);
        }
    }
}
