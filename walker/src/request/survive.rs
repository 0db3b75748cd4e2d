//! The checks of a batch of walks on a floor (`survive`): how many walks, how many steps each,
//! and the floor's inputs that cannot be given together.

use super::error::RequestError;
use super::field::{Field, Role};
use super::limits::{MAX_STEPS, count};

/// The most walks of a batch (`walks`): each walk's outcome is kept (a few dozen bytes).
pub const MAX_WALKS: usize = 100_000;

/// The most steps of a batch in all (walks times `max_steps`): about three hours of the
/// paper's walker on one core (100 us a step), so a mistyped count is refused, not run.
pub const MAX_SURVIVE_STEPS: u64 = 100_000_000;

/// The number of walks in `[1, MAX_WALKS]` and the step limit of each in `[1, MAX_STEPS]`,
/// with at most [`MAX_SURVIVE_STEPS`] steps in all.
///
/// # Errors
/// A count outside its range ([`Field::Walks`], [`Field::MaxSteps`]), or too many steps in all
/// (named as [`Field::Walks`]).
pub fn survive_counts(walks: i128, max_steps: i128) -> Result<(usize, usize), RequestError> {
    let walks = count(Field::Walks, walks, 1, MAX_WALKS)?;
    let steps = count(Field::MaxSteps, max_steps, 1, MAX_STEPS)?;
    let total = walks as u64 * steps as u64;
    if total > MAX_SURVIVE_STEPS {
        return Err(RequestError::TooLarge {
            field: Field::Walks,
            what: "steps in all (walks times max_steps)",
            count: total as f64,
            limit: MAX_SURVIVE_STEPS,
        });
    }
    Ok((walks, steps))
}

/// The largest index a walk of a batch may have: the largest seed, `2^63 - 1`, so that a
/// walk's index is a whole number in the same range wherever it is written (JSON, Python).
pub const MAX_WALK_INDEX: u64 = i64::MAX as u64;

/// The walks of a batch that starts at walk `first_walk` and has `walks` walks (already
/// checked by [`survive_counts`]): `first_walk` in `[0, MAX_WALK_INDEX + 1 - walks]`, so that
/// the last walk's index is at most [`MAX_WALK_INDEX`].
///
/// # Errors
/// `first_walk` outside its range ([`Field::FirstWalk`]).
pub fn walk_range(first_walk: i128, walks: usize) -> Result<std::ops::Range<u64>, RequestError> {
    let high = MAX_WALK_INDEX + 1 - (walks as u64).min(MAX_WALK_INDEX);
    let first = count(Field::FirstWalk, first_walk, 0, high as usize)? as u64;
    Ok(first..first + walks as u64)
}

/// Checks that a floor is given one way: a floor file (`floor`), a list of `mu0` per step
/// (`mu0_steps`), and a uniform `mu0` (by its role) are exclusive, since each sets `mu0`.
///
/// # Errors
/// Two of them are given ([`RequestError::Conflict`], naming the later in this order).
pub fn floor_once(floor: bool, mu0_steps: bool, mu0: bool) -> Result<(), RequestError> {
    let why = "each sets mu0; give one";
    if floor && mu0_steps {
        return Err(RequestError::Conflict {
            field: Field::Mu0Steps,
            other: Field::Floor,
            why,
        });
    }
    if (floor || mu0_steps) && mu0 {
        return Err(RequestError::Conflict {
            field: Field::Role(Role::Mu0),
            other: if floor { Field::Floor } else { Field::Mu0Steps },
            why,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_are_refused_outside_their_ranges_and_in_all() {
        assert_eq!(survive_counts(10, 100), Ok((10, 100)));
        for (walks, steps, field) in [
            (0, 100, Field::Walks),
            (-1, 100, Field::Walks),
            (100_001, 1, Field::Walks),
            (10, 0, Field::MaxSteps),
            (10, 1_000_001, Field::MaxSteps),
            (100_000, 1001, Field::Walks),
        ] {
            let e = survive_counts(walks, steps).expect_err("out of range");
            assert_eq!(e.field(), &field, "{e}");
        }
        let e = survive_counts(100_000, 1001).expect_err("too many steps");
        assert!(e.to_string().contains("at most 100000000"), "{e}");
    }

    #[test]
    fn a_walk_range_starts_at_first_walk_and_ends_at_the_largest_index() {
        assert_eq!(walk_range(0, 10), Ok(0..10));
        assert_eq!(walk_range(30, 10), Ok(30..40));
        let last = i128::from(MAX_WALK_INDEX);
        assert_eq!(walk_range(last, 1), Ok(MAX_WALK_INDEX..MAX_WALK_INDEX + 1));
        for (first, walks) in [(-1, 1), (last, 2), (last + 1, 1), (i128::MAX, 1)] {
            let e = walk_range(first, walks).expect_err("out of range");
            assert_eq!(e.field(), &Field::FirstWalk, "{e}");
            assert!(e.to_string().contains("first_walk"), "{e}");
        }
    }

    #[test]
    fn a_floor_is_given_one_way() {
        assert_eq!(floor_once(true, false, false), Ok(()));
        assert_eq!(floor_once(false, true, false), Ok(()));
        assert_eq!(floor_once(false, false, true), Ok(()));
        let e = floor_once(true, true, false).expect_err("both");
        assert_eq!(e.field(), &Field::Mu0Steps);
        assert!(e.to_string().contains("cannot be given with floor"), "{e}");
        let e = floor_once(false, true, true).expect_err("both");
        assert_eq!(e.field(), &Field::Role(Role::Mu0));
    }
}
