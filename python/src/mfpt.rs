//! The mean first-passage time by the Markov-chain (mesh) approximation for Python
//! (`docs/floors.md`, "`walker mfpt`"): `mfpt(...)`, as `walker mfpt --json`, with the GIL
//! released; with `walks`, also the statistics of that many walks from the mesh's fixed point
//! (`monte_carlo`), as the command line's `--walks`. The mesh itself is the library's
//! (`walker::floor::mesh`); this file only translates the arguments and the report.

use pyo3::prelude::*;
use walker::floor::mesh::{MeshBox, MeshError, MeshOptions, mesh_mfpt, start_setup};
use walker::floor::{Survival, survive};
use walker::poincare::Section;

use crate::chunks::stoppable;
use crate::error::ArgError;
use crate::floor::{floor_spec, mu0_once, walker_on};
use crate::options;
use crate::walker_args::{self, overrides};

/// A mesh error named by its keyword (`points` is `mesh=`; `floor` for the floor's own).
fn named(e: &MeshError) -> ArgError {
    let field = match e {
        MeshError::OutOfRange { field, .. } | MeshError::TooLarge { field, .. } => match *field {
            "points" => "mesh",
            other => other,
        },
        _ => "floor",
    };
    ArgError::new(field, e.to_string())
}

/// `n` as a count, or an error naming `field` (a negative number is out of every range).
fn count(field: &str, n: i64) -> Result<usize, ArgError> {
    usize::try_from(n)
        .map_err(|_| ArgError::out_of_range(field, n, "a whole number >= 0 in its range"))
}

/// The mesh estimate of the mean first-passage time (see the Python docstring of
/// `slippery_walker.mfpt`): the JSON text of `walker mfpt --json`. `walks` (with `max_steps`)
/// adds the statistics of that many walks from the mesh's fixed point as `monte_carlo`.
///
/// # Errors
/// `ValueError` naming a bad argument and its valid range, a floor the mesh cannot take (a
/// `steps` floor), a mesh too large, or no gait to mesh around. On a floor that sets the slope
/// the walker starts on the chain's central slope, as on the command line.
#[pyfunction]
#[pyo3(signature = (*, scene, model, set, init, floor, t_set, omega0, phi, c, friction,
    impact, method, rtol, atol, mesh, samples, box_scale, half_widths, walks, max_steps))]
#[allow(clippy::too_many_arguments)]
pub fn mfpt(
    py: Python<'_>,
    scene: Option<&str>,
    model: Option<&str>,
    set: Vec<(String, f64)>,
    init: Vec<(String, f64)>,
    floor: &Bound<'_, PyAny>,
    t_set: Option<f64>,
    omega0: Option<f64>,
    phi: Option<f64>,
    c: Option<f64>,
    friction: Option<&str>,
    impact: Option<&str>,
    method: &str,
    rtol: Option<f64>,
    atol: Option<f64>,
    mesh: i64,
    samples: i64,
    box_scale: Option<f64>,
    half_widths: Option<Vec<f64>>,
    walks: Option<i64>,
    max_steps: i64,
) -> PyResult<String> {
    let spec = floor_spec(floor)?;
    let bounds = match (box_scale, half_widths) {
        (Some(_), Some(_)) => {
            return Err(ArgError::new(
                "half_widths",
                "cannot be given with box_scale: each sets the box; give one",
            )
            .into());
        }
        (_, Some(w)) => MeshBox::HalfWidths(w),
        (Some(scale), None) => MeshBox::Spread { scale },
        (None, None) => MeshOptions::default().bounds,
    };
    let opts = MeshOptions {
        points: count("mesh", mesh)?,
        samples: count("samples", samples)?,
        bounds,
    };
    opts.check().map_err(|e| named(&e))?;
    let check = walks
        .map(|w| walker::request::survive_counts(i128::from(w), i128::from(max_steps)))
        .transpose()
        .map_err(ArgError::from)?;
    let ov = overrides(None, c, t_set, phi, friction, impact)?;
    let mut setup = walker_args::setup_released(py, scene, model, &ov, &set)?;
    mu0_once(&setup, &spec, None, phi, &set)?;
    walker_args::set_omega0(&mut setup, omega0, |_| true, "finite")?;
    // On a floor that sets the slope the walker stands on the slope the chain starts on (its
    // central sample), so that the pilot walks and the check's walks start where the chain
    // does: as `walker mfpt`.
    let setup = start_setup(&setup, &spec, opts.samples);
    let cfg = options::config(method, rtol, atol)?;
    let m = walker_args::model(&setup)?;
    // The mesh starts at its fixed point; `init` is checked as everywhere, though unused.
    walker_args::start(&m, &init)?;
    let fw = walker_on(&setup, spec)?;
    let run = || -> Result<(serde_json::Value, Option<Survival>), ArgError> {
        let r = mesh_mfpt(&fw, &cfg, &opts).map_err(|e| named(&e))?;
        let mc = match check {
            None => None,
            Some((walks, steps)) => {
                let start = Section::of(&m).embed(&r.centre);
                let mc = survive(&fw, &cfg, &start, 0..walks as u64, steps)
                    .map_err(|e| ArgError::new("floor", e.to_string()))?;
                Some(mc.survival)
            }
        };
        Ok((serde_json::to_value(&r).unwrap_or_default(), mc))
    };
    // On a thread of its own with the GIL released; the mesh has no stop of its own, so a
    // Ctrl-C is raised when it ends.
    let (mut v, mc) = stoppable(py, |_| run())??;
    if let (Some(mc), Some(map)) = (mc, v.as_object_mut()) {
        map.insert(
            "monte_carlo".to_owned(),
            serde_json::to_value(mc.summary()).unwrap_or_default(),
        );
    }
    Ok(v.to_string())
}
