//! RABBIT's designed gaits (`docs/design.md`, "RABBIT"; made by `docs/designs/rabbit.sh`),
//! confirmed by `walker simulate` alone: each design's gait walks 100 steps from its fixed
//! point with the foot held on a floor of its `mu0` less the friction margin, every step
//! meeting the design's constraints and repeating the objective the design reported; `walker
//! fixed-point` finds the same gait with the multipliers the design reports; and the design
//! command, started at a committed optimum, still ends there.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

use std::path::Path;

use serde_json::Value;

use crate::common::{designed_setup, json, num, row};

/// `models/five-link.toml`.
fn model() -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../models/five-link.toml")
        .to_str()
        .unwrap()
        .to_owned()
}

/// The committed design `docs/designs/rabbit-mu0-MU.json`.
fn design(mu: &str) -> Value {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../docs/designs/rabbit-mu0-{mu}.json"));
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The five-link biped's state names, in the model file's order (`[[coordinate]]`, then their
/// velocities).
const STATE: [&str; 14] = [
    "x",
    "z",
    "th_s1",
    "th_f1",
    "th_torso",
    "th_f2",
    "th_s2",
    "xd",
    "zd",
    "th_s1d",
    "th_f1d",
    "th_torsod",
    "th_f2d",
    "th_s2d",
];

/// The design's request as `rabbit.sh` makes it: the floor, the contact laws and the bounds.
const FRICTION_MARGIN: f64 = 0.01;
/// `--min-speed` of the designs.
const MIN_SPEED: f64 = 0.6;
/// The designs' `--multiplier-margin` (the default).
const MULTIPLIER_MARGIN: f64 = 0.05;

/// `walker CMD` of the five-link biped under exact Coulomb friction on a floor of `mu0`, with
/// the design's parameters (and, for `simulate`, its fixed point as the start), then `extra`.
fn at_design(cmd: &str, d: &Value, mu0: f64, extra: &[&str]) -> Value {
    let mut a: Vec<String> = vec![
        cmd.into(),
        "--model".into(),
        model(),
        "--friction".into(),
        "coulomb".into(),
        "--impact".into(),
        "coulomb".into(),
        "--set".into(),
        format!("mu0={mu0}"),
    ];
    for p in d["parameters"].as_array().unwrap() {
        a.extend([
            "--set".into(),
            format!("{}={}", p["name"].as_str().unwrap(), num(&p["value"])),
        ]);
    }
    if cmd == "simulate" {
        let fp = d["gait"]["fixed_point"]["state_plus"].as_array().unwrap();
        for (n, v) in STATE.iter().zip(fp) {
            a.extend(["--init".into(), format!("{n}={}", num(v))]);
        }
    }
    a.extend(extra.iter().map(|s| (*s).to_owned()));
    let args: Vec<&str> = a.iter().map(String::as_str).collect();
    json(&args)
}

#[test]
fn each_designed_gait_walks_100_steps_held_within_every_constraint() {
    for mu in ["0.6", "0.3"] {
        let d = design(mu);
        let mu0: f64 = mu.parse().unwrap();
        assert_eq!(d["status"], "optimal", "{mu}: {d}");
        assert_eq!(num(&d["mu0"]), mu0);
        let sr = num(&d["value"]);

        // The friction constraint `ratio <= mu0 - margin`, read by the simulator: on a floor
        // of exactly `mu0 - margin` the foot must still hold through every stance and every
        // strike (a held gait does not depend on `mu0`, so this is the design's gait, and a
        // ratio above the floor's would show as a slip or a slipping strike).
        let w = at_design(
            "simulate",
            &d,
            mu0 - FRICTION_MARGIN,
            &["--max-steps", "100"],
        );
        assert_eq!(w["status"], "ok", "{mu}: {w}");
        let steps = w["steps"].as_array().unwrap();
        assert_eq!(steps.len(), 100);
        for s in steps {
            assert_eq!(s["impact"]["regime"], "stick", "{mu}: {s}");
            assert!(
                (num(&s["stuck_time"]) - num(&s["T"])).abs() <= 1e-12 * num(&s["T"]),
                "{mu}: {s}"
            );
            // The normal force stays positive (`--normal-margin 0`).
            assert!(num(&s["lambda_min"]) > 0.0, "{mu}: {s}");
            // The walk repeats the fixed point, found to a residual of 1e-11 with the
            // integrator at rtol 1e-10, so each step's SR is the design's to 1e-8 relative (as
            // the paper's designs in `design_bounds_cli`). This needs every kink of the power's
            // integrand located: with the four inputs' kinks watched as one product, two in one
            // integrator step went unseen and the steps' SR scattered by 2e-5 (`Guard::PowerKink`).
            let got = num(&s["SR"]);
            assert!((got - sr).abs() <= 1e-8 * sr, "{mu}: SR {got} vs {sr}");
            assert!(
                num(&s["V"]) >= MIN_SPEED * (1.0 - 1e-8),
                "{mu}: V {}",
                s["V"]
            );
        }

        // The multipliers, by the analysis alone: `walker fixed-point` at the design's
        // parameters finds the gait the design reports (T to 1e-8) with every multiplier
        // inside the design's margin.
        let f = at_design("fixed-point", &d, mu0, &[]);
        let (t, want) = (num(&f["T"]), num(&d["gait"]["fixed_point"]["T"]));
        assert!((t - want).abs() <= 1e-8 * want, "{mu}: {t} vs {want}");
        let largest = f["multipliers"]
            .as_array()
            .unwrap()
            .iter()
            .map(|m| num(&m["re"]).hypot(num(&m["im"])))
            .fold(0.0, f64::max);
        assert!(largest <= 1.0 - MULTIPLIER_MARGIN, "{mu}: {largest}");
    }
}

#[test]
fn the_friction_of_the_floor_shapes_the_gait() {
    // On mu0 = 0.6 the cheapest gait at 0.6 m/s needs less friction than the floor has; on
    // mu0 = 0.3 that gait would slip, so the design's friction row is active and the gait
    // costs more: the floor's friction, not the request, made the difference.
    let (dry, icy) = (design("0.6"), design("0.3"));
    let need =
        |d: &Value| num(&d["gait"]["stance_friction"]).max(num(&d["gait"]["impact_friction"]));
    assert!(need(&dry) > 0.3 - FRICTION_MARGIN, "{}", need(&dry));
    let stance = row(&icy, "stance-friction");
    assert!(num(&stance["lagrange"]) > 0.0, "{stance}");
    assert!(need(&icy) <= 0.3 - FRICTION_MARGIN, "{}", need(&icy));
    assert!(num(&icy["value"]) > num(&dry["value"]));
}

#[test]
fn the_design_started_at_its_committed_optimum_stays_there() {
    // `rabbit.sh`'s request on mu0 = 0.3, started at the committed design: the current code
    // still finds it optimal, with the objective to 1e-8 (the solver's stopping test is 1e-10
    // relative on the objective, the gait's evaluation good to about 1e-11).
    let d = design("0.3");
    let vary: Vec<String> = d["parameters"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            format!(
                "{}={}:{}:{}",
                p["name"].as_str().unwrap(),
                num(&p["lo"]),
                num(&p["hi"]),
                num(&p["value"])
            )
        })
        .collect();
    let vary = vary.join(",");
    let again = json(&[
        "design",
        "--model",
        &model(),
        "--friction",
        "coulomb",
        "--impact",
        "coulomb",
        "--set",
        "mu0=0.3",
        "--vary",
        &vary,
        "--clearance",
        "0.02",
        "--min-speed",
        "0.6",
        "--max-evaluations",
        "40",
    ]);
    assert_eq!(again["status"], "optimal", "{again}");
    let (got, want) = (num(&again["value"]), num(&d["value"]));
    assert!((got - want).abs() <= 1e-8 * want, "{got} vs {want}");
}

/// The five-link biped's swing foot above the level floor at the coordinates `q`, written out
/// from `models/five-link.toml`'s `swing_foot` point (not through the design's code).
fn swing_height(m: &walker::model::Model, q: &[f64]) -> f64 {
    let (l_s, l_f) = (m.param("l_s"), m.param("l_f"));
    q[1] + l_s * q[2].cos() + l_f * q[3].cos() - l_f * q[5].cos() - l_s * q[6].cos()
}

#[test]
fn the_designed_swing_foot_clears_the_floor_between_the_samples_too() {
    // The design on mu0 = 0.3 (`--clearance 0.02`, its clearance row active): one step of the
    // simulator from its fixed point, the height written out from the model file's geometry.
    use walker::design::{SAMPLES, clearance_profile};
    let d = design("0.3");
    let setup = designed_setup(Path::new(&model()), &d, num(&d["mu0"]));
    let m = setup.model().unwrap();
    let start: Vec<f64> = d["gait"]["fixed_point"]["state_plus"]
        .as_array()
        .unwrap()
        .iter()
        .map(num)
        .collect();
    let period = num(&d["gait"]["fixed_point"]["T"]);
    let (h, reported) = (0.02, num(&d["gait"]["clearance"]));
    let limits = walker::sim::WalkLimits {
        max_steps: 1,
        ..Default::default()
    };
    // (height, height over the profile, height less H times the profile) at the interior
    // samples of a grid of `samples` over the stance.
    let walk = |samples: usize| {
        let cfg = walker::sim::SimConfig::default();
        let dt = period / samples as f64;
        let tr = walker::sim::trajectory(&m, &cfg, &start, &limits, dt, samples + 8);
        assert!(tr.walk.failure.is_none());
        tr.frames
            .into_iter()
            .filter(|f| f.step == 0 && f.t > 0.0 && f.t < period)
            .map(|f| {
                let z = swing_height(&m, &f.state.as_slice()[..7]);
                let w = clearance_profile(f.t / period);
                (z, z / w, z - h * w)
            })
            .collect::<Vec<_>>()
    };
    // At the design's own sample times the simulator gives the clearance the design reported
    // (the same integration from the same state: to the rounding of `z / (4 s (1 - s))`).
    let same = walk(SAMPLES);
    let walked = same.iter().map(|x| x.1).fold(f64::INFINITY, f64::min);
    assert!((walked - reported).abs() <= 1e-12, "{walked} vs {reported}");
    assert!(reported >= h, "{reported}");
    // Between the samples: on a grid ten times finer the foot stays above the profile but
    // for what a sample spacing can hide, `(dt / 2)^2 / 2 |z''|` with `dt = T / 400` (1.8 ms)
    // and the foot's vertical acceleration at most 50 m/s^2: 2e-5 m.
    let fine = walk(10 * SAMPLES);
    let dip = fine.iter().map(|x| x.2).fold(f64::INFINITY, f64::min);
    assert!(dip >= -2e-5, "{dip}");
    assert!(fine.iter().all(|x| x.0 > 0.0));
}
