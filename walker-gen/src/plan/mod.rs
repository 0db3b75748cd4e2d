//! The evaluation plan: what the emitter writes, decided before any syntax is produced.
//!
//! Passes, in order:
//!
//! 1. **validate** the module (identifiers, declared inputs and parameters, output counts);
//! 2. **expand powers**: `powi(x, n)` becomes a square-and-multiply chain (`x*x`, `x2*x2*x`...,
//!    `1/(...)` for negative `n`), the same chain [`crate::ir::Graph::powi`] folds with; no `powi`
//!    call is emitted;
//! 3. **reciprocals** ([`Division::SharedReciprocal`](crate::Division::SharedReciprocal)): per kernel, `a / d` becomes `a * (1/d)`
//!    when `d` depends on parameters only (the reciprocal is then hoisted into `prepare`) or when
//!    two or more divisions of the kernel share the state-dependent `d`;
//! 4. **hoisting**: a node whose leaves are all parameters and constants (and that is not itself
//!    a constant) is computed in `prepare`; the *frontier* (hoisted nodes used directly by a
//!    kernel) becomes the fields of `Prepared`, inner hoisted nodes are `let`s of `prepare`;
//! 5. **schedule**: in each block (`prepare` or a kernel), a node gets a `let` iff it is used
//!    more than once in the block, or it is a function call (sqrt, sin, cos, tanh) used inside
//!    another expression, or its sine and cosine are both needed (one `sin_cos`), or inlining
//!    it would nest operations deeper than 16 levels (long sums are cut into `let`s of at most
//!    that depth); everything else is inlined. `let`s appear in node-id (topological) order and are named `t0, t1, ...`
//!    in that order, so the output depends on the module only.

mod block;
mod passes;
mod reach;
mod rewrite;
mod schedule;
#[cfg(test)]
mod tests;
mod validate;

pub(crate) use block::{Block, Step};
pub(crate) use passes::Plan;
