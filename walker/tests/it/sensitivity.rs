//! Parameter sensitivities of gaits (`walker::sensitivity`): against the rimless wheel's
//! closed forms (the held wheel of `rimless_wheel.rs`: `w0^2 = eta^2 K 2 sin phi sin(alpha/2)
//! / (1 - eta^2)`, multiplier `eta^2`, `eta = (I + m l^2 cos alpha) / (I + m l^2)`), against
//! differences of whole fixed-point solves at several steps, on the paper's active walker and
//! on a model file derived at run time (the tape), and the errors for names that are not
//! run-time parameters.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use crate::common;

use std::path::{Path, PathBuf};

use walker::model::{Friction, ImpactLaw};
use walker::poincare::{FixedPoint, FixedPointOptions, Status, fixed_point};
use walker::sensitivity::{Estimate, Sensitivity, SensitivityError, sensitivities};
use walker::setup::{Overrides, Setup};
use walker::sim::SimConfig;

/// The maps of the sensitivities run at `rtol = 1e-12`; the fixed points here too, so that the
/// differences of whole solves below are not limited by the solves' own error.
fn tight() -> SimConfig {
    SimConfig {
        rtol: 1e-12,
        atol: 1e-14,
        ..SimConfig::default()
    }
}

fn solve(setup: &Setup) -> FixedPoint {
    let model = setup.model().unwrap();
    let fp = fixed_point(&model, &tight(), &FixedPointOptions::for_model(&model)).unwrap();
    assert_eq!(fp.status, Status::Converged, "{fp:?}");
    fp
}

/// The estimate of section coordinate `name`.
fn state(s: &Sensitivity, name: &str) -> Estimate {
    s.d_state
        .iter()
        .find(|(n, _)| n == name)
        .unwrap_or_else(|| panic!("no {name} in {:?}", s.d_state))
        .1
}

/// `value` agrees with `exact` within its own error estimate and within `tol` (absolute).
fn agrees(what: &str, e: Estimate, exact: f64, tol: f64) {
    let err = (e.value - exact).abs();
    assert!(
        err <= e.error && err <= tol,
        "{what}: {} vs {exact} (error {err:e}, estimate {:e}, tolerance {tol:e})",
        e.value,
        e.error
    );
}

/// The held paper wheel (exact Coulomb friction in stance and at the impact, `mu0 = 3`).
fn held_wheel(phi: f64) -> Setup {
    let mut setup = common::setup("passive-slope", &[("phi", phi), ("mu0", 3.0)]);
    setup.friction = Friction::Coulomb;
    setup.impact = ImpactLaw::Coulomb;
    setup
}

/// The rimless wheel's closed-form `w0` and step period (Simpson on `dth / th1d`, 4000
/// intervals: error below 1e-15 relative, see `rimless_wheel.rs`).
fn rimless(m: f64, l: f64, i: f64, g: f64, alpha: f64, phi: f64) -> (f64, f64, f64) {
    let j = i + m * l * l;
    let eta = (i + m * l * l * alpha.cos()) / j;
    let k = 2.0 * m * g * l / j;
    let (th_a, th_b) = (phi - alpha / 2.0, phi + alpha / 2.0);
    let w0 = eta * (k * (th_a.cos() - th_b.cos()) / (1.0 - eta * eta)).sqrt();
    let f = |th: f64| 1.0 / (w0 * w0 + k * (th_a.cos() - th.cos())).sqrt();
    let n = 4000;
    let h = (th_b - th_a) / f64::from(n);
    let mut sum = f(th_a) + f(th_b);
    for s in 1..n {
        sum += if s % 2 == 1 { 4.0 } else { 2.0 } * f(th_a + h * f64::from(s));
    }
    (w0, sum * h / 3.0, eta)
}

/// `dT/dphi` of the closed form by Richardson-extrapolated central differences of the
/// quadrature (steps 1e-3 and 5e-4: truncation about 1e-12, rounding 1e-15 / 1e-3).
fn closed_dt_dphi(m: f64, l: f64, i: f64, g: f64, alpha: f64, phi: f64) -> f64 {
    let t = |p: f64| rimless(m, l, i, g, alpha, p).1;
    let h = 1e-3;
    let d1 = (t(phi + h) - t(phi - h)) / (2.0 * h);
    let d2 = (t(phi + h / 2.0) - t(phi - h / 2.0)) / h;
    (4.0 * d2 - d1) / 3.0
}

/// Checks a held rimless wheel's sensitivities in `phi` and `alpha` against the closed forms;
/// `thd` is the name of its angular velocity, `m`, `i` its hub mass and inertia.
fn check_rimless(setup: &Setup, thd: &str, m: f64, i: f64, phi: f64) {
    let p = |name: &str| setup.params.get(name).unwrap();
    let (l, g, alpha) = (p("l"), p("g"), p("alpha"));
    let fp = solve(setup);
    let s = sensitivities(setup, &SimConfig::default(), &fp, &["phi", "alpha"]).unwrap();
    let (w0, t, eta) = rimless(m, l, i, g, alpha, phi);
    // The differences' truncation after the extrapolation is O(h^4) ~ 1e-12 and the maps'
    // noise about rtol / h = 1e-9 relative; amplified by (I - J)^{-1} (J's multiplier
    // eta^2 ~ 0.7: a factor 3): 1e-7 relative leaves a margin of 30 or more.
    let tol = 1e-7;
    // w0^2 is proportional to sin phi: dw0/dphi = w0 cot(phi) / 2.
    let dphi = &s[0];
    agrees("dw0/dphi", state(dphi, thd), w0 / phi.tan() / 2.0, tol * w0);
    // The foot is held: its velocity stays exactly zero.
    assert_eq!(state(dphi, "xd").value, 0.0);
    // The step is the chord 2 l sin(alpha/2) whatever the slope.
    agrees("d(dx)/dphi", dphi.d_dx, 0.0, tol);
    let dt = closed_dt_dphi(m, l, i, g, alpha, phi);
    agrees("dT/dphi", dphi.d_period, dt, tol * t.max(dt.abs()));
    let dx = 2.0 * l * (alpha / 2.0).sin();
    agrees("dV/dphi", dphi.d_speed, -dx / (t * t) * dt, tol * dx / t);
    // eta does not depend on the slope: the multiplier eta^2 neither.
    let lead = dphi.d_multipliers[0].unwrap();
    assert!(
        lead.re.hypot(lead.im) <= lead.error.max(1e-7),
        "dlambda/dphi = {lead:?}"
    );
    assert!(lead.re.abs() < 1e-7, "dlambda/dphi = {lead:?}");
    // d(eta^2)/dalpha = 2 eta deta/dalpha, deta/dalpha = -m l^2 sin(alpha) / (I + m l^2).
    let dalpha = &s[1];
    let dl = 2.0 * eta * (-m * l * l * alpha.sin() / (i + m * l * l));
    let lead = dalpha.d_multipliers[0].unwrap();
    agrees(
        "dlambda/dalpha",
        Estimate {
            value: lead.re,
            error: lead.error,
        },
        dl,
        tol,
    );
    assert_eq!(lead.im, 0.0);
}

#[test]
fn the_held_wheels_sensitivities_in_slope_and_spoke_angle_are_the_closed_forms() {
    for phi in [0.1, 0.2] {
        let setup = held_wheel(phi);
        let p = |name: &str| setup.params.get(name).unwrap();
        check_rimless(&setup, "th1d", p("m1") + p("m2"), p("I1"), phi);
    }
}

fn shipped(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../models")
        .join(format!("{name}.toml"))
}

#[test]
fn a_model_file_derived_at_run_time_has_the_closed_form_sensitivities() {
    // `models/rimless-wheel.toml` with its mass written `1*(...)`: not a compiled model's
    // content, so `walker-load` derives it and the tape evaluates its kernels.
    let text = std::fs::read_to_string(shipped("rimless-wheel")).unwrap();
    let (head, tail) = text.split_once("mass = \"").unwrap();
    let (mass, rest) = tail.split_once('"').unwrap();
    let path = std::env::temp_dir().join(format!(
        "walker-sensitivity-{}-rimless-wheel.toml",
        std::process::id()
    ));
    std::fs::write(&path, format!("{head}mass = \"1*({mass})\"{rest}")).unwrap();
    let phi = 0.1;
    let ov = Overrides {
        friction: Some(Friction::Coulomb),
        impact: Some(ImpactLaw::Coulomb),
        set: vec![("phi".into(), phi), ("mu0".into(), 3.0)],
        ..Overrides::default()
    };
    let source = walker_load::runtime_source();
    let setup = Setup::from_model_file(&path, &ov, Some(&source as &_)).unwrap();
    let p = |name: &str| setup.params.get(name).unwrap();
    let (m, rg) = (p("m"), p("rg"));
    check_rimless(&setup, "thd", m, m * rg * rg, phi);
}

/// `(dr*/dp, dT/dp, d(dx)/dp, d lambda_1/dp)` by central differences of whole fixed-point
/// solves at `p +- h`.
fn solve_differences(setup: &Setup, name: &str, h: f64) -> (Vec<f64>, f64, f64, f64) {
    let p0 = setup.params.get(name).unwrap();
    let a = solve(&setup.with(name, p0 + h).unwrap());
    let b = solve(&setup.with(name, p0 - h).unwrap());
    let c = |x: f64, y: f64| (x - y) / (2.0 * h);
    (
        a.state_plus
            .iter()
            .zip(b.state_plus.iter())
            .map(|(x, y)| c(*x, *y))
            .collect(),
        c(a.period, b.period),
        c(a.dx, b.dx),
        c(a.multipliers[0].re, b.multipliers[0].re),
    )
}

#[test]
fn the_active_walkers_sensitivities_to_mu0_and_t_set_match_differences_of_whole_solves() {
    let setup = common::setup("active-level", &[]);
    let fp = solve(&setup);
    let sens = sensitivities(&setup, &SimConfig::default(), &fp, &["mu0", "T_set"]).unwrap();
    for s in &sens {
        let lead = s.d_multipliers[0].unwrap();
        // Step study: the solves' differences have a truncation error C h^2 and a noise of
        // about 1e-11 / h (Newton's residual 1e-11, rtol 1e-12). Their distance to the
        // sensitivities must shrink by about 100 from h = 1e-2 to 1e-3 (O(h^2): the
        // sensitivities are their limit), and their Richardson extrapolation from h = 1e-3 and
        // 5e-4 (truncation C' h^4, noise 1e-11 / 5e-4 = 2e-8) must agree to 1e-6 (relative to
        // the derivative where it exceeds 1).
        let quantities = |h: f64| {
            let (dr, dt, ddx, dl) = solve_differences(&setup, &s.parameter, h);
            [dr[4], dr[6], dt, ddx, dl]
        };
        let ours = [
            state(s, "xd").value,
            state(s, "th1d").value,
            s.d_period.value,
            s.d_dx.value,
            lead.re,
        ];
        let dist =
            |q: [f64; 5]| -> Vec<f64> { q.iter().zip(&ours).map(|(a, b)| (a - b).abs()).collect() };
        let coarse = dist(quantities(1e-2));
        let (d1, d2) = (quantities(1e-3), quantities(5e-4));
        let fine = dist(d1);
        let extrapolated = dist(std::array::from_fn(|k| (4.0 * d2[k] - d1[k]) / 3.0));
        for k in 0..5 {
            // Converging at second order (a factor 100 with room for the noise: 20).
            assert!(
                fine[k] * 20.0 < coarse[k],
                "{}: {k}: {coarse:?} {fine:?}",
                s.parameter
            );
            assert!(
                extrapolated[k] < 1e-6 * ours[k].abs().max(1.0),
                "{}: {k}: {extrapolated:?}",
                s.parameter
            );
        }
        // The speed's derivative is that of dx / T.
        let v = fp.dx / fp.period;
        let dv = (s.d_dx.value - v * s.d_period.value) / fp.period;
        assert!((s.d_speed.value - dv).abs() < 1e-12 * dv.abs().max(1.0));
    }
}

#[test]
fn names_that_are_not_run_time_parameters_are_refused_with_the_valid_names() {
    let setup = common::setup("active-level", &[]);
    let fp = solve(&setup);
    for bad in ["bogus", "omega0", "phi"] {
        match sensitivities(&setup, &SimConfig::default(), &fp, &["mu0", bad]) {
            Err(SensitivityError::NotAParameter { name, known, .. }) => {
                assert_eq!(name, bad);
                assert!(known.contains("T_set") && known.contains("mu0"), "{known}");
                assert!(!known.contains("omega0"), "{known}");
            }
            other => panic!("{bad}: {other:?}"),
        }
    }
}
