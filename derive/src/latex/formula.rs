//! The public printers of whole formulas: a polynomial, a rational function (a `\frac` of two
//! factored products, bounded or not) and a matrix, each in the angle that is shortest.

use super::context::{Ctx, best_angle};
use super::factor::factor;
use super::group::product;
use crate::matrix::Matrix;
use crate::poly::{Poly, Q};
use crate::ratfunc::RatFunc;

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
    let common = n.mono.gcd(&d.mono);
    let (nm, dm) = (
        n.mono.div(&common).unwrap_or(n.mono),
        d.mono.div(&common).unwrap_or(d.mono),
    );
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
