//! Quick stress cases of the generated kernels (the long ones are in `src/bin/stress.rs`, whose
//! tables are in `docs/stability.md`): small and large spoke angles against an exact reference,
//! extreme mass and inertia ratios, and the vanishing denominator of `lambda` (Eq. 23).

#![allow(clippy::unwrap_used, reason = "tests")]

use crate::common;

use common::{start, table1};
use walker::model::{Args, KernelId, Model};
use walker::sim::{FailureKind, SimConfig, WalkLimits, walk};

/// The physical parameters of the wheel (Table 1 and `g`), as these cases vary them.
#[derive(Clone, Copy, Debug)]
struct Physical {
    m1: f64,
    m2: f64,
    l: f64,
    i1: f64,
    i2: f64,
    g: f64,
    alpha: f64,
}

impl Physical {
    /// Table 1 with `g = 9.81`, as the built-in scenes fix it.
    fn table1() -> Self {
        Physical {
            m1: table1("m1"),
            m2: table1("m2"),
            l: table1("l"),
            i1: table1("I1"),
            i2: table1("I2"),
            g: table1("g"),
            alpha: table1("alpha"),
        }
    }

    /// `m_t = m1 + m2` (Eq. 2).
    fn total_mass(&self) -> f64 {
        self.m1 + self.m2
    }

    /// The parameters by name.
    fn params(&self) -> [(&'static str, f64); 7] {
        [
            ("m1", self.m1),
            ("m2", self.m2),
            ("l", self.l),
            ("I1", self.i1),
            ("I2", self.i2),
            ("g", self.g),
            ("alpha", self.alpha),
        ]
    }
}

/// The active walker's kernels with every parameter at run time (the paper's `general_level`),
/// the physical parameters `ph`, friction `mu0`, `c` and the paper's control settings.
fn prepared(ph: &Physical, mu0: f64, c: f64) -> Model {
    let mut params = ph.params().to_vec();
    params.extend([
        ("mu0", mu0),
        ("c", c),
        ("T_set", 0.3),
        ("K_P", 0.0),
        ("K_D", 0.0),
    ]);
    common::active_run_time(&params)
}

/// The frictionless impact (`impact`, the paper's `impact2_level`: fore-foot impulse, torso-lock
/// impulse, then `qd+ = [xd, zd, th1d, th2d]`) at the stance angle `th1` with the velocities
/// `xd, zd, th1d, th2d`.
fn impact(p: &Model, th1: f64, qd: [f64; 4]) -> [f64; 6] {
    let mut out = [0.0; 6];
    let q = [0.0, 0.0, th1, 0.0];
    p.kernels()
        .eval(KernelId::Impact, &Args::state(&q, &qd), &mut out);
    out
}

/// `lambda` of Eqs. 22-23 (the `lambda` kernel, the paper's `lambda_level`) at the stance angle
/// `th1`, its rate `th1d`, the input `u` and the foot's velocity `xd`.
fn lambda(p: &Model, th1: f64, th1d: f64, u: f64, xd: f64) -> f64 {
    let mut out = [0.0; 1];
    let (q, qd) = ([0.0, 0.0, th1, 0.0], [xd, 0.0, th1d, 0.0]);
    let args = Args {
        u: &[u],
        ..Args::state(&q, &qd)
    };
    p.kernels().eval(KernelId::Lambda, &args, &mut out);
    out[0]
}

/// The torso-lock impulse of `impact2_level` at the heel strike of a rigid rotation (`th1 =
/// alpha/2`, stance foot at rest, `th1d = th2d = w`). With a vertical impulse at the fore foot
/// (the floor is slippery: it may slide) and the torso locked, momentum and the fore foot's
/// constraint give `w+ = w (2 I_t - m_t l^2 k) / (2 I_t + m_t l^2 k)` with `k = 1 - cos alpha`,
/// `I_t = I1 + I2`, so `|lambda_I[1]| = I2 (w - w+) = 2 I2 w m_t l^2 k / (2 I_t + m_t l^2 k)`;
/// `k = 2 sin^2(alpha/2)` (a few ulps) or naively `1 - cos alpha` (the "before").
fn torso_impulse_reference(ph: &Physical, w: f64, naive: bool) -> f64 {
    let mt = ph.total_mass();
    let one_minus_cos = if naive {
        1.0 - ph.alpha.cos()
    } else {
        2.0 * (ph.alpha / 2.0).sin().powi(2)
    };
    let ml2k = mt * ph.l * ph.l * one_minus_cos;
    2.0 * ph.i2 * w * ml2k / (2.0 * (ph.i1 + ph.i2) + ml2k)
}

/// The fore-foot impulse `4 m_t l sin(alpha/2) I_t w / (2 I_t + m_t l^2 k)` and `w+` of the
/// same rigid heel strike (see [`torso_impulse_reference`]).
fn fore_impulse_and_w_plus(ph: &Physical, w: f64) -> [f64; 2] {
    let (mt, it) = (ph.total_mass(), ph.i1 + ph.i2);
    let s = (ph.alpha / 2.0).sin();
    let ml2k = 2.0 * mt * ph.l * ph.l * s * s;
    [
        4.0 * mt * ph.l * s * it * w / (2.0 * it + ml2k),
        w * (2.0 * it - ml2k) / (2.0 * it + ml2k),
    ]
}

fn torso_impulse_kernel(ph: &Physical, w: f64) -> f64 {
    let p = prepared(ph, 0.0, 100.0);
    impact(&p, ph.alpha / 2.0, [0.0, 0.0, w, w])[1].abs()
}

#[test]
fn small_and_large_alpha_impact_against_the_exact_closed_form() {
    for alpha in [1e-2, 1e-3, 1e-4, 1e-6, 0.5, 1.0, 2.0, 2.5] {
        let ph = Physical {
            alpha,
            ..Physical::table1()
        };
        let exact = torso_impulse_reference(&ph, 1.0, false);
        let kernel = torso_impulse_kernel(&ph, 1.0);
        let rel = ((kernel - exact) / exact).abs();
        // The kernel takes a general th1, so at th1 = alpha/2 this O(alpha^2) impulse is a
        // difference of O(1) terms: its error is ~eps / (1 - cos alpha), as the naive form's.
        let k = 1.0 - alpha.cos();
        let bound = 1e-13_f64.max(8.0 * f64::EPSILON / k);
        assert!(
            rel < bound,
            "alpha {alpha}: kernel {kernel} vs {exact} ({rel:e})"
        );
        // The fore-foot impulse and w+ have no such cancellation.
        let p = prepared(&ph, 0.0, 100.0);
        let out = impact(&p, alpha / 2.0, [0.0, 0.0, 1.0, 1.0]);
        let [foot, w_plus] = fore_impulse_and_w_plus(&ph, 1.0);
        assert!(
            ((out[0] - foot) / foot).abs() < 1e-13,
            "alpha {alpha}: {} vs {foot}",
            out[0]
        );
        assert!(((out[4] - w_plus) / w_plus).abs() < 1e-13, "alpha {alpha}");
    }
    // The naive 1 - cos alpha loses digits: ~1e-8 relative error at alpha = 1e-4, all at 1e-8.
    let ph = Physical {
        alpha: 1e-8,
        ..Physical::table1()
    };
    assert_eq!(torso_impulse_reference(&ph, 1.0, true), 0.0);
    assert!(torso_impulse_kernel(&ph, 1.0) > 0.0);
}

#[test]
fn small_alpha_walk_gives_steps_or_a_named_failure() {
    for alpha in [1e-2, 1e-3, 1e-4] {
        let ph = Physical {
            alpha,
            ..Physical::table1()
        };
        let model = prepared(&ph, 0.4, 100.0);
        let w = walk(
            &model,
            &SimConfig::default(),
            &start(&model, 0.8),
            &WalkLimits {
                max_steps: 3,
                ..WalkLimits::default()
            },
        );
        assert_no_nan(&w, &format!("alpha {alpha}"));
    }
}

fn assert_no_nan(w: &walker::sim::Walk, case: &str) {
    for s in &w.steps {
        let scalars = [s.period, s.dx, s.speed, s.rear_impulse, s.lambda_min];
        let all = s.q_plus.iter().chain(&s.qd_plus).chain(&scalars);
        for v in all.chain(s.p.iter()).chain(s.sr.iter()) {
            assert!(v.is_finite(), "{case}: non-finite step value in {s:?}");
        }
    }
    if let Some(f) = &w.failure {
        let json = serde_json::to_string(f).unwrap();
        assert!(
            !json.contains("NaN") && !json.contains("inf"),
            "{case}: {json}"
        );
    }
    assert!(
        !w.steps.is_empty() || w.failure.is_some(),
        "{case}: no step and no failure"
    );
}

#[test]
fn extreme_mass_and_inertia_ratios_never_give_nan() {
    let ratios = [1e-6, 1e-3, 1.0, 1e3, 1e6];
    let base = Physical::table1();
    for &r_m in &ratios {
        for &r_i1 in &ratios {
            for &r_i2 in &[1e-6, 1.0, 1e6] {
                let m2 = base.m1 * r_m;
                let mt = base.m1 + m2;
                let i1 = r_i1 * mt * base.l * base.l;
                let ph = Physical {
                    m2,
                    i1,
                    i2: r_i2 * i1,
                    ..base
                };
                let model = prepared(&ph, 0.4, 100.0);
                let w = walk(
                    &model,
                    &SimConfig {
                        max_step_time: 2.0,
                        ..SimConfig::default()
                    },
                    &start(&model, 0.8),
                    &WalkLimits {
                        max_steps: 3,
                        ..WalkLimits::default()
                    },
                );
                assert_no_nan(&w, &format!("m2/m1 {r_m}, I1/(m l^2) {r_i1}, I2/I1 {r_i2}"));
            }
        }
    }
}

/// The stance-leg angles where Eq. 23's denominator `2 I1 + 2 m_t l^2 s (s - mu c)` vanishes
/// (`s, c` = sine, cosine of `th1`): `cos 2th1 + mu sin 2th1 = 1 + 2 I1 / (m_t l^2)`.
fn singular_angles(ph: &Physical, mu: f64) -> Option<[f64; 2]> {
    let k = ph.i1 / (ph.total_mass() * ph.l * ph.l);
    let r = (1.0 + mu * mu).sqrt();
    let ratio = (1.0 + 2.0 * k) / r;
    (ratio <= 1.0).then(|| {
        let d = mu.atan2(1.0);
        let a = ratio.acos();
        [(d - a) / 2.0, (d + a) / 2.0]
    })
}

#[test]
fn lambda_grows_without_bound_near_the_singular_denominator_and_the_walk_names_it() {
    let ph = Physical::table1();
    // |mu| must exceed sqrt((1 + 2 I1/(m_t l^2))^2 - 1) = 0.882 for Table 1.
    assert!(singular_angles(&ph, 0.85).is_none());
    let mu0 = 2.0;
    let p = prepared(&ph, mu0, 100.0);
    // xd = -1 with c = 100: mu = -mu0 tanh(c xd) = mu0 exactly.
    for th in singular_angles(&ph, mu0).unwrap() {
        let mut last = 0.0;
        for eps in [1e-2, 1e-4, 1e-6, 1e-8] {
            let below = lambda(&p, th - eps, 1.0, 0.0, -1.0);
            let above = lambda(&p, th + eps, 1.0, 0.0, -1.0);
            assert!(below.is_finite() && above.is_finite());
            // opposite signs on the two sides, magnitude ~ 1/eps
            assert!(below * above < 0.0, "th {th} eps {eps}: {below} {above}");
            assert!(below.abs() > last && below.abs() * eps > 1.0);
            last = below.abs();
        }
    }
    // The passive wheel (u = 0; phi = 0 is level ground, so Eq. 23 holds) started next to the
    // singular angle, rolling towards it, reports the named failure. (The active walker's
    // control input moves the pole: its closed-loop lambda is finite there.)
    let mut params = ph.params().to_vec();
    params.extend([("mu0", mu0), ("phi", 0.0), ("c", 100.0)]);
    let model = common::passive_run_time(&params);
    let th = singular_angles(&ph, mu0).unwrap()[0];
    let start = [0.0, 0.0, th - 1e-9, 0.0, -1.0, 0.0, 1.0, 1.0];
    let w = walk(
        &model,
        &SimConfig::default(),
        &start,
        &WalkLimits::default(),
    );
    assert!(
        matches!(
            w.failure.as_ref().map(|f| &f.kind),
            Some(FailureKind::LambdaDenominatorZero { .. })
        ),
        "{:?}",
        w.failure
    );
    assert_no_nan(&w, "singular start");
}
