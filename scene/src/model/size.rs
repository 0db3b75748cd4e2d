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
type ListSize<'a> = (
    &'a str,
    usize,
    usize,
    Option<std::ops::Range<usize>>,
    &'a str,
);

/// The span of entry `i` of `list`, if it has one.
fn span_of<T>(list: &[Spanned<T>], i: usize) -> Option<std::ops::Range<usize>> {
    list.get(i).map(Spanned::span)
}

impl Loader<'_> {
    /// Refuses a model with more entries in a list than its limit allows, at the first entry
    /// past the limit.
    pub(crate) fn check_size(&self, raw: &RawModel) -> Result<(), ModelError> {
        let locks = raw
            .impact
            .as_ref()
            .map_or(&[][..], |i| i.get_ref().locks.as_slice());
        let lists: [ListSize<'_>; 8] = [
            (
                "[[coordinate]]",
                raw.coordinate.get_ref().len(),
                MAX_COORDINATES,
                span_of(raw.coordinate.get_ref(), MAX_COORDINATES),
                "the simulator's state holds at most that many",
            ),
            (
                "[[parameter]]",
                raw.parameter.len(),
                MAX_PARAMETERS,
                span_of(&raw.parameter, MAX_PARAMETERS),
                "each is a symbol of every derived polynomial",
            ),
            (
                "[[body]]",
                raw.body.get_ref().len(),
                MAX_BODIES,
                span_of(raw.body.get_ref(), MAX_BODIES),
                "each adds its energy to every entry of the mass matrix",
            ),
            (
                "[[point]]",
                raw.point.len(),
                MAX_POINTS,
                span_of(&raw.point, MAX_POINTS),
                "the simulator's strike test holds at most that many",
            ),
            (
                "[[fall]]",
                raw.fall.len(),
                MAX_FALLS,
                span_of(&raw.fall, MAX_FALLS),
                "the simulator's event table watches at most that many",
            ),
            (
                "[[input]]",
                raw.input.len(),
                MAX_INPUTS,
                span_of(&raw.input, MAX_INPUTS),
                "the controller's A is inverted by its adjugate, derived up to 4 x 4",
            ),
            (
                "[[output]]",
                raw.output.len(),
                MAX_INPUTS,
                span_of(&raw.output, MAX_INPUTS),
                "there are as many outputs as inputs",
            ),
            (
                "[impact] locks",
                locks.len(),
                MAX_LOCKS,
                locks.get(MAX_LOCKS).map(Spanned::span),
                "each is a row of the impact's constraints, held in fixed arrays",
            ),
        ];
        for (what, count, max, span, why) in lists {
            if count > max {
                return Err(self.error(
                    span.unwrap_or(0..0),
                    ModelErrorKind::Limit,
                    format!("{count} {what}: expected at most {max} ({why})"),
                ));
            }
        }
        Ok(())
    }
}
