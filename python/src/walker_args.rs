//! The walker of a call, given as the command line gives it (`cli/src/run.rs`): `scene=` (a
//! built-in name or a scene file) or `model=` (a model file, with its defaults; one that is not
//! a shipped model is derived when the call starts, by `walker-load`), the parameter keywords
//! (`mu0`, `c`, `t_set`, `phi`, by their roles in the model), `set={name: value}` for any
//! run-time parameter, `omega0` (the paper's start parameter) and `init={name: value}` for
//! components of the start.

use std::path::Path;

use walker::model::{Model, Spec};
use walker::request::{Field, Role};
use walker::setup::{Overrides, Setup, SetupError};
use walker::vector::Vector;

use pyo3::prelude::*;

use crate::chunks;
use crate::error::{ArgError, check};
use crate::options;

/// The scene of a call that names neither a scene nor a model.
pub const DEFAULT_SCENE: &str = "active-level";

/// The overrides of the keyword arguments: the parameters by role, and the laws by name.
///
/// # Errors
/// An unknown friction or impact law.
pub fn overrides(
    mu0: Option<f64>,
    c: Option<f64>,
    t_set: Option<f64>,
    phi: Option<f64>,
    friction: Option<&str>,
    impact: Option<&str>,
) -> Result<Overrides, ArgError> {
    Ok(Overrides {
        mu0,
        c,
        t_set,
        phi,
        set: Vec::new(),
        friction: options::friction(friction)?,
        impact: options::impact(impact)?,
    })
}

/// The argument `set['name']`, as errors about a key of `set` name it.
#[must_use]
pub fn set_key(name: &str) -> String {
    format!("set['{}']", crate::error::echo(name))
}

/// The argument `init['name']`, as errors about a key of `init` name it.
#[must_use]
pub fn init_key(name: &str) -> String {
    format!("init['{}']", crate::error::echo(name))
}

/// The setup of `scene` or `model` (neither: [`DEFAULT_SCENE`]) with the overrides `ov`, then
/// every `(name, value)` of `set` in order, each checked against the range its model file
/// gives.
///
/// # Errors
/// Both `scene` and `model`; a file that is not a regular file or too long; an unknown or
/// invalid scene; an invalid model file or one that cannot be derived; an override or a key of
/// `set` that is unknown or out of its range (named `set['name']`).
pub fn setup(
    scene: Option<&str>,
    model: Option<&str>,
    ov: &Overrides,
    set: &[(String, f64)],
) -> Result<Setup, ArgError> {
    let runtime = walker_load::runtime_source();
    let mut setup = match (scene, model) {
        (Some(_), Some(_)) => {
            return Err(ArgError::new(
                "model",
                "give either scene= or model=, not both",
            ));
        }
        (None, Some(path)) => Setup::from_model_file(Path::new(path), ov, Some(&runtime))?,
        (scene, None) => Setup::resolve(scene.unwrap_or(DEFAULT_SCENE), ov, Some(&runtime))?,
    };
    // Each parameter once, by its keyword or in `set` (the library's check for every front
    // end): a second value would silently replace the first.
    let given = [
        (ov.mu0, Role::Mu0),
        (ov.c, Role::C),
        (ov.t_set, Role::TSet),
        (ov.phi, Role::Slope),
    ];
    let fields: Vec<Field> = given
        .iter()
        .filter(|(v, _)| v.is_some())
        .map(|&(_, r)| Field::Role(r))
        .chain(set.iter().map(|(n, _)| Field::Parameter(n.clone())))
        .collect();
    walker::request::distinct_fields(setup.walker.spec(), &fields)?;
    for (name, value) in set {
        setup
            .set(name, *value)
            .map_err(|e| ArgError::from(e).named(&set_key(name)))?;
    }
    Ok(setup)
}

/// [`setup`] (reading the files and deriving a model file that is not shipped, with its kernels
/// for the setup's friction law lowered) on a thread of its own with the GIL released: other
/// Python threads run, and Ctrl-C raises `KeyboardInterrupt` within a fraction of a second
/// ([`chunks::abandonable`]: a derivation cannot be asked to stop, so it ends on its own,
/// within the derivation's budget, with nobody waiting for it).
///
/// # Errors
/// As [`setup`] (`ValueError`), or a signal handler's error.
pub fn setup_released(
    py: Python<'_>,
    scene: Option<&str>,
    model: Option<&str>,
    ov: &Overrides,
    set: &[(String, f64)],
) -> PyResult<Setup> {
    let (scene, model) = (scene.map(str::to_owned), model.map(str::to_owned));
    let (ov, set) = (ov.clone(), set.to_vec());
    let s = chunks::abandonable(py, move || {
        let s = setup(scene.as_deref(), model.as_deref(), &ov, &set)?;
        // The first model lowers the kernels of the friction law (kept for later models);
        // its error, if any, is reported where the model is asked for.
        let _ = s.model();
        Ok::<_, ArgError>(s)
    })??;
    Ok(s)
}

/// Sets the paper's initial angular velocity `omega0` (a parameter of the start) where the
/// keyword gives it, as the command line's `--omega0`.
///
/// # Errors
/// Not finite, not `ok`, out of its range, or the model has no start parameter `omega0`.
pub fn set_omega0(
    setup: &mut Setup,
    omega0: Option<f64>,
    ok: impl Fn(f64) -> bool,
    must_be: &str,
) -> Result<(), ArgError> {
    if let Some(w) = omega0 {
        check("omega0", w, ok(w), must_be)?;
        setup.set_start("omega0", w).map_err(|e| match e {
            SetupError::NoStartParameter { .. } => {
                ArgError::new("omega0", format!("{e}; use init={{name: value}}"))
            }
            e => e.into(),
        })?;
    }
    Ok(())
}

/// The model of `setup`.
///
/// # Errors
/// Its friction law has no kernels (named `friction`), or its run-time derivation failed
/// (`model`).
pub fn model(setup: &Setup) -> Result<Model, ArgError> {
    Ok(setup.model()?)
}

/// The index in the state of each `(name, value)` of `init` with its value, checked against
/// the model `spec` ([`walker::request::start_components`]): a coordinate or a velocity by
/// name, each once, and a finite value.
///
/// # Errors
/// An unknown component (named `init['name']`, listing the model's), one given twice, or a
/// value that is not finite.
pub fn check_init(spec: &Spec, init: &[(String, f64)]) -> Result<Vec<(usize, f64)>, ArgError> {
    Ok(walker::request::start_components(spec, init)?)
}

/// The start of a walk: the model's `[start]` with the components of `init` (a coordinate or a
/// velocity by name) replaced, as the command line's `--init` ([`walker::request::start()`]).
///
/// # Errors
/// As [`check_init`] and [`on_the_floor`].
pub fn start(model: &Model, init: &[(String, f64)]) -> Result<Vector, ArgError> {
    Ok(walker::request::start(model, init)?)
}

/// Checks that a start whose stance foot `components` moved is still on the floor and moving
/// along it ([`walker::request::on_the_floor`]), named by the `init` key that moved the foot.
///
/// # Errors
/// The stance foot given by `init` is off the floor or leaves it.
pub fn on_the_floor(
    model: &Model,
    start: &[f64],
    components: &[(usize, f64)],
) -> Result<(), ArgError> {
    Ok(walker::request::on_the_floor(model, start, components)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn active() -> Setup {
        setup(None, None, &Overrides::default(), &[]).expect("the default scene")
    }

    #[test]
    fn a_key_of_set_out_of_its_range_is_named_with_the_model_files_range() {
        let e = setup(None, None, &Overrides::default(), &[("K_P".into(), -1.0)])
            .expect_err("K_P >= 0");
        assert_eq!(e.arg, "set['K_P']");
        assert!(e.message.starts_with("-1: must be in ["), "{e}");
    }

    #[test]
    fn an_unknown_key_of_set_lists_the_models_parameters() {
        let e = setup(
            None,
            None,
            &Overrides::default(),
            &[("gravity".into(), 9.8)],
        )
        .expect_err("no such parameter");
        assert_eq!(e.arg, "set['gravity']");
        assert!(e.message.contains("T_set"), "{e}");
    }

    #[test]
    fn init_replaces_one_component_of_the_models_start() {
        let s = active();
        let m = model(&s).expect("model");
        let plain = m.start_state();
        let got = start(&m, &[("th1d".into(), 0.7)]).expect("th1d is a velocity");
        let i = m.spec().state_index("th1d").expect("th1d");
        for k in 0..plain.len() {
            assert_eq!(got[k], if k == i { 0.7 } else { plain[k] }, "component {k}");
        }
        let e = start(&m, &[("th9".into(), 0.0)]).expect_err("unknown");
        assert_eq!(e.arg, "init['th9']");
        let e = start(&m, &[("th1".into(), f64::NAN)]).expect_err("not finite");
        assert_eq!(e.arg, "init['th1']");
    }

    #[test]
    fn scene_and_model_together_are_refused_naming_model() {
        let e = setup(
            Some("active-level"),
            Some("models/paper-active.toml"),
            &Overrides::default(),
            &[],
        )
        .expect_err("both");
        assert_eq!(e.arg, "model");
    }
}
