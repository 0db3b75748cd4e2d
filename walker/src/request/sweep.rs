//! The range of a sweep and its chains: `from`, `to` and `step` make the grid
//! ([`crate::sweep::mu0_grid`]), counted against [`MAX_SWEEP_POINTS`] before it is made; the
//! chains are at most [`MAX_SWEEP_CHAINS`].

use crate::sweep::mu0_grid;

use super::error::RequestError;
use super::field::Field;
use super::limits::{at_most, values_in};
use super::shown;

/// The most chains a sweep may have: without a restart each chain runs on its own thread.
pub const MAX_SWEEP_CHAINS: usize = 64;

/// The most points a sweep may have in all (chains times swept values): each is a walk, and
/// its outcome is kept.
pub const MAX_SWEEP_POINTS: usize = 100_000;

/// The swept values: `from, from + step, ..` up to `to`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepRange {
    /// The first value.
    pub from: f64,
    /// The last value (inclusive within rounding).
    pub to: f64,
    /// The increment.
    pub step: f64,
}

impl SweepRange {
    /// How many values the range has (`mu0_grid`'s count, as a float: it may be huge or
    /// infinite before it is checked).
    #[must_use]
    pub fn values(&self) -> f64 {
        values_in(self.to - self.from, self.step)
    }

    /// The grid of the range for `chains` chains, checked: `from` finite, `to` finite and
    /// `>= from`, `step` finite and `> 0`, at most [`MAX_SWEEP_CHAINS`] chains (`chain` is
    /// the field that gives them) and [`MAX_SWEEP_POINTS`] points in all. Nothing is allocated
    /// before the count is checked.
    ///
    /// # Errors
    /// The first of these that does not hold, naming its field.
    pub fn grid(&self, chains: usize, chain: Field) -> Result<Vec<f64>, RequestError> {
        let SweepRange { from, to, step } = *self;
        if !from.is_finite() {
            return Err(RequestError::out_of_range(Field::From, from, "finite"));
        }
        if !(to.is_finite() && to >= from) {
            return Err(RequestError::out_of_range(
                Field::To,
                to,
                format!("finite and >= the first value, {}", shown::number(from)),
            ));
        }
        if !(step.is_finite() && step > 0.0) {
            return Err(RequestError::out_of_range(
                Field::Step,
                step,
                "finite and > 0",
            ));
        }
        at_most(chain, "chains", chains as f64, MAX_SWEEP_CHAINS)?;
        at_most(
            Field::Step,
            "points in all (values times chains)",
            self.values() * chains.max(1) as f64,
            MAX_SWEEP_POINTS,
        )?;
        Ok(mu0_grid(from, to, step))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn range(from: f64, to: f64, step: f64) -> SweepRange {
        SweepRange { from, to, step }
    }

    #[test]
    fn the_grid_of_a_valid_range_is_mu0_grids() {
        let g = range(0.0, 1.0, 0.25).grid(1, Field::Role(super::super::Role::TSet));
        assert_eq!(g, Ok(mu0_grid(0.0, 1.0, 0.25)));
    }

    #[test]
    fn bad_ranges_name_from_to_or_step() {
        let chain = Field::Role(super::super::Role::TSet);
        let field = |r: SweepRange| r.grid(1, chain.clone()).expect_err("bad").field().clone();
        assert_eq!(field(range(f64::NAN, 1.0, 0.1)), Field::From);
        assert_eq!(field(range(1.0, 0.0, 0.1)), Field::To);
        assert_eq!(field(range(0.0, f64::INFINITY, 0.1)), Field::To);
        assert_eq!(field(range(0.0, 1.0, 0.0)), Field::Step);
        assert_eq!(field(range(0.0, 1.0, -0.1)), Field::Step);
        // 10^9 values, or 10^308 / 5e-324 (infinite): counted, not made.
        assert_eq!(field(range(0.0, 1.0, 1e-9)), Field::Step);
        assert_eq!(field(range(0.0, 1e308, 5e-324)), Field::Step);
    }

    #[test]
    fn chains_count_towards_the_points_and_are_bounded_themselves() {
        let chain = Field::Role(super::super::Role::TSet);
        // 10^4 + 1 values alone are within the bound; twenty chains of them are not.
        assert!(range(0.0, 1.0, 1e-4).grid(1, chain.clone()).is_ok());
        let e = range(0.0, 1.0, 1e-4)
            .grid(20, chain.clone())
            .expect_err("too many");
        assert_eq!(e.field(), &Field::Step);
        let e = range(0.0, 1.0, 0.5).grid(MAX_SWEEP_CHAINS + 1, chain.clone());
        assert_eq!(e.expect_err("too many").field(), &chain);
    }
}
