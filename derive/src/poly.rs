//! Sparse multivariate polynomials over `Q` in the atoms of [`crate::symbol`], reduced modulo
//! `sin^2 + cos^2 = 1`.
//!
//! Every product is brought to the *reduced form* in which no cosine of a base angle appears
//! with an exponent above one (`cos^2 -> 1 - sin^2`). In that form `{1, cos}` is a basis of the
//! quotient ring over the other atoms, so two polynomials are equal as trigonometric functions
//! exactly when their reduced forms are equal: the reduced form is canonical.
//!
//! This file holds the polynomial type and its arithmetic (sums, products in the reduced form,
//! exact division, content, substitution, evaluation); the monomial type is in `poly/mono.rs`
//! and the greatest common divisor, [`Poly::gcd`], in `poly/gcd.rs` (which uses this file, not
//! the other way round).

use std::cmp::Ordering;
use std::collections::BTreeMap;
use std::fmt;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use crate::symbol::{Atom, Valuation, is_cos_slot};

mod gcd;
mod mono;

pub use mono::Mono;

/// An exact rational number.
pub type Q = BigRational;

/// A polynomial: terms sorted by descending monomial, no zero coefficients.
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct Poly {
    terms: Vec<(Mono, Q)>,
}

impl fmt::Debug for Poly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.terms.is_empty() {
            return write!(f, "0");
        }
        for (i, (m, c)) in self.terms.iter().enumerate() {
            if i > 0 {
                write!(f, " + ")?;
            }
            write!(f, "({c})*{m:?}")?;
        }
        Ok(())
    }
}

fn q_int(n: i64) -> Q {
    Q::from_integer(BigInt::from(n))
}

impl Poly {
    /// The zero polynomial.
    pub fn zero() -> Poly {
        Poly { terms: Vec::new() }
    }

    /// The constant polynomial `1`.
    pub fn one() -> Poly {
        Poly::constant(Q::one())
    }

    /// A constant.
    pub fn constant(c: Q) -> Poly {
        if c.is_zero() {
            Poly::zero()
        } else {
            Poly {
                terms: vec![(Mono::ONE, c)],
            }
        }
    }

    /// An integer constant.
    pub fn int(n: i64) -> Poly {
        Poly::constant(q_int(n))
    }

    /// An atom to the first power.
    pub fn atom(atom: Atom) -> Poly {
        Poly {
            terms: vec![(Mono::atom(atom.slot()), Q::one())],
        }
    }

    /// A single term.
    pub fn term(m: Mono, c: Q) -> Poly {
        Poly::constant(c).mul_term(&m, &Q::one())
    }

    /// Builds a polynomial from unsorted terms, merging equal monomials (no trig reduction).
    pub fn from_terms(terms: impl IntoIterator<Item = (Mono, Q)>) -> Poly {
        let mut map: BTreeMap<Mono, Q> = BTreeMap::new();
        for (m, c) in terms {
            let e = map.entry(m).or_insert_with(Q::zero);
            *e += c;
        }
        let mut terms: Vec<(Mono, Q)> = map.into_iter().filter(|(_, c)| !c.is_zero()).collect();
        terms.reverse();
        Poly { terms }
    }

    /// The terms, leading (largest monomial) first.
    pub fn terms(&self) -> &[(Mono, Q)] {
        &self.terms
    }

    /// Whether this is zero.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// The constant value, if the polynomial is constant.
    pub fn as_constant(&self) -> Option<Q> {
        match self.terms.as_slice() {
            [] => Some(Q::zero()),
            [(m, c)] if m.is_one() => Some(c.clone()),
            _ => None,
        }
    }

    /// Whether this is a constant (possibly zero).
    pub fn is_constant(&self) -> bool {
        self.as_constant().is_some()
    }

    /// Number of terms.
    pub fn len(&self) -> usize {
        self.terms.len()
    }

    /// Whether there are no terms (same as [`Poly::is_zero`]).
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// The leading term.
    pub fn leading(&self) -> Option<&(Mono, Q)> {
        self.terms.first()
    }

    /// Whether an atom slot occurs.
    pub fn contains(&self, slot: usize) -> bool {
        self.terms.iter().any(|(m, _)| m.exponent(slot) > 0)
    }

    /// Slots that occur, in increasing order.
    pub fn slots(&self) -> Vec<usize> {
        let set: std::collections::BTreeSet<usize> = self
            .terms
            .iter()
            .flat_map(|(m, _)| m.factors().map(|(s, _)| s))
            .collect();
        set.into_iter().collect()
    }

    /// Sum.
    pub fn add(&self, other: &Poly) -> Poly {
        if !crate::budget::charge(self.weight().saturating_add(other.weight())) {
            return Poly::zero();
        }
        let (a, b) = (&self.terms, &other.terms);
        let mut out = Vec::with_capacity(a.len() + b.len());
        let (mut i, mut j) = (0, 0);
        while i < a.len() && j < b.len() {
            match a[i].0.cmp(&b[j].0) {
                Ordering::Greater => {
                    out.push(a[i].clone());
                    i += 1;
                }
                Ordering::Less => {
                    out.push(b[j].clone());
                    j += 1;
                }
                Ordering::Equal => {
                    let c = &a[i].1 + &b[j].1;
                    if !c.is_zero() {
                        out.push((a[i].0.clone(), c));
                    }
                    i += 1;
                    j += 1;
                }
            }
        }
        out.extend_from_slice(&a[i..]);
        out.extend_from_slice(&b[j..]);
        Poly { terms: out }
    }

    /// Negation.
    pub fn neg(&self) -> Poly {
        Poly {
            terms: self.terms.iter().map(|(m, c)| (m.clone(), -c)).collect(),
        }
    }

    /// Difference.
    pub fn sub(&self, other: &Poly) -> Poly {
        self.add(&other.neg())
    }

    /// Product with a rational constant.
    pub fn scale(&self, k: &Q) -> Poly {
        if k.is_zero() {
            return Poly::zero();
        }
        Poly {
            terms: self.terms.iter().map(|(m, c)| (m.clone(), c * k)).collect(),
        }
    }

    /// Product with one term, without trig reduction (monomial order is preserved).
    pub fn mul_term(&self, m: &Mono, k: &Q) -> Poly {
        if k.is_zero() || !crate::budget::charge(self.terms.len()) {
            return Poly::zero();
        }
        Poly {
            terms: self
                .terms
                .iter()
                .map(|(mm, c)| (mm.mul(m), c * k))
                .collect(),
        }
    }

    /// The size of the polynomial for the derivation's budget: its terms, each weighed by one
    /// plus the 64-bit words of its coefficient (a product's cost is the product of its
    /// factors' weights: every pair of terms is multiplied, in time growing with their digits).
    pub(crate) fn weight(&self) -> usize {
        self.terms
            .iter()
            .map(|(_, c)| 1 + ((c.numer().bits() + c.denom().bits()) / 64) as usize)
            .sum()
    }

    /// Product in the free polynomial ring (no trig reduction).
    pub fn mul_raw(&self, other: &Poly) -> Poly {
        if !crate::budget::charge(self.weight().saturating_mul(other.weight())) {
            return Poly::zero();
        }
        let mut map: BTreeMap<Mono, Q> = BTreeMap::new();
        for (ma, ca) in &self.terms {
            for (mb, cb) in &other.terms {
                let e = map.entry(ma.mul(mb)).or_insert_with(Q::zero);
                *e += ca * cb;
            }
        }
        let mut terms: Vec<(Mono, Q)> = map.into_iter().filter(|(_, c)| !c.is_zero()).collect();
        terms.reverse();
        Poly { terms }
    }

    /// Product, brought to the reduced form.
    pub fn mul(&self, other: &Poly) -> Poly {
        self.mul_raw(other).reduce_trig()
    }

    /// Integer power, reduced.
    pub fn pow(&self, n: u32) -> Poly {
        let mut result = Poly::one();
        let mut base = self.clone();
        let mut n = n;
        while n > 0 {
            if n & 1 == 1 {
                result = result.mul(&base);
            }
            n >>= 1;
            if n > 0 {
                base = base.mul(&base);
            }
        }
        result
    }

    /// Whether some cosine appears squared or higher.
    fn needs_reduction(&self) -> bool {
        self.terms
            .iter()
            .any(|(m, _)| m.factors().any(|(s, e)| is_cos_slot(s) && e >= 2))
    }

    /// The reduced form: `cos^2(a) -> 1 - sin^2(a)` for every base angle.
    pub fn reduce_trig(self) -> Poly {
        if !self.needs_reduction() {
            return self;
        }
        let mut out: Vec<(Mono, Q)> = Vec::new();
        for (m, c) in self.terms {
            let cosines: Vec<usize> = m
                .factors()
                .filter(|&(s, e)| is_cos_slot(s) && e >= 2)
                .map(|(s, _)| s)
                .collect();
            let mut expansion = vec![(m, c)];
            for co in cosines {
                if !crate::budget::charge(expansion.len()) {
                    return Poly::zero();
                }
                let s = co - 1;
                let mut next = Vec::new();
                for (mm, cc) in expansion {
                    let e = mm.exponent(co);
                    // cos^e = cos^(e mod 2) (1 - sin^2)^(e / 2), binomially expanded.
                    let half = u32::from(e / 2);
                    let base = mm.with_exponent(co, e % 2);
                    let sin_e = base.exponent(s);
                    let mut binom = BigInt::one();
                    for j in 0..=half {
                        let t = base.with_exponent(s, sin_e + 2 * j as u8);
                        let sign = if j % 2 == 0 {
                            BigInt::one()
                        } else {
                            -BigInt::one()
                        };
                        next.push((t, &cc * Q::from_integer(&binom * sign)));
                        binom = binom * BigInt::from(half - j) / BigInt::from(j + 1);
                    }
                }
                expansion = next;
            }
            out.extend(expansion);
        }
        Poly::from_terms(out)
    }

    /// Partial derivative with respect to one atom slot, treating all atoms as independent.
    pub fn diff_atom(&self, slot: usize) -> Poly {
        let terms = self
            .terms
            .iter()
            .filter(|(m, _)| m.exponent(slot) > 0)
            .map(|(m, c)| {
                let e = m.exponent(slot);
                (m.with_exponent(slot, e - 1), c * q_int(i64::from(e)))
            });
        Poly::from_terms(terms)
    }

    /// Degree in one slot.
    pub fn degree_in(&self, slot: usize) -> u8 {
        self.terms
            .iter()
            .map(|(m, _)| m.exponent(slot))
            .max()
            .unwrap_or(0)
    }

    /// Coefficients in one slot: `self = sum_k coeffs[k] * atom^k`.
    pub fn coeffs_in(&self, slot: usize) -> Vec<Poly> {
        let d = usize::from(self.degree_in(slot));
        let mut buckets: Vec<Vec<(Mono, Q)>> = vec![Vec::new(); d + 1];
        for (m, c) in &self.terms {
            let e = usize::from(m.exponent(slot));
            buckets[e].push((m.with_exponent(slot, 0), c.clone()));
        }
        buckets.into_iter().map(Poly::from_terms).collect()
    }

    /// Exact quotient in the free polynomial ring, if `divisor` divides `self`.
    pub fn div_exact(&self, divisor: &Poly) -> Option<Poly> {
        let (lm, lc) = divisor.leading()?;
        if divisor.terms.len() == 1 {
            let mut terms = Vec::with_capacity(self.terms.len());
            for (m, c) in &self.terms {
                terms.push((m.div(lm)?, c / lc));
            }
            return Some(Poly { terms });
        }
        // In an exact division deg_v(quotient) = deg_v(self) - deg_v(divisor) for every atom
        // v; a quotient term beyond that bound proves the division inexact (and stops the
        // lexicographic reduction from wandering through exponentially many terms).
        let mut bound = std::collections::BTreeMap::new();
        for slot in self.slots().into_iter().chain(divisor.slots()) {
            bound.insert(
                slot,
                self.degree_in(slot).checked_sub(divisor.degree_in(slot))?,
            );
        }
        let mut rem = self.clone();
        let mut quot: Vec<(Mono, Q)> = Vec::new();
        while let Some((rm, rc)) = rem.leading().cloned() {
            if crate::budget::spent() {
                return None;
            }
            let m = rm.div(lm)?;
            if m.factors()
                .any(|(s, e)| bound.get(&s).is_none_or(|b| e > *b))
            {
                return None;
            }
            let k = &rc / lc;
            rem = rem.sub(&divisor.mul_term(&m, &k));
            quot.push((m, k));
        }
        Some(Poly::from_terms(quot))
    }

    /// The rational content and the primitive part: `self = content * primitive`, where the
    /// primitive part has coprime integer coefficients and a positive leading coefficient.
    pub fn content_primitive(&self) -> (Q, Poly) {
        let Some((_, lead)) = self.leading() else {
            return (Q::one(), Poly::zero());
        };
        if !crate::budget::charge(self.weight()) {
            return (Q::one(), Poly::zero());
        }
        let mut den_lcm = BigInt::one();
        let mut num_gcd = BigInt::zero();
        for (_, c) in &self.terms {
            den_lcm = den_lcm.lcm(c.denom());
            num_gcd = num_gcd.gcd(c.numer());
        }
        let mut content = Q::new(num_gcd, den_lcm);
        if lead.is_negative() {
            content = -content;
        }
        let prim = self.scale(&content.recip());
        (content, prim)
    }

    /// The primitive part (see [`Poly::content_primitive`]).
    pub fn primitive(&self) -> Poly {
        self.content_primitive().1
    }

    /// Substitutes a polynomial for an atom slot, and reduces.
    pub fn substitute(&self, slot: usize, value: &Poly) -> Poly {
        if !self.contains(slot) {
            return self.clone();
        }
        let coeffs = self.coeffs_in(slot);
        // Horner in the substituted value.
        let mut acc = Poly::zero();
        for c in coeffs.iter().rev() {
            acc = acc.mul(value).add(c);
        }
        acc
    }

    /// Evaluates with `f64` values of the atom slots.
    pub fn eval(&self, values: &impl Valuation<f64>) -> f64 {
        use num_traits::ToPrimitive;
        self.terms
            .iter()
            .map(|(m, c)| {
                let mut t = c.to_f64().unwrap_or(f64::NAN);
                for (slot, e) in m.factors() {
                    t *= values.value(slot).powi(i32::from(e));
                }
                t
            })
            .sum()
    }

    /// Evaluates exactly with rational values of the slots that occur.
    pub fn eval_exact(&self, values: &impl Valuation<Q>) -> Q {
        let mut acc = Q::zero();
        for (m, c) in &self.terms {
            let mut t = c.clone();
            for (slot, e) in m.factors() {
                t *= num_traits::pow(values.value(slot), usize::from(e));
            }
            acc += t;
        }
        acc
    }

    /// The same polynomial with every atom slot renamed by `f` (a map between two tables'
    /// slots that sends sines to sines and cosines to cosines), merged and sorted.
    pub fn map_slots(&self, f: &impl Fn(usize) -> usize) -> Poly {
        Poly::from_terms(self.terms.iter().map(|(m, c)| {
            (
                Mono::from_factors(m.factors().map(|(s, e)| (f(s), e))),
                c.clone(),
            )
        }))
    }

    /// The greatest monomial dividing every term.
    pub fn monomial_content(&self) -> Mono {
        let mut terms = self.terms.iter();
        let Some((first, _)) = terms.next() else {
            return Mono::ONE;
        };
        terms.fold(first.clone(), |g, (m, _)| g.gcd(m))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbol::BaseAngle;

    #[test]
    fn pythagoras_reduces_to_one() {
        let sn = Poly::atom(Atom::Sin(BaseAngle::new(0)));
        let cs = Poly::atom(Atom::Cos(BaseAngle::new(0)));
        assert_eq!(sn.mul(&sn).add(&cs.mul(&cs)), Poly::one());
        assert_eq!(cs.pow(4), Poly::one().sub(&sn.mul(&sn)).pow(2));
    }
}
