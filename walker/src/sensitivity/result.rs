//! The sensitivities of one parameter, each value with its error estimate.

use serde::ser::SerializeMap as _;
use serde::{Serialize, Serializer};

/// A derivative with its error estimate (absolute).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Estimate {
    /// The value.
    pub value: f64,
    /// The error estimate (absolute, `>= 0`).
    pub error: f64,
}

/// The derivative of a Floquet multiplier with its error estimate (absolute, on the complex
/// value).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct MultiplierSensitivity {
    /// Real part of `d lambda / dp`.
    pub re: f64,
    /// Imaginary part of `d lambda / dp`.
    pub im: f64,
    /// Error estimate of `|d lambda / dp|` (the estimate of `dJ/dp` times the eigenvalue's
    /// condition number).
    pub error: f64,
}

/// The sensitivities of a fixed point to one parameter (module documentation). Serialised as
/// the `walker fixed-point --sensitivities` JSON has it: `d_state` and `map_d_state` as objects
/// keyed by the section's names.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Sensitivity {
    /// The parameter.
    #[serde(skip)]
    pub parameter: String,
    /// Its value at the fixed point.
    pub value: f64,
    /// The difference step `h` (the differences take `p +- h` and `p +- h/2`).
    pub step: f64,
    /// `dr*/dp`, by section coordinate name.
    #[serde(serialize_with = "as_map")]
    pub d_state: Vec<(String, Estimate)>,
    /// `dT/dp` along the gait (s per unit of `p`).
    #[serde(rename = "dT")]
    pub d_period: Estimate,
    /// `dV/dp` along the gait.
    #[serde(rename = "dV")]
    pub d_speed: Estimate,
    /// `d(dx)/dp` along the gait.
    pub d_dx: Estimate,
    /// `d lambda_i / dp` for the gait's multipliers (by decreasing modulus, as
    /// [`crate::poincare::FixedPoint::multipliers`]); `None` (`null`) where the multiplier is
    /// not simple.
    pub d_multipliers: Vec<Option<MultiplierSensitivity>>,
    /// `dP_r/dp` at fixed `r*` (the map's parameter column), by section coordinate name.
    #[serde(serialize_with = "as_map")]
    pub map_d_state: Vec<(String, Estimate)>,
    /// `dT/dp` of the map at fixed `r*`.
    #[serde(rename = "map_dT")]
    pub map_d_period: Estimate,
}

/// `[(name, value)]` as an object.
fn as_map<S: Serializer>(v: &[(String, Estimate)], s: S) -> Result<S::Ok, S::Error> {
    let mut m = s.serialize_map(Some(v.len()))?;
    for (k, e) in v {
        m.serialize_entry(k, e)?;
    }
    m.end()
}
