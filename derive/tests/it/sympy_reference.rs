//! Every derived kernel, evaluated in `f64` straight from its canonical form, against the
//! independent SymPy reference values in `tests/data/` (40-digit evaluation, see
//! `sympy_ref/README.md`).
//!
//! Tolerance: the canonical forms are evaluated term by term in `f64`, so the error is bounded
//! by roughly `n_terms * eps * condition`, where the condition is the ratio of the sum of the
//! absolute values of the terms to the absolute value of the result. We compute that bound at
//! each point and require the error to stay below 8 times it (plus a few ulps of the result).

use walker_symbolic::symbol::{Point, Symbols, Valuation};
use walker_symbolic::{Derivation, RatFunc};

fn atoms(names: &[String], values: &[f64]) -> Point<f64> {
    let table = Symbols::paper();
    let mut v = Point::zeros(&table);
    for (n, x) in names.iter().zip(values) {
        let s = table.lookup(n).expect("reference input names are symbols");
        v.set_sym(s, *x);
    }
    v
}

/// Sum of absolute values of the terms of a polynomial at a point.
fn abs_sum(p: &walker_symbolic::Poly, v: &Point<f64>) -> f64 {
    use num_traits::ToPrimitive;
    p.terms()
        .iter()
        .map(|(m, c)| {
            let mut t = c.to_f64().unwrap_or(f64::NAN).abs();
            for (slot, e) in m.factors() {
                t *= v.value(slot).abs().powi(i32::from(e));
            }
            t
        })
        .sum()
}

fn error_bound(r: &RatFunc, v: &Point<f64>) -> f64 {
    let n = r.num().eval(v);
    let d = r.den().eval(v);
    let cn = abs_sum(r.num(), v) / n.abs().max(f64::MIN_POSITIVE);
    let cd = abs_sum(r.den(), v) / d.abs().max(f64::MIN_POSITIVE);
    let terms = (r.num().len() + r.den().len()) as f64;
    // Each input carries a rounding of its own (sin, cos of the angles): count them too.
    (terms + 8.0) * f64::EPSILON * (cn + cd + 2.0)
}

#[test]
fn every_kernel_matches_the_sympy_reference() {
    let derivation = Derivation::new().expect("derivation");
    let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data");
    let mut checked = 0;
    for kernel in &derivation.kernels {
        let path = data.join(format!("{}.json", kernel.name));
        let text = std::fs::read_to_string(&path).expect("reference file exists for every kernel");
        let json: serde_json::Value = serde_json::from_str(&text).expect("valid json");
        let names: Vec<String> = serde_json::from_value(json["inputs"].clone()).expect("inputs");
        let outs: Vec<String> = serde_json::from_value(json["outputs"].clone()).expect("outputs");
        assert_eq!(
            outs.len(),
            kernel.outputs.len(),
            "{}: output count",
            kernel.name
        );
        for (o, (name, _)) in outs.iter().zip(&kernel.outputs) {
            assert_eq!(o, name, "{}: output order", kernel.name);
        }
        let points = json["points"].as_array().expect("points");
        assert!(
            points.len() >= 200,
            "{}: at least 200 reference points",
            kernel.name
        );
        let mut worst = 0.0f64;
        for p in points {
            let parse = |v: &serde_json::Value| -> Vec<f64> {
                v.as_array()
                    .expect("array")
                    .iter()
                    .map(|s| s.as_str().expect("string").parse::<f64>().expect("number"))
                    .collect()
            };
            let inputs = parse(&p["in"]);
            let expected = parse(&p["out"]);
            let v = atoms(&names, &inputs);
            for ((name, r), want) in kernel.outputs.iter().zip(&expected) {
                let got = r.eval(&v);
                let bound = error_bound(r, &v) * want.abs() + 4.0 * f64::EPSILON * want.abs();
                let err = (got - want).abs();
                // An exact match needs no bound (the bound is NaN where the value is an exact
                // zero, as `zd` after the torso lock at the paper's pre-impact state).
                assert!(
                    err == 0.0 || err <= 8.0 * bound + f64::MIN_POSITIVE,
                    "{} {name} at {:?} [{}]: got {got:e}, want {want:e}, err {err:e} > 8 * {bound:e}",
                    kernel.name,
                    inputs,
                    p["tag"]
                );
                if *want != 0.0 {
                    worst = worst.max(err / want.abs());
                }
                checked += 1;
            }
        }
        println!("{:18} worst relative error {worst:.2e}", kernel.name);
    }
    assert!(checked > 0);
}
