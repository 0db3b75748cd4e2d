//! The Poincare map's Jacobian (variational equations, saltation, impact and reset Jacobians)
//! against central finite differences of the map itself, and the reset's analytic Jacobian
//! against the `fore_foot` kernel.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use crate::common;

use walker::model::Model;
use walker::poincare::{JacobianMethod, Section, poincare_map};
use walker::sim::SimConfig;
use walker::vector::Vector;

/// Tight tolerances for the finite differences: the map's integration noise (not smooth in the
/// input, since the adaptive step sequence changes) is about `rtol`, and it enters the
/// difference quotient as `rtol / h`.
fn tight() -> SimConfig {
    SimConfig {
        rtol: 1e-13,
        atol: 1e-14,
        ..SimConfig::default()
    }
}

/// Compare every column of the Jacobian with `(P(s + h e_j) - P(s - h e_j)) / 2h`.
///
/// Step `h = 1e-6`: the truncation error is `h^2 |P'''| / 6 ~ 1e-12` and the rounding plus
/// integration noise `~ 1e-13 / h = 1e-7` relative to the state (the state and the Jacobian are
/// O(1)); the tolerance `1e-5 * |J|` (Frobenius) leaves two orders of margin over both.
fn check_fd(model: &Model, s: Vector) -> f64 {
    let cfg = tight();
    let m = poincare_map(model, &cfg, &s).unwrap();
    // The Jacobian under test is the variational one (the generated Jacobian kernels), not
    // the finite-difference fallback this test would compare with itself.
    assert_eq!(m.method, JacobianMethod::Variational);
    let norm = m
        .jacobian
        .iter()
        .flatten()
        .map(|v| v * v)
        .sum::<f64>()
        .sqrt();
    let h = 1e-6;
    let mut worst: f64 = 0.0;
    for j in 0..8 {
        let mut sp = s;
        let mut sm = s;
        sp[j] += h;
        sm[j] -= h;
        let p = poincare_map(model, &cfg, &sp).unwrap().state_plus;
        let q = poincare_map(model, &cfg, &sm).unwrap().state_plus;
        for i in 0..8 {
            let fd = (p[i] - q[i]) / (2.0 * h);
            let err = (fd - m.jacobian[i][j]).abs();
            worst = worst.max(err / norm);
            assert!(
                err <= 1e-5 * norm,
                "J[{i}][{j}] = {} but FD = {fd} (|J| = {norm})",
                m.jacobian[i][j]
            );
        }
    }
    println!("worst |J - FD| / |J| = {worst:e}");
    worst
}

/// A state off the cycle and off the constraint manifold, so that every column is exercised.
fn perturbed(model: &Model, r: [f64; 2]) -> Vector {
    let mut s = Section::of(model).embed(&r);
    s[0] += 0.1;
    s[3] += 0.01;
    s[5] += 0.001;
    s[7] -= 0.02;
    s
}

#[test]
fn jacobian_matches_finite_differences_active_level() {
    let model = common::active(&[("mu0", 0.4), ("T_set", 0.3)]);
    check_fd(&model, perturbed(&model, [0.1, 0.9]));
}

#[test]
fn jacobian_matches_finite_differences_active_level_gains_frictionless() {
    let model = common::active(&[("mu0", 0.0), ("T_set", 0.3), ("K_P", 20.0), ("K_D", 5.0)]);
    check_fd(&model, perturbed(&model, [0.6, 0.9]));
}

#[test]
fn jacobian_matches_finite_differences_passive_slope() {
    let model = common::passive(&[("mu0", 0.2), ("phi", 0.15)]);
    check_fd(&model, perturbed(&model, [0.05, 0.9]));
}

#[test]
fn map_agrees_with_one_step_of_walk() {
    use walker::sim::{WalkLimits, walk};
    let model = common::active(&[("mu0", 0.4), ("T_set", 0.3)]);
    let cfg = SimConfig::default();
    let s = Section::of(&model).embed(&[0.2, 0.9]);
    let m = poincare_map(&model, &cfg, &s).unwrap();
    let w = walk(
        &model,
        &cfg,
        &s,
        &WalkLimits {
            max_steps: 1,
            ..WalkLimits::default()
        },
    );
    let st = w.steps[0];
    // Both integrate with rtol = 1e-10, but the map's error norm averages over the 64
    // sensitivity components too, so the step sequences differ: agreement to ~1e-8, not 1e-12.
    assert!((st.period - m.period).abs() < 1e-8);
    assert!((st.dx - m.dx).abs() < 1e-8);
    for i in 2..8 {
        assert!((st.state_plus()[i] - m.state_plus[i]).abs() < 1e-8, "{i}");
    }
    assert!((st.q_plus[1] - m.state_plus[1]).abs() < 1e-12);
}
