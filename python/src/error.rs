//! Input errors of the Python module: which keyword argument was wrong and what it accepts.
//! They become `ValueError` at the boundary. The library's parameter errors are named by the
//! keyword that sets the parameter (`t_set` for `T_set`) with the range its model file gives;
//! a model file's own errors are named `model`, those of a scene `scene`, as the command line
//! names them by its flags (`cli/src/input.rs`).

use pyo3::PyErr;
use pyo3::exceptions::PyValueError;
use walker::model::{NoKernels, ParamError};
use walker::request::{Field, RequestError, Role};
use walker::setup::SetupError;

/// A bad argument: its keyword and what is valid.
#[derive(Debug, Clone, PartialEq)]
pub struct ArgError {
    /// The keyword argument, a key of `set`/`init` (`set['K_P']`), or a grid column.
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
    /// A value whose decimal form is longer than [`ECHO`] (`-1e308`) is written with an
    /// exponent.
    pub fn out_of_range(arg: &str, value: impl std::fmt::Display, must_be: &str) -> Self {
        let mut text = value.to_string();
        if text.len() > ECHO {
            text = text
                .parse::<f64>()
                .map_or_else(|_| echo(&text), |x| format!("{x:e}"));
        }
        ArgError::new(arg, format!("{text}: must be {must_be}"))
    }

    /// The same error named `arg` instead (a grid column, a key of `set`).
    #[must_use]
    pub fn named(self, arg: &str) -> Self {
        ArgError {
            arg: arg.to_owned(),
            ..self
        }
    }
}

impl From<ArgError> for PyErr {
    fn from(e: ArgError) -> PyErr {
        PyValueError::new_err(e.to_string())
    }
}

/// The keyword argument that sets the parameter (or the library's flag name) `name`: `t_set`
/// for `T_set` (and the library's `t-set`), else the name itself (a parameter without a keyword
/// of its own is set with `set={name: value}`).
#[must_use]
pub fn keyword(name: &str) -> &str {
    match name {
        "T_set" | "t-set" => "t_set",
        other => other,
    }
}

/// The keyword argument (or key of `set`/`init`) that gives `field` of the library's
/// requests ([`walker::request`]): `t_set` for the role `T_set`, `dt` for the trajectory's
/// sampling, `from_` for the first value of a sweep, `set['K_P']` for a parameter given by
/// name, `init['th1d']` for a component of the start.
#[must_use]
pub fn keyword_of(field: &Field) -> String {
    match field {
        Field::Method => "method".into(),
        Field::Friction => "friction".into(),
        Field::Impact => "impact".into(),
        Field::Rtol => "rtol".into(),
        Field::Atol => "atol".into(),
        Field::MaxSteps => "max_steps".into(),
        Field::Duration => "duration".into(),
        Field::UntilPeriodic => "until_periodic".into(),
        Field::TrajectoryDt => "dt".into(),
        Field::MaxFrames => "max_frames".into(),
        Field::Walks => "walks".into(),
        Field::FirstWalk => "first_walk".into(),
        Field::Floor => "floor".into(),
        Field::Mu0Steps => "mu0_steps".into(),
        Field::From => "from_".into(),
        Field::To => "to".into(),
        Field::Step => "step".into(),
        Field::Param => "param".into(),
        Field::Role(Role::Mu0) => "mu0".into(),
        Field::Role(Role::C) => "c".into(),
        Field::Role(Role::TSet) => "t_set".into(),
        Field::Role(Role::Slope) => "phi".into(),
        Field::StartParameter(name) if name == "omega0" => "omega0".into(),
        Field::Parameter(name) | Field::StartParameter(name) => crate::walker_args::set_key(name),
        Field::Init(name) => crate::walker_args::init_key(name),
    }
}

/// A field as a message mentions it, the way a caller typed it: `t_set=`, `set['K_P']`.
#[must_use]
pub fn mention(field: &Field) -> String {
    match field {
        Field::Parameter(_) | Field::StartParameter(_) | Field::Init(_) if !matches!(field, Field::StartParameter(n) if n == "omega0") => {
            keyword_of(field)
        }
        other => format!("{}=", keyword_of(other)),
    }
}

impl From<RequestError> for ArgError {
    /// Named by the keyword of the field, the other fields it mentions by theirs.
    fn from(e: RequestError) -> Self {
        ArgError::new(&keyword_of(e.field()), e.detail(&mention))
    }
}

impl From<ParamError> for ArgError {
    /// Named by the keyword of the parameter, with the valid range of its model file.
    fn from(e: ParamError) -> Self {
        match &e {
            ParamError::OutOfRange { name, value, range } => {
                ArgError::out_of_range(keyword(name), value, &format!("in {range}"))
            }
            ParamError::Unknown { name, .. } => ArgError::new(keyword(name), e.to_string()),
        }
    }
}

impl From<SetupError> for ArgError {
    /// Named by the keyword of the parameter the error is about; a model file's errors by
    /// `model`; anything else by `scene`.
    fn from(e: SetupError) -> Self {
        match e {
            SetupError::Param(p) => p.into(),
            SetupError::Request(r) => r.into(),
            SetupError::NoKernels(k) => k.into(),
            SetupError::Model(_) | SetupError::Spec(_) | SetupError::NotCompiled { .. } => {
                ArgError::new("model", e.to_string())
            }
            // The library's message starts with its flag name (`t-set: model ...`); the
            // keyword is the argument here.
            SetupError::NoRole { flag, model, role } => {
                ArgError::new(keyword(flag), format!("model `{model}` has no {role}"))
            }
            other => ArgError::new(other.param().map_or("scene", keyword), other.to_string()),
        }
    }
}

impl From<NoKernels> for ArgError {
    /// Named `friction` (a law the model does not list or has no kernels for) or `model` (its
    /// run-time derivation failed).
    fn from(e: NoKernels) -> Self {
        let arg = match e {
            NoKernels::FrictionLaw { .. } | NoKernels::NotCompiled { .. } => "friction",
            NoKernels::Source { .. } | NoKernels::Missing { .. } => "model",
        };
        ArgError::new(arg, e.to_string())
    }
}

/// The most characters of a caller's name or value that a message repeats.
pub const ECHO: usize = 80;

/// A caller's name or text as a message repeats it: control characters escaped (`\u{1b}`),
/// cut to [`ECHO`] characters with `...`.
#[must_use]
pub fn echo(text: &str) -> String {
    let mut out: String = text
        .chars()
        .take(ECHO)
        .flat_map(char::escape_debug)
        .collect();
    if text.chars().nth(ECHO).is_some() {
        out.push_str("...");
    }
    out
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
    fn a_parameter_out_of_range_is_named_by_its_keyword_with_the_model_files_range() {
        let e = ArgError::from(ParamError::OutOfRange {
            name: "T_set".into(),
            value: -1.0,
            range: "(0, inf)".into(),
        });
        assert_eq!(e.to_string(), "invalid t_set: -1: must be in (0, inf)");
    }

    #[test]
    fn a_huge_value_out_of_range_is_written_with_an_exponent() {
        let e = ArgError::out_of_range("mu0", -1e308, "in [0, inf)");
        assert_eq!(e.to_string(), "invalid mu0: -1e308: must be in [0, inf)");
        let e = ArgError::out_of_range("mu0", -1.0, "in [0, inf)");
        assert_eq!(e.to_string(), "invalid mu0: -1: must be in [0, inf)");
    }

    #[test]
    fn an_echo_escapes_control_characters_and_is_cut() {
        assert_eq!(echo("a\u{1b}b"), "a\\u{1b}b");
        assert_eq!(echo(&"x".repeat(1000)), format!("{}...", "x".repeat(ECHO)));
        assert_eq!(echo("T_set"), "T_set");
    }

    #[test]
    fn a_slope_for_the_level_walker_is_named_phi() {
        let e = SetupError::NoRole {
            flag: "phi",
            model: "paper-active".into(),
            role: "slope (its floor is level)",
        };
        assert_eq!(
            ArgError::from(e).to_string(),
            "invalid phi: model `paper-active` has no slope (its floor is level)"
        );
    }
}
