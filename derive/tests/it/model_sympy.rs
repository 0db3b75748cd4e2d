//! The model-driven derivation against the independent SymPy derivation of the same model
//! files (`sympy_ref/models.py`, reference values at 30 digits in `tests/data/models/`): `M`,
//! `h`, the energies, the stance's `lambda`, `Y` and `qdd`, the stuck foot and both impact maps,
//! at every sample of every model the Rust derivation handles today (the paper's two walkers and
//! the rimless wheel; see BENCHMARKS.md for the larger models).
//!
//! Tolerance: `1e-10 (|ref| + 1)`. The canonical forms are evaluated in `f64` term by term;
//! these kernels have at most a few hundred terms of moderate size at the samples (parameters
//! near the defaults, velocities of order one), so rounding stays below `1e-12` relative to the
//! largest term, and a wrong derivation is off by order one.

use serde_json::Value;
use walker_scene::model::Model;
use walker_symbolic::matrix::Matrix;
use walker_symbolic::model::{Mechanics, sliding, strike_impacts, stuck};
use walker_symbolic::ratfunc::RatFunc;
use walker_symbolic::symbol::Point;

fn num(v: &Value) -> f64 {
    v.as_str()
        .and_then(|s| s.parse().ok())
        .or_else(|| v.as_f64())
        .unwrap_or(f64::NAN)
}

fn check(model_name: &str) -> usize {
    let root = env!("CARGO_MANIFEST_DIR");
    let model = Model::from_file(std::path::Path::new(&format!(
        "{root}/../models/{model_name}.toml"
    )))
    .expect("shipped model loads");
    let text = std::fs::read_to_string(format!("{root}/../tests/data/models/{model_name}.json"))
        .expect("reference data");
    let data: Value = serde_json::from_str(&text).expect("json");
    let m = Mechanics::new(&model).expect("derives");
    let s = sliding(&m).expect("stance");
    let st = stuck(&m).expect("stuck");
    let imp = strike_impacts(&m, &model).expect("impacts");
    let scale = match &model.floor.slope {
        // The reference reports impulses on a slope as their vertical components
        // (docs/kernels.md); the derivation's are normal impulses.
        Some(phi) => Some(m.syms.get(&phi.name).expect("slope")),
        None => None,
    };
    let mut checked = 0;
    for sample in data["samples"].as_array().expect("samples") {
        let mut p = Point::zeros(&m.syms.table);
        for (name, v) in sample["params"].as_object().expect("params") {
            p.set_sym(m.syms.get(name).expect("parameter"), num(v));
        }
        for (k, v) in sample["q"].as_array().expect("q").iter().enumerate() {
            p.set_sym(m.syms.q[k], num(v));
        }
        for (k, v) in sample["qd"].as_array().expect("qd").iter().enumerate() {
            p.set_sym(m.syms.qd[k], num(v));
        }
        for (k, v) in sample["u"].as_array().expect("u").iter().enumerate() {
            p.set_sym(m.syms.inputs[k], num(v));
        }
        for (k, v) in sample["v"].as_array().expect("v").iter().enumerate() {
            p.set_sym(m.syms.aux[k], num(v));
        }
        p.set_sym(m.syms.mu, num(&sample["mu"]));
        p.set_sym(m.syms.t, num(&sample["t"]));
        let vertical = scale.map_or(1.0, |phi| {
            let mut q = Point::zeros(&m.syms.table);
            q.set_sym(phi, num(&sample["params"][m.syms.table.name(phi)]));
            walker_symbolic::paper::cos(&[(phi, 1)])
                .expect("cos")
                .eval(&q)
        });
        let out = &sample["out"];
        let mut cmp = |name: String, got: &RatFunc, factor: f64| {
            let want = num(&out[&name]);
            assert!(!want.is_nan(), "{model_name}: reference has {name}");
            let got = got.eval(&p) * factor;
            assert!(
                (got - want).abs() <= 1e-10 * (want.abs() + 1.0),
                "{model_name} {} {name}: {got} vs SymPy {want}",
                sample["tag"]
            );
            checked += 1;
        };
        let mut matrix = |prefix: &str, x: &Matrix, factor: f64| {
            for i in 0..x.rows() {
                for j in 0..x.cols() {
                    let name = if x.cols() > 1 {
                        format!("{prefix}_{i}_{j}")
                    } else {
                        format!("{prefix}_{i}")
                    };
                    cmp(name, x.get(i, j), factor);
                }
            }
        };
        matrix("M", &m.mass, 1.0);
        matrix("h", &m.bias, 1.0);
        matrix("qdd", &s.accel, 1.0);
        matrix("Y", &s.projection, 1.0);
        matrix("stick_qdd", &st.accel, 1.0);
        matrix("impact_qdp", &imp.single.velocity, 1.0);
        matrix("impact_lambda", &imp.single.impulse, vertical);
        if let Some(d) = &imp.double {
            matrix("impact_ds_qdp", &d.velocity, 1.0);
            matrix("impact_ds_lambda", &d.impulse, vertical);
        }
        cmp("T".into(), &m.kinetic, 1.0);
        cmp("V".into(), &m.potential, 1.0);
        cmp("lambda".into(), &s.lambda, 1.0);
        cmp("stick_lambda_t".into(), st.forces.get(0, 0), 1.0);
        cmp("stick_lambda_n".into(), st.forces.get(1, 0), 1.0);
    }
    checked
}

#[test]
fn paper_active_model_agrees_with_sympy() {
    assert!(check("paper-active") > 100);
}

#[test]
fn paper_passive_model_agrees_with_sympy() {
    assert!(check("paper-passive") > 100);
}

#[test]
fn rimless_wheel_model_agrees_with_sympy() {
    assert!(check("rimless-wheel") > 100);
}
