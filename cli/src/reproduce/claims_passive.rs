//! The claims of Section 5 (the passive wheel on a slope) that the summary states with the
//! values found: where the sweeps of Figs. 10 and 13 settle to a periodic gait, where no
//! periodic gait can exist (`mu0 < tan(phi)`), the Fig. 10(b) remark, the sliding of Fig. 11,
//! the step lengths of Fig. 12, and the failure at large `mu0` with its threshold and its
//! dependence on the wheel inertia (the paper's closing remark of Section 5.2).

use std::fmt::Write as _;

use super::models::Table1;
use walker::sweep::SweepPoint;

use super::claims_active::slides;
use super::data::Data;
use super::passive::{INERTIA_PHI, PASSIVE_DURATION};
use super::ranges::{describe, interval, runs};

/// The outcome of one point of a passive sweep: its failure's name, `periodic`, or `not
/// periodic after 100 s` (the walk reached [`PASSIVE_DURATION`] without becoming periodic).
#[must_use]
pub fn outcome(p: &SweepPoint) -> String {
    match &p.failure {
        Some(f) => f.name().to_owned(),
        None if p.periodic => "periodic".to_owned(),
        None => format!("not periodic after {PASSIVE_DURATION} s"),
    }
}

/// A point that walked the whole duration without settling to a periodic gait.
#[must_use]
pub fn transient(p: &SweepPoint) -> bool {
    p.failure.is_none() && !p.periodic
}

/// The `mu0` above which the passive wheel's foot, sliding forward right after an impact,
/// has no positive normal force: the denominator of `lambda` (Eq. 23 in the slope's frame, at
/// `th1 - phi = -alpha/2` after the impact, Eq. 45 corrected, and `mu = -mu0`),
/// `2 I1 + m_t l^2 (1 - cos alpha) - mu0 m_t l^2 sin alpha`, is zero there (Painleve's paradox
/// of sliding friction). It does not depend on `phi`.
#[must_use]
pub fn painleve_mu0(p: &Table1) -> f64 {
    let ml2 = (p.m1 + p.m2) * p.l * p.l;
    (2.0 * p.i1 + ml2 * (1.0 - p.alpha.cos())) / (ml2 * p.alpha.sin())
}

/// The speeds (first and last of the grid) of the walks that did not settle, and how many of
/// them still lengthen their step at the end.
fn transients(pts: &[SweepPoint]) -> Option<String> {
    let t: Vec<&SweepPoint> = pts.iter().filter(|p| transient(p)).collect();
    let (first, last) = (t.first()?, t.last()?);
    let speed = |p: &SweepPoint| p.last.map_or(f64::NAN, |r| r.speed);
    let growing = t
        .iter()
        .filter(|p| matches!((p.previous, p.last), (Some(a), Some(b)) if b.dx > a.dx))
        .count();
    Some(format!(
        "V after {PASSIVE_DURATION} s {:.2} m/s at mu0 = {:.2} and {:.2} m/s at mu0 = {:.2}; the step \
         still lengthens at the end in {growing} of these {}",
        speed(first),
        first.value,
        speed(last),
        last.value,
        t.len()
    ))
}

/// One sweep chain of Figs. 10 and 13 (or its continued reading): the outcomes as ranges, where
/// `mu0 < tan(phi)` excludes a periodic gait, and the speeds of the transients.
fn chain(s: &mut String, phi: f64, pts: &[SweepPoint], reading: &str) {
    let _ = writeln!(
        s,
        "- phi = {phi} ({reading}): {}",
        describe(pts, |p| Some(outcome(p)))
    );
    let below = |p: &SweepPoint| (p.value < phi.tan() && transient(p)).then(|| "x".to_owned());
    for (_, a, b) in runs(pts, below) {
        let _ = writeln!(
            s,
            "  {}: mu0 < tan(phi) = {:.4}, no periodic gait can exist (over a period the friction, \
             at most mu0 times the normal force, must balance the weight along the slope)",
            interval(a, b),
            phi.tan()
        );
    }
    if let Some(t) = transients(pts) {
        let _ = writeln!(s, "  not periodic: {t}");
    }
}

/// Figs. 10 and 13, both readings of (P5b), and the paper's Fig. 10(b) remark.
pub fn passive_sweeps(s: &mut String, d: &Data) {
    for (phi, pts) in &d.passive_sweep {
        chain(
            s,
            *phi,
            pts,
            "Figs. 10, 13; each mu0 from (P2b) for 100 s, stopped once periodic",
        );
    }
    for (phi, pts) in &d.passive_continuation {
        chain(
            s,
            *phi,
            pts,
            "each mu0 continued from the previous one's last state ((P4b))",
        );
    }
    let unsettled = |chains: &[(f64, Vec<SweepPoint>)]| -> String {
        chains
            .iter()
            .filter(|(phi, _)| *phi > 0.1)
            .map(|(phi, pts)| {
                let r: Vec<String> = runs(pts, |p| transient(p).then(String::new))
                    .iter()
                    .map(|(_, a, b)| interval(*a, *b))
                    .collect();
                format!(
                    "phi = {phi}: {}",
                    if r.is_empty() {
                        "none".to_owned()
                    } else {
                        r.join(", ")
                    }
                )
            })
            .collect::<Vec<_>>()
            .join("; ")
    };
    let _ = writeln!(
        s,
        "- Fig. 10(b): the speed does not converge at small mu0 on phi = 0.15, 0.20: not periodic \
         after 100 s at {} (from (P2b)); at {} (continued)",
        unsettled(&d.passive_sweep),
        unsettled(&d.passive_continuation)
    );
}

/// The foot speed along the slope below which Fig. 11's foot counts as at rest (m/s). The tanh
/// law (Eq. 37, c = 100) holds a foot only while it creeps at `v = atanh(r / mu0) / c` for the
/// ratio `r` of tangential to normal force it needs: 4.2e-3 m/s for `r = tan(0.2)` at
/// `mu0 = 0.5`, so 1e-2 m/s separates that creep from sliding.
const AT_REST: f64 = 1e-2;

/// Over the recorded samples of a walk on the slope `phi`: the share of the time in which the
/// foot slides faster than [`AT_REST`], and the latest time after an impact (steps from the
/// 1st on) at which it still does.
fn sliding_time(w: &walker::sim::Walk, phi: f64) -> (f64, f64) {
    let (mut sliding, mut total, mut latest) = (0.0, 0.0, 0.0_f64);
    let mut start = 0.0;
    for pair in w.samples.windows(2) {
        let (a, b) = (&pair[0], &pair[1]);
        if a.step != b.step {
            start = b.time;
            continue;
        }
        let dt = b.time - a.time;
        total += dt;
        if a.state[4].abs() / phi.cos() > AT_REST {
            sliding += dt;
            if a.step > 0 {
                latest = latest.max(b.time - start);
            }
        }
    }
    (sliding / total, latest)
}

/// Fig. 11: the foot slides at `mu0 = 0.2` and not at 0.5 (`phi = 0.2`).
pub fn sticks(s: &mut String, d: &Data) {
    let phi = 0.2;
    let parts: Vec<String> = d
        .sticks
        .iter()
        .map(|(mu0, w)| {
            let sl = slides(w, &d.table1);
            let max = sl.iter().copied().fold(0.0_f64, |a, b| a.max(b.abs()));
            let (share, latest) = sliding_time(w, phi);
            format!(
                "mu0 = {mu0}: at most {max:.4} m per step over {} steps, sliding (faster than \
                 {AT_REST} m/s) {:.0} % of the time, at the latest {latest:.3} s after an impact",
                sl.len(),
                100.0 * share
            )
        })
        .collect();
    let _ = writeln!(
        s,
        "- Fig. 11 (phi = 0.2, from (P2b)): the foot slides along the slope (dx - 2 l sin(alpha/2)): \
         {}",
        parts.join("; ")
    );
}

/// Fig. 12: the step length grows with the step number at small `mu0` (`phi = 0.2`).
pub fn step_lengths(s: &mut String, d: &Data) {
    let parts: Vec<String> = d
        .step_lengths
        .iter()
        .map(|(mu0, w)| {
            let dx: Vec<f64> = w.steps.iter().map(|r| r.dx).collect();
            let grows = dx.windows(2).filter(|p| p[1] > p[0]).count();
            format!(
                "mu0 = {mu0}: dx {:.4} -> {:.4} m, longer than the step before in {grows} of {}",
                dx.first().copied().unwrap_or(f64::NAN),
                dx.last().copied().unwrap_or(f64::NAN),
                dx.len().saturating_sub(1)
            )
        })
        .collect();
    let _ = writeln!(
        s,
        "- Fig. 12 (phi = 0.2, 20 steps from (P2b); the caption says mu0 = 0.2, the text four values, \
         not named; run: 0.2, 0.3, 0.4, 0.5): {}",
        parts.join("; ")
    );
}

/// Whether every failure of `pts` happened right after the first impact (step 1, `t = 0`).
fn all_at_first_impact(pts: &[SweepPoint]) -> bool {
    pts.iter()
        .filter_map(|p| p.failure.as_ref())
        .all(|f| f.step == 1 && f.t == 0.0)
}

/// The passive wheel beyond the paper's `mu0` and with other wheel inertias: where it fails,
/// when, and the threshold of [`painleve_mu0`].
pub fn large_mu0(s: &mut String, d: &Data) {
    let table1 = d.table1;
    for (phi, pts) in &d.passive_large_mu0 {
        let _ = writeln!(
            s,
            "- passive wheel at large mu0 (Table 1, phi = {phi}, each mu0 from (P2b)): {}",
            describe(pts, |p| Some(outcome(p)))
        );
    }
    let _ = writeln!(
        s,
        "  every failure right after the first impact (step 1, t = 0): {}; predicted from mu0 > \
         (2 I1 + m_t l^2 (1 - cos alpha)) / (m_t l^2 sin alpha) = {:.4} (lambda's denominator \
         negative while the foot slides forward: Painleve's paradox)",
        all_at_first_impact(
            &d.passive_large_mu0
                .iter()
                .flat_map(|(_, p)| p.clone())
                .collect::<Vec<_>>()
        ),
        painleve_mu0(&table1)
    );
    for (i1, pts) in &d.passive_inertia {
        let p = Table1 { i1: *i1, ..table1 };
        let _ = writeln!(
            s,
            "- wheel inertia I1 = {i1} (Table 1: {}; phi = {INERTIA_PHI}): {}; predicted threshold \
             {:.4}; failures right after the first impact: {}",
            table1.i1,
            describe(pts, |p| Some(outcome(p))),
            painleve_mu0(&p),
            all_at_first_impact(pts)
        );
    }
}

#[cfg(test)]
mod tests {
    use super::super::models::Table1;
    use super::painleve_mu0;

    /// Table 1: `(2 * 0.5 + 3 (1 - cos 30 deg)) / (3 sin 30 deg) = (1 + 0.401924) / 1.5`
    /// (the 0.402 of the paper's text under Eq. 11); the inputs are exact to f64, so 1e-12.
    #[test]
    fn the_table1_painleve_threshold_is_1_402_over_1_5() {
        let k = 3.0 * (1.0 - (std::f64::consts::PI / 6.0).cos());
        let want = (1.0 + k) / 1.5;
        let t = Table1::load().expect("Table 1");
        assert!((painleve_mu0(&t) - want).abs() < 1e-12);
        assert!((want - 0.934_616).abs() < 1e-6, "{want}");
    }
}
