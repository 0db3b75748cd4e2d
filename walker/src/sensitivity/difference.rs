//! Richardson-extrapolated central differences of a vector-valued function of one variable,
//! with an error estimate.

/// `f'(0)` from the values `f(h)`, `f(-h)`, `f(h/2)`, `f(-h/2)` (each a vector of the same
/// length): the central differences `D1` at `h` and `D2` at `h/2`, extrapolated to
/// `(4 D2 - D1) / 3` (error `O(h^4)` for a smooth `f`). The error estimate is `|D2 - D1|`:
/// three times the usual estimate of the extrapolated value, so that it also covers the noise
/// of the evaluations (the integrator's error divided by `h`), which the extrapolation
/// amplifies by up to three. Returns `(value, error)` per component.
pub(super) fn richardson(values: &[Vec<f64>; 4], h: f64) -> Vec<(f64, f64)> {
    let [plus, minus, half_plus, half_minus] = values;
    (0..plus.len())
        .map(|i| {
            let d1 = (plus[i] - minus[i]) / (2.0 * h);
            let d2 = (half_plus[i] - half_minus[i]) / h;
            ((4.0 * d2 - d1) / 3.0, (d2 - d1).abs())
        })
        .collect()
}

/// The shifts of [`richardson`]'s four evaluations, in its order.
pub(super) fn shifts(h: f64) -> [f64; 4] {
    [h, -h, 0.5 * h, -0.5 * h]
}

/// The difference step for a value `x`: `1e-3 max(|x|, 1)`. With the maps at `rtol = 1e-12`
/// the evaluations' noise contributes about `1e-12 / h <= 1e-9` relative, the truncation error
/// after the extrapolation `O(h^4) ~ 1e-12`.
pub(super) fn step(x: f64) -> f64 {
    1e-3 * x.abs().max(1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn richardson_is_exact_to_rounding_for_a_quintic_and_its_estimate_bounds_the_error() {
        // f(x) = x + x^3 + x^5: D1 and D2 carry h^2 and h^4 terms; the extrapolation removes
        // the h^2 term, leaving -h^4/4 (h/2 weighted): about 1e-12 at h = 1e-3.
        let f = |x: f64| x + x.powi(3) + x.powi(5);
        let h = 1e-3;
        let s = shifts(h);
        let vals = [vec![f(s[0])], vec![f(s[1])], vec![f(s[2])], vec![f(s[3])]];
        let (d, e) = richardson(&vals, h)[0];
        assert!((d - 1.0).abs() < 1e-11, "{d}");
        assert!(e >= (d - 1.0).abs(), "{e}");
        assert!(e < 1e-5, "{e}");
    }
}
