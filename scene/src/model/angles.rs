//! Angle combinations on the expression AST: reading `sin`/`cos` arguments as sums of angle
//! symbols with rational coefficients, finding an angle used as a length, the least common
//! denominator of each angle's coefficients (its *base angle* divisor), and constant divisors
//! that are exactly zero.
//!
//! Which symbols are angles is the caller's (the model's) business: every function takes an
//! `is_angle` predicate.

use std::collections::BTreeMap;

use crate::model::expr::{BinOp, Expr, ExprKind, Func, Span};
use crate::model::rational::{Rational, lcm};

/// Why an expression is not an angle combination.
#[derive(Clone, PartialEq, Eq, Debug, thiserror::Error)]
pub enum AngleError {
    /// A symbol that is not an angle.
    #[error("`{name}` is not an angle")]
    NotAnAngle {
        /// The symbol.
        name: String,
        /// Where.
        span: Span,
    },
    /// A product, quotient or power of angles.
    #[error("`{text}` is not linear in the angles")]
    Nonlinear {
        /// The offending sub-expression, printed.
        text: String,
        /// Where.
        span: Span,
    },
    /// A `sin` or `cos` inside the argument.
    #[error("`{text}` is a function, not an angle")]
    Function {
        /// The offending sub-expression, printed.
        text: String,
        /// Where.
        span: Span,
    },
    /// A constant term, as in `th1 + 1`.
    #[error("it has a constant term `{value}` (only angle symbols with rational coefficients)")]
    Constant {
        /// The constant.
        value: Rational,
        /// Where (the whole argument).
        span: Span,
    },
    /// Division by a constant that is zero.
    #[error("division by zero")]
    DivisionByZero {
        /// The divisor.
        span: Span,
    },
    /// A coefficient too large for 64 bits.
    #[error("a coefficient is too large")]
    Overflow {
        /// Where.
        span: Span,
    },
}

impl AngleError {
    /// Where in the expression string.
    #[must_use]
    pub fn span(&self) -> Span {
        match self {
            AngleError::NotAnAngle { span, .. }
            | AngleError::Nonlinear { span, .. }
            | AngleError::Function { span, .. }
            | AngleError::Constant { span, .. }
            | AngleError::DivisionByZero { span }
            | AngleError::Overflow { span } => *span,
        }
    }
}

/// An affine form `constant + sum coefficient * angle`.
#[derive(Clone, PartialEq, Eq, Debug, Default)]
pub struct Linear {
    /// The constant term.
    pub constant: Option<Rational>,
    /// The angles' coefficients, by name (zero coefficients dropped).
    pub terms: BTreeMap<String, Rational>,
}

impl Linear {
    fn constant(c: Rational) -> Linear {
        Linear {
            constant: Some(c),
            terms: BTreeMap::new(),
        }
    }

    fn constant_part(&self) -> Rational {
        self.constant.unwrap_or(Rational::ZERO)
    }

    fn scale(mut self, k: Rational, span: Span) -> Result<Linear, AngleError> {
        let over = || AngleError::Overflow { span };
        self.constant = Some(self.constant_part().checked_mul(k).ok_or_else(over)?);
        for c in self.terms.values_mut() {
            *c = c.checked_mul(k).ok_or_else(over)?;
        }
        self.terms.retain(|_, c| !c.is_zero());
        Ok(self)
    }

    fn plus(mut self, o: Linear, span: Span) -> Result<Linear, AngleError> {
        let over = || AngleError::Overflow { span };
        self.constant = Some(
            self.constant_part()
                .checked_add(o.constant_part())
                .ok_or_else(over)?,
        );
        for (name, c) in o.terms {
            let sum = self
                .terms
                .get(&name)
                .copied()
                .unwrap_or(Rational::ZERO)
                .checked_add(c)
                .ok_or_else(over)?;
            self.terms.insert(name, sum);
        }
        self.terms.retain(|_, c| !c.is_zero());
        Ok(self)
    }
}

/// `e` as an affine form in the angles, or why it is not one.
///
/// # Errors
///
/// A symbol that is not an angle, a product or power of angles, a function, a zero divisor,
/// or a coefficient that overflows.
pub fn linear(e: &Expr, is_angle: &impl Fn(&str) -> bool) -> Result<Linear, AngleError> {
    let over = || AngleError::Overflow { span: e.span };
    match &e.kind {
        ExprKind::Number(n) => Ok(Linear::constant(Rational::from_number(n).ok_or_else(over)?)),
        ExprKind::Symbol(name) => {
            if is_angle(name) {
                let mut l = Linear::constant(Rational::ZERO);
                l.terms.insert(name.clone(), Rational::ONE);
                Ok(l)
            } else {
                Err(AngleError::NotAnAngle {
                    name: name.clone(),
                    span: e.span,
                })
            }
        }
        ExprKind::Neg(a) => {
            linear(a, is_angle)?.scale(Rational::ONE.checked_neg().ok_or_else(over)?, e.span)
        }
        ExprKind::Binary(op, a, b) => {
            let (la, lb) = (linear(a, is_angle)?, linear(b, is_angle)?);
            let nonlinear = || AngleError::Nonlinear {
                text: e.to_string(),
                span: e.span,
            };
            match op {
                BinOp::Add => la.plus(lb, e.span),
                BinOp::Sub => la.plus(
                    lb.scale(Rational::ONE.checked_neg().ok_or_else(over)?, e.span)?,
                    e.span,
                ),
                BinOp::Mul if la.terms.is_empty() => lb.scale(la.constant_part(), e.span),
                BinOp::Mul if lb.terms.is_empty() => la.scale(lb.constant_part(), e.span),
                BinOp::Mul => Err(nonlinear()),
                BinOp::Div if lb.terms.is_empty() => {
                    if lb.constant_part().is_zero() {
                        return Err(AngleError::DivisionByZero { span: b.span });
                    }
                    let k = Rational::ONE
                        .checked_div(lb.constant_part())
                        .ok_or_else(over)?;
                    la.scale(k, e.span)
                }
                BinOp::Div => Err(nonlinear()),
            }
        }
        ExprKind::Pow(a, n) => {
            let la = linear(a, is_angle)?;
            if !la.terms.is_empty() {
                // `th1^1` is linear, but a power of an angle is almost surely a mistake.
                return Err(AngleError::Nonlinear {
                    text: e.to_string(),
                    span: e.span,
                });
            }
            let c = la.constant_part();
            if c.is_zero() && *n < 0 {
                return Err(AngleError::DivisionByZero { span: a.span });
            }
            Ok(Linear::constant(c.pow(*n).ok_or_else(over)?))
        }
        ExprKind::Call(..) => Err(AngleError::Function {
            text: e.to_string(),
            span: e.span,
        }),
    }
}

/// `e` as an angle combination (a sum of angles with rational coefficients, no constant
/// term): the coefficients by angle name.
///
/// # Errors
///
/// As [`linear`], and [`AngleError::Constant`] for a non-zero constant term.
pub fn angle_combination(
    e: &Expr,
    is_angle: &impl Fn(&str) -> bool,
) -> Result<BTreeMap<String, Rational>, AngleError> {
    let l = linear(e, is_angle)?;
    match l.constant {
        Some(c) if !c.is_zero() => Err(AngleError::Constant {
            value: c,
            span: e.span,
        }),
        _ => Ok(l.terms),
    }
}

/// Checks every `sin`/`cos` argument in `e` is an angle combination.
///
/// # Errors
///
/// The first function whose argument is not one, with the reason.
pub fn check_trig_arguments(
    e: &Expr,
    is_angle: &impl Fn(&str) -> bool,
) -> Result<(), (Func, AngleError)> {
    let mut result = Ok(());
    e.visit(&mut |node| {
        if let (Ok(()), ExprKind::Call(func, arg)) = (&result, &node.kind)
            && let Err(err) = angle_combination(arg, is_angle)
        {
            result = Err((*func, err));
        }
    });
    result
}

/// The first angle symbol outside every `sin`/`cos` (an angle used as a length), if any.
#[must_use]
pub fn angle_outside_trig<'a>(
    e: &'a Expr,
    is_angle: &impl Fn(&str) -> bool,
) -> Option<(&'a str, Span)> {
    match &e.kind {
        ExprKind::Number(_) | ExprKind::Call(..) => None,
        ExprKind::Symbol(name) => is_angle(name).then_some((name.as_str(), e.span)),
        ExprKind::Neg(a) | ExprKind::Pow(a, _) => angle_outside_trig(a, is_angle),
        ExprKind::Binary(_, a, b) => {
            angle_outside_trig(a, is_angle).or_else(|| angle_outside_trig(b, is_angle))
        }
    }
}

/// Adds to `out`, for each angle, the least common multiple of the denominators of its
/// coefficients in `e`: inside every `sin`/`cos` argument, and, when `additive` is set, in the
/// additive terms of `e` itself that are rational multiples of angle combinations (a guard's
/// `alpha/2`, a relabelling's `th1 - alpha`: values that the derivation substitutes into the
/// sines and cosines of the coordinates).
///
/// # Errors
///
/// A `sin`/`cos` argument that is not an angle combination, or a denominator too large.
pub fn add_denominators(
    e: &Expr,
    is_angle: &impl Fn(&str) -> bool,
    additive: bool,
    out: &mut BTreeMap<String, u64>,
) -> Result<(), AngleError> {
    let mut record = |terms: &BTreeMap<String, Rational>, span: Span| {
        for (name, c) in terms {
            let d = c.denom().unsigned_abs();
            let entry = out.entry(name.clone()).or_insert(1);
            *entry = lcm(*entry, d).ok_or(AngleError::Overflow { span })?;
        }
        Ok::<(), AngleError>(())
    };
    let mut calls = Vec::new();
    e.visit(&mut |node| {
        if let ExprKind::Call(_, arg) = &node.kind {
            calls.push(arg.as_ref());
        }
    });
    for arg in calls {
        record(&angle_combination(arg, is_angle)?, arg.span)?;
    }
    if additive {
        let mut terms = Vec::new();
        additive_terms(e, is_angle, &mut terms);
        for (t, span) in terms {
            record(&t, span)?;
        }
    }
    Ok(())
}

/// The angle coefficients of the additive terms of `e` that are affine in the angles.
fn additive_terms(
    e: &Expr,
    is_angle: &impl Fn(&str) -> bool,
    out: &mut Vec<(BTreeMap<String, Rational>, Span)>,
) {
    if let Ok(l) = linear(e, is_angle) {
        out.push((l.terms, e.span));
        return;
    }
    match &e.kind {
        ExprKind::Neg(a) => additive_terms(a, is_angle, out),
        ExprKind::Binary(BinOp::Add | BinOp::Sub, a, b) => {
            additive_terms(a, is_angle, out);
            additive_terms(b, is_angle, out);
        }
        _ => {}
    }
}

/// The span of a divisor (or the base of a negative power) that is a constant equal to zero,
/// as in `x/0` or `x/(1 - 1)`. Divisors with symbols are left to the derivation.
#[must_use]
pub fn zero_divisor(e: &Expr) -> Option<Span> {
    let no_angles = |_: &str| false;
    let is_zero = |d: &Expr| {
        d.symbols().is_empty()
            && matches!(linear(d, &no_angles), Ok(l) if l.constant_part().is_zero())
    };
    let mut found = None;
    e.visit(&mut |node| {
        if found.is_some() {
            return;
        }
        match &node.kind {
            ExprKind::Binary(BinOp::Div, _, d) if is_zero(d) => found = Some(d.span),
            ExprKind::Pow(b, n) if *n < 0 && is_zero(b) => found = Some(b.span),
            _ => {}
        }
    });
    found
}
