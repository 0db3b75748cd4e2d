//! Bad input to the scene parser: arbitrary strings and structured-but-wrong TOML never panic,
//! every rejection names a field that its message contains, and every valid generated scene is
//! accepted.

use proptest::prelude::*;
use walker_gen::Scene;

/// A syntax error on a line whose key is empty (`"="`, `"=\"\"a"`) names the file (found by this
/// fuzz test: it used to give an empty field).
#[test]
fn a_line_with_an_empty_key_names_a_field() {
    for src in ["=", "=\"\"a", "name = \"t\"\n= 1\n"] {
        let e = Scene::from_toml_str(src, "t.toml").err();
        assert!(e.is_some_and(|e| !e.field().is_empty()), "{src:?}");
    }
}

/// Checks the contract on one input: no panic (the test itself), and a rejection's field is
/// non-empty and appears in the message.
fn check(src: &str) -> Result<(), TestCaseError> {
    if let Err(e) = Scene::from_toml_str(src, "fuzz.toml") {
        let field = e.field();
        let message = e.to_string();
        prop_assert!(!field.is_empty(), "empty field for {src:?}: {message}");
        let leaf = field.rsplit('.').next().unwrap_or(field);
        prop_assert!(
            message.contains(leaf),
            "message does not name `{leaf}` for {src:?}: {message}"
        );
    }
    Ok(())
}

const PARAMS: [&str; 14] = [
    "m1",
    "m2",
    "l",
    "I1",
    "I2",
    "g",
    "alpha",
    "alpha_deg",
    "phi",
    "mu0",
    "c",
    "T_set",
    "K_P",
    "K_D",
];

/// A TOML value of any type, often a bad one for a number field.
fn value() -> impl Strategy<Value = String> {
    prop_oneof![
        any::<f64>().prop_map(|v| format!("{v:?}")),
        (-1e3..1e3_f64).prop_map(|v| format!("{v:?}")),
        Just("nan".to_owned()),
        Just("inf".to_owned()),
        Just("-inf".to_owned()),
        Just("0.0".to_owned()),
        Just("-0.0".to_owned()),
        any::<i64>().prop_map(|v| v.to_string()),
        "[a-z]{0,6}".prop_map(|s| format!("{s:?}")),
        Just("true".to_owned()),
        Just("[1.0, 2.0]".to_owned()),
        Just("{ x = 1 }".to_owned()),
    ]
}

/// A scene with every top-level field present or not, each a good or a wrong value.
fn structured() -> impl Strategy<Value = String> {
    let top = |key: &'static str, good: &'static [&'static str]| {
        prop_oneof![
            4 => proptest::sample::select(good).prop_map(move |v| format!("{key} = {v:?}\n")),
            1 => value().prop_map(move |v| format!("{key} = {v}\n")),
            1 => Just(String::new()),
        ]
    };
    (
        top("name", &["t", "active-level", "", "bad name!", "x_y-9"]),
        top("floor", &["level", "slope", "roof"]),
        top("friction", &["none", "tanh", "sign", "coulomb"]),
        top("torso", &["actuated", "passive", "wobbly"]),
        proptest::option::of(proptest::collection::vec(
            proptest::sample::select(
                &[
                    "accel_level",
                    "lambda_level",
                    "accel_slope",
                    "impact2_level",
                    "energy",
                    "nope",
                ][..],
            ),
            0..4,
        )),
        proptest::collection::vec(
            (
                prop_oneof![
                    9 => proptest::sample::select(&PARAMS[..]).prop_map(str::to_owned),
                    1 => "[a-z_]{1,6}",
                ],
                value(),
            ),
            0..6,
        ),
        "[a-z]{0,3}",
    )
        .prop_map(|(n, f, fr, t, kernels, fixed, extra)| {
            let mut s = format!("{n}{f}{fr}{t}");
            if let Some(k) = kernels {
                s.push_str(&format!("kernels = {k:?}\n"));
            }
            if !extra.is_empty() {
                s.push_str(&format!("{extra} = 1\n"));
            }
            s.push_str("[fixed]\n");
            for (k, v) in fixed {
                s.push_str(&format!("{k} = {v}\n"));
            }
            s
        })
}

/// A valid scene: a consistent structure and in-range values for parameters it has.
fn valid() -> impl Strategy<Value = String> {
    (
        prop_oneof![
            Just(("level", "actuated")),
            Just(("level", "passive")),
            Just(("slope", "passive")),
        ],
        proptest::sample::select(&["none", "tanh", "coulomb"][..]),
        proptest::collection::vec(proptest::bool::ANY, 14),
        proptest::collection::vec(1e-3..1e3_f64, 14),
        0.01..3.1_f64,
        0.0..1.5_f64,
    )
        .prop_map(|((floor, torso), friction, pick, vals, alpha, phi)| {
            let mut s = format!(
                "name = \"fz\"\nfloor = \"{floor}\"\nfriction = \"{friction}\"\ntorso = \"{torso}\"\n[fixed]\n"
            );
            let has = |p: &str| match p {
                "phi" => floor == "slope",
                "mu0" => friction != "none",
                "c" => friction == "tanh",
                "T_set" | "K_P" | "K_D" => torso == "actuated",
                "alpha_deg" => false,
                _ => true,
            };
            for ((p, &on), v) in PARAMS.iter().zip(&pick).zip(&vals) {
                if on && has(p) {
                    let v = match *p {
                        "alpha" => alpha,
                        "phi" => phi,
                        _ => *v,
                    };
                    s.push_str(&format!("{p} = {v:?}\n"));
                }
            }
            s
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn arbitrary_strings_never_panic(src in ".{0,200}") {
        check(&src)?;
    }

    #[test]
    fn toml_like_strings_never_panic(src in "[a-z_=\\[\\]\"\\. 0-9\n-]{0,120}") {
        check(&src)?;
    }

    #[test]
    fn structured_but_wrong_scenes_name_their_field(src in structured()) {
        check(&src)?;
    }

    #[test]
    fn valid_scenes_are_accepted(src in valid()) {
        let r = Scene::from_toml_str(&src, "fuzz.toml");
        prop_assert!(r.is_ok(), "{src}\n{:?}", r.err().map(|e| e.to_string()));
    }
}
