//! Each multiplier's error bound (`walker::poincare::multiplier_errors`): it covers the distance
//! to what no one here computed (the independent SymPy/SciPy reference of the simplest walking
//! model, `sympy_ref/simplest_walker.json`; the rimless wheel's closed form `eta^2`) and to the
//! exact Jacobian's multipliers where the Jacobian is by central differences, and it is small
//! enough to say something (not a bound of order one).

use std::path::{Path, PathBuf};

use walker::model::{Friction, ImpactLaw, Model};
use walker::poincare::{
    FixedPoint, FixedPointOptions, JacobianMethod, Section, Status, fixed_point, jacobian_error,
    multiplier_bounds, multiplier_errors,
};
use walker::setup::{Overrides, Setup};
use walker::sim::SimConfig;

fn shipped(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../models")
        .join(format!("{name}.toml"))
}

/// `models/<name>.toml` derived at run time with the overrides `ov`.
fn setup(name: &str, ov: &Overrides) -> Setup {
    let source = walker_load::runtime_source();
    Setup::from_model_file(&shipped(name), ov, Some(&source as &_)).expect("the model sets up")
}

fn converged(model: &Model) -> FixedPoint {
    let fp = fixed_point(
        model,
        &SimConfig::default(),
        &FixedPointOptions::for_model(model),
    )
    .expect("a fixed point");
    assert_eq!(fp.status, Status::Converged, "{fp:?}");
    fp
}

/// `models/simplest-walker.toml` derived at run time, and its gait.
fn simplest_walker_at_its_gait() -> (Model, FixedPoint) {
    let model = setup("simplest-walker", &Overrides::default())
        .model()
        .expect("kernels");
    let fp = converged(&model);
    (model, fp)
}

/// The reference's multipliers (`sympy_ref/simplest_walker.json`: its own Lagrangian, impact and
/// variational equations, SciPy's DOP853 at `rtol = 1e-13`).
fn reference_multipliers() -> Vec<(f64, f64)> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../sympy_ref/simplest_walker.json");
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).expect("the reference")).expect("JSON");
    v["multipliers"]
        .as_array()
        .expect("the multipliers")
        .iter()
        .map(|c| (c[0].as_f64().expect("re"), c[1].as_f64().expect("im")))
        .collect()
}

#[test]
fn the_simplest_walkers_bounds_cover_the_independent_reference_and_are_below_1e_7() {
    let (model, fp) = simplest_walker_at_its_gait();
    let bounds = multiplier_errors(&model, &SimConfig::default(), &fp).expect("the bounds");
    let reference = reference_multipliers();
    assert_eq!(bounds.len(), reference.len());
    for ((b, m), (re, im)) in bounds.iter().zip(&fp.multipliers).zip(&reference) {
        // The same Jacobian evaluated again: the same multipliers, bit for bit.
        assert_eq!(b.multiplier, *m);
        let error = b.error.expect("simple multipliers");
        // The reference's own error is about 2e-12 (it moves by that from rtol 1e-13 to 3e-14).
        let off = (m.re - re).hypot(m.im - im);
        assert!(
            off <= error + 1e-11,
            "{m:?} vs ({re}, {im}): {off:e} > {error:e}"
        );
        // Informative: the gait's pair has modulus 0.59; the issue asks agreement to 1e-8 and
        // the bound (twice the estimate, Frobenius norm, condition number) stays within 1e-7.
        assert!(error < 1e-7, "{m:?} +- {error:e}");
    }
}

#[test]
fn the_rimless_wheels_bound_covers_the_closed_form_eta_squared() {
    for phi in [0.05, 0.2] {
        let ov = Overrides {
            friction: Some(Friction::Coulomb),
            impact: Some(ImpactLaw::Coulomb),
            set: vec![("phi".into(), phi), ("mu0".into(), 3.0)],
            ..Overrides::default()
        };
        let setup = setup("rimless-wheel", &ov);
        let model = setup.model().expect("kernels");
        let fp = converged(&model);
        let bounds = multiplier_errors(&model, &SimConfig::default(), &fp).expect("the bounds");
        // eta = (I + m l^2 cos alpha) / (I + m l^2) (Coleman, Chatterjee and Ruina 1997).
        let p = |name: &str| setup.params.get(name).expect("a parameter");
        let (m, l, rg, alpha) = (p("m"), p("l"), p("rg"), p("alpha"));
        let i = m * rg * rg;
        let eta = (i + m * l * l * alpha.cos()) / (i + m * l * l);
        let lead = bounds[0];
        let error = lead.error.expect("a simple multiplier");
        let off = (lead.multiplier.re - eta * eta).hypot(lead.multiplier.im);
        assert!(
            off <= error,
            "phi = {phi}: {lead:?} vs {}: {off:e}",
            eta * eta
        );
        assert!(error < 1e-8, "phi = {phi}: {lead:?}");
    }
}

#[test]
fn a_jacobian_by_central_differences_gets_a_bound_that_covers_the_exact_multipliers() {
    // The simplest walker's map has a large third derivative (`docs/poincare.md`): differences
    // at the default step are off by about 4e-4, the case where a bound matters.
    let (model, fp) = simplest_walker_at_its_gait();
    let cfg = SimConfig::default();
    let r = Section::of(&model).reduce(&fp.state_plus);
    let estimated =
        jacobian_error(&model, &cfg, &r, JacobianMethod::FiniteDifferences).expect("differences");
    let differenced = multiplier_bounds(&estimated.jacobian, &estimated.error);
    let exact = multiplier_errors(&model, &cfg, &fp).expect("the exact bounds");
    for (d, e) in differenced.iter().zip(&exact) {
        let error = d.error.expect("simple multipliers");
        let off = (d.multiplier.re - e.multiplier.re).hypot(d.multiplier.im - e.multiplier.im);
        assert!(off <= error, "{d:?} vs {e:?}: {off:e}");
        // Informative: the differenced pair (off by 1.2e-4) is placed to within a few percent
        // of its modulus 0.59, and the bound tells it from the exact Jacobian's by a factor of
        // at least 1000 (the first-order bound with the Frobenius norm is conservative, by up
        // to two orders of magnitude here: it takes the worst direction of the error matrix).
        assert!(error < 0.05, "{d:?}");
        let exact_error = e.error.expect("simple multipliers");
        assert!(1e3 * exact_error < error, "{d:?} vs {e:?}");
    }
}

#[test]
fn extrapolated_differences_place_the_multipliers_near_the_independent_reference_with_a_bound() {
    // The same map's differences at 1e-4 and 5e-5 extrapolated (`walker fixed-point`'s
    // refinement where a phase has no Jacobian kernel): against the SymPy/SciPy reference the
    // plain differences are off by 1.2e-4; the extrapolation removes their h^2 term, leaving
    // O(h^4) and the maps' noise (about 1e-12 / 5e-5 = 2e-8 before the eigenvalues' condition).
    // Each bound covers the distance to the reference, and is below 1e-6: a hundred times
    // below the plain differences' distance.
    let (model, fp) = simplest_walker_at_its_gait();
    let cfg = SimConfig::default();
    let r = Section::of(&model).reduce(&fp.state_plus);
    let estimated = jacobian_error(&model, &cfg, &r, JacobianMethod::ExtrapolatedDifferences)
        .expect("differences");
    let reference = reference_multipliers();
    for b in multiplier_bounds(&estimated.jacobian, &estimated.error) {
        let m = b.multiplier;
        let Some(error) = b.error else { continue };
        let off = reference
            .iter()
            .map(|(re, im)| (m.re - re).hypot(m.im - im))
            .fold(f64::INFINITY, f64::min);
        assert!(off <= error, "{b:?}: {off:e}");
        assert!(error < 1e-6, "{b:?}");
    }
}
