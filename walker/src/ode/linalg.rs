//! Dense LU factorisation with partial pivoting on fixed-size matrices.
//!
//! The stiff integrator solves `(I/(h*gamma) - J) k = b` several times per step
//! with the same matrix, so the factorisation is stored once ([`Lu`]) and
//! reused for every right-hand side. Everything lives on the stack: no heap
//! allocation, no dependency on a linear-algebra crate.
//!
//! Kept by hand rather than nalgebra's `SMatrix::lu` because it is at least as fast
//! and keeps RODAS4's results bitwise as they were (nalgebra multiplies by the
//! pivot's reciprocal and substitutes column by column, so its last bits differ):
//! `cargo bench -p walker --bench linalg` (`benches/linalg.rs`), N = 9, measured
//! once on 2026-11-24: factor + one solve 337 ns against nalgebra's 414 ns (1.23x
//! faster), factor + six solves (one RODAS4 step) 783 ns against 764 ns (at par,
//! 0.98x, within the noise of a shared machine).

/// An LU factorisation `P A = L U` of an `N x N` matrix, computed by Gaussian
/// elimination with partial (row) pivoting.
///
/// `L` is unit lower triangular and stored below the diagonal of `lu`, `U` is
/// stored on and above it; `perm[k]` is the original row that ended up in row
/// `k`.
#[derive(Clone, Debug)]
pub struct Lu<const N: usize> {
    lu: [[f64; N]; N],
    perm: [usize; N],
}

/// Why a factorisation failed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LuError {
    /// A pivot was exactly zero (the matrix is singular to working precision)
    /// or not finite (the matrix contained NaN or infinity).
    Singular {
        /// Elimination step (column) at which no usable pivot was found.
        column: usize,
    },
}

impl<const N: usize> Default for Lu<N> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const N: usize> Lu<N> {
    /// An identity factorisation, to be overwritten by [`Lu::factor`].
    pub fn new() -> Self {
        let mut lu = [[0.0; N]; N];
        for (i, row) in lu.iter_mut().enumerate() {
            row[i] = 1.0;
        }
        Self {
            lu,
            perm: core::array::from_fn(|i| i),
        }
    }

    /// Factorise `a` in place of the previous factorisation.
    ///
    /// On error the stored factorisation is unusable until the next
    /// successful call.
    pub fn factor(&mut self, a: &[[f64; N]; N]) -> Result<(), LuError> {
        self.lu = *a;
        self.eliminate()
    }

    /// Factorise `shift * I - jac` (the Rosenbrock iteration matrix) without
    /// forming it separately.
    pub fn factor_shifted(&mut self, shift: f64, jac: &[[f64; N]; N]) -> Result<(), LuError> {
        for (i, (row, jrow)) in self.lu.iter_mut().zip(jac.iter()).enumerate() {
            for (v, j) in row.iter_mut().zip(jrow.iter()) {
                *v = -j;
            }
            row[i] += shift;
        }
        self.eliminate()
    }

    /// Gaussian elimination with partial pivoting on `self.lu`.
    fn eliminate(&mut self) -> Result<(), LuError> {
        for (i, p) in self.perm.iter_mut().enumerate() {
            *p = i;
        }
        for k in 0..N {
            // Choose the pivot: the largest magnitude in column k, rows k..N.
            let mut piv = k;
            let mut best = self.lu[k][k].abs();
            for i in (k + 1)..N {
                let v = self.lu[i][k].abs();
                if v > best {
                    best = v;
                    piv = i;
                }
            }
            if best == 0.0 || !best.is_finite() {
                return Err(LuError::Singular { column: k });
            }
            if piv != k {
                self.lu.swap(piv, k);
                self.perm.swap(piv, k);
            }
            let pivot = self.lu[k][k];
            let (upper, lower) = self.lu.split_at_mut(k + 1);
            let row_k = &upper[k];
            for row in lower.iter_mut() {
                let m = row[k] / pivot;
                row[k] = m;
                if m != 0.0 {
                    for (v, &u) in row[k + 1..].iter_mut().zip(&row_k[k + 1..]) {
                        *v -= m * u;
                    }
                }
            }
        }
        Ok(())
    }

    /// Solve `A x = b` with the stored factorisation; `b` is overwritten by
    /// `x`.
    pub fn solve(&self, b: &mut [f64; N]) {
        // Apply the permutation: y = P b.
        let pb: [f64; N] = core::array::from_fn(|k| b[self.perm[k]]);
        *b = pb;
        // Forward substitution with the unit lower triangle.
        for i in 0..N {
            let (done, rest) = b.split_at_mut(i);
            let s: f64 = self.lu[i][..i]
                .iter()
                .zip(done.iter())
                .map(|(l, x)| l * x)
                .sum();
            rest[0] -= s;
        }
        // Back substitution with the upper triangle.
        for i in (0..N).rev() {
            let (head, done) = b.split_at_mut(i + 1);
            let s: f64 = self.lu[i][i + 1..]
                .iter()
                .zip(done.iter())
                .map(|(u, x)| u * x)
                .sum();
            head[i] = (head[i] - s) / self.lu[i][i];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn matvec<const N: usize>(a: &[[f64; N]; N], x: &[f64; N]) -> [f64; N] {
        core::array::from_fn(|i| (0..N).map(|j| a[i][j] * x[j]).sum())
    }

    #[test]
    fn solves_a_system_that_needs_pivoting() {
        // The (0,0) entry is zero, so elimination without pivoting fails.
        let a = [[0.0, 2.0, 1.0], [1.0, 1.0, 1.0], [4.0, -1.0, 3.0]];
        let x_true = [1.0, -2.0, 0.5];
        let mut b = matvec(&a, &x_true);
        let mut lu = Lu::new();
        assert_eq!(lu.factor(&a), Ok(()));
        lu.solve(&mut b);
        for (x, xt) in b.iter().zip(x_true.iter()) {
            assert!((x - xt).abs() < 1e-14, "{x} vs {xt}");
        }
    }

    #[test]
    fn shifted_factorisation_matches_explicit_matrix() {
        let jac = [[-3.0, 1.0], [2.0, -5.0]];
        let shift = 4.0;
        let explicit = [[7.0, -1.0], [-2.0, 9.0]];
        let mut a = Lu::new();
        let mut b = Lu::new();
        assert_eq!(a.factor_shifted(shift, &jac), Ok(()));
        assert_eq!(b.factor(&explicit), Ok(()));
        let mut x = [1.0, 2.0];
        let mut z = x;
        a.solve(&mut x);
        b.solve(&mut z);
        assert_eq!(x, z);
    }

    #[test]
    fn reports_singular_matrices() {
        let a = [[1.0, 2.0], [2.0, 4.0]];
        let mut lu = Lu::new();
        assert!(lu.factor(&a).is_err());
        let nan = [[f64::NAN, 0.0], [0.0, 1.0]];
        assert!(lu.factor(&nan).is_err());
    }

    #[test]
    fn hilbert_residual_is_small() {
        const N: usize = 6;
        let a: [[f64; N]; N] =
            core::array::from_fn(|i| core::array::from_fn(|j| 1.0 / (i + j + 1) as f64));
        let x_true: [f64; N] = core::array::from_fn(|i| (i as f64) - 2.5);
        let b = matvec(&a, &x_true);
        let mut x = b;
        let mut lu = Lu::new();
        assert_eq!(lu.factor(&a), Ok(()));
        lu.solve(&mut x);
        let r = matvec(&a, &x);
        for (ri, bi) in r.iter().zip(b.iter()) {
            assert!((ri - bi).abs() < 1e-12);
        }
    }
}
