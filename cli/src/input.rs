//! Input errors of the command line: which argument was wrong and what is accepted (exit
//! code 2). Parameter errors of the library ([`walker::setup::SetupError`]) are named here by
//! the flag a user typed (`--t-set` for `T_set`).

use walker::setup::SetupError;
use walker_scene::Param;

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

/// The flag (without `--`) that sets `param`, or the parameter's scene name where no flag
/// does.
#[must_use]
pub fn flag(param: Param) -> &'static str {
    match param {
        Param::TSet => "t-set",
        other => other.name(),
    }
}

impl From<SetupError> for InputError {
    /// Named by the flag of the parameter the error is about, else `scene`.
    fn from(e: SetupError) -> Self {
        if let SetupError::OutOfRange { param, value } = e {
            return InputError::out_of_range(flag(param), value, param.valid_range());
        }
        InputError::new(e.param().map_or("scene", flag), e.to_string())
    }
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
