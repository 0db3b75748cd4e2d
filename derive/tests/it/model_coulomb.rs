//! The impact with Coulomb friction's ingredients (`impact_coulomb`) of a model without the
//! double-support test (`[impact] double_support = false`; no shipped model is one): the kernel
//! keeps its layout, with the old stance foot's row `r` (the gap rate of the stance foot, which
//! the simulator then ignores), and the double-support impact is absent.

use walker_scene::model::Model;
use walker_symbolic::RatFunc;
use walker_symbolic::model::ModelDerivation;

#[test]
fn without_the_double_support_test_the_coulomb_impact_keeps_the_old_stance_foots_row() {
    let path = format!(
        "{}/../models/rimless-wheel.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(path).expect("shipped model");
    let text = text.replacen("double_support = true", "double_support = false", 1);
    assert!(
        text.contains("double_support = false"),
        "the mutation applies"
    );
    let model = Model::from_toml(&text, "single-support.toml").expect("loads");
    let d = ModelDerivation::new(&model).expect("derives");
    assert!(
        d.kernel("impact_double").is_err(),
        "no double-support impact"
    );
    assert!(d.kernel("impact_double_rows").is_err());
    let k = d.kernel("impact_coulomb").expect("the Coulomb impact");
    let names: Vec<&str> = k.outputs.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names,
        [
            "qdl0", "qdl1", "qdl2", "v_t", "v_n", "v_r", "W_tt", "W_tn", "W_tr", "W_nn", "W_nr",
            "W_rr", "R00", "R01", "R10", "R11", "R20", "R21"
        ]
    );
    // v_r = d/dt (x sin phi + z cos phi) at qdl = qd- (the wheel has no locks).
    let s = |n: &str| RatFunc::sym(d.symbols.lookup(n).expect("symbol"));
    let phi = d.symbols.lookup("phi").expect("phi");
    let (sin, cos) = (
        walker_symbolic::paper::sin(&[(phi, 1)]).expect("sin"),
        walker_symbolic::paper::cos(&[(phi, 1)]).expect("cos"),
    );
    let want = &(&s("xd") * &sin) + &(&s("zd") * &cos);
    assert!(
        *k.output("v_r").expect("v_r") == want,
        "v_r is the stance foot's gap rate"
    );
}
