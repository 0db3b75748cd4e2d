//! Readable LaTeX for people: derived quantities in the paper's notation, for Markdown that
//! GitHub renders (`$$ ... $$` blocks), and the generator of `docs/equations.md`.
//!
//! A polynomial is printed as `sign * content * monomial * (rest)`: the rational content and
//! the greatest common monomial are pulled out, `m_1 + m_2` and `I_1 + I_2` are abbreviated as
//! `m_t` and `I_t` where the polynomial is divisible by them (trial division,
//! [`Poly::div_exact`]) or depends on the masses (inertias) only through their sum, and the
//! rest is grouped greedily: the atom that occurs in most terms is factored out of them, and
//! the groups are printed recursively. A [`RatFunc`] is a `\frac` of two such products (or a
//! polynomial). Everything is a function of the canonical form only, so the output is
//! deterministic.
//!
//! Two rewritings make the trigonometry readable, both exact and only for printing:
//!
//! - hidden cosine factors: the reduced form has no `\cos^2`, so `I_1 \cos^2\phi` is held as
//!   `I_1 - I_1 \sin^2\phi`; a factor `\cos a` is recognised (`p = \cos a \, q` exactly when
//!   `p \cos a`, reduced, is divisible by `1 - \sin^2 a`) and pulled out, and a group equal to
//!   `\sin^2 a - 1` is printed `-\cos^2 a`;
//! - shifted angles: an expression in `\theta_1` and `\alpha` or `\phi` is also written in
//!   `\theta_1 - \delta` for `\delta` one of `\alpha/2`, `\phi`, `\alpha/2 + \phi`, `\alpha` (the
//!   bisector of the feet, the slope normal, the fore leg), and the form with the fewest terms
//!   is printed, e.g. `\sin\left(\theta_1 - \phi\right)` for the slope's stance quantities.
//!
//! Otherwise angles are printed as the engine holds them: `\alpha` through its half, so the
//! paper's `1 - \cos\alpha` reads `2 \sin^2\frac{\alpha}{2}` and `\sin\alpha` reads
//! `2 \sin\frac{\alpha}{2} \cos\frac{\alpha}{2}`.

use std::fmt::Write as _;

use num_traits::{One, Signed, Zero};

use crate::error::Result;
use crate::kernels::{Derivation, Kernel, Shape};
use crate::matrix::Matrix;
use crate::mechanics::{self, Floor};
use crate::poly::{Mono, Poly, Q};
use crate::ratfunc::RatFunc;
use crate::symbol::{Atom, BaseAngle, NUM_ATOMS, Sym};
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
struct Ctx {
    mt: Option<usize>,
    it: Option<usize>,
    /// `(sin psi, cos psi)` slots.
    psi: Option<(usize, usize)>,
    /// LaTeX of `psi`, when the expression is written in it.
    psi_latex: Option<&'static str>,
}

impl Ctx {
    fn new() -> Ctx {
        let mut free =
            (2 * crate::symbol::NUM_ANGLES..NUM_ATOMS).filter(|&s| Atom::of_slot(s).is_none());
        let mt = free.next();
        let it = free.next();
        let psi = free.next().zip(free.next());
        Ctx {
            mt,
            it,
            psi,
            psi_latex: None,
        }
    }

    /// Sort key of an atom slot in a printed product.
    fn rank(&self, slot: usize) -> u32 {
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
            Some(Atom::Sym(s)) => SYM_ORDER
                .iter()
                .position(|&o| o == s)
                .map_or(100 + slot as u32, |p| 10 + p as u32),
            Some(Atom::Sin(a)) => 200 + 2 * angle_rank(a),
            Some(Atom::Cos(a)) => 201 + 2 * angle_rank(a),
            None => 300 + slot as u32,
        }
    }

    fn is_trig(&self, slot: usize) -> bool {
        matches!(Atom::of_slot(slot), Some(Atom::Sin(_) | Atom::Cos(_)))
            || self.psi.is_some_and(|(s, c)| slot == s || slot == c)
    }

    /// The `(sin, cos)` slot pairs: base angles, and `psi` when in use.
    fn trig_pairs(&self) -> Vec<(usize, usize)> {
        let mut v: Vec<(usize, usize)> = BaseAngle::ALL
            .iter()
            .map(|a| (a.sin_slot(), a.cos_slot()))
            .collect();
        if let (Some(p), Some(_)) = (self.psi, self.psi_latex) {
            v.push(p);
        }
        v
    }

    /// `cos^2 -> 1 - sin^2` for the pseudo angle too (the engine's product reduces the base
    /// angles).
    fn reduce(&self, p: &Poly) -> Poly {
        match (self.psi, self.psi_latex) {
            (Some((s, c)), Some(_)) => reduce_pair(p, s, c),
            _ => p.clone(),
        }
    }

    fn slot_power(&self, slot: usize, e: u8) -> String {
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
            Some(a) => atom_power(a, e),
            None => format!("\\mathrm{{a}}_{{{slot}}}{p}"),
        }
    }
}

fn angle_rank(a: BaseAngle) -> u32 {
    ANGLE_ORDER.iter().position(|&o| o == a).unwrap_or(0) as u32
}

fn exponent(e: u8) -> String {
    if e < 10 {
        format!("^{e}")
    } else {
        format!("^{{{e}}}")
    }
}

/// The LaTeX of a base angle: `\theta_1`, `\theta_2`, `\frac{\alpha}{2}`, `\phi`.
pub fn angle(a: BaseAngle) -> &'static str {
    match a {
        BaseAngle::Th1 => "\\theta_1",
        BaseAngle::Th2 => "\\theta_2",
        BaseAngle::HalfAlpha => "\\frac{\\alpha}{2}",
        BaseAngle::Phi => "\\phi",
    }
}

/// The LaTeX of an atom to a power: `m_1^2`, `\sin^2\theta_1`, `\cos\frac{\alpha}{2}`.
pub fn atom_power(atom: Atom, e: u8) -> String {
    let p = if e == 1 { String::new() } else { exponent(e) };
    match atom {
        Atom::Sym(s) => format!("{}{p}", s.latex()),
        Atom::Sin(a) => format!("\\sin{p}{}", angle(a)),
        Atom::Cos(a) => format!("\\cos{p}{}", angle(a)),
    }
}

/// A rational number: `3`, `-2`, `\frac{1}{2}`, `-\frac{3}{4}`.
pub fn rational(q: &Q) -> String {
    let sign = if q.is_negative() { "-" } else { "" };
    let a = q.abs();
    if a.is_integer() {
        format!("{sign}{}", a.numer())
    } else {
        format!("{sign}\\frac{{{}}}{{{}}}", a.numer(), a.denom())
    }
}

/// A polynomial as a product `sign * coef * mono * (rest)`.
struct Factored {
    negative: bool,
    /// Positive rational coefficient.
    coef: Q,
    /// The common monomial (pseudo slots included; may hold `cos^2` for printing).
    mono: Mono,
    /// The remaining sum (at least two terms), no common monomial.
    rest: Option<Poly>,
}

fn sym_poly(s: Sym) -> Poly {
    Poly::atom(Atom::Sym(s))
}

fn slot_poly(slot: usize) -> Poly {
    Poly::term(Mono::atom(slot), Q::one())
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
fn best_angle(num: &Poly, den: &Poly) -> (Ctx, Poly, Poly) {
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

fn factor(p: &Poly, ctx: &Ctx) -> Factored {
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
    let prim = prim.div_exact(&Poly::term(mono1, Q::one())).unwrap_or(prim);
    let (mt_power, prim) = abbreviate(prim, Sym::M1, Sym::M2, ctx.mt);
    let (it_power, prim) = abbreviate(prim, Sym::I1, Sym::I2, ctx.it);
    let (c2, prim) = prim.content_primitive();
    let mono2 = prim.monomial_content();
    let mut rest = prim.div_exact(&Poly::term(mono2, Q::one())).unwrap_or(prim);
    let mut mono = mono1.mul(&mono2);
    if let Some(s) = ctx.mt {
        mono.0[s] += mt_power;
    }
    if let Some(s) = ctx.it {
        mono.0[s] += it_power;
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
                mono.0[c] += 1;
                let m = rest.monomial_content();
                if !m.is_one() {
                    rest = rest.div_exact(&Poly::term(m, Q::one())).unwrap_or(rest);
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

/// The atoms of a monomial in print order, split into (non-trigonometric, trigonometric).
fn mono_parts(m: &Mono, ctx: &Ctx) -> (Vec<String>, Vec<String>) {
    let mut slots: Vec<(usize, u8)> = m.factors().collect();
    slots.sort_by_key(|&(s, _)| ctx.rank(s));
    let mut plain = Vec::new();
    let mut trig = Vec::new();
    for (s, e) in slots {
        let text = ctx.slot_power(s, e);
        if ctx.is_trig(s) {
            trig.push(text);
        } else {
            plain.push(text);
        }
    }
    (plain, trig)
}

/// `coef mono (rest)`, with the group before the trigonometric factors so that
/// `\cos\theta_1 (a + b)` is never misread as a cosine of a product.
fn product(coef: &Q, mono: &Mono, rest: Option<&Poly>, ctx: &Ctx) -> String {
    let (plain, trig) = mono_parts(mono, ctx);
    let mut parts: Vec<String> = Vec::new();
    let bare = plain.is_empty() && trig.is_empty() && rest.is_none();
    if !coef.is_one() || bare {
        parts.push(rational(coef));
    }
    parts.extend(plain);
    if let Some(r) = rest {
        let s = sum(r, ctx);
        if parts.is_empty() && trig.is_empty() {
            parts.push(s);
        } else {
            parts.push(format!("\\left({s}\\right)"));
        }
    }
    parts.extend(trig);
    parts.join(" ")
}

/// One printed term of a sum.
struct Item {
    negative: bool,
    text: String,
    degree: u32,
}

fn min_degree(p: &Poly) -> u32 {
    p.terms().iter().map(|(m, _)| m.degree()).min().unwrap_or(0)
}

fn item_of(p: &Poly, ctx: &Ctx) -> Item {
    let f = factor(p, ctx);
    Item {
        negative: f.negative,
        text: product(&f.coef, &f.mono, f.rest.as_ref(), ctx),
        degree: min_degree(p),
    }
}

/// Splits a sum into printed items: the atom that occurs in most terms (at least two, not
/// all) is factored out of those terms; ties go to the atom printed first.
fn group(p: &Poly, ctx: &Ctx, items: &mut Vec<Item>) {
    if p.is_zero() {
        return;
    }
    let n = p.len();
    if n > 1 {
        // A common factor (content, monomial, m_t, I_t, a hidden cosine): one item.
        let f = factor(p, ctx);
        if !f.coef.is_one() || !f.mono.is_one() {
            items.push(Item {
                negative: f.negative,
                text: product(&f.coef, &f.mono, f.rest.as_ref(), ctx),
                degree: min_degree(p),
            });
            return;
        }
    }
    let mut best: Option<(usize, usize)> = None;
    if n > 2 {
        for slot in 0..NUM_ATOMS {
            let count = p.terms().iter().filter(|(m, _)| m.0[slot] > 0).count();
            if count < 2 || count == n {
                continue;
            }
            let better = match best {
                None => true,
                Some((bs, bc)) => count > bc || (count == bc && ctx.rank(slot) < ctx.rank(bs)),
            };
            if better {
                best = Some((slot, count));
            }
        }
    }
    let Some((slot, _)) = best else {
        for t in p.terms() {
            items.push(item_of(&Poly::from_terms([t.clone()]), ctx));
        }
        return;
    };
    let (with, without): (Vec<_>, Vec<_>) =
        p.terms().iter().cloned().partition(|(m, _)| m.0[slot] > 0);
    items.push(item_of(&Poly::from_terms(with), ctx));
    group(&Poly::from_terms(without), ctx, items);
}

/// A sum (at least two terms, no common factor) grouped and ordered: lowest degree first,
/// then by text; a positive item leads when there is one.
fn sum(p: &Poly, ctx: &Ctx) -> String {
    let mut items = Vec::new();
    group(p, ctx, &mut items);
    items.sort_by(|a, b| a.degree.cmp(&b.degree).then_with(|| a.text.cmp(&b.text)));
    if let Some(k) = items.iter().position(|i| !i.negative)
        && k > 0
    {
        let first = items.remove(k);
        items.insert(0, first);
    }
    let mut out = String::new();
    for (k, it) in items.iter().enumerate() {
        match (k, it.negative) {
            (0, false) => {}
            (0, true) => out.push('-'),
            (_, false) => out.push_str(" + "),
            (_, true) => out.push_str(" - "),
        }
        out.push_str(&it.text);
    }
    out
}

fn poly_in(p: &Poly, ctx: &Ctx) -> String {
    if p.is_zero() {
        return "0".into();
    }
    let f = factor(p, ctx);
    let body = product(&f.coef, &f.mono, f.rest.as_ref(), ctx);
    if f.negative { format!("-{body}") } else { body }
}

/// A polynomial in the paper's notation.
pub fn poly(p: &Poly) -> String {
    let (ctx, p, _) = best_angle(p, &Poly::one());
    poly_in(&p, &ctx)
}

/// A rational function: `\frac{num}{den}` with the contents and common monomials of both
/// pulled out (the integer part of the content above, its denominator below), or a
/// polynomial.
pub fn ratfunc(r: &RatFunc) -> String {
    let (ctx, num, den) = best_angle(r.num(), r.den());
    fraction(&num, &den, &ctx)
}

fn fraction(num: &Poly, den: &Poly, ctx: &Ctx) -> String {
    if *den == Poly::one() {
        return poly_in(num, ctx);
    }
    let n = factor(num, ctx);
    let d = factor(den, ctx);
    let (mut nm, mut dm) = (n.mono, d.mono);
    for (a, b) in nm.0.iter_mut().zip(dm.0.iter_mut()) {
        let common = (*a).min(*b);
        *a -= common;
        *b -= common;
    }
    let c = &n.coef / &d.coef;
    let top = Q::from_integer(c.numer().clone());
    let bottom = Q::from_integer(c.denom().clone());
    let num = product(&top, &nm, n.rest.as_ref(), ctx);
    let den = product(&bottom, &dm, d.rest.as_ref(), ctx);
    let sign = if n.negative != d.negative { "-" } else { "" };
    if den == "1" {
        return format!("{sign}{num}");
    }
    format!("{sign}\\frac{{{num}}}{{{den}}}")
}

/// [`ratfunc`], or `None` when the printed form would have more than `max_terms` terms
/// (numerator and denominator together).
pub fn ratfunc_at_most(r: &RatFunc, max_terms: usize) -> Option<String> {
    if r.num().len() + r.den().len() > 4 * max_terms {
        return None;
    }
    let (ctx, num, den) = best_angle(r.num(), r.den());
    (num.len() + den.len() <= max_terms).then(|| fraction(&num, &den, &ctx))
}

/// A matrix as `\begin{bmatrix} ... \end{bmatrix}`.
pub fn matrix(m: &Matrix) -> String {
    let rows: Vec<String> = (0..m.rows())
        .map(|i| {
            (0..m.cols())
                .map(|j| ratfunc(m.get(i, j)))
                .collect::<Vec<_>>()
                .join(" & ")
        })
        .collect();
    format!(
        "\\begin{{bmatrix}} {} \\end{{bmatrix}}",
        rows.join(" \\\\ ")
    )
}

/// A list of symbols in LaTeX, comma separated.
pub fn symbols(syms: &[Sym]) -> String {
    syms.iter()
        .map(|s| s.latex())
        .collect::<Vec<_>>()
        .join(", ")
}

/// Outputs larger than this (terms of numerator and denominator together) are described,
/// not printed: a formula of hundreds of terms is not read by anyone, and GitHub's renderer
/// gives up on very long math blocks.
pub const MAX_PRINTED_TERMS: usize = 120;

/// Hidden cosine factors are searched for in sums of at most this many terms.
const MAX_COSINE_SEARCH: usize = 200;

/// Entries of a matrix or vector are shown in one `bmatrix` when each is at most this long.
const MAX_CELL_CHARS: usize = 90;

fn escape_text(s: &str) -> String {
    s.replace('_', "\\_")
}

/// The LaTeX label of a velocity or acceleration component `k` of `q`.
fn q_label(k: usize, dots: &str, post: &str) -> Option<String> {
    let base = ["x", "z", "\\theta_1", "\\theta_2"].get(k)?;
    Some(match k {
        0 | 1 => format!("\\{dots}{{{base}}}{post}"),
        _ => format!("\\{dots}{{\\theta}}_{}{post}", k - 1),
    })
}

fn split_index(name: &str) -> (&str, Option<usize>) {
    let stem = name.trim_end_matches(|c: char| c.is_ascii_digit());
    (stem, name[stem.len()..].parse().ok())
}

/// The LaTeX label of output `k` of a kernel.
pub fn output_label(kernel: &Kernel, k: usize) -> String {
    let Some((name, _)) = kernel.outputs.get(k) else {
        return String::new();
    };
    if let Shape::Matrix(rows, cols) = kernel.shape {
        let (i, j) = (k / cols, k % cols);
        if kernel.name.ends_with("_jacobian") && rows == 4 && j < kernel.args.len() {
            let (dots, post) = if kernel.name.starts_with("impact") {
                ("dot", "^+")
            } else {
                ("ddot", "")
            };
            if let Some(row) = q_label(i, dots, post) {
                return format!(
                    "\\frac{{\\partial {row}}}{{\\partial {}}}",
                    kernel.args[j].latex()
                );
            }
        }
        let (stem, _) = split_index(name);
        return format!("{}_{{{}{}}}", escape_stem(stem), i + 1, j + 1);
    }
    let (stem, index) = split_index(name);
    let fixed = match name.as_str() {
        "lambda" => Some("\\lambda".to_owned()),
        "lambda_t" => Some("\\lambda_t".to_owned()),
        "lambda_n" => Some("\\lambda_n".to_owned()),
        "x_f" => Some("\\bar{x}".to_owned()),
        "z_f" => Some("\\bar{z}".to_owned()),
        "xd_f" => Some("\\dot{\\bar{x}}".to_owned()),
        "zd_f" => Some("\\dot{\\bar{z}}".to_owned()),
        _ => None,
    };
    if let Some(f) = fixed {
        return f;
    }
    match (stem, index) {
        ("lambdaI", Some(i)) => format!("\\lambda_{{I{}}}", i + 1),
        ("qdp", Some(i)) => q_label(i, "dot", "^+").unwrap_or_else(|| format!("\\dot{{q}}^+_{i}")),
        ("qdd", Some(i)) => q_label(i, "ddot", "").unwrap_or_else(|| format!("\\ddot{{q}}_{i}")),
        (s, Some(i)) => format!("{}_{{{}}}", escape_stem(s), i + 1),
        (s, None) => escape_stem(s),
    }
}

fn escape_stem(stem: &str) -> String {
    if stem.chars().count() == 1 {
        stem.to_owned()
    } else {
        format!("\\mathrm{{{}}}", escape_text(stem))
    }
}

fn math_block(out: &mut String, body: &str) {
    let _ = write!(out, "\n$$\n{body}\n$$\n");
}

fn describe_large(out: &mut String, label: &str, r: &RatFunc) {
    let _ = writeln!(
        out,
        "\n${label}$: {} terms over {} terms, not printed.",
        r.num().len(),
        r.den().len()
    );
    if let Some(den) = ratfunc_at_most(&RatFunc::from(r.den().clone()), MAX_PRINTED_TERMS) {
        let _ = writeln!(out, "Its denominator:");
        math_block(out, &den);
    }
}

/// Renders the outputs of a kernel: one `bmatrix` when the shape is a vector or matrix and
/// every entry is short, otherwise one block per output.
fn kernel_outputs(out: &mut String, kernel: &Kernel) {
    let rendered: Vec<Option<String>> = kernel
        .outputs
        .iter()
        .map(|(_, r)| ratfunc_at_most(r, MAX_PRINTED_TERMS))
        .collect();
    let short = rendered
        .iter()
        .all(|r| r.as_ref().is_some_and(|s| s.len() <= MAX_CELL_CHARS));
    let grid = match kernel.shape {
        Shape::Matrix(r, c) if !kernel.name.ends_with("_jacobian") => Some((r, c)),
        Shape::Vector(n) => Some((n, 1)),
        _ => None,
    };
    if let (true, Some((rows, cols))) = (short, grid)
        && rows * cols == rendered.len()
    {
        let (stem, _) = split_index(&kernel.outputs[0].0);
        let lhs = match stem {
            "M" | "Y" => stem.to_owned(),
            "h" => "\\boldsymbol{h}".to_owned(),
            "qdd" => "\\ddot{\\boldsymbol{q}}".to_owned(),
            _ => {
                let labels: Vec<String> = (0..rendered.len())
                    .map(|k| output_label(kernel, k))
                    .collect();
                format!(
                    "\\begin{{bmatrix}} {} \\end{{bmatrix}}",
                    labels.join(" \\\\ ")
                )
            }
        };
        let body: Vec<String> = (0..rows)
            .map(|i| {
                (0..cols)
                    .map(|j| rendered[i * cols + j].clone().unwrap_or_default())
                    .collect::<Vec<_>>()
                    .join(" & ")
            })
            .collect();
        math_block(
            out,
            &format!(
                "{lhs} = \\begin{{bmatrix}} {} \\end{{bmatrix}}",
                body.join(" \\\\ ")
            ),
        );
        return;
    }
    for (k, ((_, r), text)) in kernel.outputs.iter().zip(&rendered).enumerate() {
        let label = output_label(kernel, k);
        match text {
            Some(t) => math_block(out, &format!("{label} = {t}")),
            None => describe_large(out, &label, r),
        }
    }
}

fn kernel_section(out: &mut String, kernel: &Kernel) {
    let _ = writeln!(out, "\n### `{}`\n", kernel.name);
    let _ = writeln!(out, "{} ({}).\n", kernel.doc, kernel.equation);
    let args: Vec<String> = kernel
        .args
        .iter()
        .map(|s| format!("`{}` (${}$)", s.name(), s.latex()))
        .collect();
    let params: Vec<String> = kernel
        .params()
        .iter()
        .map(|s| format!("`{}` (${}$)", s.name(), s.latex()))
        .collect();
    let _ = writeln!(out, "- inputs: {}", args.join(", "));
    let _ = writeln!(
        out,
        "- parameters: {}",
        if params.is_empty() {
            "none".to_owned()
        } else {
            params.join(", ")
        }
    );
    let names: Vec<String> = kernel
        .outputs
        .iter()
        .map(|(n, _)| format!("`{n}`"))
        .collect();
    let _ = writeln!(out, "- outputs, in order: {}", names.join(", "));
    kernel_outputs(out, kernel);
}

/// The paper's pre-impact state and posture applied to every output of an impact kernel.
fn at_paper_impact(kernel: &Kernel, floor: Floor) -> Result<Vec<RatFunc>> {
    kernel
        .outputs
        .iter()
        .map(|(_, r)| mechanics::paper_pre_impact(&mechanics::at_impact_posture(r, floor)?, floor))
        .collect()
}

fn impact_closed_form(
    out: &mut String,
    d: &Derivation,
    name: &str,
    floor: Floor,
    title: &str,
) -> Result<Vec<RatFunc>> {
    let kernel = d.kernel(name)?;
    let values = at_paper_impact(kernel, floor)?;
    let _ = writeln!(out, "\n### {title} (`{name}`)\n");
    for (k, v) in values.iter().enumerate() {
        let label = output_label(kernel, k);
        match ratfunc_at_most(v, MAX_PRINTED_TERMS) {
            Some(t) => math_block(out, &format!("{label} = {t}")),
            None => describe_large(out, &label, v),
        }
    }
    Ok(values)
}

/// The rear-foot impulse of a double-support impact multiplied by `4 l sin(alpha/2)` and
/// divided by `thdot_1^-`: the left minus the right side of the paper's condition.
fn dls_margin(rear_impulse: &RatFunc, floor: Floor) -> Result<RatFunc> {
    let scale = &(&mechanics::int(4) * &mechanics::sym(Sym::L)) * &mechanics::sin_half_alpha();
    let margin = (rear_impulse * &scale).div(&mechanics::sym(Sym::Th1d))?;
    Ok(match floor {
        Floor::Level => margin,
        // The kernel reports the vertical impulse: divide by cos phi for the normal one.
        Floor::Slope => margin.div(&RatFunc::cos_of(BaseAngle::Phi))?,
    })
}

/// The whole of `docs/equations.md`: every kernel of the derivation rendered, the paper's
/// closed forms at the impact posture, and the double-support conditions.
pub fn equations_markdown(d: &Derivation) -> Result<String> {
    let mut out = String::new();
    out.push_str(
        "# Derived equations\n\n\
         Generated from the derivation by `cargo run -p walker-symbolic --bin walker-equations --release`;\n\
         do not edit by hand (`derive/tests/equations_doc.rs` fails when this file and the derivation\n\
         differ). The paper's equations are checked one by one in [errata.md](errata.md); the kernel\n\
         contract (names, inputs, conventions) is [kernels.md](kernels.md).\n\n\
         Notation, as the engine holds the expressions (canonical form, see `derive/src/poly.rs`):\n\n\
         - $m_t = m_1 + m_2$ and $I_t = I_1 + I_2$ where an expression is divisible by them or depends\n  \
           on the masses (inertias) only through their sum.\n\
         - $\\alpha$ enters through its half: the paper's $1 - \\cos\\alpha$ is $2\\sin^2\\frac{\\alpha}{2}$ and\n  \
           $\\sin\\alpha$ is $2\\sin\\frac{\\alpha}{2}\\cos\\frac{\\alpha}{2}$. Powers of cosines are reduced by\n  \
           $\\cos^2 = 1 - \\sin^2$, so $1 - \\cos 2\\theta_1$ reads $2\\sin^2\\theta_1$; the printer puts\n  \
           cosine factors hidden by that reduction back ($I_1 - I_1\\sin^2\\phi$ is $I_1\\cos^2\\phi$).\n\
         - Where it is shorter, an expression is written in the angle $\\theta_1 - \\frac{\\alpha}{2}$ (the\n  \
           bisector of the feet), $\\theta_1 - \\phi$, $\\theta_1 - \\frac{\\alpha}{2} - \\phi$ or $\\theta_1 - \\alpha$\n  \
           (the fore leg) instead of $\\theta_1$.\n\
         - $\\mu$ is the friction coefficient with its direction (Eq. 24; Eqs. 26, 37 say what it is).\n\
         - On the slope, $\\lambda$ and the foot impulses are vertical components, as in Eqs. 36 and 42\n  \
           (the normal force is $\\lambda / \\cos\\phi$).\n\
         - The stick kernels (the stance foot at rest; not in the paper) report the ground force as\n  \
           $\\lambda_t$ along the floor's unit tangent $(\\cos\\phi, -\\sin\\phi)$ and $\\lambda_n$ along its unit\n  \
           normal $(\\sin\\phi, \\cos\\phi)$: on the slope $\\lambda_n$ is the normal force itself.\n\
         - Impact kernels take the general $\\theta_1$ and pre-impact velocities; $\\dot{x}^+, \\dot{z}^+,\n  \
           \\dot{\\theta}_1^+, \\dot{\\theta}_2^+$ are the velocities of the old coordinates right after impact.\n\
         - Outputs of more than ",
    );
    let _ = writeln!(
        out,
        "{MAX_PRINTED_TERMS} terms (numerator and denominator together) are described, not printed."
    );
    out.push_str("\n## Kernels\n");
    for kernel in &d.kernels {
        kernel_section(&mut out, kernel);
    }
    out.push_str(
        "\n## The paper's closed forms at the impact posture\n\n\
         The impact kernels with the paper's pre-impact state substituted: $\\theta_1 = \\alpha/2$ on\n\
         level ground and $\\theta_1 = \\alpha/2 + \\phi$ on the slope; the stance foot not moving into\n\
         the floor ($\\dot{z}^- = 0$, on the slope $\\dot{z}^- = -\\dot{x}^-\\tan\\phi$); the torso locked\n\
         ($\\dot{\\theta}_2^- = \\dot{\\theta}_1^-$). The velocity symbols below are the pre-impact ones.\n",
    );
    let level3 = impact_closed_form(
        &mut out,
        d,
        "impact3_level",
        Floor::Level,
        "Level ground, fore foot, rear foot and torso lock: Eqs. 8 and 10",
    )?;
    impact_closed_form(
        &mut out,
        d,
        "impact2_level",
        Floor::Level,
        "Level ground, fore foot and torso lock: Eqs. 13-16",
    )?;
    impact_closed_form(
        &mut out,
        d,
        "impact_slope",
        Floor::Slope,
        "Slope, fore foot only: Eqs. 39-42",
    )?;
    let slope2 = impact_closed_form(
        &mut out,
        d,
        "impact2_slope",
        Floor::Slope,
        "Slope, fore foot and rear foot: Eq. 46",
    )?;
    out.push_str(
        "\n## Conditions for double-limb support\n\n\
         The rear foot keeps contact (non-instantaneous double-limb support) when its impulse in the\n\
         impact with the rear-foot constraint is non-negative. For $\\dot{\\theta}_1^- > 0$ the sign is that of\n\
         the impulse times $4 l \\sin\\frac{\\alpha}{2} / \\dot{\\theta}_1^-$ (on the slope, of the normal impulse,\n\
         the vertical one over $\\cos\\phi$), which is the left minus the right side of the paper's condition.\n\n\
         Level ground (Eq. 11, $m_t l^2 (1 - \\cos\\alpha) \\ge 2 I_t$):\n",
    );
    if let Some(rear) = level3.get(1) {
        math_block(
            &mut out,
            &format!(
                "\\frac{{4 l \\sin\\frac{{\\alpha}}{{2}}}}{{\\dot{{\\theta}}_1^-}} \\lambda_{{I2}} = {}",
                ratfunc(&dls_margin(rear, Floor::Level)?)
            ),
        );
    }
    out.push_str("\nSlope (Eq. 46, $m_t l^2 (1 - \\cos\\alpha) \\ge 2 I_1$):\n");
    if let Some(rear) = slope2.get(1) {
        math_block(
            &mut out,
            &format!(
                "\\frac{{4 l \\sin\\frac{{\\alpha}}{{2}}}}{{\\dot{{\\theta}}_1^- \\cos\\phi}} \\lambda_{{I2}} = {}",
                ratfunc(&dls_margin(rear, Floor::Slope)?)
            ),
        );
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mechanics::{cos, frac, int, sin, sym};

    fn s(x: Sym) -> RatFunc {
        sym(x)
    }

    #[test]
    fn atoms_in_the_papers_notation() {
        assert_eq!(
            ratfunc(&sin(&[(Sym::Th1, 1)]).expect("sin")),
            "\\sin\\theta_1"
        );
        assert_eq!(
            ratfunc(&RatFunc::cos_of(BaseAngle::HalfAlpha)),
            "\\cos\\frac{\\alpha}{2}"
        );
        assert_eq!(ratfunc(&RatFunc::sin_of(BaseAngle::Phi)), "\\sin\\phi");
        let s1 = sin(&[(Sym::Th1, 1)]).expect("sin");
        assert_eq!(ratfunc(&(&s1 * &s1)), "\\sin^2\\theta_1");
        assert_eq!(
            ratfunc(&(&s(Sym::Th1d) * &s(Sym::Th1d))),
            "\\dot{\\theta}_1^2"
        );
    }

    #[test]
    fn constants_and_signs() {
        assert_eq!(ratfunc(&RatFunc::zero()), "0");
        assert_eq!(ratfunc(&int(-3)), "-3");
        assert_eq!(ratfunc(&frac(1, 2)), "\\frac{1}{2}");
        assert_eq!(ratfunc(&(&frac(-3, 4) * &s(Sym::L))), "-\\frac{3}{4} l");
    }

    #[test]
    fn total_mass_is_abbreviated_by_division_and_by_substitution() {
        let mt = mechanics::total_mass();
        let l = s(Sym::L);
        // divisible: m_t^2 I_1 I_2 (det M)
        let det = &(&(&mt * &mt) * &s(Sym::I1)) * &s(Sym::I2);
        assert_eq!(ratfunc(&det), "m_t^2 I_1 I_2");
        // not divisible, but depends on the masses only through their sum
        let p = &s(Sym::I1) + &(&(&mt * &l) * &l);
        assert_eq!(ratfunc(&p), "I_1 + m_t l^2");
        // neither: m_1 alone stays
        let q = &s(Sym::M1) + &(&s(Sym::M2) * &l);
        assert_eq!(ratfunc(&q), "m_1 + m_2 l");
        // I_t
        let it = mechanics::total_inertia();
        assert_eq!(ratfunc(&(&int(2) * &it)), "2 I_t");
    }

    #[test]
    fn fraction_with_content_split_above_and_below() {
        let it = mechanics::total_inertia();
        let den = &(&int(4) * &s(Sym::L)) * &mechanics::sin_half_alpha();
        let r = (&int(2) * &it).div(&den).expect("nonzero");
        assert_eq!(ratfunc(&r), "\\frac{I_t}{2 l \\sin\\frac{\\alpha}{2}}");
        let neg = r.neg();
        assert_eq!(ratfunc(&neg), "-\\frac{I_t}{2 l \\sin\\frac{\\alpha}{2}}");
    }

    #[test]
    fn grouping_recovers_eq_23() {
        let d = Derivation::new().expect("derivation");
        let text = ratfunc(&d.level.lambda);
        assert_eq!(
            text,
            "\\frac{m_t \\left(I_1 \\left(g - l \\dot{\\theta}_1^2 \\cos\\theta_1\\right) - l u \\sin\\theta_1\\right)}\
             {I_1 + m_t l^2 \\left(\\sin\\theta_1 - \\mu \\cos\\theta_1\\right) \\sin\\theta_1}"
        );
    }

    #[test]
    fn cosine_stays_after_the_group() {
        // l cos(th1) (a + b): the group comes before the cosine
        let c = cos(&[(Sym::Th1, 1)]).expect("cos");
        let p = &(&s(Sym::L) * &c) * &(&s(Sym::G) + &s(Sym::U));
        assert_eq!(ratfunc(&p), "l \\left(g + u\\right) \\cos\\theta_1");
    }

    #[test]
    fn lowest_degree_term_leads_positive() {
        // -m_t (l thdot^2 cos - g) is printed m_t (g - l thdot^2 cos), as Eq. 20
        let d = Derivation::new().expect("derivation");
        assert_eq!(
            ratfunc(d.dynamics.bias.get(1, 0)),
            "m_t \\left(g - l \\dot{\\theta}_1^2 \\cos\\theta_1\\right)"
        );
    }

    #[test]
    fn hidden_cosine_factors_are_pulled_out() {
        // I_1 - I_1 sin^2(phi) is I_1 cos^2(phi); over cos(phi) it is I_1 cos(phi)
        let sp = RatFunc::sin_of(BaseAngle::Phi);
        let cp = RatFunc::cos_of(BaseAngle::Phi);
        let p = &s(Sym::I1) - &(&(&s(Sym::I1) * &sp) * &sp);
        assert_eq!(ratfunc(&p), "I_1 \\cos^2\\phi");
        let r = p.div(&cp).expect("nonzero");
        assert_eq!(ratfunc(&r), "I_1 \\cos\\phi");
    }

    #[test]
    fn shorter_in_a_shifted_angle() {
        // sin(th1 - phi) expands to two terms in th1 and phi; the printer shifts it back
        let r = sin(&[(Sym::Th1, 1), (Sym::Phi, -1)]).expect("sin");
        assert_eq!(ratfunc(&r), "\\sin\\left(\\theta_1 - \\phi\\right)");
        let c = cos(&[(Sym::Th1, 1), (Sym::Alpha, -1)]).expect("cos");
        let c2 = &c * &c;
        assert_eq!(ratfunc(&c2), "\\cos^2\\left(\\theta_1 - \\alpha\\right)");
    }

    #[test]
    fn large_outputs_are_refused_by_the_bounded_printer() {
        let d = Derivation::new().expect("derivation");
        let k = d.kernel("impact_slope_jacobian").expect("kernel");
        let (_, big) = &k.outputs[0];
        assert!(ratfunc_at_most(big, MAX_PRINTED_TERMS).is_none());
        assert!(ratfunc_at_most(&d.level.lambda, MAX_PRINTED_TERMS).is_some());
    }

    #[test]
    fn matrices_use_bmatrix() {
        let m = Matrix::from_rows(vec![vec![int(1), s(Sym::L)], vec![int(0), frac(1, 2)]])
            .expect("rows");
        assert_eq!(
            matrix(&m),
            "\\begin{bmatrix} 1 & l \\\\ 0 & \\frac{1}{2} \\end{bmatrix}"
        );
    }

    #[test]
    fn output_is_deterministic() {
        let d = Derivation::new().expect("derivation");
        let k = d.kernel("impact2_level").expect("kernel");
        let a: Vec<String> = k.outputs.iter().map(|(_, r)| ratfunc(r)).collect();
        let b: Vec<String> = k.outputs.iter().map(|(_, r)| ratfunc(r)).collect();
        assert_eq!(a, b);
    }
}
