//! The keyword arguments shared by the functions, checked as the `walker` command line checks
//! its flags: the friction and impact laws, the integrator and its tolerances, and the limits
//! of a walk. The walker itself (`scene=` or `model=`, its parameters and its start) is
//! `walker_args.rs`.

use walker::model::{Friction, ImpactLaw};
use walker::ode::Method;
use walker::sim::{SimConfig, WalkLimits};

use crate::error::{ArgError, check};

/// The most steps a walk may take (`max_steps`): every step is kept, so this bounds the memory
/// of a call. The same bound as the command line's `--max-steps`.
pub const MAX_STEPS: usize = 1_000_000;

/// The friction law named `name` (`"none"`, `"tanh"` or `"coulomb"`, as the command line's
/// `--friction`), `None` for the scene's.
///
/// # Errors
/// Another name.
pub fn friction(name: Option<&str>) -> Result<Option<Friction>, ArgError> {
    match name {
        None => Ok(None),
        Some("none") => Ok(Some(Friction::None)),
        Some("tanh") => Ok(Some(Friction::Tanh)),
        Some("coulomb") => Ok(Some(Friction::Coulomb)),
        Some(other) => Err(ArgError::new(
            "friction",
            format!(
                "\"{}\": must be \"none\", \"tanh\" or \"coulomb\"",
                crate::error::echo(other)
            ),
        )),
    }
}

/// The impact law named `name` (`"frictionless"` or `"coulomb"`), `None` for the scene's.
///
/// # Errors
/// Another name.
pub fn impact(name: Option<&str>) -> Result<Option<ImpactLaw>, ArgError> {
    match name {
        None => Ok(None),
        Some("frictionless") => Ok(Some(ImpactLaw::Frictionless)),
        Some("coulomb") => Ok(Some(ImpactLaw::Coulomb)),
        Some(other) => Err(ArgError::new(
            "impact",
            format!(
                "\"{}\": must be \"frictionless\" or \"coulomb\"",
                crate::error::echo(other)
            ),
        )),
    }
}

/// The integrator settings: the method's default tolerances (DOP853: `rtol = 1e-10`,
/// `atol = 1e-12`; RODAS4: `1e-8`, `1e-10`, as the command line's), overridden by `rtol` and
/// `atol`, each in (0, 1).
///
/// # Errors
/// An unknown method or a tolerance outside (0, 1).
pub fn config(method: &str, rtol: Option<f64>, atol: Option<f64>) -> Result<SimConfig, ArgError> {
    let base = match method {
        "dop853" => SimConfig::default(),
        "rodas4" => SimConfig {
            method: Method::Rodas4,
            rtol: 1e-8,
            atol: 1e-10,
            ..SimConfig::default()
        },
        other => {
            return Err(ArgError::new(
                "method",
                format!(
                    "\"{}\": must be \"dop853\" or \"rodas4\"",
                    crate::error::echo(other)
                ),
            ));
        }
    };
    let tol = |arg: &str, x: f64| check(arg, x, x > 0.0 && x < 1.0, "in (0, 1)");
    Ok(SimConfig {
        rtol: rtol.map_or(Ok(base.rtol), |x| tol("rtol", x))?,
        atol: atol.map_or(Ok(base.atol), |x| tol("atol", x))?,
        ..base
    })
}

/// `n` given as `arg` if it is in `[lo, hi]` (a Python int: negative ones are named here, not
/// left to the conversion).
///
/// # Errors
/// Outside `[lo, hi]`.
pub fn count(arg: &str, n: i64, lo: usize, hi: usize) -> Result<usize, ArgError> {
    match usize::try_from(n) {
        Ok(k) if (lo..=hi).contains(&k) => Ok(k),
        _ => Err(ArgError::out_of_range(arg, n, &format!("in [{lo}, {hi}]"))),
    }
}

/// The limits of a walk: `duration` finite and > 0 (`None`: no limit), `max_steps` at most
/// [`MAX_STEPS`], `until_periodic` in (0, 1).
///
/// # Errors
/// One of them is out of its range.
pub fn limits(
    duration: Option<f64>,
    max_steps: i64,
    until_periodic: Option<f64>,
) -> Result<WalkLimits, ArgError> {
    let duration = match duration {
        Some(d) => check("duration", d, d > 0.0, "finite and > 0")?,
        None => f64::INFINITY,
    };
    let periodic = until_periodic
        .map(|x| check("until_periodic", x, x > 0.0 && x < 1.0, "in (0, 1)"))
        .transpose()?;
    Ok(WalkLimits {
        max_steps: count("max_steps", max_steps, 0, MAX_STEPS)?,
        duration,
        record: false,
        periodic,
    })
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
