//! What a hybrid simulation of a model evaluates besides its dynamics: the strike guard and each
//! fall's value (`events`), and the relabelling at the impact (`relabel`: the striking point
//! becomes the new stance foot, every other coordinate by the model's `[relabel]` map, the
//! velocities by the same maps' Jacobians), with its partial derivatives by the coordinates
//! and the velocities it is evaluated at (`relabel_jacobian`, for a Poincare map's Jacobian).

use walker_scene::model::{FallCondition, Model};

use super::assemble::{kernel, named};
use super::mechanics::{Mechanics, time_derivative};
use crate::budget::stage;
use crate::error::Result;
use crate::kernels::{Kernel, Shape};
use crate::matrix::Matrix;
use crate::ratfunc::RatFunc;
use crate::symbol::Symbols;

/// The `events` and `relabel` kernels of `model`.
///
/// # Errors
/// A guard or a relabelling expression that does not lower, or an unknown point.
pub fn event_kernels(m: &Mechanics, model: &Model, table: &Symbols) -> Result<Vec<Kernel>> {
    let gap = |name: &str| -> Result<RatFunc> {
        let [x, z] = m.point(name)?;
        Ok(m.floor.gap(x, z))
    };
    let guard = match &model.strike.guard {
        Some(e) => {
            stage(|| format!("the strike guard ({}:{})", model.path, e.location));
            m.syms.lower(e)?
        }
        None => gap(&model.strike.point.name)?,
    };
    let mut outputs = vec![("guard".to_owned(), guard)];
    for f in &model.falls {
        let value = match &f.condition {
            FallCondition::Point(p) => gap(&p.name)?,
            FallCondition::Guard(e) => {
                stage(|| format!("fall `{}` ({}:{})", f.name.name, model.path, e.location));
                m.syms.lower(e)?
            }
        };
        outputs.push((format!("fall_{}", f.name.name), value));
    }
    let events = kernel(
        table,
        "events",
        "The strike guard (positive during the stance, through zero at the strike) and each fall's value (the walk fails where one reaches zero)",
        "model file",
        outputs,
        Shape::Parts,
        &[],
    );

    // The coordinates after the impact, then their velocities from `qdot+` (the arguments).
    let [px, pz] = m.point(&model.strike.point.name)?;
    let mut after: Vec<RatFunc> = m.syms.q.iter().map(|q| RatFunc::sym(*q)).collect();
    after[0] = px.clone();
    after[1] = pz.clone();
    for r in &model.relabel {
        stage(|| format!("the relabelling ({}:{})", model.path, r.value.location));
        after[r.coordinate] = m.syms.lower(&r.value)?;
    }
    let mut outputs: Vec<(String, RatFunc)> = after
        .iter()
        .enumerate()
        .map(|(i, v)| (format!("q{i}"), v.clone()))
        .collect();
    for (i, v) in after.iter().enumerate() {
        outputs.push((format!("qd{i}"), time_derivative(&m.syms, v)));
    }
    let state: Vec<_> = m.syms.q.iter().chain(&m.syms.qd).copied().collect();
    let values: Vec<RatFunc> = outputs.iter().map(|(_, v)| v.clone()).collect();
    let relabel = kernel(
        table,
        "relabel",
        "Coordinates and velocities after the impact: the striking point becomes the stance foot, the other coordinates by the relabelling, from the post-impact velocities",
        "Eqs. 12-16, model file",
        outputs,
        Shape::Parts,
        &[],
    );
    let relabel_jacobian = kernel(
        table,
        "relabel_jacobian",
        "Partial derivatives of the relabelled coordinates and velocities by the coordinates and the post-impact velocities",
        "Eqs. 12-16, model file",
        named("J", &Matrix::jacobian(&values, &state)),
        Shape::Matrix(values.len(), state.len()),
        &[],
    );
    Ok(vec![events, relabel, relabel_jacobian])
}
