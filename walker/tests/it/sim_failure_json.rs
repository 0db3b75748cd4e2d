//! The JSON of a failure is one flat object with the keys it had when `Failure` was an enum of
//! struct variants: `kind`, `step`, `t`, `state` and the kind's own data (users' scripts read
//! them). The one change: `ImpactAtStart` now has a `t` (0). `LambdaNumeratorHuge` (a blown-up
//! `lambda` with a regular denominator, named `LambdaDenominatorZero` before) is new, with its
//! `lambda` and `u`. Since the simulator is model-generic, the paper's `FellBackward { th1 }` is
//! one of the model's falls, `Fall { name: "fell-backward", doc }` (the angle is in `state`).

use std::collections::BTreeSet;

use serde_json::{Value, json};
use walker::model::Slide;
use walker::ode::GaveUp;
use walker::sim::{Failure, FailureKind};

const STATE: [f64; 8] = [0.5, 0.0, -0.2, 0.1, 1.0, 0.0, 2.0, -1.5];

fn json_of(kind: FailureKind) -> Value {
    serde_json::to_value(kind.at(3, 0.25, STATE.into())).expect("a failure serialises")
}

/// The paper's wheel rolling back onto its rear spoke: the fall `fell-backward` of
/// `models/paper-active.toml` and `models/paper-passive.toml`.
fn fell_backward() -> FailureKind {
    FailureKind::Fall {
        name: "fell-backward".to_owned(),
        doc: "the wheel rolled back onto its rear spoke".to_owned(),
    }
}

fn keys(v: &Value) -> BTreeSet<&str> {
    v.as_object()
        .expect("a failure is a JSON object")
        .keys()
        .map(String::as_str)
        .collect()
}

/// Every kind, with the keys of its own data (before this change each variant held `step`,
/// `state` and, except `ImpactAtStart`, `t`).
fn every_kind() -> Vec<(FailureKind, &'static str, &'static [&'static str])> {
    vec![
        (
            FailureKind::LiftOff { lambda: -1e-13 },
            "LiftOff",
            &["lambda"],
        ),
        (
            FailureKind::ContactInconsistent {
                normal: 2.0,
                tangential: -3.0,
            },
            "ContactInconsistent",
            &["normal", "tangential"],
        ),
        (
            FailureKind::ImpactBeforeTSet { t_set: 0.3 },
            "ImpactBeforeTSet",
            &["t_set"],
        ),
        (
            FailureKind::DoubleSupport { rear_impulse: 0.1 },
            "DoubleSupport",
            &["rear_impulse"],
        ),
        (
            FailureKind::ImpactPulls {
                normal_impulse: -1e-3,
            },
            "ImpactPulls",
            &["normal_impulse"],
        ),
        (
            FailureKind::LambdaDenominatorZero { lambda: 1e9 },
            "LambdaDenominatorZero",
            &["lambda"],
        ),
        (
            FailureKind::LambdaNumeratorHuge {
                lambda: -3e24,
                u: 2.5e7,
            },
            "LambdaNumeratorHuge",
            &["lambda", "u"],
        ),
        (fell_backward(), "Fall", &["name", "doc"]),
        (FailureKind::ImpactAtStart, "ImpactAtStart", &[]),
        (FailureKind::NoImpact, "NoImpact", &[]),
        (FailureKind::NonFinite, "NonFinite", &[]),
        (
            FailureKind::ImpactJam {
                slip: Slide::Backward,
            },
            "ImpactJam",
            &["slip"],
        ),
        (
            FailureKind::Integrator {
                reason: GaveUp::TooManySteps,
            },
            "Integrator",
            &["reason"],
        ),
    ]
}

#[test]
fn every_failure_kind_serialises_to_its_old_flat_keys() {
    for (kind, tag, own) in every_kind() {
        let v = json_of(kind);
        let mut expected: BTreeSet<&str> = ["kind", "step", "t", "state"].into();
        expected.extend(own);
        assert_eq!(keys(&v), expected, "{tag}");
        assert_eq!(v["kind"], tag);
        assert_eq!(v["step"], 3);
        assert_eq!(v["t"], 0.25);
        assert_eq!(v["state"], json!(STATE));
    }
}

#[test]
fn a_failure_s_own_data_keeps_its_values() {
    let v = json_of(FailureKind::ContactInconsistent {
        normal: 2.0,
        tangential: -3.0,
    });
    assert_eq!(
        (v["normal"].clone(), v["tangential"].clone()),
        (json!(2.0), json!(-3.0))
    );
    let v = json_of(fell_backward());
    assert_eq!(
        (v["name"].clone(), v["doc"].clone()),
        (
            json!("fell-backward"),
            json!("the wheel rolled back onto its rear spoke")
        )
    );
    // A non-finite lambda is written as null, as serde_json writes every non-finite number.
    let v = json_of(FailureKind::LambdaDenominatorZero { lambda: f64::NAN });
    assert!(v["lambda"].is_null());
}

#[test]
fn integrator_reasons_serialise_as_their_old_strings() {
    for (reason, text) in [
        (GaveUp::TooManySteps, "too many steps"),
        (GaveUp::StepSizeTooSmall { h: 1e-20 }, "step size too small"),
        (GaveUp::InvalidInput("t_end < t0"), "t_end < t0"),
    ] {
        let v = json_of(FailureKind::Integrator { reason });
        assert_eq!(v["reason"], text);
        assert_eq!(reason.as_str(), text);
        // The text for people adds the step size where there is one.
        assert!(reason.to_string().starts_with(text), "{reason}");
    }
    assert_eq!(
        GaveUp::StepSizeTooSmall { h: 1e-20 }.to_string(),
        "step size too small (h = 1e-20)"
    );
}

#[test]
fn failure_names_are_the_cli_s_kebab_case_names() {
    let names: Vec<String> = every_kind()
        .into_iter()
        .map(|(kind, _, _)| Failure::name(&kind.at(0, 0.0, STATE.into())).to_owned())
        .collect();
    assert_eq!(
        names,
        [
            "lift-off",
            "contact-inconsistent",
            "impact-before-t-set",
            "double-support",
            "impact-pulls",
            "lambda-denominator-zero",
            "lambda-numerator-huge",
            "fell-backward",
            "impact-at-start",
            "no-impact",
            "non-finite",
            "impact-jam",
            "integrator",
        ]
    );
}
