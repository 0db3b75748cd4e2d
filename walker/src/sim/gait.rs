//! What a walk produces: the gait descriptors of each step ([`StepResult`], Section 4.2),
//! samples of the continuous motion ([`Sample`]) and the walk as a whole ([`Walk`]).

use serde::Serialize;

use super::failure::Failure;
use crate::model::ImpactRegime;
use crate::vector::Vector;

/// Gait descriptors of one step (Section 4.2) and the state right after the impact that ends it.
///
/// The fields are listed in the byte order of their JSON names (`SR`, `T`, `V`, `dx`, ...), the
/// order a sorted map gives them: the command line writes a walk's report straight from the
/// struct, and it reads the same as the sorted object it was before (a test holds the order).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct StepResult {
    /// Specific resistance `SR = p / (m_t g V)`; `None` for a passive walker.
    #[serde(rename = "SR")]
    pub sr: Option<f64>,
    /// Step period `T` (s).
    #[serde(rename = "T")]
    pub period: f64,
    /// Average walking speed `V = dx / T` (m/s).
    #[serde(rename = "V")]
    pub speed: f64,
    /// Step length `dx` (Eq. 34; on the slope the distance along the slope, Eq. 47) (m).
    pub dx: f64,
    /// The floor the step walked on (its stance and the strike that ends it), for a walk on a
    /// floor of its own (`crate::floor`); `None` (and left out of the JSON) otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub floor: Option<StepFloor>,
    /// The striking foot's impulse `[Lambda_t, Lambda_n]` at the heel strike that ends the
    /// step, along the floor's unit tangent (towards `+x`; down the slope) and unit normal
    /// (N s): `Lambda_t = 0` under the paper's frictionless impact; under the impact with
    /// friction `|Lambda_t| / Lambda_n` is the friction ratio the strike drew.
    pub foot_impulse: [f64; 2],
    /// The new stance foot's velocity normal to the floor right after the impact (should be 0).
    pub foot_normal_velocity: f64,
    /// How the striking foot ended the impact (left out of the JSON for the paper's
    /// frictionless impact, whose only regime it is).
    #[serde(skip_serializing_if = "ImpactRegime::is_frictionless")]
    pub impact: ImpactRegime,
    /// Smallest `lambda` seen at the start of the stance phase, at `T_set` and at the heel strike.
    pub lambda_min: f64,
    /// Average input power `p = (1/T) int |ydot u| dt` (W), to the model's `power_until`
    /// (`T_set` in the paper) or over the step; `None` for a passive walker.
    pub p: Option<f64>,
    /// Post-impact coordinates `q+` in the new stance leg's coordinates.
    pub q_plus: Vector,
    /// Post-impact velocities `qd+` in the new stance leg's coordinates.
    pub qd_plus: Vector,
    /// The rear-foot impulse of the double-support test (negative: the rear leg leaves).
    pub rear_impulse: f64,
    /// Time the stance foot spent stuck during the step (Coulomb friction; 0 otherwise) (s).
    pub stuck_time: f64,
}

/// The floor under one step of a walk on a changing floor: the friction coefficient its
/// stance foot felt and its strike used, and the slope of its floor if the floor sets it.
///
/// The fields are in the byte order of their names (the JSON is a sorted object).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct StepFloor {
    /// On a floor of patches by position: the number of patch boundaries the stance foot slid
    /// across during the step (each changes `mu0` there); `None` (left out of the JSON) on the
    /// other floors, whose `mu0` is the step's throughout.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub crossings: Option<u32>,
    /// The friction coefficient `mu0` of the step (on a floor of patches: at the step's start,
    /// under the stance foot).
    pub mu0: f64,
    /// On a floor of patches by position: the `mu0` of the patch under the new stance foot,
    /// which the strike that ends the step used; `None` (left out of the JSON) on the other
    /// floors, whose strike uses `mu0`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mu0_strike: Option<f64>,
    /// The slope angle `phi` of the step's floor (the line of that slope through its stance
    /// foot), for a floor that sets the slope (else `None`, left out of the JSON).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub phi: Option<f64>,
}

impl StepResult {
    /// The post-impact state `[q_plus, qd_plus]` (the next step's initial state).
    pub fn state_plus(&self) -> Vector {
        Vector::concat(&self.q_plus, &self.qd_plus)
    }
}

/// A sample of the continuous motion (for plots).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Sample {
    /// Time since the start of the walk (s).
    pub time: f64,
    /// Step number.
    pub step: usize,
    /// State `[q, qd]`.
    pub state: Vector,
    /// Vertical ground reaction `lambda`.
    pub lambda: f64,
    /// Control inputs `u` (none for a passive walker).
    pub u: Vector,
}

/// The result of a walk.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Walk {
    /// The completed steps, in order.
    pub steps: Vec<StepResult>,
    /// Why the walk ended early, if it did.
    pub failure: Option<Failure>,
    /// Sampled motion (empty unless asked for).
    #[serde(skip)]
    pub samples: Vec<Sample>,
    /// The walk stopped early because its gait became periodic ([`WalkLimits::periodic`](super::WalkLimits::periodic)):
    /// every later step would repeat the last one within that tolerance.
    pub periodic: bool,
}

impl Walk {
    /// A walk that failed before its first step.
    pub(super) fn failed(failure: Failure) -> Walk {
        Walk {
            steps: Vec::new(),
            failure: Some(failure),
            samples: Vec::new(),
            periodic: false,
        }
    }

    /// The post-impact state after the last completed step, if any.
    pub fn last_state(&self) -> Option<Vector> {
        self.steps.last().map(StepResult::state_plus)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Slide;

    /// A step with every optional field present, so that every key is written.
    fn full_step() -> StepResult {
        StepResult {
            sr: Some(0.3),
            period: 0.6,
            speed: 0.9,
            dx: 0.55,
            floor: Some(StepFloor {
                crossings: Some(2),
                mu0: 0.4,
                mu0_strike: Some(0.05),
                phi: Some(0.05),
            }),
            foot_impulse: [0.1, 1.2],
            foot_normal_velocity: 0.0,
            impact: ImpactRegime::Reverse(Slide::Backward),
            lambda_min: 22.0,
            p: Some(2.5),
            q_plus: Vector::from_slice(&[0.0, 0.0, 0.2, -0.1]),
            qd_plus: Vector::from_slice(&[0.1, 0.0, 1.0, 0.5]),
            rear_impulse: -0.2,
            stuck_time: 0.1,
        }
    }

    /// The command line writes a walk's steps straight from the struct and promises the keys of
    /// a sorted map (`walker_cli::report::walk_json`): a field declared out of order, or a
    /// nested object with unsorted keys, makes the two texts differ.
    #[test]
    fn a_step_serialises_with_its_keys_in_sorted_order() {
        let step = full_step();
        let direct = serde_json::to_string(&step).expect("a step serialises");
        let sorted = serde_json::to_value(step)
            .expect("a step serialises")
            .to_string();
        assert_eq!(direct, sorted);
        let plain = StepResult {
            floor: None,
            impact: ImpactRegime::Frictionless,
            ..step
        };
        let direct = serde_json::to_string(&plain).expect("a step serialises");
        assert_eq!(
            direct,
            serde_json::to_value(plain).expect("serialises").to_string()
        );
    }
}
