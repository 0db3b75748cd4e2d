//! One step against the high-precision references of `sympy_ref/steps.py`
//! (`tests/data/step_active.json`, `tests/data/step_passive.json`).
//!
//! Tolerance: DOP853 with `rtol = 1e-10`, `atol = 1e-12` keeps the local error of each
//! integrator step below about `1e-10` relative; over the ~50-100 steps of a stance phase the
//! global error of the state and of the event time stays below about `1e-9`, and the descriptors
//! (`dx / T`, `p / T`) inherit that. We assert `2e-8` relative (absolute for values near zero),
//! a margin of an order of magnitude, and print the measured errors.

use std::path::PathBuf;

use crate::common;

use common::table1;
use walker::sim::{SimConfig, StepResult, WalkLimits, walk};

fn load(name: &str) -> Option<serde_json::Value> {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../tests/data")
        .join(name);
    let s = std::fs::read_to_string(&p).ok()?;
    serde_json::from_str(&s).ok()
}

fn num(v: &serde_json::Value) -> f64 {
    v.as_str()
        .and_then(|s| s.parse().ok())
        .or_else(|| v.as_f64())
        .unwrap_or(f64::NAN)
}

fn vec4(v: &serde_json::Value) -> [f64; 4] {
    let mut out = [f64::NAN; 4];
    if let Some(a) = v.as_array() {
        for (o, x) in out.iter_mut().zip(a) {
            *o = num(x);
        }
    }
    out
}

const TOL: f64 = 2e-8;

fn compare(name: &str, step: &StepResult, r: &serde_json::Value) {
    let mut worst: f64 = 0.0;
    let mut check = |what: &str, got: f64, want: f64| {
        let err = (got - want).abs() / want.abs().max(1.0);
        println!("{name}: {what}: got {got:.16e} want {want:.16e} err {err:.2e}");
        worst = worst.max(err);
        assert!(err < TOL, "{name}: {what} error {err:e}");
    };
    check("T", step.period, num(&r["T"]));
    check("dx", step.dx, num(&r["dx"]));
    check("V", step.speed, num(&r["V"]));
    let (q, qd) = (vec4(&r["q_plus"]), vec4(&r["qd_plus"]));
    for i in 0..4 {
        check(&format!("q_plus[{i}]"), step.q_plus[i], q[i]);
        check(&format!("qd_plus[{i}]"), step.qd_plus[i], qd[i]);
    }
    if let (Some(p), Some(sr)) = (step.p, step.sr) {
        check("p", p, num(&r["p"]));
        check("SR", sr, num(&r["SR"]));
    }
    println!("{name}: worst relative error {worst:.2e}");
}

#[test]
fn one_active_step_matches_the_reference() {
    let r = load("step_active.json")
        .expect("tests/data/step_active.json is committed (sympy_ref/run.sh writes it)");
    let pr = &r["params"];
    let m = common::active(&[
        ("mu0", num(&pr["mu0"])),
        ("c", num(&pr["c"])),
        ("T_set", num(&pr["T_set"])),
        ("K_P", 0.0),
        ("K_D", 0.0),
    ]);
    assert!((num(&pr["alpha"]) - table1("alpha")).abs() < 1e-15);
    let mut s0 = [0.0; 8];
    s0[..4].copy_from_slice(&vec4(&r["q0"]));
    s0[4..].copy_from_slice(&vec4(&r["qd0"]));
    let lim = WalkLimits {
        max_steps: 1,
        ..WalkLimits::default()
    };
    let w = walk(&m, &SimConfig::default(), &s0, &lim);
    assert_eq!(w.steps.len(), 1, "{:?}", w.failure);
    compare("active", &w.steps[0], &r);
}

#[test]
fn one_passive_step_matches_the_reference() {
    let r = load("step_passive.json")
        .expect("tests/data/step_passive.json is committed (sympy_ref/run.sh writes it)");
    let pr = &r["params"];
    let m = common::passive(&[
        ("mu0", num(&pr["mu0"])),
        ("c", num(&pr["c"])),
        ("phi", num(&pr["phi"])),
    ]);
    let mut s0 = [0.0; 8];
    s0[..4].copy_from_slice(&vec4(&r["q0"]));
    s0[4..].copy_from_slice(&vec4(&r["qd0"]));
    let lim = WalkLimits {
        max_steps: 1,
        ..WalkLimits::default()
    };
    let w = walk(&m, &SimConfig::default(), &s0, &lim);
    assert_eq!(w.steps.len(), 1, "{:?}", w.failure);
    compare("passive", &w.steps[0], &r);
}
