//! The rimless wheel's own claims (`models/rimless-wheel.toml`: the paper's wheel without its
//! torso): the heel strike's friction and the frictionless impact's Painleve threshold in closed
//! form, the wheel sliding away below `tan(phi)` at the acceleration friction leaves it, and its
//! fall backward when friction cannot turn it.

use walker::sweep::SweepPoint;

use super::claims::{Claim, or_missing};
use super::data::{DURATION, ModelRun};
use super::laws::EXACT;
use super::outcome::{Outcome, foot_at_failure};

/// The closed forms agree with the simulator's reaction and impulse to this: the heel strike's
/// state is extrapolated from the last of 20 000 frames of the held step.
const CLOSED_FORM: f64 = 1e-4;

/// A walk that slides away gains speed at the rate friction leaves it within this share.
const ACCELERATION: f64 = 0.05;

/// The falls backward: up to this `mu0`, within this many steps, the foot sliding forward
/// faster than this (m/s).
const FALLS: (f64, usize, f64) = (0.08, 4, 3.0);

/// The wheel's parameters `(rg, l, alpha, g)`.
fn wheel(run: &ModelRun) -> Option<(f64, f64, f64, f64)> {
    let s = run.entry.setup().ok()?;
    let p = |n: &str| s.params.get(n);
    Some((p("rg")?, p("l")?, p("alpha")?, p("g")?))
}

/// The heel strike's stick impulse and the frictionless impact's Painleve threshold against
/// their closed forms, on every slope.
fn closed_forms(run: &ModelRun) -> Option<Vec<Claim>> {
    let (rg, l, alpha, _) = wheel(run)?;
    let k = rg * rg / (l * l);
    // The hub's velocity turns from normal to the old spoke to normal to the new one, its
    // speed kept by eta = (cos alpha + k) / (1 + k) (angular momentum about the new foot): the
    // impulse lies along the new spoke but for the angle atan((eta - cos alpha) / sin alpha),
    // and the new spoke stands alpha/2 behind the floor's normal.
    let eta = (alpha.cos() + k) / (1.0 + k);
    let impact = (alpha / 2.0 - ((eta - alpha.cos()) / alpha.sin()).atan()).tan();
    // Eq. 23's denominator of the paper's passive wheel without the torso, sliding forward.
    let painleve = (2.0 * k + 1.0 - alpha.cos()) / alpha.sin();
    let mut impacts = Vec::new();
    let mut pls = Vec::new();
    let (mut ok_i, mut ok_p) = (true, true);
    for (i, s) in run.slopes.iter().enumerate() {
        let Ok(h) = &s.held else {
            ok_i = false;
            ok_p = false;
            continue;
        };
        let pl = h.painleve.mu0.unwrap_or(f64::NAN);
        ok_i &= (h.impact_ratio() - impact).abs() <= CLOSED_FORM;
        ok_p &= (pl - painleve).abs() <= CLOSED_FORM && h.painleve.foot_velocity > 0.0;
        impacts.push(format!("{}: {:.6}", run.slope_label(i), h.impact_ratio()));
        pls.push(format!("{}: {pl:.6}", run.slope_label(i)));
    }
    Some(vec![
        Claim::new(
            format!(
                "rimless wheel: the held gait's heel strike needs |Lambda_t/Lambda_n| = tan(alpha/2 \
                 - atan((eta - cos alpha) / sin alpha)) = {impact:.6} on every slope (eta = (cos \
                 alpha + k) / (1 + k), k = rg^2/l^2: the collision does not see gravity), to \
                 {CLOSED_FORM:e}."
            ),
            impacts.join(", "),
            ok_i,
        ),
        Claim::new(
            format!(
                "rimless wheel: the frictionless impact leaves the foot sliding forward, and its \
                 normal force's denominator vanishes at the paper's threshold without the torso, \
                 mu0 = (2 rg^2 + l^2 (1 - cos alpha)) / (l^2 sin alpha) = {painleve:.6} on every \
                 slope (reproduce: 0.9346 with the torso), to {CLOSED_FORM:e}: above the grid, so \
                 no sweep meets it."
            ),
            pls.join(", "),
            ok_p,
        ),
    ])
}

/// Below `tan(phi)` the foot slides forward throughout: the wheel gains speed at
/// `g (sin phi - mu0 cos phi)`.
fn slides_away(run: &ModelRun) -> Option<Claim> {
    let (.., g) = wheel(run)?;
    let sweep = run.sweep(EXACT)?;
    let mut ratios = Vec::new();
    let mut n = 0;
    for (i, pts) in sweep.chains.iter().enumerate() {
        let phi = run.slopes[i].phi;
        let v0 = run.held_speed(i)?;
        for p in pts
            .iter()
            .filter(|p| run.outcome(i, p) == Outcome::SlidesAway)
        {
            n += 1;
            let a = g * (phi.sin() - p.value * phi.cos());
            let v = p.last.map_or(f64::NAN, |r| r.speed);
            ratios.push((v - v0) / (a * DURATION));
        }
    }
    let (lo, hi) = ratios
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &r| {
            (a.min(r), b.max(r))
        });
    Some(Claim::new(
        format!(
            "rimless wheel, {}: a wheel that slides away (mu0 below tan(phi)) has its foot sliding \
             forward with friction at its limit mu0 throughout, in stance and in the impacts, so \
             it gains speed at g (sin phi - mu0 cos phi): after {DURATION} s its speed exceeds \
             the held gait's by that times {DURATION} s, to {:.0} %.",
            EXACT.label(),
            100.0 * ACCELERATION
        ),
        format!(
            "{n} walks slide away; gained speed over g (sin phi - mu0 cos phi) {DURATION} s from \
             {lo:.4} to {hi:.4}"
        ),
        n > 0 && ratios.iter().all(|r| (r - 1.0).abs() <= ACCELERATION),
    ))
}

/// Where the wheel falls backward, how soon, and how fast its foot slides then.
fn falls(run: &ModelRun) -> Option<Claim> {
    let (top, steps, speed) = FALLS;
    let (mut n, mut ok) = (0, true);
    let (mut vmin, mut smax, mut mmax) = (f64::INFINITY, 0, 0.0_f64);
    for s in &run.sweeps {
        for (i, pts) in s.chains.iter().enumerate() {
            let phi = run.slopes[i].phi;
            for p in pts.iter().filter(|p: &&SweepPoint| {
                p.failure
                    .as_ref()
                    .is_some_and(|f| f.name() == "fell-backward")
            }) {
                n += 1;
                let step = p.failure.as_ref().map_or(usize::MAX, |f| f.step);
                let (v, _) = foot_at_failure(p, phi).unwrap_or((f64::NAN, f64::NAN));
                ok &= p.value <= top + 1e-9 && step <= steps && v > speed;
                (vmin, smax, mmax) = (vmin.min(v), smax.max(step), mmax.max(p.value));
            }
        }
    }
    // Without friction the rotation only loses at the impacts: its rate after each one.
    let i = run.nominal;
    let w = run.walk(i, EXACT, 0.0, 10)?;
    let spin: Vec<f64> = std::iter::once(run.slopes[i].held.as_ref().ok()?.start)
        .chain(w.steps.iter().map(walker::sim::StepResult::state_plus))
        .map(|s| s[s.len() - 1])
        .collect();
    let falling = spin.windows(2).all(|x| x[1] < x[0])
        && w.failure
            .as_ref()
            .is_some_and(|f| f.name() == "fell-backward");
    let spin: Vec<String> = spin.iter().map(|x| format!("{x:.4}")).collect();
    Some(Claim::new(
        format!(
            "rimless wheel, any law and slope: it falls backward only where friction can hardly \
             turn it (mu0 <= {top:.2}): it slides down the slope as a whole, its foot faster than \
             {speed} m/s, and, as a rimless wheel on level ground, its impacts eat the rotation \
             until it rolls back onto its rear spoke within {steps} steps (on {} at mu0 = 0 the \
             spin after each impact falls until the fall).",
            run.slope_label(i)
        ),
        format!(
            "{n} walks fall backward, at mu0 up to {mmax:.2}, in steps up to {smax}, the foot \
             sliding forward at {vmin:.3} m/s or faster; at mu0 = 0 thd+ = {} rad/s, then \
             {}",
            spin.join(", "),
            w.failure.as_ref().map_or("no fall", |f| f.name())
        ),
        n > 0 && ok && falling,
    ))
}

/// The rimless wheel's claims.
#[must_use]
pub fn claims(run: &ModelRun) -> Vec<Claim> {
    let mut c = closed_forms(run).unwrap_or_else(|| {
        vec![or_missing(
            None,
            "rimless wheel: the closed forms of the heel strike",
        )]
    });
    c.push(or_missing(slides_away(run), "rimless wheel: sliding away"));
    c.push(or_missing(falls(run), "rimless wheel: the falls backward"));
    c
}
