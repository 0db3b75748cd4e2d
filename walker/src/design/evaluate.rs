//! One design point: the periodic gait at given parameter values and the quantities the
//! objective and the constraints read from it.

use serde::Serialize;

use crate::poincare::{FixedPoint, FixedPointOptions, Section, Status, fixed_point, newton};
use crate::setup::Setup;
use crate::sim::{SimConfig, WalkLimits, trajectory};

/// Samples of the stance per step on which the path constraints are read (the integrator's
/// dense output at `T / SAMPLES` apart, each inside the accepted step that contains it).
pub const SAMPLES: usize = 400;

/// The periodic gait at one set of parameter values and what the design reads from it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Evaluation {
    /// The fixed point and its multipliers.
    pub fixed_point: FixedPoint,
    /// The fixed point in the section's independent coordinates (Newton's unknowns).
    pub reduced: Vec<f64>,
    /// Mean input power `p` of the step from the fixed point (W; 0 for a passive walker).
    pub power: f64,
    /// Specific resistance of that step (0 for a passive walker).
    pub specific_resistance: f64,
    /// The largest `|lambda_t| / lambda_n` on the stance's samples (infinite where the normal
    /// force is not positive).
    pub stance_friction: f64,
    /// `|lambda_t| / lambda_n` at `t = k T / SAMPLES`, `k = 0 .. SAMPLES - 1` (the design's
    /// path constraints, one per sample); left out of the JSON.
    #[serde(skip)]
    pub stance_ratios: Vec<f64>,
    /// The heel strike's impulse ratio `|Lambda_t| / Lambda_n`.
    pub impact_friction: f64,
    /// The smallest normal force on the stance's samples (N).
    pub min_normal: f64,
    /// Whether the stance foot stayed stuck on every sample (Coulomb friction; always false
    /// under a smooth law, whose foot always creeps).
    pub held: bool,
    /// The number of stance samples read.
    pub samples: usize,
}

impl Evaluation {
    /// The friction the gait needs: the larger of the stance's and the strike's ratio.
    #[must_use]
    pub fn required_friction(&self) -> f64 {
        self.stance_friction.max(self.impact_friction)
    }
}

/// The periodic gait of `setup` with `names` set to `values`: Newton's method on the reduced
/// map from `guess` (section coordinates) where given and converging, else the fixed-point
/// search of `walker fixed-point` from the model's start; then one step from the fixed point
/// sampled `SAMPLES` (400) times on the dense output.
///
/// # Errors
/// A text saying why there is no valid periodic gait there (a parameter out of range, no
/// convergence, an invalid gait, a failure of the step).
pub fn evaluate(
    setup: &Setup,
    cfg: &SimConfig,
    names: &[&str],
    values: &[f64],
    guess: Option<&[f64]>,
) -> Result<Evaluation, String> {
    let mut s = setup.clone();
    for (n, v) in names.iter().zip(values) {
        s.set(n, *v).map_err(|e| e.to_string())?;
    }
    let model = s.model().map_err(|e| e.to_string())?;
    let opts = FixedPointOptions::for_model(&model);
    let ok = |fp: &FixedPoint| fp.status == Status::Converged;
    let from_guess = guess.and_then(|r| newton(&model, cfg, r, &opts).ok().filter(ok));
    let fp = match from_guess {
        Some(fp) => fp,
        None => fixed_point(&model, cfg, &opts).map_err(|e| e.to_string())?,
    };
    if !ok(&fp) {
        return Err(match &fp.failure {
            Some(f) => format!("the cycle is not a valid gait: {:?} at t = {}", f.kind, f.t),
            None => format!(
                "Newton's method did not converge (residual {:.3e})",
                fp.residual
            ),
        });
    }
    let limits = WalkLimits {
        max_steps: 1,
        ..WalkLimits::default()
    };
    let dt = fp.period / SAMPLES as f64;
    let tr = trajectory(&model, cfg, &fp.state_plus, &limits, dt, SAMPLES + 8);
    let step = match (&tr.walk.failure, tr.walk.steps.first()) {
        (None, Some(step)) => *step,
        (Some(f), _) => return Err(format!("the step fails: {:?} at t = {}", f.kind, f.t)),
        (None, None) => return Err("the step did not complete".to_owned()),
    };
    let ratio = |t: f64, n: f64| if n > 0.0 { t.abs() / n } else { f64::INFINITY };
    let frames: Vec<_> = tr.frames.iter().filter(|f| f.step == 0).collect();
    // The ratio at `k T / SAMPLES` for each k (a frame the step ended before, at most the last
    // one or two by rounding of `k dt` against `T`, repeats the last frame).
    let stance_ratios: Vec<f64> = (0..SAMPLES)
        .map(|k| {
            frames.get(k).or(frames.last()).map_or(f64::INFINITY, |f| {
                ratio(f.reaction.tangential, f.reaction.normal)
            })
        })
        .collect();
    let stance_friction = stance_ratios.iter().copied().fold(0.0, f64::max);
    let min_normal = frames
        .iter()
        .map(|f| f.reaction.normal)
        .fold(f64::INFINITY, f64::min);
    let held = frames
        .iter()
        .all(|f| f.contact == crate::model::Contact::Stuck);
    let [lt, ln] = step.foot_impulse;
    let reduced = Section::of(&model).reduce(&fp.state_plus);
    Ok(Evaluation {
        fixed_point: fp,
        reduced,
        power: step.p.unwrap_or(0.0),
        specific_resistance: step.sr.unwrap_or(0.0),
        stance_friction,
        stance_ratios,
        impact_friction: ratio(lt, ln),
        min_normal,
        held,
        samples: frames.len(),
    })
}
