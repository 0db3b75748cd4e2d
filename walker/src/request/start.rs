//! The start of a request: components of the model's start replaced by name (the front ends'
//! `init`), each a coordinate or velocity of the model, finite, and given once.

use crate::model::{InitError, Spec};

use super::error::RequestError;
use super::field::Field;

/// The index in the state of each `(name, value)` of `init` with its value, checked against
/// the model `spec`.
///
/// # Errors
/// A name given twice ([`RequestError::Repeated`]), a name that is not a coordinate or
/// velocity of the model (listing the model's), or a value that is not finite; each names
/// [`Field::Init`] with the component.
pub fn start_components(
    spec: &Spec,
    init: &[(String, f64)],
) -> Result<Vec<(usize, f64)>, RequestError> {
    for (k, (name, _)) in init.iter().enumerate() {
        if init[..k].iter().any(|(n, _)| n == name) {
            return Err(RequestError::Repeated {
                parameter: name.clone(),
                first: Field::Init(name.clone()),
                second: Field::Init(name.clone()),
            });
        }
    }
    spec.start_components(init).map_err(|e| match e {
        InitError::NotFinite { name, value } => {
            RequestError::out_of_range(Field::Init(name), value, "finite")
        }
        InitError::Unknown {
            name, model, known, ..
        } => RequestError::UnknownName {
            field: Field::Init(name.clone()),
            given: name,
            expected: format!("a coordinate or velocity of model `{model}`: {known}"),
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::setup::Setup;

    #[test]
    fn a_component_given_twice_is_refused_and_an_unknown_one_lists_the_models() {
        let s = Setup::active_level().expect("the shipped scene");
        let spec = s.walker.spec();
        let twice = [("th1d".to_owned(), 0.7), ("th1d".to_owned(), 0.8)];
        let e = start_components(spec, &twice).expect_err("twice");
        assert!(matches!(e, RequestError::Repeated { .. }), "{e}");
        let e = start_components(spec, &[("th9".to_owned(), 0.0)]).expect_err("unknown");
        assert_eq!(e.field(), &Field::Init("th9".into()));
        assert!(e.to_string().contains("th1d"), "{e}");
        let e = start_components(spec, &[("th1d".to_owned(), f64::NAN)]).expect_err("NaN");
        assert!(matches!(e, RequestError::OutOfRange { .. }), "{e}");
        let ok = start_components(spec, &[("th1d".to_owned(), 0.7)]).expect("valid");
        assert_eq!(ok, vec![(spec.state_index("th1d").expect("th1d"), 0.7)]);
    }
}
