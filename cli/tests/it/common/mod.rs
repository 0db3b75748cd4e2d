//! Helpers shared by the command line's end-to-end tests.
#![allow(clippy::unwrap_used, clippy::panic, reason = "tests")]

/// The decimal numbers (`0.45`, `62.95`; not integers, not `1e-6`) in `text`: the figures a
/// README caption or table quotes from a job's `summary.txt`.
pub fn decimals(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut current = String::new();
    for c in text.chars().chain(std::iter::once(' ')) {
        if c.is_ascii_digit() || (c == '.' && !current.is_empty() && !current.contains('.')) {
            current.push(c);
        } else {
            if current.contains('.') && !current.ends_with('.') {
                out.push(current.clone());
            }
            current.clear();
        }
    }
    out
}

/// Runs `walker ARGS`: exit code, stdout, stderr.
pub fn walker(args: &[&str]) -> (i32, String, String) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_walker"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The JSON of a successful `walker ARGS --json`.
pub fn json(args: &[&str]) -> serde_json::Value {
    let mut a = args.to_vec();
    a.push("--json");
    let (code, out, err) = walker(&a);
    assert_eq!(code, 0, "walker {args:?}: {err}");
    serde_json::from_str(&out).unwrap()
}

/// `x` as a number.
pub fn num(x: &serde_json::Value) -> f64 {
    x.as_f64().unwrap()
}

/// The constraint row `name` of a design's JSON.
pub fn row<'a>(d: &'a serde_json::Value, name: &str) -> &'a serde_json::Value {
    d["constraints"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["name"] == name)
        .unwrap_or_else(|| panic!("no row {name}: {d}"))
}

/// The model file `path` derived at run time under exact Coulomb friction in stance and at the
/// impact, on a floor of `mu0`, with a design's parameters (its JSON `d`) set: the walker the
/// design describes, for the simulator alone to walk.
pub fn designed_setup(
    path: &std::path::Path,
    d: &serde_json::Value,
    mu0: f64,
) -> walker::setup::Setup {
    let mut set: Vec<(String, f64)> = vec![("mu0".into(), mu0)];
    for p in d["parameters"].as_array().unwrap() {
        set.push((p["name"].as_str().unwrap().to_owned(), num(&p["value"])));
    }
    let ov = walker::setup::Overrides {
        set,
        friction: Some(walker::model::Friction::Coulomb),
        impact: Some(walker::model::ImpactLaw::Coulomb),
        ..Default::default()
    };
    let runtime = walker_load::runtime_source();
    walker::setup::Setup::from_model_file(path, &ov, Some(&runtime)).unwrap()
}

/// The coordinates and velocities of the paper's active walker, as `--init` names them.
pub const PAPER_ACTIVE: [&str; 8] = ["x", "z", "th1", "th2", "xd", "zd", "th1d", "th2d"];

/// The coordinates and velocities of `models/three-link.toml`, as `--init` names them.
pub const THREE_LINK: [&str; 10] = [
    "x", "z", "th_st", "th_sw", "th_t", "xd", "zd", "th_std", "th_swd", "th_td",
];

/// `walker simulate` alone of a design's walker (its JSON `d`): the walker of `walker_flags`
/// (`--scene ...` or `--model ...`) under exact Coulomb friction in stance and at the impact,
/// on a floor of `mu0`, with the designed parameters set, from the designed fixed point (its
/// coordinates named `coordinates`), for `steps` steps. Its steps, after checking that the walk
/// completed all of them.
pub fn simulate_design(
    walker_flags: &[&str],
    mu0: f64,
    d: &serde_json::Value,
    coordinates: &[&str],
    steps: usize,
) -> Vec<serde_json::Value> {
    let mut sim: Vec<String> = ["simulate"]
        .iter()
        .chain(walker_flags)
        .chain(&["--friction", "coulomb", "--impact", "coulomb"])
        .map(|s| (*s).to_owned())
        .collect();
    sim.extend(["--set".into(), format!("mu0={mu0}")]);
    for p in d["parameters"].as_array().unwrap() {
        sim.extend([
            "--set".into(),
            format!("{}={}", p["name"].as_str().unwrap(), num(&p["value"])),
        ]);
    }
    let fp = d["gait"]["fixed_point"]["state_plus"].as_array().unwrap();
    assert_eq!(fp.len(), coordinates.len(), "{d}");
    for (n, v) in coordinates.iter().zip(fp) {
        sim.extend(["--init".into(), format!("{n}={}", num(v))]);
    }
    sim.extend(["--max-steps".into(), steps.to_string()]);
    let args: Vec<&str> = sim.iter().map(String::as_str).collect();
    let w = json(&args);
    assert_eq!(w["status"], "ok", "{w}");
    let out = w["steps"].as_array().unwrap().clone();
    assert_eq!(out.len(), steps);
    out
}

/// Whether a step of `walker simulate`'s JSON kept its foot stuck for the whole step: the
/// stuck time is a sum of the stance's intervals, equal to `T` up to the rounding of that sum
/// (1 ulp measured; 1e-12 relative allows a few hundred intervals' rounding).
pub fn stuck_all_step(s: &serde_json::Value) -> bool {
    (num(&s["stuck_time"]) - num(&s["T"])).abs() <= 1e-12 * num(&s["T"])
}

/// `walker design --json` of the three-link biped's least-friction gait (Coulomb friction in
/// stance and at the impact; `T_set`, `th_T` and `beta` varied) with at most `evals`
/// evaluations and `extra` flags: its text.
pub fn three_link_friction(evals: &str, extra: &[&str]) -> String {
    let model = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../models/three-link.toml");
    let mut args = vec![
        "design",
        "--model",
        model.to_str().unwrap(),
        "--friction",
        "coulomb",
        "--impact",
        "coulomb",
        "--objective",
        "friction",
        "--vary",
        "T_set=0.2:1.0,th_T=0.1:0.8,beta=0.2:0.5",
        "--max-evaluations",
        evals,
        "--json",
    ];
    args.extend(extra);
    let (code, out, err) = walker(&args);
    assert_eq!(code, 0, "{err}");
    out
}
