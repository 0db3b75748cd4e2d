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
    /// The points per coordinate (at least 2, or 1 for a coordinate held at the centre).
    n: Vec<usize>,
    /// The centre, where it is exactly a mesh point ([`Grid::with_exact_centre`]).
    centre: Option<Vec<f64>>,
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
            n: vec![n; centre.len()],
            centre: None,
        }
    }

    /// [`Grid::new`], with the centre exactly a mesh point: for an odd `n` the middle point of
    /// each coordinate is the centre's value (not `lo + h (n - 1)/2` rounded), and a state
    /// whose coordinate is the centre's exactly is interpolated on the middle points only; a
    /// coordinate with `held[k]` has the one point of the centre's value, and a state off it
    /// is outside the mesh. On a floor that sets the slope a foot at rest after its strike
    /// (`xd = 0` exactly) must stay at rest in the chain: a foot that slides by a rounding
    /// error meets a change of slope as a kink.
    #[must_use]
    pub fn with_exact_centre(centre: &[f64], half_widths: &[f64], n: usize, held: &[bool]) -> Grid {
        let mut g = Grid::new(centre, half_widths, n);
        for (k, &h) in held.iter().enumerate() {
            if h {
                g.n[k] = 1;
            }
        }
        g.centre = Some(centre.to_vec());
        g
    }

    /// The middle index and the centre's value of coordinate `k`, where the centre is exact
    /// (an odd number of points).
    fn exact(&self, k: usize) -> Option<(usize, f64)> {
        self.centre
            .as_ref()
            .filter(|_| self.n[k] % 2 == 1)
            .map(|c| ((self.n[k] - 1) / 2, c[k]))
    }

    /// The number of coordinates.
    #[must_use]
    pub fn dim(&self) -> usize {
        self.lo.len()
    }

    /// The number of points, the product of the points per coordinate (`N^d` unless some are
    /// held).
    #[must_use]
    pub fn len(&self) -> usize {
        self.n.iter().product()
    }

    /// Whether the mesh has no points (never: every coordinate has one at least).
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
                let i = rest % self.n[k];
                rest /= self.n[k];
                match self.exact(k) {
                    Some((mid, c)) if i == mid => c,
                    _ => self.lo[k] + self.h[k] * i as f64,
                }
            })
            .collect()
    }

    /// The barycentric weights of `x` on the corners of its simplex (point index, weight; the
    /// weights positive and summing to one), or `None` when `x` is outside the box or not
    /// finite.
    #[must_use]
    pub fn weights(&self, x: &[f64]) -> Option<Vec<(usize, f64)>> {
        let d = self.dim();
        let mut base = vec![0usize; d];
        let mut frac = vec![0.0; d];
        let mut free = Vec::with_capacity(d);
        for k in 0..d {
            if self.n[k] == 1 {
                // A held coordinate: on its one point exactly, or outside.
                let c = self.centre.as_ref().map_or(f64::NAN, |c| c[k]);
                if x[k].to_bits() != c.to_bits() {
                    return None;
                }
                continue;
            }
            free.push(k);
            let top = (self.n[k] - 1) as f64;
            let u = match self.exact(k) {
                Some((mid, c)) if x[k].to_bits() == c.to_bits() => mid as f64,
                _ => (x[k] - self.lo[k]) / self.h[k],
            };
            // A state on the box's face within rounding is inside.
            if !(u >= -1e-12 && u <= top + 1e-12) {
                return None;
            }
            let u = u.clamp(0.0, top);
            let b = (u.floor() as usize).min(self.n[k] - 2);
            base[k] = b;
            frac[k] = u - b as f64;
        }
        // Freudenthal: walk from the base corner along the coordinates in decreasing order of
        // their fractional parts.
        let mut order = free;
        order.sort_by(|&a, &b| frac[b].total_cmp(&frac[a]).then(a.cmp(&b)));
        let stride = |k: usize| self.n[..k].iter().product::<usize>();
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

    #[test]
    fn an_exact_centre_is_a_mesh_point_and_a_state_on_it_stays_on_its_plane() {
        // With 7 points the spacing 2 w / 6 is not exact: the plain mesh's middle point misses
        // the centre by a rounding error; the exact one hits it, and a state with the centre's
        // first coordinate is interpolated on points that have it.
        let (c, w) = ([0.0, 0.3], [0.9, 0.7]);
        assert_ne!(Grid::new(&c, &w, 7).point(3)[0], 0.0);
        let g = Grid::with_exact_centre(&c, &w, 7, &[false, false]);
        assert_eq!(g.point(3)[0], 0.0);
        assert_eq!(g.point(3 + 7 * 3), c.to_vec());
        let weights = g.weights(&[0.0, 0.41]).expect("inside");
        assert!(
            weights.iter().all(|&(i, _)| g.point(i)[0] == 0.0),
            "{weights:?}"
        );
        let sum: f64 = weights.iter().map(|&(_, v)| v).sum();
        assert!((sum - 1.0).abs() < 1e-12, "{sum}");
    }

    #[test]
    fn a_held_coordinate_has_one_point_and_a_state_off_it_is_outside() {
        let (c, w) = ([0.0, 0.3], [1e-6, 0.7]);
        let g = Grid::with_exact_centre(&c, &w, 5, &[true, false]);
        assert_eq!(g.len(), 5);
        assert_eq!(g.point(2), c.to_vec());
        assert_eq!(g.point(4), vec![0.0, 1.0]);
        // An affine function of the free coordinate is reproduced; the held one is exact.
        let weights = g.weights(&[0.0, 0.51]).expect("inside");
        let interp: f64 = weights.iter().map(|&(i, v)| v * g.point(i)[1]).sum();
        assert!((interp - 0.51).abs() < 1e-12, "{interp}");
        assert!(g.weights(&[1e-9, 0.3]).is_none());
    }
}
