//! The LaTeX of the smallest pieces: base angles, atoms to a power, rational numbers and
//! lists of symbols, in the paper's notation.

use num_traits::Signed;

use crate::poly::Q;
use crate::symbol::{Atom, BaseAngle, Sym};

pub(super) fn exponent(e: u8) -> String {
    if e < 10 {
        format!("^{e}")
    } else {
        format!("^{{{e}}}")
    }
}

/// The LaTeX of a base angle: `\theta_1`, `\theta_2`, `\frac{\alpha}{2}`, `\phi`.
pub fn angle(a: BaseAngle) -> String {
    let t = super::table();
    match t.angle(a) {
        Some((s, 1)) => t.latex(s).to_owned(),
        Some((s, k)) => format!("\\frac{{{}}}{{{k}}}", t.latex(s)),
        None => format!("\\vartheta_{{{}}}", a.index()),
    }
}

/// The LaTeX of an atom to a power: `m_1^2`, `\sin^2\theta_1`, `\cos\frac{\alpha}{2}`.
pub fn atom_power(atom: Atom, e: u8) -> String {
    let p = if e == 1 { String::new() } else { exponent(e) };
    match atom {
        Atom::Sym(s) => format!("{}{p}", super::table().latex(s)),
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

/// A list of symbols in LaTeX, comma separated.
pub fn symbols(syms: &[Sym]) -> String {
    syms.iter()
        .map(|s| super::table().latex(*s))
        .collect::<Vec<_>>()
        .join(", ")
}
