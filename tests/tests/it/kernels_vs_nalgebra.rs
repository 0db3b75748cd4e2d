//! Every kernel of `general_level` / `general_slope` and of the Coulomb scenes
//! `general_level_coulomb` / `general_slope_coulomb` against the generic nalgebra path of
//! `walker_tests`, over wide random parameters and states (proptest); and the Coulomb sliding
//! kernels against the tanh ones where `tanh` saturates.
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
//!   `Y`, `A`, `B`, impacts, the impact with friction's `qdl`, `v`, `W`, `R`): the generic side is LU with partial pivoting on `n <= 7`, backward
//!   error `||dK|| <= gamma_{3n} rho ||K||` (`3n <= 21`, growth `rho <= 2` for these small
//!   KKT matrices) plus the rounding of the right-hand side (`b_abs` in the scale); the
//!   generated closed form's roundings act as relative perturbations of ~20 eps of the data
//!   (`M`, `J`, `h`, `mu` through `tanh`), covered by the same perturbation bound
//!   `||dx|| <= ||K^-1|| (||dK|| ||x|| + ||db||)`. Entrywise-to-2-norm conversion costs
//!   `sqrt(n) <= 3`: `(21 * 2 + 20) * 3 ~ 190 < 256`. Near a singular Schur complement
//!   (`J M^-1 Jhat^T -> 0`) `cond(K)` and the bound grow together; nothing is skipped.
//!   The stick phase is a 6x6 KKT system (`3n = 18`), inside the same argument. The closed
//!   loops compose a solve for `A`, `B`, the quotient `u = (v + B) / A` and a solve at that `u`:
//!   their scale ([`walker_tests::ClosedLoop`]) adds the first-order propagation of the errors
//!   of `A` and `B` through `u` (`(|v| + s_B + |u| s_A) / |A|`) and of `u` into the solution
//!   (`||x_S||` times that), each of those terms itself a `C_SOLVE`-type bound, so the same
//!   `C_SOLVE` covers the sum. Where `A -> 0` (the sliding loop at large `|mu|`) the scale
//!   grows as `1 / |A|^2`, again with the conditioning.
//!
//! Coulomb friction: the kernels take the sliding direction `sigma = ±1` and compute
//! `mu = -mu0 sigma`; a random `mu` is realised exactly with `mu0 = |mu|`, `sigma = -sign(mu)`
//! (one product with `±1`), so the generic path sees exactly the kernel's `mu`.
#![allow(clippy::unwrap_used, reason = "test code")]
#![allow(
    clippy::needless_range_loop,
    reason = "index i names the output component in messages"
)]

use nalgebra::Vector4;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use walker_tests::scenes::{
    general_level as gl, general_level_coulomb as glc, general_slope as gs,
    general_slope_coulomb as gsc,
};
use walker_tests::{Contact, EPS, Phys, cases, mu_law, xd_for_mu};

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
    check_fore_foot_energy(p, s, th1, ff, en)
}

/// `fore_foot` and `energy` (the kernels without a solve) against the generic expressions.
fn check_fore_foot_energy(
    p: &Phys,
    s: &State,
    th1: f64,
    ff: [f64; 4],
    en: [f64; 2],
) -> Result<(), TestCaseError> {
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

/// `impact_coulomb_level` / `impact_coulomb_slope` (`qdl`, `v`, `W`, `R`) against the generic
/// path ([`walker_tests::coulomb_ingredients`]: contact rows from the feet's Cartesian
/// Jacobians, `M_L^-1 J^T` by KKT solves), each output with its scale and `C_SOLVE` (the lock
/// and the columns are `n <= 5` KKT solves; `v` and `W` add one product with the rows, whose
/// rounding is within `||J|| ||X||` of the scale).
fn check_coulomb(
    name: &str,
    p: &Phys,
    th1: f64,
    s: &State,
    out: &[f64; 21],
) -> Result<(), TestCaseError> {
    let qd = Vector4::new(s.xd, s.zd, s.th1d, s.th2d);
    let lock = name == "impact_coulomb_level";
    let c = walker_tests::coulomb_ingredients(p, th1, qd, lock).map_err(TestCaseError::fail)?;
    let (v, sc) = walker_tests::coulomb_outputs(&c);
    const NAMES: [&str; 21] = [
        "qdl0", "qdl1", "qdl2", "qdl3", "v_t", "v_n", "v_r", "W_tt", "W_tn", "W_tr", "W_nn",
        "W_nr", "W_rr", "R00", "R01", "R10", "R11", "R20", "R21", "R30", "R31",
    ];
    for i in 0..21 {
        close(
            &format!("{name} {}", NAMES[i]),
            out[i],
            v[i],
            C_SOLVE,
            sc[i],
        )?;
    }
    // The slope has no lock: qdl is qd- itself.
    if !lock {
        prop_assert!(
            out[..4] == [s.xd, s.zd, s.th1d, s.th2d],
            "{name}: qdl != qd-"
        );
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

/// `(mu0, sigma)` of the Coulomb law that gives exactly the friction coefficient `mu`:
/// `mu = -mu0 sigma` with `mu0 = |mu|` and `sigma = -sign(mu)` (`+1` for `mu = 0`).
fn coulomb_for_mu(mu: f64) -> (f64, f64) {
    (mu.abs(), if mu > 0.0 { -1.0 } else { 1.0 })
}

/// The stick kernel's outputs `[qdd0..3, lambda_t, lambda_n]` against the generic stick solve.
fn check_stick(name: &str, out: &[f64; 6], st: &walker_tests::Stick) -> Result<(), TestCaseError> {
    let tag = format!("(cond {:e})", st.cond);
    for i in 0..4 {
        close(
            &format!("{name} qdd{i} {tag}"),
            out[i],
            st.qdd[i],
            C_SOLVE,
            st.scale,
        )?;
    }
    // The foot does not move: exactly, in the generated code.
    prop_assert!(
        out[0] == 0.0 && out[1] == 0.0,
        "{name}: xdd, zdd = {}, {}",
        out[0],
        out[1]
    );
    close(
        &format!("{name} lambda_t {tag}"),
        out[4],
        st.lambda[0],
        C_SOLVE,
        st.scale,
    )?;
    close(
        &format!("{name} lambda_n {tag}"),
        out[5],
        st.lambda[1],
        C_SOLVE,
        st.scale,
    )?;
    Ok(())
}

/// A closed-loop kernel's outputs `[qdd0..3, u]` (`closed_loop_level`) or `[qdd0..3, u,
/// lambda_t, lambda_n]` (`closed_loop_stick_level`) against the generic closed loop.
fn check_closed_loop(
    name: &str,
    out: &[f64],
    cl: &walker_tests::ClosedLoop,
) -> Result<(), TestCaseError> {
    let tag = format!("(cond {:e}, A {:e})", cl.cond, cl.a);
    for i in 0..4 {
        close(
            &format!("{name} qdd{i} {tag}"),
            out[i],
            cl.qdd[i],
            C_SOLVE,
            cl.scale,
        )?;
    }
    close(
        &format!("{name} u {tag}"),
        out[4],
        cl.u,
        C_SOLVE,
        cl.scale_u,
    )?;
    for (k, got) in out.iter().enumerate().skip(5) {
        let lam = cl.lambda.get(k - 5).copied().unwrap_or(f64::NAN);
        close(
            &format!("{name} lambda[{}] {tag}", k - 5),
            *got,
            lam,
            C_SOLVE,
            cl.scale,
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
        check_coulomb("impact_coulomb_level", &p, th1, &s, &gl::impact_coulomb_level(&k, th1, s.xd, s.zd, s.th1d, s.th2d))?;
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
        check_coulomb("impact_coulomb_slope", &p, th1, &s, &gs::impact_coulomb_slope(&k, th1, s.xd, s.zd, s.th1d, s.th2d))?;
    }

    #[test]
    fn general_level_coulomb_matches_generic(p in phys(false), s in state()) {
        let (mu0, sigma) = coulomb_for_mu(s.mu);
        let k = p.level_coulomb_kernels(mu0, (0.5, 1.0, 1.0));
        let th1 = s.th1_frac * (p.alpha / 2.0 + 0.3);
        let mu = -mu0 * sigma;
        prop_assert!(mu == s.mu || (mu == 0.0 && s.mu == 0.0));
        // v of the closed loops: the state's u (same range).
        let v = s.u;

        let ff = glc::fore_foot(&k, s.x, s.z, th1, s.xd, s.zd, s.th1d);
        let en = glc::energy(&k, s.z, th1, s.xd, s.zd, s.th1d, s.th2d);
        check_fore_foot_energy(&p, &s, th1, ff, en)?;

        // Sliding in direction sigma.
        let st = walker_tests::stance(&p, th1, s.th1d, s.u, mu).map_err(TestCaseError::fail)?;
        let tag = format!("(cond {:e})", st.cond);
        close(&format!("lambda_level {tag}"), glc::lambda_level(&k, th1, s.th1d, s.u, sigma), st.lambda_eq22, C_SOLVE, st.scale)?;
        let qdd = glc::accel_level(&k, th1, s.th1d, s.u, sigma);
        for i in 0..4 {
            close(&format!("accel_level qdd{i} {tag}"), qdd[i], st.qdd[i], C_SOLVE, st.scale)?;
        }
        let [a, b, sa, sb] = walker_tests::control(&p, th1, s.th1d, mu).map_err(TestCaseError::fail)?;
        let ab = glc::control_level(&k, th1, s.th1d, sigma);
        close(&format!("A {tag}"), ab[0], a, C_SOLVE, sa)?;
        close(&format!("B {tag}"), ab[1], b, C_SOLVE, sb)?;
        let cl = walker_tests::closed_loop(&p, th1, s.th1d, v, Contact::Slide(mu)).map_err(TestCaseError::fail)?;
        check_closed_loop("closed_loop_level", &glc::closed_loop_level(&k, th1, s.th1d, sigma, v), &cl)?;

        // Stuck.
        let st = walker_tests::stick(&p, th1, s.th1d, s.u).map_err(TestCaseError::fail)?;
        check_stick("stick_level", &glc::stick_level(&k, th1, s.th1d, s.u), &st)?;
        let cl = walker_tests::closed_loop(&p, th1, s.th1d, v, Contact::Stick).map_err(TestCaseError::fail)?;
        let out = glc::closed_loop_stick_level(&k, th1, s.th1d, v);
        check_closed_loop("closed_loop_stick_level", &out, &cl)?;
        prop_assert!(out[0] == 0.0 && out[1] == 0.0);

        check_impact("impact3_level", &p, th1, &s, &glc::impact3_level(&k, th1, s.xd, s.zd, s.th1d, s.th2d))?;
        check_impact("impact2_level", &p, th1, &s, &glc::impact2_level(&k, th1, s.xd, s.zd, s.th1d, s.th2d))?;
        check_coulomb("impact_coulomb_level", &p, th1, &s, &glc::impact_coulomb_level(&k, th1, s.xd, s.zd, s.th1d, s.th2d))?;
    }

    #[test]
    fn general_slope_coulomb_matches_generic(p in phys(true), s in state()) {
        let (mu0, sigma) = coulomb_for_mu(s.mu);
        let k = p.slope_coulomb_kernels(mu0);
        let th1 = s.th1_frac * (p.alpha / 2.0 + 0.3);
        let mu = -mu0 * sigma;

        let ff = gsc::fore_foot(&k, s.x, s.z, th1, s.xd, s.zd, s.th1d);
        let en = gsc::energy(&k, s.z, th1, s.xd, s.zd, s.th1d, s.th2d);
        check_fore_foot_energy(&p, &s, th1, ff, en)?;

        // The passive wheel: u = 0.
        let st = walker_tests::stance(&p, th1, s.th1d, 0.0, mu).map_err(TestCaseError::fail)?;
        let tag = format!("(cond {:e})", st.cond);
        close(&format!("lambda_slope {tag}"), gsc::lambda_slope(&k, th1, s.th1d, sigma), st.lambda_eq22, C_SOLVE, st.scale)?;
        let qdd = gsc::accel_slope(&k, th1, s.th1d, sigma);
        for i in 0..4 {
            close(&format!("accel_slope qdd{i} {tag}"), qdd[i], st.qdd[i], C_SOLVE, st.scale)?;
        }
        let st = walker_tests::stick(&p, th1, s.th1d, 0.0).map_err(TestCaseError::fail)?;
        check_stick("stick_slope", &gsc::stick_slope(&k, th1, s.th1d), &st)?;

        check_impact("impact_slope", &p, th1, &s, &gsc::impact_slope(&k, th1, s.xd, s.zd, s.th1d, s.th2d))?;
        check_impact("impact2_slope", &p, th1, &s, &gsc::impact2_slope(&k, th1, s.xd, s.zd, s.th1d, s.th2d))?;
        check_coulomb("impact_coulomb_slope", &p, th1, &s, &gsc::impact_coulomb_slope(&k, th1, s.xd, s.zd, s.th1d, s.th2d))?;
    }

    /// Where `tanh` saturates, the tanh law is the Coulomb law: `tanh(c xd)` with `c xd = ±40`
    /// rounds to exactly `±1` (`1 - tanh 40 = 3.6e-35`, below half an ulp of 1), so the tanh
    /// scene at `xd = 40 sigma / c` (`40 sigma cos phi / c` on the slope, Eq. 37) and the
    /// Coulomb scene at `sigma` have the same `mu = -mu0 sigma` in `f64` (asserted) and
    /// evaluate the same rational function there: the values agree to the rounding of the two
    /// evaluations, each within `C_SOLVE eps s` of the exact value, so within
    /// `2 C_SOLVE eps s`.
    #[test]
    fn coulomb_sliding_kernels_are_the_saturated_tanh_kernels(
        p in phys(false), slope_phi in 0.0f64..0.5, s in state(), forward in proptest::bool::ANY,
    ) {
        prop_assert_eq!(40f64.tanh(), 1.0);
        let sigma: f64 = if forward { 1.0 } else { -1.0 };
        let mu0 = s.mu.abs();
        let mu = -mu0 * sigma;
        let th1 = s.th1_frac * (p.alpha / 2.0 + 0.3);
        let v = s.u;
        // Level: c = 1, xd = 40 sigma.
        let kt = p.level_kernels((mu0, C_LAW), (0.5, 1.0, 1.0));
        let kc = p.level_coulomb_kernels(mu0, (0.5, 1.0, 1.0));
        let xd = 40.0 * sigma / C_LAW;
        prop_assert_eq!(mu_law(mu0, C_LAW, 0.0, xd), mu);
        let st = walker_tests::stance(&p, th1, s.th1d, s.u, mu).map_err(TestCaseError::fail)?;
        let c2 = 2.0 * C_SOLVE;
        close("lambda_level", gl::lambda_level(&kt, th1, s.th1d, s.u, xd), glc::lambda_level(&kc, th1, s.th1d, s.u, sigma), c2, st.scale)?;
        let (qt, qc) = (gl::accel_level(&kt, th1, s.th1d, s.u, xd), glc::accel_level(&kc, th1, s.th1d, s.u, sigma));
        for i in 0..4 {
            close(&format!("accel_level qdd{i}"), qt[i], qc[i], c2, st.scale)?;
        }
        let [_, _, sa, sb] = walker_tests::control(&p, th1, s.th1d, mu).map_err(TestCaseError::fail)?;
        let (at, ac) = (gl::control_level(&kt, th1, s.th1d, xd), glc::control_level(&kc, th1, s.th1d, sigma));
        close("A", at[0], ac[0], c2, sa)?;
        close("B", at[1], ac[1], c2, sb)?;
        let cl = walker_tests::closed_loop(&p, th1, s.th1d, v, Contact::Slide(mu)).map_err(TestCaseError::fail)?;
        let (ct, cc) = (gl::closed_loop_level(&kt, th1, s.th1d, xd, v), glc::closed_loop_level(&kc, th1, s.th1d, sigma, v));
        for i in 0..4 {
            close(&format!("closed_loop_level qdd{i}"), ct[i], cc[i], c2, cl.scale)?;
        }
        close("closed_loop_level u", ct[4], cc[4], c2, cl.scale_u)?;
        // Slope: xd = 40 sigma cos(phi) / c, so that c xd / cos phi = 40 sigma up to rounding.
        let ps = Phys { phi: slope_phi, ..p };
        let kt = ps.slope_kernels((mu0, C_LAW));
        let kc = ps.slope_coulomb_kernels(mu0);
        let xd = 40.0 * sigma * slope_phi.cos() / C_LAW;
        prop_assert_eq!(mu_law(mu0, C_LAW, slope_phi, xd), mu);
        let st = walker_tests::stance(&ps, th1, s.th1d, 0.0, mu).map_err(TestCaseError::fail)?;
        close("lambda_slope", gs::lambda_slope(&kt, th1, s.th1d, xd), gsc::lambda_slope(&kc, th1, s.th1d, sigma), c2, st.scale)?;
        let (qt, qc) = (gs::accel_slope(&kt, th1, s.th1d, xd), gsc::accel_slope(&kc, th1, s.th1d, sigma));
        for i in 0..4 {
            close(&format!("accel_slope qdd{i}"), qt[i], qc[i], c2, st.scale)?;
        }
    }
}
