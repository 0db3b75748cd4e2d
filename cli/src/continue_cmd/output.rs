//! What `walker continue` prints and writes: a table of each branch's points with their labels
//! and a list of the special points (text), one JSON object with every branch, and a CSV file
//! with a row per point.

use std::fmt::Write as _;

use walker::continuation::{Branch, EndReason, Point, Stability};

/// The end reason in words.
fn end_text(e: &EndReason) -> String {
    match e {
        EndReason::ParameterBound => "end of the range".to_owned(),
        EndReason::MapFailed { error, .. } => format!("the map failed ({error})"),
        EndReason::NoConvergence => "the corrector did not converge".to_owned(),
        EndReason::Family => "a family of cycles (multiplier 1)".to_owned(),
        EndReason::MaxPoints => "the largest number of points".to_owned(),
        EndReason::StateBound => "the state left the box of 20 (m/s, rad/s)".to_owned(),
        EndReason::BranchSwitch => "the period doubling it is born at".to_owned(),
    }
}

fn stability(s: Stability) -> &'static str {
    match s {
        Stability::Stable => "stable",
        Stability::Unstable => "unstable",
        Stability::Neutral => "neutral",
    }
}

/// The largest multiplier modulus of a point.
#[must_use]
pub fn max_modulus(p: &Point) -> f64 {
    p.multipliers
        .iter()
        .map(|m| m.modulus())
        .fold(0.0, f64::max)
}

fn opt(v: Option<f64>) -> String {
    v.map_or_else(|| "-".to_owned(), |v| format!("{v:.6}"))
}

/// The branches as a text table with the special points listed after each.
#[must_use]
pub fn text(branches: &[Branch]) -> String {
    let mut s = String::new();
    for b in branches {
        let _ = writeln!(
            s,
            "period-{} branch in {}: {} points; ends: {} / {}",
            b.period,
            b.parameter,
            b.points.len(),
            end_text(&b.ends[0]),
            end_text(&b.ends[1])
        );
        let _ = writeln!(
            s,
            "{:>12} {:>10} {:>10} {:>10} {:>9} {:>9} {:>8} {:>11}  label",
            b.parameter, "V", "T", "dx", "|mult|", "stability", "physical", "min normal"
        );
        for p in &b.points {
            let _ = writeln!(
                s,
                "{:>12.8} {:>10.6} {:>10.6} {:>10.6} {:>9.6} {:>9} {:>8} {:>11}  {}",
                p.parameter,
                p.cycle.speed,
                p.cycle.period,
                p.cycle.dx,
                max_modulus(p),
                stability(p.stability),
                if p.physical { "yes" } else { "no" },
                opt(p.tests.min_normal_force),
                p.label
                    .map_or(String::new(), |l| format!("{}{}", l.tag, l.number))
            );
        }
        let special: Vec<_> = b
            .special()
            .filter(|p| p.label.is_some_and(|l| l.tag != "EP"))
            .collect();
        if !special.is_empty() {
            let _ = writeln!(s, "special points:");
        }
        for p in special {
            if let Some(l) = p.label {
                let _ = writeln!(
                    s,
                    "  {}{} {:?} at {} = {:.10} (located to {:.1e}): V = {:.8}, largest |multiplier| {:.8}",
                    l.tag,
                    l.number,
                    l.kind,
                    b.parameter,
                    p.parameter,
                    l.bracket,
                    p.cycle.speed,
                    max_modulus(p)
                );
            }
        }
        s.push('\n');
    }
    s
}

/// The branches as one JSON object `{"scene", "parameter", "from", "to", "branches"}`.
#[must_use]
pub fn json(scene: &str, parameter: &str, from: f64, to: f64, branches: &[Branch]) -> String {
    serde_json::json!({
        "scene": scene,
        "parameter": parameter,
        "from": from,
        "to": to,
        "branches": branches,
    })
    .to_string()
}

/// The branches as CSV: a header and a row per point.
#[must_use]
pub fn csv(branches: &[Branch]) -> String {
    let mut s = String::from(
        "branch,period,index,parameter,V,T,dx,xd_plus,th1d_plus,max_multiplier,stability,physical,min_normal_force,rear_release,strike_after_t_set,label\n",
    );
    let f = |v: Option<f64>| v.map_or(String::new(), |v| format!("{v}"));
    for (k, b) in branches.iter().enumerate() {
        for (i, p) in b.points.iter().enumerate() {
            let _ = writeln!(
                s,
                "{k},{},{i},{},{},{},{},{},{},{},{},{},{},{},{},{}",
                b.period,
                p.parameter,
                p.cycle.speed,
                p.cycle.period,
                p.cycle.dx,
                p.state.first().copied().unwrap_or(f64::NAN),
                p.state.get(1).copied().unwrap_or(f64::NAN),
                max_modulus(p),
                stability(p.stability),
                p.physical,
                f(p.tests.min_normal_force),
                f(p.tests.rear_release),
                f(p.tests.strike_after_t_set),
                p.label.map_or(String::new(), |l| l.tag.to_owned())
            );
        }
    }
    s
}
