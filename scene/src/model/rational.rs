//! Small exact rationals (`i64 / i64`, checked), for the coefficients of angle combinations
//! and for spotting constant divisors that are zero. Overflow is reported, never wrapped.

use std::fmt;

use crate::model::expr::Number;

/// A fraction in lowest terms with a positive denominator.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub struct Rational {
    num: i64,
    den: i64,
}

fn gcd(mut a: i128, mut b: i128) -> i128 {
    a = a.abs();
    b = b.abs();
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

impl Rational {
    /// Zero.
    pub const ZERO: Rational = Rational { num: 0, den: 1 };
    /// One.
    pub const ONE: Rational = Rational { num: 1, den: 1 };

    /// `num / den` in lowest terms; `None` if `den` is zero or the result does not fit.
    #[must_use]
    pub fn new(num: i64, den: i64) -> Option<Rational> {
        Rational::from_i128(i128::from(num), i128::from(den))
    }

    fn from_i128(num: i128, den: i128) -> Option<Rational> {
        if den == 0 {
            return None;
        }
        let g = gcd(num, den).max(1);
        let sign = if den < 0 { -1 } else { 1 };
        Some(Rational {
            num: i64::try_from(sign * num / g).ok()?,
            den: i64::try_from(sign * den / g).ok()?,
        })
    }

    /// The exact value of a literal; `None` if it does not fit.
    #[must_use]
    pub fn from_number(n: &Number) -> Option<Rational> {
        let m: i64 = n.mantissa().parse().ok()?;
        let e = u32::try_from(n.exponent().unsigned_abs()).ok()?;
        let p = 10_i64.checked_pow(e)?;
        if n.exponent() >= 0 {
            Rational::new(m.checked_mul(p)?, 1)
        } else {
            Rational::new(m, p)
        }
    }

    /// The numerator.
    #[must_use]
    pub fn numer(self) -> i64 {
        self.num
    }

    /// The denominator (positive).
    #[must_use]
    pub fn denom(self) -> i64 {
        self.den
    }

    /// Whether it is zero.
    #[must_use]
    pub fn is_zero(self) -> bool {
        self.num == 0
    }

    /// `self + o`, `None` on overflow.
    #[must_use]
    pub fn checked_add(self, o: Rational) -> Option<Rational> {
        let (a, b, c, d) = self.wide(o);
        Rational::from_i128(a.checked_mul(d)?.checked_add(c.checked_mul(b)?)?, b * d)
    }

    /// `self - o`, `None` on overflow.
    #[must_use]
    pub fn checked_sub(self, o: Rational) -> Option<Rational> {
        self.checked_add(o.checked_neg()?)
    }

    /// `self * o`, `None` on overflow.
    #[must_use]
    pub fn checked_mul(self, o: Rational) -> Option<Rational> {
        let (a, b, c, d) = self.wide(o);
        Rational::from_i128(a * c, b * d)
    }

    /// `self / o`, `None` if `o` is zero or on overflow.
    #[must_use]
    pub fn checked_div(self, o: Rational) -> Option<Rational> {
        let (a, b, c, d) = self.wide(o);
        Rational::from_i128(a * d, b * c)
    }

    /// `-self`, `None` on overflow.
    #[must_use]
    pub fn checked_neg(self) -> Option<Rational> {
        Some(Rational {
            num: self.num.checked_neg()?,
            den: self.den,
        })
    }

    /// `self^n`, `None` if zero to a negative power or on overflow.
    #[must_use]
    pub fn pow(self, n: i64) -> Option<Rational> {
        let base = if n < 0 {
            Rational::ONE.checked_div(self)?
        } else {
            self
        };
        if base.is_zero() || base == Rational::ONE || n == 0 {
            return Some(if n == 0 { Rational::ONE } else { base });
        }
        if base.num == -1 && base.den == 1 {
            return Some(if n % 2 == 0 { Rational::ONE } else { base });
        }
        // |base| is not 0 or 1, so the product overflows within 64 steps.
        let mut acc = Rational::ONE;
        for _ in 0..n.unsigned_abs() {
            acc = acc.checked_mul(base)?;
        }
        Some(acc)
    }

    fn wide(self, o: Rational) -> (i128, i128, i128, i128) {
        (
            i128::from(self.num),
            i128::from(self.den),
            i128::from(o.num),
            i128::from(o.den),
        )
    }
}

impl fmt::Display for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.den == 1 {
            write!(f, "{}", self.num)
        } else {
            write!(f, "{}/{}", self.num, self.den)
        }
    }
}

/// The least common multiple, `None` on overflow.
#[must_use]
pub fn lcm(a: u64, b: u64) -> Option<u64> {
    if a == 0 || b == 0 {
        return Some(a.max(b));
    }
    let g = u64::try_from(gcd(i128::from(a), i128::from(b))).ok()?;
    (a / g).checked_mul(b)
}
