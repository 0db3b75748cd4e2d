//! Every expression of a model, and from them each angle's base-angle divisor: the least
//! common denominator of the angle's coefficients in every `sin`/`cos` argument, and in the
//! additive terms of the guards and the relabelling (whose values the derivation substitutes
//! into the sines and cosines of the coordinates). The paper's `alpha` appears as `alpha/2`
//! in the strike guard, so its divisor is 2 and its base angle `alpha/2`.

use std::collections::BTreeMap;

use crate::model::angles::{AngleError, add_denominators};
use crate::model::types::{Desired, FallCondition, Model, ModelExpr};

/// Where in a model an expression is.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub enum ExprRole {
    /// A body's mass.
    Mass,
    /// A body's centre of mass (x or z).
    Com,
    /// A body's moment of inertia.
    Inertia,
    /// A body's orientation.
    BodyAngle,
    /// A point's position (x or z).
    Point,
    /// The strike guard.
    StrikeGuard,
    /// A fall's guard.
    FallGuard,
    /// A coordinate's value after the impact.
    Relabel,
    /// An impact lock.
    Lock,
    /// An input's generalised force.
    Force,
    /// An output `h`.
    OutputH,
    /// A desired trajectory's constant.
    Desired,
}

impl ExprRole {
    /// Whether the derivation substitutes the expression's value into the coordinates (so
    /// its angle coefficients count towards the base angles).
    #[must_use]
    pub fn substituted(self) -> bool {
        matches!(
            self,
            ExprRole::StrikeGuard | ExprRole::FallGuard | ExprRole::Relabel
        )
    }
}

impl Model {
    /// Every expression in the model with its role, bodies first, in file order.
    #[must_use]
    pub fn expressions(&self) -> Vec<(ExprRole, &ModelExpr)> {
        let mut out = Vec::new();
        for b in &self.bodies {
            out.push((ExprRole::Mass, &b.mass));
            out.extend(b.com.iter().map(|e| (ExprRole::Com, e)));
            if let Some((i, a)) = &b.rotation {
                out.push((ExprRole::Inertia, i));
                out.push((ExprRole::BodyAngle, a));
            }
        }
        for p in &self.points {
            out.extend(p.at.iter().map(|e| (ExprRole::Point, e)));
        }
        if let Some(g) = &self.strike.guard {
            out.push((ExprRole::StrikeGuard, g));
        }
        for f in &self.falls {
            if let FallCondition::Guard(g) = &f.condition {
                out.push((ExprRole::FallGuard, g));
            }
        }
        out.extend(self.relabel.iter().map(|r| (ExprRole::Relabel, &r.value)));
        out.extend(self.impact.locks.iter().map(|l| (ExprRole::Lock, l)));
        for i in &self.inputs {
            out.extend(i.force.iter().map(|e| (ExprRole::Force, e)));
        }
        for o in &self.outputs {
            out.push((ExprRole::OutputH, &o.h));
            match &o.desired {
                Desired::Quintic { from, to, duration } => {
                    out.extend([from, to, duration].map(|e| (ExprRole::Desired, e)));
                }
                Desired::Hold { value } => out.push((ExprRole::Desired, value)),
                Desired::Bezier { points, duration } => {
                    out.extend(points.iter().map(|e| (ExprRole::Desired, e)));
                    out.push((ExprRole::Desired, duration));
                }
            }
        }
        out
    }
}

/// The base-angle divisor of every angle that appears in a counted place (angles that do
/// not appear have divisor 1).
pub(crate) fn base_divisors(
    model: &Model,
) -> Result<BTreeMap<String, u64>, (AngleError, &ModelExpr)> {
    let is_angle = |n: &str| model.is_angle(n);
    let mut out = BTreeMap::new();
    for (role, e) in model.expressions() {
        add_denominators(&e.expr, &is_angle, role.substituted(), &mut out)
            .map_err(|err| (err, e))?;
    }
    Ok(out)
}
