//! The desired output `y_d(t)` of the control (Section 3.2) and the symbolic check of its
//! boundary conditions.

use super::notation::{frac, int, sym};
use crate::error::{Error, Result};
use crate::ratfunc::RatFunc;
use crate::symbol::{Atom, Sym};

/// The desired output `y_d(t)` of Section 3.2 on `0 <= t < T_set`, and its first two time
/// derivatives.
pub fn desired_output() -> Result<[RatFunc; 3]> {
    let s = sym(Sym::T).div(&sym(Sym::TSet))?;
    let alpha = sym(Sym::Alpha);
    let s3 = s.powi(3)?;
    let s4 = s.powi(4)?;
    let s5 = s.powi(5)?;
    let poly = &(&(&int(6) * &s5) - &(&int(15) * &s4)) + &(&int(10) * &s3);
    let yd = &(&alpha * &poly) - &(&alpha * &frac(1, 2));
    let ydd = yd.diff(Sym::T);
    let yddd = ydd.diff(Sym::T);
    Ok([yd, ydd, yddd])
}

/// Checks the boundary conditions of `y_d` symbolically: `y_d(0) = -alpha/2`,
/// `y_d(T_set) = alpha/2`, and zero first and second derivatives at both ends.
pub fn check_desired_output() -> Result<()> {
    let [yd, ydd, yddd] = desired_output()?;
    let half_alpha = &sym(Sym::Alpha) * &frac(1, 2);
    let at = |f: &RatFunc, t: &RatFunc| f.substitute(Atom::Sym(Sym::T), t);
    let t_set = sym(Sym::TSet);
    let zero = RatFunc::zero();
    let checks = [
        (at(&yd, &zero)?, -&half_alpha, "y_d(0) = -alpha/2"),
        (at(&yd, &t_set)?, half_alpha.clone(), "y_d(T_set) = alpha/2"),
        (at(&ydd, &zero)?, RatFunc::zero(), "y_d'(0) = 0"),
        (at(&ydd, &t_set)?, RatFunc::zero(), "y_d'(T_set) = 0"),
        (at(&yddd, &zero)?, RatFunc::zero(), "y_d''(0) = 0"),
        (at(&yddd, &t_set)?, RatFunc::zero(), "y_d''(T_set) = 0"),
    ];
    for (got, want, what) in checks {
        if got != want {
            return Err(Error::CheckFailed {
                what: what.to_owned(),
            });
        }
    }
    Ok(())
}
