//! The KKT residual of a design: how far the gradient of the Lagrangian is from zero with the
//! best non-negative multipliers of the active constraints.

use nalgebra::{DMatrix, DVector};

/// Constraints within this of their bound count as active.
pub const ACTIVE: f64 = 1e-6;

/// The residual `max_i |(grad f + sum_j l_j grad g_j)_i|`, projected on the bounds (a
/// component pushing against an active bound is taken by that bound's multiplier), with `l`
/// the least-squares multipliers of the active constraints (`g_j > -ACTIVE`), negative ones
/// dropped and the rest refitted; returns the residual and the multipliers (0 for inactive).
#[must_use]
pub fn kkt(
    grad_f: &[f64],
    g: &[f64],
    grad_g: &[Vec<f64>],
    at_lo: &[bool],
    at_hi: &[bool],
) -> (f64, Vec<f64>) {
    let n = grad_f.len();
    let mut active: Vec<usize> = (0..g.len()).filter(|&j| g[j] > -ACTIVE).collect();
    let mut lagrange = vec![0.0; g.len()];
    // Free components only: those not held by an active bound.
    let free: Vec<usize> = (0..n).filter(|&i| !at_lo[i] && !at_hi[i]).collect();
    for _ in 0..=g.len() {
        lagrange.iter_mut().for_each(|l| *l = 0.0);
        if !active.is_empty() && !free.is_empty() {
            let a = DMatrix::from_fn(free.len(), active.len(), |r, c| grad_g[active[c]][free[r]]);
            let b = DVector::from_fn(free.len(), |r, _| -grad_f[free[r]]);
            if let Ok(l) = a.svd(true, true).solve(&b, 1e-12) {
                for (c, &j) in active.iter().enumerate() {
                    lagrange[j] = l[c];
                }
            }
        }
        let before = active.len();
        active.retain(|&j| lagrange[j] >= 0.0);
        if active.len() == before {
            break;
        }
    }
    let mut residual: f64 = 0.0;
    for i in 0..n {
        let r = grad_f[i]
            + (0..g.len())
                .map(|j| lagrange[j] * grad_g[j][i])
                .sum::<f64>();
        let left = if at_lo[i] {
            r.min(0.0)
        } else if at_hi[i] {
            r.max(0.0)
        } else {
            r
        };
        residual = residual.max(left.abs());
    }
    (residual, lagrange)
}

#[cfg(test)]
mod tests {
    use super::kkt;

    /// min x^2 + y^2 subject to 1 - x - y <= 0: the optimum (1/2, 1/2) with multiplier 1 has a
    /// zero residual; a point off the optimum on the constraint does not.
    #[test]
    fn the_residual_vanishes_at_a_constrained_optimum_only() {
        let grad_g = vec![vec![-1.0, -1.0]];
        let (r, l) = kkt(&[1.0, 1.0], &[0.0], &grad_g, &[false; 2], &[false; 2]);
        assert!(r < 1e-14 && (l[0] - 1.0).abs() < 1e-14);
        let (r, _) = kkt(&[1.2, 0.8], &[0.0], &grad_g, &[false; 2], &[false; 2]);
        assert!((r - 0.2).abs() < 1e-12);
    }

    /// A gradient pushing against an active bound leaves no residual; pulling away from it
    /// does.
    #[test]
    fn an_active_bound_takes_the_gradient_that_pushes_against_it() {
        let (r, _) = kkt(&[2.0], &[], &[], &[true], &[false]);
        assert_eq!(r, 0.0);
        let (r, _) = kkt(&[-2.0], &[], &[], &[true], &[false]);
        assert_eq!(r, 2.0);
    }
}
