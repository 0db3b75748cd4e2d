//! Parameter assignments of a request: a parameter may be given by its role (`mu0`, `c`,
//! `T_set`, the slope) or by its name (the front ends' `set`), swept, chained or a grid
//! column. Two of these that reach the same parameter (`T_set` by role and by name, the swept
//! parameter also chained, a name given twice) are refused naming both: one of them would be
//! silently dropped otherwise.

use crate::model::Spec;

use super::error::RequestError;
use super::field::{Field, Role};

/// The index of the parameter that has `role` in the model `spec`, if it has one.
#[must_use]
pub fn role_parameter(spec: &Spec, role: Role) -> Option<usize> {
    match role {
        Role::Mu0 => spec.mu0,
        Role::C => spec.c,
        Role::TSet => spec.parameter("T_set"),
        Role::Slope => spec.slope,
    }
}

/// The index of the parameter `field` sets in the model `spec`: a role's parameter, or a
/// parameter or start parameter by name; `None` for any other field or a name the model does
/// not have (that is refused where it is set, listing the model's parameters).
#[must_use]
pub fn parameter_of(spec: &Spec, field: &Field) -> Option<usize> {
    match field {
        Field::Role(r) => role_parameter(spec, *r),
        Field::Parameter(name) | Field::StartParameter(name) => spec.parameter(name),
        _ => None,
    }
}

/// Checks that no two of `given` (each a field and the index of the parameter it sets) set the
/// same parameter of `spec`.
///
/// # Errors
/// [`RequestError::Repeated`] naming the parameter, the later field and the first.
pub fn distinct(spec: &Spec, given: &[(Field, usize)]) -> Result<(), RequestError> {
    for (k, (second, index)) in given.iter().enumerate() {
        if let Some((first, _)) = given[..k].iter().find(|(_, i)| i == index) {
            return Err(RequestError::Repeated {
                parameter: spec
                    .model
                    .parameters
                    .get(*index)
                    .map_or_else(String::new, |p| p.name.name.clone()),
                first: first.clone(),
                second: second.clone(),
            });
        }
    }
    Ok(())
}

/// Checks that no two of `fields` set the same parameter of `spec` ([`parameter_of`] each;
/// fields that set none, or a name the model does not have, are left to where they are set).
///
/// # Errors
/// As [`distinct`].
pub fn distinct_fields(spec: &Spec, fields: &[Field]) -> Result<(), RequestError> {
    let given: Vec<(Field, usize)> = fields
        .iter()
        .filter_map(|f| parameter_of(spec, f).map(|i| (f.clone(), i)))
        .collect();
    distinct(spec, &given)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::setup::{Overrides, Setup, SetupError};

    fn active() -> Setup {
        Setup::active_level().expect("the shipped scene")
    }

    #[test]
    fn t_set_by_its_role_and_by_its_name_is_refused_naming_both() {
        let mut s = active();
        let ov = Overrides {
            t_set: Some(0.3),
            set: vec![("T_set".into(), 0.2)],
            ..Overrides::default()
        };
        let got = match s.apply(&ov) {
            Err(SetupError::Request(RequestError::Repeated {
                parameter,
                first,
                second,
            })) => Some((parameter, first, second)),
            _ => None,
        };
        assert_eq!(
            got,
            Some((
                "T_set".to_owned(),
                Field::Role(Role::TSet),
                Field::Parameter("T_set".into())
            ))
        );
    }

    #[test]
    fn one_name_set_twice_is_refused_and_distinct_names_are_not() {
        let mut s = active();
        let twice = Overrides {
            set: vec![("K_P".into(), 1.0), ("K_P".into(), 2.0)],
            ..Overrides::default()
        };
        assert!(matches!(
            s.apply(&twice),
            Err(SetupError::Request(RequestError::Repeated { .. }))
        ));
        let once = Overrides {
            mu0: Some(0.4),
            set: vec![("K_P".into(), 1.0), ("K_D".into(), 2.0)],
            ..Overrides::default()
        };
        s.apply(&once).expect("each parameter once");
        assert_eq!(s.params.get("K_P"), Some(1.0));
    }

    #[test]
    fn the_swept_parameter_may_not_also_be_a_chain() {
        let s = active();
        let spec = s.walker.spec();
        let t = spec.parameter("T_set").expect("T_set");
        let e = distinct(spec, &[(Field::Role(Role::TSet), t), (Field::Param, t)])
            .expect_err("swept and chained");
        assert_eq!(e.field(), &Field::Param);
        assert!(e.to_string().contains("T_set is given twice"), "{e}");
    }
}
