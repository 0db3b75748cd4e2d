//! The symmetry a per-step slope rests on: a model whose stance foot `(x, z)` enters its
//! dynamics only by a translation can walk step `k` on the line of slope `phi_k` through its
//! stance foot as a walk of the model (whose floor is the line `z = -x tan(phi)` through the
//! origin) from the state moved so that the foot is at the origin ([`check_translation`]).
//!
//! The check reads the model file: every body's centre of mass and every named point must move
//! with the foot (`p(x + a, z + b) = p(x, z) + (a, b)`), and every other expression of the
//! model that can see the coordinates (masses, rotations, the strike and fall guards, the
//! relabelling, the inputs' generalised forces, the outputs) must not change. Then the
//! kinetic energy and the contact Jacobians do not depend on `(x, z)`, gravity's potential
//! changes by a constant, the impact map is the same, the relabelled foot moves with the old
//! one, and a point's fall (its height above the floor) is measured from the moved floor.
//! Each expression is evaluated at two sets of values of all its symbols, and at the same
//! values with the foot moved by `(1.3, -0.7)`: a dependence on `(x, z)` other than the
//! translation changes a value by far more than the tolerance `1e-9` (relative to the values'
//! size), which only rounding stays within.

use walker_scene::model::{Expr, FallCondition, Model};

/// The foot's move of the check.
const MOVE: [f64; 2] = [1.3, -0.7];

/// The largest change (relative to the values' size, at least 1) taken as rounding.
const TOLERANCE: f64 = 1e-9;

/// An arbitrary value of the symbol `name` in the sample `sample` (0 or 1): a few tenths,
/// different for different names, away from the special values of sines and divisions.
fn value(name: &str, sample: u32) -> f64 {
    let h = name.bytes().fold(u64::from(sample) * 31 + 7, |h, b| {
        h.wrapping_mul(131).wrapping_add(u64::from(b))
    });
    0.2 + 0.07 * (h % 11) as f64 + 0.013 * f64::from(sample)
}

/// `e` at the sample `sample` with the foot `(x, z)` moved by `by`; NaN where it cannot be
/// evaluated.
fn eval(e: &Expr, x: &str, z: &str, sample: u32, by: [f64; 2]) -> f64 {
    e.eval(&|name| {
        let shift = if name == x {
            by[0]
        } else if name == z {
            by[1]
        } else {
            0.0
        };
        Some(value(name, sample) + shift)
    })
    .unwrap_or(f64::NAN)
}

/// Whether `e` changes by `change` (within rounding) when the foot moves by [`MOVE`].
fn moves_by(e: &Expr, x: &str, z: &str, change: f64) -> bool {
    (0..2).all(|sample| {
        let a = eval(e, x, z, sample, [0.0, 0.0]);
        let b = eval(e, x, z, sample, MOVE);
        let scale = a.abs().max(b.abs()).max(1.0);
        // Both NaN (a division by zero at the sample) is no evidence either way.
        (a.is_nan() && b.is_nan()) || ((b - a) - change).abs() <= TOLERANCE * scale
    })
}

/// Checks that `model` is invariant under a translation of its stance foot (see the module's
/// doc); the error names the first expression that is not (`body `hip` centre of mass (z)`).
///
/// # Errors
/// An expression of the model depends on the stance foot's position other than by the
/// translation.
pub(crate) fn check_translation(model: &Model) -> Result<(), String> {
    let (Some(x), Some(z)) = (model.coordinates.first(), model.coordinates.get(1)) else {
        return Err("the model has fewer than two coordinates".to_owned());
    };
    let (x, z) = (x.name.name.as_str(), z.name.name.as_str());
    let mut moving: Vec<(String, &Expr, f64)> = Vec::new();
    let mut fixed: Vec<(String, &Expr)> = Vec::new();
    for b in &model.bodies {
        let n = &b.name.name;
        moving.push((
            format!("body `{n}` centre of mass (x)"),
            &b.com[0].expr,
            MOVE[0],
        ));
        moving.push((
            format!("body `{n}` centre of mass (z)"),
            &b.com[1].expr,
            MOVE[1],
        ));
        fixed.push((format!("body `{n}` mass"), &b.mass.expr));
        if let Some((c, s)) = &b.rotation {
            fixed.push((format!("body `{n}` rotation"), &c.expr));
            fixed.push((format!("body `{n}` rotation"), &s.expr));
        }
    }
    for p in &model.points {
        let n = &p.name.name;
        moving.push((format!("point `{n}` (x)"), &p.at[0].expr, MOVE[0]));
        moving.push((format!("point `{n}` (z)"), &p.at[1].expr, MOVE[1]));
    }
    if let Some(g) = &model.strike.guard {
        fixed.push(("the strike guard".to_owned(), &g.expr));
    }
    for f in &model.falls {
        if let FallCondition::Guard(g) = &f.condition {
            fixed.push((format!("fall `{}`", f.name.name), &g.expr));
        }
    }
    for r in &model.relabel {
        let c = &model.coordinates[r.coordinate].name.name;
        fixed.push((format!("relabel `{c}`"), &r.value.expr));
    }
    for i in &model.inputs {
        for f in &i.force {
            fixed.push((format!("input `{}` force", i.name.name), &f.expr));
        }
    }
    for o in &model.outputs {
        fixed.push((format!("output `{}`", o.name.name), &o.h.expr));
    }
    let fixed = fixed.into_iter().map(|(w, e)| (w, e, 0.0));
    for (what, e, change) in moving.into_iter().chain(fixed) {
        if !moves_by(e, x, z, change) {
            return Err(what);
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::check_translation;
    use crate::setup::Setup;

    #[test]
    fn the_shipped_sloped_walkers_move_with_their_stance_foot() {
        for s in [Setup::passive_slope(), Setup::active_level()] {
            let s = s.expect("a built-in scene");
            assert_eq!(check_translation(&s.walker.spec().model), Ok(()));
        }
    }

    #[test]
    fn a_model_that_sees_where_its_foot_is_is_named() {
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../models/rimless-wheel.toml"
        ))
        .expect("the shipped model");
        // A fall that watches the distance walked: not invariant under a move of the foot.
        let text = text.replace(
            "guard = \"th + alpha/2 - phi\"",
            "guard = \"th + alpha/2 - phi + x\"",
        );
        let model = walker_scene::model::Model::from_toml(&text, "wheel.toml")
            .expect("the edited model loads");
        assert_eq!(
            check_translation(&model),
            Err("fall `fell-backward`".to_owned())
        );
    }
}
