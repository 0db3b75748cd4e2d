//! Small dense matrices of rational functions.

use crate::error::{Error, Result};
use crate::ratfunc::RatFunc;
use crate::symbol::Sym;

/// A dense `rows x cols` matrix of rational functions, row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct Matrix {
    rows: usize,
    cols: usize,
    data: Vec<RatFunc>,
}

impl Matrix {
    /// A matrix from rows; an error if the rows have different lengths.
    pub fn from_rows(rows: Vec<Vec<RatFunc>>) -> Result<Matrix> {
        let r = rows.len();
        let c = rows.first().map_or(0, Vec::len);
        if rows.iter().any(|row| row.len() != c) {
            return Err(Error::Dimension {
                op: "from_rows",
                left: (r, c),
                right: (0, 0),
            });
        }
        Ok(Matrix {
            rows: r,
            cols: c,
            data: rows.into_iter().flatten().collect(),
        })
    }

    /// A column vector.
    pub fn column(entries: Vec<RatFunc>) -> Matrix {
        Matrix {
            rows: entries.len(),
            cols: 1,
            data: entries,
        }
    }

    /// A row vector.
    pub fn row(entries: Vec<RatFunc>) -> Matrix {
        Matrix {
            rows: 1,
            cols: entries.len(),
            data: entries,
        }
    }

    /// The zero matrix.
    pub fn zeros(rows: usize, cols: usize) -> Matrix {
        Matrix {
            rows,
            cols,
            data: vec![RatFunc::zero(); rows * cols],
        }
    }

    /// The identity.
    pub fn identity(n: usize) -> Matrix {
        let mut m = Matrix::zeros(n, n);
        for i in 0..n {
            m.data[i * n + i] = RatFunc::one();
        }
        m
    }

    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of columns.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Entry `(i, j)`.
    pub fn get(&self, i: usize, j: usize) -> &RatFunc {
        &self.data[i * self.cols + j]
    }

    /// Sets entry `(i, j)`.
    pub fn set(&mut self, i: usize, j: usize, v: RatFunc) {
        self.data[i * self.cols + j] = v;
    }

    /// Entries, row-major.
    pub fn entries(&self) -> &[RatFunc] {
        &self.data
    }

    /// Transpose.
    pub fn transpose(&self) -> Matrix {
        let mut t = Matrix::zeros(self.cols, self.rows);
        for i in 0..self.rows {
            for j in 0..self.cols {
                t.set(j, i, self.get(i, j).clone());
            }
        }
        t
    }

    /// Product.
    pub fn mul(&self, other: &Matrix) -> Result<Matrix> {
        if self.cols != other.rows {
            return Err(Error::Dimension {
                op: "mul",
                left: (self.rows, self.cols),
                right: (other.rows, other.cols),
            });
        }
        let mut p = Matrix::zeros(self.rows, other.cols);
        for i in 0..self.rows {
            for j in 0..other.cols {
                let mut acc = RatFunc::zero();
                for k in 0..self.cols {
                    let (a, b) = (self.get(i, k), other.get(k, j));
                    if !a.is_zero() && !b.is_zero() {
                        acc = acc.add(&a.mul(b));
                    }
                }
                p.set(i, j, acc);
            }
        }
        Ok(p)
    }

    fn zip(
        &self,
        other: &Matrix,
        op: &'static str,
        f: impl Fn(&RatFunc, &RatFunc) -> RatFunc,
    ) -> Result<Matrix> {
        if (self.rows, self.cols) != (other.rows, other.cols) {
            return Err(Error::Dimension {
                op,
                left: (self.rows, self.cols),
                right: (other.rows, other.cols),
            });
        }
        let data = self
            .data
            .iter()
            .zip(&other.data)
            .map(|(a, b)| f(a, b))
            .collect();
        Ok(Matrix {
            rows: self.rows,
            cols: self.cols,
            data,
        })
    }

    /// Sum.
    pub fn add(&self, other: &Matrix) -> Result<Matrix> {
        self.zip(other, "add", RatFunc::add)
    }

    /// Difference.
    pub fn sub(&self, other: &Matrix) -> Result<Matrix> {
        self.zip(other, "sub", RatFunc::sub)
    }

    /// Product with a scalar.
    pub fn scale(&self, k: &RatFunc) -> Matrix {
        Matrix {
            rows: self.rows,
            cols: self.cols,
            data: self.data.iter().map(|a| a.mul(k)).collect(),
        }
    }

    /// Applies a fallible map to every entry.
    pub fn try_map(&self, f: impl Fn(&RatFunc) -> Result<RatFunc>) -> Result<Matrix> {
        let data = self.data.iter().map(f).collect::<Result<Vec<_>>>()?;
        Ok(Matrix {
            rows: self.rows,
            cols: self.cols,
            data,
        })
    }

    /// The single entry of a `1 x 1` matrix.
    pub fn scalar(&self) -> Result<RatFunc> {
        if (self.rows, self.cols) != (1, 1) {
            return Err(Error::Dimension {
                op: "scalar",
                left: (self.rows, self.cols),
                right: (1, 1),
            });
        }
        Ok(self.data[0].clone())
    }

    /// Jacobian `d f_i / d s_j` of a column of functions with respect to symbols.
    pub fn jacobian(f: &[RatFunc], syms: &[Sym]) -> Matrix {
        let mut j = Matrix::zeros(f.len(), syms.len());
        for (i, fi) in f.iter().enumerate() {
            for (k, s) in syms.iter().enumerate() {
                j.set(i, k, fi.diff(*s));
            }
        }
        j
    }

    /// Determinant by cofactor expansion along the first row (the matrices here are at most
    /// 4 x 4, and cancellation keeps every minor compact).
    pub fn det(&self) -> Result<RatFunc> {
        if self.rows != self.cols {
            return Err(Error::Dimension {
                op: "det",
                left: (self.rows, self.cols),
                right: (0, 0),
            });
        }
        Ok(self.det_unchecked())
    }

    fn det_unchecked(&self) -> RatFunc {
        let n = self.rows;
        match n {
            0 => RatFunc::one(),
            1 => self.data[0].clone(),
            _ => {
                let mut acc = RatFunc::zero();
                for j in 0..n {
                    let a = self.get(0, j);
                    if a.is_zero() {
                        continue;
                    }
                    let minor = self.minor(0, j).det_unchecked();
                    let term = a.mul(&minor);
                    acc = if j % 2 == 0 {
                        acc.add(&term)
                    } else {
                        acc.sub(&term)
                    };
                }
                acc
            }
        }
    }

    fn minor(&self, row: usize, col: usize) -> Matrix {
        let n = self.rows;
        let mut data = Vec::with_capacity((n - 1) * (n - 1));
        for i in (0..n).filter(|&i| i != row) {
            for j in (0..n).filter(|&j| j != col) {
                data.push(self.get(i, j).clone());
            }
        }
        Matrix {
            rows: n - 1,
            cols: n - 1,
            data,
        }
    }

    /// Inverse by the adjugate: `adj(A) / det(A)`. An error [`Error::SingularMatrix`] when the
    /// determinant is identically zero.
    pub fn inverse(&self, name: &str) -> Result<Matrix> {
        let det = self.det()?;
        if det.is_zero() {
            return Err(Error::SingularMatrix {
                name: name.to_owned(),
            });
        }
        let n = self.rows;
        let inv_det = det.recip()?;
        let mut inv = Matrix::zeros(n, n);
        for i in 0..n {
            for j in 0..n {
                let cof = self.minor(j, i).det_unchecked();
                let cof = if (i + j) % 2 == 0 { cof } else { cof.neg() };
                inv.set(i, j, cof.mul(&inv_det));
            }
        }
        Ok(inv)
    }
}
