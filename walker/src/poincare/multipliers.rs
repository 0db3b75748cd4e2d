//! Floquet multipliers: eigenvalues of the map's Jacobian, their eigenvectors, and the
//! tolerance that recognises the structural multiplier at 1.

use nalgebra::{Complex, DMatrix, DVector};
use serde::Serialize;

/// A multiplier counts as the structural multiplier at 1 (family of cycles) when it is this
/// close to 1.
pub const UNIT_MULTIPLIER_TOL: f64 = 1e-6;

/// A Floquet multiplier (an eigenvalue of the map's Jacobian at the fixed point).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Multiplier {
    /// Real part.
    pub re: f64,
    /// Imaginary part.
    pub im: f64,
}

impl Multiplier {
    /// `|lambda|`.
    pub fn modulus(&self) -> f64 {
        self.re.hypot(self.im)
    }
}

/// Eigenvalues of a square matrix given row by row (real Schur form via nalgebra), sorted by
/// decreasing modulus. Rows of the wrong length give an empty list.
pub fn eigenvalues(rows: &[Vec<f64>]) -> Vec<Multiplier> {
    let n = rows.len();
    if rows.iter().any(|r| r.len() != n) {
        return Vec::new();
    }
    let m = DMatrix::from_fn(n, n, |i, j| rows[i][j]);
    let mut out: Vec<Multiplier> = m
        .complex_eigenvalues()
        .iter()
        .map(|c| Multiplier { re: c.re, im: c.im })
        .collect();
    out.sort_by(|a, b| b.modulus().total_cmp(&a.modulus()));
    out
}

/// The unit right and left eigenvectors of a simple eigenvalue `lambda`: `J w = lambda w`,
/// `u^H J = lambda u^H`.
pub(crate) struct Eigenvectors {
    /// The right eigenvector `w` (unit length).
    pub(crate) right: DVector<Complex<f64>>,
    /// The left eigenvector `u` (unit length).
    pub(crate) left: DVector<Complex<f64>>,
    /// `u^H w`: its inverse modulus is the eigenvalue's condition number (Wilkinson).
    pub(crate) overlap: Complex<f64>,
}

/// The eigenvectors of the simple eigenvalue `lambda` of `jac`: the null vectors of
/// `J - lambda I` and of its adjoint (the right singular vectors of their smallest singular
/// values); `None` where `|u^H w| < 1e-8` (not simple, to this precision) or the SVD fails.
pub(crate) fn eigenvectors(jac: &DMatrix<f64>, lambda: Complex<f64>) -> Option<Eigenvectors> {
    let d = jac.nrows();
    let a = jac.map(|x| Complex::new(x, 0.0)) - DMatrix::identity(d, d) * lambda;
    let right = null_vector(&a)?;
    let left = null_vector(&a.adjoint())?;
    let overlap = left.dotc(&right);
    (overlap.norm() >= 1e-8).then_some(Eigenvectors {
        right,
        left,
        overlap,
    })
}

/// The unit null vector of the complex square matrix `a`: the right singular vector of its
/// smallest singular value.
fn null_vector(a: &DMatrix<Complex<f64>>) -> Option<DVector<Complex<f64>>> {
    let svd = a.clone().svd(false, true);
    let v_t = svd.v_t?;
    let (k, _) = svd
        .singular_values
        .iter()
        .enumerate()
        .min_by(|x, y| x.1.total_cmp(y.1))?;
    Some(v_t.row(k).adjoint())
}
