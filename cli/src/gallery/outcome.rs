//! What became of one walk of a sweep: a gait (held, or with a slipping foot), a walk that did
//! not settle in the time it had (sliding away down the slope, or not periodic), or a failure by
//! the simulator's name (a fall of the model file, `lift-off`, `contact-inconsistent`, ...).

use walker::model::ImpactRegime;
use walker::sim::StepResult;
use walker::sweep::SweepPoint;

/// A walk has settled to a periodic gait when the library's test says so, or when its last two
/// steps agree in `T` and `dx` to this (relative; the tanh law's creep converges to its noise
/// floor of about 1e-14 without meeting the library's geometric test).
pub const SETTLED: f64 = 1e-6;

/// A walk that has not settled and is this many times faster than the held gait slides away
/// down the slope.
pub const SLIDES_AWAY: f64 = 1.5;

/// The outcome of one walk of a sweep.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Outcome {
    /// A periodic gait whose stance foot never moves: stuck through the stance, the impact
    /// sticking.
    Held,
    /// A periodic gait whose foot slips in stance or at the impact.
    Slipping,
    /// Walked to the end without settling, faster than [`SLIDES_AWAY`] times the held gait.
    SlidesAway,
    /// Walked to the end without settling.
    NotPeriodic,
    /// Failed, by the simulator's name.
    Failed(String),
}

/// Whether the step's foot never moved: stuck for the whole stance, and the impact stuck.
#[must_use]
pub fn is_held(r: &StepResult) -> bool {
    r.stuck_time >= r.period && r.impact == ImpactRegime::Stick
}

/// Where a failed walk's stance foot was when it failed, on a floor of slope `phi` (0, or NaN
/// as the gallery's data writes a level floor's slope): its velocity along the floor (m/s, positive forward, down the slope) and how far
/// along the floor it had slid since its step began (m; from the last completed step's
/// post-impact foot, or from the origin in step 0). `None` if the walk did not fail.
#[must_use]
pub fn foot_at_failure(p: &SweepPoint, phi: f64) -> Option<(f64, f64)> {
    let f = p.failure.as_ref()?;
    let n = f.state.len() / 2;
    let x0 = match (f.step, p.last) {
        (0, _) | (_, None) => 0.0,
        (_, Some(r)) => r.q_plus[0],
    };
    let c = if phi.is_nan() { 1.0 } else { phi.cos() };
    Some((f.state[n] / c, (f.state[0] - x0) / c))
}

/// Whether a point's walk settled to a periodic gait ([`SETTLED`]).
#[must_use]
pub fn settled(p: &SweepPoint) -> bool {
    if p.failure.is_some() {
        return false;
    }
    if p.periodic {
        return true;
    }
    let near = |a: f64, b: f64| (a - b).abs() <= SETTLED * b.abs();
    matches!((p.previous, p.last), (Some(a), Some(b)) if near(a.period, b.period) && near(a.dx, b.dx))
}

impl Outcome {
    /// The outcome of `p`; `held_speed` is the speed of the slope's held gait (if it has one).
    #[must_use]
    pub fn of(p: &SweepPoint, held_speed: Option<f64>) -> Outcome {
        if let Some(f) = &p.failure {
            return Outcome::Failed(f.name().to_owned());
        }
        match p.last {
            Some(r) if settled(p) && is_held(&r) => Outcome::Held,
            _ if settled(p) => Outcome::Slipping,
            Some(r) if held_speed.is_some_and(|v| r.speed > SLIDES_AWAY * v) => Outcome::SlidesAway,
            _ => Outcome::NotPeriodic,
        }
    }

    /// Whether it is a periodic gait (held or slipping).
    #[must_use]
    pub fn is_gait(&self) -> bool {
        matches!(self, Outcome::Held | Outcome::Slipping)
    }

    /// Its name in the text, the CSV files and the legends.
    #[must_use]
    pub fn label(&self) -> String {
        match self {
            Outcome::Held => "held gait".to_owned(),
            Outcome::Slipping => "gait with slip".to_owned(),
            Outcome::SlidesAway => "slides away".to_owned(),
            Outcome::NotPeriodic => "not periodic".to_owned(),
            Outcome::Failed(name) => name.clone(),
        }
    }
}

#[cfg(test)]
mod tests {
    use walker::sim::FailureKind;
    use walker::sweep::SweepPoint;
    use walker::vector::Vector;

    use super::foot_at_failure;

    /// A walk of a two-coordinate walker that failed in its first step with the foot at
    /// `x = 0.3`, moving at `xd = -0.5`.
    fn failed() -> SweepPoint {
        SweepPoint {
            value: 0.4,
            steps: 0,
            last: None,
            previous: None,
            failure: Some(FailureKind::NonFinite.at(
                0,
                0.1,
                Vector::from_slice(&[0.3, 0.0, -0.5, 0.0]),
            )),
            periodic: false,
        }
    }

    #[test]
    fn a_level_floor_written_as_nan_is_level() {
        assert_eq!(foot_at_failure(&failed(), f64::NAN), Some((-0.5, 0.3)));
        assert_eq!(foot_at_failure(&failed(), 0.0), Some((-0.5, 0.3)));
    }

    #[test]
    fn on_a_slope_the_foot_moves_along_it() {
        // x is horizontal: along a slope of 60 degrees the foot went twice as far.
        let (v, d) = foot_at_failure(&failed(), std::f64::consts::FRAC_PI_3).expect("failed");
        assert!(
            (v + 1.0).abs() < 1e-15 && (d - 0.6).abs() < 1e-15,
            "{v}, {d}"
        );
    }
}
