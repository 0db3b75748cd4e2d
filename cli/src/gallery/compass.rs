//! The compass gait's own claims (`models/compass-gait.toml`, Goswami, Thuilot and Espiau's
//! walker on their 3-degree slope): their gait with the foot held, the period doubling just
//! below it, the splits far below, and the narrow window the paper's frictionless impact leaves.

use walker::model::ImpactLaw;

use super::claims::{Claim, or_missing};
use super::data::ModelRun;
use super::laws::{EXACT, Laws};
use super::outcome::{Outcome, foot_at_failure};
use crate::reproduce::ranges::describe;

/// Goswami et al.'s 3-degree gait as this model walks it with its foot held (`walker
/// fixed-point --set mu0=5`; their Figs. C.4-C.5 give 0.735 s): period (s) and speed (m/s).
const GOSWAMI: (f64, f64) = (0.734346, 0.729146);

/// Two numbers agree to the printed digits of [`GOSWAMI`].
const DIGITS: f64 = 5e-7;

/// The first grid `mu0` at which the exact laws hold the foot on the 3-degree slope, and the
/// ratio the stance needs there right after the heel strike.
const HELD_FROM: (f64, f64) = (0.28, 0.2742);

/// Between the heel strike's and the stance's ratio: `mu0` and the two periods of the gait
/// that doubles (s).
const PERIOD_TWO: (f64, [f64; 2]) = (0.26, [0.722501, 0.750757]);

/// The splits: up to this `mu0` the walk from the held gait falls in its first step, its
/// stance foot having slid forward between these distances (m).
const SPLITS: (f64, f64, f64) = (0.20, 0.9, 1.12);

/// The frictionless impact's window of gaits on 3 degrees: Coulomb stance, tanh stance.
const WINDOW: [(f64, f64); 2] = [(0.46, 0.52), (0.48, 0.52)];

/// `a` and `b` equal to `tol`.
fn near(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

/// Goswami's gait, held from [`HELD_FROM`] on.
fn held(run: &ModelRun, i: usize) -> Option<Claim> {
    let h = run.slopes[i].held.as_ref().ok()?;
    let pts = &run.sweep(EXACT)?.chains[i];
    let held: Vec<_> = pts
        .iter()
        .filter(|p| run.outcome(i, p) == Outcome::Held)
        .filter_map(|p| Some((p.value, p.last?)))
        .collect();
    let first = held.first().map_or(f64::NAN, |(m, _)| *m);
    let all = held
        .iter()
        .all(|(_, r)| near(r.period, GOSWAMI.0, DIGITS) && near(r.speed, GOSWAMI.1, DIGITS));
    let (mu, r) = HELD_FROM;
    Some(Claim::new(
        format!(
            "compass gait, {}: with exact Coulomb friction it walks Goswami et al.'s 3-degree \
             gait with its foot held for mu0 >= {mu:.2}, the grid's first point above the \
             {r:.4} its stance needs right after the heel strike: T = {:.6} s, V = {:.6} m/s \
             at every such mu0 (their Figs. C.4-C.5: 0.735 s).",
            run.slope_label(i),
            GOSWAMI.0,
            GOSWAMI.1
        ),
        format!(
            "held from mu0 = {first:.2} at {} grid points, T and V as stated at all of them: \
             {all}; the stance needs {:.4}",
            held.len(),
            h.stance_ratio
        ),
        near(first, mu, 1e-9) && all && near(h.stance_ratio, r, 5e-5),
    ))
}

/// The period-two gait at [`PERIOD_TWO`].
fn period_two(run: &ModelRun, i: usize) -> Option<Claim> {
    let (mu0, want) = PERIOD_TWO;
    let w = run.walk(i, EXACT, mu0, 80)?;
    let t: Vec<f64> = w.steps.iter().map(|s| s.period).collect();
    let tail = t.get(t.len().saturating_sub(20)..).unwrap_or(&[]);
    let alternates = w.failure.is_none()
        && tail.len() == 20
        && tail
            .windows(3)
            .all(|x| near(x[0], x[2], 1e-9) && !near(x[0], x[1], 1e-3));
    let mut pair = [tail.first().copied(), tail.get(1).copied()].map(|x| x.unwrap_or(f64::NAN));
    pair.sort_by(f64::total_cmp);
    let stuck: Vec<String> = w
        .steps
        .iter()
        .rev()
        .take(2)
        .map(|s| format!("{:.4} of {:.4} s", s.stuck_time, s.period))
        .collect();
    Some(Claim::new(
        format!(
            "compass gait, {}, exact Coulomb friction, mu0 = {mu0:.2} (between the heel \
             strike's and the stance's ratio): the foot slips in each heel strike and right \
             after it, and the gait doubles its period: T alternates between {:.6} and {:.6} s \
             (80 steps from the held gait).",
            run.slope_label(i),
            want[0],
            want[1]
        ),
        format!(
            "T alternates {:.6} / {:.6} s over the last 20 steps: {alternates}; the foot is \
             stuck {} of the last two steps",
            pair[0],
            pair[1],
            stuck.join(" and ")
        ),
        alternates && near(pair[0], want[0], DIGITS) && near(pair[1], want[1], DIGITS),
    ))
}

/// The splits: below [`SPLITS`] the first step ends hip-down with the foot far ahead.
fn splits(run: &ModelRun, i: usize) -> Option<Claim> {
    let h = run.slopes[i].held.as_ref().ok()?;
    let pts = &run.sweep(EXACT)?.chains[i];
    let (top, lo, hi) = SPLITS;
    let phi = run.slopes[i].phi;
    let low: Vec<_> = pts.iter().filter(|p| p.value <= top + 1e-9).collect();
    let mut slides = Vec::new();
    let mut times = Vec::new();
    let mut ok = !low.is_empty();
    for p in &low {
        let first_step = p
            .failure
            .as_ref()
            .is_some_and(|f| f.step == 0 && f.name() == "hip-down");
        let (v, d) = foot_at_failure(p, phi).unwrap_or((f64::NAN, f64::NAN));
        ok &= first_step && v > 0.0 && (lo..=hi).contains(&d);
        slides.push(d);
        times.push(p.failure.as_ref().map_or(f64::NAN, |f| f.t));
    }
    let range = |x: &[f64]| {
        let (a, b) = x
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
                (a.min(v), b.max(v))
            });
        format!("{a:.3} to {b:.3}")
    };
    Some(Claim::new(
        format!(
            "compass gait, {}, exact Coulomb friction: far below (mu0 <= {top:.2}) it does the \
             splits in its first step: the stance foot, which needs {:.4} right after the heel \
             strike, slides forward from there, by {lo} to {hi} m, until the hip touches the \
             floor (hip-down).",
            run.slope_label(i),
            h.stance_ratio
        ),
        format!(
            "{} walks: hip-down in step 0 with the foot sliding forward at all of them: {ok}; \
             slid {} m, at t = {} s",
            low.len(),
            range(&slides),
            range(&times)
        ),
        ok,
    ))
}

/// The frictionless impact's narrow window of slipping gaits, below Painleve's threshold.
fn window(run: &ModelRun, i: usize) -> Option<Claim> {
    let h = run.slopes[i].held.as_ref().ok()?;
    let laws = [
        Laws {
            impact: ImpactLaw::Frictionless,
            ..EXACT
        },
        Laws {
            friction: walker::model::Friction::Tanh,
            impact: ImpactLaw::Frictionless,
        },
    ];
    let mut ok = true;
    let mut found = Vec::new();
    for (laws, (a, b)) in laws.iter().zip(WINDOW) {
        let pts = &run.sweep(*laws)?.chains[i];
        let gait = |p: &walker::sweep::SweepPoint| run.outcome(i, p).is_gait();
        ok &= pts
            .iter()
            .all(|p| gait(p) == (p.value >= a - 1e-9 && p.value <= b + 1e-9));
        ok &= pts.iter().filter(|p| gait(p)).all(|p| {
            p.last
                .is_some_and(|r| r.speed < h.step.speed && r.impact.is_frictionless())
        });
        let v: Vec<f64> = pts
            .iter()
            .filter(|p| gait(p))
            .filter_map(|p| p.last.map(|r| r.speed))
            .collect();
        let (lo, hi) = v
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                (a.min(x), b.max(x))
            });
        found.push(format!(
            "{}: {} (V {lo:.4} to {hi:.4} m/s)",
            laws.label(),
            describe(pts, |p| gait(p).then(|| "gaits".to_owned()))
        ));
    }
    let pl = h.painleve.mu0.unwrap_or(f64::NAN);
    Some(Claim::new(
        format!(
            "compass gait, {}, the paper's frictionless impact: the new foot always leaves the \
             heel strike sliding, so there is no held gait, and it walks only in a window below \
             Painleve's threshold {pl:.4}: mu0 in [{:.2}, {:.2}] with Coulomb friction in stance, \
             [{:.2}, {:.2}] with the tanh law, slower than the held gait ({:.6} m/s).",
            run.slope_label(i),
            WINDOW[0].0,
            WINDOW[0].1,
            WINDOW[1].0,
            WINDOW[1].1,
            h.step.speed
        ),
        found.join("; "),
        ok,
    ))
}

/// The compass gait's claims, on its own slope (3 degrees).
#[must_use]
pub fn claims(run: &ModelRun) -> Vec<Claim> {
    let i = run.nominal;
    vec![
        or_missing(held(run, i), "compass gait: Goswami's gait held"),
        or_missing(period_two(run, i), "compass gait: the period-two gait"),
        or_missing(splits(run, i), "compass gait: the splits"),
        or_missing(
            window(run, i),
            "compass gait: the frictionless impact's window",
        ),
    ]
}
