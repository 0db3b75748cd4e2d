//! Fixed points of the Poincare map and their Floquet multipliers: Newton converges for
//! Table 1, the cycle reproduces itself, the multipliers predict the convergence seen in `walk`
//! (as the paper's Fig. 7), and the frictionless walker reports its family of cycles.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use crate::common;

use common::start;
use walker::model::Model;
use walker::poincare::{
    FixedPointOptions, JacobianMethod, Section, Status, fixed_point, poincare_map,
};
use walker::sim::{SimConfig, WalkLimits, walk};

fn active(mu0: f64, t_set: f64) -> Model {
    common::active(&[("mu0", mu0), ("T_set", t_set)])
}

#[test]
fn newton_converges_for_table1_and_the_cycle_reproduces_itself() {
    let model = active(0.4, 0.3);
    let cfg = SimConfig::default();
    let opts = FixedPointOptions {
        full_multipliers: true,
        ..FixedPointOptions::for_model(&model)
    };
    let fp = fixed_point(&model, &cfg, &opts).unwrap();
    println!("{}", serde_json::to_string(&fp).unwrap());
    assert_eq!(fp.status, Status::Converged);
    assert_eq!(fp.jacobian_method, JacobianMethod::Variational);
    let m = poincare_map(&model, &cfg, &fp.state_plus).unwrap();
    for i in 0..8 {
        assert!(
            (m.state_plus[i] - fp.state_plus[i]).abs() < 1e-10,
            "component {i}: {} vs {}",
            m.state_plus[i],
            fp.state_plus[i]
        );
    }
    assert!(fp.period > 0.3 && fp.speed > 0.0);
    assert!(!fp.structural_unit_multiplier);
    assert_eq!(fp.multipliers.len(), 2);
    assert!(fp.max_modulus() < 1.0, "{:?}", fp.multipliers);
    // The eight multipliers of the full map: five structural zeros (x, z, th1, zd, torso lock),
    // the neutral output offset at 1 (K_P = K_D = 0) and the gait's two (here 0.76 and ~0: the
    // stuck foot makes the reduced map of rank one).
    let full = fp.full_multipliers.as_ref().unwrap();
    assert_eq!(full.len(), 8);
    let near = |re: f64| {
        full.iter()
            .filter(|l| (l.re - re).hypot(l.im) < 1e-6)
            .count()
    };
    let gait_zeros = fp.multipliers.iter().filter(|l| l.modulus() < 1e-6).count();
    assert_eq!(near(0.0), 5 + gait_zeros, "{full:?}");
    assert_eq!(near(1.0), 1, "{full:?}");
    for g in &fp.multipliers {
        assert!(
            full.iter().any(|l| (l.re - g.re).hypot(l.im - g.im) < 1e-8),
            "{g:?} not among {full:?}"
        );
    }
}

/// The largest multiplier's modulus is the asymptotic contraction of the post-impact velocity
/// error seen in a plain simulation (the paper's Fig. 7 shows `qd+` converging step by step).
#[test]
fn largest_multiplier_predicts_the_convergence_rate_of_walk() {
    let model = active(0.4, 0.3);
    let cfg = SimConfig::default();
    let fp = fixed_point(&model, &cfg, &FixedPointOptions::for_model(&model)).unwrap();
    let section = Section::of(&model);
    let star = section.reduce(&fp.state_plus);
    let w = walk(
        &model,
        &cfg,
        &start(&model, 0.8),
        &WalkLimits {
            max_steps: 200,
            ..WalkLimits::default()
        },
    );
    assert!(w.failure.is_none());
    let err: Vec<f64> = w
        .steps
        .iter()
        .map(|s| {
            let r = section.reduce(&s.state_plus());
            (r[0] - star[0]).hypot(r[1] - star[1])
        })
        .collect();
    // After the transient and before the integration noise (~1e-9): errors in [1e-7, 1e-3].
    let window: Vec<usize> = (0..err.len())
        .filter(|&i| err[i] < 1e-3 && err[i] > 1e-7)
        .collect();
    assert!(window.len() >= 4, "{err:?}");
    let (a, b) = (window[0], window[window.len() - 1]);
    let rate = (err[b] / err[a]).powf(1.0 / (b - a) as f64);
    let lam = fp.max_modulus();
    println!("observed rate {rate}, |lambda_max| {lam}, steps {a}..{b}");
    assert!((rate - lam).abs() < 0.05 * lam, "rate {rate} vs {lam}");
}

#[test]
fn frictionless_walker_reports_the_structural_unit_multiplier() {
    let model = active(0.0, 0.3);
    let cfg = SimConfig::default();
    let fp = fixed_point(&model, &cfg, &FixedPointOptions::for_model(&model)).unwrap();
    println!("{}", serde_json::to_string(&fp).unwrap());
    assert_eq!(fp.status, Status::Family);
    assert!(fp.structural_unit_multiplier);
    assert!(fp.residual < 1e-10);
    assert!(
        fp.multipliers
            .iter()
            .any(|l| (l.re - 1.0).hypot(l.im) < 1e-6),
        "{:?}",
        fp.multipliers
    );
    // A member of the family: another omega0 gives another speed (Fig. 4).
    let other = fixed_point(
        &model,
        &cfg,
        &FixedPointOptions {
            start: start(&model, 0.6),
            ..FixedPointOptions::for_model(&model)
        },
    )
    .unwrap();
    assert_eq!(other.status, Status::Family);
    assert!(
        (other.speed - fp.speed).abs() > 1e-3,
        "{} {}",
        other.speed,
        fp.speed
    );
}

#[test]
fn passive_wheel_has_a_fixed_point() {
    let model = common::passive(&[("mu0", 0.4), ("phi", 0.15)]);
    let cfg = SimConfig::default();
    let fp = fixed_point(&model, &cfg, &FixedPointOptions::for_model(&model)).unwrap();
    println!("{}", serde_json::to_string(&fp).unwrap());
    assert_eq!(fp.status, Status::Converged);
    assert!(fp.max_modulus() < 1.0);
    let section = Section::of(&model);
    let m = poincare_map(
        &model,
        &cfg,
        &section.embed(&section.reduce(&fp.state_plus)),
    )
    .unwrap();
    for i in 0..8 {
        assert!((m.state_plus[i] - fp.state_plus[i]).abs() < 1e-10, "{i}");
    }
}
