//! [`RequestError`]: why a request is refused, naming the [`Field`] in the library's words and
//! what it accepts. A front end names the fields its own way with [`RequestError::detail`].

use std::fmt;

use super::field::Field;
use super::shown;

/// Why a request is refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RequestError {
    /// A number outside its valid range (NaN and infinities are outside every range).
    #[error("{field}: {}", self.detail(&|f: &Field| f.name()))]
    OutOfRange {
        /// The input.
        field: Field,
        /// The value given.
        value: f64,
        /// What it must be, in words (`in (0, 1)`, `finite and > 0`).
        must_be: String,
    },
    /// A count that is not a whole number in its range.
    #[error("{field}: {}", self.detail(&|f: &Field| f.name()))]
    Count {
        /// The input.
        field: Field,
        /// The value given, as given (a whole number, or text that is not one).
        given: String,
        /// The smallest count accepted.
        low: u64,
        /// The largest count accepted.
        high: u64,
    },
    /// A name that is not one of the accepted names.
    #[error("{field}: {}", self.detail(&|f: &Field| f.name()))]
    UnknownName {
        /// The input.
        field: Field,
        /// The name given (echoed at most [`shown::MAX_ECHO`] characters).
        given: String,
        /// The accepted names, in words.
        expected: String,
    },
    /// The same parameter (or start component) given twice, under the same name or two names
    /// of it (`T_set` by its role and by its name).
    #[error("{second}: {}", self.detail(&|f: &Field| f.name()))]
    Repeated {
        /// The parameter's name in the model.
        parameter: String,
        /// Where it was given first.
        first: Field,
        /// Where it was given again (the field the error names).
        second: Field,
    },
    /// A request that would cost more than its bound (points of a sweep, its chains).
    #[error("{field}: {}", self.detail(&|f: &Field| f.name()))]
    TooLarge {
        /// The input that makes it too large.
        field: Field,
        /// What is counted (`points in all`, `chains`).
        what: &'static str,
        /// How many the request asks for (may be huge or infinite).
        count: f64,
        /// The most accepted.
        limit: u64,
    },
    /// A start whose stance foot is off the floor, or whose velocity leaves it.
    #[error("{field}: {}", self.detail(&|f: &Field| f.name()))]
    OffTheFloor {
        /// The start component that moved the foot.
        field: Field,
        /// The foot's `x` and `z` (or their velocities) by name, with their values.
        foot: [(String, f64); 2],
        /// Whether the velocity leaves the floor (else the position is off it).
        velocity: bool,
        /// Whether the floor is level (`z = 0`; else `z = -x tan(phi)`).
        level: bool,
    },
    /// Two inputs that cannot be given together.
    #[error("{field}: {}", self.detail(&|f: &Field| f.name()))]
    Conflict {
        /// The input named.
        field: Field,
        /// The input it conflicts with.
        other: Field,
        /// Why, in words.
        why: &'static str,
    },
}

impl RequestError {
    /// `value` of `field` is outside its range, `must_be` in words.
    #[must_use]
    pub fn out_of_range(field: Field, value: f64, must_be: impl Into<String>) -> Self {
        RequestError::OutOfRange {
            field,
            value,
            must_be: must_be.into(),
        }
    }

    /// The input the error is about.
    #[must_use]
    pub fn field(&self) -> &Field {
        match self {
            RequestError::OutOfRange { field, .. }
            | RequestError::Count { field, .. }
            | RequestError::UnknownName { field, .. }
            | RequestError::TooLarge { field, .. }
            | RequestError::OffTheFloor { field, .. }
            | RequestError::Conflict { field, .. } => field,
            RequestError::Repeated { second, .. } => second,
        }
    }

    /// What is wrong and what is accepted, without the field's own name; any other field it
    /// mentions is named by `names` (a front end's flag or keyword; the library's words are
    /// [`Field::name`]).
    #[must_use]
    pub fn detail(&self, names: &dyn Fn(&Field) -> String) -> String {
        match self {
            RequestError::OutOfRange { value, must_be, .. } => {
                format!("{}: must be {must_be}", shown::number(*value))
            }
            RequestError::Count {
                given, low, high, ..
            } => format!("{given}: must be a whole number in [{low}, {high}]"),
            RequestError::UnknownName {
                given, expected, ..
            } => format!("{}: must be {expected}", shown::text(given)),
            RequestError::Repeated {
                parameter, first, ..
            } => format!(
                "{} is given twice, also as {}; give it once",
                shown::name(parameter),
                names(first)
            ),
            RequestError::TooLarge {
                what, count, limit, ..
            } => format!("the request has {} {what}; at most {limit}", Approx(*count)),
            RequestError::OffTheFloor {
                foot: [(x, xv), (z, zv)],
                velocity,
                level,
                ..
            } => {
                let (x, z) = (shown::name(x), shown::name(z));
                let (xv, zv) = (shown::number(*xv), shown::number(*zv));
                if *velocity {
                    format!(
                        "the stance foot's velocity ({x} = {xv}, {z} = {zv}) must be along the floor"
                    )
                } else {
                    let floor = if *level {
                        "0".to_owned()
                    } else {
                        format!("-{x} tan(phi)")
                    };
                    format!(
                        "the stance foot ({x} = {xv}, {z} = {zv}) must be on the floor ({z} = {floor})"
                    )
                }
            }
            RequestError::Conflict { other, why, .. } => {
                format!("cannot be given with {}: {why}", names(other))
            }
        }
    }
}

/// A count shown exactly when it is a modest whole number, else as `1.000e12`.
struct Approx(f64);

impl fmt::Display for Approx {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.0.is_finite() && self.0 < 1e15 && self.0.fract() == 0.0 {
            write!(f, "{}", self.0)
        } else {
            write!(f, "{:.3e}", self.0)
        }
    }
}
