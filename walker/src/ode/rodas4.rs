//! RODAS: a stiffly accurate, L-stable Rosenbrock method of order 4(3) with
//! 3rd-order dense output.
//!
//! Coefficients as published in E. Hairer's `rodas.f` (subroutine `RODCOE`,
//! `METH = 1`), described in E. Hairer, G. Wanner, *Solving Ordinary
//! Differential Equations II*, 2nd ed., Springer 1996, Sect. IV.7. The stage
//! equations are written in Hairer's transformed variables: with
//! `E = I / (h γ) - J`,
//!
//! ```text
//! E k_i = f(t + c_i h, y + Σ_{j<i} a_ij k_j) + Σ_{j<i} (c_ij / h) k_j + h d_i f_t
//! ```
//!
//! and `y_new = y + Σ a_6j k_j + k_6`, the embedded solution being
//! `y + Σ a_5j k_j + k_5`, so `k_6` is the error estimate. The Jacobian `J`
//! and `f_t = df/dt` are computed once per accepted step (they are reused
//! after a rejection; only the LU factorisation is redone with the new `h`).
//! An attempted step costs five evaluations of the right-hand side and one
//! LU factorisation; an accepted one in addition `f(t + h, y_new)` for the
//! next step and the Jacobian (analytic, or `N` evaluations by finite
//! differences) and `df/dt` (analytic, or one evaluation).
// Literals keep the published digits; stage formulas index the stage
// vectors explicitly, mirroring the published Fortran loops.
#![allow(clippy::excessive_precision, clippy::needless_range_loop)]

use super::control::UROUND;
use super::linalg::Lu;
use super::options::Tolerances;
use super::stats::Stats;
use super::stepper::{ControlKind, Dense, Stepper, error_norm, rhs};
use super::system::OdeSystem;

const C2: f64 = 0.386;
const C3: f64 = 0.21;
const C4: f64 = 0.63;
const D1: f64 = 0.2500000000000000e+00;
const D2: f64 = -0.1043000000000000e+00;
const D3: f64 = 0.1035000000000000e+00;
const D4: f64 = -0.3620000000000023e-01;
const A21: f64 = 0.1544000000000000e+01;
const A31: f64 = 0.9466785280815826e+00;
const A32: f64 = 0.2557011698983284e+00;
const A41: f64 = 0.3314825187068521e+01;
const A42: f64 = 0.2896124015972201e+01;
const A43: f64 = 0.9986419139977817e+00;
const A51: f64 = 0.1221224509226641e+01;
const A52: f64 = 0.6019134481288629e+01;
const A53: f64 = 0.1253708332932087e+02;
const A54: f64 = -0.6878860361058950e+00;
const C21: f64 = -0.5668800000000000e+01;
const C31: f64 = -0.2430093356833875e+01;
const C32: f64 = -0.2063599157091915e+00;
const C41: f64 = -0.1073529058151375e+00;
const C42: f64 = -0.9594562251023355e+01;
const C43: f64 = -0.2047028614809616e+02;
const C51: f64 = 0.7496443313967647e+01;
const C52: f64 = -0.1024680431464352e+02;
const C53: f64 = -0.3399990352819905e+02;
const C54: f64 = 0.1170890893206160e+02;
const C61: f64 = 0.8083246795921522e+01;
const C62: f64 = -0.7981132988064893e+01;
const C63: f64 = -0.3152159432874371e+02;
const C64: f64 = 0.1631930543123136e+02;
const C65: f64 = -0.6058818238834054e+01;
const GAMMA: f64 = 0.2500000000000000e+00;
const D21: f64 = 0.1012623508344586e+02;
const D22: f64 = -0.7487995877610167e+01;
const D23: f64 = -0.3480091861555747e+02;
const D24: f64 = -0.7992771707568823e+01;
const D25: f64 = 0.1025137723295662e+01;
const D31: f64 = -0.6762803392801253e+00;
const D32: f64 = 0.6087714651680015e+01;
const D33: f64 = 0.1643084320892478e+02;
const D34: f64 = 0.2476722511418386e+02;
const D35: f64 = -0.6594389125716872e+01;

/// Work space of RODAS.
#[derive(Clone)]
pub(crate) struct Rodas4<const N: usize> {
    /// `f(t, y)` at the start of the step (`DY1`).
    f0: [f64; N],
    /// `df/dt` at the start of the step (`FX`).
    ft: [f64; N],
    jac: [[f64; N]; N],
    /// Whether `jac` and `ft` belong to the current step start.
    jac_current: bool,
    lu: Lu<N>,
    k: [[f64; N]; 6],
    y_new: [f64; N],
    /// `u(s) = c0 (1 - s) + s (c1 + (1 - s)(c2 + s c3))` (`CONTRO`).
    cont: [[f64; N]; 4],
}

impl<const N: usize> Rodas4<N> {
    pub(crate) fn new() -> Self {
        Self {
            f0: [0.0; N],
            ft: [0.0; N],
            jac: [[0.0; N]; N],
            jac_current: false,
            lu: Lu::new(),
            k: [[0.0; N]; 6],
            y_new: [0.0; N],
            cont: [[0.0; N]; 4],
        }
    }

    /// Jacobian and `df/dt` at `(t, y)`, analytic when the system provides
    /// them, else by forward differences as in Hairer's codes.
    fn update_jacobian<S: OdeSystem<N>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &[f64; N],
        h: f64,
        stats: &mut Stats,
    ) {
        if sys.jacobian(t, y, &mut self.jac) {
            stats.jacobian_evals += 1;
        } else {
            stats.fd_jacobians += 1;
            let mut yp = *y;
            let mut fp = [0.0; N];
            for j in 0..N {
                let ysafe = yp[j];
                yp[j] = ysafe + (UROUND * ysafe.abs().max(1.0e-5)).sqrt();
                // The increment actually applied (exact in floating point).
                let delt = yp[j] - ysafe;
                rhs(sys, stats, t, &yp, &mut fp);
                for i in 0..N {
                    self.jac[i][j] = (fp[i] - self.f0[i]) / delt;
                }
                yp[j] = ysafe;
            }
        }
        if !sys.time_derivative(t, y, &mut self.ft) {
            // Hairer uses sqrt(eps * max(1e-5, |t|)), which is far too small
            // near t = 0 (the rounding error of the difference quotient then
            // dominates and spoils the order). Scale the increment with the
            // larger of |t| and the step size instead, and make it exactly
            // representable as a difference of times.
            let scale = t.abs().max(h.abs());
            let delt = if scale > 0.0 {
                UROUND.sqrt() * scale
            } else {
                UROUND.sqrt()
            };
            let delt = (t + delt) - t;
            let mut fp = [0.0; N];
            rhs(sys, stats, t + delt, y, &mut fp);
            for i in 0..N {
                self.ft[i] = (fp[i] - self.f0[i]) / delt;
            }
        }
        self.jac_current = true;
    }
}

impl<const N: usize> Dense<N> for Rodas4<N> {
    fn eval(&self, s: f64, out: &mut [f64; N]) {
        let s1 = 1.0 - s;
        let [c0, c1, c2, c3] = &self.cont;
        for i in 0..N {
            out[i] = c0[i] * s1 + s * (c1[i] + s1 * (c2[i] + s * c3[i]));
        }
    }

    fn eval_dtheta(&self, s: f64, out: &mut [f64; N]) {
        let s1 = 1.0 - s;
        let [c0, c1, c2, c3] = &self.cont;
        for i in 0..N {
            let a = c2[i] + s * c3[i];
            let b = c1[i] + s1 * a;
            let db = -a + s1 * c3[i];
            out[i] = -c0[i] + b + s * db;
        }
    }
}

impl<const N: usize> Stepper<N> for Rodas4<N> {
    const HINIT_ORDER: i32 = 4;
    const CONTROL: ControlKind = ControlKind::Predictive { exponent: 0.25 };

    fn start<S: OdeSystem<N>>(&mut self, sys: &mut S, t: f64, y: &[f64; N], stats: &mut Stats) {
        rhs(sys, stats, t, y, &mut self.f0);
        self.jac_current = false;
    }

    fn f0(&self) -> &[f64; N] {
        &self.f0
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
        if !self.jac_current {
            self.update_jacobian(sys, t, y, h, stats);
        }
        stats.lu_decompositions += 1;
        if self
            .lu
            .factor_shifted(1.0 / (h * GAMMA), &self.jac)
            .is_err()
        {
            // Singular (or non-finite) iteration matrix: report a failed
            // attempt; the driver reduces the step size.
            return f64::NAN;
        }
        let ft = &self.ft;
        let lu = &self.lu;
        let k = &mut self.k;
        let mut ak = [0.0; N];
        let mut dy = [0.0; N];

        // Stage 1.
        for i in 0..N {
            k[0][i] = self.f0[i] + h * D1 * ft[i];
        }
        lu.solve(&mut k[0]);
        // Stage 2.
        for i in 0..N {
            ak[i] = y[i] + A21 * k[0][i];
        }
        rhs(sys, stats, t + C2 * h, &ak, &mut dy);
        for i in 0..N {
            k[1][i] = dy[i] + h * D2 * ft[i] + (C21 / h) * k[0][i];
        }
        lu.solve(&mut k[1]);
        // Stage 3.
        for i in 0..N {
            ak[i] = y[i] + A31 * k[0][i] + A32 * k[1][i];
        }
        rhs(sys, stats, t + C3 * h, &ak, &mut dy);
        for i in 0..N {
            k[2][i] = dy[i] + h * D3 * ft[i] + ((C31 / h) * k[0][i] + (C32 / h) * k[1][i]);
        }
        lu.solve(&mut k[2]);
        // Stage 4.
        for i in 0..N {
            ak[i] = y[i] + A41 * k[0][i] + A42 * k[1][i] + A43 * k[2][i];
        }
        rhs(sys, stats, t + C4 * h, &ak, &mut dy);
        for i in 0..N {
            k[3][i] = dy[i]
                + h * D4 * ft[i]
                + ((C41 / h) * k[0][i] + (C42 / h) * k[1][i] + (C43 / h) * k[2][i]);
        }
        lu.solve(&mut k[3]);
        // Stage 5 (at t + h; no f_t term since d_5 = 0).
        for i in 0..N {
            ak[i] = y[i] + A51 * k[0][i] + A52 * k[1][i] + A53 * k[2][i] + A54 * k[3][i];
        }
        rhs(sys, stats, t + h, &ak, &mut dy);
        for i in 0..N {
            k[4][i] = dy[i]
                + ((C51 / h) * k[0][i]
                    + (C52 / h) * k[1][i]
                    + (C53 / h) * k[2][i]
                    + (C54 / h) * k[3][i]);
        }
        lu.solve(&mut k[4]);
        // Embedded solution, then stage 6.
        for i in 0..N {
            ak[i] += k[4][i];
        }
        rhs(sys, stats, t + h, &ak, &mut dy);
        for i in 0..N {
            k[5][i] = dy[i]
                + (C61 * k[0][i] + C62 * k[1][i] + C63 * k[2][i] + C64 * k[3][i] + C65 * k[4][i])
                    / h;
        }
        lu.solve(&mut k[5]);
        // New solution; k6 is the difference to the embedded one.
        for i in 0..N {
            self.y_new[i] = ak[i] + k[5][i];
        }
        let n = sys.controlled_components(t, y, t + h, &self.y_new);
        error_norm(&k[5], y, &self.y_new, tol, n)
    }

    fn y_new(&self) -> &[f64; N] {
        &self.y_new
    }

    fn accept<S: OdeSystem<N>>(
        &mut self,
        sys: &mut S,
        t: f64,
        y: &[f64; N],
        h: f64,
        dense: bool,
        stats: &mut Stats,
    ) {
        if dense {
            let k = &self.k;
            for i in 0..N {
                self.cont[0][i] = y[i];
                self.cont[1][i] = self.y_new[i];
                self.cont[2][i] =
                    D21 * k[0][i] + D22 * k[1][i] + D23 * k[2][i] + D24 * k[3][i] + D25 * k[4][i];
                self.cont[3][i] =
                    D31 * k[0][i] + D32 * k[1][i] + D33 * k[2][i] + D34 * k[3][i] + D35 * k[4][i];
            }
        }
        let y_new = self.y_new;
        rhs(sys, stats, t + h, &y_new, &mut self.f0);
        self.jac_current = false;
    }
}
