//! `walker design`'s bounds on the gait end to end (`docs/design.md`, "Clearance and speed"):
//! the swing foot's clearance on the three-link biped (straight legs: infeasible, a result
//! naming the constraint), a least speed, a band of one speed and the speed objective under an
//! effort bound on the paper's walker, a most speed on the three-link biped, each confirmed by
//! `walker simulate` alone, and bad requests exiting 2 with the flag and its valid range.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use std::path::Path;

use serde_json::Value;

use crate::common::{
    PAPER_ACTIVE, THREE_LINK, json, num, row, simulate_design, stuck_all_step, three_link_friction,
    walker,
};

/// `models/NAME.toml`.
fn model(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join(format!("../models/{name}.toml"))
        .to_str()
        .unwrap()
        .to_owned()
}

/// The paper's walker held on `mu0 = 1` (where the held gaits of the paper's ramps up to
/// `T_set = 0.27` need less friction than the floor has, so that the speed, not the friction,
/// bounds them), its ramp's duration varied from the sweep's longest, 0.4 s; then `extra`.
fn paper_design(extra: &[&str]) -> Value {
    let mut args = vec![
        "design",
        "--scene",
        "active-level",
        "--set",
        "mu0=1.0",
        "--friction",
        "coulomb",
        "--impact",
        "coulomb",
        "--vary",
        "T_set=0.2:0.4:0.4",
    ];
    args.extend(extra);
    json(&args)
}

/// `walker simulate` of the paper's walker on the design's floor (`mu0 = 1`) from the designed
/// fixed point with the designed parameters, 100 steps: its steps, each with the foot held.
fn walk_paper_design(d: &Value) -> Vec<Value> {
    let steps = simulate_design(&["--scene", "active-level"], 1.0, d, &PAPER_ACTIVE, 100);
    for s in &steps {
        assert_eq!(s["impact"]["regime"], "stick", "{s}");
        assert!(stuck_all_step(s), "{s}");
    }
    steps
}

/// Each of the walk's steps has `key` (`V`, `p`) equal to `want` to 1e-8 relative: the walk
/// repeats the fixed point, found to a residual of 1e-11 with the integrator's rtol 1e-10
/// (the designed shapes' `SR` agreed to 3e-12 in `design_cli`).
fn every_step_has(steps: &[Value], key: &str, want: f64) {
    for s in steps {
        let got = num(&s[key]);
        assert!(
            (got - want).abs() <= 1e-8 * want.abs(),
            "{key}: {got} vs {want}"
        );
    }
}

#[test]
fn a_clearance_the_straight_legged_three_link_biped_cannot_give_is_an_infeasible_design() {
    // The gallery's friction design of the three-link biped, asked for a swing foot 1 m above
    // the floor at mid-stance: a result (exit 0) with status infeasible naming the clearance.
    // And not only 1 m: the biped's legs are straight, so its swing foot is at or below the
    // floor where the swing leg passes the vertical (`r (cos(th_st) - 1) <= 0`), and the
    // clearance it has is at most 0 for every gait (`walker/tests/it/design_clearance.rs`).
    // On the 400 samples it can read slightly above 0: the instant `t*` may fall between two
    // samples, half a sample (`dt / 2`, about 1 ms) from the nearest, where the height is at
    // most `-r a^2 / 2 + r |a| w dt / 2 <= r (w dt)^2 / 8` (`a` the stance angle at `t*`, `w`
    // its rate, about 1.6 rad/s): 1.4e-6 m. A design pushed towards 1 mm reached 2.8e-8 m.
    let m = model("three-link");
    for h in ["1", "0.001"] {
        let d: Value =
            serde_json::from_str(&three_link_friction("10", &["--clearance", h])).unwrap();
        assert_eq!(d["status"], "infeasible", "{d}");
        assert_eq!(d["violated"], "clearance", "{d}");
        let c = row(&d, "clearance");
        assert_eq!(
            (c["sense"].as_str(), num(&c["limit"])),
            (Some(">="), h.parse().unwrap())
        );
        assert!(num(&c["value"]) <= 1e-5, "{c}");
        assert_eq!(num(&c["value"]), num(&d["gait"]["clearance"]));
        // The parameters and the gait reported belong together (an infeasible design whose
        // solver ended where there is no gait is reported at a visited gait): `walker
        // fixed-point` at the reported parameters, on a floor where the held gait holds
        // (`mu0 = 1`), has the reported period to 1e-8 (both solved to a residual of 1e-10).
        let mut fp = vec![
            "fixed-point".to_owned(),
            "--model".into(),
            m.clone(),
            "--friction".into(),
            "coulomb".into(),
            "--impact".into(),
            "coulomb".into(),
            "--set".into(),
            "mu0=1".into(),
        ];
        for p in d["parameters"].as_array().unwrap() {
            fp.extend([
                "--set".into(),
                format!("{}={}", p["name"].as_str().unwrap(), num(&p["value"])),
            ]);
        }
        let args: Vec<&str> = fp.iter().map(String::as_str).collect();
        let f = json(&args);
        let (t, want) = (num(&f["T"]), num(&d["gait"]["fixed_point"]["T"]));
        assert!((t - want).abs() <= 1e-8 * want, "{t} vs {want}");
    }
}

#[test]
fn without_the_new_bounds_a_design_has_the_rows_and_keys_it_had() {
    let d = paper_design(&[]);
    let names: Vec<&str> = d["constraints"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["name"].as_str().unwrap())
        .collect();
    assert_eq!(
        names,
        [
            "multipliers",
            "impact-friction",
            "normal-force",
            "stance-friction",
            "strike-after-ramp"
        ]
    );
    assert!(d["gait"].get("clearance").is_none(), "{d}");
}

/// The constraint row `name` of a design `d`, checked to be active: its `sense` and `limit`,
/// met to the solver's feasibility tolerance (slack within 1e-8) with a positive Lagrange
/// multiplier.
fn active<'a>(d: &'a Value, name: &str, sense: &str, limit: f64) -> &'a Value {
    let c = row(d, name);
    assert_eq!(
        (c["sense"].as_str(), num(&c["limit"])),
        (Some(sense), limit)
    );
    assert_eq!(c["holds"], true, "{c}");
    assert!(
        num(&c["slack"]).abs() <= 1e-8 && num(&c["lagrange"]) > 0.0,
        "{c}"
    );
    c
}

#[test]
fn a_least_speed_the_cheapest_gait_misses_is_met_and_simulate_alone_walks_it() {
    // Without a speed bound the cheapest gait has the longest ramp, 0.4 s, and walks at
    // 0.781 m/s; asked for 0.85 m/s the design shortens the ramp until the bound is active,
    // and pays for the speed in SR.
    let free = paper_design(&[]);
    let v_free = num(&free["gait"]["fixed_point"]["V"]);
    assert!(v_free < 0.85, "{free}");
    let d = paper_design(&["--min-speed", "0.85"]);
    assert_eq!(d["status"], "optimal", "{d}");
    let c = active(&d, "min-speed", ">=", 0.85);
    let v = num(&d["gait"]["fixed_point"]["V"]);
    assert_eq!(num(&c["value"]), v);
    assert!(num(&d["value"]) > num(&free["value"]), "{d}");
    // `walker simulate` alone: every step's speed the design's to 1e-8 relative.
    let steps = walk_paper_design(&d);
    every_step_has(&steps, "V", v);
}

#[test]
fn a_most_speed_the_least_friction_gait_exceeds_is_met_and_simulate_alone_walks_it() {
    // The three-link biped's least-friction gait walks at 0.72 m/s (every parameter at its
    // lower bound); held to 0.65 m/s it lengthens its ramp and needs a little more friction.
    let three = model("three-link");
    let design = |extra: &[&str]| -> Value {
        serde_json::from_str(&three_link_friction("40", extra)).unwrap()
    };
    let free = design(&[]);
    assert!(num(&free["gait"]["fixed_point"]["V"]) > 0.7, "{free}");
    let d = design(&["--max-speed", "0.65"]);
    assert_eq!(d["status"], "optimal", "{d}");
    active(&d, "max-speed", "<=", 0.65);
    let v = num(&d["gait"]["fixed_point"]["V"]);
    assert!((v - 0.65).abs() <= 1e-8, "{v}");
    let need = num(&d["value"]);
    assert!(need > num(&free["value"]), "{d}");
    // `walker simulate` alone on a floor 0.01 above what the gait needs: held through every
    // stance and strike, every step at the design's speed to 1e-8 relative.
    let steps = simulate_design(&["--model", &three], need + 0.01, &d, &THREE_LINK, 100);
    for s in &steps {
        assert_eq!(s["impact"]["regime"], "stick", "{s}");
        assert!(stuck_all_step(s), "{s}");
    }
    every_step_has(&steps, "V", v);
}

#[test]
fn a_least_and_most_speed_of_one_value_give_a_gait_at_that_speed() {
    // Faster than the cheapest gait (0.781 m/s): the least speed is the active side.
    let d = paper_design(&["--min-speed", "0.82", "--max-speed", "0.82"]);
    assert_eq!(d["status"], "optimal", "{d}");
    let (lo, hi) = (row(&d, "min-speed"), row(&d, "max-speed"));
    assert_eq!(
        (lo["holds"].as_bool(), hi["holds"].as_bool()),
        (Some(true), Some(true))
    );
    assert!(num(&lo["lagrange"]) > 0.0, "{lo}");
    let v = num(&d["gait"]["fixed_point"]["V"]);
    assert!((v - 0.82).abs() <= 1e-8, "{v}");
    let steps = walk_paper_design(&d);
    every_step_has(&steps, "V", v);
}

#[test]
fn the_fastest_gait_at_a_fixed_effort_spends_the_effort_and_simulate_alone_walks_it() {
    let d = paper_design(&["--objective", "speed", "--max-power", "12"]);
    assert_eq!(d["status"], "optimal", "{d}");
    assert_eq!(d["objective"], "speed");
    // The objective is reported as the speed itself (the program minimises -V), larger than
    // the start's, with the power bound active.
    let v = num(&d["gait"]["fixed_point"]["V"]);
    assert_eq!(num(&d["value"]), v);
    assert!(v > num(&d["start_value"]), "{d}");
    active(&d, "max-power", "<=", 12.0);
    // A shorter ramp is faster and costs more: d V / d T_set < 0 at the design.
    assert!(num(&d["parameters"][0]["gradient"]) < 0.0, "{d}");
    let steps = walk_paper_design(&d);
    every_step_has(&steps, "V", v);
    every_step_has(&steps, "p", num(&d["gait"]["power"]));
}

#[test]
fn bad_bounds_exit_2_naming_the_flag_and_the_range() {
    let three = model("three-link");
    let compass = model("compass-gait");
    let wheel = model("rimless-wheel");
    let paper_t = ["--vary", "T_set=0.2:0.4"];
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["--scene", "active-level", "--clearance", "-0.1"],
            "invalid clearance: clearance is -0.1: must be finite and > 0",
        ),
        (
            vec!["--model", &three, "--clearance", "nan"],
            "invalid clearance: clearance is NaN: must be finite and > 0",
        ),
        (
            vec!["--scene", "active-level", "--min-speed", "0"],
            "invalid min-speed: min-speed is 0: must be finite and > 0",
        ),
        (
            vec!["--scene", "active-level", "--max-speed", "-1"],
            "invalid max-speed: max-speed is -1: must be finite and > 0",
        ),
        (
            vec![
                "--scene",
                "active-level",
                "--min-speed",
                "0.9",
                "--max-speed",
                "0.8",
            ],
            "invalid max-speed: max-speed is 0.8, below min-speed 0.9: must be at least min-speed",
        ),
        (
            vec![
                "--scene",
                "active-level",
                "--objective",
                "speed",
                "--max-power",
                "12",
                "--max-speed",
                "0.9",
            ],
            "invalid max-speed: max-speed bounds what objective `speed` optimises",
        ),
        (
            vec!["--scene", "active-level", "--max-power", "inf"],
            "invalid max-power: max-power is inf: must be finite and > 0",
        ),
        (
            vec![
                "--scene",
                "active-level",
                "--objective",
                "speed",
                "--min-speed",
                "0.5",
            ],
            "invalid min-speed: min-speed bounds what objective `speed` optimises",
        ),
        (
            vec![
                "--scene",
                "active-level",
                "--objective",
                "power",
                "--max-power",
                "5",
            ],
            "invalid max-power: max-power bounds what objective `power` optimises",
        ),
        (
            vec!["--scene", "active-level", "--objective", "speed"],
            "invalid max-power: objective `speed` on model `paper-active` needs an effort bound",
        ),
        (
            vec!["--scene", "active-level", "--clearance", "0.01"],
            "invalid clearance: clearance needs a swing foot; model `paper-active` has none",
        ),
    ];
    for (flags, fragment) in cases {
        let mut args = vec!["design"];
        args.extend(&flags);
        if flags.contains(&"--model") {
            args.extend(["--vary", "beta=0.3:0.45"]);
        } else {
            args.extend(paper_t);
        }
        let (code, _, err) = walker(&args);
        assert_eq!(code, 2, "{flags:?}: {err}");
        assert!(
            err.contains(fragment),
            "{flags:?}: `{err}` lacks `{fragment}`"
        );
    }
    // The passive walkers: a power bound needs inputs, the wheel has no swing foot.
    let (code, _, err) = walker(&[
        "design",
        "--model",
        &compass,
        "--friction",
        "coulomb",
        "--objective",
        "friction",
        "--vary",
        "mu0=0.5:0.9",
        "--max-power",
        "1",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("invalid max-power: max-power needs an actuated walker"),
        "{err}"
    );
    let (code, _, err) = walker(&[
        "design",
        "--model",
        &wheel,
        "--objective",
        "friction",
        "--vary",
        "phi=0.1:0.3",
        "--clearance",
        "0.01",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("invalid clearance: clearance needs a swing foot; model `rimless-wheel` has none: its striking point `fore_foot`"),
        "{err}"
    );
}
