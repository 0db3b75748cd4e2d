//! The bound on the angles' multiples, checked before any derivation: the canonical form writes
//! `sin(n b)` and `cos(n b)` of a base angle `b` by the addition formulas as polynomials of
//! degree `n` in `sin b` and `cos b`, whose coefficients grow as `2^n`. Their cost grows with
//! `n` (about as its cube, with the coefficients' digits, in every product that follows), and
//! so does the loss of digits where the generated code evaluates them: the sum of the absolute
//! values of the coefficients of `sin(n b)` is about `(1 + sqrt 2)^n`, so a kernel may lose up
//! to `n log10(1 + sqrt 2)`, about `0.38 n`, of its 16 digits. At the bound, `n = 12`, that is
//! under five digits (measured: at most `2e-12` absolute error in `sin(12 b)`); at `n = 50` no
//! digit is left.

use walker_scene::model::angles::{add_denominators, angle_combination};
use walker_scene::model::{ExprKind, Model, ModelExpr, Span};

use crate::error::{Error, Result};

/// The largest multiple of a base angle in a `sin` or `cos` of a model: each angle's
/// coefficient in an argument times the angle's base-angle divisor, and each divisor itself
/// (the `sin` and `cos` of the angle are `n = divisor` times its base angle). The shipped
/// models use at most 2 (the paper's `alpha`, whose base angle is `alpha/2`).
pub const MAX_ANGLE_MULTIPLE: u64 = 12;

fn located(model: &Model, e: &ModelExpr, span: Span, what: String) -> Error {
    Error::CheckFailed {
        what: format!("{}:{}: {what}", model.path, e.location_of(span)),
    }
}

/// Checks every angle's multiple in every `sin` and `cos` argument of `model`, and every
/// angle's base-angle divisor, against [`MAX_ANGLE_MULTIPLE`].
///
/// # Errors
/// [`Error::CheckFailed`] naming the model file, line and column of the argument (or, for a
/// divisor, of the first fraction of the angle), the angle, its multiple and the bound.
pub fn check_angle_multiples(model: &Model) -> Result<()> {
    let is_angle = |name: &str| model.is_angle(name);
    let divisor = |name: &str| model.base_angle_divisor(name).unwrap_or(1);
    let expressions = model.expressions();
    // The divisors first (a multiple is a coefficient times its divisor): the first expression
    // whose denominators bring an angle's least common denominator past the bound.
    let mut divisors = std::collections::BTreeMap::new();
    for (role, e) in &expressions {
        // The loader computed the same divisors without error; an error here is its business.
        let _ = add_denominators(&e.expr, &is_angle, role.substituted(), &mut divisors);
        if let Some((name, d)) = divisors.iter().find(|(_, d)| **d > MAX_ANGLE_MULTIPLE) {
            return Err(located(
                model,
                e,
                e.expr.span,
                format!(
                    "the base angle of `{name}` is `{name}/{d}` (the least common denominator of \
                     its coefficients): the divisor must be at most {MAX_ANGLE_MULTIPLE}"
                ),
            ));
        }
    }
    for (_, e) in &expressions {
        let mut found = None;
        e.expr.visit(&mut |node| {
            if found.is_some() {
                return;
            }
            let ExprKind::Call(_, arg) = &node.kind else {
                return;
            };
            let Ok(terms) = angle_combination(arg, &is_angle) else {
                return;
            };
            for (name, coef) in terms {
                // |coef| * divisor, exact: the divisor is a multiple of the denominator.
                let d = divisor(&name);
                let n = u64::try_from(coef.denom())
                    .ok()
                    .filter(|den| *den > 0 && d % den == 0)
                    .and_then(|den| coef.numer().unsigned_abs().checked_mul(d / den));
                if n.is_none_or(|n| n > MAX_ANGLE_MULTIPLE) {
                    found = Some((node.span, name, n));
                    return;
                }
            }
        });
        if let Some((span, name, n)) = found {
            let times = n.map_or_else(|| "too many".to_owned(), |n| n.to_string());
            return Err(located(
                model,
                e,
                span,
                format!(
                    "`{name}` appears as {times} times its base angle: a `sin` or `cos` takes at \
                     most {MAX_ANGLE_MULTIPLE} times a base angle (the addition formulas expand \
                     it into a polynomial of that degree, whose cost and lost digits grow with it)"
                ),
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::MAX_ANGLE_MULTIPLE;
    use crate::symbol::BaseAngle;
    use crate::trig::sin_cos_multiple;

    /// The largest absolute error of `sin(n b)` and `cos(n b)` in the canonical form, evaluated
    /// in `f64` at 2001 points of `[-3.2, 3.2]`, against the library's `sin` and `cos` of `n b`.
    fn worst_error(n: i64) -> f64 {
        let b = BaseAngle::new(0);
        let (s, c) = sin_cos_multiple(b, n);
        let mut worst = 0.0_f64;
        for k in 0..=2000 {
            let x = -3.2 + 6.4 * f64::from(k) / 2000.0;
            let v = |slot: usize| {
                if slot == b.sin_slot() {
                    x.sin()
                } else if slot == b.cos_slot() {
                    x.cos()
                } else {
                    0.0
                }
            };
            let nx = n as f64 * x;
            worst = worst
                .max((s.eval(&v) - nx.sin()).abs())
                .max((c.eval(&v) - nx.cos()).abs());
        }
        worst
    }

    /// At the bound the canonical form keeps eleven digits: the coefficients' absolute sum is
    /// about `(1 + sqrt 2)^12 = 4e4`, times the rounding `2.2e-16`, `1e-11`.
    #[test]
    fn a_multiple_at_the_bound_keeps_eleven_digits() {
        let n = i64::try_from(MAX_ANGLE_MULTIPLE).unwrap_or(i64::MAX);
        let e = worst_error(n);
        assert!(e < 1e-11, "sin/cos({n} b): {e:e}");
    }

    /// Past the bound the digits go (the reason for it): at 40 times a base angle fewer than
    /// six are left, where the library's own `sin` keeps fifteen.
    #[test]
    fn a_multiple_far_past_the_bound_loses_most_digits() {
        let e = worst_error(40);
        assert!(e > 1e-6, "sin/cos(40 b): {e:e}");
    }
}
