//! The root finder of event location: Anderson–Björck regula falsi with a bisection
//! safeguard, down to a bracket of about two ulps.

/// Maximum iterations of the root finder (it normally needs far fewer; the
/// bisection safeguard guarantees progress). Reaching it is no failure: the bracket
/// halves at least every fourth iteration (three without halving force a bisection),
/// so after 200 it is at most `2^-50` of the step, and its end on `b`'s side is
/// returned as for a converged search: the event is then located at most `1e-15` steps
/// after the crossing instead of two ulps.
const MAX_ROOT_ITERATIONS: usize = 200;

/// Find a zero of `g` in `[a, b]`, given `ga = g(a)` and `gb = g(b)` of
/// strictly opposite signs, by the Anderson–Björck method with a bisection
/// safeguard. Returns the end of the final bracket on `b`'s side (where `g`
/// is zero or has the sign of `gb`), once the bracket is at most about two
/// ulps wide.
pub(crate) fn find_root<E>(
    mut a: f64,
    mut ga: f64,
    mut b: f64,
    mut gb: f64,
    g: &mut impl FnMut(f64) -> Result<f64, E>,
) -> Result<f64, E> {
    // side: +1 if b was replaced last, -1 if a was, 0 at the start.
    let mut side = 0i8;
    let mut width_ref = b - a;
    let mut stalled = 0u32;
    for _ in 0..MAX_ROOT_ITERATIONS {
        let width = b - a;
        let scale = a.abs().max(b.abs()).max(f64::MIN_POSITIVE);
        let tol = 2.0 * f64::EPSILON * scale;
        if width <= tol {
            break;
        }
        let mid = a + 0.5 * width;
        let mut c = if stalled >= 3 {
            stalled = 0;
            mid
        } else {
            b - gb * (width / (gb - ga))
        };
        if !c.is_finite() {
            c = mid;
        }
        // Never probe closer than tol/2 to an end (the secant point can
        // round onto an end): once one end has converged, this closes the
        // bracket from the other side at once.
        c = c.clamp(a + 0.5 * tol, b - 0.5 * tol);
        if !(c > a && c < b) {
            // a and b are adjacent floating-point numbers.
            break;
        }
        let gc = g(c)?;
        if gc == 0.0 {
            return Ok(c);
        }
        if (gc > 0.0) == (gb > 0.0) {
            // c replaces b; if a is kept twice in a row, scale g(a).
            if side == 1 {
                let m = 1.0 - gc / gb;
                ga *= if m > 0.0 { m } else { 0.5 };
            }
            b = c;
            gb = gc;
            side = 1;
        } else {
            if side == -1 {
                let m = 1.0 - gc / ga;
                gb *= if m > 0.0 { m } else { 0.5 };
            }
            a = c;
            ga = gc;
            side = -1;
        }
        if b - a <= 0.5 * width_ref {
            width_ref = b - a;
            stalled = 0;
        } else {
            stalled += 1;
        }
    }
    Ok(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn root(a: f64, b: f64, f: impl Fn(f64) -> f64) -> (f64, usize) {
        let mut calls = 0;
        let mut g = |t: f64| -> Result<f64, ()> {
            calls += 1;
            Ok(f(t))
        };
        let r = find_root(a, f(a), b, f(b), &mut g);
        (r.unwrap_or(f64::NAN), calls)
    }

    #[test]
    fn root_finder_reaches_a_few_ulps() {
        let exact = core::f64::consts::FRAC_PI_2;
        let (r, calls) = root(1.0, 2.0, f64::cos);
        assert!(
            (r - exact).abs() <= 4.0 * f64::EPSILON * exact,
            "{r} vs {exact}"
        );
        assert!(calls < 20, "{calls} evaluations");
        // Far side: cos is negative right of pi/2.
        assert!(r.cos() <= 0.0);
    }

    #[test]
    fn root_finder_survives_flat_and_steep_functions() {
        // Very flat near the root (multiplicity 5), then a step-like one.
        let (r, _) = root(0.0, 3.0, |t| (t - 1.0).powi(5));
        assert!((r - 1.0).abs() < 1e-2, "{r}");
        let (r, _) = root(-1.0, 1.0, |t| (1e6 * (t - 0.3)).tanh());
        assert!((r - 0.3).abs() <= 4.0 * f64::EPSILON, "{r}");
    }
}
