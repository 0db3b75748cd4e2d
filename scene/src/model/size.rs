//! The model's size checked first, on the file's layout before anything is built: the number
//! of coordinates, parameters, bodies, points, falls, inputs, outputs and impact locks against
//! the [`limits`](crate::limits), each refusal at the first entry past its limit.

use toml::Spanned;

use crate::limits::{
    MAX_BODIES, MAX_COORDINATES, MAX_FALLS, MAX_INPUTS, MAX_LOCKS, MAX_PARAMETERS, MAX_POINTS,
};
use crate::model::error::{ModelError, ModelErrorKind};
use crate::model::load::Loader;
use crate::model::raw::RawModel;

/// One list's check: its name, its length, its limit, the span of its first entry past the
/// limit, and why the limit is there.
struct ListSize<'a> {
    what: &'a str,
    count: usize,
    max: usize,
    past: Option<std::ops::Range<usize>>,
    why: &'a str,
}

/// The check of `list`, named `what`, against `max` (length and span from the same list).
fn list<'a, T>(what: &'a str, list: &[Spanned<T>], max: usize, why: &'a str) -> ListSize<'a> {
    ListSize {
        what,
        count: list.len(),
        max,
        past: list.get(max).map(Spanned::span),
        why,
    }
}

impl Loader<'_> {
    /// Refuses a model with more entries in a list than its limit allows, at the first entry
    /// past the limit.
    pub(crate) fn check_size(&self, raw: &RawModel) -> Result<(), ModelError> {
        let locks = raw
            .impact
            .as_ref()
            .map_or(&[][..], |i| i.get_ref().locks.as_slice());
        let lists = [
            list(
                "[[coordinate]]",
                raw.coordinate.get_ref(),
                MAX_COORDINATES,
                "the simulator's state holds at most that many",
            ),
            list(
                "[[parameter]]",
                &raw.parameter,
                MAX_PARAMETERS,
                "each is a symbol of every derived polynomial",
            ),
            list(
                "[[body]]",
                raw.body.get_ref(),
                MAX_BODIES,
                "each adds its energy to every entry of the mass matrix",
            ),
            list(
                "[[point]]",
                &raw.point,
                MAX_POINTS,
                "the simulator's strike test holds at most that many",
            ),
            list(
                "[[fall]]",
                &raw.fall,
                MAX_FALLS,
                "the simulator's event table watches at most that many",
            ),
            list(
                "[[input]]",
                &raw.input,
                MAX_INPUTS,
                "the controller's A is inverted by its adjugate, derived up to 4 x 4",
            ),
            list(
                "[[output]]",
                &raw.output,
                MAX_INPUTS,
                "there are as many outputs as inputs",
            ),
            list(
                "[impact] locks",
                locks,
                MAX_LOCKS,
                "each is a row of the impact's constraints, held in fixed arrays",
            ),
        ];
        for ListSize {
            what,
            count,
            max,
            past,
            why,
        } in lists
        {
            if count > max {
                return Err(self.error(
                    past.unwrap_or(0..0),
                    ModelErrorKind::Limit,
                    format!("{count} {what}: expected at most {max} ({why})"),
                ));
            }
        }
        Ok(())
    }
}
