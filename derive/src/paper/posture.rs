//! The substitutions that bring the derived impact maps to the paper's printed closed forms:
//! the impact posture and the pre-impact state the paper assumes.

use super::notation::{frac, sym, tan_phi};
use crate::error::Result;
use crate::ratfunc::RatFunc;
use crate::symbol::{Atom, BaseAngle, Sym};
use crate::trig::sin_cos_combination;
use walker_scene::Floor;

/// `f` at the impact posture: the fore foot on the floor, `th1 = alpha/2` on level ground and
/// `th1 = alpha/2 + phi` on the slope (Sections 2.2 and 5.1).
///
/// # Errors
/// An arithmetic error of the substitution.
pub fn at_impact_posture(f: &RatFunc, floor: Floor) -> Result<RatFunc> {
    // th1 = alpha/2 (+ phi): sin and cos of that combination of base angles.
    let combo: Vec<(BaseAngle, i64)> = match floor {
        Floor::Level => vec![(BaseAngle::HalfAlpha, 1)],
        Floor::Slope => vec![(BaseAngle::HalfAlpha, 1), (BaseAngle::Phi, 1)],
    };
    let (s, c) = sin_cos_combination(&combo);
    let f = f.substitute(Atom::Sin(BaseAngle::Th1), &s.into())?;
    let f = f.substitute(Atom::Cos(BaseAngle::Th1), &c.into())?;
    let th1 = match floor {
        Floor::Level => &sym(Sym::Alpha) * &frac(1, 2),
        Floor::Slope => &(&sym(Sym::Alpha) * &frac(1, 2)) + &sym(Sym::Phi),
    };
    f.substitute(Atom::Sym(Sym::Th1), &th1)
}

/// The pre-impact state the paper's closed forms assume: the torso locked (`th2d = th1d`) and
/// the stance foot not moving vertically (`zd = 0`, `zd = -xd tan phi` on the slope).
///
/// # Errors
/// An arithmetic error of the substitution.
pub fn paper_pre_impact(f: &RatFunc, floor: Floor) -> Result<RatFunc> {
    let zd = match floor {
        Floor::Level => RatFunc::zero(),
        Floor::Slope => -(&sym(Sym::Xd) * &tan_phi()?),
    };
    let f = f.substitute(Atom::Sym(Sym::Zd), &zd)?;
    f.substitute(Atom::Sym(Sym::Th2d), &sym(Sym::Th1d))
}
