//! One step on a floor of patches by position ([`Patches`], `crate::floor`): the friction
//! coefficient is a piecewise-constant function of the position along the floor, so it can
//! change inside a stance phase, where the stance foot slides across a boundary.
//!
//! The stance is integrated in pieces, one per patch the foot stands on, by the stance's own
//! segments (`super::step::segments`) with one more guard, [`super::Guard::Boundary`]: the foot
//! reaching an end of its patch is an event located like the others. There the piece ends and
//! the next begins from the same time and state (no reset: the ground reaction jumps with
//! `mu0`), in the same contact (a sliding foot slides on; the check that a contact can begin,
//! lift-off or an inconsistent contact, is made again), with the model of the next patch. The
//! integrator's budget of attempted steps is the whole stance's, as without patches. The
//! strike uses the model of the patch under the new stance foot, which the next step stands on.
//!
//! Nothing here runs for a walk without patches: [`super::walk_by_step`] calls [`patched_step`]
//! only when [`super::StepModels::patches`] gives some.

use crate::model::{ImpactRegime, ImpactResult, Model};
use crate::ode::Integrator;
use crate::vector::Vector;

use super::config::SimConfig;
use super::failure::Failure;
use super::foot::{Foot, reaction_at_start};
use super::gait::{StepFloor, StepResult};
use super::guard::Guards;
use super::stance::Recorder;
use super::step::{Budget, Ended, Record, Strike, attempts, begin, impact, segments};

/// A floor of patches as the simulator sees it: the boundaries between regions of constant
/// friction, and a model for each region.
///
/// With boundaries `b_0 < b_1 < .. < b_{m-1}` (metres along the floor, the position `s` of a
/// point being its `x / cos phi` in the model's frame), region `0` is `s < b_0`, region `i` is
/// `b_{i-1} <= s < b_i` and region `m` is `s >= b_{m-1}`. Every model is the same walker at the
/// same parameters but `mu0`.
pub trait Patches {
    /// The boundaries, strictly increasing and finite.
    fn boundaries(&self) -> &[f64];

    /// The model of region `region` (`0..=boundaries().len()`).
    fn model(&self, region: usize) -> &Model;
}

/// The region of `patches` that holds the position `s` along the floor.
#[must_use]
pub fn region_at(patches: &dyn Patches, s: f64) -> usize {
    patches.boundaries().partition_point(|&b| b <= s)
}

/// The ends `[from, to)` of region `region` (infinite at the outer ends).
fn ends(patches: &dyn Patches, region: usize) -> [f64; 2] {
    let b = patches.boundaries();
    let from = region.checked_sub(1).map_or(f64::NEG_INFINITY, |i| b[i]);
    let to = b.get(region).copied().unwrap_or(f64::INFINITY);
    [from, to]
}

/// The new stance foot's position along the floor after a strike at the pre-impact state
/// `pre`: the relabelled coordinates' first, which the impact's velocities do not change.
fn strike_position(model: &Model, pre: &Vector) -> f64 {
    let n = model.n();
    let positions_only = ImpactResult {
        foot_impulse: [0.0, 0.0],
        rear_impulse: 0.0,
        qd: Vector::from_slice(&pre[n..2 * n]),
        regime: ImpactRegime::Frictionless,
    };
    model.reset(pre, &positions_only).q_plus[0] / model.phi().cos()
}

/// One step on the floor `patches` from the post-impact state `s0`: the stance on the patch
/// under the stance foot, going on on the next patch wherever the foot slides across a
/// boundary, and the impact on the patch under the new stance foot. The step's record carries
/// its floor: `mu0` at its start, the boundaries crossed, the `mu0` of its strike.
pub(super) fn patched_step<const S: usize>(
    patches: &dyn Patches,
    cfg: &SimConfig,
    integ: &mut Integrator<S>,
    step: usize,
    s0: &Vector,
    mut record: Record<'_>,
) -> Result<StepResult, Failure> {
    let first_model = patches.model(0);
    let cos_phi = first_model.phi().cos();
    let mut region = region_at(patches, s0[0] / cos_phi);
    let model = patches.model(region);
    let mu0 = model.mu0();
    let (foot, y0, r0, lambda_max) = begin::<S>(model, cfg, step, s0, &mut record)?;
    let Record {
        samples: mut out,
        mut frames,
        t_offset,
    } = record;
    let budget = integ.config().max_steps;
    let within = Budget {
        budget,
        first: attempts(integ.stats()),
    };
    let mut at = Strike {
        t: 0.0,
        y: y0,
        lambda_min: r0.lambda,
        stuck_time: 0.0,
        kinks: model.is_active(),
    };
    let mut contact = foot.contact();
    let mut crossings: u32 = 0;
    let ended = loop {
        let model = patches.model(region);
        let foot = Foot::new(model, contact);
        if crossings > 0
            && let Err(f) = reaction_at_start(&foot, at.t, &at.y, step)
        {
            break Err(f);
        }
        let guards = Guards::on_patch(&foot, lambda_max, ends(patches, region), cos_phi);
        let obs = Recorder {
            foot: &foot,
            out: out.as_deref_mut(),
            t_offset,
            step,
            interior: 3,
            frames: frames.as_deref_mut(),
        };
        match segments(cfg, integ, &guards, step, at, lambda_max, obs, within) {
            Ok(Ended::Boundary(here)) => {
                // The side the foot left by: the nearer end (the located point is on the far
                // side of it, or on it).
                let [from, to] = ends(patches, region);
                let s = here.y[0] / cos_phi;
                region = if s - from < to - s {
                    region.saturating_sub(1)
                } else {
                    region + 1
                };
                contact = foot.contact();
                crossings = crossings.saturating_add(1);
                at = here;
            }
            Ok(Ended::Strike(strike)) => break Ok(strike),
            Err(f) => break Err(f),
        }
    };
    integ.config_mut().max_steps = budget;
    let strike = ended?;
    let pre = super::state::mech(&strike.y);
    let landing = patches.model(region_at(patches, strike_position(model, &pre)));
    let mut result = impact(landing, step, s0, &strike)?;
    result.floor = Some(StepFloor {
        crossings: Some(crossings),
        mu0,
        mu0_strike: Some(landing.mu0()),
        phi: None,
    });
    Ok(result)
}
