//! The mesh of the Poincare section ([`Grid`]): a box around the gait's fixed point with `N`
//! points per coordinate, and the barycentric interpolation of a state onto its points.
//!
//! The interpolation is Byl and Tedrake's: the box's cells are cut into simplices (Kuhn's, or
//! Freudenthal's, triangulation: the cell's `d!` simplices along the orderings of the
//! fractional coordinates), and a state is the convex combination of its simplex's `d + 1`
//! corners. The weights are non-negative and sum to one (the chain keeps its probability), they
//! reproduce every affine function exactly (a state's interpolated image has the right mean),
//! and a row of the transition matrix has `d + 1` entries per floor sample, not the `2^d` of
//! multilinear interpolation (5 instead of 16 on the compass gait's four-dimensional section).

/// A regular mesh of a box in the section's coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct Grid {
    /// The box's lower corner.
    lo: Vec<f64>,
    /// The spacing per coordinate.
    h: Vec<f64>,
    /// The points per coordinate (at least 2).
    n: usize,
}

impl Grid {
    /// The mesh of the box `centre +- half_widths` with `n >= 2` points per coordinate (every
    /// half-width `> 0`).
    #[must_use]
    pub fn new(centre: &[f64], half_widths: &[f64], n: usize) -> Grid {
        let n = n.max(2);
        Grid {
            lo: centre.iter().zip(half_widths).map(|(c, w)| c - w).collect(),
            h: half_widths
                .iter()
                .map(|w| 2.0 * w / (n - 1) as f64)
                .collect(),
            n,
        }
    }

    /// The number of coordinates.
    #[must_use]
    pub fn dim(&self) -> usize {
        self.lo.len()
    }

    /// The number of points, `N^d`.
    #[must_use]
    pub fn len(&self) -> usize {
        self.n.pow(self.dim() as u32)
    }

    /// Whether the mesh has no points (never: `N >= 2`).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The coordinates of point `index` (coordinate 0 varies fastest).
    #[must_use]
    pub fn point(&self, index: usize) -> Vec<f64> {
        let mut rest = index;
        (0..self.dim())
            .map(|k| {
                let i = rest % self.n;
                rest /= self.n;
                self.lo[k] + self.h[k] * i as f64
            })
            .collect()
    }

    /// The barycentric weights of `x` on the corners of its simplex (point index, weight; the
    /// weights positive and summing to one), or `None` when `x` is outside the box or not
    /// finite.
    #[must_use]
    pub fn weights(&self, x: &[f64]) -> Option<Vec<(usize, f64)>> {
        let d = self.dim();
        let top = (self.n - 1) as f64;
        let mut base = vec![0usize; d];
        let mut frac = vec![0.0; d];
        for k in 0..d {
            let u = (x[k] - self.lo[k]) / self.h[k];
            // A state on the box's face within rounding is inside.
            if !(u >= -1e-12 && u <= top + 1e-12) {
                return None;
            }
            let u = u.clamp(0.0, top);
            let b = (u.floor() as usize).min(self.n - 2);
            base[k] = b;
            frac[k] = u - b as f64;
        }
        // Freudenthal: walk from the base corner along the coordinates in decreasing order of
        // their fractional parts.
        let mut order: Vec<usize> = (0..d).collect();
        order.sort_by(|&a, &b| frac[b].total_cmp(&frac[a]).then(a.cmp(&b)));
        let stride = |k: usize| self.n.pow(k as u32);
        let mut corner: usize = base.iter().enumerate().map(|(k, &b)| b * stride(k)).sum();
        let mut out = Vec::with_capacity(d + 1);
        let mut prev = 1.0;
        for &k in &order {
            out.push((corner, prev - frac[k]));
            prev = frac[k];
            corner += stride(k);
        }
        out.push((corner, prev));
        out.retain(|&(_, w)| w > 0.0);
        Some(out)
    }
}

#[cfg(test)]
mod tests {
    use super::Grid;

    #[test]
    fn mesh_points_span_the_box_with_the_centre_in_the_middle() {
        let g = Grid::new(&[1.0, -2.0], &[0.5, 0.25], 5);
        assert_eq!(g.len(), 25);
        assert_eq!(g.point(0), vec![0.5, -2.25]);
        assert_eq!(g.point(24), vec![1.5, -1.75]);
        assert_eq!(g.point(12), vec![1.0, -2.0]);
    }

    #[test]
    fn barycentric_weights_sum_to_one_and_reproduce_affine_functions() {
        // An affine function of the point is reproduced by its weights to rounding (1e-12
        // relative: a few operations on numbers of order 1).
        let g = Grid::new(&[0.3, 1.0, -0.5], &[0.2, 0.7, 0.1], 4);
        let f = |p: &[f64]| 2.0 * p[0] - 3.0 * p[1] + 5.0 * p[2] + 0.7;
        for x in [
            [0.31, 1.2, -0.45],
            [0.1, 0.3, -0.6],
            [0.5, 1.7, -0.4],
            [0.2, 0.9, -0.52],
        ] {
            let w = g.weights(&x).expect("inside");
            assert!(w.len() <= 4 && w.iter().all(|&(_, v)| v > 0.0));
            let sum: f64 = w.iter().map(|&(_, v)| v).sum();
            assert!((sum - 1.0).abs() < 1e-12, "{sum}");
            let interp: f64 = w.iter().map(|&(i, v)| v * f(&g.point(i))).sum();
            assert!((interp - f(&x)).abs() < 1e-12, "{interp} vs {}", f(&x));
        }
    }

    #[test]
    fn a_state_outside_the_box_or_not_finite_has_no_weights() {
        let g = Grid::new(&[0.0, 0.0], &[1.0, 1.0], 3);
        assert!(g.weights(&[1.01, 0.0]).is_none());
        assert!(g.weights(&[0.0, -1.5]).is_none());
        assert!(g.weights(&[f64::NAN, 0.0]).is_none());
        assert_eq!(g.weights(&[1.0, 1.0]), Some(vec![(8, 1.0)]));
    }
}
