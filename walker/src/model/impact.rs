//! The impact map's result ([`ImpactResult`]) and the two adapters from the level and slope
//! impact kernels' outputs to it.

use serde::Serialize;

/// The result of an impact kernel evaluated at the pre-impact state.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ImpactResult {
    /// The impulses of the impact that is applied (`impact2_level`: fore foot and torso lock;
    /// `impact_slope`: fore foot).
    pub impulses: [f64; 2],
    /// The rear-foot impulse of the test map with the rear foot kept on the floor
    /// (`impact3_level`'s `lambda_I[1]`, Eq. 11; `impact2_slope`'s `lambda_I[1]`, Eq. 46):
    /// non-negative means the walker would stay in double support.
    pub rear_impulse: f64,
    /// Post-impact velocities of the old coordinates `[xd, zd, th1d, th2d]`.
    pub qd: [f64; 4],
}

/// [`ImpactResult`] of the level kernels: `impact2_level` applied, `impact3_level` the test.
pub(super) fn level_impact(test: [f64; 7], applied: [f64; 6]) -> ImpactResult {
    ImpactResult {
        impulses: [applied[0], applied[1]],
        rear_impulse: test[1],
        qd: [applied[2], applied[3], applied[4], applied[5]],
    }
}

/// [`ImpactResult`] of the slope kernels: `impact_slope` applied, `impact2_slope` the test.
pub(super) fn slope_impact(applied: [f64; 5], test: [f64; 6]) -> ImpactResult {
    ImpactResult {
        impulses: [applied[0], 0.0],
        rear_impulse: test[1],
        qd: [applied[1], applied[2], applied[3], applied[4]],
    }
}
