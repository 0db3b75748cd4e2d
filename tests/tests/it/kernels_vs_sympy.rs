//! Every kernel of `general_level` / `general_slope` and of the Coulomb scenes
//! `general_level_coulomb` / `general_slope_coulomb` (all parameters at run time) against the
//! 30-digit SymPy reference values in `tests/data/<kernel>.json` (format: docs/kernels.md).
//!
//! Prints (`--nocapture`) and writes to `target/kernel_ulps.txt` a table of the worst error
//! per kernel and scene: in ulps of the reference, relative, and as a fraction of the asserted
//! bound.
//!
//! # Tolerance argument
//!
//! The reference is exact to 30 digits; rounding it to `f64` costs half an ulp. The generated
//! kernel's own error is that of a straight-line evaluation of a rational function: its
//! roundings act as relative perturbations of the data (parameters folded by `prepare`, sin/cos,
//! products, the `tanh` of the friction law) of at most ~20 eps each, so the forward error is
//! at most `C * eps * s` with `s` the conditioning-based error scale of the generic path
//! (`walker_tests`, documented per function: absolute-value evaluation for direct formulas,
//! `cond(K) ||x|| + ||K^-1|| ||b_abs||` for the quantities defined by a linear system `K x = b`):
//!
//! - `C_DIRECT = 16`: direct formulas, `gamma_n` with `n <= ~12` operations per output;
//! - `C_SOLVE = 64`: ~20 eps data perturbations, times `sqrt(n) <= 3` from the entrywise to
//!   2-norm conversion.
//!
//! At a point near a singular denominator (the Schur complement `J M^-1 Jhat^T` on the stance
//! side, `J_I M^-1 J_I^T` for impacts) `cond(K)` is large and so is the bound: that is where
//! the large errors are expected, identified by the condition estimate, not by trial.
//!
//! Friction: the kernels take `xd` and compute `mu = -mu0 tanh(c xd [/ cos phi])` inside. A
//! reference `mu` is realised with `mu0 = 2.5`, `c = 1`, `xd = cos(phi) atanh(-mu / mu0)`; the
//! realised `mu_eff` differs from `mu` by `|mu_eff - mu|` (measured in `f64`, exact by Sterbenz)
//! plus the kernel's own rounding of the law (argument within 3 ulps, `|a sech^2 a| < 0.45`,
//! one product: below `4 eps (|mu| + mu0)`). The resulting output error
//! `|d out / d mu| * dmu` is added to the bound, `d out / d mu` by a central difference of the
//! generic path (step `1e-6`, accurate to far better than the factor 2 applied).
//!
//! The Coulomb scenes take the sliding direction `sigma` and compute `mu = -mu0 sigma`: a
//! reference `mu` is realised exactly with `mu0 = |mu|`, `sigma = -sign(mu)` (a product with
//! `±1`), so `dmu = 0` there. The stick kernels have no `mu`.
//!
//! The impact with Coulomb friction (`impact_coulomb_level` / `impact_coulomb_slope`): the
//! scales of [`walker_tests::CoulombIngredients`], the lock's impact solve for `qdl`, the KKT
//! solves of `M_L^-1 J^T` for `R`, and their products with the contact rows for `v` and `W`
//! (the product's own rounding, a few eps of `||J|| ||X||`, is inside the scale): `C_SOLVE`.
//! On the slope `qdl = qd-` is returned exactly.
//!
//! Closed loops (`closed_loop_level`, `closed_loop_stick_level`): the scale is that of
//! [`walker_tests::ClosedLoop`], the solve at `u` plus the first-order propagation of the
//! errors of `A`, `B` through `u = (v + B) / A`; the same `C_SOLVE` (see
//! `kernels_vs_nalgebra.rs` for the argument).
#![allow(clippy::unwrap_used, clippy::panic, reason = "test code")]
#![allow(
    clippy::neg_cmp_op_on_partial_ord,
    reason = "`!(err <= bound)` also fails on NaN"
)]

use std::collections::HashMap;
use std::fmt::Write as _;

use nalgebra::Vector4;
use serde_json::Value;
use walker_tests::scenes::{
    general_level as gl, general_level_coulomb as glc, general_slope as gs,
    general_slope_coulomb as gsc,
};
use walker_tests::{Contact, EPS, Phys, mu_law, ulp, xd_for_mu};

const C_DIRECT: f64 = 16.0;
const C_SOLVE: f64 = 64.0;
const MU0: f64 = 2.5;
const C_LAW: f64 = 1.0;

/// The kernels of the tanh scenes `general_level` / `general_slope` checked here.
const KERNELS: [&str; 17] = [
    "mass_matrix",
    "bias",
    "lambda_level",
    "projection_level",
    "control_level",
    "accel_level",
    "closed_loop_level",
    "lambda_slope",
    "accel_slope",
    "impact3_level",
    "impact2_level",
    "impact_slope",
    "impact2_slope",
    "impact_coulomb_level",
    "impact_coulomb_slope",
    "fore_foot",
    "energy",
];

/// The kernels of `general_level_coulomb`.
const COULOMB_LEVEL: [&str; 11] = [
    "lambda_level",
    "control_level",
    "accel_level",
    "closed_loop_level",
    "stick_level",
    "closed_loop_stick_level",
    "impact3_level",
    "impact2_level",
    "impact_coulomb_level",
    "fore_foot",
    "energy",
];

/// The kernels of `general_slope_coulomb`.
const COULOMB_SLOPE: [&str; 8] = [
    "lambda_slope",
    "accel_slope",
    "stick_slope",
    "impact_slope",
    "impact2_slope",
    "impact_coulomb_slope",
    "fore_foot",
    "energy",
];

/// Which generated module a kernel is taken from.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Module {
    /// `general_level` or `general_slope` (by the kernel's name), `mu` through the tanh law.
    Tanh,
    /// `general_level_coulomb`, `mu = -mu0 sigma`.
    CoulombLevel,
    /// `general_slope_coulomb`, `mu = -mu0 sigma`.
    CoulombSlope,
}

impl Module {
    fn name(self, kernel: &str) -> &'static str {
        match self {
            Module::Tanh if is_slope(kernel) => "general_slope",
            Module::Tanh => "general_level",
            Module::CoulombLevel => "general_level_coulomb",
            Module::CoulombSlope => "general_slope_coulomb",
        }
    }
}

fn is_slope(kernel: &str) -> bool {
    kernel.ends_with("_slope")
}

/// `(mu0, sigma)` of the Coulomb law that gives exactly `mu = -mu0 sigma`.
fn coulomb_for_mu(mu: f64) -> (f64, f64) {
    (mu.abs(), if mu > 0.0 { -1.0 } else { 1.0 })
}

struct Point {
    v: HashMap<String, f64>,
}

impl Point {
    fn get(&self, k: &str) -> f64 {
        *self.v.get(k).unwrap_or_else(|| panic!("input {k} missing"))
    }
    fn or(&self, k: &str, d: f64) -> f64 {
        self.v.get(k).copied().unwrap_or(d)
    }
    fn phys(&self, slope: bool) -> Phys {
        Phys {
            m1: self.or("m1", 2.0),
            m2: self.or("m2", 1.0),
            l: self.or("l", 1.0),
            i1: self.or("I1", 0.5),
            i2: self.or("I2", 1.0),
            g: self.or("g", 9.81),
            alpha: self.or("alpha", 0.5),
            phi: if slope { self.or("phi", 0.0) } else { 0.0 },
        }
    }
    fn qd(&self) -> Vector4<f64> {
        Vector4::new(
            self.get("xd"),
            self.get("zd"),
            self.get("th1d"),
            self.or("th2d", 0.0),
        )
    }
}

/// The generated kernel of a Coulomb scene at the point (`mu` realised exactly through
/// `mu0 = |mu|` and `sigma`).
fn generated_coulomb(kernel: &str, module: Module, pt: &Point) -> Vec<f64> {
    let p = pt.phys(module == Module::CoulombSlope);
    let (mu0, sigma) = coulomb_for_mu(pt.or("mu", 0.0));
    let th1 = pt.get("th1");
    let th1d = || pt.get("th1d");
    let imp = || (pt.get("xd"), pt.get("zd"), pt.get("th1d"), pt.get("th2d"));
    let ff = || {
        (
            pt.get("x"),
            pt.get("z"),
            pt.get("xd"),
            pt.get("zd"),
            pt.get("th1d"),
        )
    };
    let en = || {
        (
            pt.get("z"),
            pt.get("xd"),
            pt.get("zd"),
            pt.get("th1d"),
            pt.get("th2d"),
        )
    };
    if module == Module::CoulombSlope {
        let k = p.slope_coulomb_kernels(mu0);
        return match kernel {
            "lambda_slope" => vec![gsc::lambda_slope(&k, th1, th1d(), sigma)],
            "accel_slope" => gsc::accel_slope(&k, th1, th1d(), sigma).to_vec(),
            "stick_slope" => gsc::stick_slope(&k, th1, th1d()).to_vec(),
            "impact_slope" => {
                let (a, b, c, d) = imp();
                gsc::impact_slope(&k, th1, a, b, c, d).to_vec()
            }
            "impact2_slope" => {
                let (a, b, c, d) = imp();
                gsc::impact2_slope(&k, th1, a, b, c, d).to_vec()
            }
            "impact_coulomb_slope" => {
                let (a, b, c, d) = imp();
                gsc::impact_coulomb_slope(&k, th1, a, b, c, d).to_vec()
            }
            "fore_foot" => {
                let (x, z, xd, zd, w) = ff();
                gsc::fore_foot(&k, x, z, th1, xd, zd, w).to_vec()
            }
            "energy" => {
                let (z, xd, zd, w1, w2) = en();
                gsc::energy(&k, z, th1, xd, zd, w1, w2).to_vec()
            }
            _ => panic!("unknown kernel {kernel}"),
        };
    }
    let k = p.level_coulomb_kernels(mu0, (0.5, 1.0, 1.0));
    match kernel {
        "lambda_level" => vec![glc::lambda_level(&k, th1, th1d(), pt.get("u"), sigma)],
        "control_level" => glc::control_level(&k, th1, th1d(), sigma).to_vec(),
        "accel_level" => glc::accel_level(&k, th1, th1d(), pt.get("u"), sigma).to_vec(),
        "closed_loop_level" => glc::closed_loop_level(&k, th1, th1d(), sigma, pt.get("v")).to_vec(),
        "stick_level" => glc::stick_level(&k, th1, th1d(), pt.get("u")).to_vec(),
        "closed_loop_stick_level" => {
            glc::closed_loop_stick_level(&k, th1, th1d(), pt.get("v")).to_vec()
        }
        "impact3_level" => {
            let (a, b, c, d) = imp();
            glc::impact3_level(&k, th1, a, b, c, d).to_vec()
        }
        "impact2_level" => {
            let (a, b, c, d) = imp();
            glc::impact2_level(&k, th1, a, b, c, d).to_vec()
        }
        "impact_coulomb_level" => {
            let (a, b, c, d) = imp();
            glc::impact_coulomb_level(&k, th1, a, b, c, d).to_vec()
        }
        "fore_foot" => {
            let (x, z, xd, zd, w) = ff();
            glc::fore_foot(&k, x, z, th1, xd, zd, w).to_vec()
        }
        "energy" => {
            let (z, xd, zd, w1, w2) = en();
            glc::energy(&k, z, th1, xd, zd, w1, w2).to_vec()
        }
        _ => panic!("unknown kernel {kernel}"),
    }
}

/// The generated kernel at the point (mu realised through `xd`).
fn generated(kernel: &str, module: Module, pt: &Point) -> Vec<f64> {
    if module != Module::Tanh {
        return generated_coulomb(kernel, module, pt);
    }
    let slope = is_slope(kernel);
    let p = pt.phys(slope);
    let kl = gl::prepare(&gl::Params {
        m1: p.m1,
        m2: p.m2,
        l: p.l,
        i1: p.i1,
        i2: p.i2,
        g: p.g,
        alpha: p.alpha,
        mu0: MU0,
        c: C_LAW,
        t_set: 0.5,
        k_p: 1.0,
        k_d: 1.0,
    });
    let ks = gs::prepare(&gs::Params {
        m1: p.m1,
        m2: p.m2,
        l: p.l,
        i1: p.i1,
        i2: p.i2,
        g: p.g,
        alpha: p.alpha,
        phi: p.phi,
        mu0: MU0,
        c: C_LAW,
    });
    let th1 = pt.get("th1");
    let xmu = || xd_for_mu(pt.get("mu"), MU0, C_LAW, p.phi);
    let imp = || (pt.get("xd"), pt.get("zd"), pt.get("th1d"), pt.get("th2d"));
    match kernel {
        "mass_matrix" => gl::mass_matrix(&kl, th1).concat(),
        "bias" => gl::bias(&kl, th1, pt.get("th1d")).to_vec(),
        "lambda_level" => vec![gl::lambda_level(
            &kl,
            th1,
            pt.get("th1d"),
            pt.get("u"),
            xmu(),
        )],
        "projection_level" => gl::projection_level(&kl, th1, xmu()).concat(),
        "control_level" => gl::control_level(&kl, th1, pt.get("th1d"), xmu()).to_vec(),
        "accel_level" => gl::accel_level(&kl, th1, pt.get("th1d"), pt.get("u"), xmu()).to_vec(),
        "closed_loop_level" => {
            gl::closed_loop_level(&kl, th1, pt.get("th1d"), xmu(), pt.get("v")).to_vec()
        }
        "lambda_slope" => vec![gs::lambda_slope(&ks, th1, pt.get("th1d"), xmu())],
        "accel_slope" => gs::accel_slope(&ks, th1, pt.get("th1d"), xmu()).to_vec(),
        "impact3_level" => {
            let (a, b, c, d) = imp();
            gl::impact3_level(&kl, th1, a, b, c, d).to_vec()
        }
        "impact2_level" => {
            let (a, b, c, d) = imp();
            gl::impact2_level(&kl, th1, a, b, c, d).to_vec()
        }
        "impact_slope" => {
            let (a, b, c, d) = imp();
            gs::impact_slope(&ks, th1, a, b, c, d).to_vec()
        }
        "impact2_slope" => {
            let (a, b, c, d) = imp();
            gs::impact2_slope(&ks, th1, a, b, c, d).to_vec()
        }
        "impact_coulomb_level" => {
            let (a, b, c, d) = imp();
            gl::impact_coulomb_level(&kl, th1, a, b, c, d).to_vec()
        }
        "impact_coulomb_slope" => {
            let (a, b, c, d) = imp();
            gs::impact_coulomb_slope(&ks, th1, a, b, c, d).to_vec()
        }
        "fore_foot" => gl::fore_foot(
            &kl,
            pt.get("x"),
            pt.get("z"),
            th1,
            pt.get("xd"),
            pt.get("zd"),
            pt.get("th1d"),
        )
        .to_vec(),
        "energy" => gl::energy(
            &kl,
            pt.get("z"),
            th1,
            pt.get("xd"),
            pt.get("zd"),
            pt.get("th1d"),
            pt.get("th2d"),
        )
        .to_vec(),
        _ => panic!("unknown kernel {kernel}"),
    }
}

/// The generic values (at friction coefficient `mu`) and their bounds' `C * scale`.
fn generic(kernel: &str, module: Module, pt: &Point, mu: f64) -> (Vec<f64>, Vec<f64>) {
    let slope = is_slope(kernel) || module == Module::CoulombSlope;
    let p = pt.phys(slope);
    let th1 = pt.get("th1");
    let n_out = |n: usize, c: f64, s: f64| vec![c * s; n];
    match kernel {
        "mass_matrix" => {
            let m = walker_tests::mass_matrix(&p, th1);
            let v: Vec<f64> = m.transpose().iter().copied().collect();
            let s = v.iter().map(|x| C_DIRECT * x.abs()).collect();
            (v, s)
        }
        "bias" => {
            let (h, ha) = walker_tests::bias(&p, th1, pt.get("th1d"));
            (
                h.iter().copied().collect(),
                ha.iter().map(|x| C_DIRECT * x).collect(),
            )
        }
        "lambda_level" | "lambda_slope" | "accel_level" | "accel_slope" => {
            let u = pt.or("u", 0.0);
            let st = walker_tests::stance(&p, th1, pt.get("th1d"), u, mu).expect("stance solve");
            if kernel.starts_with("lambda") {
                (vec![st.lambda_eq22], n_out(1, C_SOLVE, st.scale))
            } else {
                (
                    st.qdd.iter().copied().collect(),
                    n_out(4, C_SOLVE, st.scale),
                )
            }
        }
        "closed_loop_level" | "closed_loop_stick_level" => {
            let contact = if kernel == "closed_loop_level" {
                Contact::Slide(mu)
            } else {
                Contact::Stick
            };
            let cl = walker_tests::closed_loop(&p, th1, pt.get("th1d"), pt.get("v"), contact)
                .expect("closed-loop solves");
            let mut v: Vec<f64> = cl.qdd.iter().copied().collect();
            let mut s = vec![C_SOLVE * cl.scale; 4];
            v.push(cl.u);
            s.push(C_SOLVE * cl.scale_u);
            if contact == Contact::Stick {
                v.extend(&cl.lambda);
                s.extend([C_SOLVE * cl.scale; 2]);
            }
            (v, s)
        }
        "stick_level" | "stick_slope" => {
            let u = pt.or("u", 0.0);
            let st = walker_tests::stick(&p, th1, pt.get("th1d"), u).expect("stick solve");
            let mut v: Vec<f64> = st.qdd.iter().copied().collect();
            v.extend(st.lambda);
            (v, n_out(6, C_SOLVE, st.scale))
        }
        "projection_level" => {
            let (y, s) = walker_tests::projection(&p, th1, mu).expect("projection");
            (
                y.transpose().iter().copied().collect(),
                n_out(16, C_SOLVE, s),
            )
        }
        "control_level" => {
            let [a, b, sa, sb] =
                walker_tests::control(&p, th1, pt.get("th1d"), mu).expect("control");
            (vec![a, b], vec![C_SOLVE * sa, C_SOLVE * sb])
        }
        "impact3_level" | "impact2_level" | "impact_slope" | "impact2_slope" => {
            let rows = walker_tests::impact_rows(kernel, &p, th1);
            let imp = walker_tests::impact(&p, &rows, th1, pt.qd()).expect("impact solve");
            let mut v = imp.lambda.clone();
            v.extend(imp.qd_plus.iter());
            let n = v.len();
            (v, n_out(n, C_SOLVE, imp.scale))
        }
        "impact_coulomb_level" | "impact_coulomb_slope" => {
            let lock = kernel == "impact_coulomb_level";
            let c = walker_tests::coulomb_ingredients(&p, th1, pt.qd(), lock)
                .expect("Coulomb impact solves");
            let (v, s) = walker_tests::coulomb_outputs(&c);
            (v, s.iter().map(|x| C_SOLVE * x).collect())
        }
        "fore_foot" => {
            let (v, a) = walker_tests::fore_foot(
                &p,
                pt.get("x"),
                pt.get("z"),
                th1,
                pt.get("xd"),
                pt.get("zd"),
                pt.get("th1d"),
            );
            (v.to_vec(), a.iter().map(|x| C_DIRECT * x).collect())
        }
        "energy" => {
            let (v, a) = walker_tests::energy(&p, pt.get("z"), th1, pt.qd());
            (v.to_vec(), a.iter().map(|x| C_DIRECT * x).collect())
        }
        _ => panic!("unknown kernel {kernel}"),
    }
}

#[derive(Default)]
struct Worst {
    points: usize,
    ulps: f64,
    rel: f64,
    ratio: f64,
    ratio_where: String,
    rel_scale: f64,
}

#[test]
fn kernels_match_sympy_reference() {
    let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data");
    let mut table = String::new();
    let _ = writeln!(
        table,
        "{:<24} {:<22} {:>6} {:>12} {:>12} {:>12} {:>12}  worst-ratio point",
        "kernel", "module", "points", "worst ulps", "worst rel", "err/bound", "max s/|ref|"
    );
    let mut failures = Vec::new();
    let cases = KERNELS
        .iter()
        .map(|k| (*k, Module::Tanh))
        .chain(COULOMB_LEVEL.iter().map(|k| (*k, Module::CoulombLevel)))
        .chain(COULOMB_SLOPE.iter().map(|k| (*k, Module::CoulombSlope)));
    for (kernel, module) in cases {
        let text = std::fs::read_to_string(data.join(format!("{kernel}.json")))
            .expect("reference file readable");
        let json: Value = serde_json::from_str(&text).expect("reference file is JSON");
        let inputs: Vec<String> = json["inputs"]
            .as_array()
            .expect("inputs array")
            .iter()
            .map(|s| s.as_str().expect("input name").to_owned())
            .collect();
        let mut w = Worst::default();
        for point in json["points"].as_array().expect("points array") {
            let tag = point["tag"].as_str().unwrap_or("?");
            let parse = |v: &Value| -> f64 {
                v.as_str()
                    .expect("decimal string")
                    .parse()
                    .expect("decimal number")
            };
            let ins: Vec<f64> = point["in"]
                .as_array()
                .expect("in")
                .iter()
                .map(parse)
                .collect();
            let refs: Vec<f64> = point["out"]
                .as_array()
                .expect("out")
                .iter()
                .map(parse)
                .collect();
            let pt = Point {
                v: inputs.iter().cloned().zip(ins.iter().copied()).collect(),
            };
            let gen_out = generated(kernel, module, &pt);
            assert_eq!(gen_out.len(), refs.len(), "{kernel}: output count");
            let has_mu = pt.v.contains_key("mu");
            let phi = pt.phys(is_slope(kernel)).phi;
            let (mu, dmu) = match (has_mu, module) {
                (false, _) => (0.0, 0.0),
                (true, Module::Tanh) => {
                    let mu = pt.get("mu");
                    let eff = mu_law(MU0, C_LAW, phi, xd_for_mu(mu, MU0, C_LAW, phi));
                    (mu, (eff - mu).abs() + 4.0 * EPS * (mu.abs() + MU0))
                }
                // -|mu| * (-sign(mu)) is mu exactly.
                (true, _) => (pt.get("mu"), 0.0),
            };
            let (_, bound_c) = generic(kernel, module, &pt, mu);
            let dfdmu: Vec<f64> = if dmu > 0.0 {
                let hstep = 1e-6;
                let (vp, _) = generic(kernel, module, &pt, mu + hstep);
                let (vm, _) = generic(kernel, module, &pt, mu - hstep);
                vp.iter()
                    .zip(&vm)
                    .map(|(a, b)| (a - b) / (2.0 * hstep))
                    .collect()
            } else {
                vec![0.0; refs.len()]
            };
            w.points += 1;
            for i in 0..refs.len() {
                let err = (gen_out[i] - refs[i]).abs();
                let bound = bound_c[i] * EPS + 2.0 * dfdmu[i].abs() * dmu + 0.5 * ulp(refs[i]);
                if refs[i] != 0.0 {
                    w.ulps = w.ulps.max(err / ulp(refs[i]));
                    w.rel = w.rel.max(err / refs[i].abs());
                    w.rel_scale = w.rel_scale.max(bound_c[i] / refs[i].abs());
                }
                let ratio = err / bound;
                if ratio > w.ratio {
                    w.ratio = ratio;
                    w.ratio_where = format!("{tag} out[{i}]");
                }
                if !(err <= bound) {
                    failures.push(format!(
                        "{kernel} ({}) [{tag}] out[{i}]: generated {:e} reference {:e} err {err:e} > bound {bound:e}",
                        module.name(kernel),
                        gen_out[i],
                        refs[i]
                    ));
                }
            }
        }
        let _ = writeln!(
            table,
            "{:<24} {:<22} {:>6} {:>12.1} {:>12.3e} {:>12.3e} {:>12.3e}  {}",
            kernel,
            module.name(kernel),
            w.points,
            w.ulps,
            w.rel,
            w.ratio,
            w.rel_scale,
            w.ratio_where
        );
    }
    println!("{table}");
    let target = std::env::var_os("CARGO_TARGET_DIR").map_or_else(
        || std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target"),
        std::path::PathBuf::from,
    );
    std::fs::create_dir_all(&target).expect("target dir");
    std::fs::write(target.join("kernel_ulps.txt"), &table).expect("write report");
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
