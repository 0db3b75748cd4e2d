//! The Table 1 scenes give the general kernels' numbers at Table 1, and the frictionless scene
//! renders without `tanh`.
//!
//! Tolerance: the fixed scenes evaluate the same expressions with the parameter-only
//! subexpressions folded to constants at generation time (with libm) instead of computed by
//! `prepare` at run time, and with a possibly different Horner grouping of the folded terms.
//! Each folded constant differs from its run-time counterpart by at most a few roundings
//! (<= ~8 eps relative); these enter the outputs like relative perturbations of the data, so the
//! difference is bounded by `C * eps * s` with `s` the absolute-value/conditioning scale of
//! `walker_tests` and `C = 16` (two evaluations, ~8 eps each). At Table 1 the systems are
//! well conditioned (cond(K) < 100), so this is a few ulps of the outputs' scale.
#![allow(clippy::unwrap_used, reason = "test code")]

use nalgebra::Vector4;
use walker_tests::scenes::{
    active_level as al, general_level as gl, general_slope as gs, passive_slope as ps,
};
use walker_tests::{EPS, Phys};

const C: f64 = 16.0;

fn close(what: &str, a: &[f64], b: &[f64], scale: f64) {
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        let err = (x - y).abs();
        assert!(
            err <= C * EPS * scale,
            "{what}[{i}]: fixed {x:e} general {y:e} diff {err:e} > {:e}",
            C * EPS * scale
        );
    }
}

#[test]
fn active_level_equals_general_level_at_table1() {
    let p = Phys::table1(0.0);
    let (mu0, c) = (0.3, 100.0);
    let ka = al::prepare(&al::Params {
        mu0,
        c,
        t_set: 0.5,
        k_p: 100.0,
        k_d: 20.0,
    });
    let kg = gl::prepare(&gl::Params {
        m1: p.m1,
        m2: p.m2,
        l: p.l,
        i1: p.i1,
        i2: p.i2,
        g: p.g,
        alpha: p.alpha,
        mu0,
        c,
        t_set: 0.5,
        k_p: 100.0,
        k_d: 20.0,
    });
    for k in 0..200 {
        let t = f64::from(k) / 199.0;
        let th1 = (2.0 * t - 1.0) * (p.alpha / 2.0 + 0.2);
        let (xd, zd, th1d, th2d, u) = (
            0.5 * (7.0 * t).sin(),
            0.3 * (3.0 * t).cos(),
            3.0 * (5.0 * t).cos(),
            -2.0 + 4.0 * t,
            10.0 * (11.0 * t).sin(),
        );
        let mu = walker_tests::mu_law(mu0, c, 0.0, xd);
        let st = walker_tests::stance(&p, th1, th1d, u, mu).expect("stance");
        let (_, habs) = walker_tests::bias(&p, th1, th1d);
        let mabs = walker_tests::mass_matrix(&p, th1).abs().max();
        close(
            "mass_matrix",
            &al::mass_matrix(&ka, th1).concat(),
            &gl::mass_matrix(&kg, th1).concat(),
            mabs,
        );
        close(
            "bias",
            &al::bias(&ka, th1, th1d),
            &gl::bias(&kg, th1, th1d),
            habs.max(),
        );
        close(
            "lambda_level",
            &[al::lambda_level(&ka, th1, th1d, u, xd)],
            &[gl::lambda_level(&kg, th1, th1d, u, xd)],
            st.scale,
        );
        close(
            "accel_level",
            &al::accel_level(&ka, th1, th1d, u, xd),
            &gl::accel_level(&kg, th1, th1d, u, xd),
            st.scale,
        );
        let (_, ys) = walker_tests::projection(&p, th1, mu).expect("projection");
        close(
            "projection_level",
            &al::projection_level(&ka, th1, xd).concat(),
            &gl::projection_level(&kg, th1, xd).concat(),
            ys,
        );
        let [_, _, sa, sb] = walker_tests::control(&p, th1, th1d, mu).expect("control");
        close(
            "control_level",
            &al::control_level(&ka, th1, th1d, xd),
            &gl::control_level(&kg, th1, th1d, xd),
            sa.max(sb),
        );
        let qd = Vector4::new(xd, zd, th1d, th2d);
        for name in ["impact3_level", "impact2_level"] {
            let rows = walker_tests::impact_rows(name, &p, th1);
            let s = walker_tests::impact(&p, &rows, th1, qd)
                .expect("impact")
                .scale;
            let (a, b) = if name == "impact3_level" {
                (
                    al::impact3_level(&ka, th1, xd, zd, th1d, th2d).to_vec(),
                    gl::impact3_level(&kg, th1, xd, zd, th1d, th2d).to_vec(),
                )
            } else {
                (
                    al::impact2_level(&ka, th1, xd, zd, th1d, th2d).to_vec(),
                    gl::impact2_level(&kg, th1, xd, zd, th1d, th2d).to_vec(),
                )
            };
            close(name, &a, &b, s);
        }
        let (_, fa) = walker_tests::fore_foot(&p, 1.0, 0.1, th1, xd, zd, th1d);
        close(
            "fore_foot",
            &al::fore_foot(&ka, 1.0, 0.1, th1, xd, zd, th1d),
            &gl::fore_foot(&kg, 1.0, 0.1, th1, xd, zd, th1d),
            fa.iter().copied().fold(0.0, f64::max),
        );
        let (_, ea) = walker_tests::energy(&p, 0.1, th1, qd);
        close(
            "energy",
            &al::energy(&ka, 0.1, th1, xd, zd, th1d, th2d),
            &gl::energy(&kg, 0.1, th1, xd, zd, th1d, th2d),
            ea[0].max(ea[1]),
        );
    }
}

#[test]
fn passive_slope_equals_general_slope_at_table1() {
    for phi in [0.0, 0.02, 0.1, 0.3] {
        let p = Phys::table1(phi);
        let (mu0, c) = (0.3, 100.0);
        let ka = ps::prepare(&ps::Params { phi, mu0, c });
        let kg = gs::prepare(&gs::Params {
            m1: p.m1,
            m2: p.m2,
            l: p.l,
            i1: p.i1,
            i2: p.i2,
            g: p.g,
            alpha: p.alpha,
            phi,
            mu0,
            c,
        });
        for k in 0..100 {
            let t = f64::from(k) / 99.0;
            let th1 = (2.0 * t - 1.0) * (p.alpha / 2.0 + phi + 0.2);
            let (xd, zd, th1d, th2d) = (
                0.5 * (7.0 * t).sin(),
                0.3 * (3.0 * t).cos(),
                3.0 * (5.0 * t).cos(),
                -2.0 + 4.0 * t,
            );
            let mu = walker_tests::mu_law(mu0, c, phi, xd);
            let st = walker_tests::stance(&p, th1, th1d, 0.0, mu).expect("stance");
            let (_, habs) = walker_tests::bias(&p, th1, th1d);
            let mabs = walker_tests::mass_matrix(&p, th1).abs().max();
            close(
                "mass_matrix",
                &ps::mass_matrix(&ka, th1).concat(),
                &gs::mass_matrix(&kg, th1).concat(),
                mabs,
            );
            close(
                "bias",
                &ps::bias(&ka, th1, th1d),
                &gs::bias(&kg, th1, th1d),
                habs.max(),
            );
            close(
                "lambda_slope",
                &[ps::lambda_slope(&ka, th1, th1d, xd)],
                &[gs::lambda_slope(&kg, th1, th1d, xd)],
                st.scale,
            );
            close(
                "accel_slope",
                &ps::accel_slope(&ka, th1, th1d, xd),
                &gs::accel_slope(&kg, th1, th1d, xd),
                st.scale,
            );
            let qd = Vector4::new(xd, zd, th1d, th2d);
            for name in ["impact_slope", "impact2_slope"] {
                let rows = walker_tests::impact_rows(name, &p, th1);
                let s = walker_tests::impact(&p, &rows, th1, qd)
                    .expect("impact")
                    .scale;
                let (a, b) = if name == "impact_slope" {
                    (
                        ps::impact_slope(&ka, th1, xd, zd, th1d, th2d).to_vec(),
                        gs::impact_slope(&kg, th1, xd, zd, th1d, th2d).to_vec(),
                    )
                } else {
                    (
                        ps::impact2_slope(&ka, th1, xd, zd, th1d, th2d).to_vec(),
                        gs::impact2_slope(&kg, th1, xd, zd, th1d, th2d).to_vec(),
                    )
                };
                close(name, &a, &b, s);
            }
            let (_, fa) = walker_tests::fore_foot(&p, 1.0, 0.1, th1, xd, zd, th1d);
            close(
                "fore_foot",
                &ps::fore_foot(&ka, 1.0, 0.1, th1, xd, zd, th1d),
                &gs::fore_foot(&kg, 1.0, 0.1, th1, xd, zd, th1d),
                fa.iter().copied().fold(0.0, f64::max),
            );
            let (_, ea) = walker_tests::energy(&p, 0.1, th1, qd);
            close(
                "energy",
                &ps::energy(&ka, 0.1, th1, xd, zd, th1d, th2d),
                &gs::energy(&kg, 0.1, th1, xd, zd, th1d, th2d),
                ea[0].max(ea[1]),
            );
        }
    }
}

#[test]
fn frictionless_scene_has_no_tanh() {
    let scene = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../walker/scenes/active-level-frictionless.toml");
    let src = walker_gen::Config::new()
        .scene_file(scene)
        .render()
        .expect("frictionless scene renders");
    assert!(
        src.contains("pub fn accel_level"),
        "the scene renders the stance kernels"
    );
    assert!(
        !src.contains("tanh"),
        "friction = \"none\" must not evaluate tanh"
    );
}
