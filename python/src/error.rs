//! Input errors of the Python module: which keyword argument was wrong and what it accepts.
//! They become `ValueError` at the boundary; the library's parameter errors
//! ([`walker::setup::SetupError`]) are named by the keyword that sets the parameter
//! (`t_set` for `T_set`) with the range of the parameter table (`walker_scene::Param`).

use pyo3::PyErr;
use pyo3::exceptions::PyValueError;
use walker::setup::SetupError;
use walker_scene::Param;

/// A bad argument: its keyword and what is valid.
#[derive(Debug, Clone, PartialEq)]
pub struct ArgError {
    /// The keyword argument (or grid column).
    pub arg: String,
    /// The rejected value and what is accepted.
    pub message: String,
}

impl std::fmt::Display for ArgError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "invalid {}: {}", self.arg, self.message)
    }
}

impl ArgError {
    /// An error about `arg`.
    pub fn new(arg: &str, message: impl Into<String>) -> Self {
        ArgError {
            arg: arg.to_owned(),
            message: message.into(),
        }
    }

    /// `value` of `arg` is outside its valid range, `must_be` in words.
    pub fn out_of_range(arg: &str, value: impl std::fmt::Display, must_be: &str) -> Self {
        ArgError::new(arg, format!("{value}: must be {must_be}"))
    }
}

impl From<ArgError> for PyErr {
    fn from(e: ArgError) -> PyErr {
        PyValueError::new_err(e.to_string())
    }
}

/// The keyword argument that sets `param` (`t_set` for `T_set`), else the parameter's scene
/// name.
#[must_use]
pub fn keyword(param: Param) -> &'static str {
    match param {
        Param::TSet => "t_set",
        other => other.name(),
    }
}

impl From<SetupError> for ArgError {
    /// Named by the keyword of the parameter the error is about, else `scene`.
    fn from(e: SetupError) -> Self {
        if let SetupError::OutOfRange { param, value } = e {
            return ArgError::out_of_range(keyword(param), value, param.valid_range());
        }
        ArgError::new(e.param().map_or("scene", keyword), e.to_string())
    }
}

/// `x` given as `arg` if it is finite and `ok`; else an error naming `arg` and what it must be.
///
/// # Errors
/// `x` is not finite or not `ok`.
pub fn check(arg: &str, x: f64, ok: bool, must_be: &str) -> Result<f64, ArgError> {
    if x.is_finite() && ok {
        Ok(x)
    } else {
        Err(ArgError::out_of_range(arg, x, must_be))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_parameter_out_of_range_is_named_by_its_keyword_with_the_tables_range() {
        let e = ArgError::from(SetupError::OutOfRange {
            param: Param::TSet,
            value: -1.0,
        });
        assert_eq!(e.arg, "t_set");
        assert!(e.message.contains(Param::TSet.valid_range()), "{e}");
    }

    #[test]
    fn a_slope_for_the_level_walker_is_named_phi() {
        assert_eq!(ArgError::from(SetupError::SlopeForLevelWalker).arg, "phi");
    }
}
