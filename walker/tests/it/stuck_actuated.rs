//! The exact Jacobian through the held foot of an actuated walker under exact Coulomb friction
//! (`walker::jacobian`, "held foot"; `docs/poincare.md`): a model with inputs has no
//! `stick_jacobian`, so its stuck stance is differentiated as the sliding stance at the friction
//! ratio `mu* = lambda_t / lambda_n` that holds the foot, `mu*`'s own derivative eliminated by
//! the implicit function theorem. Checked against central differences of the stuck field itself
//! (`closed_loop_stick`; on the level and on a slope), and the Poincare map's Jacobian,
//! multipliers and parameter columns against Richardson-extrapolated differences of whole
//! steps, on the paper's active walker (held, and slipping within the step). The three-link
//! biped has no `closed_loop_jacobian` (its `M^-1` has no closed form), so it keeps differences.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use std::path::Path;

use walker::jacobian::{NoJacobian, Scratch, StanceJacobian};
use walker::model::{Contact, Friction, ImpactLaw, ImpactRegime, Model};
use walker::poincare::{
    FixedPoint, FixedPointOptions, JacobianMethod, Section, Status,
    finite_difference_map_with_step, fixed_point, jacobian_error, multiplier_bounds,
    multiplier_errors, parameter_column, poincare_map, poincare_map_with,
};
use walker::setup::{Overrides, Setup};
use walker::sim::{SimConfig, WalkLimits, walk};

use crate::common;

/// The paper's active walker (`active-level`, compiled) under exact Coulomb friction in stance
/// and at the impact, with `params` set.
fn active(params: &[(&str, f64)]) -> Setup {
    let mut s = common::setup("active-level", params);
    s.friction = Friction::Coulomb;
    s.impact = ImpactLaw::Coulomb;
    s
}

/// `models/three-link.toml` (compiled; exact Coulomb friction in stance and at the impact by
/// default).
fn three_link() -> Setup {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../models/three-link.toml");
    let source = walker_load::runtime_source();
    Setup::from_model_file(&path, &Overrides::default(), Some(&source as &_)).unwrap()
}

/// The paper's active walker on a slope `phi` (a parameter added to `models/paper-active.toml`,
/// the floor tilted by it; derived at run time) under exact Coulomb friction with `mu0 = 1`
/// and gains on: no shipped actuated model has a slope, and the held foot's rows must vanish
/// in the floor's frame there too (`x` horizontal, the foot held on the tilted floor).
fn active_on_a_slope(phi: f64) -> Setup {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../models/paper-active.toml"),
    )
    .unwrap();
    let param = "[[parameter]]\nname = \"phi\"\nunit = \"rad\"\ndoc = \"slope\"\nrange = \"[0, pi/2)\"\ndefault = 0.0\n[floor]\nslope = \"phi\"";
    assert!(text.contains("\n[floor]\n"));
    let path = std::env::temp_dir().join(format!(
        "walker-stuck-actuated-{}-slope.toml",
        std::process::id()
    ));
    std::fs::write(&path, text.replacen("[floor]", param, 1)).unwrap();
    let source = walker_load::runtime_source();
    let ov = Overrides {
        friction: Some(Friction::Coulomb),
        impact: Some(ImpactLaw::Coulomb),
        set: vec![
            ("phi".into(), phi),
            ("mu0".into(), 1.0),
            ("K_P".into(), 50.0),
            ("K_D".into(), 10.0),
        ],
        ..Overrides::default()
    };
    let setup = Setup::from_model_file(&path, &ov, Some(&source as &_)).unwrap();
    let _ = std::fs::remove_file(path);
    setup
}

/// The maps at `rtol = 1e-12`, as every model but the Table-1 tanh variants runs them.
fn tight() -> SimConfig {
    SimConfig {
        rtol: 1e-12,
        atol: 1e-14,
        ..SimConfig::default()
    }
}

fn converged(model: &Model) -> FixedPoint {
    let fp = fixed_point(
        model,
        &SimConfig::default(),
        &FixedPointOptions::for_model(model),
    )
    .unwrap();
    assert_eq!(fp.status, Status::Converged, "{fp:?}");
    fp
}

/// A deterministic stream of numbers in `[-1, 1)` (a linear congruential generator: the
/// states are spread, and the same on every run).
fn noise(seed: u64) -> impl FnMut() -> f64 {
    let mut x = seed;
    move || {
        x = x
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (x >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

/// `[qdd, u]` of the stuck stance at `(t, y)` (`n + m` numbers).
fn stuck_field(model: &Model, t: f64, y: &[f64]) -> Vec<f64> {
    let mut out = [0.0; Model::STANCE_LEN];
    model.stance(t, y, Contact::Stuck, &mut out);
    out[..model.n() + model.inputs()].to_vec()
}

/// The Richardson extrapolation `(4 D(h/2) - D(h)) / 3` of central differences of `f` at `x`
/// in its component `j` (`h = 1e-4 max(1, |x_j|)`).
fn richardson(f: &dyn Fn(&[f64]) -> Vec<f64>, x: &[f64], j: usize) -> Vec<f64> {
    let h = 1e-4 * x[j].abs().max(1.0);
    let at = |d: f64| {
        let mut p = x.to_vec();
        p[j] += d;
        f(&p)
    };
    let (up, down, hu, hd) = (at(h), at(-h), at(h / 2.0), at(-h / 2.0));
    (0..up.len())
        .map(|i| {
            let d1 = (up[i] - down[i]) / (2.0 * h);
            let d2 = (hu[i] - hd[i]) / h;
            (4.0 * d2 - d1) / 3.0
        })
        .collect()
}

/// States near the model's start (coordinates within 0.1, velocities within 0.3 of it, `t`
/// within the ramp) where the held foot's normal force is positive.
fn held_states(model: &Model, seed: u64, count: usize) -> Vec<(f64, Vec<f64>)> {
    let (n, s0) = (model.n(), model.start_state());
    let mut r = noise(seed);
    let mut out = Vec::new();
    while out.len() < count {
        let t = 0.2 + 0.2 * r();
        let y: Vec<f64> = (0..2 * n)
            .map(|j| match j {
                // The foot at rest, on the floor.
                0 | 1 => 0.0,
                j if j == n || j == n + 1 => 0.0,
                j if j < n => s0[j] + 0.1 * r(),
                j => s0[j] + 0.3 * r(),
            })
            .collect();
        if model.reaction(t, &y, Contact::Stuck).normal > 0.0 {
            out.push((t, y));
        }
    }
    out
}

#[test]
fn the_held_foots_jacobian_is_the_stuck_fields_and_its_foot_rows_vanish() {
    let cases = [
        (
            "level",
            active(&[("mu0", 1.0), ("K_P", 50.0), ("K_D", 10.0)]),
        ),
        ("slope 0.1", active_on_a_slope(0.1)),
        // No closed forms: `closed_loop_stick_jacobian` (its foot rows are exactly zero).
        ("three-link", three_link()),
    ];
    for (name, setup) in cases {
        let model = setup.model().unwrap();
        let jac = StanceJacobian::any_law(&model);
        assert!(jac.has_contact(Contact::Stuck), "{name}");
        let (n, inputs) = (model.n(), model.inputs());
        let rows = n + inputs;
        for (t, y) in held_states(&model, 7, 6) {
            let mut exact = vec![0.0; rows * 2 * n];
            jac.accel_in(t, &y, Contact::Stuck, &mut exact).unwrap();
            // The held foot does not accelerate, whatever the state: its row is zero, exactly
            // (the elimination subtracts row 0 from itself), and so is the vertical one to
            // rounding (the sliding foot's zdd is -tan(phi) xdd, so its row is that multiple
            // of row 0 before the elimination).
            assert!(
                exact[..2 * n].iter().all(|&d| d == 0.0),
                "{name}: {exact:?}"
            );
            let scale = exact.iter().fold(1.0_f64, |a, d| a.max(d.abs()));
            assert!(
                exact[2 * n..4 * n].iter().all(|d| d.abs() < 1e-13 * scale),
                "{name}: {:?}",
                &exact[2 * n..4 * n]
            );
            let f = |y: &[f64]| stuck_field(&model, t, y);
            for j in 0..2 * n {
                let fd = richardson(&f, &y, j);
                for i in 0..rows {
                    // The extrapolated differences' error: the kernels' rounding (1e-16 of
                    // values up to 1e3) over the step 5e-5, times 3: about 1e-8; O(h^4) below.
                    // 1e-7 of the largest entry; a missing elimination is off by O(1).
                    let e = exact[i * 2 * n + j];
                    assert!(
                        (e - fd[i]).abs() <= 1e-7 * scale,
                        "{name}, t = {t}, d[{i}]/dy[{j}]: exact {e}, differences {}",
                        fd[i]
                    );
                }
            }
        }
    }
}

#[test]
fn the_held_ratio_and_its_rates_in_state_and_time_are_the_stuck_forces_ratio() {
    for setup in [
        active(&[("mu0", 1.0), ("K_P", 50.0), ("K_D", 10.0)]),
        active_on_a_slope(0.1),
    ] {
        let model = setup.model().unwrap();
        let jac = StanceJacobian::any_law(&model);
        let n = model.n();
        let ratio = |t: f64, y: &[f64]| {
            let r = model.reaction(t, y, Contact::Stuck);
            vec![r.tangential / r.normal]
        };
        for (t, y) in held_states(&model, 11, 6) {
            let held = jac.held_ratio(t, &y, &mut Scratch::new()).unwrap();
            assert_eq!(held.mu, ratio(t, &y)[0]);
            for j in 0..2 * n {
                let fd = richardson(&|y: &[f64]| ratio(t, y), &y, j)[0];
                // As above: the ratio is of order one, its derivatives up to about 10.
                assert!(
                    (held.d_y[j] - fd).abs() <= 1e-7 * fd.abs().max(1.0),
                    "t = {t}, dmu/dy[{j}]: {} vs {fd}",
                    held.d_y[j]
                );
            }
            // In time, through the desired trajectories (t inside the ramp, 0.2 +- 0.2 of
            // T_set = 0.3 for the paper's walker; the step 1e-4 stays off its end unless t is
            // within it, which the seed avoids).
            let fd = richardson(&|x: &[f64]| ratio(x[0], &y), &[t], 0)[0];
            assert!(
                (held.d_t - fd).abs() <= 1e-7 * fd.abs().max(1.0),
                "t = {t}, dmu/dt: {} vs {fd}",
                held.d_t
            );
        }
    }
}

#[test]
fn an_unloaded_held_foot_has_no_jacobian_and_leaves_no_nan() {
    // The wheel spinning at 10 rad/s: the hip's centripetal acceleration l w^2 = 100 m/s^2
    // exceeds g, the held foot would be pulled off the floor (negative normal force).
    let model = active(&[("mu0", 1.0)]).model().unwrap();
    let mut y = model.start_state().to_vec();
    let n = model.n();
    for v in &mut y[n + 2..] {
        *v = 10.0;
    }
    assert!(model.reaction(0.1, &y, Contact::Stuck).normal < 0.0);
    let jac = StanceJacobian::any_law(&model);
    assert_eq!(
        jac.held_ratio(0.1, &y, &mut Scratch::new()).unwrap_err(),
        NoJacobian::HeldRatioSingular
    );
    let mut out = vec![7.0; n * 2 * n];
    assert!(jac.accel_in(0.1, &y, Contact::Stuck, &mut out).is_err());
    assert!(out.iter().all(|&d| d == 7.0));
    // Without friction (mu0 = 0) no ratio can be written as -mu0 sigma: no held Jacobian, the
    // map takes differences.
    let frictionless = active(&[("mu0", 0.0)]).model().unwrap();
    assert!(!StanceJacobian::any_law(&frictionless).has_contact(Contact::Stuck));
}

/// The full map Jacobian at `s` by Richardson-extrapolated central differences of whole steps
/// (`h = 1e-4`, `5e-5`).
fn extrapolated(model: &Model, s: &[f64]) -> Vec<Vec<f64>> {
    let cfg = SimConfig::default();
    let a = finite_difference_map_with_step(model, &cfg, s, 1e-4).unwrap();
    let b = finite_difference_map_with_step(model, &cfg, s, 5e-5).unwrap();
    a.jacobian
        .iter()
        .zip(&b.jacobian)
        .map(|(ra, rb)| {
            ra.iter()
                .zip(rb)
                .map(|(x, y)| (4.0 * y - x) / 3.0)
                .collect()
        })
        .collect()
}

/// The exact map Jacobian at the gait `fp` of `model` against extrapolated differences, every
/// column but the held foot's velocity's (`xd`, `zd`: after a sticking impact the map exists
/// only with the foot at rest, and the exact columns are zero while the differences push the
/// foot into a slide, `docs/poincare.md`); returns the largest difference.
fn exact_against_differences(model: &Model, fp: &FixedPoint, tol: f64) -> f64 {
    let n = model.n();
    let exact = poincare_map_with(
        model,
        &SimConfig::default(),
        &fp.state_plus,
        JacobianMethod::Variational,
    )
    .unwrap();
    assert_eq!(exact.method, JacobianMethod::Variational);
    let fd = extrapolated(model, &fp.state_plus);
    let mut worst = 0.0_f64;
    for (i, (re, rd)) in exact.jacobian.iter().zip(&fd).enumerate() {
        for (j, (e, d)) in re.iter().zip(rd).enumerate() {
            if j == n || j == n + 1 {
                continue;
            }
            worst = worst.max((e - d).abs() / d.abs().max(1.0));
            assert!(
                (e - d).abs() <= tol * d.abs().max(1.0),
                "d P[{i}]/d s[{j}]: exact {e}, differences {d}"
            );
        }
    }
    worst
}

#[test]
fn the_held_active_walkers_map_jacobian_is_exact_and_agrees_with_extrapolated_differences() {
    let model = active(&[("mu0", 1.0)]).model().unwrap();
    let fp = converged(&model);
    assert_eq!(fp.jacobian_method, JacobianMethod::Variational);
    assert_eq!(fp.impact, ImpactRegime::Stick);
    // The differences' error: each step's own error (rtol 1e-12, about 1e-12 after the
    // stance) over 5e-5, times 3 from the extrapolation: at most about 6e-8 (the neighbouring
    // steps take nearly the same step sizes, so it is much less: 5e-11 seen); their O(h^4)
    // term and the exact Jacobian's integration error (about 1e-11) are below. 1e-7 relative,
    // where a missing elimination or saltation is off by 1e-2 or more.
    let worst = exact_against_differences(&model, &fp, 1e-7);
    eprintln!("largest relative difference {worst:e}");
}

#[test]
fn the_three_link_bipeds_held_map_jacobian_is_exact_and_agrees_with_extrapolated_differences() {
    // Its mass matrix's inverse has no closed form within the derivation's limit: its held
    // foot goes through `closed_loop_stick_jacobian`, the structured solve differentiated
    // (`derive/src/model/forward.rs`), and its map is exact. Tolerance as for the paper's
    // walker above (seen: 2e-10).
    let model = three_link().model().unwrap();
    let fp = converged(&model);
    assert_eq!(fp.jacobian_method, JacobianMethod::Variational);
    assert_eq!(fp.impact, ImpactRegime::Stick);
    let worst = exact_against_differences(&model, &fp, 1e-7);
    eprintln!("largest relative difference {worst:e}");
}

/// The time the foot spends stuck in one step from `s`, with the step's period.
fn stuck_time(model: &Model, s: &[f64]) -> (f64, f64) {
    let limits = WalkLimits {
        max_steps: 1,
        ..WalkLimits::default()
    };
    let w = walk(model, &tight(), s, &limits);
    let step = w.steps.first().unwrap();
    (step.stuck_time, step.period)
}

/// The foot's phases through one step from `s`, from the recorded samples: `true` for a run
/// of samples with the foot at rest (`xd = 0`: held), `false` for one sliding.
fn foot_phases(model: &Model, s: &[f64]) -> Vec<bool> {
    let limits = WalkLimits {
        max_steps: 1,
        record: true,
        ..WalkLimits::default()
    };
    let w = walk(model, &tight(), s, &limits);
    let n = model.n();
    let mut phases: Vec<bool> = Vec::new();
    for sample in w.samples.iter().filter(|x| x.step == 0) {
        let held = sample.state[n] == 0.0;
        if phases.last() != Some(&held) {
            phases.push(held);
        }
    }
    phases
}

#[test]
fn a_gait_that_slips_within_the_step_has_the_exact_jacobian() {
    // mu0 = 0.5: the impact sticks, the held foot starts to slip, then comes to rest and
    // sticks again: both events' saltation and the held stance on both sides of them. (At the
    // slip the field is continuous, so that saltation is the identity to the event's
    // location, and the slip guard's gradient and time rate hardly matter; at the return to
    // rest it is not.)
    let model = active(&[("mu0", 0.5)]).model().unwrap();
    let fp = converged(&model);
    assert_eq!(fp.jacobian_method, JacobianMethod::Variational);
    let (stuck, period) = stuck_time(&model, &fp.state_plus);
    assert!(
        0.05 * period < stuck && stuck < 0.95 * period,
        "stuck {stuck} of {period}"
    );
    // Held after the sticking impact, then a slip, then held again (twice, at this gait).
    let phases = foot_phases(&model, &fp.state_plus);
    assert!(phases.starts_with(&[true, false, true]), "{phases:?}");
    // As for the held gait (7e-11 seen).
    let worst = exact_against_differences(&model, &fp, 1e-7);
    eprintln!("largest relative difference {worst:e}");
}

#[test]
fn the_exact_multipliers_lie_within_the_extrapolated_differences_bounds() {
    let cases = [
        ("active held", active(&[("mu0", 1.0)])),
        ("active stick-slip", active(&[("mu0", 0.5)])),
    ];
    for (name, setup) in cases {
        let model = setup.model().unwrap();
        let fp = converged(&model);
        let cfg = SimConfig::default();
        let r = Section::of(&model).reduce(&fp.state_plus);
        let estimated =
            jacobian_error(&model, &cfg, &r, JacobianMethod::ExtrapolatedDifferences).unwrap();
        let exact = multiplier_errors(&model, &cfg, &fp).unwrap();
        for b in multiplier_bounds(&estimated.jacobian, &estimated.error) {
            let Some(bound) = b.error else { continue };
            let m = b.multiplier;
            let off = exact
                .iter()
                .map(|e| (m.re - e.multiplier.re).hypot(m.im - e.multiplier.im))
                .fold(f64::INFINITY, f64::min);
            assert!(off <= bound, "{name}: {b:?} vs {exact:?}: {off:e}");
        }
        // The exact multipliers' own bounds, an order of the integration's tolerance: far
        // below the differences' (1e-7 to 1e-4 on these walkers).
        for e in &exact {
            if let Some(bound) = e.error {
                assert!(bound < 1e-8, "{name}: {e:?}");
            }
        }
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

/// The exact column of `name` at `s` against the Richardson extrapolation of central
/// differences of the map in `p` (`h = 1e-4 max(|p|, 1)`), as `parameter_column.rs` checks the
/// sliding and smooth stances: the maps' error `1e-12` over the step, times three, about
/// `3e-8` relative; `2e-7` relative to `max(1, |value|)`. Returns the column's largest entry.
fn check_column(setup: &Setup, name: &str, s: &[f64]) -> f64 {
    let model = setup.model().unwrap();
    let zero = vec![0.0; s.len()];
    let (_, col) = parameter_column(&model, &tight(), s, name, &zero)
        .unwrap()
        .unwrap_or_else(|| panic!("{name} has no exact column"));
    let p = setup.params.get(name).unwrap();
    let h = 1e-4 * p.abs().max(1.0);
    let [up, down, half_up, half_down] =
        [h, -h, h / 2.0, -h / 2.0].map(|d| image(setup, name, p + d, s));
    let mut exact = col.d_state.clone();
    exact.extend([col.d_period, col.d_dx]);
    let mut moved = 0.0_f64;
    for (i, e) in exact.iter().enumerate() {
        let d1 = (up[i] - down[i]) / (2.0 * h);
        let d2 = (half_up[i] - half_down[i]) / h;
        let r = (4.0 * d2 - d1) / 3.0;
        moved = moved.max(r.abs());
        assert!(
            (e - r).abs() <= 2e-7 * r.abs().max(1.0),
            "d/d{name} of component {i}: exact {e}, differences {r} (D1 {d1}, D2 {d2})"
        );
    }
    moved
}

#[test]
fn the_held_and_slipping_stances_have_exact_columns_in_the_ramp_and_the_gains() {
    // Gains on, and the start off the controller's manifold (the torso 0.02 rad and 0.1 rad/s
    // off), so that the tracking error is not zero and the gains' columns are not; mu0 = 1
    // holds the foot through the step, mu0 = 0.5 lets it slip and stick again (the slip
    // guard's rate in the parameter through v, and its time rate).
    for (mu0, held) in [(1.0, true), (0.5, false)] {
        let setup = active(&[("mu0", mu0), ("K_P", 10.0), ("K_D", 2.0)]);
        let model = setup.model().unwrap();
        let mut s = model.start_state().to_vec();
        let n = model.n();
        s[3] += 0.05;
        s[n + 3] += 0.2;
        let (stuck, period) = stuck_time(&model, &s);
        let whole = (period - stuck).abs() <= 1e-12 * period;
        assert_eq!(whole, held, "mu0 = {mu0}: stuck {stuck} of {period}");
        assert!(
            stuck > 0.05 * period,
            "mu0 = {mu0}: stuck {stuck} of {period}"
        );
        for name in ["T_set", "K_P", "K_D"] {
            let moved = check_column(&setup, name, &s);
            // Not trivially zero: the parameter moves the step.
            assert!(moved > 1e-3, "mu0 = {mu0}, d/d{name}: {moved:e}");
        }
        // mu0 moves only a step that slips (the held field and the sticking impact do not
        // depend on it).
        let moved = check_column(&setup, "mu0", &s);
        assert_eq!(moved > 1e-3, !held, "mu0 = {mu0}, d/dmu0: {moved:e}");
    }
}

#[test]
fn the_three_link_bipeds_held_stance_has_exact_columns_in_its_gains() {
    // The held foot through `closed_loop_stick_jacobian` (no friction ratio to eliminate): the
    // gains' columns, with the torso started 0.05 rad and 0.2 rad/s off its output so that
    // they are not zero.
    let setup = three_link();
    let model = setup.model().unwrap();
    let mut s = model.start_state().to_vec();
    let n = model.n();
    s[n - 1] += 0.05;
    s[2 * n - 1] += 0.2;
    let (stuck, period) = stuck_time(&model, &s);
    assert!(
        (period - stuck).abs() <= 1e-12 * period,
        "held: {stuck} of {period}"
    );
    for name in ["K_P", "K_D"] {
        // Not trivially zero: the gains move the step (seen: 2.8e-4 for K_P, its error
        // decays fast at K_P = 100), fifty times the check's resolution 2e-7.
        let moved = check_column(&setup, name, &s);
        assert!(moved > 1e-5, "d/d{name}: {moved:e}");
    }
}
