//! Every model file of `models/`: its generated kernels called by name (`build.rs` generates
//! them with exact Coulomb friction and an adapter per model), its SymPy reference samples
//! (`tests/data/models/<name>.json`, made by `sympy_ref/models.py` from the same file), and the
//! names under which the reference lists each kernel output.

use std::collections::BTreeMap;
use std::path::PathBuf;

use serde_json::Value;
use walker_gen::scene::model::{Model, SymbolKind};
use walker_symbolic::symbol::Point;
use walker_symbolic::{Poly, RatFunc};

/// Calls a kernel by name: `(kernel, parameter by name, argument by name)` to its outputs,
/// flattened row-major, or `None` for a kernel the model does not have.
pub type KernelCall = fn(&str, &dyn Fn(&str) -> f64, &dyn Fn(&str) -> f64) -> Option<Vec<f64>>;

/// A model's generated kernels.
#[derive(Clone, Copy, Debug)]
pub struct GeneratedModel {
    /// The model's name (its file stem).
    pub name: &'static str,
    /// Calls a kernel by name.
    pub call: KernelCall,
    /// Every kernel and its output names.
    pub kernels: &'static [(&'static str, &'static [&'static str])],
}

include!(concat!(env!("OUT_DIR"), "/models.rs"));

/// The model file `models/<name>.toml`.
///
/// # Panics
/// The file does not load (a shipped model always does).
#[must_use]
pub fn load(name: &str) -> Model {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../models")
        .join(format!("{name}.toml"));
    Model::from_file(&path).expect("a shipped model file loads")
}

/// One reference sample: every parameter and kernel argument by name, and the reference
/// outputs.
#[derive(Clone, Debug)]
pub struct Sample {
    /// The sample's tag (`random`, `strike`, ...).
    pub tag: String,
    /// Parameters and arguments by name (`mu` realised as `mu0 = |mu|`, `sigma = -sign mu`).
    pub values: BTreeMap<String, f64>,
    /// The reference outputs by the reference's names.
    pub out: Value,
}

impl Sample {
    /// The value called `name` (NaN if the sample has none: a kernel reading it fails loudly).
    #[must_use]
    pub fn get(&self, name: &str) -> f64 {
        self.values.get(name).copied().unwrap_or(f64::NAN)
    }

    /// The reference value called `key`, if the reference has it.
    #[must_use]
    pub fn reference(&self, key: &str) -> Option<f64> {
        let v = &self.out[key];
        v.as_str()
            .and_then(|s| s.parse().ok())
            .or_else(|| v.as_f64())
    }
}

impl Sample {
    /// The sample with its velocities replaced by the reference's post-impact velocities
    /// (`impact_qdp_i`): the arguments of the `relabel` kernel, whose reference
    /// (`relabel_qd_i`) relabels those.
    #[must_use]
    pub fn after_impact(&self, model: &Model) -> Sample {
        let mut s = self.clone();
        for (i, name) in names_of(model, SymbolKind::Velocity).iter().enumerate() {
            if let Some(v) = self.reference(&format!("impact_qdp_{i}")) {
                s.values.insert(name.clone(), v);
            }
        }
        s
    }
}

fn num(v: &Value) -> f64 {
    v.as_str()
        .and_then(|s| s.parse().ok())
        .or_else(|| v.as_f64())
        .unwrap_or(f64::NAN)
}

/// The names of a model's symbols of one kind, in order.
#[must_use]
pub fn names_of(model: &Model, kind: SymbolKind) -> Vec<String> {
    model
        .symbols()
        .iter()
        .filter(|s| s.kind == kind)
        .map(|s| s.name.clone())
        .collect()
}

/// The reference samples of `model`.
///
/// # Panics
/// The reference file is missing or malformed.
#[must_use]
pub fn samples(model: &Model) -> Vec<Sample> {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("data/models")
        .join(format!("{}.json", model.name));
    let text = std::fs::read_to_string(&path).expect("the model's reference file");
    let data: Value = serde_json::from_str(&text).expect("reference JSON");
    let groups = [
        ("q", names_of(model, SymbolKind::Coordinate)),
        ("qd", names_of(model, SymbolKind::Velocity)),
        ("u", names_of(model, SymbolKind::Input)),
        ("v", names_of(model, SymbolKind::Aux)),
    ];
    let mut out = Vec::new();
    for sample in data["samples"].as_array().expect("samples") {
        let mut values = BTreeMap::new();
        for (name, v) in sample["params"].as_object().expect("params") {
            values.insert(name.clone(), num(v));
        }
        for (key, names) in &groups {
            for (name, v) in names.iter().zip(sample[*key].as_array().expect("values")) {
                values.insert(name.clone(), num(v));
            }
        }
        let mu = num(&sample["mu"]);
        values.insert("mu0".into(), mu.abs());
        values.insert("sigma".into(), if mu > 0.0 { -1.0 } else { 1.0 });
        values.insert("t".into(), num(&sample["t"]));
        out.push(Sample {
            tag: sample["tag"].as_str().unwrap_or("").to_owned(),
            values,
            out: sample["out"].clone(),
        });
    }
    out
}

/// The reference's name for output `name` of kernel `kernel` of a model with `inputs` inputs
/// (the columns of the control's `A` and the rows of the input rates' Jacobian); `None` for the matrices the reference does not list
/// (`S`, `J_I`, `H`, the drift), which the generic linear-algebra tests check through the
/// solves built from them. Every shipped model has fewer than ten coordinates, inputs and
/// outputs, so a matrix entry's index pair is two digits, except a Jacobian's: its row (up to
/// `2n`) is its first digit, or the digits before `_` past ten rows, its column (up to
/// `2n + 1 + m`) the rest.
#[must_use]
pub fn reference_name(kernel: &str, name: &str, inputs: usize) -> Option<String> {
    let index = |prefix: &str| name.strip_prefix(prefix).map(str::to_owned);
    // `A{i}{j}` for a matrix with more than one row and column, `A{k}` otherwise.
    let matrix = |prefix: &str, to: &str| {
        let digits = index(prefix)?;
        Some(if inputs > 1 && digits.len() == 2 {
            let (i, j) = digits.split_at(1);
            format!("{to}_{i}_{j}")
        } else {
            format!("{to}_{digits}_0")
        })
    };
    // `J{i}{j}`: row i (one digit), column j (the rest); `J{i}_{j}` past ten rows.
    let jacobian = |to: &str| {
        let digits = index("J")?;
        let (i, j) = digits.split_once('_').unwrap_or_else(|| digits.split_at(1));
        Some(format!("{to}_{i}_{j}"))
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
        ("closed_loop_stick", "lambda_t") => "stick_lambda_t_cl".into(),
        ("closed_loop_stick", "lambda_n") => "stick_lambda_n_cl".into(),
        ("closed_loop_stick", n) if n.starts_with("qdd") => {
            format!("stick_qdd_cl_{}", index("qdd")?)
        }
        ("closed_loop_stick", _) => format!("stick_u_cl_{}", index("u")?),
        ("impact", n) if n.starts_with("lambdaI") => {
            format!("impact_lambda_{}", index("lambdaI")?)
        }
        ("impact", _) => format!("impact_qdp_{}", index("qdp")?),
        ("impact_double", n) if n.starts_with("lambdaI") => {
            format!("impact_ds_lambda_{}", index("lambdaI")?)
        }
        ("impact_double", _) => format!("impact_ds_qdp_{}", index("qdp")?),
        ("impact_coulomb", n) if n.starts_with("qdl") => {
            format!("coulomb_qdl_{}", index("qdl")?)
        }
        ("impact_coulomb", n) if n.starts_with('R') => {
            let digits = index("R")?;
            let (i, j) = digits.split_at(1);
            format!("coulomb_R_{i}_{j}")
        }
        ("impact_coulomb", n) => format!("coulomb_{n}"),
        ("accel_jacobian", _) => jacobian("accel_jac")?,
        ("closed_loop_jacobian", _) => jacobian("cl_jac")?,
        ("impact_jacobian", _) => jacobian("impact_jac")?,
        ("relabel_jacobian", _) => jacobian("relabel_jac")?,
        ("output_rates_jacobian", _) => jacobian("yrates_jac")?,
        // One input: one row, whose entries are `J{j}`.
        ("input_rates_jacobian", _) if inputs == 1 => format!("w_jac_0_{}", index("J")?),
        ("input_rates_jacobian", _) => jacobian("w_jac")?,
        ("points", _) => {
            let (axis, point) = name.split_once('_')?;
            format!("{point}_{axis}")
        }
        ("energy", n) => n.to_owned(),
        ("outputs", n) if n.starts_with('y') => format!("y_{}", index("y")?),
        ("output_rates", n) if n.starts_with("yd") => format!("yd_{}", index("yd")?),
        ("output_rates", _) => format!("y_{}", index("y")?),
        ("input_rates", _) => format!("w_{}", index("w")?),
        ("total_mass", "m_total") => "total_mass".into(),
        ("events", n) => n.to_owned(),
        ("relabel", n) if n.starts_with("qd") => format!("relabel_qd_{}", index("qd")?),
        ("relabel", _) => format!("relabel_q_{}", index("q")?),
        _ => return None,
    })
}

/// The kernels whose outputs the reference does not list at all (the matrices `S`, `J_I`; see
/// [`reference_name`]): every other kernel of a model is compared with it. `stick_jacobian` is
/// checked exactly instead, entry by entry, as the derivatives of `stick`'s outputs
/// (`derive/tests/it/model_stick_jacobian.rs`).
pub const UNREFERENCED: &[&str] = &[
    "input_map",
    "impact_rows",
    "impact_double_rows",
    "stick_jacobian",
    "closed_loop_stick_jacobian",
];

/// The reference's value of `key` (an output of `kernel`), or `None` where the reference has no
/// Jacobian of that name at all: `sympy_ref/models.py` differentiates closed forms only (of at
/// most four coordinates), so the Jacobians a model without closed forms has from its
/// structured solves (`derive/src/model/forward.rs`: the compass gait's and the simplest
/// walker's `accel_jacobian`, the three-link biped's `closed_loop_jacobian`) are not in it.
/// Those are checked exactly against the closed forms on the paper's walkers (the forward
/// mode's unit tests) and by differences of the stance and of whole steps
/// (`walker/tests/it/stuck_actuated.rs`, `poincare_exact.rs`); `closed_loop_stick_jacobian`
/// likewise ([`UNREFERENCED`]).
///
/// # Errors
/// A key the reference should have and has not (a reference that lists some of a Jacobian's
/// entries must list them all), named with the model.
pub fn reference_value(
    sample: &Sample,
    model: &str,
    kernel: &str,
    key: &str,
) -> Result<Option<f64>, String> {
    if let Some(v) = sample.reference(key) {
        return Ok(Some(v));
    }
    let jacobian = ["accel_jac_", "cl_jac_"]
        .into_iter()
        .find(|prefix| key.starts_with(prefix));
    let listed = |prefix: &str| {
        sample
            .out
            .as_object()
            .is_some_and(|o| o.keys().any(|k| k.starts_with(prefix)))
    };
    match jacobian {
        Some(prefix) if kernel.ends_with("_jacobian") && !listed(prefix) => Ok(None),
        _ => Err(format!("{model}: the reference has no {key}")),
    }
}

/// The factor that turns a kernel output into the reference's: impulses on a slope are
/// reported by the reference as their vertical components (`cos phi` times the normal one).
#[must_use]
pub fn reference_factor(model: &Model, sample: &Sample, name: &str) -> f64 {
    match &model.floor.slope {
        Some(phi) if name.starts_with("lambdaI") => sample.get(&phi.name).cos(),
        _ => 1.0,
    }
}

/// The 2-norm condition number of a symmetric positive definite matrix given by rows (cyclic
/// Jacobi: its eigenvalues to full precision for these small, well-scaled matrices).
#[must_use]
pub fn spd_condition(mut a: Vec<Vec<f64>>) -> f64 {
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
                let t = theta.signum() / (theta.abs() + theta.hypot(1.0));
                let c = 1.0 / t.hypot(1.0);
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

/// A bound on the relative rounding error of `RatFunc::eval` of `r` at `p` in `f64`, to first
/// order: each polynomial is evaluated as the sum of its `k` terms in sequence, each term its
/// coefficient rounded to `f64` times powers of the atoms (`powi`), the atoms (sines and cosines
/// from the maths library) within an ulp, so that a term of degree at most `d` carries at most
/// `4d + 1` roundings and `|fl(P) - P| <= gamma_{k + 4d + 1} sum |t_i|` (Higham, Accuracy and
/// Stability of Numerical Algorithms, 2nd ed., 2002, Lemma 3.1 and Eq. 4.4 for the recursive
/// sum); the quotient adds one rounding. The bound is `gamma` times the sum's condition number
/// `sum |t_i| / |P|` of numerator and denominator: large where the terms cancel (a closed form
/// near a vanishing denominator), about `k eps` elsewhere.
#[must_use]
pub fn rounding_bound(r: &RatFunc, p: &Point<f64>) -> f64 {
    let u = f64::EPSILON / 2.0;
    let gamma = |n: usize| {
        let nu = n as f64 * u;
        nu / (1.0 - nu)
    };
    let relative = |q: &Poly| {
        let (mut abs, mut degree) = (0.0, 0);
        for (m, c) in q.terms() {
            abs += Poly::term(m.clone(), c.clone()).eval(p).abs();
            degree = degree.max(m.degree() as usize);
        }
        gamma(q.len() + 4 * degree + 1) * abs / q.eval(p).abs()
    };
    let (num, den) = (relative(r.num()), relative(r.den()));
    (num + den + u) / (1.0 - den)
}
