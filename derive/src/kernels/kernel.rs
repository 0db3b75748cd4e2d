//! A named kernel as data: its arguments, its output expressions and their [`Shape`], and an
//! optional [`Staged`] form that evaluates the same outputs more cheaply.

use std::collections::BTreeSet;

use crate::error::{Error, Result};
use crate::ratfunc::RatFunc;
use crate::symbol::{Atom, Sym, SymKind, Symbols};

/// The shape of a kernel's output.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// One value.
    Scalar,
    /// A vector of the given length.
    Vector(usize),
    /// A matrix, rows x columns, row-major.
    Matrix(usize, usize),
    /// Several named parts (e.g. `lambda_I` then `qdot+`), flattened in order.
    Parts,
}

/// A named kernel: the state and input symbols it takes, and its outputs.
#[derive(Clone, Debug)]
pub struct Kernel {
    /// Name, as in `docs/kernels.md`.
    pub name: &'static str,
    /// What the kernel computes.
    pub doc: &'static str,
    /// The paper's equation numbers.
    pub equation: &'static str,
    /// State and input arguments, in order.
    pub args: Vec<Sym>,
    /// Output names and their canonical expressions.
    pub outputs: Vec<(String, RatFunc)>,
    /// Output shape.
    pub shape: Shape,
    /// An equivalent, cheaper way to evaluate the outputs, if the derivation knows one (see
    /// [`Staged`]); `outputs` stays the definition.
    pub staged: Option<Staged>,
}

/// A kernel's outputs evaluated in stages: first the `locals` in order, each a symbol bound to
/// an expression in the arguments and the locals before it, then `outputs`, expressions in the
/// arguments and the locals.
///
/// Substituting the locals back (last to first) gives exactly the kernel's `outputs`
/// ([`Kernel::check_staged`] proves it with exact arithmetic). The staged form exists for
/// evaluation: a quantity such as `u = (v + B) / A` (Eq. 31) is computed once and then used,
/// where the flattened quotient of quotients would multiply denominators together.
#[derive(Clone, Debug)]
pub struct Staged {
    /// `(symbol, expression)` pairs, evaluated in order.
    pub locals: Vec<(Sym, RatFunc)>,
    /// One expression per output of the kernel, in the kernel's output order.
    pub outputs: Vec<RatFunc>,
}

impl Kernel {
    /// The parameters the outputs contain (`symbols`: the table of the derivation), in symbol
    /// order.
    pub fn params(&self, symbols: &Symbols) -> Vec<Sym> {
        let mut set = BTreeSet::new();
        for (_, r) in &self.outputs {
            for p in [r.num(), r.den()] {
                for slot in p.slots() {
                    if let Some(s) = symbols.symbol_of_slot(slot)
                        && symbols.kind(s) == SymKind::Parameter
                    {
                        set.insert(s);
                    }
                }
            }
        }
        set.into_iter().collect()
    }

    /// The output called `name`, if the kernel has one.
    pub fn output(&self, name: &str) -> Option<&RatFunc> {
        self.outputs.iter().find(|(n, _)| n == name).map(|(_, r)| r)
    }

    /// Checks that the staged form, if any, composes to the outputs exactly.
    ///
    /// # Errors
    /// [`Error::CheckFailed`] naming the kernel and the first output that differs, or an
    /// arithmetic error of the substitution.
    pub fn check_staged(&self) -> Result<()> {
        let Some(staged) = &self.staged else {
            return Ok(());
        };
        if staged.outputs.len() != self.outputs.len() {
            return Err(Error::CheckFailed {
                what: format!("kernel {}: staged output count", self.name),
            });
        }
        for ((name, want), got) in self.outputs.iter().zip(&staged.outputs) {
            let mut got = got.clone();
            for (s, value) in staged.locals.iter().rev() {
                got = got.substitute(Atom::Sym(*s), value)?;
            }
            if &got != want {
                return Err(Error::CheckFailed {
                    what: format!(
                        "kernel {}: staged output {name} differs from its definition",
                        self.name
                    ),
                });
            }
        }
        Ok(())
    }

    /// Every symbol the outputs depend on, that is not an argument or a parameter (must be
    /// empty for a well-formed kernel; `symbols`: the table of the derivation).
    pub fn free_symbols(&self, symbols: &Symbols) -> Vec<Sym> {
        let mut set = BTreeSet::new();
        for (_, r) in &self.outputs {
            for p in [r.num(), r.den()] {
                for slot in p.slots() {
                    let Some(s) = symbols.symbol_of_slot(slot) else {
                        continue;
                    };
                    if symbols.kind(s) != SymKind::Parameter && !self.args.contains(&s) {
                        set.insert(s);
                    }
                }
            }
        }
        set.into_iter().collect()
    }
}
