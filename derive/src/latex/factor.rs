//! Factoring a polynomial for print: the sign, the rational content, the common monomial,
//! `m_t` and `I_t` (by trial division or substitution) and hidden cosine factors are pulled
//! out, leaving a sum without common factor.

use num_traits::{One, Signed, Zero};

use super::context::{Ctx, slot_poly};
use crate::poly::{Mono, Poly, Q};
use crate::symbol::{Atom, Sym};

/// A polynomial as a product `sign * coef * mono * (rest)`.
pub(super) struct Factored {
    pub(super) negative: bool,
    /// Positive rational coefficient.
    pub(super) coef: Q,
    /// The common monomial (pseudo slots included; may hold `cos^2` for printing).
    pub(super) mono: Mono,
    /// The remaining sum (at least two terms), no common monomial.
    pub(super) rest: Option<Poly>,
}

fn sym_poly(s: Sym) -> Poly {
    Poly::atom(Atom::Sym(s))
}

/// Abbreviates `a + b` as the pseudo atom `t`: first pulls out every power of `a + b` by
/// trial division, then, if what is left depends on `a` and `b` only through `a + b`, writes
/// it in `t`. Returns the power pulled out and the new polynomial.
fn abbreviate(p: Poly, a: Sym, b: Sym, t: Option<usize>) -> (u8, Poly) {
    let Some(t) = t else { return (0, p) };
    let sum = sym_poly(a).add(&sym_poly(b));
    let mut p = p;
    let mut power = 0u8;
    while p.contains(a.slot()) && p.contains(b.slot()) {
        match p.div_exact(&sum) {
            Some(q) => {
                p = q;
                power += 1;
            }
            None => break,
        }
    }
    if p.contains(a.slot()) && p.contains(b.slot()) {
        let s = p.substitute(a.slot(), &slot_poly(t).sub(&sym_poly(b)));
        if !s.contains(b.slot()) {
            p = s;
        }
    }
    (power, p)
}

/// Hidden cosine factors are searched for in sums of at most this many terms.
const MAX_COSINE_SEARCH: usize = 200;

pub(super) fn factor(p: &Poly, ctx: &Ctx) -> Factored {
    if p.is_zero() {
        return Factored {
            negative: false,
            coef: Q::zero(),
            mono: Mono::ONE,
            rest: None,
        };
    }
    let (c1, prim) = p.content_primitive();
    let mono1 = prim.monomial_content();
    let prim = prim
        .div_exact(&Poly::term(mono1.clone(), Q::one()))
        .unwrap_or(prim);
    let (mt_power, prim) = abbreviate(prim, Sym::M1, Sym::M2, ctx.mt);
    let (it_power, prim) = abbreviate(prim, Sym::I1, Sym::I2, ctx.it);
    let (c2, prim) = prim.content_primitive();
    let mono2 = prim.monomial_content();
    let mut rest = prim
        .div_exact(&Poly::term(mono2.clone(), Q::one()))
        .unwrap_or(prim);
    let mut mono = mono1.mul(&mono2);
    if let Some(s) = ctx.mt {
        mono = mono.mul(&Mono::power(s, mt_power));
    }
    if let Some(s) = ctx.it {
        mono = mono.mul(&Mono::power(s, it_power));
    }
    let mut coef = c1 * c2;
    // Cosine factors that the reduced form hides (`I_1 - I_1 \sin^2\phi` is
    // `I_1 \cos^2\phi`): `p` is `cos(a) q` exactly when `p cos(a)`, reduced, is divisible by
    // `1 - sin^2(a)` in the free ring, and then `q` is the quotient.
    if rest.len() <= MAX_COSINE_SEARCH {
        for (s, c) in ctx.trig_pairs() {
            let one_minus_s2 = Poly::one().sub(&slot_poly(s).mul_raw(&slot_poly(s)));
            while !rest.is_constant() {
                let times_c = ctx.reduce(&rest.mul(&slot_poly(c)));
                let Some(q) = times_c.div_exact(&one_minus_s2) else {
                    break;
                };
                let (k, q) = q.content_primitive();
                coef *= k;
                rest = q;
                mono = mono.mul(&Mono::atom(c));
                let m = rest.monomial_content();
                if !m.is_one() {
                    rest = rest
                        .div_exact(&Poly::term(m.clone(), Q::one()))
                        .unwrap_or(rest);
                    mono = mono.mul(&m);
                }
            }
        }
    }
    // The sign that makes the lowest-degree term positive (g - l thdot^2 cos, not
    // -(l thdot^2 cos - g)).
    let lowest = rest
        .terms()
        .iter()
        .min_by_key(|(m, _)| m.degree())
        .map(|(_, c)| c.is_negative());
    if rest.len() > 1 && lowest == Some(true) {
        rest = rest.neg();
        coef = -coef;
    }
    Factored {
        negative: coef.is_negative(),
        coef: coef.abs(),
        mono,
        rest: if rest.len() > 1 { Some(rest) } else { None },
    }
}
