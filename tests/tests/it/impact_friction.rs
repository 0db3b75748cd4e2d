//! The library's plastic impact with Coulomb friction at the striking foot
//! (`walker::model::plastic_coulomb` and `rear_test` on `Ingredients::from_kernel` of the
//! generated `impact_coulomb_level` / `impact_coulomb_slope` of the Coulomb scenes) against
//! the independent SymPy/mpmath reference `tests/data/impact_friction.json`
//! (`sympy_ref/impact_friction.py`: Stronge's incremental model, W. J. Stronge, *Impact
//! Mechanics*, Cambridge University Press, 2000, Ch. 5, with restitution zero, solved from `M`
//! and the contact geometry by KKT systems and by numerical integration in the normal
//! impulse), and its properties over random pre-impact states and `mu0` in `[0, 3]` on both
//! floors: the kinetic energy never increases, the impulse lies in the friction cone, the foot
//! ends at rest after a stick and on the floor, slipping the regime's way, after a slide, and
//! `mu0 = 0` gives back the frictionless maps (`impact2_level` / `impact_slope`, and the rear
//! test impulse of `impact3_level` / `impact2_slope`).
//!
//! Error model of the properties (`C_LAW`, `condition`): the kernel's 21 outputs are within
//! `C_SOLVE = 256` eps of their scale (`kernels_vs_nalgebra.rs`, same argument); the friction
//! law is at most ~20 further roundings; its divisions amplify relative input errors by the
//! condition of the regime's linear solve, `kappa` ([`condition`]). Every tolerance below is
//! `C_LAW * eps * kappa` times the absolute-value magnitude of the quantity's formula, with
//! `C_LAW = 2 * 256 + 20 * 2 < 600`.
#![allow(clippy::unwrap_used, clippy::panic, reason = "test code")]
#![allow(
    clippy::neg_cmp_op_on_partial_ord,
    reason = "`!(err <= bound)` also fails on NaN"
)]

use nalgebra::Vector4;
use proptest::prelude::*;
use serde_json::Value;
use walker::model::{ImpactRegime, Ingredients, Slide, in_regime, plastic_coulomb, rear_test};
use walker_tests::scenes::{general_level_coulomb as glc, general_slope_coulomb as gsc};
use walker_tests::{EPS, Phys, cases};

/// See the module documentation.
const C_LAW: f64 = 600.0;

/// Relative tolerance against the reference cases. Each case's regime decisions and
/// denominators are at least `min_margin >= 0.01` (relative) away from zero (asserted by the
/// generator and checked here), so a relative perturbation `delta` of the 21 kernel outputs
/// moves the impulse, the velocities and the rear test by at most about
/// `20 delta / min_margin` relative (at most ~20 operations, each denominator at least the
/// margin times its terms). With `delta <= C_LAW eps` (module documentation):
/// `20 * 600 * 2.2e-16 / 0.01 = 2.7e-10`; the reference itself is exact to 30 digits.
const REL_REFERENCE: f64 = 3e-10;

/// The Coulomb scenes' impact ingredients at the point (`mu0` does not enter these kernels).
fn ingredients(p: &Phys, slope: bool, th1: f64, qd: Vector4<f64>) -> Ingredients {
    let [xd, zd, w1, w2] = [qd[0], qd[1], qd[2], qd[3]];
    let out = if slope {
        gsc::impact_coulomb_slope(&p.slope_coulomb_kernels(1.0), th1, xd, zd, w1, w2)
    } else {
        glc::impact_coulomb_level(
            &p.level_coulomb_kernels(1.0, (0.5, 1.0, 1.0)),
            th1,
            xd,
            zd,
            w1,
            w2,
        )
    };
    Ingredients::from_kernel(4, &out)
}

/// `qd+ = qd_L + R Lambda` of the paper's walker (four coordinates).
fn velocity(ing: &Ingredients, lambda: [f64; 2]) -> [f64; 4] {
    let v = ing.velocity(lambda);
    [v[0], v[1], v[2], v[3]]
}

/// The regime's name in the reference file.
fn regime_name(r: ImpactRegime) -> String {
    let d = |s: Slide| match s {
        Slide::Forward => "forward",
        Slide::Backward => "backward",
    };
    match r {
        ImpactRegime::Frictionless => "frictionless".to_owned(),
        ImpactRegime::Stick => "stick".to_owned(),
        ImpactRegime::Slide(s) => format!("slide-{}", d(s)),
        ImpactRegime::Reverse(s) => format!("reverse-{}", d(s)),
    }
}

/// `kappa`: the relative condition of the regime's impulse in `W` and `v` (absolute-value
/// magnitude of the divisor's terms over the divisor): `||W|| ||W^-1||` (1-norm, 2x2) for a
/// stick, `(W_nn + mu0 |W_tn|) / |W_nn - s mu0 W_tn|` per sliding phase, and for a reversal
/// also the slip-stop divisor `(|W_tn| + mu0 W_tt) / |W_tn - s mu0 W_tt|`.
fn condition(ing: &Ingredients, mu0: f64, regime: ImpactRegime) -> f64 {
    let w = &ing.w;
    let slide = |s: f64| (w[1][1] + mu0 * w[0][1].abs()) / (w[1][1] - s * mu0 * w[0][1]).abs();
    match regime {
        ImpactRegime::Stick => {
            let det = w[0][0] * w[1][1] - w[0][1] * w[0][1];
            let n1 = (w[0][0] + w[0][1].abs()).max(w[1][1] + w[0][1].abs());
            n1 * n1 / det.abs()
        }
        ImpactRegime::Slide(s) => slide(s.sigma()),
        ImpactRegime::Reverse(s) => {
            let stop =
                (w[0][1].abs() + mu0 * w[0][0]) / (w[0][1] - s.sigma() * mu0 * w[0][0]).abs();
            slide(s.sigma()).max(slide(-s.sigma())).max(stop)
        }
        ImpactRegime::Frictionless => 1.0,
    }
}

fn parse(v: &Value) -> f64 {
    v.as_str()
        .expect("decimal string")
        .parse()
        .expect("decimal number")
}

/// One reference case: the library's result against the file's, or why not.
fn check_case(c: &Value) -> Result<f64, String> {
    let name = c["name"].as_str().unwrap_or("?");
    let slope = c["floor"].as_str() == Some("slope");
    let par = &c["params"];
    let get = |k: &str| parse(&par[k]);
    let p = Phys {
        m1: get("m1"),
        m2: get("m2"),
        l: get("l"),
        i1: get("I1"),
        i2: get("I2"),
        g: get("g"),
        alpha: get("alpha"),
        phi: if slope { get("phi") } else { 0.0 },
    };
    let th1 = parse(&c["th1"]);
    let q: Vec<f64> = c["qd_minus"]
        .as_array()
        .unwrap()
        .iter()
        .map(parse)
        .collect();
    let qd = Vector4::new(q[0], q[1], q[2], q[3]);
    let mu0 = parse(&c["mu0"]);
    let margin: f64 = c["min_margin"].as_str().unwrap().parse().unwrap();
    assert!(
        margin >= 0.01,
        "{name}: the reference case's margin {margin} < 0.01"
    );
    let ing = ingredients(&p, slope, th1, qd);
    let (lam, regime) = plastic_coulomb(&ing, mu0).map_err(|e| {
        // What the reference's regime would give with these ingredients (for the report).
        let alt = match c["regime"].as_str() {
            Some("stick") => in_regime(&ing, mu0, ImpactRegime::Stick),
            _ => None,
        };
        let r: Vec<f64> = c["impulse"]
            .as_array()
            .map_or(Vec::new(), |a| a.iter().map(parse).collect());
        format!(
            "{name}: the library fails ({e}) where the reference has a {} impact with \
             Lambda = {r:?}; the stick impulse in_regime(Stick) = {alt:?}",
            c["regime"]
        )
    })?;
    let want = c["regime"].as_str().unwrap();
    if regime_name(regime) != want {
        return Err(format!(
            "{name}: regime {} != reference {want}",
            regime_name(regime)
        ));
    }
    let mut worst: f64 = 0.0;
    let mut cmp = |what: &str, got: f64, r: f64, scale: f64| -> Result<(), String> {
        let err = (got - r).abs();
        let tol = REL_REFERENCE * (r.abs() + scale);
        worst = worst.max(err / (r.abs() + scale));
        if !(err <= tol) {
            return Err(format!(
                "{name} {what}: library {got:e} reference {r:e} err {err:e} > {tol:e}"
            ));
        }
        Ok(())
    };
    // Natural scales: the velocities' |qd_L|, the impulses' |v| / W_nn.
    let vscale = ing.qdl.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    let iscale = ing.v.iter().fold(0.0f64, |a, x| a.max(x.abs())) / ing.w[1][1];
    for (i, r) in c["impulse"].as_array().unwrap().iter().enumerate() {
        cmp(&format!("Lambda[{i}]"), lam[i], parse(r), iscale)?;
    }
    let qp = velocity(&ing, lam);
    for (i, r) in c["qd_plus"].as_array().unwrap().iter().enumerate() {
        cmp(&format!("qd+[{i}]"), qp[i], parse(r), vscale)?;
    }
    let rear = rear_test(&ing, mu0, lam, regime);
    cmp("rear test", rear, parse(&c["rear_impulse"]), iscale)?;
    Ok(worst)
}

fn reference_cases(growing: bool) -> Vec<Value> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("data/impact_friction.json");
    let json: Value =
        serde_json::from_str(&std::fs::read_to_string(path).expect("readable")).expect("JSON");
    json["cases"]
        .as_array()
        .expect("cases")
        .iter()
        .filter(|c| c["approach_grows_while_slipping"].as_bool() == Some(growing))
        .cloned()
        .collect()
}

fn run_reference(growing: bool) {
    let cases = reference_cases(growing);
    assert!(!cases.is_empty(), "no reference cases");
    let mut failures = Vec::new();
    let mut worst: f64 = 0.0;
    for c in &cases {
        match check_case(c) {
            Ok(w) => worst = worst.max(w),
            Err(e) => failures.push(e),
        }
    }
    println!("{} cases, worst relative error {worst:e}", cases.len());
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// Stick, slide forward and backward, reverse and `mu0 = 0`, on both floors at Table 1 and at
/// a second parameter set.
#[test]
fn matches_reference_stronge() {
    let cases = reference_cases(false);
    for want in [
        "stick",
        "slide-forward",
        "slide-backward",
        "reverse-backward",
    ] {
        assert!(
            cases.iter().any(|c| c["regime"].as_str() == Some(want)),
            "the reference covers {want}"
        );
    }
    run_reference(false);
}

/// The cases where, while the foot slips, more normal impulse makes it approach faster
/// (`W_nn - s mu0 W_tn <= 0`): in Stronge's model the slip still decelerates and stops within
/// finite impulse (for a positive definite `W`, `s (W_tn - s mu0 W_tt) < 0` follows), and the
/// foot then sticks, so the impact has a solution; the reference (both of its methods) says
/// stick.
#[test]
fn matches_reference_when_the_approach_grows_while_slipping() {
    run_reference(true);
}

fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo.log10()..hi.log10()).prop_map(|e| 10f64.powf(e))
}

prop_compose! {
    /// Parameters within an order of magnitude of Table 1's.
    fn phys(slope: bool)(
        m1 in log_uniform(0.2, 5.0), m2 in log_uniform(0.2, 5.0), i1 in log_uniform(0.05, 2.0),
        i2 in log_uniform(0.05, 2.0), l in 0.3f64..3.0, alpha in 0.1f64..1.5, phi in 0.0f64..0.4,
    ) -> Phys {
        Phys { m1, m2, l, i1, i2, g: 9.81, alpha, phi: if slope { phi } else { 0.0 } }
    }
}

/// A pre-impact state at the heel strike: `th1 = alpha/2 (+ phi)`, the stance foot on the floor
/// (`zd = 0`, `-xd tan phi` on the slope), with the velocities' sign chosen so that the fore
/// foot approaches the floor (`v_n` is linear in `qd-`).
fn heel_strike(
    p: &Phys,
    slope: bool,
    xd: f64,
    th1d: f64,
    th2d: f64,
) -> (f64, Vector4<f64>, Ingredients) {
    let th1 = p.alpha / 2.0 + p.phi;
    let qd = Vector4::new(xd, -xd * p.phi.tan(), th1d, th2d);
    let ing = ingredients(p, slope, th1, qd);
    if ing.v[1] < 0.0 {
        (th1, qd, ing)
    } else {
        (th1, -qd, ingredients(p, slope, th1, -qd))
    }
}

/// The fore foot's velocity along the floor's tangent and normal at `qd` (the `fore_foot`
/// kernel's Cartesian velocity projected).
fn foot_velocity(p: &Phys, slope: bool, th1: f64, qd: [f64; 4]) -> [f64; 2] {
    let f = if slope {
        gsc::fore_foot(
            &p.slope_coulomb_kernels(1.0),
            0.0,
            0.0,
            th1,
            qd[0],
            qd[1],
            qd[2],
        )
    } else {
        glc::fore_foot(
            &p.level_coulomb_kernels(1.0, (0.5, 1.0, 1.0)),
            0.0,
            0.0,
            th1,
            qd[0],
            qd[1],
            qd[2],
        )
    };
    let (s, c) = p.phi.sin_cos();
    [f[2] * c - f[3] * s, f[2] * s + f[3] * c]
}

/// Kinetic energy by the `energy` kernel.
fn kinetic(p: &Phys, slope: bool, th1: f64, qd: [f64; 4]) -> f64 {
    if slope {
        gsc::energy(
            &p.slope_coulomb_kernels(1.0),
            0.0,
            th1,
            qd[0],
            qd[1],
            qd[2],
            qd[3],
        )[0]
    } else {
        glc::energy(
            &p.level_coulomb_kernels(1.0, (0.5, 1.0, 1.0)),
            0.0,
            th1,
            qd[0],
            qd[1],
            qd[2],
            qd[3],
        )[0]
    }
}

fn check_properties(
    p: &Phys,
    slope: bool,
    xd: f64,
    th1d: f64,
    th2d: f64,
    mu0: f64,
) -> Result<(), TestCaseError> {
    let (th1, qd, ing) = heel_strike(p, slope, xd, th1d, th2d);
    prop_assert!(ing.v[1] < 0.0, "the fore foot approaches");
    // W is positive definite, so Stronge's model never jams: slipping in `s` along
    // d = (-s mu0, 1), d.W d > 0 means that where the approach grows (d_n.W d <= 0) the slip
    // decelerates and stops, and after a reversal the approach always shrinks.
    let (lam, regime) = match plastic_coulomb(&ing, mu0) {
        Ok(r) => r,
        Err(jam) => {
            return Err(TestCaseError::fail(format!(
                "jam {jam:?} with W = {:?}",
                ing.w
            )));
        }
    };
    let kappa = condition(&ing, mu0, regime);
    let qp = velocity(&ing, lam);
    // Absolute-value magnitude of qd+ = qdl + R Lambda, the impulse error amplified by kappa.
    let dq: Vec<f64> = (0..4)
        .map(|i| {
            ing.qdl[i].abs()
                + (ing.r[2 * i].abs() * lam[0].abs() + ing.r[2 * i + 1].abs() * lam[1].abs())
                    * (1.0 + kappa)
        })
        .collect();
    let qd_arr = [qd[0], qd[1], qd[2], qd[3]];

    // Energy: T+ <= T-. T's own evaluation error is C_LAW eps of its absolute-value form
    // (walker_tests::energy); the error of qd+ enters through dT = (M qd+) . dqd.
    let t_minus = kinetic(p, slope, th1, qd_arr);
    let t_plus = kinetic(p, slope, th1, qp);
    let m = walker_tests::mass_matrix(p, th1);
    let mq = (m * Vector4::from(qp)).abs();
    let (_, t_abs_m) = walker_tests::energy(p, 0.0, th1, qd);
    let (_, t_abs_p) = walker_tests::energy(p, 0.0, th1, Vector4::from(qp));
    let tol_t =
        C_LAW * EPS * (t_abs_m[0] + t_abs_p[0] + (0..4).map(|i| mq[i] * dq[i]).sum::<f64>());
    prop_assert!(
        t_plus <= t_minus + tol_t,
        "energy grows: {t_minus:e} -> {t_plus:e} (tol {tol_t:e}, {regime:?})"
    );

    // The friction cone, Lambda_n >= 0.
    let tol_l = C_LAW * EPS * kappa * (lam[0].abs() + lam[1].abs());
    prop_assert!(lam[1] >= -tol_l, "Lambda_n = {:e} < 0 ({regime:?})", lam[1]);
    prop_assert!(
        lam[0].abs() <= mu0 * lam[1] + tol_l,
        "outside the cone: {lam:?}, mu0 {mu0} ({regime:?})"
    );

    // The foot after the impact: the rows' magnitude times dq bounds its velocity's error.
    let v = foot_velocity(p, slope, th1, qp);
    let rows = walker_tests::contact_rows(p, th1);
    let tol_v = |k: usize| {
        C_LAW
            * EPS
            * (0..4)
                .map(|i| rows[k][i].abs() * (dq[i] + qp[i].abs()))
                .sum::<f64>()
    };
    prop_assert!(
        v[1].abs() <= tol_v(1),
        "normal velocity {:e} after the impact ({regime:?})",
        v[1]
    );
    match regime {
        ImpactRegime::Stick => {
            prop_assert!(v[0].abs() <= tol_v(0), "slip {:e} after a stick", v[0])
        }
        ImpactRegime::Slide(s) => prop_assert!(
            s.sigma() * v[0] >= -tol_v(0),
            "slip {:e} against {s:?}",
            v[0]
        ),
        ImpactRegime::Reverse(s) => prop_assert!(
            -s.sigma() * v[0] >= -tol_v(0),
            "slip {:e} not reversed from {s:?}",
            v[0]
        ),
        ImpactRegime::Frictionless => {
            prop_assert!(false, "frictionless regime from the Coulomb law")
        }
    }
    Ok(())
}

/// `mu0 = 0`: the frictionless maps. The frictionless kernels are within `C_SOLVE eps` of the
/// generic impact's scale (`kernels_vs_nalgebra.rs`), and so is this route (`kappa = 1` at
/// `mu0 = 0`: the one divisor is `W_nn`); `2 * C_LAW` covers both.
fn check_frictionless(
    p: &Phys,
    slope: bool,
    xd: f64,
    th1d: f64,
    th2d: f64,
) -> Result<(), TestCaseError> {
    let (th1, qd, ing) = heel_strike(p, slope, xd, th1d, th2d);
    let (lam, regime) =
        plastic_coulomb(&ing, 0.0).map_err(|e| TestCaseError::fail(e.to_string()))?;
    prop_assert!(
        lam[0] == 0.0 || lam[0] == -0.0,
        "Lambda_t = {} at mu0 = 0",
        lam[0]
    );
    let qp = velocity(&ing, lam);
    let rear = rear_test(&ing, 0.0, lam, regime);
    let [a, b, c, d] = [qd[0], qd[1], qd[2], qd[3]];
    let (map, rear_ref, rows, rear_rows) = if slope {
        let k = p.slope_coulomb_kernels(1.0);
        let m = gsc::impact_slope(&k, th1, a, b, c, d);
        let r = gsc::impact2_slope(&k, th1, a, b, c, d);
        // impact2_slope reports the vertical component: the normal impulse times cos phi.
        (
            [m[1], m[2], m[3], m[4]],
            r[1] / p.phi.cos(),
            "impact_slope",
            "impact2_slope",
        )
    } else {
        let k = p.level_coulomb_kernels(1.0, (0.5, 1.0, 1.0));
        let m = glc::impact2_level(&k, th1, a, b, c, d);
        let r = glc::impact3_level(&k, th1, a, b, c, d);
        (
            [m[2], m[3], m[4], m[5]],
            r[1],
            "impact2_level",
            "impact3_level",
        )
    };
    let imp = walker_tests::impact(p, &walker_tests::impact_rows(rows, p, th1), th1, qd)
        .map_err(TestCaseError::fail)?;
    let imp_r = walker_tests::impact(p, &walker_tests::impact_rows(rear_rows, p, th1), th1, qd)
        .map_err(TestCaseError::fail)?;
    for i in 0..4 {
        let tol = 2.0 * C_LAW * EPS * imp.scale;
        prop_assert!(
            (qp[i] - map[i]).abs() <= tol,
            "qd+[{i}] {:e} vs {rows} {:e} (tol {tol:e})",
            qp[i],
            map[i]
        );
    }
    // The rear impulse: the generic scale of the three-row impact, divided by cos phi <= 1 /
    // cos 0.4 on the slope (one more rounding).
    let tol = 2.0 * C_LAW * EPS * imp_r.scale / p.phi.cos();
    prop_assert!(
        (rear - rear_ref).abs() <= tol,
        "rear {rear:e} vs {rear_rows} {rear_ref:e} (tol {tol:e})"
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), ..ProptestConfig::default() })]

    #[test]
    fn level_impact_properties(p in phys(false), xd in -3.0f64..3.0, th1d in -5.0f64..5.0, th2d in -5.0f64..5.0, mu0 in 0.0f64..3.0) {
        check_properties(&p, false, xd, th1d, th2d, mu0)?;
    }

    #[test]
    fn slope_impact_properties(p in phys(true), xd in -3.0f64..3.0, th1d in -5.0f64..5.0, th2d in -5.0f64..5.0, mu0 in 0.0f64..3.0) {
        check_properties(&p, true, xd, th1d, th2d, mu0)?;
    }

    #[test]
    fn level_mu0_zero_is_frictionless(p in phys(false), xd in -3.0f64..3.0, th1d in -5.0f64..5.0, th2d in -5.0f64..5.0) {
        check_frictionless(&p, false, xd, th1d, th2d)?;
    }

    #[test]
    fn slope_mu0_zero_is_frictionless(p in phys(true), xd in -3.0f64..3.0, th1d in -5.0f64..5.0, th2d in -5.0f64..5.0) {
        check_frictionless(&p, true, xd, th1d, th2d)?;
    }
}
