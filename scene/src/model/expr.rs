//! The expression AST of model files: exact numbers, symbols, `+ - * /`, unary minus, integer
//! powers, `sin` and `cos`, each node with the byte span it came from; and the pretty-printer
//! whose output parses back to the same tree.

use std::fmt;

/// A byte range `start..end` inside the expression string.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Default)]
pub struct Span {
    /// The first byte.
    pub start: usize,
    /// One past the last byte.
    pub end: usize,
}

impl Span {
    /// The span from `start` to `end`.
    #[must_use]
    pub fn new(start: usize, end: usize) -> Span {
        Span { start, end }
    }

    /// The smallest span covering both.
    #[must_use]
    pub fn to(self, other: Span) -> Span {
        Span::new(self.start.min(other.start), self.end.max(other.end))
    }
}

/// An exact, non-negative decimal number: `mantissa * 10^exponent`.
///
/// Normalised when parsed: the mantissa has no leading zeros and no trailing zeros (the trailing
/// zeros move into the exponent), and zero is `0e0`. So `0.163` is `163e-3`, `1e-3` is `1e-3`,
/// `100` is `1e2`, and two numbers are equal exactly when their values are.
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub struct Number {
    mantissa: String,
    exponent: i64,
}

impl Number {
    /// The number `mantissa * 10^exponent`, normalised; `None` if `mantissa` is empty, has a
    /// character other than a decimal digit, or the normalised exponent overflows.
    #[must_use]
    pub fn new(mantissa: &str, exponent: i64) -> Option<Number> {
        if mantissa.is_empty() || !mantissa.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        let trimmed = mantissa.trim_start_matches('0');
        if trimmed.is_empty() {
            return Some(Number {
                mantissa: "0".to_owned(),
                exponent: 0,
            });
        }
        let digits = trimmed.trim_end_matches('0');
        let zeros = i64::try_from(trimmed.len() - digits.len()).ok()?;
        Some(Number {
            mantissa: digits.to_owned(),
            exponent: exponent.checked_add(zeros)?,
        })
    }

    /// The integer `n`.
    #[must_use]
    pub fn integer(n: u64) -> Number {
        Number::new(&n.to_string(), 0).unwrap_or(Number {
            mantissa: "0".to_owned(),
            exponent: 0,
        })
    }

    /// The decimal digits of the mantissa (no leading or trailing zeros; `"0"` for zero).
    #[must_use]
    pub fn mantissa(&self) -> &str {
        &self.mantissa
    }

    /// The power of ten.
    #[must_use]
    pub fn exponent(&self) -> i64 {
        self.exponent
    }

    /// Whether the number is zero.
    #[must_use]
    pub fn is_zero(&self) -> bool {
        self.mantissa == "0"
    }

    /// The nearest `f64` (for defaults and plots; the derivation keeps the exact value).
    #[must_use]
    pub fn to_f64(&self) -> f64 {
        format!("{}e{}", self.mantissa, self.exponent)
            .parse()
            .unwrap_or(f64::NAN)
    }
}

impl fmt::Display for Number {
    /// Plain decimals while short (`12`, `0.163`, `1500`), else `163e-30`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let digits = self.mantissa.len() as i64;
        match self.exponent {
            0 => f.write_str(&self.mantissa),
            e @ 1..=6 => write!(f, "{}{}", self.mantissa, "0".repeat(e as usize)),
            e if e < 0 && -e < digits => {
                let point = (digits + e) as usize;
                write!(f, "{}.{}", &self.mantissa[..point], &self.mantissa[point..])
            }
            e if e < 0 && -e - digits <= 6 => {
                write!(
                    f,
                    "0.{}{}",
                    "0".repeat((-e - digits) as usize),
                    self.mantissa
                )
            }
            e => write!(f, "{}e{}", self.mantissa, e),
        }
    }
}

/// A built-in function of an angle combination.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub enum Func {
    /// `sin`.
    Sin,
    /// `cos`.
    Cos,
}

impl Func {
    /// The name as written.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Func::Sin => "sin",
            Func::Cos => "cos",
        }
    }
}

/// A binary operator.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub enum BinOp {
    /// `+`.
    Add,
    /// `-`.
    Sub,
    /// `*`.
    Mul,
    /// `/`.
    Div,
}

impl BinOp {
    /// The operator as written.
    #[must_use]
    pub fn symbol(self) -> char {
        match self {
            BinOp::Add => '+',
            BinOp::Sub => '-',
            BinOp::Mul => '*',
            BinOp::Div => '/',
        }
    }
}

/// What an expression node is.
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub enum ExprKind {
    /// An exact number literal.
    Number(Number),
    /// A symbol, by name (resolved against the model's symbol table by the loader).
    Symbol(String),
    /// Unary minus.
    Neg(Box<Expr>),
    /// A binary operation.
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// A power by an integer literal, `x^2`, `x^-1`.
    Pow(Box<Expr>, i64),
    /// `sin(..)` or `cos(..)`.
    Call(Func, Box<Expr>),
}

/// An expression with the span of the text it was parsed from.
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub struct Expr {
    /// What it is.
    pub kind: ExprKind,
    /// Where it is in the expression string.
    pub span: Span,
}

impl Expr {
    /// A node.
    #[must_use]
    pub fn new(kind: ExprKind, span: Span) -> Expr {
        Expr { kind, span }
    }

    /// Whether two trees are the same apart from their spans.
    #[must_use]
    pub fn same_as(&self, other: &Expr) -> bool {
        match (&self.kind, &other.kind) {
            (ExprKind::Number(a), ExprKind::Number(b)) => a == b,
            (ExprKind::Symbol(a), ExprKind::Symbol(b)) => a == b,
            (ExprKind::Neg(a), ExprKind::Neg(b)) => a.same_as(b),
            (ExprKind::Binary(o, a, b), ExprKind::Binary(p, c, d)) => {
                o == p && a.same_as(c) && b.same_as(d)
            }
            (ExprKind::Pow(a, n), ExprKind::Pow(b, m)) => n == m && a.same_as(b),
            (ExprKind::Call(f, a), ExprKind::Call(g, b)) => f == g && a.same_as(b),
            _ => false,
        }
    }

    /// Every symbol in the tree, with its span, in reading order.
    #[must_use]
    pub fn symbols(&self) -> Vec<(&str, Span)> {
        let mut out = Vec::new();
        self.visit(&mut |e| {
            if let ExprKind::Symbol(name) = &e.kind {
                out.push((name.as_str(), e.span));
            }
        });
        out
    }

    /// Calls `f` on every node, parents before children, left before right.
    pub fn visit<'a>(&'a self, f: &mut impl FnMut(&'a Expr)) {
        f(self);
        match &self.kind {
            ExprKind::Number(_) | ExprKind::Symbol(_) => {}
            ExprKind::Neg(a) | ExprKind::Pow(a, _) | ExprKind::Call(_, a) => a.visit(f),
            ExprKind::Binary(_, a, b) => {
                a.visit(f);
                b.visit(f);
            }
        }
    }

    /// The value of the expression in floating point, with each symbol's value from `value`;
    /// `None` if a symbol has none. Evaluated as written, left to right (`-alpha/2` is
    /// `(-alpha) / 2`), with `sin`, `cos` and `powi` of the standard library: what the simulator
    /// uses for the expressions it evaluates at run time (desired trajectories, the start, the
    /// section, masses), never for a kernel.
    #[must_use]
    pub fn eval(&self, value: &dyn Fn(&str) -> Option<f64>) -> Option<f64> {
        Some(match &self.kind {
            ExprKind::Number(n) => n.to_f64(),
            ExprKind::Symbol(s) => value(s)?,
            ExprKind::Neg(a) => -a.eval(value)?,
            ExprKind::Binary(op, a, b) => {
                let (a, b) = (a.eval(value)?, b.eval(value)?);
                match op {
                    BinOp::Add => a + b,
                    BinOp::Sub => a - b,
                    BinOp::Mul => a * b,
                    BinOp::Div => a / b,
                }
            }
            ExprKind::Pow(a, n) => a.eval(value)?.powi(i32::try_from(*n).ok()?),
            ExprKind::Call(Func::Sin, a) => a.eval(value)?.sin(),
            ExprKind::Call(Func::Cos, a) => a.eval(value)?.cos(),
        })
    }

    /// The derivative of the expression with respect to the symbol `name`, unsimplified (for
    /// evaluation): `d sin(a) = cos(a) da`, `d x^k = k x^(k-1) dx`, and so on.
    #[must_use]
    pub fn derivative(&self, name: &str) -> Expr {
        let span = self.span;
        let num = |k: u64| Expr::new(ExprKind::Number(Number::integer(k)), span);
        let bin =
            |op, a: Expr, b: Expr| Expr::new(ExprKind::Binary(op, Box::new(a), Box::new(b)), span);
        match &self.kind {
            ExprKind::Number(_) => num(0),
            ExprKind::Symbol(s) => num(u64::from(s == name)),
            ExprKind::Neg(a) => Expr::new(ExprKind::Neg(Box::new(a.derivative(name))), span),
            ExprKind::Binary(op, a, b) => {
                let (da, db) = (a.derivative(name), b.derivative(name));
                match op {
                    BinOp::Add | BinOp::Sub => bin(*op, da, db),
                    BinOp::Mul => bin(
                        BinOp::Add,
                        bin(BinOp::Mul, da, (**b).clone()),
                        bin(BinOp::Mul, (**a).clone(), db),
                    ),
                    BinOp::Div => bin(
                        BinOp::Div,
                        bin(
                            BinOp::Sub,
                            bin(BinOp::Mul, da, (**b).clone()),
                            bin(BinOp::Mul, (**a).clone(), db),
                        ),
                        Expr::new(ExprKind::Pow(b.clone(), 2), span),
                    ),
                }
            }
            ExprKind::Pow(a, k) => {
                let coefficient =
                    Expr::new(ExprKind::Number(Number::integer(k.unsigned_abs())), span);
                let coefficient = if *k < 0 {
                    Expr::new(ExprKind::Neg(Box::new(coefficient)), span)
                } else {
                    coefficient
                };
                bin(
                    BinOp::Mul,
                    bin(
                        BinOp::Mul,
                        coefficient,
                        Expr::new(ExprKind::Pow(a.clone(), k - 1), span),
                    ),
                    a.derivative(name),
                )
            }
            ExprKind::Call(Func::Sin, a) => bin(
                BinOp::Mul,
                Expr::new(ExprKind::Call(Func::Cos, a.clone()), span),
                a.derivative(name),
            ),
            ExprKind::Call(Func::Cos, a) => Expr::new(
                ExprKind::Neg(Box::new(bin(
                    BinOp::Mul,
                    Expr::new(ExprKind::Call(Func::Sin, a.clone()), span),
                    a.derivative(name),
                ))),
                span,
            ),
        }
    }

    /// Binding strength for printing: sums 1, products 2, unary minus 3, powers 4, atoms 5.
    fn precedence(&self) -> u8 {
        match &self.kind {
            ExprKind::Binary(BinOp::Add | BinOp::Sub, ..) => 1,
            ExprKind::Binary(BinOp::Mul | BinOp::Div, ..) => 2,
            ExprKind::Neg(_) => 3,
            ExprKind::Pow(..) => 4,
            ExprKind::Number(_) | ExprKind::Symbol(_) | ExprKind::Call(..) => 5,
        }
    }
}

/// Writes `e`, in parentheses when it binds looser than `min`.
fn write_operand(f: &mut fmt::Formatter<'_>, e: &Expr, min: u8) -> fmt::Result {
    if e.precedence() < min {
        write!(f, "({e})")
    } else {
        write!(f, "{e}")
    }
}

impl fmt::Display for Expr {
    /// The expression with the fewest parentheses that parse back to the same tree.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.kind {
            ExprKind::Number(n) => write!(f, "{n}"),
            ExprKind::Symbol(s) => f.write_str(s),
            ExprKind::Neg(a) => {
                f.write_str("-")?;
                write_operand(f, a, 3)
            }
            ExprKind::Binary(op, a, b) => {
                let p = self.precedence();
                write_operand(f, a, p)?;
                write!(f, " {} ", op.symbol())?;
                // Left-associative: an operand of the same strength on the right needs brackets.
                write_operand(f, b, p + 1)
            }
            ExprKind::Pow(a, n) => {
                // A power's base is an atom; `(x^2)^3` keeps its brackets.
                write_operand(f, a, 5)?;
                write!(f, "^{n}")
            }
            ExprKind::Call(func, a) => write!(f, "{}({a})", func.name()),
        }
    }
}
