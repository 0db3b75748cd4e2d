//! The actuated part of a model: inputs and their generalised forces, the output-following
//! controller's gains, the outputs with their desired trajectories, and the descriptors to
//! report (some of which need inputs).

use std::collections::HashSet;

use crate::model::error::{ModelError, ModelErrorKind};
use crate::model::load::{Loader, Use};
use crate::model::raw::{RawModel, Str};
use crate::model::types::{
    Control, Descriptor, Desired, Input, MAX_BEZIER_POINTS, ModelExpr, Name, Output,
};

/// Inputs, control, outputs and descriptors, checked.
pub(crate) struct Actuation {
    pub(crate) inputs: Vec<Input>,
    pub(crate) control: Option<Control>,
    pub(crate) outputs: Vec<Output>,
    pub(crate) descriptors: Vec<Descriptor>,
    pub(crate) power_until: Option<ModelExpr>,
}

impl Loader<'_> {
    /// Checks `[[input]]`, `[control]`, `[[output]]` and `[descriptors]` for a model with
    /// `n_coordinates` coordinates.
    pub(crate) fn actuation(
        &self,
        raw: &RawModel,
        n_coordinates: usize,
    ) -> Result<Actuation, ModelError> {
        let mut inputs = Vec::new();
        for input in &raw.input {
            let i = input.get_ref();
            let force = i.force.get_ref();
            if force.len() != n_coordinates {
                return Err(self.error(
                    i.force.span(),
                    ModelErrorKind::Count,
                    format!(
                        "input `{}` force: expected one expression per coordinate, {}; found {}",
                        i.name.get_ref(),
                        n_coordinates,
                        force.len()
                    ),
                ));
            }
            let force = force
                .iter()
                .map(|f| {
                    self.expr(
                        f,
                        &format!("input `{}` force", i.name.get_ref()),
                        Use::Configuration,
                    )
                })
                .collect::<Result<Vec<_>, _>>()?;
            inputs.push(Input {
                name: self.name(&i.name),
                doc: i.doc.clone(),
                force,
            });
        }

        let control = match (&raw.control, inputs.is_empty()) {
            (Some(c), false) => {
                let c = c.get_ref();
                Some(Control {
                    kp: self.parameter_ref(&c.kp, "kp", false)?,
                    kd: self.parameter_ref(&c.kd, "kd", false)?,
                })
            }
            (Some(c), true) => {
                return Err(self.error(
                    c.span(),
                    ModelErrorKind::Inconsistent,
                    "[control] without [[input]]: output-following control needs inputs".to_owned(),
                ));
            }
            (None, false) => {
                return Err(self.error(raw.input.first().map_or(0..0, |i| i.span()), ModelErrorKind::Inconsistent, "[[input]] without [control]: expected [control] with the gains kp and kd, and one [[output]] per input".to_owned()));
            }
            (None, true) => None,
        };
        if raw.output.len() != inputs.len() {
            let span = raw.output.first().map_or_else(
                || raw.input.first().map_or(0..0, |i| i.span()),
                |o| o.span(),
            );
            return Err(self.error(
                span,
                ModelErrorKind::Count,
                format!("{} [[output]] for {} [[input]]: expected as many outputs as inputs (A must be square)", raw.output.len(), inputs.len()),
            ));
        }
        let mut seen_outputs = HashSet::new();
        let mut outputs = Vec::new();
        for o in &raw.output {
            let o = o.get_ref();
            let name = self.unique(&o.name, "output", false, &mut seen_outputs)?;
            let what = format!("output `{}`", name.name);
            let h = self.expr(&o.h, &format!("{what} h"), Use::Configuration)?;
            let aux = match &o.aux {
                Some(a) => self.name(a),
                None => Name {
                    name: format!("v_{}", name.name),
                    location: name.location,
                },
            };
            let d = o.desired.get_ref();
            let field = |f: &Option<Str>, key: &str| -> Result<ModelExpr, ModelError> {
                match f {
                    Some(s) => self.expr(s, &format!("{what} desired {key}"), Use::Constant),
                    None => Err(self.error(
                        o.desired.span(),
                        ModelErrorKind::Toml,
                        format!(
                            "{what} desired: missing field `{key}` for shape \"{}\"",
                            d.shape.get_ref()
                        ),
                    )),
                }
            };
            let extra = |present: &[(&Option<Str>, &str)]| -> Result<(), ModelError> {
                match present.iter().find(|(f, _)| f.is_some()) {
                    Some((f, key)) => Err(self.error(
                        f.as_ref().map_or(0..0, Str::span),
                        ModelErrorKind::Toml,
                        format!(
                            "{what} desired: `{key}` does not belong to shape \"{}\"",
                            d.shape.get_ref()
                        ),
                    )),
                    None => Ok(()),
                }
            };
            let no_points = || match &d.points {
                Some(p) => Err(self.error(
                    p.span(),
                    ModelErrorKind::Toml,
                    format!(
                        "{what} desired: `points` does not belong to shape \"{}\"",
                        d.shape.get_ref()
                    ),
                )),
                None => Ok(()),
            };
            let desired = match d.shape.get_ref().as_str() {
                "bezier" => {
                    extra(&[(&d.from, "from"), (&d.to, "to"), (&d.value, "value")])?;
                    let Some(points) = &d.points else {
                        return Err(self.error(
                            o.desired.span(),
                            ModelErrorKind::Toml,
                            format!("{what} desired: missing field `points` for shape \"bezier\" (2 to {MAX_BEZIER_POINTS} expressions of the parameters)"),
                        ));
                    };
                    let n = points.get_ref().len();
                    if !(2..=MAX_BEZIER_POINTS).contains(&n) {
                        return Err(self.error(
                            points.span(),
                            ModelErrorKind::Count,
                            format!("{what} desired points: {n} given; expected 2 to {MAX_BEZIER_POINTS} (a Bezier of order 1 to {})", MAX_BEZIER_POINTS - 1),
                        ));
                    }
                    let points = points
                        .get_ref()
                        .iter()
                        .enumerate()
                        .map(|(k, p)| {
                            self.expr(p, &format!("{what} desired points[{k}]"), Use::Constant)
                        })
                        .collect::<Result<Vec<_>, _>>()?;
                    Desired::Bezier {
                        points,
                        duration: field(&d.duration, "duration")?,
                    }
                }
                "quintic" => {
                    no_points()?;
                    extra(&[(&d.value, "value")])?;
                    Desired::Quintic {
                        from: field(&d.from, "from")?,
                        to: field(&d.to, "to")?,
                        duration: field(&d.duration, "duration")?,
                    }
                }
                "hold" => {
                    no_points()?;
                    extra(&[(&d.from, "from"), (&d.to, "to"), (&d.duration, "duration")])?;
                    Desired::Hold {
                        value: field(&d.value, "value")?,
                    }
                }
                other => {
                    return Err(self.error(
                        d.shape.span(),
                        ModelErrorKind::Toml,
                        format!(
                            "{what} desired shape `{}`: expected \"quintic\", \"bezier\" or \"hold\"",
                            crate::limits::echo(other)
                        ),
                    ));
                }
            };
            outputs.push(Output {
                name,
                h,
                aux,
                desired,
            });
        }

        let report = raw
            .descriptors
            .as_ref()
            .and_then(|d| d.get_ref().report.as_ref());
        let descriptors = match report {
            None => Descriptor::ALL
                .into_iter()
                .filter(|d| !d.needs_inputs() || !inputs.is_empty())
                .collect(),
            Some(report) => {
                let mut out = Vec::new();
                for s in report.get_ref() {
                    let Some(desc) = Descriptor::ALL
                        .into_iter()
                        .find(|d| d.name() == s.get_ref())
                    else {
                        return Err(self.error(s.span(), ModelErrorKind::Toml, format!("descriptor `{}`: expected one of \"T\", \"dx\", \"V\", \"power\", \"specific_resistance\"", s.get_ref())));
                    };
                    if out.contains(&desc) {
                        return Err(self.error(
                            s.span(),
                            ModelErrorKind::Duplicate,
                            format!(
                                "descriptor `{}` is listed twice",
                                crate::limits::echo(s.get_ref())
                            ),
                        ));
                    }
                    if desc.needs_inputs() && inputs.is_empty() {
                        return Err(self.error(
                            s.span(),
                            ModelErrorKind::Inconsistent,
                            format!(
                                "descriptor `{}` needs inputs; this model has none",
                                s.get_ref()
                            ),
                        ));
                    }
                    out.push(desc);
                }
                out
            }
        };

        let power_until = match raw
            .descriptors
            .as_ref()
            .and_then(|d| d.get_ref().power_until.as_ref())
        {
            None => None,
            Some(s) if inputs.is_empty() => {
                return Err(self.error(
                    s.span(),
                    ModelErrorKind::Inconsistent,
                    "descriptors power_until: the input power needs inputs; this model has none"
                        .to_owned(),
                ));
            }
            Some(s) => Some(self.expr(s, "descriptors power_until", Use::Constant)?),
        };

        Ok(Actuation {
            inputs,
            control,
            outputs,
            descriptors,
            power_until,
        })
    }
}
