//! The desired output trajectory `y_d(t)` of the output-following control (paper Section 3.2)
//! and the auxiliary input `v` of Eq. 32.
//!
//! `y_d` is the quintic `alpha (6 s^5 - 15 s^4 + 10 s^3) - alpha/2` with `s = t / T_set` for
//! `0 <= t < T_set`, and `alpha/2` afterwards; it goes from `-alpha/2` to `alpha/2` with zero first
//! and second derivatives at both ends (the derivation checks these boundary conditions
//! symbolically). The time `t` is reset to zero at every impact.

/// `[y_d, yd_d, ydd_d]` at time `t` since the last impact (Section 3.2).
pub fn desired(alpha: f64, t_set: f64, t: f64) -> [f64; 3] {
    Ramp::new(alpha, t_set).at(t)
}

/// The ramp `y_d` of Section 3.2 for one `alpha` and `T_set`, with its coefficients computed
/// once (it is evaluated at every right-hand side of the active walker).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ramp {
    alpha: f64,
    t_set: f64,
    inv_t_set: f64,
    /// `30 alpha / T_set`, the scale of `yd_d`.
    c1: f64,
    /// `60 alpha / T_set^2`, the scale of `ydd_d`.
    c2: f64,
}

impl Ramp {
    /// The ramp from `-alpha/2` to `alpha/2` in `T_set`.
    pub fn new(alpha: f64, t_set: f64) -> Self {
        Self {
            alpha,
            t_set,
            inv_t_set: 1.0 / t_set,
            c1: 30.0 * alpha / t_set,
            c2: 60.0 * alpha / (t_set * t_set),
        }
    }

    /// `[y_d, yd_d, ydd_d]` at time `t` since the last impact: with `s = t / T_set`,
    /// `y_d = alpha s^3 (10 - 15 s + 6 s^2) - alpha/2`, `yd_d = (30 alpha / T_set) s^2 (1 - s)^2`,
    /// `ydd_d = (60 alpha / T_set^2) s (1 - s) (1 - 2 s)`; `[alpha/2, 0, 0]` from `T_set` on.
    pub fn at(&self, t: f64) -> [f64; 3] {
        if t >= self.t_set {
            return [0.5 * self.alpha, 0.0, 0.0];
        }
        let s = t.max(0.0) * self.inv_t_set;
        let s2 = s * s;
        let s3 = s2 * s;
        let y = self.alpha * s3 * (10.0 + s * (-15.0 + 6.0 * s)) - 0.5 * self.alpha;
        let yd = self.c1 * s2 * (1.0 - 2.0 * s + s2);
        let ydd = self.c2 * s * (1.0 - 3.0 * s + 2.0 * s2);
        [y, yd, ydd]
    }
}

/// The auxiliary input `v = ydd_d + K_D (yd_d - ydot) + K_P (y_d - y)` (Eq. 32).
pub fn aux_input(desired: [f64; 3], y: f64, ydot: f64, k_p: f64, k_d: f64) -> f64 {
    desired[2] + k_d * (desired[1] - ydot) + k_p * (desired[0] - y)
}

#[cfg(test)]
mod tests {
    use super::desired;

    #[test]
    fn boundary_conditions() {
        let a = 0.5;
        let ts = 0.3;
        let d0 = desired(a, ts, 0.0);
        assert!((d0[0] + a / 2.0).abs() < 1e-15 && d0[1] == 0.0 && d0[2] == 0.0);
        let d1 = desired(a, ts, ts * (1.0 - 1e-12));
        assert!((d1[0] - a / 2.0).abs() < 1e-10);
        assert!(d1[1].abs() < 1e-9 && d1[2].abs() < 1e-8);
        // derivatives against central differences
        let t = 0.1;
        let e = 1e-6;
        let dp = desired(a, ts, t + e);
        let dm = desired(a, ts, t - e);
        let d = desired(a, ts, t);
        assert!(((dp[0] - dm[0]) / (2.0 * e) - d[1]).abs() < 1e-6);
        assert!(((dp[1] - dm[1]) / (2.0 * e) - d[2]).abs() < 1e-5);
    }
}
