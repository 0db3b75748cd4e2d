//! Angle combinations, base-angle divisors, zero divisors and parameter ranges, on the typed
//! AST and on small models.

use std::collections::BTreeMap;

use walker_scene::model::angles::{add_denominators, angle_combination, zero_divisor};
use walker_scene::model::{Interval, Model, ModelError, Rational, parse_expr};

fn is_angle(name: &str) -> bool {
    matches!(name, "th1" | "th2" | "alpha" | "phi")
}

fn divisors(exprs: &[(&str, bool)]) -> BTreeMap<String, u64> {
    let mut out = BTreeMap::new();
    for (text, additive) in exprs {
        let e = parse_expr(text);
        assert!(e.is_ok(), "{text}");
        if let Ok(e) = e {
            assert!(add_denominators(&e, &is_angle, *additive, &mut out).is_ok());
        }
    }
    out
}

#[test]
fn an_angle_combination_has_rational_coefficients() {
    let e = parse_expr("cos(2*(th1 - alpha)/3 + th2 - th2 + phi/2)");
    let arg = match e.map(|e| e.kind) {
        Ok(walker_scene::model::ExprKind::Call(_, arg)) => Some(*arg),
        _ => None,
    };
    let combo = arg.map(|a| angle_combination(&a, &is_angle));
    let expected: BTreeMap<String, Rational> = [
        ("alpha", Rational::new(-2, 3)),
        ("phi", Rational::new(1, 2)),
        ("th1", Rational::new(2, 3)),
    ]
    .into_iter()
    .filter_map(|(k, v)| Some((k.to_owned(), v?)))
    .collect();
    assert_eq!(combo, Some(Ok(expected)));
}

#[test]
fn the_divisor_is_the_lcm_of_the_denominators_in_sines_guards_and_relabels() {
    let d = divisors(&[("l*sin(th1/2 + phi)", false), ("cos(th1/3)", false)]);
    assert_eq!(d.get("th1"), Some(&6));
    assert_eq!(d.get("phi"), Some(&1));
    // A guard's additive terms count, a product's do not.
    let d = divisors(&[("alpha/2 - th1 + l*th2/5", true)]);
    assert_eq!(d.get("alpha"), Some(&2));
    assert_eq!(d.get("th2"), None);
    // Outside guards and relabels, bare angles do not count.
    let d = divisors(&[("alpha/2 - th1", false)]);
    assert_eq!(d.get("alpha"), None);
}

#[test]
fn a_model_with_a_third_of_an_angle_in_a_sine_has_divisor_three() -> Result<(), ModelError> {
    let text = include_str!("../../../models/compass-gait.toml").replace(
        "com = [\"x + a*sin(th_st)\", \"z + a*cos(th_st)\"]",
        "com = [\"x + a*sin(th_st/3)\", \"z + a*cos(th_st)\"]",
    );
    let m = Model::from_toml(&text, "c.toml")?;
    assert_eq!(m.base_angle_divisor("th_st"), Some(3));
    assert_eq!(m.base_angle_divisor("th_sw"), Some(1));
    Ok(())
}

#[test]
fn only_constant_zero_divisors_are_found() {
    let at = |t: &str| {
        parse_expr(t)
            .ok()
            .and_then(|e| zero_divisor(&e))
            .map(|s| s.start)
    };
    assert_eq!(at("x/0"), Some(2));
    assert_eq!(at("x/(2 - 2*1)"), Some(2));
    assert_eq!(at("(1 - 1)^-2"), Some(0));
    assert_eq!(at("x/(y - y)"), None);
    assert_eq!(at("x/0.001"), None);
    assert_eq!(at("0^2"), None);
}

#[test]
fn ranges_parse_with_pi_and_open_infinities() {
    let r = |s: &str| s.parse::<Interval>();
    assert!(r("(0, inf)").is_ok_and(|i| i.contains(1e300) && !i.contains(0.0)));
    assert!(
        r("[0, pi/2)").is_ok_and(|i| i.contains(0.0) && !i.contains(std::f64::consts::FRAC_PI_2))
    );
    assert!(r("(-pi/2, pi/2]").is_ok_and(|i| i.contains(-1.5) && !i.contains(-1.6)));
    assert!(r("[-1.5e0, -inf)").is_err());
    assert!(r("[0, inf]").is_err());
    assert!(r("[2, 2]").is_ok_and(|i| i.contains(2.0)));
    for bad in [
        "(0, pi/0)",
        "(0, nan)",
        "0, 1",
        "(0; 1)",
        "(0, 1, 2)",
        "",
        "(a, b)",
        "(0, 2pi)",
    ] {
        assert!(r(bad).is_err(), "{bad}");
    }
}

#[test]
fn rationals_report_overflow_instead_of_wrapping() {
    let big = Rational::new(i64::MAX, 1);
    assert_eq!(big.and_then(|b| b.checked_add(Rational::ONE)), None);
    assert_eq!(Rational::new(2, 1).and_then(|r| r.pow(64)), None);
    assert_eq!(
        Rational::new(-1, 1).and_then(|r| r.pow(3)),
        Rational::new(-1, 1)
    );
    assert_eq!(Rational::new(2, -4), Rational::new(-1, 2));
    assert_eq!(Rational::ZERO.pow(-1), None);
}
