//! The claims every model of the gallery gets, each from a physical argument the run checks
//! against its sweeps: the held gait exists exactly where the friction it needs is available
//! ([`held_range`]); no periodic gait below `tan(phi)` ([`below_slope`], on a slope only); with
//! the frictionless impact, the new foot's slide becomes inconsistent above Painleve's threshold
//! ([`painleve`], where that heel strike lets the old stance foot leave the floor).
//!
//! An actuated walker on a level floor (the three-link biped) gets the first two: its held gait
//! is a cycle of its controller with the foot stuck, which no more depends on `mu0` than a
//! passive walker's, so the friction it needs decides where it holds the foot in the same way.
//! The other two are left out for it where their premise fails, each for the reason stated at
//! its check; its own claims say what happens instead.

use walker::sweep::SweepPoint;

use super::claims::Claim;
use super::data::{ModelRun, Sweep};
use super::held::HELD_MU0;
use super::laws::EXACT;
use super::outcome::Outcome;
use crate::reproduce::ranges::{describe, interval, runs};

/// The held gait's period may differ between the points of a sweep by this (relative): the
/// same trajectory, integrated from the same state.
pub const PERIOD_SPREAD: f64 = 1e-9;

/// The outcomes of `pts` on slope `i` as ranges of `mu0` (`held gait for mu0 in [a, b]; ...`).
#[must_use]
pub fn outcomes(run: &ModelRun, i: usize, pts: &[SweepPoint]) -> String {
    describe(pts, |p| Some(run.outcome(i, p).label()))
}

/// `mu0 in [a, b], ...` for the points of `pts` that `keep` selects (`none` if there are none).
fn where_(pts: &[SweepPoint], keep: impl Fn(&SweepPoint) -> bool) -> String {
    let r: Vec<String> = runs(pts, |p| keep(p).then(String::new))
        .iter()
        .map(|(_, a, b)| interval(*a, *b))
        .collect();
    if r.is_empty() {
        "none".to_owned()
    } else {
        r.join(", ")
    }
}

/// The model walks a held gait on every slope (with friction to spare, [`HELD_MU0`]).
#[must_use]
pub fn has_held_gait(run: &ModelRun) -> Claim {
    let found: Vec<String> = run
        .slopes
        .iter()
        .enumerate()
        .map(|(i, s)| match &s.held {
            Ok(h) => format!("{}: T = {:.6} s", run.slope_label(i), h.step.period),
            Err(why) => format!("{}: {why}", run.slope_label(i)),
        })
        .collect();
    let floors = if run.slope_param.is_none() {
        "on its level floor"
    } else {
        "on every slope"
    };
    Claim::new(
        format!(
            "{}: with exact Coulomb friction and friction to spare (mu0 = {HELD_MU0}), the walk \
             from its start settles to a held gait, its foot never moving, {floors}.",
            run.entry.title
        ),
        found.join("; "),
        run.slopes.iter().all(|s| s.held.is_ok()),
    )
}

/// Per slope with a held gait: the exact laws hold the foot at every grid `mu0` at least the
/// ratio the held gait needs (in stance and at the heel strike) and at none below, with the
/// same period.
#[must_use]
pub fn held_range(run: &ModelRun) -> Vec<Claim> {
    let Some(sweep) = run.sweep(EXACT) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for (i, slope) in run.slopes.iter().enumerate() {
        let Ok(h) = &slope.held else { continue };
        let pts = &sweep.chains[i];
        let r = h.needs();
        let held = |p: &SweepPoint| run.outcome(i, p) == Outcome::Held;
        let as_claimed = pts.iter().all(|p| held(p) == (p.value >= r));
        let periods: Vec<f64> = pts
            .iter()
            .filter(|p| held(p))
            .filter_map(|p| p.last.map(|s| s.period))
            .collect();
        let (lo, hi) = periods
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &t| {
                (a.min(t), b.max(t))
            });
        let t = h.step.period;
        let same = periods.iter().all(|&p| (p - t).abs() <= PERIOD_SPREAD * t);
        let which = if h.impact_ratio() >= h.stance_ratio {
            "the heel strike"
        } else {
            "the stance"
        };
        out.push(Claim::new(
            format!(
                "{}, {}, {}: the held gait (T = {t:.6} s, dx = {:.6} m, V = {:.6} m/s) needs \
                 |lambda_t/lambda_n| up to {:.4} in stance (at t = {:.2} T) and |Lambda_t/Lambda_n| \
                 = {:.4} at the heel strike; {which} decides, so the walker keeps its foot held \
                 exactly for mu0 >= {r:.4}: at every grid mu0 from there, with T the same to \
                 {PERIOD_SPREAD:e}, and at none below.",
                run.entry.title,
                run.slope_label(i),
                EXACT.label(),
                h.step.dx,
                h.step.speed,
                h.stance_ratio,
                h.stance_at,
                h.impact_ratio(),
            ),
            if periods.is_empty() {
                "held at no grid mu0".to_owned()
            } else {
                format!(
                    "held for {}; T from {lo:.9} to {hi:.9} s",
                    where_(pts, held)
                )
            },
            as_claimed && same && !periods.is_empty(),
        ));
    }
    out
}

/// Across every law and slope: no walk settles to a periodic gait where `mu0 < tan(phi)`. None
/// for a level walker.
#[must_use]
pub fn below_slope(run: &ModelRun) -> Vec<Claim> {
    // On a level floor (a model without a slope parameter) `tan(phi)` is 0 and no `mu0` lies
    // below it: friction need not hold the walker against gravity along the floor over a
    // period, its energy comes from its actuators, so there is nothing to claim.
    if run.slope_param.is_none() {
        return Vec::new();
    }
    let (mut n, mut settled) = (0, 0);
    for s in &run.sweeps {
        for (i, pts) in s.chains.iter().enumerate() {
            let tan = run.slopes[i].phi.tan();
            for p in pts.iter().filter(|p| p.value < tan) {
                n += 1;
                if run.outcome(i, p).is_gait() {
                    settled += 1;
                }
            }
        }
    }
    if n == 0 {
        return Vec::new();
    }
    let tans: Vec<String> = run
        .slopes
        .iter()
        .enumerate()
        .map(|(i, s)| format!("{}: {:.4}", run.slope_label(i), s.phi.tan()))
        .collect();
    let i = run.nominal;
    let tan = run.slopes[i].phi.tan();
    let below: Vec<String> = run
        .sweeps
        .iter()
        .map(|s| {
            let pts: Vec<SweepPoint> = s.chains[i]
                .iter()
                .filter(|p| p.value < tan)
                .cloned()
                .collect();
            format!("{}: {}", s.laws.label(), outcomes(run, i, &pts))
        })
        .collect();
    vec![Claim::new(
        format!(
            "{}: no walk settles to a periodic gait where mu0 < tan(phi) ({}), under any of the \
             four laws: over a period the friction, at most mu0 times the normal force at every \
             instant and in every impulse, must balance the weight along the slope.",
            run.entry.title,
            tans.join(", ")
        ),
        format!(
            "{settled} of {n} walks below tan(phi) settle; on {} they end as: {}",
            run.slope_label(i),
            below.join("; ")
        ),
        settled == 0,
    )]
}

/// Whether `p` failed right at the start of step 1 by a contact that cannot slide
/// (`contact-inconsistent`, `lift-off`).
fn fails_at_first_impact(p: &SweepPoint) -> bool {
    p.failure.as_ref().is_some_and(|f| {
        f.step == 1 && f.t == 0.0 && matches!(f.name(), "contact-inconsistent" | "lift-off")
    })
}

/// The sweeps with the frictionless impact.
fn frictionless(run: &ModelRun) -> impl Iterator<Item = &Sweep> {
    run.sweeps
        .iter()
        .filter(|s| s.laws.impact == walker::model::ImpactLaw::Frictionless)
}

/// Per slope with a held gait whose frictionless heel strike lets the old stance foot leave
/// the floor: with the frictionless impact the walk from the held gait fails at the start of
/// step 1 exactly where `mu0` is above the Painleve threshold of the new foot's slide.
#[must_use]
pub fn painleve(run: &ModelRun) -> Vec<Claim> {
    let mut out = Vec::new();
    let top = run.grid.last().copied().unwrap_or(0.0);
    for (i, slope) in run.slopes.iter().enumerate() {
        let Ok(h) = &slope.held else { continue };
        let pl = h.painleve;
        // Where the frictionless heel strike keeps the old stance foot on the floor (the
        // three-link biped's grazing strike: its normal impulse is too small to lift the rear
        // foot), the simulator ends every walk that reaches it in `double-support`: no next
        // stance begins, so the threshold of its sliding foot decides nothing. The model's own
        // claims say how its walks end.
        if pl.double_support() {
            continue;
        }
        let threshold = pl.mu0.unwrap_or(f64::INFINITY);
        let mut found = Vec::new();
        let mut ok = true;
        for s in frictionless(run) {
            let pts = &s.chains[i];
            ok &= pts
                .iter()
                .all(|p| fails_at_first_impact(p) == (p.value > threshold));
            found.push(format!(
                "{}: {}",
                s.laws.label(),
                where_(pts, fails_at_first_impact)
            ));
        }
        let text = match pl.mu0 {
            Some(m) if m <= top => format!(
                "{}, {}, frictionless impact: the held gait's heel strike leaves the new foot \
                 sliding at {:+.4} m/s; sliding that way its normal force's denominator vanishes \
                 at mu0 = {m:.4} (Painleve's paradox), so the walk from the held gait ends at the \
                 start of step 1 (contact-inconsistent under Coulomb friction, lift-off under the \
                 tanh law) at every grid mu0 above {m:.4} and at none below.",
                run.entry.title,
                run.slope_label(i),
                pl.foot_velocity
            ),
            Some(m) => format!(
                "{}, {}, frictionless impact: the new foot slides at {:+.4} m/s after the heel \
                 strike; its Painleve threshold mu0 = {m:.4} lies above the grid, so no walk \
                 ends at the start of step 1 for want of a consistent contact.",
                run.entry.title,
                run.slope_label(i),
                pl.foot_velocity
            ),
            None => format!(
                "{}, {}, frictionless impact: the new foot slides at {:+.4} m/s after the heel \
                 strike, and sliding that way its normal force has no pole in mu0, so no walk \
                 ends at the start of step 1 for want of a consistent contact.",
                run.entry.title,
                run.slope_label(i),
                pl.foot_velocity
            ),
        };
        out.push(Claim::new(
            text,
            format!("fails so for {}", found.join("; ")),
            ok,
        ));
    }
    out
}

/// Every generic claim of `run`.
#[must_use]
pub fn claims(run: &ModelRun) -> Vec<Claim> {
    let mut c = vec![has_held_gait(run)];
    c.extend(held_range(run));
    c.extend(below_slope(run));
    c.extend(painleve(run));
    c
}
