//! Floating-point units of the error bounds: machine epsilon and the ulp of a value.

/// Machine epsilon of `f64` (the spacing of floats at 1.0, twice the unit roundoff).
pub const EPS: f64 = f64::EPSILON;

/// Units in the last place of `x` (for `x = 0`: the smallest subnormal).
#[must_use]
pub fn ulp(x: f64) -> f64 {
    let a = x.abs();
    if a == 0.0 || !a.is_finite() {
        return f64::from_bits(1);
    }
    let next = f64::from_bits(a.to_bits() + 1);
    next - a
}
