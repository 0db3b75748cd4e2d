//! Input errors of the command line: which argument was wrong and what is accepted (exit
//! code 2). Parameter errors of the library ([`walker::setup::SetupError`]) are named here by
//! the flag a user typed (`--t-set` for `T_set`).

use walker::model::{NoKernels, ParamError};
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
        InputError::new(field, format!("{value}: must be {must_be}"))
    }
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
            ParamError::Unknown { name, .. } => InputError::new(flag(name), e.to_string()),
        }
    }
}

impl From<SetupError> for InputError {
    /// Named by the flag of the parameter the error is about, else `scene` (`model` for a
    /// model file's own errors).
    fn from(e: SetupError) -> Self {
        match e {
            SetupError::Param(p) => p.into(),
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
            let (name, value) = s
                .split_once('=')
                .ok_or_else(|| InputError::new(field, format!("{s:?}: expected NAME=VALUE")))?;
            let name = name.trim();
            if name.is_empty() {
                return Err(InputError::new(
                    field,
                    format!("{s:?}: expected NAME=VALUE"),
                ));
            }
            let v: f64 = value.trim().parse().map_err(|_| {
                InputError::new(field, format!("{s:?}: the value of {name} is not a number"))
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
