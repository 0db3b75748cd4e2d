//! The start of a request: components of the model's start replaced by name (the front ends'
//! `init`), each a coordinate or velocity of the model, finite, and given once; and a start
//! whose stance foot those components moved still on the floor and moving along it.

use crate::model::{InitError, Model, Spec};
use crate::vector::Vector;

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

/// The start of a walk: the model's `[start]` with the components of `init` (a coordinate or
/// a velocity by name) replaced, as the front ends' `init` gives them.
///
/// # Errors
/// As [`start_components`] and [`on_the_floor`].
pub fn start(model: &Model, init: &[(String, f64)]) -> Result<Vector, RequestError> {
    let components = start_components(model.spec(), init)?;
    let start = model.start_state_replacing(&components);
    on_the_floor(model, &start, &components)?;
    Ok(start)
}

/// Checks that a start whose stance foot the `components` moved is still on the floor: the
/// first two coordinates are the stance foot's `x` and `z` (`docs/model-format.md`), held on
/// the floor `z = -x tan(phi)` (level: `z = 0`) and moving along it (`zd = -xd tan(phi)`). A
/// start off the floor walks as if it were on it (a foot a kilometre up walks "ok"), so it is
/// refused, named by the component that moved the foot. The tolerance is relative to the
/// foot's distance from the origin (and 1 m, 1 m/s): rounding in `x tan(phi)`, not a
/// displacement. A start the model file gives itself is checked where the model is loaded.
///
/// # Errors
/// The stance foot is off the floor or leaves it ([`RequestError::OffTheFloor`]).
pub fn on_the_floor(
    model: &Model,
    start: &[f64],
    components: &[(usize, f64)],
) -> Result<(), RequestError> {
    let n = model.n();
    let Some(&(moved, _)) = components
        .iter()
        .find(|(i, _)| [0, 1, n, n + 1].contains(i))
    else {
        return Ok(());
    };
    let names = model.spec().state_names();
    let tan = model.phi().tan();
    let off = |a: f64, b: f64| {
        let scale = 1.0 + a.abs().max(b.abs());
        (b + a * tan).abs() > 1e-9 * scale
    };
    for (velocity, i) in [(false, 0), (true, n)] {
        if off(start[i], start[i + 1]) {
            return Err(RequestError::OffTheFloor {
                field: Field::Init(names[moved].clone()),
                foot: [
                    (names[i].clone(), start[i]),
                    (names[i + 1].clone(), start[i + 1]),
                ],
                velocity,
                level: tan == 0.0,
            });
        }
    }
    Ok(())
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

    #[test]
    fn a_start_moved_off_the_floor_or_leaving_it_is_refused_naming_the_component() {
        let s = Setup::active_level().expect("the shipped scene");
        let m = s.model().expect("the shipped model");
        let names = m.spec().state_names();
        let (z, zd) = (names[1].clone(), names[m.n() + 1].clone());
        let e = start(&m, &[(z.clone(), 1000.0)]).expect_err("a kilometre up");
        assert_eq!(e.field(), &Field::Init(z.clone()));
        assert!(e.to_string().contains("must be on the floor"), "{e}");
        let e = start(&m, &[(zd.clone(), 1.0)]).expect_err("leaving the floor");
        assert_eq!(e.field(), &Field::Init(zd));
        assert!(e.to_string().contains("must be along the floor"), "{e}");
        let e = start(&m, &[(z.clone(), f64::NAN)]).expect_err("NaN");
        assert!(matches!(e, RequestError::OutOfRange { .. }), "{e}");
        let on = start(&m, &[(z, 0.0)]).expect("on the floor");
        assert_eq!(on, m.start_state());
    }
}
