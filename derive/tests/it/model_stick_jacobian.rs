//! `stick_jacobian`, the stuck stance's partial derivatives (the Poincare map's variational
//! equations in a stuck phase, and the slip guard's gradient): every entry is the derivative of
//! the matching output of `stick` by the matching state symbol, compared exactly as rational
//! functions (cross-multiplied, modulo `sin^2 + cos^2 = 1`), so a wrong column, row or sign
//! fails. It exists for the models without inputs whose stuck stance has a closed form, and not
//! for a model with inputs (whose stuck phase is `closed_loop_stick`).

use walker_scene::model::Model;
use walker_symbolic::model::ModelDerivation;

fn load(name: &str) -> Model {
    let path = format!("{}/../models/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    Model::from_file(std::path::Path::new(&path)).expect("shipped model loads")
}

/// Checks `stick_jacobian` of `name` against the derivatives of `stick`'s outputs.
fn check(name: &str) {
    let d = ModelDerivation::new(&load(name)).expect("derives");
    let stick = d.kernel("stick").expect("stick");
    let jac = d.kernel("stick_jacobian").expect("stick_jacobian");
    let n = d.syms.q.len();
    let state: Vec<_> = d.syms.q.iter().chain(&d.syms.qd).copied().collect();
    assert_eq!(
        stick.outputs.len(),
        n + 2,
        "{name}: qdd, lambda_t, lambda_n"
    );
    assert_eq!(jac.outputs.len(), (n + 2) * 2 * n, "{name}: (n + 2) x 2n");
    for (i, (out, f)) in stick.outputs.iter().enumerate() {
        for (j, &x) in state.iter().enumerate() {
            let (_, entry) = &jac.outputs[i * 2 * n + j];
            assert!(
                *entry == f.diff(x),
                "{name}: d {out} / d {} differs",
                d.symbols.name(x)
            );
        }
    }
    // The stuck foot's accelerations are zero, and so are their rows.
    for entry in &jac.outputs[..2 * 2 * n] {
        assert!(entry.1.is_zero(), "{name}: {} is not zero", entry.0);
    }
}

#[test]
fn the_stuck_stances_jacobian_is_the_derivative_of_stick_for_the_simplest_walker() {
    check("simplest-walker");
}

#[test]
fn the_stuck_stances_jacobian_is_the_derivative_of_stick_for_the_passive_walkers() {
    check("paper-passive");
    check("rimless-wheel");
}

#[test]
fn a_model_with_inputs_has_no_stick_jacobian() {
    let d = ModelDerivation::new(&load("paper-active")).expect("derives");
    assert!(d.kernel("stick_jacobian").is_err());
    assert!(d.kernel("closed_loop_stick").is_ok());
}
