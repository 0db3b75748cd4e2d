//! Every kernel of every shipped model (`models/*.toml`), in each form the derivation gives it
//! (closed form, structured solve), evaluated from the derivation itself (before any code is
//! generated), against the independent SymPy derivation of the same file (`sympy_ref/models.py`:
//! Euler-Lagrange from the energies, the stance and impact equations solved at 30 digits;
//! reference values in `tests/data/models/<name>.json`).
//!
//! Tolerance, relative to `|ref| + 1` (the outputs are of order one at the samples: parameters
//! near the defaults, velocities of order one):
//! - closed forms, `1e-10`: canonical polynomials evaluated term by term in `f64`, at most a
//!   few hundred terms of moderate size, so rounding stays near `1e-13`; or, where larger, the
//!   first-order rounding bound of that evaluation at the sample
//!   ([`walker_tests::models::rounding_bound`], `gamma_k` times the condition number of the
//!   sums) times `|ref|`: the Jacobians' expanded quotients `(N' D - N D') / D^2` have up to
//!   1227 terms, and at the passive walker's "strike" sample, near the Painleve boundary
//!   (below), the terms of one denominator cancel to `6e-7` of their size, so the rounding
//!   reaches `1.4e-10` (the bound there: `3e-8`; everywhere the error is below 0.14 of it);
//! - staged forms (the closed forms as the code generator evaluates them: the closed loop's `u`
//!   once, the Jacobians by the quotient rule over `N` and `D`), `1e-10`, as closed forms: a
//!   handful of closed forms of the sizes above, combined by a few operations;
//! - structured solves, `1e-12 * kappa`: an `L D L^T` solve is backward stable, so its forward
//!   error is a modest multiple of `kappa(M) * eps` (Higham, Accuracy and Stability of Numerical
//!   Algorithms, 2002, Thm. 10.4 for Cholesky; `L D L^T` of a positive definite matrix is the
//!   same factorisation), where `kappa` is the 2-norm condition number of `M` at the sample,
//!   computed here. The factor `1e4` over `eps` covers up to three solves in a row (the
//!   impact's second factorisation of the Delassus matrix, the projection, the control's
//!   `A^-1`) and the cancellation in the sliding denominator `J M^-1 (J + J_mu)^T` near the
//!   Painleve boundary: the samples include one ("strike" of the passive walker) where
//!   `lambda` is `1e4` times its usual size, so a rounding of `1e-16` in the denominator's
//!   terms is `1e-12` of `lambda`. A wrong derivation is off by order one.
#![allow(clippy::unwrap_used, clippy::panic, reason = "test code")]

use std::collections::BTreeSet;
use walker_symbolic::model::ModelDerivation;
use walker_symbolic::symbol::{Point, SymKind};

use walker_tests::models::{
    UNREFERENCED, load, reference_factor, reference_name, reference_value, rounding_bound, samples,
    spd_condition,
};

/// Checks every kernel of `model_name`; returns the number of values compared per form.
fn check(model_name: &str) -> (usize, usize) {
    let model = load(model_name);
    let d = ModelDerivation::new(&model).expect("derives");
    let n = d.syms.q.len();
    let (mut closed, mut solved) = (0, 0);
    let mut compared = BTreeSet::new();
    let mut unreferenced = BTreeSet::new();
    for sample in samples(&model) {
        let mut p = Point::zeros(&d.symbols);
        for s in d.symbols.syms() {
            if d.symbols.kind(s) != SymKind::Local {
                p.set_sym(s, sample.get(d.symbols.name(s)));
            }
        }
        p.set_sym(d.syms.mu, -sample.get("mu0") * sample.get("sigma"));
        let mass = d.kernel("mass_matrix").unwrap().eval_closed(&p).unwrap();
        let kappa = spd_condition((0..n).map(|i| mass[i * n..(i + 1) * n].to_vec()).collect());
        // The relabelling's arguments are the post-impact velocities.
        let mut p_after = p.clone();
        for (i, qd) in d.syms.qd.iter().enumerate() {
            if let Some(v) = sample.reference(&format!("impact_qdp_{i}")) {
                p_after.set_sym(*qd, v);
            }
        }
        for k in &d.kernels {
            let p = if k.name == "relabel" { &p_after } else { &p };
            let forms = [
                ("closed form", k.eval_closed(p), 1e-10),
                ("staged form", k.eval_staged(p), 1e-10),
                ("structured solve", k.eval_solve(p), 1e-12 * kappa),
            ];
            for (form, values, tol) in forms {
                let Some(values) = values else { continue };
                for ((name, r), got) in k.outputs.iter().zip(values) {
                    let Some(key) = reference_name(k.name, name, model.inputs.len()) else {
                        continue;
                    };
                    let Some(want) = reference_value(&sample, model_name, k.name, &key).unwrap()
                    else {
                        // A Jacobian the reference does not derive (see `reference_value`).
                        unreferenced.insert(k.name);
                        continue;
                    };
                    let got = got * reference_factor(&model, &sample, name);
                    let bound = if form == "closed form" {
                        rounding_bound(r, p) * want.abs()
                    } else {
                        0.0
                    };
                    assert!(
                        (got - want).abs() <= (tol * (want.abs() + 1.0)).max(bound),
                        "{model_name} {} {}.{name} by {form}: {got} vs SymPy {want} \
                         (tolerance {tol:e} relative or the rounding bound {bound:e}, \
                         kappa(M) = {kappa:.3e})",
                        sample.tag,
                        k.name
                    );
                    compared.insert(k.name);
                    if form != "structured solve" {
                        closed += 1;
                    } else {
                        solved += 1;
                    }
                }
            }
        }
    }
    for k in &d.kernels {
        assert!(
            compared.contains(k.name)
                || UNREFERENCED.contains(&k.name)
                || unreferenced.contains(k.name),
            "{model_name}: {} is compared with the reference",
            k.name
        );
    }
    (closed, solved)
}

#[test]
fn paper_active_kernels_agree_with_sympy_in_both_forms() {
    let (closed, solved) = check("paper-active");
    assert!(closed > 300 && solved > 200, "{closed} {solved}");
}

#[test]
fn paper_passive_kernels_agree_with_sympy_in_both_forms() {
    let (closed, solved) = check("paper-passive");
    assert!(closed > 200 && solved > 150, "{closed} {solved}");
}

#[test]
fn rimless_wheel_kernels_agree_with_sympy_in_both_forms() {
    let (closed, solved) = check("rimless-wheel");
    assert!(closed > 100 && solved > 80, "{closed} {solved}");
}

#[test]
fn compass_gait_kernels_agree_with_sympy() {
    let (closed, solved) = check("compass-gait");
    assert!(closed > 100 && solved > 150, "{closed} {solved}");
}

#[test]
fn three_link_kernels_agree_with_sympy() {
    let (closed, solved) = check("three-link");
    assert!(closed > 100 && solved > 250, "{closed} {solved}");
}

#[test]
fn five_link_kernels_agree_with_sympy() {
    let (closed, solved) = check("five-link");
    assert!(closed > 100 && solved > 400, "{closed} {solved}");
}
