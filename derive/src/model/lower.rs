//! Model expressions (the loader's AST) into the canonical form: exact numbers, symbols,
//! sums, products, quotients and integer powers as rational functions, and `sin`/`cos` of an
//! angle combination by the addition formulas over the model's base angles.

use num_bigint::BigInt;
use num_traits::Pow;
use walker_scene::model::{BinOp, Expr, ExprKind, Func, ModelExpr, Number};

use super::table::ModelSymbols;
use crate::error::{Error, Result};
use crate::poly::Q;
use crate::ratfunc::RatFunc;
use crate::trig::sin_cos_combination;

/// The largest power a model expression may take (`x^8`, `(a + b)^-2`).
const MAX_EXPONENT: i32 = 8;

/// An exact number of the model as a rational.
fn number(n: &Number) -> Result<Q> {
    let mantissa: BigInt = n.mantissa().parse().map_err(|_| Error::CheckFailed {
        what: format!("number `{n}`"),
    })?;
    let e = n.exponent();
    let ten = BigInt::from(10);
    let scale = ten.pow(e.unsigned_abs());
    Ok(if e >= 0 {
        Q::from_integer(mantissa * scale)
    } else {
        Q::new(mantissa, scale)
    })
}

impl ModelSymbols {
    /// The error of an expression at its place in the model file: `file:line:col: what`.
    fn at(
        &self,
        e: &ModelExpr,
        span: walker_scene::model::Span,
        what: impl std::fmt::Display,
    ) -> Error {
        let l = e.location_of(span);
        Error::CheckFailed {
            what: format!("{}:{l}: {what}", self.path),
        }
    }

    /// The canonical form of a model expression.
    ///
    /// # Errors
    /// An unknown symbol, a `sin`/`cos` argument that is not a combination of the base angles
    /// with integer multiples, or a division by zero: each names the file, line and column.
    pub fn lower(&self, e: &ModelExpr) -> Result<RatFunc> {
        self.lower_node(e, &e.expr)
    }

    fn lower_node(&self, top: &ModelExpr, e: &Expr) -> Result<RatFunc> {
        Ok(match &e.kind {
            ExprKind::Number(n) => RatFunc::constant(number(n)?),
            ExprKind::Symbol(name) => RatFunc::sym(
                self.get(name)
                    .map_err(|_| self.at(top, e.span, format!("unknown symbol `{name}`")))?,
            ),
            ExprKind::Neg(a) => -self.lower_node(top, a)?,
            ExprKind::Binary(op, a, b) => {
                let (a, b) = (self.lower_node(top, a)?, self.lower_node(top, b)?);
                match op {
                    BinOp::Add => a + &b,
                    BinOp::Sub => a - &b,
                    BinOp::Mul => &a * &b,
                    BinOp::Div => a
                        .div(&b)
                        .map_err(|_| self.at(top, e.span, "division by zero"))?,
                }
            }
            ExprKind::Pow(a, n) => {
                let a = self.lower_node(top, a)?;
                // Exponents of the canonical form are bytes, and the derivation multiplies them
                // further: a model's own powers stay small.
                let k = i32::try_from(*n)
                    .ok()
                    .filter(|k| k.abs() <= MAX_EXPONENT)
                    .ok_or_else(|| {
                        self.at(
                            top,
                            e.span,
                            format!("exponent {n} is outside -{MAX_EXPONENT}..={MAX_EXPONENT}"),
                        )
                    })?;
                a.powi(k)
                    .map_err(|_| self.at(top, e.span, "a negative power of zero"))?
            }
            ExprKind::Call(f, arg) => {
                let (s, c) = self.sin_cos(top, arg)?;
                match f {
                    Func::Sin => s,
                    Func::Cos => c,
                }
            }
        })
    }

    /// `sin` and `cos` of an angle combination, by the addition formulas: each angle symbol's
    /// coefficient times its base-angle divisor must be an integer.
    fn sin_cos(&self, top: &ModelExpr, arg: &Expr) -> Result<(RatFunc, RatFunc)> {
        let is_angle = |name: &str| self.get(name).is_ok_and(|s| s.base_angle().is_some());
        let combo = walker_scene::model::angles::angle_combination(arg, &is_angle)
            .map_err(|err| self.at(top, err.span(), err))?;
        let mut terms = Vec::with_capacity(combo.len());
        for (name, coef) in combo {
            let s = self.get(&name)?;
            let Some((base, k)) = s.base_angle() else {
                return Err(self.at(top, arg.span, format!("`{name}` is not an angle")));
            };
            let n = Q::new(coef.numer().into(), coef.denom().into()) * Q::from_integer(k.into());
            if !n.is_integer() {
                return Err(self.at(
                    top,
                    arg.span,
                    format!("`{name}` appears as a fraction of its base angle `{name}/{k}`"),
                ));
            }
            let n: i64 = n
                .to_integer()
                .try_into()
                .map_err(|_| self.at(top, arg.span, "an angle multiple too large"))?;
            if n.unsigned_abs() > super::MAX_ANGLE_MULTIPLE {
                return Err(self.at(
                    top,
                    arg.span,
                    format!(
                        "`{name}` appears as {} times its base angle: at most {}",
                        n.unsigned_abs(),
                        super::MAX_ANGLE_MULTIPLE
                    ),
                ));
            }
            terms.push((base, n));
        }
        let (s, c) = sin_cos_combination(&terms);
        Ok((s.into(), c.into()))
    }
}
