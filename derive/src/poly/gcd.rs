//! Greatest common divisors in the free ring `Z[atoms]`: a proof of coprimality by modular
//! images, exact division by the smaller operand, and otherwise the primitive pseudo-remainder
//! sequence in the shared atom of lowest degree. [`RatFunc`](crate::ratfunc::RatFunc) cancels
//! with it.

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Zero};

use super::{Mono, Poly, Q};

impl Poly {
    /// Greatest common divisor in the free ring `Z[atoms]`, normalised to a primitive
    /// polynomial with positive leading coefficient (`1` if coprime).
    pub fn gcd(&self, other: &Poly) -> Poly {
        gcd(self, other)
    }

    /// Leading coefficient in one slot.
    fn lc_in(&self, slot: usize) -> Poly {
        let d = self.degree_in(slot);
        Poly::from_terms(
            self.terms
                .iter()
                .filter(|(m, _)| m.exponent(slot) == d)
                .map(|(m, c)| (m.with_exponent(slot, 0), c.clone())),
        )
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

/// The value every other atom takes in [`univariate_image`]: fixed, distinct per slot, and
/// generic enough that a leading coefficient rarely vanishes there (which is detected anyway).
fn image_point(slot: usize) -> u64 {
    let i = slot as u64 % PRIME;
    (1_000_003 + 7_919 * i % PRIME * ((i + 13) % PRIME)) % PRIME
}

/// The image of `p` in `F_p[v]` with every other atom set to a fixed value ([`image_point`]).
fn univariate_image(p: &Poly, slot: usize) -> Option<Vec<u64>> {
    let mut out = vec![0u64; usize::from(p.degree_in(slot)) + 1];
    for (m, c) in &p.terms {
        let mut t = mod_p(c)?;
        let mut k = 0;
        for (s, e) in m.factors() {
            if s == slot {
                k = usize::from(e);
            } else {
                t = t * pow_mod(image_point(s), u64::from(e)) % PRIME;
            }
        }
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
    for slot in a.slots() {
        if !b.contains(slot) {
            continue;
        }
        let (Some(ia), Some(ib)) = (univariate_image(a, slot), univariate_image(b, slot)) else {
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

/// Pseudo-remainder of `a` by `b` as polynomials in `slot`; `None` when the sequence outgrows
/// its budget ([`MAX_PRS_EXPONENT`]).
fn prem(a: &Poly, b: &Poly, slot: usize) -> Option<Poly> {
    let db = b.degree_in(slot);
    let lb = b.lc_in(slot);
    let mut r = a.clone();
    while !r.is_zero() && r.degree_in(slot) >= db {
        if !within_budget(&r) || !within_budget(&lb) {
            return None;
        }
        let dr = r.degree_in(slot);
        let lr = r.lc_in(slot);
        let shift = Mono::power(slot, dr - db);
        r = lb
            .mul_raw(&r)
            .sub(&lr.mul_raw(&b.mul_term(&shift, &Q::one())));
    }
    Some(r)
}

/// The largest exponent a remainder sequence may reach ([`MAX_PRS_TERMS`] terms): beyond it the
/// sequence is abandoned and only the common content cancels (a common divisor, if not the
/// greatest), so that a large model's gcd never overflows an exponent or runs away.
const MAX_PRS_EXPONENT: u8 = 64;

/// See [`MAX_PRS_EXPONENT`].
const MAX_PRS_TERMS: usize = 20_000;

fn within_budget(p: &Poly) -> bool {
    p.len() <= MAX_PRS_TERMS
        && p.terms()
            .iter()
            .all(|(m, _)| m.factors().all(|(_, e)| e <= MAX_PRS_EXPONENT))
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
        let g = a.monomial_content().gcd(&b.monomial_content());
        return Poly::term(g, Q::one());
    }
    if coprime_by_images(a, b) {
        return Poly::one();
    }
    let (small, large) = if a.len() <= b.len() { (a, b) } else { (b, a) };
    if large.div_exact(small).is_some() {
        return normalize(small);
    }
    // An atom only one of them contains: the gcd divides every coefficient in it.
    let (sa, sb) = (a.slots(), b.slots());
    let only_one = sa
        .iter()
        .filter(|s| !sb.contains(s))
        .chain(sb.iter().filter(|s| !sa.contains(s)))
        .min()
        .copied();
    if let Some(slot) = only_one {
        return if a.contains(slot) {
            gcd_with_coeffs(b, a, slot)
        } else {
            gcd_with_coeffs(a, b, slot)
        };
    }
    // Otherwise eliminate the shared atom of lowest degree: the remainder sequence is shortest.
    let Some(slot) = sa
        .iter()
        .copied()
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
        let Some(r) = prem(&x, &y, slot) else {
            // The sequence outgrew its budget: cancel the common content only.
            return normalize(&c);
        };
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
    use crate::symbol::{Atom, Sym};

    fn s(index: u16) -> Poly {
        Poly::atom(Atom::Sym(Sym::plain(index)))
    }

    // Symbols by index, named as the paper's masses, inertia and leg length.
    const M1: u16 = 12;
    const M2: u16 = 13;
    const L: u16 = 14;
    const I1: u16 = 16;

    #[test]
    fn gcd_finds_common_factor() {
        let m1 = s(M1);
        let m2 = s(M2);
        let i1 = s(I1);
        let mt = m1.add(&m2);
        let a = mt.mul(&mt).mul(&i1);
        let b = mt.mul(&s(L)).add(&mt.mul(&i1));
        assert_eq!(a.gcd(&b), mt);
        let c = a.div_exact(&mt).expect("divisible");
        assert_eq!(c, mt.mul(&i1));
        assert!(a.div_exact(&s(L)).is_none());
    }

    #[test]
    fn gcd_of_coprime_is_one() {
        let a = s(M1).add(&Poly::one());
        let b = s(M1).sub(&Poly::one());
        assert_eq!(a.gcd(&b), Poly::one());
    }
}
