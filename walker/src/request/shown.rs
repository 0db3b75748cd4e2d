//! How a request's error echoes what a user gave: a name or text at most [`MAX_ECHO`]
//! characters long with control characters escaped, a number short (`1e300`, not its 301
//! digits). A megabyte argument is not echoed whole.

/// The most characters of a user's text an error echoes.
pub const MAX_ECHO: usize = 80;

/// `s` quoted as Rust's `{:?}` quotes it (control characters and quotes escaped), cut to
/// [`MAX_ECHO`] characters of `s` with `...` and the full length when longer.
#[must_use]
pub fn text(s: &str) -> String {
    let count = s.chars().count();
    if count <= MAX_ECHO {
        return format!("{s:?}");
    }
    let head: String = s.chars().take(MAX_ECHO).collect();
    format!("{head:?}... ({count} characters)")
}

/// `s` as a name in a message: as given when it is short and printable (a parameter's name),
/// else as [`text`] quotes it.
#[must_use]
pub fn name(s: &str) -> String {
    let plain = !s.is_empty()
        && s.chars().count() <= MAX_ECHO
        && s.chars()
            .all(|c| !c.is_control() && !c.is_whitespace() && c != '"');
    if plain { s.to_owned() } else { text(s) }
}

/// `x` as a message shows it: Rust's shortest round-trip decimal (`0.3`, `-1`, `NaN`, `inf`)
/// where that is at most 24 characters, else in exponent form (`1e300`, `5e-324`).
#[must_use]
pub fn number(x: f64) -> String {
    let plain = x.to_string();
    if plain.len() <= 24 {
        plain
    } else {
        format!("{x:e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_megabyte_of_text_is_echoed_as_its_first_80_characters_and_its_length() {
        let s = "x".repeat(1 << 20);
        let shown = text(&s);
        assert!(shown.len() < 120, "{shown}");
        assert!(shown.contains("1048576 characters"), "{shown}");
    }

    #[test]
    fn control_characters_are_escaped_not_printed() {
        assert_eq!(text("a\u{1b}[2Jb\n"), "\"a\\u{1b}[2Jb\\n\"");
        assert_eq!(name("T\nset"), "\"T\\nset\"");
        assert_eq!(name("T_set"), "T_set");
    }

    #[test]
    fn huge_and_tiny_numbers_are_shown_in_exponent_form() {
        assert_eq!(number(1e300), "1e300");
        assert_eq!(number(5e-324), "5e-324");
        assert_eq!(number(0.3), "0.3");
        assert_eq!(number(-1.0), "-1");
        assert_eq!(number(f64::NAN), "NaN");
        assert_eq!(number(f64::INFINITY), "inf");
    }
}
