//! Why the ground reaction `lambda` blew up: at a pole of Eq. 23 (its denominator vanishes), or
//! with a regular denominator and a huge numerator (the control input or the spin), or into
//! values that are not numbers.
//!
//! `lambda = N / D` (Eq. 23). Its numerator's gravity term is `N_g = m_t I1 g` (times
//! `cos^2 phi` on the slope), and `lambda_g = N_g / D`, `lambda` with gravity alone in the
//! numerator ([`Model::gravity_lambda`](crate::model::Model::gravity_lambda), from the kernels),
//! measures the denominator against its constant term `I1`: `|lambda_g| / (m_t g) = I1 / |D|`
//! on level ground. A blow-up is a pole where `lambda_g` itself counts as blown up, by the same
//! measure as `lambda` at the end of an integration segment ([`blown_up`]: not finite, or
//! beyond a thousandth of the threshold `lambda_max =`
//! [`SimConfig::lambda_blowup`](super::SimConfig::lambda_blowup) `m_t g`), that is where
//! `|D| <= 1e3 I1 / lambda_blowup` (`1e-3 I1` by default, times `cos^2 phi` on the slope):
//! the denominator vanished against the scale of its terms. Otherwise the numerator is huge
//! (a control input `u` made huge by a ramp `T_set` so short that `ydd_d = 60 alpha / T_set^2`
//! is huge, or a huge spin `th1d^2`).
//!
//! The margins of this thousandth, at the default threshold: where `D` is regular `lambda_g`
//! is of the order of `m_t g` (at most `1.31 m_t g` on level ground with Table 1 and `mu0 =
//! 0.4`, where `D >= 0.384`), 760 times below it; at a pole reached from a walking gait the
//! guard fires at `|lambda| = lambda_max` with a numerator within a factor 10 of `N_g` (`l
//! th1d^2 + l |u sin th1| / I1` below `9 g`), so `|lambda_g| >= lambda_max / 10`, 100 times
//! above it. A blow-up with both (a vanishing denominator and a huge numerator) is named
//! for the pole.

use super::failure::FailureKind;
use super::foot::{Foot, control_input};

/// Whether `lambda = lam` counts as blown up at the end of an integration segment or as the
/// measure of a pole: not finite, or above a thousandth of the blow-up threshold `lambda_max`.
pub(super) fn blown_up(lam: f64, lambda_max: f64) -> bool {
    !lam.is_finite() || lam.abs() > lambda_max * 1e-3
}

/// The failure for `lambda = lam` beyond the blow-up threshold `lambda_max` (or not finite) at
/// `(t, y)` on `foot`: [`FailureKind::LambdaDenominatorZero`] at a pole of Eq. 23,
/// [`FailureKind::LambdaNumeratorHuge`] where the denominator is regular and `lambda` and `u`
/// are finite, [`FailureKind::NonFinite`] otherwise (see the module documentation).
pub(super) fn blow_up<const S: usize>(
    foot: &Foot<'_>,
    t: f64,
    y: &[f64; S],
    lam: f64,
    lambda_max: f64,
) -> FailureKind {
    let model = foot.model;
    let contact = foot.contact();
    // A NaN `lambda_g` (only with a non-finite state, which is checked before) is no pole.
    let pole = model
        .gravity_lambda(y, contact)
        .is_some_and(|lg| !lg.is_nan() && blown_up(lg, lambda_max));
    if pole {
        return FailureKind::LambdaDenominatorZero { lambda: lam };
    }
    // The input largest in magnitude (0 for a passive walker).
    let u = control_input(model, t, y, contact)
        .iter()
        .copied()
        .fold(0.0, |a: f64, b: f64| {
            if b.abs() > a.abs() || b.is_nan() {
                b
            } else {
                a
            }
        });
    if lam.is_finite() && u.is_finite() {
        FailureKind::LambdaNumeratorHuge { lambda: lam, u }
    } else {
        FailureKind::NonFinite
    }
}
