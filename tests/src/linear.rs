//! Square linear solves with their conditioning: the one numerical tool of the generic path.

use nalgebra::{DMatrix, DVector};

/// Solution of a square linear system with its conditioning (2-norm, by SVD).
#[derive(Debug, Clone)]
pub struct Solved {
    /// The solution.
    pub x: DVector<f64>,
    /// `cond_2(K) = sigma_max / sigma_min`.
    pub cond: f64,
    /// `||K^-1||_2 = 1 / sigma_min`.
    pub inv_norm: f64,
}

impl Solved {
    /// Error scale of the solution for a right-hand side whose entries carry rounding errors
    /// relative to `b_abs` (the absolute-value evaluation of `b`):
    /// `cond(K) ||x|| + ||K^-1|| ||b_abs||`. The perturbation bound of a linear system,
    /// `||dx|| <= ||K^-1|| (||dK|| ||x|| + ||db||)`, with `||dK|| <= c eps ||K||` and
    /// `||db|| <= c eps ||b_abs||` for any backward-stable method, is `c eps` times this.
    #[must_use]
    pub fn scale(&self, b_abs: &DVector<f64>) -> f64 {
        self.cond * self.x.norm() + self.inv_norm * b_abs.norm()
    }
}

/// Solves `k x = b` by LU with partial pivoting and measures `k`'s conditioning by SVD.
///
/// # Errors
/// `k` is exactly singular (LU fails).
pub fn solve(k: &DMatrix<f64>, b: &DVector<f64>) -> Result<Solved, String> {
    let x = k.clone().lu().solve(b).ok_or("singular system")?;
    let sv = k.clone().svd(false, false).singular_values;
    let smax = sv.max();
    let smin = sv.min();
    Ok(Solved {
        x,
        cond: smax / smin,
        inv_norm: 1.0 / smin,
    })
}
