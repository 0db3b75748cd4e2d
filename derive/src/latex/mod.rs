//! Readable LaTeX for people: derived quantities in the paper's notation, for Markdown that
//! GitHub renders (`$$ ... $$` blocks), and the generator of `docs/equations.md`.
//!
//! A polynomial is printed as `sign * content * monomial * (rest)`: the rational content and
//! the greatest common monomial are pulled out, `m_1 + m_2` and `I_1 + I_2` are abbreviated as
//! `m_t` and `I_t` where the polynomial is divisible by them (trial division,
//! [`Poly::div_exact`](crate::poly::Poly::div_exact)) or depends on the masses (inertias) only
//! through their sum, and the rest is grouped greedily: the atom that occurs in most terms is
//! factored out of them, and the groups are printed recursively. A
//! [`RatFunc`](crate::ratfunc::RatFunc) is a `\frac` of two such products (or a polynomial).
//! Everything is a function of the canonical form only, so the output is deterministic.
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
//!
//! The printer is layered, each file using only those listed before it:
//!
//! - `notation`: atoms, base angles, rationals and symbol lists in LaTeX;
//! - `context`: the trig-aware printing context (pseudo atoms for `m_t`, `I_t` and a shifted
//!   angle, print order) and the choice of the angle an expression is written in;
//! - `factor`: a polynomial as `sign * content * monomial * (rest)`;
//! - `group`: products and the grouping of sums into readable terms;
//! - `formula`: the public printers of polynomials, rational functions and matrices;
//! - `label`: the LaTeX names of kernel outputs;
//! - `document`: the Markdown document of every kernel, `docs/equations.md`.

mod context;
mod document;
mod factor;
mod formula;
mod group;
mod label;
mod notation;
#[cfg(test)]
mod tests;

pub use document::{MAX_PRINTED_TERMS, equations_markdown};
pub use formula::{matrix, poly, ratfunc, ratfunc_at_most};
pub use label::output_label;
pub use notation::{angle, atom_power, rational, symbols};

/// The symbol table of the walker these documents print: the paper's.
pub(crate) fn table() -> &'static crate::symbol::Symbols {
    static TABLE: std::sync::LazyLock<crate::symbol::Symbols> =
        std::sync::LazyLock::new(crate::symbol::Symbols::paper);
    &TABLE
}
