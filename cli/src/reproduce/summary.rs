//! The claims text of `walker reproduce`: each of the paper's claims with the values found in
//! the collected [`Data`], in the paper's order (the first part of `summary.txt`; the stability
//! lines follow). Sweeps are stated as ranges of `mu0` with one outcome each ([`super::ranges`]);
//! the claims of Sections 4 and 5 beyond the sweeps are in [`super::claims_active`] and
//! [`super::claims_passive`].

use std::fmt::Write as _;

use walker::model::ImpactRegime;
use walker::sim::{StepResult, Walk};
use walker::sweep::SweepPoint;

use super::claims_active::{
    convergence, fig8_details, period_convergence, slides_backward, slides_forward, step_limit,
};
use super::claims_passive::{large_mu0, passive_sweeps, step_lengths, sticks};
use super::data::Data;
use super::ranges::describe;

/// The `mu0 > 0` of the valid points of a sweep where `key` of the last step is largest
/// (`max`) or smallest, with that value, or `none`.
fn argbest(pts: &[SweepPoint], key: impl Fn(&StepResult) -> Option<f64>, max: bool) -> String {
    let mut best: Option<(f64, f64)> = None;
    for p in pts.iter().filter(|p| p.failure.is_none() && p.value > 0.0) {
        if let Some(v) = p.last.as_ref().and_then(&key) {
            let better = best.is_none_or(|(_, b)| if max { v > b } else { v < b });
            if better {
                best = Some((p.value, v));
            }
        }
    }
    best.map_or_else(
        || "none".to_owned(),
        |(m, v)| format!("mu0 = {m:.2} ({v:.6})"),
    )
}

/// Figs. 4 and 6: the steady speed reached from each `omega0` (`mu0 = 0` first, then the claims
/// of Fig. 4(a) and Fig. 5 between them, in the paper's order).
fn uniqueness(s: &mut String, d: &Data) {
    let steady_v = |w: &Walk| w.steps.last().map_or(f64::NAN, |s| s.speed);
    let v0: Vec<String> = d.omega_series[0]
        .iter()
        .map(|(w0, w)| format!("omega0={w0}: V={:.6}", steady_v(w)))
        .collect();
    let v4: Vec<String> = d.omega_series[1]
        .iter()
        .map(|(w0, w)| format!("omega0={w0}: V={:.6}", steady_v(w)))
        .collect();
    let _ = writeln!(
        s,
        "- mu0 = 0: limit cycles not unique (Fig. 4): {}",
        v0.join(", ")
    );
    period_convergence(s, d);
    slides_forward(s, d);
    let _ = writeln!(
        s,
        "- mu0 = 0.4: unique limit cycle (Fig. 6), after 30 steps: {}",
        v4.join(", ")
    );
}

/// Fig. 8: per `T_set`, where it walks and fails, the best speed and specific resistance, the
/// step length at the largest `mu0` against its limit `2 l sin(alpha/2)`, the jump from
/// `mu0 = 0` to 0.01 and where the step length lies above its limit.
fn active_sweep(s: &mut String, d: &Data) {
    for (ts, pts) in &d.active_sweep {
        let outcome =
            |p: &SweepPoint| Some(p.failure.as_ref().map_or("walks", |f| f.name()).to_owned());
        let _ = writeln!(s, "- T_set = {ts} (Fig. 8): {}", describe(pts, outcome));
        let _ = writeln!(
            s,
            "  max V at {}; min SR at {}",
            argbest(pts, |r| Some(r.speed), true),
            argbest(pts, |r| r.sr, false)
        );
        if let Some(last) = pts.last().and_then(|p| p.last.as_ref()) {
            let _ = writeln!(
                s,
                "  dx at mu0 = {:.2}: {:.6} (limit 2 l sin(alpha/2) = {:.6})",
                pts.last().map_or(f64::NAN, |p| p.value),
                last.dx,
                step_limit(&d.table1)
            );
        }
        fig8_details(s, pts, &d.table1);
    }
}

/// The largest relative difference of the steady speeds of two sweeps over the same grid
/// (`mu0 > 0`, both points walking), and where.
fn max_speed_difference(a: &[SweepPoint], b: &[SweepPoint]) -> (f64, f64) {
    a.iter()
        .zip(b)
        .filter(|(a, b)| a.value > 0.0 && a.failure.is_none() && b.failure.is_none())
        .filter_map(|(a, b)| Some((a.value, a.last?.speed, b.last?.speed)))
        .map(|(mu0, a, b)| (((a - b) / b).abs(), mu0))
        .fold(
            (0.0, f64::NAN),
            |best, x| if x.0 > best.0 { x } else { best },
        )
}

/// Exact Coulomb friction against the tanh law at `T_set = 0.3`, in stance only and in stance
/// and at the impact.
fn coulomb(s: &mut String, d: &Data) {
    let Some((_, tanh)) = d.active_sweep.iter().find(|(ts, _)| *ts == 0.3) else {
        return;
    };
    if let Some((_, exact)) = d.coulomb_sweep.first() {
        let (dv, _) = max_speed_difference(tanh, exact);
        let fails = exact.iter().filter(|p| p.failure.is_some()).count();
        let _ = writeln!(
            s,
            "- exact Coulomb friction (Eq. 25, stick-slip), T_set = 0.3: max V at {}; min SR at {}; \
             V differs from the tanh law (c = 100) by at most {:.2} % for mu0 in (0, 1]; {fails} failed points",
            argbest(exact, |r| Some(r.speed), true),
            argbest(exact, |r| r.sr, false),
            100.0 * dv
        );
    }
    if let Some((_, both)) = d.coulomb_impact_sweep.first() {
        let (dv, at) = max_speed_difference(tanh, both);
        let fails = both.iter().filter(|p| p.failure.is_some()).count();
        // From which mu0 on every impact sticks.
        let sticks_from = both
            .iter()
            .rev()
            .take_while(|p| p.last.is_some_and(|r| r.impact == ImpactRegime::Stick))
            .last()
            .map_or_else(|| "none".to_owned(), |p| format!("{:.2}", p.value));
        let _ = writeln!(
            s,
            "- exact Coulomb friction in stance and at the impact (docs/impacts.md), T_set = 0.3: \
             max V at {}; min SR at {}; V differs from the paper's model by at most {:.2} % \
             (at mu0 = {at:.2}); the impact sticks for mu0 >= {sticks_from}; {fails} failed points",
            argbest(both, |r| Some(r.speed), true),
            argbest(both, |r| r.sr, false),
            100.0 * dv
        );
    }
}

/// Fig. 14: how the walk at `phi = 0.10`, `mu0 = 0.19` ends.
fn fall(s: &mut String, d: &Data) {
    let _ = writeln!(
        s,
        "- phi = 0.10, mu0 = 0.19 (Fig. 14): {}",
        d.fall.failure.as_ref().map_or_else(
            || "walks".to_owned(),
            |f| format!("{} at step {}", f.name(), f.step)
        )
    );
}

/// The summary table of the paper's claims and the values found.
#[must_use]
pub fn summary(d: &Data) -> String {
    let mut s = String::from("Claims of the paper and values found\n");
    slides_backward(&mut s, d);
    uniqueness(&mut s, d);
    convergence(&mut s, d);
    active_sweep(&mut s, d);
    passive_sweeps(&mut s, d);
    sticks(&mut s, d);
    step_lengths(&mut s, d);
    fall(&mut s, d);
    large_mu0(&mut s, d);
    coulomb(&mut s, d);
    s
}
