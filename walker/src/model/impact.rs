//! The impact map's result ([`ImpactResult`]) and the adapters from the impact kernels'
//! outputs to it: the paper's frictionless maps (level and slope) and the map with Coulomb
//! friction at the striking foot ([`super::friction_impact`]).

use serde::Serialize;

use super::friction_impact::{ImpactJam, ImpactRegime, Ingredients, plastic_coulomb, rear_test};

/// The result of an impact map evaluated at the pre-impact state.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ImpactResult {
    /// The striking foot's impulse `[Lambda_t, Lambda_n]` along the floor's unit tangent
    /// (towards `+x`; down the slope) and unit normal (N s); `Lambda_t = 0` for the paper's
    /// frictionless impact.
    pub foot_impulse: [f64; 2],
    /// The rear-foot impulse of the test map with the rear foot kept on the floor
    /// (`impact3_level`'s `lambda_I[1]`, Eq. 11; `impact2_slope`'s `lambda_I[1]`, Eq. 46; with
    /// friction, [`super::friction_impact::rear_test`]): non-negative means the walker would
    /// stay in double support.
    pub rear_impulse: f64,
    /// Post-impact velocities of the old coordinates `[xd, zd, th1d, th2d]`.
    pub qd: [f64; 4],
    /// How the striking foot ends the impact.
    pub regime: ImpactRegime,
}

/// [`ImpactResult`] of the level kernels: `impact2_level` applied, `impact3_level` the test.
pub(super) fn level_impact(test: [f64; 7], applied: [f64; 6]) -> ImpactResult {
    ImpactResult {
        foot_impulse: [0.0, applied[0]],
        rear_impulse: test[1],
        qd: [applied[2], applied[3], applied[4], applied[5]],
        regime: ImpactRegime::Frictionless,
    }
}

/// [`ImpactResult`] of the slope kernels: `impact_slope` applied, `impact2_slope` the test.
/// The kernels give the foot impulses' vertical components (Eq. 42); `cos_phi` turns the
/// fore foot's back into the normal impulse.
pub(super) fn slope_impact(applied: [f64; 5], test: [f64; 6], cos_phi: f64) -> ImpactResult {
    ImpactResult {
        foot_impulse: [0.0, applied[0] / cos_phi],
        rear_impulse: test[1],
        qd: [applied[1], applied[2], applied[3], applied[4]],
        regime: ImpactRegime::Frictionless,
    }
}

/// [`ImpactResult`] of `impact_coulomb_level` / `impact_coulomb_slope` with the friction
/// coefficient `mu0`.
///
/// # Errors
/// [`ImpactJam`]: the impact with friction has no rigid-body solution.
pub(super) fn coulomb_impact(kernel: [f64; 21], mu0: f64) -> Result<ImpactResult, ImpactJam> {
    let ing = Ingredients::from_kernel(kernel);
    let (lambda, regime) = plastic_coulomb(&ing, mu0)?;
    Ok(ImpactResult {
        foot_impulse: lambda,
        rear_impulse: rear_test(&ing, mu0, lambda, regime),
        qd: ing.velocity(lambda),
        regime,
    })
}
