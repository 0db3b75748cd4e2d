//! The compass gait written as a model file (`models/compass-gait.toml`) derives the inertia
//! matrix of the dynamic model Goswami, Thuilot and Espiau print for it (A study of the passive
//! gait of a compass-like biped robot, Int. J. Robotics Research 17(12), 1998), in their
//! notation `q = (theta_ns, theta_s)`:
//!
//! ```text
//! M = [ m b^2                     -m l b cos(theta_s - theta_ns) ]
//!     [ -m l b cos(theta_s - theta_ns)   (m_H + m) l^2 + m a^2   ],   l = a + b,
//! ```
//!
//! the block of our `M` over the two leg angles (the stance foot's `x`, `z` are our extra
//! coordinates; with the foot held they drop out). Our swing leg is at `th_sw` with the swing
//! foot at `hip - l (sin th_sw, cos th_sw)`, which is their `theta_ns`. Compared exactly.

use walker_scene::model::Model;
use walker_symbolic::model::Mechanics;
use walker_symbolic::ratfunc::RatFunc;

#[test]
fn compass_gait_inertia_matrix_is_goswamis() {
    let path = format!("{}/../models/compass-gait.toml", env!("CARGO_MANIFEST_DIR"));
    let model = Model::from_file(std::path::Path::new(&path)).expect("shipped model loads");
    let mech = Mechanics::new(&model).expect("derives");
    let s = |n: &str| RatFunc::sym(mech.syms.get(n).expect("symbol"));
    let (m, mh, a, b) = (s("m"), s("m_H"), s("a"), s("b"));
    let l = &a + &b;
    let th_st = mech.syms.get("th_st").expect("th_st");
    let th_sw = mech.syms.get("th_sw").expect("th_sw");
    let cos = walker_symbolic::paper::cos(&[(th_st, 1), (th_sw, -1)]).expect("cos");
    let (st, sw) = (2, 3);
    let want_sw_sw = &(&m * &b) * &b;
    let want_cross = -(&(&(&m * &l) * &b) * &cos);
    let want_st_st = &(&(&mh + &m) * &(&l * &l)) + &(&(&m * &a) * &a);
    assert!(*mech.mass.get(sw, sw) == want_sw_sw, "M_sw,sw = m b^2");
    assert!(*mech.mass.get(sw, st) == want_cross, "M_sw,st = -m l b cos");
    assert!(*mech.mass.get(st, sw) == want_cross, "M_st,sw = -m l b cos");
    assert!(
        *mech.mass.get(st, st) == want_st_st,
        "M_st,st = (m_H + m) l^2 + m a^2"
    );
    // The total mass sits in the translational block, as for any floating-base walker.
    let total = &(&m + &m) + &mh;
    assert!(*mech.mass.get(0, 0) == total && *mech.mass.get(1, 1) == total);
}

#[test]
fn a_huge_power_is_an_error_naming_its_place_not_a_panic() {
    let path = format!(
        "{}/../models/rimless-wheel.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).expect("shipped model");
    let text = text.replacen("mass = \"m\"", "mass = \"m^300\"", 1);
    assert!(text.contains("m^300"), "the mutation applies");
    let model = Model::from_toml(&text, "huge-power.toml").expect("the loader accepts powers");
    let err = Mechanics::new(&model).expect_err("refused").to_string();
    assert!(
        err.contains("huge-power.toml:") && err.contains("exponent 300"),
        "{err}"
    );
}
