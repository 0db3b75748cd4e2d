//! The keyword arguments shared by the functions, checked as the `walker` command line checks
//! its flags: the friction and impact laws, the integrator and its tolerances, and the limits
//! of a walk. The walker itself (`scene=` or `model=`, its parameters and its start) is
//! `walker_args.rs`.

use walker::model::{Friction, ImpactLaw};
use walker::request::{self, Field};
use walker::sim::{SimConfig, WalkLimits};

use crate::error::ArgError;

/// The most steps a walk may take (`max_steps`), the library's bound for every front end
/// ([`walker::request::MAX_STEPS`]).
pub const MAX_STEPS: usize = request::MAX_STEPS;

/// The friction law named `name` (`"none"`, `"tanh"` or `"coulomb"`, as the command line's
/// `--friction`), `None` for the scene's ([`walker::request::friction_named`]).
///
/// # Errors
/// Another name.
pub fn friction(name: Option<&str>) -> Result<Option<Friction>, ArgError> {
    Ok(name.map(request::friction_named).transpose()?)
}

/// The impact law named `name` (`"frictionless"` or `"coulomb"`), `None` for the scene's
/// ([`walker::request::impact_named`]).
///
/// # Errors
/// Another name.
pub fn impact(name: Option<&str>) -> Result<Option<ImpactLaw>, ArgError> {
    Ok(name.map(request::impact_named).transpose()?)
}

/// The integrator settings: the method's default tolerances (DOP853: `rtol = 1e-10`,
/// `atol = 1e-12`; RODAS4: `1e-8`, `1e-10`, as the command line's), overridden by `rtol` and
/// `atol`, each in its range ([`walker::request::sim_config`]).
///
/// # Errors
/// An unknown method or a tolerance outside its range.
pub fn config(method: &str, rtol: Option<f64>, atol: Option<f64>) -> Result<SimConfig, ArgError> {
    let method = request::method_named(method)?;
    Ok(request::sim_config(method, rtol, atol)?)
}

/// `n` given as `field` if it is in `[lo, hi]` (a Python int: negative ones are named here,
/// not left to the conversion; [`walker::request::count`]).
///
/// # Errors
/// Outside `[lo, hi]`.
pub fn count(field: Field, n: i64, lo: usize, hi: usize) -> Result<usize, ArgError> {
    Ok(request::count(field, i128::from(n), lo, hi)?)
}

/// The limits of a walk ([`walker::request::walk_limits`]): `duration` in `(0, 1e9]` s
/// (`None`: no limit), `max_steps` at most [`MAX_STEPS`], `until_periodic` in (0, 1).
///
/// # Errors
/// One of them is out of its range.
pub fn limits(
    duration: Option<f64>,
    max_steps: i64,
    until_periodic: Option<f64>,
) -> Result<WalkLimits, ArgError> {
    Ok(request::walk_limits(
        duration,
        i128::from(max_steps),
        until_periodic,
    )?)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_tolerances_are_the_command_lines() {
        let cfg = config("dop853", None, None).expect("valid");
        assert_eq!((cfg.rtol, cfg.atol), (1e-10, 1e-12));
        let cfg = config("rodas4", None, Some(1e-9)).expect("valid");
        assert_eq!((cfg.rtol, cfg.atol), (1e-8, 1e-9));
    }

    #[test]
    fn bad_limits_name_their_keyword() {
        let arg = |r: Result<WalkLimits, ArgError>| r.err().map(|e| e.arg);
        assert_eq!(arg(limits(Some(0.0), 10, None)), Some("duration".into()));
        assert_eq!(
            arg(limits(None, MAX_STEPS as i64 + 1, None)),
            Some("max_steps".into())
        );
        assert_eq!(arg(limits(None, -1, None)), Some("max_steps".into()));
        assert_eq!(
            arg(limits(None, 1, Some(1.0))),
            Some("until_periodic".into())
        );
        assert_eq!(
            config("rk4", None, None).err().map(|e| e.arg),
            Some("method".into())
        );
    }
}
