//! The expression parser: text to [`Expr`], by hand-written recursive descent.
//!
//! Hand-written rather than generated because the grammar is tiny (four precedence levels, two
//! functions), because every error must point at an exact byte of the string (the loader turns
//! it into a file column), and because literals must stay exact rationals (`0.163` is
//! `163e-3`, never an `f64`), which a general parser library would not give for free.
//!
//! ```text
//! expr     := term (("+" | "-") term)*            left-associative
//! term     := unary (("*" | "/") unary)*          left-associative
//! unary    := "-" unary | power                   -x^2 is -(x^2)
//! power    := atom ("^" exponent)?                x^2, x^-1, (a + b)^3
//! exponent := "-"? INTEGER | "(" exponent ")"     an integer literal, nothing else
//! atom     := NUMBER | NAME | ("sin" | "cos") "(" expr ")" | "(" expr ")"
//! NUMBER   := DIGITS ("." DIGITS)? (("e" | "E") ("+" | "-")? DIGITS)?
//! NAME     := ASCII letter (ASCII letter | digit | "_")*
//! ```
//!
//! `^` is right-associative in principle, but since an exponent must be an integer literal,
//! `x^2^3` is rejected at `2^3`; write `(x^2)^3`. Trees are at most [`MAX_DEPTH`] levels deep
//! (group a sum of hundreds of terms), so no input can exhaust the stack.

use crate::model::expr::{BinOp, Expr, ExprKind, Func, Number, Span};

/// The deepest expression tree (and bracket nesting) the parser accepts.
pub const MAX_DEPTH: usize = 200;

/// Why an expression did not parse.
#[derive(Clone, PartialEq, Eq, Debug, thiserror::Error)]
pub enum ParseErrorKind {
    /// Nothing, or an operator, where an operand must be.
    #[error("expected an expression {after}")]
    ExpectedExpression {
        /// Where: "after `*`", "at the start", "inside `( )`".
        after: String,
    },
    /// A character outside the grammar.
    #[error("unexpected character `{}`", .0.escape_debug())]
    UnexpectedChar(char),
    /// An operand followed by something that is not an operator.
    #[error("expected an operator or the end of the expression, found `{}`", crate::limits::echo(.0))]
    ExpectedOperator(String),
    /// A `)` without its `(`.
    #[error("`)` without a matching `(`")]
    Unmatched,
    /// A `(` without its `)`.
    #[error("expected `)` to close the `(`, found {}", crate::limits::echo(found))]
    Unclosed {
        /// Byte offset of the `(`.
        open: usize,
        /// What came instead.
        found: String,
    },
    /// A call of a function other than `sin` and `cos`.
    #[error("unknown function `{}`: only sin and cos", crate::limits::echo(.0))]
    UnknownFunction(String),
    /// `sin` or `cos` not followed by `(`.
    #[error("expected `(` after `{0}`")]
    ExpectedParen(&'static str),
    /// An exponent that is not an integer literal.
    #[error("exponent must be an integer literal (`x^2`, `x^-1`)")]
    NonIntegerExponent,
    /// A malformed number.
    #[error("malformed number: {0}")]
    BadNumber(&'static str),
    /// A number or exponent too large to hold.
    #[error("number too large")]
    TooLarge,
    /// A number literal with more significant digits than
    /// [`MAX_NUMBER_DIGITS`](crate::limits::MAX_NUMBER_DIGITS), or a power of ten beyond
    /// [`MAX_NUMBER_EXPONENT`](crate::limits::MAX_NUMBER_EXPONENT).
    #[error(
        "number literal with {digits} significant digits and power of ten {exponent}: expected \
         at most {} digits and a power of ten within +-{}",
        crate::limits::MAX_NUMBER_DIGITS,
        crate::limits::MAX_NUMBER_EXPONENT
    )]
    NumberTooLong {
        /// Its significant digits.
        digits: usize,
        /// The power of ten of its leading digit.
        exponent: i64,
    },
    /// Deeper than [`MAX_DEPTH`].
    #[error("expression nested more than {MAX_DEPTH} levels deep")]
    TooDeep,
}

/// A parse error: what went wrong and where (a byte span inside the expression string).
#[derive(Clone, PartialEq, Eq, Debug, thiserror::Error)]
#[error("{kind}")]
pub struct ParseError {
    /// What was expected.
    pub kind: ParseErrorKind,
    /// Where, in bytes of the expression string; `start <= end <= len`.
    pub span: Span,
}

/// Parses one expression.
///
/// # Errors
///
/// A [`ParseError`] with the span of the offending text and what was expected there.
pub fn parse_expr(text: &str) -> Result<Expr, ParseError> {
    let mut p = Parser {
        text,
        pos: 0,
        depth: 0,
    };
    p.skip_ws();
    if p.pos == text.len() {
        return Err(p.error(
            ParseErrorKind::ExpectedExpression {
                after: "(the string is empty)".to_owned(),
            },
            Span::new(0, 0),
        ));
    }
    let e = p.expr("at the start")?;
    p.skip_ws();
    if p.pos < text.len() {
        let (tok, span) = p.peek_token();
        let kind = if tok == ")" {
            ParseErrorKind::Unmatched
        } else {
            ParseErrorKind::ExpectedOperator(tok)
        };
        return Err(p.error(kind, span));
    }
    Ok(e)
}

struct Parser<'a> {
    text: &'a str,
    pos: usize,
    depth: usize,
}

impl Parser<'_> {
    fn error(&self, kind: ParseErrorKind, span: Span) -> ParseError {
        ParseError { kind, span }
    }

    fn skip_ws(&mut self) {
        while let Some(c) = self.text[self.pos..].chars().next() {
            if c == ' ' || c == '\t' || c == '\n' || c == '\r' {
                self.pos += 1;
            } else {
                break;
            }
        }
    }

    fn peek(&mut self) -> Option<char> {
        self.skip_ws();
        self.text[self.pos..].chars().next()
    }

    /// The next token as text (a name, a number, or one character) and its span, for messages.
    fn peek_token(&mut self) -> (String, Span) {
        self.skip_ws();
        let rest = &self.text[self.pos..];
        let Some(c) = rest.chars().next() else {
            return ("the end".to_owned(), Span::new(self.pos, self.pos));
        };
        let len = if c.is_ascii_alphanumeric() {
            rest.find(|ch: char| !(ch.is_ascii_alphanumeric() || ch == '_' || ch == '.'))
                .unwrap_or(rest.len())
        } else {
            c.len_utf8()
        };
        (rest[..len].to_owned(), Span::new(self.pos, self.pos + len))
    }

    fn describe_next(&mut self) -> String {
        let (tok, _) = self.peek_token();
        if tok == "the end" {
            tok
        } else {
            format!("`{tok}`")
        }
    }

    fn enter(&mut self) -> Result<(), ParseError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(self.error(ParseErrorKind::TooDeep, Span::new(self.pos, self.pos)));
        }
        Ok(())
    }

    /// Builds a node, rejecting trees deeper than [`MAX_DEPTH`].
    fn node(&self, kind: ExprKind, span: Span) -> Result<Expr, ParseError> {
        let e = Expr::new(kind, span);
        if depth(&e) > MAX_DEPTH {
            return Err(self.error(ParseErrorKind::TooDeep, span));
        }
        Ok(e)
    }

    fn expr(&mut self, context: &str) -> Result<Expr, ParseError> {
        self.enter()?;
        let mut lhs = self.term(context)?;
        loop {
            let op = match self.peek() {
                Some('+') => BinOp::Add,
                Some('-') => BinOp::Sub,
                _ => break,
            };
            self.pos += 1;
            let rhs = self.term(&format!("after `{}`", op.symbol()))?;
            let span = lhs.span.to(rhs.span);
            lhs = self.node(ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)), span)?;
        }
        self.depth -= 1;
        Ok(lhs)
    }

    fn term(&mut self, context: &str) -> Result<Expr, ParseError> {
        let mut lhs = self.unary(context)?;
        loop {
            let op = match self.peek() {
                Some('*') => BinOp::Mul,
                Some('/') => BinOp::Div,
                _ => break,
            };
            self.pos += 1;
            let rhs = self.unary(&format!("after `{}`", op.symbol()))?;
            let span = lhs.span.to(rhs.span);
            lhs = self.node(ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)), span)?;
        }
        Ok(lhs)
    }

    fn unary(&mut self, context: &str) -> Result<Expr, ParseError> {
        if self.peek() == Some('-') {
            self.enter()?;
            let start = self.pos;
            self.pos += 1;
            let inner = self.unary("after `-`")?;
            let span = Span::new(start, inner.span.end);
            self.depth -= 1;
            return self.node(ExprKind::Neg(Box::new(inner)), span);
        }
        self.power(context)
    }

    fn power(&mut self, context: &str) -> Result<Expr, ParseError> {
        let base = self.atom(context)?;
        if self.peek() != Some('^') {
            return Ok(base);
        }
        self.pos += 1;
        let (n, end) = self.exponent()?;
        let span = Span::new(base.span.start, end);
        self.node(ExprKind::Pow(Box::new(base), n), span)
    }

    /// `"-"? INTEGER | "(" exponent ")"`; returns the value and the end of its text.
    fn exponent(&mut self) -> Result<(i64, usize), ParseError> {
        self.enter()?;
        self.skip_ws();
        let start = self.pos;
        let result = match self.peek() {
            Some('(') => {
                self.pos += 1;
                let (n, _) = self.exponent()?;
                if self.peek() != Some(')') {
                    let found = self.describe_next();
                    let (_, span) = self.peek_token();
                    return Err(self.error(ParseErrorKind::Unclosed { open: start, found }, span));
                }
                self.pos += 1;
                (n, self.pos)
            }
            Some('-') => {
                self.pos += 1;
                let (n, end) = self.exponent_integer(start)?;
                (-n, end)
            }
            Some(c) if c.is_ascii_digit() => self.exponent_integer(start)?,
            None => {
                return Err(self.error(
                    ParseErrorKind::ExpectedExpression {
                        after: "after `^`".to_owned(),
                    },
                    Span::new(self.pos, self.pos),
                ));
            }
            Some(_) => return Err(self.non_integer_exponent(start)),
        };
        self.depth -= 1;
        Ok(result)
    }

    fn exponent_integer(&mut self, start: usize) -> Result<(i64, usize), ParseError> {
        if !self.peek().is_some_and(|c| c.is_ascii_digit()) {
            return Err(self.non_integer_exponent(start));
        }
        let digits_start = self.pos;
        let len = self.text[self.pos..]
            .find(|c: char| !c.is_ascii_digit())
            .unwrap_or(self.text.len() - self.pos);
        let end = self.pos + len;
        // `2.5`, `2e3` or `2x` after `^` are not integer literals.
        if self.text[end..]
            .chars()
            .next()
            .is_some_and(|c| c == '.' || c.is_ascii_alphanumeric() || c == '_')
        {
            return Err(self.non_integer_exponent(start));
        }
        let n: i64 = self.text[digits_start..end]
            .parse()
            .map_err(|_| self.error(ParseErrorKind::TooLarge, Span::new(digits_start, end)))?;
        self.pos = end;
        // `x^2^3` would be `x^(2^3)`: an exponent that is not a literal.
        if self.peek() == Some('^') {
            return Err(self.non_integer_exponent(start));
        }
        self.pos = end;
        Ok((n, end))
    }

    /// The error for a bad exponent, spanning the token that follows `^`.
    fn non_integer_exponent(&mut self, start: usize) -> ParseError {
        self.pos = start;
        let (_, span) = self.peek_token();
        self.error(
            ParseErrorKind::NonIntegerExponent,
            Span::new(start, span.end.max(start)),
        )
    }

    fn atom(&mut self, context: &str) -> Result<Expr, ParseError> {
        let Some(c) = self.peek() else {
            return Err(self.error(
                ParseErrorKind::ExpectedExpression {
                    after: context.to_owned(),
                },
                Span::new(self.pos, self.pos),
            ));
        };
        let start = self.pos;
        if c == '(' {
            self.enter()?;
            self.pos += 1;
            if self.peek() == Some(')') {
                return Err(self.error(
                    ParseErrorKind::ExpectedExpression {
                        after: "inside `( )`".to_owned(),
                    },
                    Span::new(start, self.pos + 1),
                ));
            }
            let inner = self.expr("after `(`")?;
            if self.peek() != Some(')') {
                let found = self.describe_next();
                let (_, span) = self.peek_token();
                return Err(self.error(ParseErrorKind::Unclosed { open: start, found }, span));
            }
            self.pos += 1;
            self.depth -= 1;
            // Brackets only group: the node keeps its own kind, with the brackets' span.
            return Ok(Expr::new(inner.kind, Span::new(start, self.pos)));
        }
        if c.is_ascii_digit() {
            return self.number();
        }
        if c.is_ascii_alphabetic() {
            let len = self.text[start..]
                .find(|ch: char| !(ch.is_ascii_alphanumeric() || ch == '_'))
                .unwrap_or(self.text.len() - start);
            let name = &self.text[start..start + len];
            self.pos = start + len;
            let name_span = Span::new(start, start + len);
            let func = match name {
                "sin" => Some(Func::Sin),
                "cos" => Some(Func::Cos),
                _ => None,
            };
            let paren = self.peek() == Some('(');
            return match (func, paren) {
                (Some(func), true) => {
                    self.enter()?;
                    let open = self.pos;
                    self.pos += 1;
                    if self.peek() == Some(')') {
                        return Err(self.error(
                            ParseErrorKind::ExpectedExpression {
                                after: format!("inside `{}( )`", func.name()),
                            },
                            Span::new(open, self.pos + 1),
                        ));
                    }
                    let arg = self.expr(&format!("after `{}(`", func.name()))?;
                    if self.peek() != Some(')') {
                        let found = self.describe_next();
                        let (_, span) = self.peek_token();
                        return Err(self.error(ParseErrorKind::Unclosed { open, found }, span));
                    }
                    self.pos += 1;
                    self.depth -= 1;
                    self.node(
                        ExprKind::Call(func, Box::new(arg)),
                        Span::new(start, self.pos),
                    )
                }
                (Some(func), false) => {
                    Err(self.error(ParseErrorKind::ExpectedParen(func.name()), name_span))
                }
                (None, true) => {
                    Err(self.error(ParseErrorKind::UnknownFunction(name.to_owned()), name_span))
                }
                (None, false) => Ok(Expr::new(ExprKind::Symbol(name.to_owned()), name_span)),
            };
        }
        match c {
            '+' | '*' | '/' | '^' | ')' => Err(self.error(
                ParseErrorKind::ExpectedExpression {
                    after: format!("{context}, found `{c}`"),
                },
                Span::new(start, start + 1),
            )),
            _ => Err(self.error(
                ParseErrorKind::UnexpectedChar(c),
                Span::new(start, start + c.len_utf8()),
            )),
        }
    }

    fn number(&mut self) -> Result<Expr, ParseError> {
        let start = self.pos;
        let bytes = self.text.as_bytes();
        let digits = |from: usize| {
            bytes[from..]
                .iter()
                .position(|b| !b.is_ascii_digit())
                .map_or(bytes.len(), |i| from + i)
        };
        let int_end = digits(start);
        let mut mantissa = self.text[start..int_end].to_owned();
        let mut exponent: i64 = 0;
        let mut end = int_end;
        if bytes.get(end) == Some(&b'.') {
            let frac_end = digits(end + 1);
            if frac_end == end + 1 {
                return Err(self.error(
                    ParseErrorKind::BadNumber("expected a digit after `.`"),
                    Span::new(start, end + 1),
                ));
            }
            mantissa.push_str(&self.text[end + 1..frac_end]);
            exponent = -i64::try_from(frac_end - end - 1)
                .map_err(|_| self.error(ParseErrorKind::TooLarge, Span::new(start, frac_end)))?;
            end = frac_end;
        }
        if matches!(bytes.get(end), Some(b'e' | b'E')) {
            let mut exp_start = end + 1;
            let negative = bytes.get(exp_start) == Some(&b'-');
            if matches!(bytes.get(exp_start), Some(b'+' | b'-')) {
                exp_start += 1;
            }
            let exp_end = digits(exp_start);
            if exp_end == exp_start {
                return Err(self.error(
                    ParseErrorKind::BadNumber("expected the exponent's digits after `e`"),
                    Span::new(start, exp_start),
                ));
            }
            let e: i64 = self.text[exp_start..exp_end]
                .parse()
                .map_err(|_| self.error(ParseErrorKind::TooLarge, Span::new(start, exp_end)))?;
            let e = if negative { -e } else { e };
            exponent = exponent
                .checked_add(e)
                .ok_or_else(|| self.error(ParseErrorKind::TooLarge, Span::new(start, exp_end)))?;
            end = exp_end;
        }
        if bytes
            .get(end)
            .is_some_and(|b| b.is_ascii_alphanumeric() || *b == b'_' || *b == b'.')
        {
            return Err(self.error(
                ParseErrorKind::BadNumber("a number must not run into a name or another `.`"),
                Span::new(start, end + 1),
            ));
        }
        self.pos = end;
        let span = Span::new(start, end);
        let n = Number::new(&mantissa, exponent)
            .ok_or_else(|| self.error(ParseErrorKind::TooLarge, span))?;
        let digits = n.mantissa().len();
        let lead = i64::try_from(digits)
            .ok()
            .and_then(|d| n.exponent().checked_add(d - 1))
            .unwrap_or(i64::MAX);
        if !n.is_zero()
            && (digits > crate::limits::MAX_NUMBER_DIGITS
                || lead.unsigned_abs() > crate::limits::MAX_NUMBER_EXPONENT.unsigned_abs())
        {
            return Err(self.error(
                ParseErrorKind::NumberTooLong {
                    digits,
                    exponent: lead,
                },
                span,
            ));
        }
        Ok(Expr::new(ExprKind::Number(n), span))
    }
}

/// The depth of a tree, counting only as deep as the first level past [`MAX_DEPTH`] (so it
/// stays cheap on the parser's own growing trees: each node's children were checked already).
fn depth(e: &Expr) -> usize {
    fn go(e: &Expr, limit: usize) -> usize {
        if limit == 0 {
            return 1;
        }
        1 + match &e.kind {
            ExprKind::Number(_) | ExprKind::Symbol(_) => 0,
            ExprKind::Neg(a) | ExprKind::Pow(a, _) | ExprKind::Call(_, a) => go(a, limit - 1),
            ExprKind::Binary(_, a, b) => go(a, limit - 1).max(go(b, limit - 1)),
        }
    }
    go(e, MAX_DEPTH + 1)
}
