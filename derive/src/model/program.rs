//! A structured solve as a straight-line program: values bound to locals in order, an unrolled
//! `L D L^T` factorisation of a symmetric positive definite matrix, its forward and back
//! substitutions, and a small dense inverse.
//!
//! Where the closed forms of a model's kernels are too large (every product through a
//! closed-form `M^-1` multiplies its determinant into the numerators), a kernel is derived
//! instead as a program: the entries of `M`, `h` and the constraint Jacobians, each a closed form
//! of the state, are bound to locals ([`SymKind::Local`]), and everything after them is
//! arithmetic on locals, a handful of terms per step. The code generator lowers the program
//! through the same graph as a closed form (the locals become nodes), so common subexpressions
//! and the hoisting of parameter-only values into `prepare` apply unchanged.
//!
//! Written here rather than taken from nalgebra: the factorisation runs on symbols, at
//! generation time, with the matrix's structural zeros known exactly (`0 * x` never appears, so
//! a block-diagonal or sparse `M` costs only its non-zeros), and it emits code rather than
//! numbers. `L D L^T` needs no pivoting for a symmetric positive definite matrix (`M`, its
//! blocks, and the Delassus matrix `J M^-1 J^T` of independent constraints), and has no square
//! roots.

use crate::error::{Error, Result};
use crate::kernels::Staged;
use crate::matrix::Matrix;
use crate::ratfunc::RatFunc;
use crate::symbol::{Sym, SymKind, Symbols};

/// The largest order of [`Program::small_solve`] (the outputs of the control): four, the
/// five-link biped's hip and knee inputs.
pub const MAX_SMALL_SOLVE: usize = 4;

/// A program under construction: the locals bound so far, in evaluation order.
#[derive(Debug)]
pub struct Program<'a> {
    table: &'a mut Symbols,
    prefix: &'a str,
    locals: Vec<(Sym, RatFunc)>,
}

/// An `L D L^T` factorisation of an `n x n` matrix: `L` unit lower triangular, `D` diagonal, each
/// entry a local (or an exact zero).
#[derive(Clone, Debug)]
pub struct Ldlt {
    /// `L[i][j]` for `j < i`.
    lower: Vec<Vec<RatFunc>>,
    /// `D[i]`.
    diagonal: Vec<RatFunc>,
}

impl Ldlt {
    /// The order `n`.
    pub fn order(&self) -> usize {
        self.diagonal.len()
    }
}

impl<'a> Program<'a> {
    /// An empty program whose locals are added to `table`, named `prefix` and a counter (the
    /// names never reach the generated code; they keep the table's names unique).
    pub fn new(table: &'a mut Symbols, prefix: &'a str) -> Program<'a> {
        Program {
            table,
            prefix,
            locals: Vec::new(),
        }
    }

    /// Binds `value` to a new local and returns the local as an expression; a constant
    /// (including zero) is returned as it is, so that exact zeros and ones keep simplifying.
    ///
    /// # Errors
    /// A full symbol table.
    pub fn bind(&mut self, value: RatFunc) -> Result<RatFunc> {
        if value.as_constant().is_some() {
            return Ok(value);
        }
        let name = format!("{}.{}", self.prefix, self.locals.len());
        let s = self.table.push(&name, &name, SymKind::Local)?;
        self.locals.push((s, value));
        Ok(RatFunc::sym(s))
    }

    /// Binds every entry of a column.
    ///
    /// # Errors
    /// As [`Program::bind`].
    pub fn bind_all(&mut self, values: &[RatFunc]) -> Result<Vec<RatFunc>> {
        values.iter().map(|v| self.bind(v.clone())).collect()
    }

    /// Binds every entry of a matrix, row-major.
    ///
    /// # Errors
    /// As [`Program::bind`].
    pub fn bind_matrix(&mut self, m: &Matrix) -> Result<Matrix> {
        let mut out = Matrix::zeros(m.rows(), m.cols());
        for i in 0..m.rows() {
            for j in 0..m.cols() {
                out.set(i, j, self.bind(m.get(i, j).clone())?);
            }
        }
        Ok(out)
    }

    /// Factors the symmetric matrix `a` (its lower triangle is read) as `L D L^T`:
    /// `D_j = a_jj - sum_k L_jk^2 D_k`, `L_ij = (a_ij - sum_k L_ik L_jk D_k) / D_j`, with
    /// `E_ik = L_ik D_k` bound once.
    ///
    /// # Errors
    /// A pivot that is identically zero (`a` singular, or not positive definite in its
    /// leading blocks), named by `name`.
    pub fn ldlt(&mut self, a: &Matrix, name: &str) -> Result<Ldlt> {
        let n = a.rows();
        let mut lower: Vec<Vec<RatFunc>> = vec![Vec::new(); n];
        let mut scaled: Vec<Vec<RatFunc>> = vec![Vec::new(); n];
        let mut diagonal = Vec::with_capacity(n);
        for i in 0..n {
            for j in 0..i {
                let mut v = a.get(i, j).clone();
                for k in 0..j {
                    v = &v - &(&scaled[i][k] * &lower[j][k]);
                }
                // E_ij = L_ij D_j is the reduced entry itself.
                let e = self.bind(v)?;
                let l = self.bind(e.div(&diagonal[j])?)?;
                scaled[i].push(e);
                lower[i].push(l);
            }
            let mut d = a.get(i, i).clone();
            for k in 0..i {
                d = &d - &(&scaled[i][k] * &lower[i][k]);
            }
            if d.is_zero() {
                return Err(Error::SingularMatrix {
                    name: name.to_owned(),
                });
            }
            diagonal.push(self.bind(d)?);
        }
        Ok(Ldlt { lower, diagonal })
    }

    /// Solves `L D L^T x = b` by forward substitution, the diagonal, and back substitution.
    ///
    /// # Errors
    /// A right-hand side of the wrong length, or a full symbol table.
    pub fn solve(&mut self, f: &Ldlt, b: &[RatFunc]) -> Result<Vec<RatFunc>> {
        let n = f.order();
        if b.len() != n {
            return Err(Error::CheckFailed {
                what: format!("a solve of order {n} with {} right-hand sides", b.len()),
            });
        }
        let mut y: Vec<RatFunc> = Vec::with_capacity(n);
        for (bi, row) in b.iter().zip(&f.lower) {
            let mut v = bi.clone();
            for (l, yk) in row.iter().zip(&y) {
                v = &v - &(l * yk);
            }
            y.push(self.bind(v)?);
        }
        let mut x = vec![RatFunc::zero(); n];
        for i in (0..n).rev() {
            let mut v = y[i].div(&f.diagonal[i])?;
            for (row, xk) in f.lower.iter().zip(&x).skip(i + 1) {
                v = &v - &(&row[i] * xk);
            }
            x[i] = self.bind(v)?;
        }
        Ok(x)
    }

    /// `a^-1 b` for a small square matrix of locals that need not be symmetric (the control's
    /// `A`): the adjugate over the determinant. Only for order at most `MAX_SMALL_SOLVE`, where
    /// a cofactor has at most six products; the determinant vanishes exactly where `a` is
    /// singular, so no pivoting question arises (an elimination without pivoting could divide
    /// by a zero pivot of a regular matrix).
    ///
    /// # Errors
    /// Order above `MAX_SMALL_SOLVE`, or `a` singular identically.
    pub fn small_solve(&mut self, a: &Matrix, b: &Matrix, name: &str) -> Result<Matrix> {
        if a.rows() > MAX_SMALL_SOLVE {
            return Err(Error::CheckFailed {
                what: format!(
                    "{name} is {0}x{0}: the structured solve inverts at most \
                     {MAX_SMALL_SOLVE}x{MAX_SMALL_SOLVE} (the number of outputs and inputs)",
                    a.rows()
                ),
            });
        }
        let inv = self.bind_matrix(&a.inverse(name)?)?;
        let x = inv.mul(b)?;
        self.bind_matrix(&x)
    }

    /// The finished program with these outputs (expressions in the arguments and the locals).
    pub fn finish(self, outputs: Vec<RatFunc>) -> Staged {
        Staged {
            locals: self.locals,
            outputs,
        }
    }
}
