//! The gallery's summary (`summary.txt`): per model its held gaits and the outcomes of every
//! sweep as ranges of `mu0`, then its claims with their verdicts; the bifurcation diagrams'
//! branches and claims; and the tally.

use std::fmt::Write as _;

use super::bifurcation::{self, Diagram};
use super::claims::{Claim, table, tally};
use super::data::{DURATION, ModelRun};
use super::generic::{self, outcomes};
use super::{compass, rimless, three_link};

/// Every claim of `run`: the generic ones, then the model's own (a model without a module of
/// its own has the generic ones only).
#[must_use]
pub fn claims(run: &ModelRun) -> Vec<Claim> {
    let mut c = generic::claims(run);
    c.extend(match run.entry.model {
        "rimless-wheel" => rimless::claims(run),
        "compass-gait" => compass::claims(run),
        "three-link" => three_link::claims(run),
        _ => Vec::new(),
    });
    c
}

/// What was found for `run`: the held gaits and the sweeps' outcomes.
fn findings(s: &mut String, run: &ModelRun) {
    let _ = writeln!(
        s,
        "\n{} ({}), each walk from {}",
        run.entry.title,
        run.entry.path(),
        run.entry.start.phrase()
    );
    for (i, slope) in run.slopes.iter().enumerate() {
        let label = run.slope_label(i);
        match &slope.held {
            Ok(h) => {
                let pl = h.painleve;
                let _ = writeln!(
                    s,
                    "  held gait, {label}: T = {:.6} s, dx = {:.6} m, V = {:.6} m/s; needs \
                     |lambda_t/lambda_n| <= {:.4} (max at t = {:.2} T), |Lambda_t/Lambda_n| = \
                     {:.4} at the heel strike; a frictionless impact leaves the foot sliding at \
                     {:+.4} m/s, inconsistent above mu0 = {}{}",
                    h.step.period,
                    h.step.dx,
                    h.step.speed,
                    h.stance_ratio,
                    h.stance_at,
                    h.impact_ratio(),
                    pl.foot_velocity,
                    pl.mu0.map_or_else(|| "-".to_owned(), |m| format!("{m:.4}")),
                    if pl.double_support() {
                        format!(
                            ", but its normal impulse ({:.3e} N s) leaves the old foot on the \
                             floor (test impulse {:+.3e} N s): double support",
                            pl.normal_impulse, pl.rear_impulse
                        )
                    } else {
                        String::new()
                    }
                );
            }
            Err(why) => {
                let _ = writeln!(s, "  no held gait, {label}: {why}");
            }
        }
    }
    for sw in &run.sweeps {
        for (i, pts) in sw.chains.iter().enumerate() {
            let _ = writeln!(
                s,
                "  {}, {}: {}",
                run.slope_label(i),
                sw.laws.label(),
                outcomes(run, i, pts)
            );
        }
    }
}

/// The summary of every model's run and of the bifurcation diagrams: findings, claims, tally.
#[must_use]
pub fn summary(runs: &[ModelRun], diagrams: &[Diagram]) -> String {
    let (first, last, step) = runs.first().map_or((0.0, 0.0, 0.0), |r| {
        let g = &r.grid;
        let step = if g.len() > 1 { g[1] - g[0] } else { 0.0 };
        (g[0], g[g.len() - 1], step)
    });
    let mut s = format!(
        "Gallery: where the shipped walkers still walk as mu0 falls, how they fail, and why\n\
         (each mu0 from the walker's gait, walked {DURATION} s or until periodic; mu0 from \
         {first} to {last} by {step:.2})\n"
    );
    let mut all = Vec::new();
    for run in runs {
        findings(&mut s, run);
        let c = claims(run);
        s.push_str(&table(&c));
        all.extend(c);
    }
    s.push_str(&bifurcation::findings(diagrams));
    let c = bifurcation::claims(diagrams);
    s.push_str(&table(&c));
    all.extend(c);
    let _ = writeln!(s, "\n{}", tally(&all));
    s
}
