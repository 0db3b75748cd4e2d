//! The limits every model file is checked against when it is loaded, before any derivation:
//! each bounds what a file can cost or is a capacity of a structure downstream, so that a file
//! beyond one gets a clear error naming the place instead of a long run or a silent cut.
//! `docs/model-format.md` ("Limits and checks") states each with its measured cost.

/// The longest model or scene file read, in bytes (1 MiB). The largest shipped model has 11 kB;
/// the bound keeps a device, a runaway generator or a mistaken path from being read into
/// memory.
pub const MAX_FILE_BYTES: u64 = 1 << 20;

/// The most coordinates (`[[coordinate]]`, the foot's `x` and `z` included): the simulator
/// holds the state `[q, qd]` in fixed arrays of `2 * MAX_COORDINATES` numbers, and the
/// derivation's cost grows steeply with the coordinates (RABBIT's seven derive in about
/// 0.01 s; a chain of 152 ran for more than 20 s before this check).
pub const MAX_COORDINATES: usize = 8;

/// The most bodies (`[[body]]`): each adds its energy's terms to every entry of `M(q)`; the
/// largest shipped model has five.
pub const MAX_BODIES: usize = 32;

/// The most named points (`[[point]]`): the simulator's strike test evaluates every point into
/// a fixed array of `2 * MAX_POINTS` numbers (a model with more walked no step before this
/// check).
pub const MAX_POINTS: usize = 32;

/// The most falls (`[[fall]]`): the simulator's stance watches the strike and every fall in an
/// event table of `1 + MAX_FALLS` entries (the falls past it were not watched before this
/// check).
pub const MAX_FALLS: usize = 2 * MAX_COORDINATES;

/// The most inputs (`[[input]]`), and so outputs: the controller's `A` (Eq. 30) is inverted by
/// its adjugate, derived for at most a 4 x 4 matrix.
pub const MAX_INPUTS: usize = 4;

/// The most impact locks (`[impact] locks`): each is a row of the impact's constraint
/// Jacobian, held by the simulator with the coordinates' rows in fixed arrays; more locks than
/// angles over-determine the impact anyway.
pub const MAX_LOCKS: usize = MAX_COORDINATES;

/// The most parameters (`[[parameter]]`): each is a field of the generated `Params` and a
/// symbol of every polynomial; the largest shipped model has 21.
pub const MAX_PARAMETERS: usize = 256;

/// The most significant digits of a number literal in an expression: the derivation keeps
/// numbers exact, and its cost grows with their digits (a 5000-digit literal took over 20 s).
/// Forty digits are more than twice what an `f64` holds.
pub const MAX_NUMBER_DIGITS: usize = 40;

/// The largest power of ten of a number literal's value, either way (`1e300`, `1e-300`): an
/// `f64` holds about `1e-308` to `1e308`, and an exact number beyond costs the derivation its
/// digits as [`MAX_NUMBER_DIGITS`] does.
pub const MAX_NUMBER_EXPONENT: i64 = 330;

/// The longest name (a coordinate, parameter, body, point, fall, input or output), in
/// characters: names are identifiers of the generated code and appear in every message.
pub const MAX_NAME_CHARS: usize = 64;

/// The longest piece of a file echoed in an error message, in characters; longer text is cut
/// with its length noted (a megabyte name is not printed whole).
pub const MAX_ECHO_CHARS: usize = 80;

/// `text` as an error message shows it: control characters and quotes escaped
/// (`escape_debug`), cut to [`MAX_ECHO_CHARS`] characters with its length noted.
#[must_use]
pub fn echo(text: &str) -> String {
    echo_at_most(text, MAX_ECHO_CHARS)
}

/// [`echo`] with a bound of `max` characters (for a parser's message, which quotes the file).
#[must_use]
pub fn echo_at_most(text: &str, max: usize) -> String {
    let escaped: String = text.chars().flat_map(char::escape_debug).collect();
    if escaped.chars().count() <= max {
        return escaped;
    }
    let cut: String = escaped.chars().take(max).collect();
    format!("{cut}... ({} bytes in all)", text.len())
}
