//! Input errors of the command line: which argument was wrong and what is accepted (exit
//! code 2). The library checks what a request may ask ([`walker::request`]) and names the
//! field in its own words; its errors ([`RequestError`], [`walker::setup::SetupError`]) are
//! named here by the flag a user typed (`--t-set` for `T_set`, `--max-steps` for
//! `max_steps`). A user's text is echoed at most [`walker::request::shown::MAX_ECHO`]
//! characters long with control characters escaped.

use walker::model::{NoKernels, ParamError};
use walker::request::shown;
use walker::request::{Field, RequestError, Role};
use walker::setup::SetupError;

/// A user error: which input was wrong and what is accepted (exit code 2).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("invalid {field}: {message}")]
pub struct InputError {
    /// The flag or scene field.
    pub field: String,
    /// What is valid.
    pub message: String,
}

impl InputError {
    /// An error about `field`.
    pub fn new(field: &str, message: impl Into<String>) -> Self {
        InputError {
            field: field.to_owned(),
            message: message.into(),
        }
    }

    /// `value` of `field` is outside its valid range, `must_be` in words (`"in (0, 1)"`,
    /// `"finite and > 0"`).
    pub fn out_of_range(field: &str, value: f64, must_be: &str) -> Self {
        InputError::new(
            field,
            format!("{}: must be {must_be}", shown::number(value)),
        )
    }
}

/// The flag (without `--`) of a field of the library's requests: `max-steps` for
/// `max_steps`, `t-set` for the role `T_set`, `set` for a parameter given by name, `init` for
/// a component of the start.
#[must_use]
pub fn flag_of(field: &Field) -> String {
    match field {
        Field::Method => "method".into(),
        Field::Friction => "friction".into(),
        Field::Impact => "impact".into(),
        Field::Rtol => "rtol".into(),
        Field::Atol => "atol".into(),
        Field::MaxSteps => "max-steps".into(),
        Field::Duration => "duration".into(),
        Field::UntilPeriodic => "until-periodic".into(),
        Field::TrajectoryDt => "trajectory-dt".into(),
        Field::MaxFrames => "max-frames".into(),
        Field::Walks => "walks".into(),
        Field::FirstWalk => "first-walk".into(),
        Field::Floor => "floor".into(),
        Field::Mu0Steps => "mu0-steps".into(),
        Field::From => "from".into(),
        Field::To => "to".into(),
        Field::Step => "step".into(),
        Field::Param => "param".into(),
        Field::Role(Role::Mu0) => "mu0".into(),
        Field::Role(Role::C) => "c".into(),
        Field::Role(Role::TSet) => "t-set".into(),
        Field::Role(Role::Slope) => "phi".into(),
        Field::StartParameter(name) if name == "omega0" => "omega0".into(),
        Field::Parameter(_) | Field::StartParameter(_) => "set".into(),
        Field::Init(_) => "init".into(),
    }
}

/// A field as a message mentions it, the way a user typed it: `--t-set`, `--set T_set=..`,
/// `--init th1d=..`.
#[must_use]
pub fn mention(field: &Field) -> String {
    match field {
        Field::Parameter(name) => format!("--set {}=..", shown::name(name)),
        Field::Init(name) => format!("--init {}=..", shown::name(name)),
        other => format!("--{}", flag_of(other)),
    }
}

impl From<RequestError> for InputError {
    /// Named by the flag of the field, the other fields it mentions by theirs.
    fn from(e: RequestError) -> Self {
        InputError::new(&flag_of(e.field()), e.detail(&mention))
    }
}

/// A whole number given as the flag `field` (text: `1e30`, `-1` and `1.5` are refused with
/// the range, not left to the parser) in `[low, high]`.
///
/// # Errors
/// Not a whole number, or outside the range.
pub fn whole(field: &str, text: &str, low: usize, high: usize) -> Result<usize, InputError> {
    walker::request::count_text(Field::MaxSteps, text, low, high)
        .map_err(|e| InputError::new(field, e.detail(&mention)))
}

/// The flag (without `--`) that sets the parameter called `name`, or the name itself where no
/// flag does (it is set with `--set NAME=VALUE`).
#[must_use]
pub fn flag(name: &str) -> &str {
    match name {
        "T_set" => "t-set",
        other => other,
    }
}

impl From<ParamError> for InputError {
    /// Named by the flag of the parameter, with its valid range.
    fn from(e: ParamError) -> Self {
        match &e {
            ParamError::OutOfRange { name, value, range } => {
                InputError::out_of_range(flag(name), *value, &format!("in {range}"))
            }
            // Only a name given as it is can be unknown (a role the model lacks is a
            // `SetupError::NoRole`): a sweep's chains by `--t-set` (`T_set`) or `--phi`, any
            // other by `--set NAME=..`.
            ParamError::Unknown { name, .. } => {
                let field = match name.as_str() {
                    "T_set" => "t-set",
                    "phi" => "phi",
                    _ => "set",
                };
                InputError::new(field, e.to_string())
            }
        }
    }
}

impl From<SetupError> for InputError {
    /// Named by the flag of the parameter the error is about, else `scene` (`model` for a
    /// model file's own errors).
    fn from(e: SetupError) -> Self {
        match e {
            SetupError::Param(p) => p.into(),
            SetupError::Request(r) => r.into(),
            SetupError::Model(_) | SetupError::Spec(_) | SetupError::NotCompiled { .. } => {
                InputError::new("model", e.to_string())
            }
            other => InputError::new(other.param().map_or("scene", flag), other.to_string()),
        }
    }
}

impl From<NoKernels> for InputError {
    /// Named `friction` (the law that has no kernels) or `model`.
    fn from(e: NoKernels) -> Self {
        let field = match e {
            NoKernels::FrictionLaw { .. } | NoKernels::NotCompiled { .. } => "friction",
            NoKernels::Source { .. } | NoKernels::Missing { .. } => "model",
        };
        InputError::new(field, e.to_string())
    }
}

/// `NAME=VALUE` pairs given as the flag `field`, the values numbers.
///
/// # Errors
/// A pair without `=`, an empty name, or a value that is not a number.
pub fn assignments(field: &str, pairs: &[String]) -> Result<Vec<(String, f64)>, InputError> {
    pairs
        .iter()
        .map(|s| {
            let malformed =
                || InputError::new(field, format!("{}: expected NAME=VALUE", shown::text(s)));
            let (name, value) = s.split_once('=').ok_or_else(malformed)?;
            let name = name.trim();
            if name.is_empty() {
                return Err(malformed());
            }
            let v: f64 = value.trim().parse().map_err(|_| {
                InputError::new(
                    field,
                    format!(
                        "{}: the value of {} is not a number",
                        shown::text(s),
                        shown::name(name)
                    ),
                )
            })?;
            Ok((name.to_owned(), v))
        })
        .collect()
}

/// `x` given as `field` if it is finite and `ok`; else an error naming `field` and what it
/// must be.
///
/// # Errors
/// `x` is not finite or not `ok`.
pub fn check(field: &str, x: f64, ok: bool, must_be: &str) -> Result<f64, InputError> {
    if x.is_finite() && ok {
        Ok(x)
    } else {
        Err(InputError::out_of_range(field, x, must_be))
    }
}

/// A relative or absolute tolerance given as the flag `field`: in (0, 1).
///
/// # Errors
/// Outside (0, 1).
pub fn tolerance(field: &str, x: f64) -> Result<f64, InputError> {
    check(field, x, x > 0.0 && x < 1.0, "in (0, 1)")
}

/// A duration given as the flag `field`: finite and > 0.
///
/// # Errors
/// Not finite or not positive.
pub fn duration(field: &str, x: f64) -> Result<f64, InputError> {
    check(field, x, x > 0.0, "finite and > 0")
}

/// Parsers of the command line's number flags for clap: each reads a number as clap's own
/// `f64` parser does (`f64`'s `FromStr`: `1e-3`, `inf`, `NaN` are numbers), and refuses text
/// that is not a number with the flag's valid range (clap names the flag; exit code 2). The
/// range itself is checked after parsing, by the library ([`walker::request`]) or the command,
/// where a number out of it is named with the same words.
pub mod number {
    /// `text` as a number; else why not, with `range` (what the flag accepts).
    fn parse(text: &str, range: &str) -> Result<f64, String> {
        text.parse::<f64>()
            .map_err(|_| format!("not a number; expected {range}"))
    }

    macro_rules! parsers {
        ($($(#[$doc:meta])* $name:ident => $range:expr;)*) => {$(
            $(#[$doc])*
            ///
            /// # Errors
            /// `text` is not a number (the message states the range).
            pub fn $name(text: &str) -> Result<f64, String> {
                parse(text, $range)
            }
        )*};
    }

    parsers! {
        /// A friction coefficient (`--mu0`).
        mu0 => "a number >= 0";
        /// A positive number (`--c`, `--t-set`, `--step`).
        positive => "a number > 0";
        /// A relative tolerance (`--rtol`).
        rtol => "a number in [2.2e-15, 1)";
        /// An absolute tolerance (`--atol`).
        atol => "a number in [2.2e-308, 1)";
        /// A start parameter (`--omega0`).
        finite => "a finite number";
        /// A slope angle in radians (`--phi`).
        slope => "a number in [0, pi/2) (radians)";
        /// The length of a walk (`--duration` of `simulate` and `sweep`).
        duration => "a number in (0, 1e9] (seconds)";
        /// The periodic-gait tolerance (`--until-periodic`).
        fraction => "a number in (0, 1)";
        /// A value of a parameter's range (`--from`, `--to`, `--at`).
        value => "a finite number within the parameter's range";
        /// The length of an animated walk (`animate --duration`).
        animate_duration => "a number in (0, 600] (seconds)";
        /// The playback speed (`--speed`).
        speed => "a number in [0.01, 100]";
        /// Frames per second (`--fps`).
        fps => "a number in [1, 50]";
        /// The continuation's largest step (`--max-step`).
        max_step => "a number in (0, 1]";
    }

    #[cfg(test)]
    mod tests {
        #[test]
        fn a_number_parses_as_clap_parses_it_and_text_names_the_range() {
            assert_eq!(super::mu0("0.3"), Ok(0.3));
            assert_eq!(super::mu0("-1e3"), Ok(-1000.0));
            assert!(super::mu0("inf").is_ok_and(f64::is_infinite));
            assert_eq!(
                super::mu0("abc"),
                Err("not a number; expected a number >= 0".to_owned())
            );
            assert!(super::speed("").is_err_and(|e| e.contains("[0.01, 100]")));
        }
    }
}
