//! Parameter ranges: intervals such as `"(0, inf)"`, `"[0, pi/2)"`, `"(-pi/2, pi/2]"`.
//!
//! A bound is a decimal number, `inf` / `-inf` (only on an open side), `pi` or `pi/k` with a
//! positive integer `k`, optionally negated. An interval must not be empty.

use std::fmt;

/// One end of an interval.
#[derive(Clone, Copy, PartialEq, Debug)]
pub enum Bound {
    /// A finite number, as written.
    Number(f64),
    /// `pi/k`, negated when `negative` (`pi` is `k = 1`).
    Pi {
        /// `-pi/k`.
        negative: bool,
        /// The divisor `k >= 1`.
        divisor: u32,
    },
    /// `inf` or `-inf`, by sign.
    Infinite {
        /// `-inf`.
        negative: bool,
    },
}

impl Bound {
    /// The value.
    #[must_use]
    pub fn value(self) -> f64 {
        match self {
            Bound::Number(x) => x,
            Bound::Pi { negative, divisor } => {
                let v = std::f64::consts::PI / f64::from(divisor);
                if negative { -v } else { v }
            }
            Bound::Infinite { negative } => {
                if negative {
                    f64::NEG_INFINITY
                } else {
                    f64::INFINITY
                }
            }
        }
    }
}

impl fmt::Display for Bound {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Bound::Number(x) => write!(f, "{x}"),
            Bound::Pi { negative, divisor } => {
                let sign = if negative { "-" } else { "" };
                if divisor == 1 {
                    write!(f, "{sign}pi")
                } else {
                    write!(f, "{sign}pi/{divisor}")
                }
            }
            Bound::Infinite { negative } => f.write_str(if negative { "-inf" } else { "inf" }),
        }
    }
}

/// A non-empty interval of the real line.
#[derive(Clone, Copy, PartialEq, Debug)]
pub struct Interval {
    /// The lower bound.
    pub low: Bound,
    /// Whether the lower bound belongs to the interval (`[`).
    pub low_closed: bool,
    /// The upper bound.
    pub high: Bound,
    /// Whether the upper bound belongs to the interval (`]`).
    pub high_closed: bool,
}

impl Interval {
    /// Whether `x` lies in the interval (`NaN` never does).
    #[must_use]
    pub fn contains(&self, x: f64) -> bool {
        let (lo, hi) = (self.low.value(), self.high.value());
        let above = if self.low_closed { x >= lo } else { x > lo };
        let below = if self.high_closed { x <= hi } else { x < hi };
        above && below
    }
}

impl fmt::Display for Interval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}{}, {}{}",
            if self.low_closed { '[' } else { '(' },
            self.low,
            self.high,
            if self.high_closed { ']' } else { ')' }
        )
    }
}

/// Why a range did not parse.
#[derive(Clone, PartialEq, Eq, Debug, thiserror::Error)]
pub enum IntervalError {
    /// Not of the shape `[a, b]` with `(`/`[` and `)`/`]`.
    #[error("expected an interval such as \"(0, inf)\" or \"[0, pi/2)\"")]
    Shape,
    /// A bound that is not a number, `inf`, `-inf`, `pi` or `pi/k`.
    #[error("bound `{}` is not a number, inf, -inf, pi or pi/k", crate::limits::echo(.0))]
    BadBound(String),
    /// `inf` on a closed side.
    #[error("an infinite bound must be open: `{}`", crate::limits::echo(.0))]
    ClosedInfinity(String),
    /// The interval holds no number.
    #[error("the interval {} is empty", crate::limits::echo(.0))]
    Empty(String),
}

impl std::str::FromStr for Interval {
    type Err = IntervalError;

    fn from_str(s: &str) -> Result<Interval, IntervalError> {
        let t = s.trim();
        let mut chars = t.chars();
        let open = chars.next().ok_or(IntervalError::Shape)?;
        let close = chars.next_back().ok_or(IntervalError::Shape)?;
        let low_closed = match open {
            '[' => true,
            '(' => false,
            _ => return Err(IntervalError::Shape),
        };
        let high_closed = match close {
            ']' => true,
            ')' => false,
            _ => return Err(IntervalError::Shape),
        };
        let inner = chars.as_str();
        let (a, b) = inner.split_once(',').ok_or(IntervalError::Shape)?;
        if b.contains(',') {
            return Err(IntervalError::Shape);
        }
        let (low, high) = (parse_bound(a)?, parse_bound(b)?);
        for (bound, closed) in [(low, low_closed), (high, high_closed)] {
            if closed && matches!(bound, Bound::Infinite { .. }) {
                return Err(IntervalError::ClosedInfinity(t.to_owned()));
            }
        }
        let (lo, hi) = (low.value(), high.value());
        if lo > hi || (lo == hi && !(low_closed && high_closed)) {
            return Err(IntervalError::Empty(t.to_owned()));
        }
        Ok(Interval {
            low,
            low_closed,
            high,
            high_closed,
        })
    }
}

fn parse_bound(s: &str) -> Result<Bound, IntervalError> {
    let t = s.trim();
    let bad = || IntervalError::BadBound(t.to_owned());
    let (negative, body) = match t.strip_prefix('-') {
        Some(rest) => (true, rest.trim_start()),
        None => (false, t),
    };
    if body == "inf" {
        return Ok(Bound::Infinite { negative });
    }
    if body == "pi" {
        return Ok(Bound::Pi {
            negative,
            divisor: 1,
        });
    }
    if let Some(k) = body.strip_prefix("pi/") {
        let k = k.trim();
        if k.is_empty() || !k.bytes().all(|b| b.is_ascii_digit()) {
            return Err(bad());
        }
        let divisor: u32 = k.parse().map_err(|_| bad())?;
        if divisor == 0 {
            return Err(bad());
        }
        return Ok(Bound::Pi { negative, divisor });
    }
    // A decimal number: digits, an optional fraction and exponent (no `nan`, `infinity`, `+`).
    let ok_chars = body
        .bytes()
        .all(|b| b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'-' | b'+'));
    if body.is_empty() || !body.as_bytes()[0].is_ascii_digit() || !ok_chars {
        return Err(bad());
    }
    let x: f64 = body.parse().map_err(|_| bad())?;
    if !x.is_finite() {
        return Err(bad());
    }
    Ok(Bound::Number(if negative { -x } else { x }))
}
