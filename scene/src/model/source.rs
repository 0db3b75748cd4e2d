//! Byte offsets of a model file to 1-based lines and columns, and the offset of an expression
//! string's text inside the file (exact for plain strings, the opening quote otherwise).

use crate::model::error::Location;

/// The text of a model file with its line starts.
pub(crate) struct SourceMap<'a> {
    text: &'a str,
    line_starts: Vec<usize>,
}

impl<'a> SourceMap<'a> {
    pub(crate) fn new(text: &'a str) -> SourceMap<'a> {
        let mut line_starts = vec![0];
        line_starts.extend(text.match_indices('\n').map(|(i, _)| i + 1));
        SourceMap { text, line_starts }
    }

    /// The location of byte `offset` (clamped into the text and onto a character boundary).
    pub(crate) fn location(&self, offset: usize) -> Location {
        let mut offset = offset.min(self.text.len());
        while !self.text.is_char_boundary(offset) {
            offset -= 1;
        }
        let line = self.line_starts.partition_point(|&s| s <= offset);
        let start = self
            .line_starts
            .get(line.saturating_sub(1))
            .copied()
            .unwrap_or(0);
        let column = self.text[start..offset].chars().count() + 1;
        Location { line, column }
    }

    /// Where the value of a string spanning `span` (quotes included) starts, and whether its
    /// characters stand in the file exactly as in the value (no escapes, one line), so that a
    /// column inside the value is that start plus the offset.
    pub(crate) fn string_start(
        &self,
        span: std::ops::Range<usize>,
        value: &str,
    ) -> (Location, bool) {
        let raw = self.text.get(span.clone()).unwrap_or("");
        let single = (raw.starts_with('"') && !raw.starts_with("\"\"\""))
            || (raw.starts_with('\'') && !raw.starts_with("'''"));
        if single && raw.len() >= 2 && raw.get(1..raw.len() - 1) == Some(value) {
            (self.location(span.start + 1), true)
        } else {
            (self.location(span.start), false)
        }
    }
}
