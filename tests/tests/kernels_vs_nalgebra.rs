//! Every kernel of `general_level` / `general_slope` against the generic nalgebra path of
//! `walker_tests`, over wide random parameters and states (proptest).
//!
//! Case count: `walker_tests::cases()` (256 by default; `PROPTEST_CASES=N` replaces 256 and
//! `WALKER_LONG_TESTS=1` multiplies by `walker_tests::LONG_FACTOR`).
//!
//! Tolerances (`|generated - generic| <= C * eps * s`, `s` the error scale the generic path
//! returns next to each value):
//!
//! - `C_DIRECT = 32` for the direct formulas (`mass_matrix`, `bias`, `fore_foot`, `energy`):
//!   each output is a sum of at most ~6 products of at most ~4 factors (sin/cos within 1 ulp,
//!   parameter constants folded by `prepare` with at most ~5 roundings); the classical bound
//!   of such an evaluation is `gamma_n * (absolute-value evaluation)` with `n <= ~12`, on both
//!   the generated and the generic side: `2 * 12 < 32`.
//! - `C_SOLVE = 256` for everything obtained from a linear system (reactions, accelerations,
//!   `Y`, `A`, `B`, impacts): the generic side is LU with partial pivoting on `n <= 7`, backward
//!   error `||dK|| <= gamma_{3n} rho ||K||` (`3n <= 21`, growth `rho <= 2` for these small
//!   KKT matrices) plus the rounding of the right-hand side (`b_abs` in the scale); the
//!   generated closed form's roundings act as relative perturbations of ~20 eps of the data
//!   (`M`, `J`, `h`, `mu` through `tanh`), covered by the same perturbation bound
//!   `||dx|| <= ||K^-1|| (||dK|| ||x|| + ||db||)`. Entrywise-to-2-norm conversion costs
//!   `sqrt(n) <= 3`: `(21 * 2 + 20) * 3 ~ 190 < 256`. Near a singular Schur complement
//!   (`J M^-1 Jhat^T -> 0`) `cond(K)` and the bound grow together; nothing is skipped.
#![allow(clippy::unwrap_used, reason = "test code")]
#![allow(
    clippy::needless_range_loop,
    reason = "index i names the output component in messages"
)]

use nalgebra::Vector4;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use walker::kernels::{general_level as gl, general_slope as gs};
use walker_tests::{EPS, Phys, cases, mu_law, xd_for_mu};

const C_DIRECT: f64 = 32.0;
const C_SOLVE: f64 = 256.0;
/// `mu0` used to realise a given `mu` through the tanh law (`|mu| <= 2 < mu0`).
const MU0: f64 = 2.5;
/// `c` of the tanh law (any positive value; 1 keeps `xd` of order 1).
const C_LAW: f64 = 1.0;

fn level_params(p: &Phys) -> gl::Prepared {
    p.level_kernels((MU0, C_LAW), (0.5, 1.0, 1.0))
}

fn slope_params(p: &Phys) -> gs::Prepared {
    p.slope_kernels((MU0, C_LAW))
}

fn close(what: &str, gen_v: f64, generic: f64, c: f64, scale: f64) -> Result<(), TestCaseError> {
    let err = (gen_v - generic).abs();
    let bound = c * EPS * scale;
    prop_assert!(
        err <= bound,
        "{what}: generated {gen_v:e} generic {generic:e} |diff| {err:e} > bound {bound:e} \
         (C = {c}, scale {scale:e})"
    );
    Ok(())
}

fn log_uniform() -> impl Strategy<Value = f64> {
    (-2.0f64..2.0).prop_map(|e| 10f64.powf(e))
}

prop_compose! {
    fn phys(slope: bool)(
        m1 in log_uniform(), m2 in log_uniform(), i1 in log_uniform(), i2 in log_uniform(),
        l in 0.1f64..10.0, g in 1.0f64..20.0, alpha in 1e-3f64..2.5, phi in 0.0f64..0.5,
    ) -> Phys {
        Phys { m1, m2, l, i1, i2, g, alpha, phi: if slope { phi } else { 0.0 } }
    }
}

/// A state: `th1` within `[-alpha/2 - 0.3, alpha/2 + 0.3]` (as a fraction of the half
/// width), positions up to 10, velocities up to 50, `u` in `[-50, 50]`, `mu` in `[-2, 2]`.
#[derive(Debug, Clone, Copy)]
struct State {
    th1_frac: f64,
    x: f64,
    z: f64,
    xd: f64,
    zd: f64,
    th1d: f64,
    th2d: f64,
    u: f64,
    mu: f64,
}

prop_compose! {
    fn state()(
        th1_frac in -1.0f64..1.0, x in -10.0f64..10.0, z in -10.0f64..10.0,
        xd in -50.0f64..50.0, zd in -50.0f64..50.0, th1d in -50.0f64..50.0,
        th2d in -50.0f64..50.0, u in -50.0f64..50.0, mu in -2.0f64..2.0,
    ) -> State {
        State { th1_frac, x, z, xd, zd, th1d, th2d, u, mu }
    }
}

fn check_direct_common(
    p: &Phys,
    s: &State,
    th1: f64,
    mm: [[f64; 4]; 4],
    h: [f64; 4],
    ff: [f64; 4],
    en: [f64; 2],
) -> Result<(), TestCaseError> {
    let m = walker_tests::mass_matrix(p, th1);
    for i in 0..4 {
        for j in 0..4 {
            close(
                &format!("M{i}{j}"),
                mm[i][j],
                m[(i, j)],
                C_DIRECT,
                m[(i, j)].abs(),
            )?;
        }
    }
    let (hv, habs) = walker_tests::bias(p, th1, s.th1d);
    for i in 0..4 {
        close(&format!("h{i}"), h[i], hv[i], C_DIRECT, habs[i])?;
    }
    let (f, fabs) = walker_tests::fore_foot(p, s.x, s.z, th1, s.xd, s.zd, s.th1d);
    for i in 0..4 {
        close(&format!("fore_foot[{i}]"), ff[i], f[i], C_DIRECT, fabs[i])?;
    }
    let qd = Vector4::new(s.xd, s.zd, s.th1d, s.th2d);
    let (e, eabs) = walker_tests::energy(p, s.z, th1, qd);
    for i in 0..2 {
        close(&format!("energy[{i}]"), en[i], e[i], C_DIRECT, eabs[i])?;
    }
    Ok(())
}

fn check_impact(
    name: &str,
    p: &Phys,
    th1: f64,
    s: &State,
    out: &[f64],
) -> Result<(), TestCaseError> {
    let rows = walker_tests::impact_rows(name, p, th1);
    let qd = Vector4::new(s.xd, s.zd, s.th1d, s.th2d);
    let imp = walker_tests::impact(p, &rows, th1, qd).map_err(TestCaseError::fail)?;
    let n = rows.len();
    for (r, lam) in imp.lambda.iter().enumerate() {
        close(
            &format!("{name} lambdaI{r} (cond {:e})", imp.cond),
            out[r],
            *lam,
            C_SOLVE,
            imp.scale,
        )?;
    }
    for i in 0..4 {
        close(
            &format!("{name} qd+{i} (cond {:e})", imp.cond),
            out[n + i],
            imp.qd_plus[i],
            C_SOLVE,
            imp.scale,
        )?;
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn general_level_matches_generic(p in phys(false), s in state()) {
        let k = level_params(&p);
        let th1 = s.th1_frac * (p.alpha / 2.0 + 0.3);
        let xd_mu = xd_for_mu(s.mu, MU0, C_LAW, 0.0);
        // The generic path evaluates the same friction law at the same xd.
        let mu = mu_law(MU0, C_LAW, 0.0, xd_mu);

        check_direct_common(
            &p, &s, th1,
            gl::mass_matrix(&k, th1),
            gl::bias(&k, th1, s.th1d),
            gl::fore_foot(&k, s.x, s.z, th1, s.xd, s.zd, s.th1d),
            gl::energy(&k, s.z, th1, s.xd, s.zd, s.th1d, s.th2d),
        )?;

        let st = walker_tests::stance(&p, th1, s.th1d, s.u, mu).map_err(TestCaseError::fail)?;
        let tag = format!("(cond {:e})", st.cond);
        // Eq. 22 and the KKT solve are two generic routes to the same lambda.
        close(&format!("lambda eq22 vs kkt {tag}"), st.lambda_eq22, st.lambda_kkt, C_SOLVE, st.scale)?;
        close(&format!("lambda_level {tag}"), gl::lambda_level(&k, th1, s.th1d, s.u, xd_mu), st.lambda_eq22, C_SOLVE, st.scale)?;
        let qdd = gl::accel_level(&k, th1, s.th1d, s.u, xd_mu);
        for i in 0..4 {
            close(&format!("accel_level qdd{i} {tag}"), qdd[i], st.qdd[i], C_SOLVE, st.scale)?;
        }

        let (y, ys) = walker_tests::projection(&p, th1, mu).map_err(TestCaseError::fail)?;
        let yg = gl::projection_level(&k, th1, xd_mu);
        for i in 0..4 {
            for j in 0..4 {
                close(&format!("Y{i}{j} {tag}"), yg[i][j], y[(i, j)], C_SOLVE, ys)?;
            }
        }

        let [a, b, sa, sb] = walker_tests::control(&p, th1, s.th1d, mu).map_err(TestCaseError::fail)?;
        let ab = gl::control_level(&k, th1, s.th1d, xd_mu);
        close(&format!("A {tag}"), ab[0], a, C_SOLVE, sa)?;
        close(&format!("B {tag}"), ab[1], b, C_SOLVE, sb)?;

        check_impact("impact3_level", &p, th1, &s, &gl::impact3_level(&k, th1, s.xd, s.zd, s.th1d, s.th2d))?;
        check_impact("impact2_level", &p, th1, &s, &gl::impact2_level(&k, th1, s.xd, s.zd, s.th1d, s.th2d))?;
    }

    #[test]
    fn general_slope_matches_generic(p in phys(true), s in state()) {
        let k = slope_params(&p);
        let th1 = s.th1_frac * (p.alpha / 2.0 + 0.3);
        let xd_mu = xd_for_mu(s.mu, MU0, C_LAW, p.phi);
        let mu = mu_law(MU0, C_LAW, p.phi, xd_mu);

        check_direct_common(
            &p, &s, th1,
            gs::mass_matrix(&k, th1),
            gs::bias(&k, th1, s.th1d),
            gs::fore_foot(&k, s.x, s.z, th1, s.xd, s.zd, s.th1d),
            gs::energy(&k, s.z, th1, s.xd, s.zd, s.th1d, s.th2d),
        )?;

        // The passive wheel: u = 0.
        let st = walker_tests::stance(&p, th1, s.th1d, 0.0, mu).map_err(TestCaseError::fail)?;
        let tag = format!("(cond {:e})", st.cond);
        close(&format!("lambda eq22 vs kkt {tag}"), st.lambda_eq22, st.lambda_kkt, C_SOLVE, st.scale)?;
        close(&format!("lambda_slope {tag}"), gs::lambda_slope(&k, th1, s.th1d, xd_mu), st.lambda_eq22, C_SOLVE, st.scale)?;
        let qdd = gs::accel_slope(&k, th1, s.th1d, xd_mu);
        for i in 0..4 {
            close(&format!("accel_slope qdd{i} {tag}"), qdd[i], st.qdd[i], C_SOLVE, st.scale)?;
        }

        check_impact("impact_slope", &p, th1, &s, &gs::impact_slope(&k, th1, s.xd, s.zd, s.th1d, s.th2d))?;
        check_impact("impact2_slope", &p, th1, &s, &gs::impact2_slope(&k, th1, s.xd, s.zd, s.th1d, s.th2d))?;
    }
}
