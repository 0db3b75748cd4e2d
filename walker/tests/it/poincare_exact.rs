//! The exact Jacobian of the Poincare map (variational equations, saltation at every event that
//! switches a phase, the impact's Jacobian in its regime) on models derived at run time
//! (`walker-load`: every derived kernel, the Jacobians included), checked against an
//! independent SymPy/SciPy reference (`sympy_ref/simplest_walker.py`), a closed form (the
//! rimless wheel's `eta^2`) and central differences at several steps.

use std::path::{Path, PathBuf};

use walker::model::{Friction, ImpactLaw, ImpactRegime, Model};
use walker::poincare::{
    FixedPoint, FixedPointOptions, JacobianMethod, Section, Status,
    finite_difference_map_with_step, fixed_point, poincare_map_with,
};
use walker::setup::{Overrides, Setup};
use walker::sim::SimConfig;

fn shipped(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../models")
        .join(format!("{name}.toml"))
}

/// A copy of `models/<name>.toml` with its first mass written `1*(...)`: the same walker, but
/// not a compiled model's canonical content, so that `walker-load` derives it at run time. `tag`
/// names the copy (the tests run in parallel, each with its own).
fn uncompiled(name: &str, tag: &str) -> PathBuf {
    let text = std::fs::read_to_string(shipped(name)).expect("a shipped model");
    let (head, tail) = text.split_once("mass = \"").expect("a body with a mass");
    let (mass, rest) = tail.split_once('"').expect("the mass's closing quote");
    let changed = format!("{head}mass = \"1*({mass})\"{rest}");
    let path = std::env::temp_dir().join(format!(
        "walker-exact-{}-{tag}-{name}.toml",
        std::process::id()
    ));
    std::fs::write(&path, changed).expect("a temporary file");
    path
}

/// The model file at `path` derived at run time, with the overrides `ov`.
fn loaded(path: &Path, ov: &Overrides) -> Model {
    let source = walker_load::runtime_source();
    let setup = Setup::from_model_file(path, ov, Some(&source as &_)).expect("the model sets up");
    setup.model().expect("kernels")
}

/// The reference's numbers (`sympy_ref/simplest_walker.json`).
struct Reference {
    fixed_point: Vec<f64>,
    period: f64,
    multipliers: Vec<(f64, f64)>,
}

fn reference() -> Reference {
    let text = include_str!("../../../sympy_ref/simplest_walker.json");
    let v: serde_json::Value = serde_json::from_str(text).expect("the reference's JSON");
    let floats = |v: &serde_json::Value| -> Vec<f64> {
        v.as_array()
            .expect("an array")
            .iter()
            .map(|x| x.as_f64().expect("a number"))
            .collect()
    };
    Reference {
        fixed_point: floats(&v["fixed_point"]),
        period: v["period"].as_f64().expect("the period"),
        multipliers: v["multipliers"]
            .as_array()
            .expect("the multipliers")
            .iter()
            .map(|c| {
                let c = floats(c);
                (c[0], c[1])
            })
            .collect(),
    }
}

fn simplest_walker() -> Model {
    loaded(&shipped("simplest-walker"), &Overrides::default())
}

/// The simplest walker's fixed point with its exact Jacobian.
fn simplest_fixed_point(model: &Model) -> FixedPoint {
    let fp = fixed_point(
        model,
        &SimConfig::default(),
        &FixedPointOptions::for_model(model),
    )
    .expect("a fixed point");
    assert_eq!(fp.status, Status::Converged, "{fp:?}");
    fp
}

/// The largest entry of `a - b`.
fn max_diff(a: &[Vec<f64>], b: &[Vec<f64>]) -> f64 {
    a.iter()
        .flatten()
        .zip(b.iter().flatten())
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

#[test]
fn the_simplest_walkers_multipliers_agree_with_the_independent_reference_to_1e_8() {
    let model = simplest_walker();
    let fp = simplest_fixed_point(&model);
    assert_eq!(fp.jacobian_method, JacobianMethod::Variational);
    assert_eq!(fp.impact, ImpactRegime::Stick);
    let reference = reference();
    // The reference moves by 2e-12 from rtol 1e-13 to 3e-14; here the stance is integrated at
    // rtol 1e-12 (Phi under the same error control, about 1e-10 after the stance's growth) and
    // the impact's coordinate columns are good to about 2e-10 (impact_jacobian.rs): the
    // multipliers of this well-conditioned 3 x 3 Jacobian to about 1e-9. The issue asks 1e-8.
    assert_eq!(fp.multipliers.len(), reference.multipliers.len());
    for (got, (re, im)) in fp.multipliers.iter().zip(&reference.multipliers) {
        assert!(
            (got.re - re).abs() < 1e-8 && (got.im - im).abs() < 1e-8,
            "{got:?} vs ({re}, {im})"
        );
    }
    // The complex pair is the gait's: modulus 0.588, stable.
    assert!(
        (fp.max_modulus() - 0.5881).abs() < 1e-3,
        "{:?}",
        fp.multipliers
    );
}

#[test]
fn the_simplest_walkers_fixed_point_is_the_references_and_garcia_et_als_to_the_foot_mass() {
    let model = simplest_walker();
    let fp = simplest_fixed_point(&model);
    let reference = reference();
    // State [x, z, th_st, th_sw, xd, zd, th_std, th_swd]; the section (th_st, th_std, th_swd).
    let got = [fp.state_plus[2], fp.state_plus[6], fp.state_plus[7]];
    // Newton stops at a residual of 1e-11 of a map integrated at rtol 1e-12 (the reference at
    // 1e-13): 1e-9 leaves a margin of 100.
    for (g, r) in got.iter().zip(&reference.fixed_point) {
        assert!(
            (g - r).abs() < 1e-9,
            "{got:?} vs {:?}",
            reference.fixed_point
        );
    }
    assert!(
        (fp.period - reference.period).abs() < 1e-9,
        "T = {}",
        fp.period
    );
    // The new foot is at rest: the impact sticks and the foot stays stuck.
    assert_eq!(fp.state_plus[4], 0.0);
    // Garcia et al.'s theta = 0.2003109, thetadot = -0.1998325 are the limit m -> 0; the feet
    // of mass m = 1e-4 move them by O(m) (the reference: 1.5e-5 and 7e-6).
    let phi = 0.009;
    let (theta, thetadot) = (phi - got[0], -got[1]);
    assert!((theta - 0.2003109).abs() < 5e-5, "theta = {theta}");
    assert!((thetadot + 0.1998325).abs() < 5e-5, "thetadot = {thetadot}");
}

#[test]
fn central_differences_converge_to_the_exact_jacobian_as_h_squared() {
    let model = simplest_walker();
    let fp = simplest_fixed_point(&model);
    let cfg = SimConfig::default();
    let section = Section::of(&model);
    let r = section.reduce(&fp.state_plus);
    let exact = poincare_map_with(&model, &cfg, &fp.state_plus, JacobianMethod::Variational)
        .expect("the map");
    let je = section.reduced_jacobian(&exact.jacobian, &r);
    let err = |h: f64| {
        let fd = finite_difference_map_with_step(&model, &cfg, &fp.state_plus, h).expect("map");
        max_diff(&je, &section.reduced_jacobian(&fd.jacobian, &r))
    };
    let errors: Vec<f64> = [1e-3, 1e-4, 1e-5].into_iter().map(err).collect();
    // The truncation error h^2 |P'''| / 6 dominates down to 1e-5 (the map's own error, 1e-12,
    // over h is 1e-7 there): each tenth of the step divides the error by about 100. The
    // bracket [50, 200] allows the next order (h^4) and the rounding.
    for w in errors.windows(2) {
        let ratio = w[0] / w[1];
        assert!((50.0..200.0).contains(&ratio), "errors {errors:?}");
    }
    // The fixed step 1e-4 the map used is off by more than 1e-4 here (|P'''| is about 3e5):
    // the multipliers off by 2e-4.
    assert!(errors[1] > 1e-4, "errors {errors:?}");
}

/// The rimless wheel's closed-form multiplier `eta^2`, `eta = (I + m l^2 cos alpha) / (I + m l^2)`
/// (Coleman, Chatterjee and Ruina 1997; `tests/it/rimless_wheel.rs`).
fn eta_squared(setup: &Setup) -> f64 {
    let p = |name: &str| setup.params.get(name).expect("a parameter");
    let (m, l, rg, alpha) = (p("m"), p("l"), p("rg"), p("alpha"));
    let i = m * rg * rg;
    let eta = (i + m * l * l * alpha.cos()) / (i + m * l * l);
    eta * eta
}

#[test]
fn the_rimless_wheel_derived_at_run_time_has_the_exact_multiplier_eta_squared() {
    let path = uncompiled("rimless-wheel", "eta");
    let source = walker_load::runtime_source();
    for phi in [0.05, 0.1, 0.2] {
        let ov = Overrides {
            friction: Some(Friction::Coulomb),
            impact: Some(ImpactLaw::Coulomb),
            set: vec![("phi".into(), phi), ("mu0".into(), 3.0)],
            ..Overrides::default()
        };
        let setup = Setup::from_model_file(&path, &ov, Some(&source as &_)).expect("sets up");
        let model = setup.model().expect("kernels");
        let fp = fixed_point(
            &model,
            &SimConfig::default(),
            &FixedPointOptions::for_model(&model),
        )
        .expect("a fixed point");
        assert_eq!(fp.status, Status::Converged, "phi = {phi}: {fp:?}");
        assert_eq!(fp.jacobian_method, JacobianMethod::Variational);
        assert_eq!(fp.impact, ImpactRegime::Stick);
        let lead = fp.multipliers[0];
        let closed = eta_squared(&setup);
        // Stuck stance (stick_jacobian) and sticking impact: the multiplier is good to the
        // integration's accuracy (rtol 1e-12) and the impact's coordinate column's (2e-10);
        // central differences got 1e-6 (`tests/it/rimless_wheel.rs`).
        assert!(
            lead.im == 0.0 && (lead.re - closed).abs() < 1e-9,
            "phi = {phi}: {:?} vs {closed}",
            fp.multipliers
        );
    }
    let _ = std::fs::remove_file(path);
}

/// The rimless wheel derived at run time under exact Coulomb friction in stance with `impact`
/// and `mu0`, and its post-impact state after 10 steps from its start, with the last step.
fn sliding_wheel(impact: ImpactLaw, mu0: f64) -> (Model, Vec<f64>, walker::sim::StepResult) {
    let path = uncompiled("rimless-wheel", &format!("{impact:?}-{mu0}"));
    let source = walker_load::runtime_source();
    let ov = Overrides {
        friction: Some(Friction::Coulomb),
        impact: Some(impact),
        set: vec![("mu0".into(), mu0)],
        ..Overrides::default()
    };
    let setup = Setup::from_model_file(&path, &ov, Some(&source as &_)).expect("sets up");
    let _ = std::fs::remove_file(path);
    let model = setup.model().expect("kernels");
    let limits = walker::sim::WalkLimits {
        max_steps: 10,
        ..walker::sim::WalkLimits::default()
    };
    let w = walker::sim::walk(&model, &SimConfig::default(), &model.start_state(), &limits);
    assert!(w.failure.is_none(), "{:?}", w.failure);
    let s = w.last_state().expect("a step").to_vec();
    let last = *w.steps.last().expect("a step");
    (model, s, last)
}

/// The largest difference between the exact Jacobian at `s` and Richardson-extrapolated
/// central differences (steps `1e-5`, `2e-5`: truncation `O(h^4)`, about `1e-20`).
fn exact_against_extrapolated(model: &Model, s: &[f64]) -> f64 {
    exact_against_extrapolated_where(model, s, &|_, _| true)
}

/// [`exact_against_extrapolated`] over the rows before `split` and over the others.
fn exact_against_extrapolated_rows(model: &Model, s: &[f64], split: usize) -> (f64, f64) {
    let rows =
        |keep: &dyn Fn(usize) -> bool| exact_against_extrapolated_where(model, s, &|i, _| keep(i));
    (rows(&|i| i < split), rows(&|i| i >= split))
}

/// [`exact_against_extrapolated`] over the entries `(i, j)` where `entry(i, j)`.
fn exact_against_extrapolated_where(
    model: &Model,
    s: &[f64],
    entry: &dyn Fn(usize, usize) -> bool,
) -> f64 {
    let cfg = SimConfig::default();
    let exact = poincare_map_with(model, &cfg, s, JacobianMethod::Variational).expect("map");
    assert_eq!(exact.method, JacobianMethod::Variational);
    let fd = |h| finite_difference_map_with_step(model, &cfg, s, h).expect("map");
    let (a, b) = (fd(1e-5), fd(2e-5));
    let mut worst: f64 = 0.0;
    for (i, row) in exact.jacobian.iter().enumerate() {
        for (j, e) in row.iter().enumerate().filter(|&(j, _)| entry(i, j)) {
            let rich = (4.0 * a.jacobian[i][j] - b.jacobian[i][j]) / 3.0;
            worst = worst.max((e - rich).abs());
        }
    }
    worst
}

#[test]
fn the_saltation_where_a_sliding_foot_comes_to_rest_matches_extrapolated_differences() {
    // The frictionless impact leaves the new foot sliding forward; with mu0 = 0.5 it comes to
    // rest within the stance and sticks: the event `sigma xd = 0` with its reset and the
    // change of field, then the stuck phase (stick_jacobian).
    let (model, s, last) = sliding_wheel(ImpactLaw::Frictionless, 0.5);
    assert!(s[model.n()] > 0.0, "the foot slides at the start");
    assert!(
        last.stuck_time > 0.0 && last.stuck_time < last.period,
        "it comes to rest within the stance: {last:?}"
    );
    // The maps are integrated at rtol 1e-12; their errors are smooth in the start (the same
    // steps and events), so the differences keep about 1e-10 (seen: 6e-11), not the bound
    // 1e-12 / 1e-5 = 1e-7 of an error that is not; 1e-8 leaves a margin of 100.
    let d = exact_against_extrapolated(&model, &s);
    assert!(d < 1e-8, "exact against extrapolated differences: {d:e}");
}

#[test]
fn a_foot_sliding_through_the_stance_and_the_impact_has_the_exact_jacobian() {
    // mu0 = 0.2 with friction at the impact: the foot slides forward throughout the stance
    // (mu = -mu0, no event) and the impact slides too (ImpactRegime::Slide).
    let (model, s, last) = sliding_wheel(ImpactLaw::Coulomb, 0.2);
    assert!(s[model.n()] > 0.0 && last.stuck_time == 0.0, "{last:?}");
    assert!(matches!(last.impact, ImpactRegime::Slide(_)), "{last:?}");
    // As above.
    let d = exact_against_extrapolated(&model, &s);
    assert!(d < 1e-8, "exact against extrapolated differences: {d:e}");
}

#[test]
fn the_compass_gait_derived_at_run_time_has_the_exact_jacobian_of_its_held_gait() {
    // No closed form for its sliding stance (its M^-1 is too large), but its stuck stance has
    // one (stick_jacobian): the held gait of Goswami et al. with friction at the impact.
    let path = uncompiled("compass-gait", "held");
    let source = walker_load::runtime_source();
    let ov = Overrides {
        friction: Some(Friction::Coulomb),
        impact: Some(ImpactLaw::Coulomb),
        set: vec![("mu0".into(), 5.0)],
        ..Overrides::default()
    };
    let setup = Setup::from_model_file(&path, &ov, Some(&source as &_)).expect("sets up");
    let _ = std::fs::remove_file(path);
    let model = setup.model().expect("kernels");
    let fp = fixed_point(
        &model,
        &SimConfig::default(),
        &FixedPointOptions::for_model(&model),
    )
    .expect("a fixed point");
    assert_eq!(fp.status, Status::Converged, "{fp:?}");
    assert_eq!(fp.jacobian_method, JacobianMethod::Variational);
    assert_eq!(fp.impact, ImpactRegime::Stick);
    // The foot at rest: its velocity's columns are zero in the exact Jacobian and one-sided in
    // the differences; every other column as in the sliding checks above (seen: 1.5e-10).
    let n = model.n();
    let cfg = SimConfig::default();
    let exact =
        poincare_map_with(&model, &cfg, &fp.state_plus, JacobianMethod::Variational).expect("map");
    let fd = |h| finite_difference_map_with_step(&model, &cfg, &fp.state_plus, h).expect("map");
    let (a, b) = (fd(1e-5), fd(2e-5));
    let mut worst: f64 = 0.0;
    for i in 0..2 * n {
        for j in (2..2 * n).filter(|&j| j != n && j != n + 1) {
            let rich = (4.0 * a.jacobian[i][j] - b.jacobian[i][j]) / 3.0;
            worst = worst.max((exact.jacobian[i][j] - rich).abs());
        }
    }
    assert!(
        worst < 1e-8,
        "exact against extrapolated differences: {worst:e}"
    );
}

/// `models/<name>.toml` under exact Coulomb friction in stance and at the impact with `mu0`,
/// derived at run time where `run_time`, else the compiled model.
fn coulomb(name: &str, mu0: f64, run_time: bool) -> Model {
    let ov = Overrides {
        friction: Some(Friction::Coulomb),
        impact: Some(ImpactLaw::Coulomb),
        set: vec![("mu0".into(), mu0)],
        ..Overrides::default()
    };
    if !run_time {
        return Setup::from_model_file(&shipped(name), &ov, None)
            .expect("sets up")
            .model()
            .expect("compiled");
    }
    let path = uncompiled(name, &format!("coulomb-{mu0}"));
    let model = loaded(&path, &ov);
    let _ = std::fs::remove_file(path);
    model
}

#[test]
fn the_compass_gait_sliding_in_its_stance_has_the_exact_jacobian() {
    // Below the least friction of the held gait (0.2742, the gallery's) the compass gait's
    // foot arrives sliding (the impact reverses it), comes to rest, holds, and slips again
    // before the strike: its sliding phases go through `accel_jacobian` of the structured
    // solve, differentiated (`derive/src/model/forward.rs`), derived here at run time.
    let model = coulomb("compass-gait", 0.27, true);
    let cfg = SimConfig::default();
    let fp = fixed_point(&model, &cfg, &FixedPointOptions::for_model(&model)).expect("a gait");
    assert_eq!(fp.status, Status::Converged, "{fp:?}");
    assert_eq!(fp.jacobian_method, JacobianMethod::Variational);
    assert!(matches!(fp.impact, ImpactRegime::Reverse(_)), "{fp:?}");
    let limits = walker::sim::WalkLimits {
        max_steps: 1,
        ..walker::sim::WalkLimits::default()
    };
    let step = walker::sim::walk(&model, &cfg, &fp.state_plus, &limits).steps[0];
    assert!(
        step.stuck_time > 0.0 && step.stuck_time < step.period,
        "sliding and held within the step: {step:?}"
    );
    // The positions' rows are the stance's flow alone (the impact keeps them): as for the
    // wheel above, with the margin of 100 on what is seen (1e-12) taken to 1e-10. The
    // velocities' rows go through the reversing impact, whose coordinate columns are
    // extrapolated differences of the regime's map (`docs/poincare.md`: about 2e-10 of the
    // impact's entries; seen 1.8e-8 of this map's, whose entries reach 15): 1e-7.
    let n = model.n();
    let (positions, velocities) = exact_against_extrapolated_rows(&model, &fp.state_plus, n);
    assert!(positions < 1e-10, "positions' rows: {positions:e}");
    assert!(velocities < 1e-7, "velocities' rows: {velocities:e}");
}
