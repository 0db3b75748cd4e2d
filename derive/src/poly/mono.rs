//! Monomials: the exponent of every atom slot, and the plain-text names of the slots.

use std::fmt;

use crate::symbol::{Atom, NUM_ATOMS};

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
