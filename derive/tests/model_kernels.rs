//! Every kernel of every shipped model (`models/*.toml`), in each form the derivation gives it
//! (closed form, structured solve), against the independent SymPy derivation of the same file
//! (`sympy_ref/models.py`: Euler-Lagrange from the energies, the stance and impact equations
//! solved at 30 digits; reference values in `tests/data/models/<name>.json`).
//!
//! Tolerance, relative to `|ref| + 1` (the outputs are of order one at the samples: parameters
//! near the defaults, velocities of order one):
//! - closed forms, `1e-10`: canonical polynomials evaluated term by term in `f64`, at most a
//!   few hundred terms of moderate size, so rounding stays near `1e-13`;
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

use serde_json::Value;
use walker_scene::model::Model;
use walker_symbolic::model::ModelDerivation;
use walker_symbolic::symbol::Point;

fn num(v: &Value) -> f64 {
    v.as_str()
        .and_then(|s| s.parse().ok())
        .or_else(|| v.as_f64())
        .unwrap_or(f64::NAN)
}

/// The reference's name for output `name` of kernel `kernel` (`None`: not in the reference).
fn reference_name(kernel: &str, name: &str, cols: usize) -> Option<String> {
    // (Every shipped model has fewer than ten coordinates, inputs and outputs, so an index
    // pair is two digits.)
    let index = |prefix: &str| name.strip_prefix(prefix).map(str::to_owned);
    // `A{i}{j}` for a matrix with more than one row and column, `A{k}` otherwise.
    let matrix = |prefix: &str, to: &str| {
        let digits = index(prefix)?;
        Some(if cols > 1 && digits.len() == 2 {
            let (i, j) = digits.split_at(1);
            format!("{to}_{i}_{j}")
        } else {
            format!("{to}_{digits}_0")
        })
    };
    Some(match (kernel, name) {
        ("mass_matrix", _) => {
            let digits = index("M")?;
            let (i, j) = digits.split_at(1);
            format!("M_{i}_{j}")
        }
        ("bias", _) => format!("h_{}", index("h")?),
        ("lambda", "lambda") => "lambda".into(),
        ("accel", _) => format!("qdd_{}", index("qdd")?),
        ("control", n) if n.starts_with('A') => matrix("A", "A")?,
        ("control", _) => format!("B_{}", index("B")?),
        ("closed_loop", n) if n.starts_with("qdd") => format!("qdd_cl_{}", index("qdd")?),
        ("closed_loop", _) => format!("u_cl_{}", index("u")?),
        ("stick", "lambda_t") => "stick_lambda_t".into(),
        ("stick", "lambda_n") => "stick_lambda_n".into(),
        ("stick", _) => format!("stick_qdd_{}", index("qdd")?),
        ("impact", n) if n.starts_with("lambdaI") => {
            format!("impact_lambda_{}", index("lambdaI")?)
        }
        ("impact", _) => format!("impact_qdp_{}", index("qdp")?),
        ("impact_double", n) if n.starts_with("lambdaI") => {
            format!("impact_ds_lambda_{}", index("lambdaI")?)
        }
        ("impact_double", _) => format!("impact_ds_qdp_{}", index("qdp")?),
        ("points", _) => {
            let (axis, point) = name.split_once('_')?;
            format!("{point}_{axis}")
        }
        ("energy", n) => n.to_owned(),
        ("outputs", n) if n.starts_with('y') => format!("y_{}", index("y")?),
        _ => return None,
    })
}

/// The 2-norm condition number of a symmetric positive definite matrix (Jacobi eigenvalues).
fn condition(mut a: Vec<Vec<f64>>) -> f64 {
    let n = a.len();
    for _ in 0..100 {
        let mut off = 0.0;
        for p in 0..n {
            for q in p + 1..n {
                off += a[p][q] * a[p][q];
                if a[p][q].abs() < 1e-300 {
                    continue;
                }
                let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                for row in &mut a {
                    let (akp, akq) = (row[p], row[q]);
                    row[p] = c * akp - s * akq;
                    row[q] = s * akp + c * akq;
                }
                let (rp, rq) = (a[p].clone(), a[q].clone());
                a[p] = rp.iter().zip(&rq).map(|(x, y)| c * x - s * y).collect();
                a[q] = rp.iter().zip(&rq).map(|(x, y)| s * x + c * y).collect();
            }
        }
        if off < 1e-30 {
            break;
        }
    }
    let eig: Vec<f64> = (0..n).map(|i| a[i][i].abs()).collect();
    let max = eig.iter().copied().fold(0.0, f64::max);
    let min = eig.iter().copied().fold(f64::INFINITY, f64::min);
    max / min
}

/// Checks every kernel of `model_name`; returns the number of values compared per form.
fn check(model_name: &str) -> (usize, usize) {
    let root = env!("CARGO_MANIFEST_DIR");
    let model = Model::from_file(std::path::Path::new(&format!(
        "{root}/../models/{model_name}.toml"
    )))
    .expect("shipped model loads");
    let text = std::fs::read_to_string(format!("{root}/../tests/data/models/{model_name}.json"))
        .expect("reference data");
    let data: Value = serde_json::from_str(&text).expect("json");
    let d = ModelDerivation::new(&model).expect("derives");
    let s = &d.syms;
    let n = s.q.len();
    let vertical_of = |p: &Point<f64>| {
        model.floor.slope.as_ref().map_or(1.0, |phi| {
            let phi = s.get(&phi.name).expect("slope");
            walker_symbolic::mechanics::cos(&[(phi, 1)])
                .expect("cos")
                .eval(p)
        })
    };
    let (mut closed, mut solved) = (0, 0);
    for sample in data["samples"].as_array().expect("samples") {
        let mut p = Point::zeros(&d.symbols);
        for (name, v) in sample["params"].as_object().expect("params") {
            p.set_sym(s.get(name).expect("parameter"), num(v));
        }
        for (k, v) in sample["q"].as_array().expect("q").iter().enumerate() {
            p.set_sym(s.q[k], num(v));
        }
        for (k, v) in sample["qd"].as_array().expect("qd").iter().enumerate() {
            p.set_sym(s.qd[k], num(v));
        }
        for (k, v) in sample["u"].as_array().expect("u").iter().enumerate() {
            p.set_sym(s.inputs[k], num(v));
        }
        for (k, v) in sample["v"].as_array().expect("v").iter().enumerate() {
            p.set_sym(s.aux[k], num(v));
        }
        p.set_sym(s.mu, num(&sample["mu"]));
        p.set_sym(s.t, num(&sample["t"]));
        let vertical = vertical_of(&p);
        let mass = d
            .kernel("mass_matrix")
            .expect("M")
            .eval_closed(&p)
            .expect("closed");
        let kappa = condition((0..n).map(|i| mass[i * n..(i + 1) * n].to_vec()).collect());
        let out = &sample["out"];
        let tag = &sample["tag"];
        for k in &d.kernels {
            let cols = match k.name {
                "control" => model.inputs.len(),
                _ => 1,
            };
            let forms = [
                ("closed form", k.eval_closed(&p), 1e-10),
                ("structured solve", k.eval_solve(&p), 1e-12 * kappa),
            ];
            for (form, values, tol) in forms {
                let Some(values) = values else { continue };
                for ((name, _), got) in k.outputs.iter().zip(values) {
                    let Some(key) = reference_name(k.name, name, cols) else {
                        // The matrices the reference does not list (`S`, `J_I`, `H`) are
                        // checked through the solves built from them (tests/ crate).
                        assert!(
                            matches!(
                                k.name,
                                "input_map" | "impact_rows" | "impact_double_rows" | "outputs"
                            ),
                            "{model_name}: no reference name for {}.{name}",
                            k.name
                        );
                        continue;
                    };
                    // Impulses on a slope: the reference reports their vertical components.
                    let got = if name.starts_with("lambdaI") {
                        got * vertical
                    } else {
                        got
                    };
                    let want = num(&out[&key]);
                    assert!(!want.is_nan(), "{model_name}: the reference has no {key}");
                    assert!(
                        (got - want).abs() <= tol * (want.abs() + 1.0),
                        "{model_name} {tag} {}.{name} by {form}: {got} vs SymPy {want} \
                         (tolerance {tol:e} relative, kappa(M) = {kappa:.3e})",
                        k.name
                    );
                    if form == "closed form" {
                        closed += 1;
                    } else {
                        solved += 1;
                    }
                }
            }
        }
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
