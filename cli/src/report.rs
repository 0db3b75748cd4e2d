//! What the command line prints: the JSON objects and text tables of walks, sweeps, fixed
//! points and continuations. The library returns typed results; only this module turns them
//! into text.

use std::fmt::Write as _;

use serde::Serialize;
use serde_json::json;
use walker::poincare::{
    ContinuationPoint, FixedPoint, FixedPointError, MapError, MultiplierBound, Status,
};
use walker::sensitivity::{Estimate, Sensitivity, SensitivityError};
use walker::sim::{StepResult, Walk};
use walker::sweep::SweepPoint;

/// The JSON report of a walk, `{"failure", "status", "steps"}`, as one line of text.
///
/// Keys are in byte order at every level, as a sorted map writes them: the steps are written
/// straight from [`StepResult`], whose fields are declared in that order (a test compares the
/// two), so a walk of many steps builds no map per step. The failure, at most one per walk and
/// a flattened enum, goes through a sorted map.
pub fn walk_json(w: &Walk) -> String {
    /// The report's top level, its fields in key order.
    #[derive(Serialize)]
    struct Report<'a> {
        failure: Option<serde_json::Value>,
        status: &'a str,
        steps: &'a [StepResult],
    }
    let report = Report {
        failure: w
            .failure
            .as_ref()
            .map(|f| serde_json::to_value(f).unwrap_or_default()),
        status: w.failure.as_ref().map_or("ok", |f| f.name()),
        steps: &w.steps,
    };
    serde_json::to_string(&report).unwrap_or_default()
}

/// A text table of a walk, with each step's `mu0` for a walk on a floor of its own (and its
/// slope `phi` where the floor sets it; on a floor of patches by position, the `mu0` of the
/// step's strike and the patch boundaries its stance foot slid across).
pub fn walk_text(w: &Walk) -> String {
    let floored = w.steps.iter().any(|s| s.floor.is_some());
    let sloped = w
        .steps
        .iter()
        .any(|s| s.floor.is_some_and(|f| f.phi.is_some()));
    // A floor of patches by position: the strike's mu0 and the boundaries crossed in stance.
    let patched = w
        .steps
        .iter()
        .any(|s| s.floor.is_some_and(|f| f.crossings.is_some()));
    let mut s = String::from("step          T         dx          V          p         SR");
    s.push_str(if floored { "        mu0" } else { "" });
    s.push_str(if patched {
        " mu0_strike  crossings"
    } else {
        ""
    });
    s.push_str(if sloped { "        phi\n" } else { "\n" });
    let opt = |v: Option<f64>| v.map_or_else(|| "-".to_owned(), |x| format!("{x:.6}"));
    for (k, st) in w.steps.iter().enumerate() {
        s.push_str(&format!(
            "{k:4} {:10.6} {:10.6} {:10.6} {:>10} {:>10}",
            st.period,
            st.dx,
            st.speed,
            opt(st.p),
            opt(st.sr)
        ));
        if floored {
            s.push_str(&format!(" {:>10}", opt(st.floor.map(|f| f.mu0))));
        }
        if patched {
            let crossings = st.floor.and_then(|f| f.crossings);
            s.push_str(&format!(
                " {:>10} {:>10}",
                opt(st.floor.and_then(|f| f.mu0_strike)),
                crossings.map_or_else(|| "-".to_owned(), |c| c.to_string())
            ));
        }
        if sloped {
            s.push_str(&format!(" {:>10}", opt(st.floor.and_then(|f| f.phi))));
        }
        s.push('\n');
    }
    match &w.failure {
        None => s.push_str("status: ok\n"),
        Some(f) => s.push_str(&format!(
            "status: {} at step {}\n{}\n",
            f.name(),
            f.step,
            serde_json::to_string(f).unwrap_or_default()
        )),
    }
    s
}

/// One sweep chain (one `T_set` or `phi`) in a report.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Chain {
    /// The chain's parameter (`T_set` for the active walker, `phi` for the passive wheel), if
    /// the sweep is chained.
    pub param: Option<String>,
    /// Its value.
    pub value: f64,
    /// The swept parameter (`mu0`).
    pub swept: String,
    /// The points of the chain.
    pub points: Vec<SweepPoint>,
}

/// The JSON report of a sweep: `{"chains": [{"param", "value", "points": [{<swept>, "steps",
/// "last", "previous", "failure", "periodic"}]}]}`, each point keyed by the swept parameter's
/// name (`"mu0": 0.4`).
pub fn sweep_json(chains: &[Chain]) -> serde_json::Value {
    let chains: Vec<serde_json::Value> = chains
        .iter()
        .map(|ch| {
            let points: Vec<serde_json::Value> = ch
                .points
                .iter()
                .map(|p| {
                    let mut o = serde_json::Map::new();
                    o.insert(ch.swept.clone(), json!(p.value));
                    o.insert("steps".into(), json!(p.steps));
                    o.insert("last".into(), json!(p.last));
                    o.insert("previous".into(), json!(p.previous));
                    o.insert("failure".into(), json!(p.failure));
                    o.insert("periodic".into(), json!(p.periodic));
                    serde_json::Value::Object(o)
                })
                .collect();
            json!({ "param": ch.param, "value": ch.value, "points": points })
        })
        .collect();
    json!({ "chains": chains })
}

/// A text table of a sweep.
pub fn sweep_text(chains: &[Chain]) -> String {
    let mut s = String::new();
    for ch in chains {
        if let Some(name) = &ch.param {
            s.push_str(&format!("{name} = {}\n", ch.value));
        }
        s.push_str(&format!(
            "{:>5}   steps          T         dx          V         SR  status\n",
            ch.swept
        ));
        for p in &ch.points {
            let l: Option<&StepResult> = p.last.as_ref();
            let f = |g: fn(&StepResult) -> Option<f64>| {
                l.and_then(g)
                    .map_or_else(|| "-".to_owned(), |x| format!("{x:.6}"))
            };
            s.push_str(&format!(
                "{:5.3} {:7} {:>10} {:>10} {:>10} {:>10}  {}\n",
                p.value,
                p.steps,
                f(|s| Some(s.period)),
                f(|s| Some(s.dx)),
                f(|s| Some(s.speed)),
                f(|s| s.sr),
                p.failure
                    .as_ref()
                    .map_or(if p.periodic { "periodic" } else { "ok" }, |x| x.name())
            ));
        }
    }
    s
}
/// The output of `walker fixed-point`: the JSON object and the text table.
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    /// `{"status", "state_plus", "T", "V", "multipliers", ...}`; a failed search is
    /// `{"status": "failed", "reason"}`.
    pub json: serde_json::Value,
    /// Human-readable summary.
    pub text: String,
}

/// The report of a fixed-point search (`names`: the model's state components, for the text);
/// a failed search is a result (status `failed`).
#[must_use]
pub fn fixed_point_report(
    result: &Result<FixedPoint, FixedPointError>,
    names: &[String],
) -> Report {
    match result {
        Ok(fp) => Report {
            json: serde_json::to_value(fp).unwrap_or(serde_json::Value::Null),
            text: fixed_point_text(fp, names),
        },
        Err(e) => Report {
            json: json!({ "status": "failed", "reason": e.to_string() }),
            text: format!("status: failed ({e})\n"),
        },
    }
}

/// Adds each multiplier's error bound to the report of `walker fixed-point`: the JSON array
/// `multiplier_errors`, in the order of `multipliers` (the bound on `|lambda - lambda_exact|`,
/// `null` for a multiplier that is not simple; `walker::poincare::multiplier_errors`), and a
/// line per multiplier in the text; a failure is `multiplier_errors_error` with its reason.
pub fn add_multiplier_errors(out: &mut Report, result: &Result<Vec<MultiplierBound>, MapError>) {
    let Some(obj) = out.json.as_object_mut() else {
        return;
    };
    match result {
        Ok(bounds) => {
            let errors: Vec<Option<f64>> = bounds.iter().map(|b| b.error).collect();
            obj.insert("multiplier_errors".into(), json!(errors));
            out.text.push_str("multipliers' error bounds:\n");
            for b in bounds {
                let bound = b
                    .error
                    .map_or_else(|| "- (not simple)".to_owned(), |e| format!("{e:.1e}"));
                let _ = writeln!(
                    out.text,
                    "  {:+.10} {:+.10}i  +- {bound}",
                    b.multiplier.re, b.multiplier.im
                );
            }
        }
        Err(e) => {
            obj.insert("multiplier_errors_error".into(), e.to_string().into());
            let _ = writeln!(out.text, "multipliers' error bounds: failed ({e})");
        }
    }
}

/// Adds the sensitivities of `walker fixed-point --sensitivities` to its report: the JSON
/// object `sensitivities` (per parameter: `d_state` by section coordinate, `dT`, `dV`, `d_dx`,
/// `d_multipliers`, the map's `map_d_state` and `map_dT`, `value`, `step`; each derivative with
/// its `error`) and a table; a failure is `sensitivities_error` with its reason.
pub fn add_sensitivities(out: &mut Report, result: &Result<Vec<Sensitivity>, SensitivityError>) {
    let Some(obj) = out.json.as_object_mut() else {
        return;
    };
    match result {
        Ok(list) => {
            let map: serde_json::Map<String, serde_json::Value> = list
                .iter()
                .map(|s| {
                    (
                        s.parameter.clone(),
                        serde_json::to_value(s).unwrap_or(serde_json::Value::Null),
                    )
                })
                .collect();
            obj.insert("sensitivities".into(), map.into());
            out.text.push_str(&sensitivities_text(list));
        }
        Err(e) => {
            obj.insert("sensitivities_error".into(), e.to_string().into());
            let _ = writeln!(out.text, "sensitivities: failed ({e})");
        }
    }
}

/// The sensitivities as a table: one row per parameter, `value +- error`.
fn sensitivities_text(list: &[Sensitivity]) -> String {
    let mut s = String::new();
    let e = |x: &Estimate| format!("{:+.6e} +- {:.1e}", x.value, x.error);
    for p in list {
        let _ = writeln!(
            s,
            "sensitivities to {} = {} (step {:.1e}):",
            p.parameter, p.value, p.step
        );
        for (name, d) in &p.d_state {
            let _ = writeln!(s, "  d{name}+/dp  {}", e(d));
        }
        let _ = writeln!(s, "  dT/dp      {}", e(&p.d_period));
        let _ = writeln!(s, "  dV/dp      {}", e(&p.d_speed));
        let _ = writeln!(s, "  d(dx)/dp   {}", e(&p.d_dx));
        for (i, m) in p.d_multipliers.iter().enumerate() {
            match m {
                Some(m) => {
                    let _ = writeln!(
                        s,
                        "  dlambda{}/dp {:+.6e} {:+.6e}i +- {:.1e}",
                        i + 1,
                        m.re,
                        m.im,
                        m.error
                    );
                }
                None => {
                    let _ = writeln!(s, "  dlambda{}/dp  - (not a simple multiplier)", i + 1);
                }
            }
        }
    }
    s
}

fn fixed_point_text(fp: &FixedPoint, names: &[String]) -> String {
    let mut s = String::new();
    let status = serde_json::to_value(fp.status)
        .ok()
        .and_then(|v| v.as_str().map(str::to_owned))
        .unwrap_or_default();
    let _ = writeln!(s, "status: {status}");
    if let Some(f) = &fp.failure {
        let _ = writeln!(s, "walk on the cycle fails: {}", f.name());
    }
    let _ = writeln!(s, "state_plus [{}]: {:?}", names.join(" "), fp.state_plus);
    let _ = writeln!(
        s,
        "T = {:.10} s, V = {:.10} m/s, dx = {:.10} m",
        fp.period, fp.speed, fp.dx
    );
    let _ = writeln!(
        s,
        "residual {:.3e} after {} Newton iterations",
        fp.residual, fp.iterations
    );
    let section: Vec<String> = fp.section.iter().map(|c| format!("{c}+")).collect();
    let _ = writeln!(s, "multipliers (reduced map in {}):", section.join(", "));
    for m in &fp.multipliers {
        let _ = writeln!(
            s,
            "  {:+.10} {:+.10}i  |.| = {:.10}",
            m.re,
            m.im,
            m.modulus()
        );
    }
    if fp.structural_unit_multiplier {
        let _ = writeln!(
            s,
            "the multiplier at 1 is structural: a family of cycles (conserved horizontal momentum)"
        );
    }
    s
}

/// The continuation as CSV: `chain,mu0,status,T,V,dx,max_modulus,stable` (empty fields when
/// no cycle was found; never NaN).
pub fn continuation_csv(points: &[ContinuationPoint]) -> String {
    let mut s = String::from("chain,mu0,status,T,V,dx,max_modulus,stable\n");
    for p in points {
        let _ = match &p.cycle {
            Some(c) => writeln!(
                s,
                "{},{},{},{},{},{},{},{}",
                p.chain,
                p.mu0,
                status_name(c.status),
                c.period,
                c.speed,
                c.dx,
                c.max_modulus(),
                p.is_stable()
            ),
            None => writeln!(s, "{},{},failed,,,,,false", p.chain, p.mu0),
        };
    }
    s
}

fn status_name(s: Status) -> &'static str {
    match s {
        Status::Converged => "converged",
        Status::Family => "family",
        Status::NotConverged => "not-converged",
        Status::InvalidGait => "invalid-gait",
    }
}

/// A stability summary of a continuation: for every chain, the maximal runs of consecutive grid
/// values of `mu0` on which the gait is stable ([`ContinuationPoint::is_stable`]), e.g.
/// `T_set = 0.3: stable for mu0 in [0.05, 1] (20/20 points)`. `name` is the chain's
/// parameter (`T_set` or `phi`).
pub fn stability_summary(points: &[ContinuationPoint], name: &str) -> String {
    let mut s = String::new();
    let mut chains: Vec<f64> = points.iter().map(|p| p.chain).collect();
    chains.dedup();
    for chain in chains {
        let pts: Vec<&ContinuationPoint> = points.iter().filter(|p| p.chain == chain).collect();
        let mut runs: Vec<(f64, f64)> = Vec::new();
        let mut open: Option<(f64, f64)> = None;
        for p in &pts {
            match (p.is_stable(), open) {
                (true, None) => open = Some((p.mu0, p.mu0)),
                (true, Some((a, _))) => open = Some((a, p.mu0)),
                (false, Some(run)) => {
                    runs.push(run);
                    open = None;
                }
                (false, None) => {}
            }
        }
        runs.extend(open);
        let n = pts.iter().filter(|p| p.is_stable()).count();
        let ranges = if runs.is_empty() {
            "nowhere on the grid".to_owned()
        } else {
            runs.iter()
                .map(|(a, b)| format!("[{a:.2}, {b:.2}]"))
                .collect::<Vec<_>>()
                .join(" and ")
        };
        let _ = writeln!(
            s,
            "{name} = {chain}: stable for mu0 in {ranges} ({n}/{} points)",
            pts.len()
        );
    }
    s
}
