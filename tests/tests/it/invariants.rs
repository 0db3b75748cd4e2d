//! Physical invariants checked with the generated kernels (`general_level`, `general_slope`).
//!
//! Tolerances use the error scales of `walker_tests` with `C = 256` (the constant of
//! `kernels_vs_nalgebra`, argued there): every quantity below is a fixed linear combination of
//! kernel outputs, so its error is bounded by the combination's absolute coefficients times the
//! kernels' bounds, plus the rounding of the combination itself.
#![allow(clippy::unwrap_used, reason = "test code")]

use nalgebra::Vector4;
use proptest::prelude::*;
use walker_tests::scenes::{general_level as gl, general_slope as gs};
use walker_tests::{EPS, Phys, cases};

const C: f64 = 256.0;

fn gl_prep(p: &Phys, mu0: f64) -> gl::Prepared {
    p.level_kernels((mu0, 1.0), (0.5, 1.0, 1.0))
}

fn gs_prep(p: &Phys, mu0: f64) -> gs::Prepared {
    p.slope_kernels((mu0, 1.0))
}

prop_compose! {
    fn phys(slope: bool)(
        m1 in 0.1f64..10.0, m2 in 0.1f64..10.0, i1 in 0.1f64..10.0, i2 in 0.1f64..10.0,
        l in 0.2f64..5.0, g in 1.0f64..20.0, alpha in 0.05f64..1.5, phi in 0.0f64..0.4,
    ) -> Phys {
        Phys { m1, m2, l, i1, i2, g, alpha, phi: if slope { phi } else { 0.0 } }
    }
}

/// One RK4 run of the frictionless stance (`u = 0`); returns the energy drift `|E(T) - E(0)|`.
fn rk4_drift(
    accel: &dyn Fn(f64, f64, f64) -> [f64; 4],
    energy: &dyn Fn(&[f64; 8]) -> f64,
    y0: [f64; 8],
    t_end: f64,
    steps: u32,
) -> f64 {
    let f = |y: &[f64; 8]| -> [f64; 8] {
        let a = accel(y[2], y[6], y[4]);
        [y[4], y[5], y[6], y[7], a[0], a[1], a[2], a[3]]
    };
    let dt = t_end / f64::from(steps);
    let mut y = y0;
    for _ in 0..steps {
        let k1 = f(&y);
        let add = |y: &[f64; 8], k: &[f64; 8], s: f64| -> [f64; 8] {
            std::array::from_fn(|i| y[i] + s * k[i])
        };
        let k2 = f(&add(&y, &k1, dt / 2.0));
        let k3 = f(&add(&y, &k2, dt / 2.0));
        let k4 = f(&add(&y, &k3, dt));
        y = std::array::from_fn(|i| y[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
    }
    (energy(&y) - energy(&y0)).abs()
}

/// Energy is conserved along the frictionless, unactuated stance (level: `mu0 = 0`, `u = 0`;
/// slope: `mu0 = 0`, passive). RK4 is fourth order: halving the step divides the drift by ~16;
/// asserted over `T = 0.3 s` (the wheel falls fast later, the drift then measures truncation
/// only): the drift at `dt = 1e-2` is below `1e-6` of the energy scale (~50 J) and either at the
/// rounding floor (`1e4 * eps * scale` over 60 steps) or at least 8 times the drift at `dt/2`.
#[test]
fn energy_conserved_along_frictionless_stance() {
    let p = Phys::table1(0.0);
    let kl = gl_prep(&p, 0.0);
    let ps = Phys::table1(0.1);
    let ks = gs_prep(&ps, 0.0);
    let level_acc = |th1: f64, th1d: f64, xd: f64| gl::accel_level(&kl, th1, th1d, 0.0, xd);
    let slope_acc = |th1: f64, th1d: f64, xd: f64| gs::accel_slope(&ks, th1, th1d, xd);
    let level_e = |y: &[f64; 8]| {
        let e = gl::energy(&kl, y[1], y[2], y[4], y[5], y[6], y[7]);
        e[0] + e[1]
    };
    let slope_e = |y: &[f64; 8]| {
        let e = gs::energy(&ks, y[1], y[2], y[4], y[5], y[6], y[7]);
        e[0] + e[1]
    };
    type Case<'a> = (
        &'a dyn Fn(f64, f64, f64) -> [f64; 4],
        &'a dyn Fn(&[f64; 8]) -> f64,
        [f64; 8],
    );
    let cases: [Case; 2] = [
        (
            &level_acc,
            &level_e,
            [0.0, 0.0, -0.2, 0.1, 0.3, 0.0, 1.2, -0.5],
        ),
        (
            &slope_acc,
            &slope_e,
            [0.0, 0.0, -0.2, 0.1, 0.3, -0.3 * 0.1f64.tan(), 1.2, -0.5],
        ),
    ];
    for (acc, e, y0) in cases {
        let scale = 50.0;
        let d1 = rk4_drift(acc, e, y0, 0.3, 30);
        let d2 = rk4_drift(acc, e, y0, 0.3, 60);
        println!("drift {d1:e} {d2:e}");
        assert!(d1 < 1e-6 * scale, "drift {d1:e}");
        assert!(
            d1 < 1e4 * EPS * scale || d1 > 8.0 * d2,
            "drift {d1:e} at dt, {d2:e} at dt/2: not fourth order"
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    /// Frictionless: d/dt of the horizontal momentum `m_t (xd + l cos th1 th1d)` is
    /// `m_t (xdd + l cos th1 th1dd - l sin th1 th1d^2) = 0` for any internal torque `u`.
    #[test]
    fn horizontal_momentum_conserved_without_friction(p in phys(false), f in -1.0f64..1.0, th1d in -20.0f64..20.0, u in -50.0f64..50.0, xd in -5.0f64..5.0) {
        let k = gl_prep(&p, 0.0);
        let th1 = f * (p.alpha / 2.0 + 0.3);
        let a = gl::accel_level(&k, th1, th1d, u, xd);
        let (s, c) = th1.sin_cos();
        let dp = a[0] + p.l * c * a[2] - p.l * s * th1d * th1d;
        let st = walker_tests::stance(&p, th1, th1d, u, 0.0).expect("stance");
        let tol = C * EPS * st.scale * (1.0 + p.l) + 4.0 * EPS * (a[0].abs() + p.l * a[2].abs() + p.l * th1d * th1d);
        prop_assert!(dp.abs() <= tol, "d/dt p_x / m_t = {dp:e} > {tol:e}");
    }

    /// After each impact the constraint rows hold: `J_I qd+ = 0` to the kernels' error.
    /// Angular momentum about the new contact point (the fore foot) is conserved by the impacts
    /// whose only external impulse acts at the fore foot: `impact2_level` (the torso lock is
    /// internal) and `impact_slope` (the passive wheel; the torso is decoupled and keeps
    /// `th2d`). Horizontal momentum is conserved by every level impact (vertical impulses), and
    /// the momentum along the slope by `impact_slope` (normal impulse).
    #[test]
    fn impact_invariants(slope in any::<bool>(), p0 in phys(true), f in -1.0f64..1.0, xd in -5.0f64..5.0, zd in -5.0f64..5.0, th1d in -10.0f64..10.0, th2d in -10.0f64..10.0) {
        let p = if slope { p0 } else { Phys { phi: 0.0, ..p0 } };
        let th1 = f * (p.alpha / 2.0 + p.phi + 0.2);
        let qd = Vector4::new(xd, zd, th1d, th2d);
        let q = Vector4::new(0.3, -0.3 * p.phi.tan(), th1, 0.1);
        let names: &[&str] = if slope { &["impact_slope", "impact2_slope"] } else { &["impact3_level", "impact2_level"] };
        for &name in names {
            let out: Vec<f64> = match name {
                "impact3_level" => gl::impact3_level(&gl_prep(&p, 0.3), th1, xd, zd, th1d, th2d).to_vec(),
                "impact2_level" => gl::impact2_level(&gl_prep(&p, 0.3), th1, xd, zd, th1d, th2d).to_vec(),
                "impact_slope" => gs::impact_slope(&gs_prep(&p, 0.3), th1, xd, zd, th1d, th2d).to_vec(),
                _ => gs::impact2_slope(&gs_prep(&p, 0.3), th1, xd, zd, th1d, th2d).to_vec(),
            };
            let rows = walker_tests::impact_rows(name, &p, th1);
            let n = rows.len();
            let qp = Vector4::new(out[n], out[n + 1], out[n + 2], out[n + 3]);
            let imp = walker_tests::impact(&p, &rows, th1, qd).expect("impact");
            let e = C * EPS * imp.scale;
            for (r, row) in rows.iter().enumerate() {
                let v = (row * qp)[0];
                let tol = row.abs().sum() * e + 4.0 * EPS * (row.abs() * qp.abs())[0];
                prop_assert!(v.abs() <= tol, "{name}: row {r}: J_I qd+ = {v:e} > {tol:e}");
            }
            if name == "impact2_level" || name == "impact_slope" {
                let k = gl_prep(&p, 0.0);
                let ff = gl::fore_foot(&k, q[0], q[1], th1, 0.0, 0.0, 0.0);
                let (px, pz) = (ff[0], ff[1]);
                let (xh, zh) = walker_tests::hip(&p, q[0], q[1], th1);
                let arm = (xh - px).abs() + (zh - pz).abs();
                let l0 = walker_tests::angular_momentum(&p, q, qd, px, pz);
                let l1 = walker_tests::angular_momentum(&p, q, qp, px, pz);
                let mt = p.mt();
                let lscale = mt * arm * (qd.abs().sum() + qp.abs().sum()) * (1.0 + p.l) + (p.i1 + p.i2) * (qd.abs().sum() + qp.abs().sum());
                let tol = (mt * arm * (2.0 + p.l) + p.i1 + p.i2) * e + 16.0 * EPS * lscale;
                prop_assert!((l1 - l0).abs() <= tol, "{name}: angular momentum {l0:e} -> {l1:e} (tol {tol:e})");
            }
            let (s, c) = th1.sin_cos();
            let mt = p.mt();
            let tang = |v: &Vector4<f64>| mt * ((v[0] + p.l * c * v[2]) * p.phi.cos() - (v[1] - p.l * s * v[2]) * p.phi.sin());
            if !slope || name == "impact_slope" {
                let tol = mt * (2.0 + p.l) * e + 8.0 * EPS * mt * (1.0 + p.l) * (qd.abs().sum() + qp.abs().sum());
                prop_assert!((tang(&qp) - tang(&qd)).abs() <= tol, "{name}: tangential momentum {:e} -> {:e}", tang(&qd), tang(&qp));
            }
        }
    }

    /// `Y` eliminates the reaction consistently with the constraint: `J M^-1 Y = 0`
    /// (`Y = I - Jhat^T (J M^-1 Jhat^T)^-1 J M^-1` gives `J M^-1 Y = J M^-1 - J M^-1 = 0`).
    #[test]
    fn projection_annihilated_by_constraint(p in phys(false), f in -1.0f64..1.0, mu in -2.0f64..2.0) {
        let k = gl::prepare(&gl::Params {
            m1: p.m1, m2: p.m2, l: p.l, i1: p.i1, i2: p.i2, g: p.g, alpha: p.alpha,
            mu0: 2.5, c: 1.0, t_set: 0.5, k_p: 1.0, k_d: 1.0,
        });
        let th1 = f * (p.alpha / 2.0 + 0.3);
        let xd = walker_tests::xd_for_mu(mu, 2.5, 1.0, 0.0);
        let yk = gl::projection_level(&k, th1, xd);
        let y = nalgebra::Matrix4::from_fn(|i, j| yk[i][j]);
        let mu_eff = walker_tests::mu_law(2.5, 1.0, 0.0, xd);
        let (_, ys) = walker_tests::projection(&p, th1, mu_eff).expect("projection");
        let jm = walker_tests::j_stance(0.0) * walker_tests::mass_matrix(&p, th1).try_inverse().expect("M invertible");
        let r = jm * y;
        // |J M^-1 dY| <= ||J M^-1|| * C eps s_Y, plus the rounding of the product and of M^-1.
        let tol = jm.norm() * (C * EPS * ys + 16.0 * EPS * y.norm());
        prop_assert!(r.norm() <= tol, "J M^-1 Y = {r} (tol {tol:e})");
    }
}
