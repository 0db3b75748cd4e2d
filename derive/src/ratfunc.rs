//! Rational functions `num / den` of reduced polynomials, with cancellation.
//!
//! Invariants: the denominator is primitive with a positive leading coefficient (the rational
//! content lives in the numerator); numerator and denominator have no common factor that the
//! gcd of [`Poly`] finds; zero is `0 / 1`. Equality is semantic: `a/b == c/d` iff
//! `a d - c b` reduces to zero, so equal functions compare equal even when a factor hidden by
//! the trigonometric reduction was not cancelled.

use std::fmt;

use num_traits::{One, Zero};

use crate::error::{Error, Result};
use crate::poly::{Poly, Q};
use crate::symbol::{Atom, BaseAngle, Sym, Valuation};

/// A quotient of two reduced polynomials. (No `Hash`: equality is semantic, see the module
/// docs, and a structural hash would disagree with it.)
#[derive(Clone)]
pub struct RatFunc {
    num: Poly,
    den: Poly,
}

impl fmt::Debug for RatFunc {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.den == Poly::one() {
            write!(f, "{:?}", self.num)
        } else {
            write!(f, "({:?}) / ({:?})", self.num, self.den)
        }
    }
}

impl PartialEq for RatFunc {
    fn eq(&self, other: &Self) -> bool {
        if self.den == other.den {
            return self.num == other.num;
        }
        self.num.mul(&other.den) == other.num.mul(&self.den)
    }
}

impl Eq for RatFunc {}

impl From<Poly> for RatFunc {
    fn from(p: Poly) -> Self {
        RatFunc {
            num: p,
            den: Poly::one(),
        }
    }
}

impl RatFunc {
    /// Zero.
    pub fn zero() -> RatFunc {
        Poly::zero().into()
    }

    /// One.
    pub fn one() -> RatFunc {
        Poly::one().into()
    }

    /// An integer.
    pub fn int(n: i64) -> RatFunc {
        Poly::int(n).into()
    }

    /// A rational constant.
    pub fn constant(c: Q) -> RatFunc {
        Poly::constant(c).into()
    }

    /// A symbol.
    pub fn sym(s: Sym) -> RatFunc {
        Poly::atom(Atom::Sym(s)).into()
    }

    /// `sin` of a base angle.
    pub fn sin_of(a: BaseAngle) -> RatFunc {
        Poly::atom(Atom::Sin(a)).into()
    }

    /// `cos` of a base angle.
    pub fn cos_of(a: BaseAngle) -> RatFunc {
        Poly::atom(Atom::Cos(a)).into()
    }

    /// `num / den`, cancelled and normalised.
    pub fn new(num: Poly, den: Poly) -> Result<RatFunc> {
        if den.is_zero() {
            return Err(Error::DivisionByZero);
        }
        if num.is_zero() {
            return Ok(RatFunc::zero());
        }
        let g = num.gcd(&den);
        let (num, den) = if g == Poly::one() {
            (num, den)
        } else {
            match (num.div_exact(&g), den.div_exact(&g)) {
                (Some(n), Some(d)) => (n, d),
                _ => (num, den),
            }
        };
        let (content, den) = den.content_primitive();
        Ok(RatFunc {
            num: num.scale(&content.recip()),
            den,
        })
    }

    /// The numerator.
    pub fn num(&self) -> &Poly {
        &self.num
    }

    /// The denominator (primitive, positive leading coefficient).
    pub fn den(&self) -> &Poly {
        &self.den
    }

    /// Whether this is a polynomial.
    pub fn is_poly(&self) -> bool {
        self.den == Poly::one()
    }

    /// Whether this is identically zero.
    pub fn is_zero(&self) -> bool {
        self.num.is_zero()
    }

    /// The constant value, if constant.
    pub fn as_constant(&self) -> Option<Q> {
        if self.is_poly() {
            self.num.as_constant()
        } else {
            None
        }
    }

    /// Sum, by Henrici's rule: with `g = gcd(b, d)`,
    /// `a/b + c/d = (a (d/g) + c (b/g)) / ((b/g) d)`, and only `g` can share a factor with the
    /// new numerator, so the final cancellation is against `g` alone.
    pub fn add(&self, other: &RatFunc) -> RatFunc {
        if self.is_zero() {
            return other.clone();
        }
        if other.is_zero() {
            return self.clone();
        }
        if self.is_poly() && other.is_poly() {
            return self.num.add(&other.num).into();
        }
        if self.den == other.den {
            return Self::cancelled(self.num.add(&other.num), self.den.clone());
        }
        let g = self.den.gcd(&other.den);
        let (Some(b_g), Some(d_g)) = (self.den.div_exact(&g), other.den.div_exact(&g)) else {
            let num = self.num.mul(&other.den).add(&other.num.mul(&self.den));
            return Self::cancelled(num, self.den.mul(&other.den));
        };
        let num = self.num.mul(&d_g).add(&other.num.mul(&b_g));
        let den = b_g.mul(&other.den);
        if g.is_constant() {
            return Self::normalised(num, den);
        }
        let h = num.gcd(&g);
        match (num.div_exact(&h), den.div_exact(&h)) {
            (Some(n), Some(d)) => Self::normalised(n, d),
            _ => Self::normalised(num, den),
        }
    }

    /// Difference.
    pub fn sub(&self, other: &RatFunc) -> RatFunc {
        self.add(&other.neg())
    }

    /// Negation.
    pub fn neg(&self) -> RatFunc {
        RatFunc {
            num: self.num.neg(),
            den: self.den.clone(),
        }
    }

    /// Product, cancelling crosswise: `(a/b)(c/d) = ((a/g1)(c/g2)) / ((b/g2)(d/g1))` with
    /// `g1 = gcd(a, d)`, `g2 = gcd(c, b)`; the factors are already reduced, so no other
    /// cancellation is possible.
    pub fn mul(&self, other: &RatFunc) -> RatFunc {
        if self.is_zero() || other.is_zero() {
            return RatFunc::zero();
        }
        if self.is_poly() && other.is_poly() {
            return self.num.mul(&other.num).into();
        }
        let (a, b, c, d) = (&self.num, &self.den, &other.num, &other.den);
        let g1 = a.gcd(d);
        let g2 = c.gcd(b);
        let split = |p: &Poly, g: &Poly| {
            if g.is_constant() {
                Some(p.clone())
            } else {
                p.div_exact(g)
            }
        };
        match (split(a, &g1), split(d, &g1), split(c, &g2), split(b, &g2)) {
            (Some(a), Some(d), Some(c), Some(b)) => Self::normalised(a.mul(&c), b.mul(&d)),
            _ => Self::cancelled(a.mul(c), b.mul(d)),
        }
    }

    /// `num / den` already free of common factors: only the content is normalised.
    fn normalised(num: Poly, den: Poly) -> RatFunc {
        if num.is_zero() {
            return RatFunc::zero();
        }
        let (content, den) = den.content_primitive();
        RatFunc {
            num: num.scale(&content.recip()),
            den,
        }
    }

    /// Product with a rational constant.
    pub fn scale(&self, k: &Q) -> RatFunc {
        RatFunc {
            num: self.num.scale(k),
            den: self.den.clone(),
        }
    }

    /// Reciprocal; an error for zero.
    pub fn recip(&self) -> Result<RatFunc> {
        RatFunc::new(self.den.clone(), self.num.clone())
    }

    /// Quotient; an error when the divisor is identically zero.
    pub fn div(&self, other: &RatFunc) -> Result<RatFunc> {
        Ok(self.mul(&other.recip()?))
    }

    /// Integer power (negative powers are reciprocals).
    pub fn powi(&self, n: i32) -> Result<RatFunc> {
        let base = if n < 0 { self.recip()? } else { self.clone() };
        let e = n.unsigned_abs();
        Ok(RatFunc {
            num: base.num.pow(e),
            den: base.den.pow(e),
        })
    }

    fn cancelled(num: Poly, den: Poly) -> RatFunc {
        // `den` is never zero here: it is a product of nonzero denominators.
        RatFunc::new(num, den).unwrap_or_else(|_| RatFunc::zero())
    }

    /// Partial derivative with respect to a symbol (angles through their sine and cosine).
    pub fn diff(&self, sym: Sym) -> RatFunc {
        let dn = diff_poly(&self.num, sym);
        if self.is_poly() {
            return dn.into();
        }
        let dd = diff_poly(&self.den, sym);
        // (n/d)' = (n' d - n d') / d^2
        let num = dn.mul(&self.den).sub(&self.num.mul(&dd));
        Self::cancelled(num, self.den.mul(&self.den))
    }

    /// Substitutes a rational function for an atom, and cancels.
    pub fn substitute(&self, atom: Atom, value: &RatFunc) -> Result<RatFunc> {
        let slot = atom.slot();
        // Already cancelled: without the atom there is nothing to substitute or cancel (and the
        // quotient below would compute the gcd of numerator and denominator again).
        if !self.num.contains(slot) && !self.den.contains(slot) {
            return Ok(self.clone());
        }
        let sub = |p: &Poly| -> Result<RatFunc> {
            if !p.contains(slot) {
                return Ok(p.clone().into());
            }
            let coeffs = p.coeffs_in(slot);
            let mut acc = RatFunc::zero();
            for c in coeffs.iter().rev() {
                acc = acc.mul(value).add(&c.clone().into());
            }
            Ok(acc)
        };
        sub(&self.num)?.div(&sub(&self.den)?)
    }

    /// The same function with every atom slot renamed by `f` (see [`Poly::map_slots`]): to
    /// compare expressions written in two symbol tables.
    ///
    /// # Errors
    /// [`Error::DivisionByZero`] if `f` is not injective and the denominator collapses.
    pub fn map_slots(&self, f: &impl Fn(usize) -> usize) -> Result<RatFunc> {
        RatFunc::new(self.num.map_slots(f), self.den.map_slots(f))
    }

    /// Evaluates in `f64`.
    pub fn eval(&self, values: &impl Valuation<f64>) -> f64 {
        self.num.eval(values) / self.den.eval(values)
    }

    /// Evaluates exactly; an error if the denominator vanishes at the point.
    pub fn eval_exact(&self, values: &impl Valuation<Q>) -> Result<Q> {
        let d = self.den.eval_exact(values);
        if d.is_zero() {
            return Err(Error::DivisionByZero);
        }
        Ok(self.num.eval_exact(values) / d)
    }

    /// Whether the function is identically zero after clearing denominators (a semantic test).
    pub fn is_identically(&self, other: &RatFunc) -> bool {
        self == other
    }
}

/// Partial derivative of a reduced polynomial with respect to a symbol. For an angle symbol
/// the chain rule goes through the sine and cosine atoms of its base angle:
/// `d sin(b)/d sym = cos(b) / k`, `d cos(b)/d sym = -sin(b) / k` where `sym = k b`.
pub fn diff_poly(p: &Poly, sym: Sym) -> Poly {
    let mut out = p.diff_atom(sym.slot());
    if let Some((angle, k)) = sym.base_angle() {
        let inv_k = Q::new(One::one(), k.into());
        let s = Poly::atom(Atom::Sin(angle));
        let c = Poly::atom(Atom::Cos(angle));
        let ds = p.diff_atom(angle.sin_slot()).mul(&c);
        let dc = p.diff_atom(angle.cos_slot()).mul(&s);
        out = out.add(&ds.sub(&dc).scale(&inv_k));
    }
    out
}

impl Zero for RatFunc {
    fn zero() -> Self {
        RatFunc::zero()
    }
    fn is_zero(&self) -> bool {
        self.num.is_zero()
    }
}

impl std::ops::Add for RatFunc {
    type Output = RatFunc;
    fn add(self, rhs: RatFunc) -> RatFunc {
        RatFunc::add(&self, &rhs)
    }
}

macro_rules! binop {
    ($trait:ident, $method:ident, $f:ident) => {
        impl std::ops::$trait<&RatFunc> for &RatFunc {
            type Output = RatFunc;
            fn $method(self, rhs: &RatFunc) -> RatFunc {
                RatFunc::$f(self, rhs)
            }
        }
        impl std::ops::$trait<RatFunc> for RatFunc {
            type Output = RatFunc;
            fn $method(self, rhs: RatFunc) -> RatFunc {
                RatFunc::$f(&self, &rhs)
            }
        }
        impl std::ops::$trait<&RatFunc> for RatFunc {
            type Output = RatFunc;
            fn $method(self, rhs: &RatFunc) -> RatFunc {
                RatFunc::$f(&self, rhs)
            }
        }
    };
}
binop!(Sub, sub, sub);
binop!(Mul, mul, mul);

impl std::ops::Neg for &RatFunc {
    type Output = RatFunc;
    fn neg(self) -> RatFunc {
        RatFunc::neg(self)
    }
}

impl std::ops::Neg for RatFunc {
    type Output = RatFunc;
    fn neg(self) -> RatFunc {
        RatFunc::neg(&self)
    }
}

impl std::ops::Add<&RatFunc> for &RatFunc {
    type Output = RatFunc;
    fn add(self, rhs: &RatFunc) -> RatFunc {
        RatFunc::add(self, rhs)
    }
}

impl std::ops::Add<&RatFunc> for RatFunc {
    type Output = RatFunc;
    fn add(self, rhs: &RatFunc) -> RatFunc {
        RatFunc::add(&self, rhs)
    }
}
