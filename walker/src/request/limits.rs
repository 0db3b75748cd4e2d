//! The limits of a walk and of a trajectory: how many steps, how long, when a periodic gait
//! stops early, how densely and how many samples. Each is bounded so that a request's memory
//! and time are bounded before any work starts.

use crate::sim::WalkLimits;

use super::error::RequestError;
use super::field::Field;
use super::shown;

/// The most steps a walk may take (`max_steps`): every step of a walk is kept (about 200 bytes
/// each), so this bounds a request's memory (about 200 MB) and time (about 6 minutes of the
/// paper's walker at the step limit).
pub const MAX_STEPS: usize = 1_000_000;

/// The longest walk (s): no walk of at most [`MAX_STEPS`] steps lasts this long unless its
/// steps last over 1000 s each (the shipped walkers' take about a second at most), so a longer
/// duration cannot change a walk; a value above it is a mistyped number.
pub const MAX_DURATION: f64 = 1e9;

/// The most samples of a trajectory (`max_frames`): a sample is a few dozen numbers, so this
/// bounds a trajectory's memory as [`MAX_STEPS`] bounds a walk's.
pub const MAX_FRAMES: usize = 1_000_000;

/// `n` given as `field` if it is a whole number in `[low, high]` (a front end passes what it
/// was given: a negative or huge number is named here, not left to a conversion).
///
/// # Errors
/// Outside `[low, high]`.
pub fn count(field: Field, n: i128, low: usize, high: usize) -> Result<usize, RequestError> {
    match usize::try_from(n) {
        Ok(k) if (low..=high).contains(&k) => Ok(k),
        _ => Err(RequestError::Count {
            field,
            given: n.to_string(),
            low: low as u64,
            high: high as u64,
        }),
    }
}

/// A count given as text (`"100"`, `"1e30"`, `"-1"`), as [`count`] checks it.
///
/// # Errors
/// Not a whole number, or outside `[low, high]`.
pub fn count_text(
    field: Field,
    text: &str,
    low: usize,
    high: usize,
) -> Result<usize, RequestError> {
    let t = text.trim();
    // A count has no sign: `-0` is a mistyped flag or value, not zero.
    match t.parse::<i128>() {
        Ok(n) if !t.starts_with('-') => count(field, n, low, high),
        _ => Err(RequestError::Count {
            field,
            given: shown::text(text),
            low: low as u64,
            high: high as u64,
        }),
    }
}

/// The most steps of a walk: in `[0, MAX_STEPS]`.
///
/// # Errors
/// Outside the range ([`Field::MaxSteps`]).
pub fn max_steps(n: i128) -> Result<usize, RequestError> {
    count(Field::MaxSteps, n, 0, MAX_STEPS)
}

/// How long a walk lasts (s): in `(0, MAX_DURATION]`.
///
/// # Errors
/// NaN, infinite or outside the range ([`Field::Duration`]).
pub fn duration(d: f64) -> Result<f64, RequestError> {
    if d > 0.0 && d <= MAX_DURATION {
        Ok(d)
    } else {
        Err(RequestError::out_of_range(
            Field::Duration,
            d,
            format!("in (0, {MAX_DURATION:e}] s"),
        ))
    }
}

/// The tolerance of the periodic-gait stop: in `(0, 1)`.
///
/// # Errors
/// NaN or outside the range ([`Field::UntilPeriodic`]).
pub fn until_periodic(x: f64) -> Result<f64, RequestError> {
    if x > 0.0 && x < 1.0 {
        Ok(x)
    } else {
        Err(RequestError::out_of_range(
            Field::UntilPeriodic,
            x,
            "in (0, 1)",
        ))
    }
}

/// The limits of a walk: `duration` by [`duration()`] (`None`: none, the steps bound the
/// walk), `max_steps` by [`max_steps()`], `until_periodic` by [`until_periodic()`]. Nothing is
/// recorded.
///
/// # Errors
/// One of them out of its range.
pub fn walk_limits(
    duration_given: Option<f64>,
    max_steps_given: i128,
    until_periodic_given: Option<f64>,
) -> Result<WalkLimits, RequestError> {
    Ok(WalkLimits {
        max_steps: max_steps(max_steps_given)?,
        duration: duration_given.map_or(Ok(f64::INFINITY), duration)?,
        record: false,
        periodic: until_periodic_given.map(until_periodic).transpose()?,
    })
}

/// The time between a trajectory's samples (s): in `(0, MAX_DURATION]`. How many samples it
/// makes is bounded by [`max_frames()`] (the trajectory is cut there and says so).
///
/// # Errors
/// NaN, infinite or outside the range ([`Field::TrajectoryDt`]).
pub fn trajectory_dt(dt: f64) -> Result<f64, RequestError> {
    if dt > 0.0 && dt <= MAX_DURATION {
        Ok(dt)
    } else {
        Err(RequestError::out_of_range(
            Field::TrajectoryDt,
            dt,
            format!("in (0, {MAX_DURATION:e}] s"),
        ))
    }
}

/// The most samples of a trajectory: in `[1, MAX_FRAMES]`.
///
/// # Errors
/// Outside the range ([`Field::MaxFrames`]).
pub fn max_frames(n: i128) -> Result<usize, RequestError> {
    count(Field::MaxFrames, n, 1, MAX_FRAMES)
}

/// A trajectory's sampling, checked as a whole: `dt` by [`trajectory_dt()`], `max_frames`
/// by [`max_frames()`], and, for a walk of finite `duration`, the samples it asks for,
/// `duration / dt + 1`, at most [`MAX_FRAMES`] (a request for more is refused before any
/// work, rather than cut). Returns `(dt, max_frames)`.
///
/// # Errors
/// One of them out of its range, or too many samples ([`Field::TrajectoryDt`]).
pub fn trajectory(
    duration: Option<f64>,
    dt: f64,
    max_frames_given: i128,
) -> Result<(f64, usize), RequestError> {
    let dt = trajectory_dt(dt)?;
    let frames = max_frames(max_frames_given)?;
    if let Some(d) = duration.filter(|d| d.is_finite()) {
        at_most(
            Field::TrajectoryDt,
            "samples (duration / trajectory_dt + 1)",
            values_in(d, dt),
            MAX_FRAMES,
        )?;
    }
    Ok((dt, frames))
}

/// How many values `first, first + step, ..` up to `first + span` makes (the last counted
/// when rounding leaves it within `1e-9` steps), as `f64`: a huge or infinite count is
/// counted, never made.
#[must_use]
pub fn values_in(span: f64, step: f64) -> f64 {
    (span / step + 1e-9).floor() + 1.0
}

/// `count` of `what` asked for by `field`, at most `limit` (checked before any work).
///
/// # Errors
/// More than `limit` ([`RequestError::TooLarge`], naming `field`).
pub fn at_most(
    field: Field,
    what: &'static str,
    count: f64,
    limit: usize,
) -> Result<(), RequestError> {
    if count > limit as f64 {
        Err(RequestError::TooLarge {
            field,
            what,
            count,
            limit: limit as u64,
        })
    } else {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_bad_limit_names_its_field() {
        let field = |r: Result<WalkLimits, RequestError>| r.err().map(|e| e.field().clone());
        assert_eq!(
            field(walk_limits(Some(0.0), 10, None)),
            Some(Field::Duration)
        );
        assert_eq!(
            field(walk_limits(Some(1e300), 10, None)),
            Some(Field::Duration)
        );
        assert_eq!(
            field(walk_limits(Some(f64::NAN), 10, None)),
            Some(Field::Duration)
        );
        assert_eq!(field(walk_limits(None, -1, None)), Some(Field::MaxSteps));
        assert_eq!(
            field(walk_limits(None, MAX_STEPS as i128 + 1, None)),
            Some(Field::MaxSteps)
        );
        assert_eq!(
            field(walk_limits(None, 1, Some(1.0))),
            Some(Field::UntilPeriodic)
        );
        assert_eq!(
            trajectory_dt(0.0).expect_err("zero").field(),
            &Field::TrajectoryDt
        );
        assert_eq!(max_frames(0).expect_err("zero").field(), &Field::MaxFrames);
    }

    #[test]
    fn the_bounds_themselves_are_accepted() {
        let l = walk_limits(Some(MAX_DURATION), MAX_STEPS as i128, Some(1e-9)).expect("valid");
        assert_eq!((l.max_steps, l.duration), (MAX_STEPS, MAX_DURATION));
        assert_eq!(
            walk_limits(None, 0, None).expect("valid").duration,
            f64::INFINITY
        );
    }

    #[test]
    fn a_count_that_is_not_a_whole_number_states_the_range() {
        let e = count_text(Field::MaxSteps, "1e30", 0, MAX_STEPS).expect_err("not whole");
        assert_eq!(
            e.to_string(),
            "max_steps: \"1e30\": must be a whole number in [0, 1000000]"
        );
        assert_eq!(count_text(Field::MaxSteps, " 7 ", 0, 10), Ok(7));
        assert!(count_text(Field::MaxSteps, "-0", 0, 10).is_err());
    }

    #[test]
    fn a_trajectory_of_more_samples_than_the_bound_is_refused_before_any_work() {
        let e = trajectory(Some(100.0), 1e-6, 10).expect_err("1e8 samples");
        assert_eq!(e.field(), &Field::TrajectoryDt);
        assert!(e.to_string().contains("at most 1000000"), "{e}");
        assert_eq!(trajectory(Some(100.0), 1e-3, 10), Ok((1e-3, 10)));
        // Without a duration the walk's steps end it; the samples are cut at `max_frames`.
        assert_eq!(trajectory(None, 1e-9, 5), Ok((1e-9, 5)));
    }
}
