//! Interval enclosures of an expression over the parameters' ranges: a range of values that
//! surely holds every value the expression takes while each parameter stays in its declared
//! range (interval arithmetic, with open and closed ends), so that a mass can be shown positive
//! for every admissible parameter set and not only at the defaults. An enclosure may be wider
//! than the true range (`m1 - m1` encloses `(-inf, inf)` with `m1` in `(0, inf)`); it is never
//! narrower.

use std::f64::consts::{FRAC_PI_2, PI};

use crate::model::expr::{BinOp, Expr, ExprKind, Func};

/// One end of an enclosure: its value and whether the expression can take it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct End {
    /// The value (may be infinite).
    pub(crate) value: f64,
    /// Whether the value itself is excluded (an open end).
    pub(crate) open: bool,
}

/// A range of values, `lo` to `hi`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Enclosure {
    /// The lower end.
    pub(crate) lo: End,
    /// The upper end.
    pub(crate) hi: End,
}

const fn end(value: f64, open: bool) -> End {
    End { value, open }
}

/// Everything: what an operation whose range is not known encloses.
const WHOLE: Enclosure = Enclosure {
    lo: end(f64::NEG_INFINITY, true),
    hi: end(f64::INFINITY, true),
};

impl Enclosure {
    /// The single value `x`.
    pub(crate) fn point(x: f64) -> Enclosure {
        Enclosure {
            lo: end(x, false),
            hi: end(x, false),
        }
    }

    /// Whether every value is positive.
    pub(crate) fn positive(&self) -> bool {
        self.lo.value > 0.0 || (self.lo.value == 0.0 && self.lo.open)
    }

    fn neg(self) -> Enclosure {
        Enclosure {
            lo: end(-self.hi.value, self.hi.open),
            hi: end(-self.lo.value, self.lo.open),
        }
    }

    fn add(self, o: Enclosure) -> Enclosure {
        let lo = self.lo.value + o.lo.value;
        let hi = self.hi.value + o.hi.value;
        if lo.is_nan() || hi.is_nan() {
            return WHOLE;
        }
        Enclosure {
            lo: end(lo, self.lo.open || o.lo.open),
            hi: end(hi, self.hi.open || o.hi.open),
        }
    }

    fn mul(self, o: Enclosure) -> Enclosure {
        // The extremes of a product lie at products of ends; `0 * inf` is the zero end's value
        // (the product tends to zero along the zero end).
        let product = |a: End, b: End| {
            if a.value == 0.0 {
                end(0.0, a.open)
            } else if b.value == 0.0 {
                end(0.0, b.open)
            } else {
                end(a.value * b.value, a.open || b.open)
            }
        };
        let candidates = [
            product(self.lo, o.lo),
            product(self.lo, o.hi),
            product(self.hi, o.lo),
            product(self.hi, o.hi),
        ];
        if candidates.iter().any(|c| c.value.is_nan()) {
            return WHOLE;
        }
        extremes(&candidates)
    }

    fn recip(self) -> Enclosure {
        let (lo, hi) = (self.lo, self.hi);
        let positive = lo.value > 0.0 || (lo.value == 0.0 && lo.open);
        let negative = hi.value < 0.0 || (hi.value == 0.0 && hi.open);
        if !(positive || negative) {
            return WHOLE;
        }
        let inv = |e: End| {
            if e.value == 0.0 {
                end(
                    if positive {
                        f64::INFINITY
                    } else {
                        f64::NEG_INFINITY
                    },
                    true,
                )
            } else {
                end(1.0 / e.value, e.open)
            }
        };
        Enclosure {
            lo: inv(hi),
            hi: inv(lo),
        }
    }

    fn powi(self, n: i64) -> Enclosure {
        if n == 0 {
            return Enclosure::point(1.0);
        }
        if n < 0 {
            return self.powi(-n).recip();
        }
        let p = |e: End| end(e.value.powi(i32::try_from(n).unwrap_or(i32::MAX)), e.open);
        if n % 2 == 1 {
            return Enclosure {
                lo: p(self.lo),
                hi: p(self.hi),
            };
        }
        let (lo, hi) = (self.lo, self.hi);
        let straddles = lo.value < 0.0 && hi.value > 0.0;
        let zero_in = straddles || (lo.value == 0.0 && !lo.open) || (hi.value == 0.0 && !hi.open);
        let (a, b) = (p(lo), p(hi));
        let top = if a.value > b.value || (a.value == b.value && !a.open) {
            a
        } else {
            b
        };
        if straddles || zero_in {
            return Enclosure {
                lo: end(0.0, !zero_in),
                hi: top,
            };
        }
        if lo.value >= 0.0 {
            Enclosure { lo: a, hi: b }
        } else {
            Enclosure { lo: b, hi: a }
        }
    }

    fn trig(self, f: Func) -> Enclosure {
        let shift = if f == Func::Cos { FRAC_PI_2 } else { 0.0 };
        // cos(x) = sin(x + pi/2).
        let (a, b) = (self.lo.value + shift, self.hi.value + shift);
        if b - a >= 2.0 * PI || !a.is_finite() || !b.is_finite() {
            return Enclosure {
                lo: end(-1.0, false),
                hi: end(1.0, false),
            };
        }
        let mut candidates = vec![end(a.sin(), self.lo.open), end(b.sin(), self.hi.open)];
        // The extremes of sin inside (a, b): pi/2 + k pi.
        let mut k = ((a - FRAC_PI_2) / PI).ceil();
        while FRAC_PI_2 + k * PI <= b {
            candidates.push(end((FRAC_PI_2 + k * PI).sin(), false));
            k += 1.0;
        }
        let mut e = extremes(&candidates);
        // Rounding of the ends: widen by an ulp-sized margin, never past +-1.
        e.lo.value = (e.lo.value - 1e-15).max(-1.0);
        e.hi.value = (e.hi.value + 1e-15).min(1.0);
        e
    }
}

/// The smallest and largest of `candidates`, an end closed if any candidate of its value is.
fn extremes(candidates: &[End]) -> Enclosure {
    let mut lo = candidates[0];
    let mut hi = candidates[0];
    for &c in &candidates[1..] {
        if c.value < lo.value || (c.value == lo.value && !c.open) {
            lo = c;
        }
        if c.value > hi.value || (c.value == hi.value && !c.open) {
            hi = c;
        }
    }
    Enclosure { lo, hi }
}

/// An enclosure of `e` with each symbol's from `range`; `None` if a symbol has none.
pub(crate) fn enclose(e: &Expr, range: &dyn Fn(&str) -> Option<Enclosure>) -> Option<Enclosure> {
    Some(match &e.kind {
        ExprKind::Number(n) => Enclosure::point(n.to_f64()),
        ExprKind::Symbol(s) => range(s)?,
        ExprKind::Neg(a) => enclose(a, range)?.neg(),
        ExprKind::Binary(op, a, b) => {
            let (a, b) = (enclose(a, range)?, enclose(b, range)?);
            match op {
                BinOp::Add => a.add(b),
                BinOp::Sub => a.add(b.neg()),
                BinOp::Mul => a.mul(b),
                BinOp::Div => a.mul(b.recip()),
            }
        }
        ExprKind::Pow(a, n) => enclose(a, range)?.powi(*n),
        ExprKind::Call(f, a) => enclose(a, range)?.trig(*f),
    })
}

#[cfg(test)]
mod tests {
    use super::{Enclosure, End, enclose};
    use crate::model::parse::parse_expr;

    fn open_positive(_: &str) -> Option<Enclosure> {
        Some(Enclosure {
            lo: End {
                value: 0.0,
                open: true,
            },
            hi: End {
                value: f64::INFINITY,
                open: true,
            },
        })
    }

    fn positive(text: &str) -> bool {
        let e = parse_expr(text).expect("parses");
        enclose(&e, &open_positive).is_some_and(|r| r.positive())
    }

    #[test]
    fn products_quotients_and_even_powers_of_positive_parameters_are_positive() {
        for text in ["m", "m*r^2", "m/r", "m + r", "2*m*(a + b)^2", "m*r^-2"] {
            assert!(positive(text), "{text}");
        }
    }

    #[test]
    fn what_can_reach_zero_or_below_is_not_shown_positive() {
        for text in ["-m", "m - r", "m*0", "(m - r)^2", "sin(m)", "0"] {
            assert!(!positive(text), "{text}");
        }
    }
}
