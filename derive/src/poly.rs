//! Sparse multivariate polynomials over `Q` in the atoms of [`crate::symbol`], reduced modulo
//! `sin^2 + cos^2 = 1`.
//!
//! Every product is brought to the *reduced form* in which no cosine of a base angle appears
//! with an exponent above one (`cos^2 -> 1 - sin^2`). In that form `{1, cos}` is a basis of the
//! quotient ring over the other atoms, so two polynomials are equal as trigonometric functions
//! exactly when their reduced forms are equal: the reduced form is canonical.

use std::cmp::Ordering;
use std::collections::BTreeMap;
use std::fmt;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use crate::symbol::{Atom, NUM_ANGLES, NUM_ATOMS};

/// An exact rational number.
pub type Q = BigRational;

/// A monomial: the exponent of every atom slot.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Mono(pub [u8; NUM_ATOMS]);

impl Mono {
    /// The monomial `1`.
    pub const ONE: Mono = Mono([0; NUM_ATOMS]);

    /// The monomial of one atom slot to the first power.
    pub fn atom(slot: usize) -> Mono {
        let mut e = [0; NUM_ATOMS];
        e[slot] = 1;
        Mono(e)
    }

    /// Product of two monomials.
    pub fn mul(&self, other: &Mono) -> Mono {
        let mut e = self.0;
        for (a, b) in e.iter_mut().zip(other.0.iter()) {
            *a += *b;
        }
        Mono(e)
    }

    /// Quotient `self / other` if `other` divides `self`.
    pub fn div(&self, other: &Mono) -> Option<Mono> {
        let mut e = self.0;
        for (a, b) in e.iter_mut().zip(other.0.iter()) {
            *a = a.checked_sub(*b)?;
        }
        Some(Mono(e))
    }

    /// Total degree.
    pub fn degree(&self) -> u32 {
        self.0.iter().map(|&e| u32::from(e)).sum()
    }

    /// Whether this is the monomial `1`.
    pub fn is_one(&self) -> bool {
        self.0.iter().all(|&e| e == 0)
    }

    /// Slots with a nonzero exponent, with the exponent.
    pub fn factors(&self) -> impl Iterator<Item = (usize, u8)> + '_ {
        self.0
            .iter()
            .enumerate()
            .filter(|(_, e)| **e > 0)
            .map(|(i, e)| (i, *e))
    }
}

impl fmt::Debug for Mono {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut first = true;
        for (slot, e) in self.factors() {
            if !first {
                write!(f, "*")?;
            }
            first = false;
            write!(f, "{}", atom_name(slot))?;
            if e > 1 {
                write!(f, "^{e}")?;
            }
        }
        if first {
            write!(f, "1")?;
        }
        Ok(())
    }
}

/// Plain-text name of an atom slot (`sin(th1)`, `m1`, ...).
pub fn atom_name(slot: usize) -> String {
    match Atom::of_slot(slot) {
        Some(Atom::Sin(a)) => format!("sin({})", angle_name(a)),
        Some(Atom::Cos(a)) => format!("cos({})", angle_name(a)),
        Some(Atom::Sym(s)) => s.name().to_owned(),
        None => format!("#{slot}"),
    }
}

fn angle_name(a: crate::symbol::BaseAngle) -> &'static str {
    use crate::symbol::BaseAngle::*;
    match a {
        Th1 => "th1",
        Th2 => "th2",
        HalfAlpha => "alpha/2",
        Phi => "phi",
    }
}

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
        self.terms.iter().any(|(m, _)| m.0[slot] > 0)
    }

    /// Slots that occur, in increasing order.
    pub fn slots(&self) -> Vec<usize> {
        (0..NUM_ATOMS).filter(|&s| self.contains(s)).collect()
    }

    /// Sum.
    pub fn add(&self, other: &Poly) -> Poly {
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
                        out.push((a[i].0, c));
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
            terms: self.terms.iter().map(|(m, c)| (*m, -c)).collect(),
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
            terms: self.terms.iter().map(|(m, c)| (*m, c * k)).collect(),
        }
    }

    /// Product with one term, without trig reduction (monomial order is preserved).
    pub fn mul_term(&self, m: &Mono, k: &Q) -> Poly {
        if k.is_zero() {
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

    /// Product in the free polynomial ring (no trig reduction).
    pub fn mul_raw(&self, other: &Poly) -> Poly {
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
            .any(|(m, _)| (0..NUM_ANGLES).any(|k| m.0[2 * k + 1] >= 2))
    }

    /// The reduced form: `cos^2(a) -> 1 - sin^2(a)` for every base angle.
    pub fn reduce_trig(self) -> Poly {
        if !self.needs_reduction() {
            return self;
        }
        let mut out: Vec<(Mono, Q)> = Vec::new();
        for (m, c) in self.terms {
            let mut expansion = vec![(m, c)];
            for k in 0..NUM_ANGLES {
                let (s, co) = (2 * k, 2 * k + 1);
                let mut next = Vec::new();
                for (mm, cc) in expansion {
                    let e = mm.0[co];
                    if e < 2 {
                        next.push((mm, cc));
                        continue;
                    }
                    // cos^e = cos^(e mod 2) (1 - sin^2)^(e / 2), binomially expanded.
                    let half = u32::from(e / 2);
                    let mut base = mm;
                    base.0[co] = e % 2;
                    let mut binom = BigInt::one();
                    for j in 0..=half {
                        let mut t = base;
                        t.0[s] += 2 * j as u8;
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
            .filter(|(m, _)| m.0[slot] > 0)
            .map(|(m, c)| {
                let mut mm = *m;
                let e = mm.0[slot];
                mm.0[slot] -= 1;
                (mm, c * q_int(i64::from(e)))
            });
        Poly::from_terms(terms)
    }

    /// Degree in one slot.
    pub fn degree_in(&self, slot: usize) -> u8 {
        self.terms.iter().map(|(m, _)| m.0[slot]).max().unwrap_or(0)
    }

    /// Coefficients in one slot: `self = sum_k coeffs[k] * atom^k`.
    pub fn coeffs_in(&self, slot: usize) -> Vec<Poly> {
        let d = usize::from(self.degree_in(slot));
        let mut buckets: Vec<Vec<(Mono, Q)>> = vec![Vec::new(); d + 1];
        for (m, c) in &self.terms {
            let mut mm = *m;
            let e = usize::from(mm.0[slot]);
            mm.0[slot] = 0;
            buckets[e].push((mm, c.clone()));
        }
        buckets.into_iter().map(Poly::from_terms).collect()
    }

    /// Leading coefficient in one slot.
    fn lc_in(&self, slot: usize) -> Poly {
        let d = self.degree_in(slot);
        Poly::from_terms(
            self.terms
                .iter()
                .filter(|(m, _)| m.0[slot] == d)
                .map(|(m, c)| {
                    let mut mm = *m;
                    mm.0[slot] = 0;
                    (mm, c.clone())
                }),
        )
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
        let mut bound = [0u8; NUM_ATOMS];
        for (slot, b) in bound.iter_mut().enumerate() {
            *b = self.degree_in(slot).checked_sub(divisor.degree_in(slot))?;
        }
        let mut rem = self.clone();
        let mut quot: Vec<(Mono, Q)> = Vec::new();
        while let Some((rm, rc)) = rem.leading().cloned() {
            let m = rm.div(lm)?;
            if m.0.iter().zip(bound.iter()).any(|(e, b)| e > b) {
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

    /// Greatest common divisor in the free ring `Z[atoms]`, normalised to a primitive
    /// polynomial with positive leading coefficient (`1` if coprime).
    pub fn gcd(&self, other: &Poly) -> Poly {
        gcd(self, other)
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

    /// Evaluates with `f64` values for every atom slot.
    pub fn eval(&self, values: &[f64; NUM_ATOMS]) -> f64 {
        use num_traits::ToPrimitive;
        self.terms
            .iter()
            .map(|(m, c)| {
                let mut t = c.to_f64().unwrap_or(f64::NAN);
                for (slot, e) in m.factors() {
                    t *= values[slot].powi(i32::from(e));
                }
                t
            })
            .sum()
    }

    /// Evaluates exactly with rational values for every slot that occurs.
    pub fn eval_exact(&self, values: &[Q; NUM_ATOMS]) -> Q {
        let mut acc = Q::zero();
        for (m, c) in &self.terms {
            let mut t = c.clone();
            for (slot, e) in m.factors() {
                t *= num_traits::pow(values[slot].clone(), usize::from(e));
            }
            acc += t;
        }
        acc
    }

    /// The greatest monomial dividing every term.
    pub fn monomial_content(&self) -> Mono {
        let mut e = [u8::MAX; NUM_ATOMS];
        for (m, _) in &self.terms {
            for (a, b) in e.iter_mut().zip(m.0.iter()) {
                *a = (*a).min(*b);
            }
        }
        if self.terms.is_empty() {
            return Mono::ONE;
        }
        Mono(e)
    }
}

/// Normalises to primitive with positive leading coefficient.
fn normalize(p: &Poly) -> Poly {
    p.primitive()
}

fn gcd_list(ps: &[Poly]) -> Poly {
    let mut g = Poly::zero();
    for p in ps {
        g = gcd(&g, p);
        if g.as_constant().is_some_and(|c| !c.is_zero()) {
            return Poly::one();
        }
    }
    g
}

/// `gcd(p, q)` where `p` does not contain `slot`: the gcd of `p` and every coefficient of `q`
/// in `slot`, smallest coefficients first so that a coprime pair is found early.
fn gcd_with_coeffs(p: &Poly, q: &Poly, slot: usize) -> Poly {
    let mut coeffs = q.coeffs_in(slot);
    coeffs.retain(|c| !c.is_zero());
    coeffs.sort_by_key(Poly::len);
    let mut g = p.clone();
    for c in &coeffs {
        g = gcd(&g, c);
        if g.is_constant() {
            return Poly::one();
        }
    }
    normalize(&g)
}

/// The prime of the modular images in [`coprime_by_images`].
const PRIME: u64 = 2_147_483_647;

fn mod_p(q: &Q) -> Option<u64> {
    use num_traits::ToPrimitive;
    let p = BigInt::from(PRIME);
    let n = q.numer().mod_floor(&p).to_u64()?;
    let d = q.denom().mod_floor(&p).to_u64()?;
    if d == 0 {
        return None;
    }
    Some(n * pow_mod(d, PRIME - 2) % PRIME)
}

fn pow_mod(mut b: u64, mut e: u64) -> u64 {
    let mut r = 1;
    b %= PRIME;
    while e > 0 {
        if e & 1 == 1 {
            r = r * b % PRIME;
        }
        b = b * b % PRIME;
        e >>= 1;
    }
    r
}

/// The image of `p` in `F_p[v]` with every other atom set to a fixed value.
fn univariate_image(p: &Poly, slot: usize, point: &[u64; NUM_ATOMS]) -> Option<Vec<u64>> {
    let mut out = vec![0u64; usize::from(p.degree_in(slot)) + 1];
    for (m, c) in &p.terms {
        let mut t = mod_p(c)?;
        for (s, e) in m.factors() {
            if s != slot {
                t = t * pow_mod(point[s], u64::from(e)) % PRIME;
            }
        }
        let k = usize::from(m.0[slot]);
        out[k] = (out[k] + t) % PRIME;
    }
    Some(out)
}

fn trim(p: &mut Vec<u64>) {
    while p.last() == Some(&0) {
        p.pop();
    }
}

/// Degree of the gcd of two univariate polynomials over `F_p`.
fn univariate_gcd_degree(mut a: Vec<u64>, mut b: Vec<u64>) -> usize {
    trim(&mut a);
    trim(&mut b);
    while !b.is_empty() {
        // a <- a mod b
        let lb_inv = pow_mod(b[b.len() - 1], PRIME - 2);
        while a.len() >= b.len() {
            let Some(&la) = a.last() else { break };
            let k = la * lb_inv % PRIME;
            let shift = a.len() - b.len();
            for (i, &bi) in b.iter().enumerate() {
                a[shift + i] = (a[shift + i] + PRIME - k * bi % PRIME) % PRIME;
            }
            trim(&mut a);
        }
        std::mem::swap(&mut a, &mut b);
    }
    a.len().saturating_sub(1)
}

/// A fast proof of coprimality: if, for every atom that both contain, the images in
/// `F_p[v]` (all other atoms at a fixed point that keeps the degrees) have a constant gcd,
/// then the gcd has degree zero in every atom. `false` means "not proven", not "not coprime".
fn coprime_by_images(a: &Poly, b: &Poly) -> bool {
    let mut point = [0u64; NUM_ATOMS];
    for (i, v) in point.iter_mut().enumerate() {
        *v = 1_000_003 + 7_919 * i as u64 * (i as u64 + 13);
    }
    for slot in 0..NUM_ATOMS {
        if !(a.contains(slot) && b.contains(slot)) {
            continue;
        }
        let (Some(ia), Some(ib)) = (
            univariate_image(a, slot, &point),
            univariate_image(b, slot, &point),
        ) else {
            return false;
        };
        let degrees_kept = ia.last() != Some(&0) && ib.last() != Some(&0);
        if !degrees_kept || univariate_gcd_degree(ia, ib) > 0 {
            return false;
        }
    }
    true
}

/// Content with respect to a slot: gcd of the coefficients.
fn content_in(p: &Poly, slot: usize) -> Poly {
    gcd_list(&p.coeffs_in(slot))
}

/// Pseudo-remainder of `a` by `b` as polynomials in `slot`.
fn prem(a: &Poly, b: &Poly, slot: usize) -> Poly {
    let db = b.degree_in(slot);
    let lb = b.lc_in(slot);
    let mut r = a.clone();
    while !r.is_zero() && r.degree_in(slot) >= db {
        let dr = r.degree_in(slot);
        let lr = r.lc_in(slot);
        let mut shift = Mono::ONE;
        shift.0[slot] = dr - db;
        r = lb
            .mul_raw(&r)
            .sub(&lr.mul_raw(&b.mul_term(&shift, &Q::one())));
    }
    r
}

fn gcd(a: &Poly, b: &Poly) -> Poly {
    if a.is_zero() {
        return normalize(b);
    }
    if b.is_zero() {
        return normalize(a);
    }
    if a.is_constant() || b.is_constant() {
        return Poly::one();
    }
    if a.len() == 1 || b.len() == 1 {
        let ma = a.monomial_content();
        let mb = b.monomial_content();
        let mut e = [0u8; NUM_ATOMS];
        for (x, (p, q)) in e.iter_mut().zip(ma.0.iter().zip(mb.0.iter())) {
            *x = (*p).min(*q);
        }
        return Poly::term(Mono(e), Q::one());
    }
    if coprime_by_images(a, b) {
        return Poly::one();
    }
    let (small, large) = if a.len() <= b.len() { (a, b) } else { (b, a) };
    if large.div_exact(small).is_some() {
        return normalize(small);
    }
    // An atom only one of them contains: the gcd divides every coefficient in it.
    if let Some(slot) = (0..NUM_ATOMS).find(|&s| a.contains(s) != b.contains(s)) {
        return if a.contains(slot) {
            gcd_with_coeffs(b, a, slot)
        } else {
            gcd_with_coeffs(a, b, slot)
        };
    }
    // Otherwise eliminate the shared atom of lowest degree: the remainder sequence is shortest.
    let Some(slot) = (0..NUM_ATOMS)
        .filter(|&s| a.contains(s))
        .min_by_key(|&s| (a.degree_in(s).max(b.degree_in(s)), a.len() + b.len(), s))
    else {
        return Poly::one();
    };
    if !b.contains(slot) {
        return gcd_with_coeffs(b, a, slot);
    }
    if !a.contains(slot) {
        return gcd_with_coeffs(a, b, slot);
    }
    let ca = content_in(a, slot);
    let cb = content_in(b, slot);
    let c = gcd(&ca, &cb);
    let (Some(pa), Some(pb)) = (a.div_exact(&ca), b.div_exact(&cb)) else {
        return Poly::one();
    };
    let (pa, pb) = (pa.primitive(), pb.primitive());
    let (mut x, mut y) = if pa.degree_in(slot) >= pb.degree_in(slot) {
        (pa, pb)
    } else {
        (pb, pa)
    };
    while !y.is_zero() {
        let r = prem(&x, &y, slot);
        x = y;
        y = if r.is_zero() {
            r
        } else {
            // Divide out the content in the other atoms and the integer content, or the
            // coefficients of the remainder sequence grow exponentially.
            let cr = content_in(&r, slot);
            r.div_exact(&cr).unwrap_or(r).primitive()
        };
        if !y.is_zero() && y.degree_in(slot) == 0 {
            // Coprime in this slot.
            x = Poly::one();
            break;
        }
    }
    let g = if x.degree_in(slot) == 0 {
        Poly::one()
    } else {
        x
    };
    normalize(&c.mul_raw(&g))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbol::{BaseAngle, Sym};

    fn s(sym: Sym) -> Poly {
        Poly::atom(Atom::Sym(sym))
    }

    #[test]
    fn pythagoras_reduces_to_one() {
        let sn = Poly::atom(Atom::Sin(BaseAngle::Th1));
        let cs = Poly::atom(Atom::Cos(BaseAngle::Th1));
        assert_eq!(sn.mul(&sn).add(&cs.mul(&cs)), Poly::one());
        assert_eq!(cs.pow(4), Poly::one().sub(&sn.mul(&sn)).pow(2));
    }

    #[test]
    fn gcd_finds_common_factor() {
        let m1 = s(Sym::M1);
        let m2 = s(Sym::M2);
        let i1 = s(Sym::I1);
        let mt = m1.add(&m2);
        let a = mt.mul(&mt).mul(&i1);
        let b = mt.mul(&s(Sym::L)).add(&mt.mul(&i1));
        assert_eq!(a.gcd(&b), mt);
        let c = a.div_exact(&mt).expect("divisible");
        assert_eq!(c, mt.mul(&i1));
        assert!(a.div_exact(&s(Sym::L)).is_none());
    }

    #[test]
    fn gcd_of_coprime_is_one() {
        let a = s(Sym::M1).add(&Poly::one());
        let b = s(Sym::M1).sub(&Poly::one());
        assert_eq!(a.gcd(&b), Poly::one());
    }
}
