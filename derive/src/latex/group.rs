//! Products and sums as text: a factored product with its group before the trigonometric
//! factors, and a sum split greedily into groups around the atom that occurs in most terms.

use num_traits::One;

use super::context::Ctx;
use super::factor::factor;
use super::notation::rational;
use crate::poly::{Mono, Poly, Q};

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
pub(super) fn product(coef: &Q, mono: &Mono, rest: Option<&Poly>, ctx: &Ctx) -> String {
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
        for slot in p.slots() {
            let count = p
                .terms()
                .iter()
                .filter(|(m, _)| m.exponent(slot) > 0)
                .count();
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
    let (with, without): (Vec<_>, Vec<_>) = p
        .terms()
        .iter()
        .cloned()
        .partition(|(m, _)| m.exponent(slot) > 0);
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
