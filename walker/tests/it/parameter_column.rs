//! The Poincare map's exact parameter columns (`walker::poincare::parameter_column`: one
//! variational integration with `d s / dp` beside `Phi`, `docs/poincare.md`) against
//! Richardson-extrapolated central differences of the map in the parameter, the model rebuilt at
//! `p +- h` and `p +- h/2`: the friction law's `mu0` and `c` (tanh, and Coulomb with its events
//! and its impact), the quintic's duration `T_set` and the gains of Eq. 32 on the paper's
//! walker, and a Bezier's points and duration (whose ramp's end moves the field's switch).
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use crate::common;

use walker::model::{Friction, ImpactLaw};
use walker::poincare::{parameter_column, poincare_map};
use walker::setup::{Overrides, Setup};
use walker::sim::SimConfig;

/// The maps at `rtol = 1e-12`, as the sensitivities run them.
fn tight() -> SimConfig {
    SimConfig {
        rtol: 1e-12,
        atol: 1e-14,
        ..SimConfig::default()
    }
}

/// `(state_plus, T, dx)` of the map of `setup` with `name = value` at `s`.
fn image(setup: &Setup, name: &str, value: f64, s: &[f64]) -> Vec<f64> {
    let model = setup.with(name, value).unwrap().model().unwrap();
    let m = poincare_map(&model, &tight(), s).unwrap();
    let mut out: Vec<f64> = m.state_plus.iter().copied().collect();
    out.extend([m.period, m.dx]);
    out
}

/// The exact column of `name` at `s` (a start that does not move with `p`) against the
/// Richardson extrapolation `(4 D(h/2) - D(h)) / 3` of central differences, `h = 1e-4 max(|p|,
/// 1)`.
///
/// Tolerance: each map carries the integrator's error, about `rtol = 1e-12` relative; divided
/// by the step and amplified up to three times by the extrapolation it is about `3e-8`
/// relative. The truncation: at `h = 1e-3` the paper's step in `T_set` from its start has
/// `D(h)` off by `5e-4` and the extrapolation by `3e-7` (large higher derivatives: a start
/// that is not a gait), which `h = 1e-4` divides by `10^4`. The exact column's own error is of
/// the integrator's order. `2e-7` relative to `max(1, |value|)` leaves a factor of about 5 over
/// the noise; a sign or a missing term (the ramp's moving end, the slip guard's `mu0`, the
/// impact's `mu0`) is off by orders more.
fn check(setup: &Setup, name: &str, s: &[f64]) {
    let model = setup.model().unwrap();
    let zero = vec![0.0; s.len()];
    let (_, col) = parameter_column(&model, &tight(), s, name, &zero)
        .unwrap()
        .unwrap_or_else(|| panic!("{}: {name} has no exact column", setup.name));
    let p = setup.params.get(name).unwrap();
    let h = 1e-4 * p.abs().max(1.0);
    let [up, down, half_up, half_down] =
        [h, -h, h / 2.0, -h / 2.0].map(|d| image(setup, name, p + d, s));
    let mut exact = col.d_state.clone();
    exact.extend([col.d_period, col.d_dx]);
    for (i, e) in exact.iter().enumerate() {
        let d1 = (up[i] - down[i]) / (2.0 * h);
        let d2 = (half_up[i] - half_down[i]) / h;
        let r = (4.0 * d2 - d1) / 3.0;
        assert!(
            (e - r).abs() <= 2e-7 * r.abs().max(1.0),
            "{}, d/d{name} of component {i}: exact {e}, differences {r} (D1 {d1}, D2 {d2})",
            setup.name
        );
    }
}

#[test]
fn the_papers_walker_has_exact_columns_in_its_friction_ramp_and_gains() {
    // Gains on, so that their columns are not zero: the tracking error grows off the section.
    let setup = common::setup("active-level", &[("K_P", 50.0), ("K_D", 10.0)]);
    let s = setup.model().unwrap().start_state();
    for name in ["mu0", "c", "T_set", "K_P", "K_D"] {
        check(&setup, name, &s);
    }
}

#[test]
fn under_coulomb_friction_the_mu0_column_crosses_the_slide_and_the_impact() {
    // The paper's wheel on its slope (phi = 0.2, tan phi = 0.203) under exact Coulomb friction
    // slides below mu0 = 0.203 and its impact reverses the striking foot's slip: the column has
    // the sliding field's rate -sigma (d qdd / d mu) and the impact's own rate in mu0. (At
    // mu0 = 0.3 it is held and its column is zero, as the differences'.)
    for mu0 in [0.19, 0.15] {
        let mut setup = common::setup("passive-slope", &[("mu0", mu0)]);
        setup.friction = Friction::Coulomb;
        setup.impact = ImpactLaw::Coulomb;
        let model = setup.model().unwrap();
        let s = model.start_state();
        let (_, col) = parameter_column(&model, &tight(), &s, "mu0", &vec![0.0; s.len()])
            .unwrap()
            .unwrap();
        assert!(col.d_period.abs() > 0.1, "mu0 = {mu0}: {col:?}");
        check(&setup, "mu0", &s);
    }
}

#[test]
fn a_beziers_points_and_duration_have_exact_columns() {
    // The paper's walker with its ramp an order-5 Bezier whose inner points are parameters
    // (the shape `walker design --fig8` designs), derived at run time: its second derivative
    // jumps at the ramp's end, which moves with T_set.
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../models/paper-active.toml"),
    )
    .unwrap();
    let quintic =
        r#"desired = { shape = "quintic", from = "-alpha/2", to = "alpha/2", duration = "T_set" }"#;
    let bezier = r#"desired = { shape = "bezier", points = ["-alpha/2", "-alpha/2", "a2", "a3", "alpha/2", "alpha/2"], duration = "T_set" }"#;
    assert!(text.contains(quintic));
    let params = "[[parameter]]\nname = \"a2\"\nunit = \"rad\"\ndoc = \"a point\"\nrange = \"(-inf, inf)\"\ndefault = -0.1\n[[parameter]]\nname = \"a3\"\nunit = \"rad\"\ndoc = \"a point\"\nrange = \"(-inf, inf)\"\ndefault = 0.35\n[floor]";
    let path = std::env::temp_dir().join(format!(
        "walker-parameter-column-{}-bezier.toml",
        std::process::id()
    ));
    std::fs::write(
        &path,
        text.replace(quintic, bezier).replacen("[floor]", params, 1),
    )
    .unwrap();
    let source = walker_load::runtime_source();
    let setup = Setup::from_model_file(&path, &Overrides::default(), Some(&source as &_)).unwrap();
    let s = setup.model().unwrap().start_state();
    for name in ["a2", "a3", "T_set", "mu0"] {
        check(&setup, name, &s);
    }
}

#[test]
fn a_parameter_of_the_mechanics_has_no_exact_column() {
    let setup = common::setup("active-level", &[]);
    let model = setup.model().unwrap();
    let s = model.start_state();
    let zero = vec![0.0; s.len()];
    // alpha is the wheel's spoke angle (the strike and the relabelling use it).
    for name in ["alpha", "no-such-parameter"] {
        let col = parameter_column(&model, &tight(), &s, name, &zero).unwrap();
        assert!(col.is_none(), "{name}");
    }
}
