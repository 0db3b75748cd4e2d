//! The trig-aware printing context: free atom slots standing for `m_t`, `I_t` and the sine and
//! cosine of a shifted angle `theta_1 - delta`, the order atoms are printed in, and the choice
//! of the angle (`theta_1` or a shift of it) that writes an expression in the fewest terms.

use num_traits::One;

use super::notation::{atom_power, exponent};
use crate::poly::{Mono, Poly, Q};
use crate::symbol::{Atom, BaseAngle, SYM_SLOT_BASE, Sym};
use crate::trig::sin_cos_combination;

/// The plain symbols in the order they are printed in a product (and preferred when a common
/// factor is pulled out of a group of terms): masses and inertias first, as the paper writes
/// `m_t l^2`, `I_1 g`; then lengths, gravity, inputs, states; angles last.
const SYM_ORDER: [Sym; 30] = [
    Sym::M1,
    Sym::M2,
    Sym::I1,
    Sym::I2,
    Sym::L,
    Sym::R,
    Sym::G,
    Sym::Mu0,
    Sym::C,
    Sym::TSet,
    Sym::Kp,
    Sym::Kd,
    Sym::Mu,
    Sym::U,
    Sym::V,
    Sym::T,
    Sym::X,
    Sym::Z,
    Sym::Xd,
    Sym::Zd,
    Sym::Th1d,
    Sym::Th2d,
    Sym::Xdd,
    Sym::Zdd,
    Sym::Th1dd,
    Sym::Th2dd,
    Sym::Th1,
    Sym::Th2,
    Sym::Alpha,
    Sym::Phi,
];

/// The base angles in the order their sines and cosines are printed.
const ANGLE_ORDER: [BaseAngle; 4] = [
    BaseAngle::HalfAlpha,
    BaseAngle::Phi,
    BaseAngle::Th1,
    BaseAngle::Th2,
];

/// The angle `theta_1 - delta` some expressions are shorter in: the fore leg is at
/// `theta_1 - alpha`, the bisector of the two feet at `theta_1 - alpha/2`, the slope normal at
/// `phi`. The printer tries each and keeps the form with the fewest terms.
const SHIFTS: [(&[(BaseAngle, i64)], &str); 4] = [
    (
        &[(BaseAngle::HalfAlpha, 1)],
        "\\theta_1 - \\frac{\\alpha}{2}",
    ),
    (&[(BaseAngle::Phi, 1)], "\\theta_1 - \\phi"),
    (
        &[(BaseAngle::HalfAlpha, 1), (BaseAngle::Phi, 1)],
        "\\theta_1 - \\frac{\\alpha}{2} - \\phi",
    ),
    (&[(BaseAngle::HalfAlpha, 2)], "\\theta_1 - \\alpha"),
];

/// Atom slots that no symbol uses, standing inside the printer for `m_t`, `I_t` and the sine
/// and cosine of a shifted angle `psi = theta_1 - delta`.
#[derive(Clone, Copy)]
pub(super) struct Ctx {
    pub(super) mt: Option<usize>,
    pub(super) it: Option<usize>,
    /// `(sin psi, cos psi)` slots.
    psi: Option<(usize, usize)>,
    /// LaTeX of `psi`, when the expression is written in it.
    psi_latex: Option<&'static str>,
}

impl Ctx {
    fn new() -> Ctx {
        // Slots after every symbol of the table: the engine treats them as plain symbols (the
        // pseudo angle's `cos^2` is reduced by [`Ctx::reduce`]).
        let first = SYM_SLOT_BASE + super::table().len();
        let mt = Some(first);
        let it = Some(first + 1);
        let psi = Some((first + 2, first + 3));
        Ctx {
            mt,
            it,
            psi,
            psi_latex: None,
        }
    }

    /// Sort key of an atom slot in a printed product.
    pub(super) fn rank(&self, slot: usize) -> u32 {
        if Some(slot) == self.mt {
            return 0;
        }
        if Some(slot) == self.it {
            return 1;
        }
        if let Some((s, c)) = self.psi {
            if slot == s {
                return 250;
            }
            if slot == c {
                return 251;
            }
        }
        match Atom::of_slot(slot) {
            Atom::Sym(s) if s.index() < super::table().len() => SYM_ORDER
                .iter()
                .position(|&o| o == s)
                .map_or(100 + slot as u32, |p| 10 + p as u32),
            Atom::Sym(s) => 300 + s.index() as u32,
            Atom::Sin(a) => 200 + 2 * angle_rank(a),
            Atom::Cos(a) => 201 + 2 * angle_rank(a),
        }
    }

    pub(super) fn is_trig(&self, slot: usize) -> bool {
        matches!(Atom::of_slot(slot), Atom::Sin(_) | Atom::Cos(_))
            || self.psi.is_some_and(|(s, c)| slot == s || slot == c)
    }

    /// The `(sin, cos)` slot pairs: base angles, and `psi` when in use.
    pub(super) fn trig_pairs(&self) -> Vec<(usize, usize)> {
        let mut v: Vec<(usize, usize)> = super::table()
            .base_angles()
            .map(|a| (a.sin_slot(), a.cos_slot()))
            .collect();
        if let (Some(p), Some(_)) = (self.psi, self.psi_latex) {
            v.push(p);
        }
        v
    }

    /// `cos^2 -> 1 - sin^2` for the pseudo angle too (the engine's product reduces the base
    /// angles).
    pub(super) fn reduce(&self, p: &Poly) -> Poly {
        match (self.psi, self.psi_latex) {
            (Some((s, c)), Some(_)) => reduce_pair(p, s, c),
            _ => p.clone(),
        }
    }

    pub(super) fn slot_power(&self, slot: usize, e: u8) -> String {
        let p = if e == 1 { String::new() } else { exponent(e) };
        if Some(slot) == self.mt {
            return format!("m_t{p}");
        }
        if Some(slot) == self.it {
            return format!("I_t{p}");
        }
        if let (Some((s, c)), Some(arg)) = (self.psi, self.psi_latex) {
            if slot == s {
                return format!("\\sin{p}\\left({arg}\\right)");
            }
            if slot == c {
                return format!("\\cos{p}\\left({arg}\\right)");
            }
        }
        match Atom::of_slot(slot) {
            Atom::Sym(s) if s.index() >= super::table().len() => {
                format!("\\mathrm{{a}}_{{{slot}}}{p}")
            }
            a => atom_power(a, e),
        }
    }
}

fn angle_rank(a: BaseAngle) -> u32 {
    ANGLE_ORDER.iter().position(|&o| o == a).unwrap_or(0) as u32
}

pub(super) fn slot_poly(slot: usize) -> Poly {
    Poly::term(Mono::atom(slot), Q::one())
}

/// `cos^2 -> 1 - sin^2` for a pair of pseudo slots (the engine reduces only base angles).
fn reduce_pair(p: &Poly, s: usize, c: usize) -> Poly {
    if p.degree_in(c) < 2 {
        return p.clone();
    }
    let one_minus_s2 = Poly::one().sub(&slot_poly(s).mul(&slot_poly(s)));
    let mut acc = Poly::zero();
    for (k, a) in p.coeffs_in(c).iter().enumerate() {
        if a.is_zero() {
            continue;
        }
        let mut t = a.clone();
        if k % 2 == 1 {
            t = t.mul(&slot_poly(c));
        }
        for _ in 0..k / 2 {
            t = t.mul(&one_minus_s2);
        }
        acc = acc.add(&t);
    }
    acc
}

/// `p` with `theta_1 = psi + delta`, `psi` in the pseudo slots `(s, c)`.
fn shift(p: &Poly, delta: &[(BaseAngle, i64)], (s, c): (usize, usize)) -> Poly {
    let (sd, cd) = sin_cos_combination(delta);
    let (sp, cp) = (slot_poly(s), slot_poly(c));
    let sin_th = sp.mul(&cd).add(&cp.mul(&sd));
    let cos_th = cp.mul(&cd).sub(&sp.mul(&sd));
    let p = p.substitute(BaseAngle::Th1.sin_slot(), &sin_th);
    let p = p.substitute(BaseAngle::Th1.cos_slot(), &cos_th);
    reduce_pair(&p, s, c)
}

/// The numerator and denominator written in the angle (`theta_1` or one of [`SHIFTS`]) that
/// gives the fewest terms.
pub(super) fn best_angle(num: &Poly, den: &Poly) -> (Ctx, Poly, Poly) {
    let mut ctx = Ctx::new();
    let th1 = [BaseAngle::Th1.sin_slot(), BaseAngle::Th1.cos_slot()];
    let has = |slot: usize| num.contains(slot) || den.contains(slot);
    let mut best = (num.clone(), den.clone());
    if let Some(pair) = ctx.psi
        && th1.iter().any(|&s| has(s))
    {
        let mut best_len = num.len() + den.len();
        for (delta, latex) in SHIFTS {
            let present = delta
                .iter()
                .all(|(a, _)| has(a.sin_slot()) || has(a.cos_slot()));
            if !present {
                continue;
            }
            let n = shift(num, delta, pair);
            let d = shift(den, delta, pair);
            if n.len() + d.len() < best_len {
                best_len = n.len() + d.len();
                best = (n, d);
                ctx.psi_latex = Some(latex);
            }
        }
    }
    (ctx, best.0, best.1)
}
