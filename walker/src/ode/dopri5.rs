//! Dormand–Prince 5(4) with Shampine's 4th-order dense output.
//!
//! Coefficients as published in E. Hairer's `dopri5.f` (subroutine `CDOPRI`;
//! E. Hairer, S. P. Nørsett, G. Wanner, *Solving Ordinary Differential
//! Equations I*, 2nd ed., Springer 1993, Table II.5.2; dense output of
//! Shampine 1986, Sect. II.6). The method is FSAL: the seventh stage is
//! `f(t + h, y_new)` and becomes the first stage of the next step, so a step
//! costs six evaluations of the right-hand side, and the dense output costs
//! none.
// Stage formulas index the stage vectors explicitly, mirroring the
// published Fortran loops.
#![allow(clippy::needless_range_loop)]

use super::options::Tolerances;
use super::stats::Stats;
use super::stepper::{ControlKind, Dense, Stepper, error_norm, rhs};
use super::system::OdeSystem;

const C2: f64 = 0.2;
const C3: f64 = 0.3;
const C4: f64 = 0.8;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 0.2;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const A71: f64 = 35.0 / 384.0;
const A73: f64 = 500.0 / 1113.0;
const A74: f64 = 125.0 / 192.0;
const A75: f64 = -2187.0 / 6784.0;
const A76: f64 = 11.0 / 84.0;
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
// Dense output of Shampine (1986).
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// Stage storage and dense-output coefficients of DOPRI5.
#[derive(Clone)]
pub(crate) struct Dopri5<const N: usize> {
    k1: [f64; N],
    k2: [f64; N],
    k3: [f64; N],
    k4: [f64; N],
    k5: [f64; N],
    k6: [f64; N],
    k7: [f64; N],
    y_new: [f64; N],
    /// `CONT` of `dopri5.f`: `u(θ) = c0 + θ(c1 + θ'(c2 + θ(c3 + θ' c4)))`,
    /// `θ' = 1 - θ`.
    cont: [[f64; N]; 5],
}

impl<const N: usize> Dopri5<N> {
    pub(crate) fn new() -> Self {
        Self {
            k1: [0.0; N],
            k2: [0.0; N],
            k3: [0.0; N],
            k4: [0.0; N],
            k5: [0.0; N],
            k6: [0.0; N],
            k7: [0.0; N],
            y_new: [0.0; N],
            cont: [[0.0; N]; 5],
        }
    }
}

impl<const N: usize> Dense<N> for Dopri5<N> {
    fn eval(&self, theta: f64, out: &mut [f64; N]) {
        let th1 = 1.0 - theta;
        let [c0, c1, c2, c3, c4] = &self.cont;
        for i in 0..N {
            out[i] = c0[i] + theta * (c1[i] + th1 * (c2[i] + theta * (c3[i] + th1 * c4[i])));
        }
    }

    fn eval_dtheta(&self, theta: f64, out: &mut [f64; N]) {
        let th1 = 1.0 - theta;
        let [_, c1, c2, c3, c4] = &self.cont;
        for i in 0..N {
            let p = c3[i] + th1 * c4[i];
            let dp = -c4[i];
            let q = c2[i] + theta * p;
            let dq = p + theta * dp;
            let r = c1[i] + th1 * q;
            let dr = -q + th1 * dq;
            out[i] = r + theta * dr;
        }
    }
}

impl<const N: usize> Stepper<N> for Dopri5<N> {
    const HINIT_ORDER: i32 = 5;
    const CONTROL: ControlKind = ControlKind::Lund {
        base: 0.2,
        weight: 0.75,
    };

    fn start<S: OdeSystem<N>>(&mut self, sys: &mut S, t: f64, y: &[f64; N], stats: &mut Stats) {
        rhs(sys, stats, t, y, &mut self.k1);
    }

    fn f0(&self) -> &[f64; N] {
        &self.k1
    }

    fn attempt<S: OdeSystem<N>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &[f64; N],
        h: f64,
        tol: &Tolerances,
        stats: &mut Stats,
    ) -> f64 {
        let mut y1 = [0.0; N];
        for i in 0..N {
            y1[i] = y[i] + h * A21 * self.k1[i];
        }
        rhs(sys, stats, t + C2 * h, &y1, &mut self.k2);
        for i in 0..N {
            y1[i] = y[i] + h * (A31 * self.k1[i] + A32 * self.k2[i]);
        }
        rhs(sys, stats, t + C3 * h, &y1, &mut self.k3);
        for i in 0..N {
            y1[i] = y[i] + h * (A41 * self.k1[i] + A42 * self.k2[i] + A43 * self.k3[i]);
        }
        rhs(sys, stats, t + C4 * h, &y1, &mut self.k4);
        for i in 0..N {
            y1[i] = y[i]
                + h * (A51 * self.k1[i] + A52 * self.k2[i] + A53 * self.k3[i] + A54 * self.k4[i]);
        }
        rhs(sys, stats, t + C5 * h, &y1, &mut self.k5);
        for i in 0..N {
            y1[i] = y[i]
                + h * (A61 * self.k1[i]
                    + A62 * self.k2[i]
                    + A63 * self.k3[i]
                    + A64 * self.k4[i]
                    + A65 * self.k5[i]);
        }
        let tph = t + h;
        rhs(sys, stats, tph, &y1, &mut self.k6);
        for i in 0..N {
            self.y_new[i] = y[i]
                + h * (A71 * self.k1[i]
                    + A73 * self.k3[i]
                    + A74 * self.k4[i]
                    + A75 * self.k5[i]
                    + A76 * self.k6[i]);
        }
        rhs(sys, stats, tph, &self.y_new, &mut self.k7);
        // Error estimate (difference with the embedded 4th-order solution).
        let mut e = [0.0; N];
        for i in 0..N {
            e[i] = h
                * (E1 * self.k1[i]
                    + E3 * self.k3[i]
                    + E4 * self.k4[i]
                    + E5 * self.k5[i]
                    + E6 * self.k6[i]
                    + E7 * self.k7[i]);
        }
        let n = sys.controlled_components(t, y, tph, &self.y_new);
        error_norm(&e, y, &self.y_new, tol, n)
    }

    fn y_new(&self) -> &[f64; N] {
        &self.y_new
    }

    fn accept<S: OdeSystem<N>>(
        &mut self,
        _sys: &mut S,
        _t: f64,
        y: &[f64; N],
        h: f64,
        dense: bool,
        _stats: &mut Stats,
    ) {
        if dense {
            for i in 0..N {
                let ydiff = self.y_new[i] - y[i];
                let bspl = h * self.k1[i] - ydiff;
                self.cont[0][i] = y[i];
                self.cont[1][i] = ydiff;
                self.cont[2][i] = bspl;
                self.cont[3][i] = -h * self.k7[i] + ydiff - bspl;
                self.cont[4][i] = h
                    * (D1 * self.k1[i]
                        + D3 * self.k3[i]
                        + D4 * self.k4[i]
                        + D5 * self.k5[i]
                        + D6 * self.k6[i]
                        + D7 * self.k7[i]);
            }
        }
        // First same as last.
        self.k1 = self.k7;
    }
}
