//! Monomials: the nonzero exponents of a product of atoms, sparse and sized by what occurs.
//!
//! A monomial of a walker's kernels has a handful of factors among tens of atoms, and a model
//! has as many atoms as it declares: so a monomial is the sorted list of its `(slot, exponent)`
//! pairs, each packed into one `u32` (slot in the high 24 bits, exponent in the low 8), inline up
//! to twelve factors (`smallvec`: no allocation for the products the derivation forms).
//!
//! The order is the lexicographic order of the dense exponent vectors (the first slot where two
//! monomials differ decides, the larger exponent is the larger monomial): the order every
//! polynomial's terms are sorted in, independent of how many slots a model has.

use std::cmp::Ordering;
use std::fmt;

use smallvec::SmallVec;

/// A monomial: the nonzero exponents by increasing atom slot.
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct Mono(SmallVec<[u32; 12]>);

const EXP_BITS: u32 = 8;
const EXP_MASK: u32 = (1 << EXP_BITS) - 1;

fn pack(slot: usize, e: u8) -> u32 {
    // Slots are below 2^17 (`SYM_SLOT_BASE` plus a u16 index): they fit in 24 bits.
    ((slot as u32) << EXP_BITS) | u32::from(e)
}

fn slot_of(f: u32) -> usize {
    (f >> EXP_BITS) as usize
}

fn exp_of(f: u32) -> u8 {
    (f & EXP_MASK) as u8
}

impl Mono {
    /// The monomial `1`.
    pub const ONE: Mono = Mono(SmallVec::new_const());

    /// The monomial of one atom slot to the first power.
    pub fn atom(slot: usize) -> Mono {
        Mono::power(slot, 1)
    }

    /// One atom slot to a power (`1` for the power 0).
    pub fn power(slot: usize, e: u8) -> Mono {
        let mut m = Mono::ONE;
        if e > 0 {
            m.0.push(pack(slot, e));
        }
        m
    }

    /// From `(slot, exponent)` pairs in any order (repeated slots add up, zeros vanish).
    pub fn from_factors(factors: impl IntoIterator<Item = (usize, u8)>) -> Mono {
        let mut m = Mono::ONE;
        for (s, e) in factors {
            m = m.mul(&Mono::power(s, e));
        }
        m
    }

    /// Product of two monomials.
    pub fn mul(&self, other: &Mono) -> Mono {
        let (a, b) = (&self.0, &other.0);
        if b.is_empty() {
            return self.clone();
        }
        if a.is_empty() {
            return other.clone();
        }
        let mut out = SmallVec::new();
        let (mut i, mut j) = (0, 0);
        while i < a.len() && j < b.len() {
            let (sa, sb) = (slot_of(a[i]), slot_of(b[j]));
            match sa.cmp(&sb) {
                Ordering::Less => {
                    out.push(a[i]);
                    i += 1;
                }
                Ordering::Greater => {
                    out.push(b[j]);
                    j += 1;
                }
                Ordering::Equal => {
                    out.push(pack(sa, exp_of(a[i]) + exp_of(b[j])));
                    i += 1;
                    j += 1;
                }
            }
        }
        out.extend_from_slice(&a[i..]);
        out.extend_from_slice(&b[j..]);
        Mono(out)
    }

    /// Quotient `self / other` if `other` divides `self`.
    pub fn div(&self, other: &Mono) -> Option<Mono> {
        let mut out = SmallVec::with_capacity(self.0.len());
        let mut j = 0;
        for &f in &self.0 {
            let s = slot_of(f);
            match other.0.get(j) {
                Some(&g) if slot_of(g) == s => {
                    let e = exp_of(f).checked_sub(exp_of(g))?;
                    if e > 0 {
                        out.push(pack(s, e));
                    }
                    j += 1;
                }
                Some(&g) if slot_of(g) < s => return None,
                _ => out.push(f),
            }
        }
        (j == other.0.len()).then_some(Mono(out))
    }

    /// Total degree.
    pub fn degree(&self) -> u32 {
        self.0.iter().map(|&f| u32::from(exp_of(f))).sum()
    }

    /// Whether this is the monomial `1`.
    pub fn is_one(&self) -> bool {
        self.0.is_empty()
    }

    /// The exponent of one slot.
    pub fn exponent(&self, slot: usize) -> u8 {
        self.0
            .iter()
            .find(|&&f| slot_of(f) == slot)
            .map_or(0, |&f| exp_of(f))
    }

    /// The same monomial with the exponent of `slot` set to `e`.
    pub fn with_exponent(&self, slot: usize, e: u8) -> Mono {
        let mut out: SmallVec<[u32; 12]> = self
            .0
            .iter()
            .copied()
            .filter(|&f| slot_of(f) != slot)
            .collect();
        if e > 0 {
            let at = out.partition_point(|&f| slot_of(f) < slot);
            out.insert(at, pack(slot, e));
        }
        Mono(out)
    }

    /// Slots with a nonzero exponent, with the exponent, by increasing slot.
    pub fn factors(&self) -> impl Iterator<Item = (usize, u8)> + '_ {
        self.0.iter().map(|&f| (slot_of(f), exp_of(f)))
    }

    /// The greatest common divisor of two monomials.
    pub fn gcd(&self, other: &Mono) -> Mono {
        let mut out = SmallVec::new();
        let mut j = 0;
        for &f in &self.0 {
            while j < other.0.len() && slot_of(other.0[j]) < slot_of(f) {
                j += 1;
            }
            if let Some(&g) = other.0.get(j)
                && slot_of(g) == slot_of(f)
            {
                out.push(pack(slot_of(f), exp_of(f).min(exp_of(g))));
            }
        }
        Mono(out)
    }
}

impl Ord for Mono {
    /// The lexicographic order of the dense exponent vectors.
    fn cmp(&self, other: &Mono) -> Ordering {
        let (a, b) = (&self.0, &other.0);
        let mut i = 0;
        loop {
            match (a.get(i), b.get(i)) {
                (None, None) => return Ordering::Equal,
                (Some(_), None) => return Ordering::Greater,
                (None, Some(_)) => return Ordering::Less,
                (Some(&f), Some(&g)) => {
                    if f == g {
                        i += 1;
                        continue;
                    }
                    let (sf, sg) = (slot_of(f), slot_of(g));
                    // The first slot where the dense vectors differ: a slot only one of them
                    // has (the other's exponent there is zero), or a different exponent.
                    return match sf.cmp(&sg) {
                        Ordering::Less => Ordering::Greater,
                        Ordering::Greater => Ordering::Less,
                        Ordering::Equal => exp_of(f).cmp(&exp_of(g)),
                    };
                }
            }
        }
    }
}

impl PartialOrd for Mono {
    fn partial_cmp(&self, other: &Mono) -> Option<Ordering> {
        Some(self.cmp(other))
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
            write!(f, "a{slot}")?;
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The dense lexicographic order, written out, as the reference for the sparse one.
    fn dense(m: &Mono) -> Vec<u8> {
        let mut v = vec![0u8; 64];
        for (s, e) in m.factors() {
            v[s] = e;
        }
        v
    }

    #[test]
    fn order_is_the_dense_lexicographic_order() {
        let ms = [
            Mono::ONE,
            Mono::atom(3),
            Mono::power(3, 2),
            Mono::from_factors([(1, 1), (5, 2)]),
            Mono::from_factors([(1, 1), (4, 1)]),
            Mono::from_factors([(1, 2)]),
            Mono::from_factors([(0, 1), (63, 1)]),
            Mono::atom(63),
        ];
        for a in &ms {
            for b in &ms {
                assert_eq!(a.cmp(b), dense(a).cmp(&dense(b)), "{a:?} vs {b:?}");
            }
        }
    }

    #[test]
    fn product_quotient_and_gcd() {
        let a = Mono::from_factors([(1, 2), (7, 1)]);
        let b = Mono::from_factors([(1, 1), (9, 3)]);
        let p = a.mul(&b);
        assert_eq!(p, Mono::from_factors([(1, 3), (7, 1), (9, 3)]));
        assert_eq!(p.div(&b), Some(a.clone()));
        assert_eq!(a.div(&b), None);
        assert_eq!(a.gcd(&b), Mono::atom(1));
        assert_eq!(p.with_exponent(9, 0), Mono::from_factors([(1, 3), (7, 1)]));
        assert_eq!(p.exponent(9), 3);
    }
}
