//! The `tanh` friction law of the scenes and its inverse, the velocity that gives a chosen
//! friction coefficient.

/// The friction law of the `tanh` scenes: `-mu0 tanh(c xd)` on level ground (Eq. 26),
/// `-mu0 tanh(c xd / cos phi)` on the slope (Eq. 37).
#[must_use]
pub fn mu_law(mu0: f64, c: f64, phi: f64, xd: f64) -> f64 {
    if phi == 0.0 {
        -mu0 * (c * xd).tanh()
    } else {
        -mu0 * (c * xd / phi.cos()).tanh()
    }
}

/// The velocity `xd` at which [`mu_law`] gives (up to rounding) `mu`: `xd = cos phi *
/// atanh(-mu / mu0) / c`. Requires `|mu| < mu0`.
#[must_use]
pub fn xd_for_mu(mu: f64, mu0: f64, c: f64, phi: f64) -> f64 {
    (-mu / mu0).atanh() / c * phi.cos()
}
