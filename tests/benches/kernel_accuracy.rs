//! Accuracy against the SymPy reference and side-by-side speed of the generated kernels and the
//! generic nalgebra path (a `harness = false` bench: `cargo bench -p walker-tests --bench
//! kernel_accuracy`).
//!
//! Accuracy: for every reference point of `tests/data/<kernel>.json` the normwise relative error
//! `max_i |out_i - ref_i| / max_i |ref_i|`, in units of `f64::EPSILON` ("ulps of the largest
//! output"); median and worst over the points, for the generated `general_*` kernels (every
//! point), the Table-1 kernels `active_level` / `passive_slope` (the points tagged `table1`,
//! the only ones at Table 1) and the lean generic path (`common`). Friction enters every path
//! the same way: the reference `mu` is realised as `xd = atanh(-mu / mu0) cos(phi) / c`
//! (`mu0 = 2.5`, `c = 1`) and each path computes `mu = -mu0 tanh(c xd [/ cos phi])` itself.
//!
//! Speed: every candidate evaluated over the same 1024 seeded Table-1 points, the candidates of
//! one kernel interleaved round by round, median of 41 rounds; ratios are generic / generated.

mod common;

use std::collections::HashMap;
use std::hint::black_box;
use std::time::Instant;

use common::{Input, inputs};
use nalgebra::Vector4;
use serde_json::Value;
use walker_tests::scenes::{
    active_level as al, general_level as gl, general_slope as gs, passive_slope as ps,
};
use walker_tests::{EPS, Phys, mu_law, xd_for_mu};

const MU0_REF: f64 = 2.5;
const C_REF: f64 = 1.0;

struct Point {
    tag: String,
    v: HashMap<String, f64>,
    out: Vec<f64>,
}

impl Point {
    fn get(&self, k: &str) -> f64 {
        self.v.get(k).copied().unwrap_or(f64::NAN)
    }
    fn or(&self, k: &str, d: f64) -> f64 {
        self.v.get(k).copied().unwrap_or(d)
    }
    fn phys(&self) -> Phys {
        Phys {
            m1: self.or("m1", 2.0),
            m2: self.or("m2", 1.0),
            l: self.or("l", 1.0),
            i1: self.or("I1", 0.5),
            i2: self.or("I2", 1.0),
            g: self.or("g", 9.81),
            alpha: self.or("alpha", 0.5),
            phi: self.or("phi", 0.0),
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
    /// The realised friction input: `xd` and the `mu` every path computes from it.
    fn friction(&self) -> (f64, f64) {
        let phi = self.or("phi", 0.0);
        let xd = xd_for_mu(self.get("mu"), MU0_REF, C_REF, phi);
        (xd, mu_law(MU0_REF, C_REF, phi, xd))
    }
}

fn load(kernel: &str) -> Vec<Point> {
    let path = format!("{}/data/{kernel}.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("reference data readable");
    let doc: Value = serde_json::from_str(&text).expect("reference data is JSON");
    let names: Vec<String> = doc["inputs"]
        .as_array()
        .expect("inputs array")
        .iter()
        .map(|n| n.as_str().expect("input name").to_owned())
        .collect();
    let num = |v: &Value| -> f64 {
        v.as_str()
            .expect("decimal string")
            .parse()
            .expect("decimal")
    };
    doc["points"]
        .as_array()
        .expect("points array")
        .iter()
        .map(|p| Point {
            tag: p["tag"].as_str().unwrap_or("").to_owned(),
            v: names
                .iter()
                .cloned()
                .zip(p["in"].as_array().expect("in").iter().map(num))
                .collect(),
            out: p["out"].as_array().expect("out").iter().map(num).collect(),
        })
        .collect()
}

fn err_ulps(got: &[f64], reference: &[f64]) -> f64 {
    let scale = reference.iter().fold(0.0_f64, |m, r| m.max(r.abs()));
    let diff = got
        .iter()
        .zip(reference)
        .fold(0.0_f64, |m, (g, r)| m.max((g - r).abs()));
    if diff.is_nan() {
        f64::INFINITY
    } else {
        diff / scale / EPS
    }
}

fn gl_prep(p: &Phys) -> gl::Prepared {
    p.level_kernels((MU0_REF, C_REF), (0.3, 0.0, 0.0))
}

fn gs_prep(p: &Phys) -> gs::Prepared {
    p.slope_kernels((MU0_REF, C_REF))
}

fn al_prep() -> al::Prepared {
    al::prepare(&al::Params {
        mu0: MU0_REF,
        c: C_REF,
        t_set: 0.3,
        k_p: 0.0,
        k_d: 0.0,
    })
}

/// `(general, table1 or None, generic)` outputs at one reference point.
fn eval(kernel: &str, pt: &Point) -> (Vec<f64>, Option<Vec<f64>>, Vec<f64>) {
    let p = pt.phys();
    let th1 = pt.get("th1");
    let t1 = pt.tag == "table1";
    let kl = gl_prep(&p);
    let ks = gs_prep(&p);
    let ka = al_prep();
    let kp = ps::prepare(&ps::Params {
        phi: p.phi,
        mu0: MU0_REF,
        c: C_REF,
    });
    let qd = pt.qd();
    let (a, b, c, d) = (qd[0], qd[1], qd[2], qd[3]);
    match kernel {
        "accel_level" => {
            let (xd, mu) = pt.friction();
            let (w, u) = (pt.get("th1d"), pt.get("u"));
            (
                gl::accel_level(&kl, th1, w, u, xd).to_vec(),
                t1.then(|| al::accel_level(&ka, th1, w, u, xd).to_vec()),
                common::generic_accel(&p, th1, w, u, mu).0.to_vec(),
            )
        }
        "closed_loop_level" => {
            let (xd, mu) = pt.friction();
            let (w, v) = (pt.get("th1d"), pt.get("v"));
            let (q, _, _, u) = common::generic_closed_loop(&p, th1, w, mu, v);
            (
                gl::closed_loop_level(&kl, th1, w, xd, v).to_vec(),
                t1.then(|| al::closed_loop_level(&ka, th1, w, xd, v).to_vec()),
                vec![q[0], q[1], q[2], q[3], u],
            )
        }
        "control_level" => {
            let (xd, mu) = pt.friction();
            let w = pt.get("th1d");
            (
                gl::control_level(&kl, th1, w, xd).to_vec(),
                t1.then(|| al::control_level(&ka, th1, w, xd).to_vec()),
                common::generic_control(&p, th1, w, mu).to_vec(),
            )
        }
        "lambda_level" => {
            let (xd, mu) = pt.friction();
            let (w, u) = (pt.get("th1d"), pt.get("u"));
            (
                vec![gl::lambda_level(&kl, th1, w, u, xd)],
                t1.then(|| vec![al::lambda_level(&ka, th1, w, u, xd)]),
                vec![common::generic_accel(&p, th1, w, u, mu).1],
            )
        }
        "projection_level" => {
            let (xd, mu) = pt.friction();
            (
                gl::projection_level(&kl, th1, xd).concat(),
                t1.then(|| al::projection_level(&ka, th1, xd).concat()),
                common::generic_projection(&p, th1, mu).to_vec(),
            )
        }
        "impact2_level" => (
            gl::impact2_level(&kl, th1, a, b, c, d).to_vec(),
            t1.then(|| al::impact2_level(&ka, th1, a, b, c, d).to_vec()),
            common::generic_impact2_level(&p, th1, qd).to_vec(),
        ),
        "impact3_level" => (
            gl::impact3_level(&kl, th1, a, b, c, d).to_vec(),
            t1.then(|| al::impact3_level(&ka, th1, a, b, c, d).to_vec()),
            common::generic_impact3_level(&p, th1, qd).to_vec(),
        ),
        "impact_slope" => (
            gs::impact_slope(&ks, th1, a, b, c, d).to_vec(),
            t1.then(|| ps::impact_slope(&kp, th1, a, b, c, d).to_vec()),
            common::generic_impact_slope(&p, th1, qd).to_vec(),
        ),
        "accel_slope" => {
            let (xd, mu) = pt.friction();
            let w = pt.get("th1d");
            (
                gs::accel_slope(&ks, th1, w, xd).to_vec(),
                t1.then(|| ps::accel_slope(&kp, th1, w, xd).to_vec()),
                common::generic_accel_slope(&p, th1, w, mu).0.to_vec(),
            )
        }
        _ => (Vec::new(), None, Vec::new()),
    }
}

fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn worst(v: &[f64]) -> f64 {
    v.iter().copied().fold(0.0, f64::max)
}

/// Accuracy row: `[med, worst]` for general (random+edge), table1, generic (random+edge),
/// and the worst over the random points only for general and generic.
struct Acc {
    general: Vec<f64>,
    general_random: Vec<f64>,
    table1: Vec<f64>,
    generic: Vec<f64>,
    generic_random: Vec<f64>,
    generic_table1: Vec<f64>,
}

fn accuracy(kernel: &str) -> Acc {
    let mut acc = Acc {
        general: Vec::new(),
        general_random: Vec::new(),
        table1: Vec::new(),
        generic: Vec::new(),
        generic_random: Vec::new(),
        generic_table1: Vec::new(),
    };
    for pt in load(kernel) {
        let (g, t, n) = eval(kernel, &pt);
        let (eg, en) = (err_ulps(&g, &pt.out), err_ulps(&n, &pt.out));
        acc.general.push(eg);
        acc.generic.push(en);
        if pt.tag == "random" {
            acc.general_random.push(eg);
            acc.generic_random.push(en);
        }
        if let Some(t) = t {
            acc.table1.push(err_ulps(&t, &pt.out));
            acc.generic_table1.push(en);
        }
    }
    acc
}

type Cand<'a> = (&'a str, Box<dyn Fn(&[Input]) -> f64 + 'a>);

/// Median ns per evaluation of each candidate, interleaved over `rounds`.
fn time_side_by_side(xs: &[Input], cands: &[Cand<'_>], rounds: usize) -> Vec<f64> {
    let mut samples = vec![Vec::with_capacity(rounds); cands.len()];
    for (_, f) in cands {
        black_box(f(xs));
    }
    for _ in 0..rounds {
        for (k, (_, f)) in cands.iter().enumerate() {
            let t0 = Instant::now();
            for _ in 0..8 {
                black_box(f(black_box(xs)));
            }
            samples[k].push(t0.elapsed().as_secs_f64() * 1e9 / (8 * xs.len()) as f64);
        }
    }
    samples.iter_mut().map(|s| median(s)).collect()
}

fn main() {
    let xs = inputs();
    let p0 = Phys::table1(0.0);
    let ps_ = Phys::table1(0.2);
    let (mu0, c) = (common::MU0, common::C);
    let ka = al::prepare(&al::Params {
        mu0,
        c,
        t_set: 0.3,
        k_p: 0.0,
        k_d: 0.0,
    });
    let kl = gl::prepare(&gl::Params {
        m1: 2.0,
        m2: 1.0,
        l: 1.0,
        i1: 0.5,
        i2: 1.0,
        g: 9.81,
        alpha: p0.alpha,
        mu0,
        c,
        t_set: 0.3,
        k_p: 0.0,
        k_d: 0.0,
    });
    let kp = ps::prepare(&ps::Params { phi: 0.2, mu0, c });
    let ks = gs::prepare(&gs::Params {
        m1: 2.0,
        m2: 1.0,
        l: 1.0,
        i1: 0.5,
        i2: 1.0,
        g: 9.81,
        alpha: ps_.alpha,
        phi: 0.2,
        mu0,
        c,
    });
    let (ka, kl, kp, ks) = (&ka, &kl, &kp, &ks);
    let (p0, ps_) = (&p0, &ps_);

    // Right-hand side of the closed loop: A, B -> u = (v + B) / A -> qdd.
    let rhs: Vec<Cand<'_>> = vec![
        (
            "active_level control_level + accel_level",
            Box::new(move |xs: &[Input]| {
                xs.iter().fold(0.0, |s, x| {
                    let [a, b] = al::control_level(ka, x.th1, x.th1d, x.xd);
                    let u = (x.v + b) / a;
                    let q = al::accel_level(ka, x.th1, x.th1d, u, x.xd);
                    s + q[0] + q[2] + q[3]
                })
            }),
        ),
        (
            "general_level control_level + accel_level",
            Box::new(move |xs: &[Input]| {
                xs.iter().fold(0.0, |s, x| {
                    let [a, b] = gl::control_level(kl, x.th1, x.th1d, x.xd);
                    let u = (x.v + b) / a;
                    let q = gl::accel_level(kl, x.th1, x.th1d, u, x.xd);
                    s + q[0] + q[2] + q[3]
                })
            }),
        ),
        (
            "generic LU",
            Box::new(move |xs: &[Input]| {
                xs.iter().fold(0.0, |s, x| {
                    let mu = mu_law(mu0, c, 0.0, x.xd);
                    let (q, _, _, _) = common::generic_closed_loop(p0, x.th1, x.th1d, mu, x.v);
                    s + q[0] + q[2] + q[3]
                })
            }),
        ),
        (
            "active_level closed_loop_level (one call: what the simulator evaluates)",
            Box::new(move |xs: &[Input]| {
                xs.iter().fold(0.0, |s, x| {
                    let q = al::closed_loop_level(ka, x.th1, x.th1d, x.xd, x.v);
                    s + q[0] + q[2] + q[3]
                })
            }),
        ),
        (
            "general_level closed_loop_level (one call)",
            Box::new(move |xs: &[Input]| {
                xs.iter().fold(0.0, |s, x| {
                    let q = gl::closed_loop_level(kl, x.th1, x.th1d, x.xd, x.v);
                    s + q[0] + q[2] + q[3]
                })
            }),
        ),
        (
            "std sin_cos + std tanh alone (what the generic path pays for them)",
            Box::new(move |xs: &[Input]| {
                xs.iter().fold(0.0, |s, x| {
                    let (a, b) = x.th1.sin_cos();
                    s + a + b + (c * x.xd).tanh() + x.v
                })
            }),
        ),
        (
            "test-suite generic",
            Box::new(move |xs: &[Input]| {
                xs.iter().fold(0.0, |s, x| {
                    let mu = mu_law(mu0, c, 0.0, x.xd);
                    let ab = walker_tests::control(p0, x.th1, x.th1d, mu).expect("regular");
                    let u = (x.v + ab[1]) / ab[0];
                    let st = walker_tests::stance(p0, x.th1, x.th1d, u, mu).expect("regular");
                    s + st.qdd[0] + st.qdd[2] + st.qdd[3]
                })
            }),
        ),
    ];
    let lam: Vec<Cand<'_>> = vec![
        (
            "active_level",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| al::lambda_level(ka, x.th1, x.th1d, x.u, x.xd))
                    .sum()
            }),
        ),
        (
            "general_level",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| gl::lambda_level(kl, x.th1, x.th1d, x.u, x.xd))
                    .sum()
            }),
        ),
        (
            "generic LU",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| {
                        common::generic_accel(p0, x.th1, x.th1d, x.u, mu_law(mu0, c, 0.0, x.xd)).1
                    })
                    .sum()
            }),
        ),
    ];
    let proj: Vec<Cand<'_>> = vec![
        (
            "active_level",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| al::projection_level(ka, x.th1, x.xd)[0][1])
                    .sum()
            }),
        ),
        (
            "general_level",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| gl::projection_level(kl, x.th1, x.xd)[0][1])
                    .sum()
            }),
        ),
        (
            "generic inverse",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| common::generic_projection(p0, x.th1, mu_law(mu0, c, 0.0, x.xd))[1])
                    .sum()
            }),
        ),
    ];
    let qd = |x: &Input| Vector4::new(x.xd, x.zd, x.th1d, x.th2d);
    let imp2: Vec<Cand<'_>> = vec![
        (
            "active_level",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| al::impact2_level(ka, x.th1, x.xd, x.zd, x.th1d, x.th2d)[2])
                    .sum()
            }),
        ),
        (
            "general_level",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| gl::impact2_level(kl, x.th1, x.xd, x.zd, x.th1d, x.th2d)[2])
                    .sum()
            }),
        ),
        (
            "generic LU",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| common::generic_impact2_level(p0, x.th1, qd(x))[2])
                    .sum()
            }),
        ),
    ];
    let imp3: Vec<Cand<'_>> = vec![
        (
            "active_level",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| al::impact3_level(ka, x.th1, x.xd, x.zd, x.th1d, x.th2d)[3])
                    .sum()
            }),
        ),
        (
            "general_level",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| gl::impact3_level(kl, x.th1, x.xd, x.zd, x.th1d, x.th2d)[3])
                    .sum()
            }),
        ),
        (
            "generic LU",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| common::generic_impact3_level(p0, x.th1, qd(x))[3])
                    .sum()
            }),
        ),
    ];
    let imps: Vec<Cand<'_>> = vec![
        (
            "passive_slope",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| ps::impact_slope(kp, x.th1, x.xd, x.zd, x.th1d, x.th2d)[1])
                    .sum()
            }),
        ),
        (
            "general_slope",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| gs::impact_slope(ks, x.th1, x.xd, x.zd, x.th1d, x.th2d)[1])
                    .sum()
            }),
        ),
        (
            "generic LU",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| common::generic_impact_slope(ps_, x.th1, qd(x))[1])
                    .sum()
            }),
        ),
    ];
    let accs: Vec<Cand<'_>> = vec![
        (
            "passive_slope",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| ps::accel_slope(kp, x.th1, x.th1d, x.xd)[0])
                    .sum()
            }),
        ),
        (
            "general_slope",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| gs::accel_slope(ks, x.th1, x.th1d, x.xd)[0])
                    .sum()
            }),
        ),
        (
            "generic LU",
            Box::new(move |xs: &[Input]| {
                xs.iter()
                    .map(|x| {
                        common::generic_accel_slope(ps_, x.th1, x.th1d, mu_law(mu0, c, 0.2, x.xd)).0
                            [0]
                    })
                    .sum()
            }),
        ),
    ];

    let rounds: usize = std::env::var("KERNEL_ROUNDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(41);
    println!(
        "# Speed: ns per evaluation, median of {rounds} interleaved rounds over 1024 seeded Table-1 points"
    );
    println!("| kernel | candidate | ns/eval | generic / this |");
    println!("|---|---|---:|---:|");
    let groups: [(&str, &[Cand<'_>]); 7] = [
        (
            "rhs: closed loop, u = (v + B)/A then qdd (Eqs. 27, 31)",
            &rhs,
        ),
        ("lambda_level", &lam),
        ("projection_level (Y)", &proj),
        ("impact2_level", &imp2),
        ("impact3_level", &imp3),
        ("impact_slope (phi = 0.2)", &imps),
        ("accel_slope (phi = 0.2)", &accs),
    ];
    for (name, cands) in groups {
        let t = time_side_by_side(&xs, cands, rounds);
        let generic = t[2];
        for (k, (cn, _)) in cands.iter().enumerate() {
            println!("| {name} | {cn} | {:.1} | {:.2}x |", t[k], generic / t[k]);
        }
    }

    println!();
    println!("# Accuracy vs SymPy (30 digits): normwise relative error in eps, median / worst");
    println!(
        "| kernel | points | general_* gen. | generic LU | worst on random pts: gen. / generic | Table-1 kernel (table1 pts) | generic (table1 pts) |"
    );
    println!("|---|---:|---|---|---|---|---|");
    for kernel in [
        "closed_loop_level",
        "accel_level",
        "control_level",
        "lambda_level",
        "projection_level",
        "impact2_level",
        "impact3_level",
        "impact_slope",
        "accel_slope",
    ] {
        let mut a = accuracy(kernel);
        let n = a.general.len();
        let (wg, wn) = (worst(&a.general), worst(&a.generic));
        let (wgr, wnr) = (worst(&a.general_random), worst(&a.generic_random));
        let (wt, wtn) = (worst(&a.table1), worst(&a.generic_table1));
        let (mg, mn) = (median(&mut a.general), median(&mut a.generic));
        let (mt, mtn) = (median(&mut a.table1), median(&mut a.generic_table1));
        println!(
            "| {kernel} | {n} | {mg:.2} / {wg:.3e} | {mn:.2} / {wn:.3e} | {wgr:.1} / {wnr:.1} | {mt:.2} / {wt:.2} | {mtn:.2} / {wtn:.2} |"
        );
    }
}
