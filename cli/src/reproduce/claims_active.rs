//! The claims of Section 4 (the active walker on level ground) that the summary states with the
//! values found: the foot's sliding in Figs. 3 and 5, the period's convergence in Fig. 4(a), the
//! signs of the errors in Fig. 7, and in Fig. 8 the jump from `mu0 = 0` to 0.01 and where the
//! step length lies above its limit `2 l sin(alpha/2)`.

use std::fmt::Write as _;

use super::models::Table1;
use walker::sim::{StepResult, Walk};
use walker::sweep::SweepPoint;

use super::data::Data;
use super::ranges::describe;

/// The foot's step `2 l sin(alpha/2)` of Table 1 (Eq. 17; along the slope, Eq. 43): the step
/// length without sliding (m).
#[must_use]
pub fn step_limit(p: &Table1) -> f64 {
    2.0 * p.l * (p.alpha / 2.0).sin()
}

/// How far the stance foot slid in each step of `w` (along the floor): `dx - 2 l sin(alpha/2)`
/// (Eqs. 34, 47).
pub fn slides(w: &Walk, t: &Table1) -> Vec<f64> {
    w.steps.iter().map(|s| s.dx - step_limit(t)).collect()
}

/// `n of N steps, by a to b m per step` for the slides of [`slides`] with the sign `sign`.
fn slide_text(w: &Walk, sign: f64, t: &Table1) -> String {
    let s = slides(w, t);
    let n = s.iter().filter(|&&d| d * sign > 0.0).count();
    let (lo, hi) = s
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &d| {
            (a.min(d), b.max(d))
        });
    format!(
        "{n} of {} steps, by {lo:.4} to {hi:.4} m per step (dx - 2 l sin(alpha/2))",
        s.len()
    )
}

/// Fig. 3: the foot slides backward at `mu0 = 0`.
pub fn slides_backward(s: &mut String, d: &Data) {
    let _ = writeln!(
        s,
        "- Fig. 3 (T_set = 0.3, mu0 = 0, omega0 = 0.8): the stance foot slides backward in {}",
        slide_text(&d.motion[0], -1.0, &d.table1)
    );
}

/// Fig. 5: the foot slides forward at `mu0 = 0.4` and the step is longer than
/// `2 l sin(alpha/2)`.
pub fn slides_forward(s: &mut String, d: &Data) {
    let dx: Vec<f64> = d.motion[1].steps.iter().map(|s| s.dx).collect();
    let _ = writeln!(
        s,
        "- Fig. 5 (T_set = 0.3, mu0 = 0.4, omega0 = 0.8): the stance foot slides forward in {}; \
         dx = {:.4} to {:.4} m against 2 l sin(alpha/2) = {:.6}",
        slide_text(&d.motion[1], 1.0, &d.table1),
        dx.iter().copied().fold(f64::INFINITY, f64::min),
        dx.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        step_limit(&d.table1)
    );
}

/// The first step from which every later period of `w` lies within `rel` (relative) of the
/// last one, and that last period.
fn settled_at(w: &Walk, rel: f64) -> Option<(usize, f64)> {
    let last = w.steps.last()?.period;
    let far = |s: &StepResult| (s.period - last).abs() > rel * last;
    let k = w.steps.iter().rposition(far).map_or(0, |k| k + 1);
    Some((k, last))
}

/// Fig. 4(a): at `mu0 = 0` the period converges fast.
pub fn period_convergence(s: &mut String, d: &Data) {
    let walks = &d.omega_series[0];
    let settled: Vec<Option<(usize, f64)>> =
        walks.iter().map(|(_, w)| settled_at(w, 1e-6)).collect();
    let from: Vec<String> = walks
        .iter()
        .zip(&settled)
        .map(|((w0, _), k)| {
            k.map_or_else(
                || format!("no step (omega0 = {w0})"),
                |(k, _)| format!("{k} (omega0 = {w0})"),
            )
        })
        .collect();
    let periods: Vec<String> = settled
        .iter()
        .map(|k| k.map_or_else(|| "-".to_owned(), |(_, t)| format!("{t:.6}")))
        .collect();
    let _ = writeln!(
        s,
        "- Fig. 4(a), mu0 = 0: the period converges fast: T stays within 1e-6 (relative) of its \
         value at the last step ({}) from step {}; T = {} s",
        walks
            .first()
            .map_or(0, |(_, w)| w.steps.len().saturating_sub(1)),
        from.join(", "),
        periods.join(", ")
    );
}

/// `+` or `-` for the sign of `v` (`0` for zero).
fn sign(v: f64) -> char {
    if v > 0.0 {
        '+'
    } else if v < 0.0 {
        '-'
    } else {
        '0'
    }
}

/// Fig. 7: the velocity error norm falls monotonically, fast at the first impact and slowly
/// after; `d xd+` is always negative; `d th1d+` is positive at the 0th impact and negative after
/// the 1st.
pub fn convergence(s: &mut String, d: &Data) {
    let c = &d.convergence;
    let (Some(first), Some(last)) = (c.first(), c.last()) else {
        let _ = writeln!(s, "- Fig. 7: no steady gait at T_set = 0.3, mu0 = 0.4");
        return;
    };
    let n = c.len() - 1;
    let monotone = c.windows(2).all(|w| w[1][0] < w[0][0]);
    let rate_first = c.get(1).map_or(f64::NAN, |r| r[0] / first[0]);
    let rate_last = c
        .get(n.saturating_sub(1))
        .map_or(f64::NAN, |r| last[0] / r[0]);
    let count = |i: usize, neg: bool| {
        c[1..]
            .iter()
            .filter(|r| if neg { r[i] < 0.0 } else { r[i] > 0.0 })
            .count()
    };
    let _ = writeln!(
        s,
        "- Fig. 7 (T_set = 0.3, mu0 = 0.4, start 0.1 rad/s above the steady th1d+): \
         |qd+ - qd+_eq| falls monotonically: {monotone}; by a factor {rate_first:.4} at the 1st \
         impact, {rate_last:.4} per impact at the {n}th; d xd+: sign {} at the 0th impact, negative \
         at {} of impacts 1-{n}; d th1d+: sign {} at the 0th impact ({:+.4}), negative at {} of \
         impacts 1-{n}",
        sign(first[1]),
        count(1, true),
        sign(first[2]),
        first[2],
        count(2, true),
    );
}

/// `T dx V SR` of a point's last step, or `failed`.
fn descriptors(p: &SweepPoint) -> String {
    match (&p.failure, &p.last) {
        (None, Some(r)) => format!(
            "T = {:.4}, dx = {:.4}, V = {:.4}, SR = {}",
            r.period,
            r.dx,
            r.speed,
            r.sr.map_or_else(|| "-".to_owned(), |v| format!("{v:.4}"))
        ),
        (Some(f), _) => f.name().to_owned(),
        (None, None) => "no step".to_owned(),
    }
}

/// Fig. 8, per `T_set`: the descriptors at `mu0 = 0` and 0.01 (the paper: significant
/// differences except the period) and where the step length lies above or below its limit.
pub fn fig8_details(s: &mut String, pts: &[SweepPoint], t: &Table1) {
    if let [p0, p1, ..] = pts {
        let _ = writeln!(
            s,
            "  mu0 = {:.2}: {}; mu0 = {:.2}: {}",
            p0.value,
            descriptors(p0),
            p1.value,
            descriptors(p1)
        );
    }
    let lim = step_limit(t);
    let side = |p: &SweepPoint| {
        if p.failure.is_some() {
            return None;
        }
        let dx = p.last.as_ref()?.dx;
        Some(if dx > lim { "above" } else { "at or below" }.to_owned())
    };
    let _ = writeln!(
        s,
        "  dx against its limit 2 l sin(alpha/2): {}",
        describe(pts, side)
    );
}
