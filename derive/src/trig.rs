//! Sines and cosines of integer combinations of base angles, by the addition formulas; and of
//! integer combinations of angle symbols, as rational functions.

use crate::error::{Error, Result};
use crate::poly::Poly;
use crate::ratfunc::RatFunc;
use crate::symbol::{Atom, BaseAngle, Sym};

/// `(sin(n b), cos(n b))` for an integer `n` and base angle `b`.
pub fn sin_cos_multiple(angle: BaseAngle, n: i64) -> (Poly, Poly) {
    let s = Poly::atom(Atom::Sin(angle));
    let c = Poly::atom(Atom::Cos(angle));
    let (mut sn, mut cn) = (Poly::zero(), Poly::one());
    for _ in 0..n.unsigned_abs() {
        // sin((k+1) b) = sin(k b) cos b + cos(k b) sin b; cos((k+1) b) = cos(k b) cos b - sin(k b) sin b
        let s_next = sn.mul(&c).add(&cn.mul(&s));
        let c_next = cn.mul(&c).sub(&sn.mul(&s));
        sn = s_next;
        cn = c_next;
    }
    if n < 0 { (sn.neg(), cn) } else { (sn, cn) }
}

/// `(sin(sum_k n_k b_k), cos(sum_k n_k b_k))` for integer multiples of base angles.
pub fn sin_cos_combination(terms: &[(BaseAngle, i64)]) -> (Poly, Poly) {
    let (mut s, mut c) = (Poly::zero(), Poly::one());
    for &(angle, n) in terms {
        let (sb, cb) = sin_cos_multiple(angle, n);
        let s_next = s.mul(&cb).add(&c.mul(&sb));
        let c_next = c.mul(&cb).sub(&s.mul(&sb));
        s = s_next;
        c = c_next;
    }
    (s, c)
}

/// The combination `sum n_k s_k` of angle symbols as one of base angles (`alpha = 2 (alpha/2)`).
fn combination(angle: &[(Sym, i64)]) -> Result<Vec<(BaseAngle, i64)>> {
    angle
        .iter()
        .map(|&(s, n)| {
            let (base, k) = s.base_angle().ok_or_else(|| Error::UnsupportedAngle {
                what: format!("symbol {} is not an angle", s.index()),
            })?;
            Ok((base, n * k))
        })
        .collect()
}

/// `sin(sum n_k s_k)` for angle symbols `s_k` and integers `n_k`.
///
/// # Errors
/// A symbol that is not an angle.
pub fn sin(angle: &[(Sym, i64)]) -> Result<RatFunc> {
    Ok(sin_cos_combination(&combination(angle)?).0.into())
}

/// `cos(sum n_k s_k)` for angle symbols `s_k` and integers `n_k`.
///
/// # Errors
/// A symbol that is not an angle.
pub fn cos(angle: &[(Sym, i64)]) -> Result<RatFunc> {
    Ok(sin_cos_combination(&combination(angle)?).1.into())
}

#[cfg(test)]
mod tests {
    use super::*;

    // Base angles by index, named as the paper's.
    const TH1: BaseAngle = BaseAngle::new(0);
    const HALF_ALPHA: BaseAngle = BaseAngle::new(2);

    #[test]
    fn one_minus_cos_alpha_is_twice_sin_squared_half() {
        let (_, c) = sin_cos_multiple(HALF_ALPHA, 2);
        let s = Poly::atom(Atom::Sin(HALF_ALPHA));
        assert_eq!(
            Poly::one().sub(&c),
            s.mul(&s)
                .scale(&Poly::int(2).as_constant().unwrap_or_default())
        );
    }

    #[test]
    fn addition_formula_round_trip() {
        // sin(alpha - th1) cos(th1) + cos(alpha - th1) sin(th1) = sin(alpha)
        let (s1, c1) = sin_cos_combination(&[(HALF_ALPHA, 2), (TH1, -1)]);
        let (st, ct) = sin_cos_multiple(TH1, 1);
        let (sa, _) = sin_cos_multiple(HALF_ALPHA, 2);
        assert_eq!(s1.mul(&ct).add(&c1.mul(&st)), sa);
    }
}
