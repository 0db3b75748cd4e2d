//! Floquet multipliers: eigenvalues of the map's Jacobian, and the tolerance that recognises
//! the structural multiplier at 1.

use nalgebra::DMatrix;
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
