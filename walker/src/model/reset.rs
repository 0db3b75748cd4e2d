//! The change of stance leg at an impact: the relabelling of the post-impact state to the new
//! stance leg, measured from the new stance foot (Eqs. 18, 45 corrected).

use serde::Serialize;

use super::dispatch::Model;
use super::friction_impact::ImpactRegime;
use super::impact::ImpactResult;
use super::kind::Kind;

/// The state right after an impact in the new stance leg's coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PostImpact {
    /// `q+ = [x_f, z+, th1 - alpha, th2]`: the fore foot's position `x_f` (Eqs. 3, 39), `z+ = 0`
    /// on level ground and the fore foot's `z_f` on the slope, the new stance-leg angle and the
    /// torso angle.
    pub q_plus: [f64; 4],
    /// `qd+ = [xd_f, zd_f, th1d, th2d]`: the fore foot's velocity and the post-impact angular
    /// velocities.
    pub qd_plus: [f64; 4],
    /// The new stance foot's velocity normal to the floor (`zd_f` on level ground,
    /// `zd_f + xd_f tan phi` on the slope; zero for an exact impact).
    pub foot_normal_velocity: f64,
}

impl Model {
    /// The relabelling after an impact at the pre-impact state
    /// `pre = [x, z, th1, th2, xd, zd, th1d, th2d]` whose impact map gave `imp` (its velocities
    /// `qd = [xd, zd, th1d, th2d]` are of the old coordinates): the fore foot (kernel
    /// `fore_foot` at the pre-impact position and the post-impact velocity) becomes the stance
    /// foot. After a sticking impact ([`ImpactRegime::Stick`]) the new foot is at rest, so its
    /// velocity is set to exactly zero (the kernels give it to rounding, and exact Coulomb
    /// friction tells a stuck foot from a sliding one by `xd = 0`).
    pub fn reset(&self, pre: &[f64; 8], imp: &ImpactResult) -> PostImpact {
        let [x, z, th1, th2, ..] = *pre;
        let [xd, zd, th1d, th2d] = imp.qd;
        let [xf, zf, mut xdf, mut zdf] = self.fore_foot(x, z, th1, xd, zd, th1d);
        if imp.regime == ImpactRegime::Stick {
            (xdf, zdf) = (0.0, 0.0);
        }
        let (z_plus, foot_normal_velocity) = match self.kind() {
            Kind::ActiveLevel => (0.0, zdf),
            Kind::PassiveSlope => (zf, zdf + xdf * self.runtime.phi.tan()),
        };
        PostImpact {
            q_plus: [xf, z_plus, th1 - self.physical.alpha, th2],
            qd_plus: [xdf, zdf, th1d, th2d],
            foot_normal_velocity,
        }
    }
}
