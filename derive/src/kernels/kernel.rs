//! A named kernel as data: its arguments, its output expressions and their [`Shape`], and an
//! optional [`Staged`] form that evaluates the same outputs more cheaply.

use std::collections::BTreeSet;

use crate::error::{Error, Result};
use crate::ratfunc::RatFunc;
use crate::symbol::{Atom, Point, Sym, SymKind, Symbols};

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
    /// Output names and their canonical expressions: closed forms in the arguments and the
    /// parameters, or, when `closed` is false, the outputs of `solve` (expressions in its
    /// locals).
    pub outputs: Vec<(String, RatFunc)>,
    /// Output shape.
    pub shape: Shape,
    /// An equivalent, cheaper way to evaluate the outputs, if the derivation knows one (see
    /// [`Staged`]); `outputs` stays the definition.
    pub staged: Option<Staged>,
    /// A structured solve of the same outputs: `M`, `h` and the constraint Jacobians bound to
    /// locals ([`SymKind::Local`]), an unrolled factorisation and its substitutions
    /// (`crate::model::Program`). The code generator evaluates whichever of the closed form and
    /// the solve it estimates faster (critical path and operation count).
    pub solve: Option<Staged>,
    /// Whether `outputs` are closed forms; false for a kernel that only has its structured
    /// solve (a model whose closed forms are too large to derive).
    pub closed: bool,
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
    /// A kernel of closed forms taking `args`, with no staged form and no structured solve.
    #[must_use]
    pub fn closed_form(
        name: &'static str,
        doc: &'static str,
        equation: &'static str,
        args: Vec<Sym>,
        outputs: Vec<(String, RatFunc)>,
        shape: Shape,
    ) -> Kernel {
        Kernel {
            name,
            doc,
            equation,
            args,
            outputs,
            shape,
            staged: None,
            solve: None,
            closed: true,
        }
    }

    /// The parameters the kernel's forms contain (`symbols`: the table of the derivation), in
    /// symbol order.
    pub fn params(&self, symbols: &Symbols) -> Vec<Sym> {
        let mut set = BTreeSet::new();
        for r in self.expressions() {
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

    /// Checks that the kernel is well formed: its staged form composes to its outputs
    /// ([`Kernel::check_staged`]) and it depends on no symbol it does not take
    /// ([`Kernel::free_symbols`]).
    ///
    /// # Errors
    /// [`Error::CheckFailed`] naming the kernel and the symbols, or the staged form's error.
    pub fn check(&self, symbols: &Symbols) -> Result<()> {
        self.check_staged()?;
        let free = self.free_symbols(symbols);
        if free.is_empty() {
            return Ok(());
        }
        let names: Vec<&str> = free.iter().map(|s| symbols.name(*s)).collect();
        Err(Error::CheckFailed {
            what: format!(
                "kernel {} depends on {names:?} which are not arguments",
                self.name
            ),
        })
    }

    /// Every symbol the kernel's forms depend on that is not an argument, a parameter or a
    /// local bound by a staged form or the structured solve (must be empty for a well-formed
    /// kernel; `symbols`: the table of the derivation).
    pub fn free_symbols(&self, symbols: &Symbols) -> Vec<Sym> {
        let bound: BTreeSet<Sym> = [&self.staged, &self.solve]
            .into_iter()
            .flatten()
            .flat_map(|st| st.locals.iter().map(|(s, _)| *s))
            .collect();
        let mut set = BTreeSet::new();
        for r in self.expressions() {
            for p in [r.num(), r.den()] {
                for slot in p.slots() {
                    let Some(s) = symbols.symbol_of_slot(slot) else {
                        continue;
                    };
                    if symbols.kind(s) != SymKind::Parameter
                        && !bound.contains(&s)
                        && !self.args.contains(&s)
                    {
                        set.insert(s);
                    }
                }
            }
        }
        set.into_iter().collect()
    }

    /// Every expression the kernel evaluates in some form: its outputs, and the locals and
    /// outputs of its staged form and of its structured solve.
    pub fn expressions(&self) -> impl Iterator<Item = &RatFunc> {
        let forms = [&self.staged, &self.solve];
        self.outputs.iter().map(|(_, r)| r).chain(
            forms
                .into_iter()
                .flatten()
                .flat_map(|st| st.locals.iter().map(|(_, r)| r).chain(&st.outputs)),
        )
    }

    /// The outputs' closed forms evaluated at `point` (the arguments and parameters), or
    /// `None` for a kernel without closed forms.
    pub fn eval_closed(&self, point: &Point<f64>) -> Option<Vec<f64>> {
        self.closed
            .then(|| self.outputs.iter().map(|(_, r)| r.eval(point)).collect())
    }

    /// The outputs evaluated at `point` by the structured solve (its locals computed in order),
    /// or `None` for a kernel without one.
    pub fn eval_solve(&self, point: &Point<f64>) -> Option<Vec<f64>> {
        Some(self.solve.as_ref()?.eval(point))
    }

    /// The outputs evaluated at `point` by the staged form of the closed forms (what the code
    /// generator evaluates for the closed form), or `None` for a kernel without one.
    pub fn eval_staged(&self, point: &Point<f64>) -> Option<Vec<f64>> {
        Some(self.staged.as_ref()?.eval(point))
    }
}

impl Staged {
    /// The outputs evaluated at `point`, the locals computed in order.
    pub fn eval(&self, point: &Point<f64>) -> Vec<f64> {
        let mut p = point.clone();
        for (s, value) in &self.locals {
            let v = value.eval(&p);
            p.set(s.slot(), v);
        }
        self.outputs.iter().map(|r| r.eval(&p)).collect()
    }
}

/// The kernel called `name` among `kernels`.
///
/// # Errors
/// [`Error::UnknownKernel`].
pub fn find_kernel<'k>(kernels: &'k [Kernel], name: &str) -> Result<&'k Kernel> {
    kernels
        .iter()
        .find(|k| k.name == name)
        .ok_or_else(|| Error::UnknownKernel {
            name: name.to_owned(),
        })
}
