//! The integrator of a request: its method and tolerances, and the laws of the contacts by
//! name, as every front end takes them.
//!
//! The smallest relative tolerance is [`RTOL_MIN`], ten units of `f64::EPSILON`, the bound
//! Hairer's RADAU5 refuses below ("tolerances are too small"): a step's local error cannot be
//! estimated below the round-off of the step itself (a few units of `EPSILON` of `|y|`), so a
//! smaller relative tolerance asks for what no step can show; it is at best the same request
//! as the absolute tolerance alone, at worst a controller that rejects every step. The smallest absolute tolerance is
//! [`ATOL_MIN`], the smallest normal `f64`: below it the scale `atol + rtol |y|` of a
//! component near zero is subnormal (fewer significant bits than the arithmetic) and the
//! squared error ratio of the error norm overflows.

use crate::model::{Friction, ImpactLaw};
use crate::ode::Method;
use crate::sim::SimConfig;

use super::error::RequestError;
use super::field::Field;

/// The smallest relative tolerance: `10 * f64::EPSILON` (about 2.2e-15), Hairer's bound.
pub const RTOL_MIN: f64 = 10.0 * f64::EPSILON;

/// The smallest absolute tolerance: the smallest normal `f64` (about 2.2e-308).
pub const ATOL_MIN: f64 = f64::MIN_POSITIVE;

/// The integration method called `name`: `dop853` or `rodas4`.
///
/// # Errors
/// Another name ([`Field::Method`]).
pub fn method_named(name: &str) -> Result<Method, RequestError> {
    match name {
        "dop853" => Ok(Method::Dop853),
        "rodas4" => Ok(Method::Rodas4),
        other => Err(RequestError::UnknownName {
            field: Field::Method,
            given: other.to_owned(),
            expected: "\"dop853\" or \"rodas4\"".into(),
        }),
    }
}

/// The friction law called `name`: `none`, `tanh` or `coulomb`.
///
/// # Errors
/// Another name ([`Field::Friction`]).
pub fn friction_named(name: &str) -> Result<Friction, RequestError> {
    match name {
        "none" => Ok(Friction::None),
        "tanh" => Ok(Friction::Tanh),
        "coulomb" => Ok(Friction::Coulomb),
        other => Err(RequestError::UnknownName {
            field: Field::Friction,
            given: other.to_owned(),
            expected: "\"none\", \"tanh\" or \"coulomb\"".into(),
        }),
    }
}

/// The impact law called `name`: `frictionless` or `coulomb`.
///
/// # Errors
/// Another name ([`Field::Impact`]).
pub fn impact_named(name: &str) -> Result<ImpactLaw, RequestError> {
    match name {
        "frictionless" => Ok(ImpactLaw::Frictionless),
        "coulomb" => Ok(ImpactLaw::Coulomb),
        other => Err(RequestError::UnknownName {
            field: Field::Impact,
            given: other.to_owned(),
            expected: "\"frictionless\" or \"coulomb\"".into(),
        }),
    }
}

/// The default tolerances `(rtol, atol)` of `method`: `(1e-10, 1e-12)` for DOP853 (and
/// DOPRI5), `(1e-8, 1e-10)` for RODAS4.
#[must_use]
pub fn default_tolerances(method: Method) -> (f64, f64) {
    match method {
        Method::Dop853 | Method::Dopri5 => (1e-10, 1e-12),
        Method::Rodas4 => (1e-8, 1e-10),
    }
}

/// A relative tolerance: in `[RTOL_MIN, 1)`.
///
/// # Errors
/// NaN, infinite or outside the range ([`Field::Rtol`]).
pub fn rtol(x: f64) -> Result<f64, RequestError> {
    if (RTOL_MIN..1.0).contains(&x) {
        Ok(x)
    } else {
        Err(RequestError::out_of_range(
            Field::Rtol,
            x,
            format!(
                "in [{RTOL_MIN:e}, 1) (below 10 machine epsilons no step's error can be estimated)"
            ),
        ))
    }
}

/// An absolute tolerance: in `[ATOL_MIN, 1)`.
///
/// # Errors
/// NaN, infinite or outside the range ([`Field::Atol`]).
pub fn atol(x: f64) -> Result<f64, RequestError> {
    if (ATOL_MIN..1.0).contains(&x) {
        Ok(x)
    } else {
        Err(RequestError::out_of_range(
            Field::Atol,
            x,
            format!("in [{ATOL_MIN:e}, 1) (a normal number below 1)"),
        ))
    }
}

/// The simulation settings of `method` with its [`default_tolerances`] replaced by `rtol` and
/// `atol` where given (each checked by [`rtol()`] and [`atol()`]).
///
/// # Errors
/// A tolerance out of its range.
pub fn sim_config(
    method: Method,
    rtol_given: Option<f64>,
    atol_given: Option<f64>,
) -> Result<SimConfig, RequestError> {
    let (r, a) = default_tolerances(method);
    Ok(SimConfig {
        method,
        rtol: rtol_given.map_or(Ok(r), rtol)?,
        atol: atol_given.map_or(Ok(a), atol)?,
        ..SimConfig::default()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_tolerances_are_accepted_and_kept() {
        let cfg = sim_config(Method::Dop853, None, None).expect("defaults");
        assert_eq!((cfg.rtol, cfg.atol), (1e-10, 1e-12));
        let cfg = sim_config(Method::Rodas4, None, Some(1e-9)).expect("valid");
        assert_eq!(
            (cfg.method, cfg.rtol, cfg.atol),
            (Method::Rodas4, 1e-8, 1e-9)
        );
    }

    #[test]
    fn a_relative_tolerance_below_ten_epsilons_is_refused_naming_rtol() {
        for x in [1e-16, 2e-15, 0.0, -1e-10, 1.0, f64::NAN, f64::INFINITY] {
            let e = rtol(x).expect_err("out of range");
            assert_eq!(e.field(), &Field::Rtol, "{x}");
        }
        assert_eq!(rtol(RTOL_MIN), Ok(RTOL_MIN));
    }

    #[test]
    fn a_subnormal_absolute_tolerance_is_refused_naming_atol() {
        for x in [5e-324, 1e-310, 0.0, 1.0, f64::NAN] {
            assert_eq!(
                atol(x).expect_err("out of range").field(),
                &Field::Atol,
                "{x}"
            );
        }
        assert_eq!(atol(1e-300), Ok(1e-300));
    }

    #[test]
    fn unknown_law_and_method_names_are_refused_with_the_names_accepted() {
        let e = method_named("rk4").expect_err("unknown");
        assert_eq!(
            e.to_string(),
            "method: \"rk4\": must be \"dop853\" or \"rodas4\""
        );
        assert_eq!(friction_named("tanh"), Ok(Friction::Tanh));
        assert_eq!(
            impact_named("x").expect_err("unknown").field(),
            &Field::Impact
        );
    }
}
