//! One design point: the periodic gait at given parameter values and the quantities the
//! objective and the constraints read from it.

use serde::Serialize;

use crate::poincare::{
    FixedPoint, FixedPointOptions, Section, Status, StepCheck, fixed_point, newton,
};
use crate::setup::Setup;
use crate::sim::{Frame, SimConfig, WalkLimits, trajectory};

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
    /// `|lambda_t| / lambda_n` at `t = k T / SAMPLES`, `k = 0 .. SAMPLES - 1`, then at the
    /// stance's end just before the strike (`END`) (the design's path constraints, one per
    /// sample); left out of the JSON.
    #[serde(skip)]
    pub stance_ratios: Vec<f64>,
    /// The heel strike's impulse ratio `|Lambda_t| / Lambda_n`.
    pub impact_friction: f64,
    /// The smallest normal force on the stance's samples (N).
    pub min_normal: f64,
    /// Whether the stance foot stayed stuck on every sample (Coulomb friction; always false
    /// under a smooth law, whose foot always creeps).
    pub held: bool,
    /// The end of the desired trajectories' last ramp (the paper's `T_set`), which the strike
    /// must come after; `None` (and left out of the JSON) for a model without ramps.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ramps_end: Option<f64>,
    /// The largest `|u_i|` on the stance's samples, per input (empty for a passive walker);
    /// with `ramp_inputs` also just before each ramp's end.
    pub max_input: Vec<f64>,
    /// `|u_i|` at `t = k T / SAMPLES` per input `i` and at the stance's end (the input bounds'
    /// samples), and with `ramp_inputs` just before each ramp's end; left out of the JSON.
    #[serde(skip)]
    pub input_samples: Vec<Vec<f64>>,
    /// The swing foot's clearance: the largest `H` whose profile `H 4 s (1 - s)` its height
    /// above the floor meets at every interior stance sample (`min h_k / (4 s_k (1 - s_k))`,
    /// m; [`super::swing_height`]); `None` (and left out of the JSON) unless the design bounds it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub clearance: Option<f64>,
    /// The swing foot's height above the floor and the profile's value `4 s (1 - s)` at the
    /// interior stance samples `t = k T / SAMPLES`, `k = 1 .. SAMPLES - 1` (empty unless the
    /// design bounds the clearance); left out of the JSON.
    #[serde(skip)]
    pub swing_heights: Vec<(f64, f64)>,
    /// The number of stance samples read (the grid's and the stance's end).
    pub samples: usize,
}

impl Evaluation {
    /// The friction the gait needs: the larger of the stance's and the strike's ratio.
    #[must_use]
    pub fn required_friction(&self) -> f64 {
        self.stance_friction.max(self.impact_friction)
    }
}

/// Where the stance's last sample is read: at `T (1 - END)`, just before the strike. The
/// friction ratio can peak within the last `T / SAMPLES` of the stance, after the grid's last
/// sample: RABBIT's did, and a gait whose samples all met a friction bound slipped 9
/// microseconds before its strike on a floor of that friction (`docs/design.md`). `1e-9` of the period rather than the period itself:
/// the fixed point's `T` and the sampled step's strike may differ by the integrations'
/// rounding, and the sample must fall inside the stance.
pub const END: f64 = 1e-9;

/// The periodic gait of `setup` with `names` set to `values`: Newton's method on the reduced
/// map from `guess` (section coordinates) where given and converging, else the fixed-point
/// search of `walker fixed-point` from the model's start; then one step from the fixed point
/// sampled `SAMPLES` (400) times on the dense output. With `ramp_inputs`, the inputs are also
/// read just before each ramp's end inside the step (`inputs_before_ramp_ends`): where a
/// ramp's second derivative does not vanish at its end (a Bezier's, unlike the paper's
/// quintic) the input jumps there, and its largest value is the left limit, which samples on a
/// grid miss. With `swing`, the swing foot's height is read on the interior samples
/// ([`Evaluation::clearance`]).
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
    ramp_inputs: bool,
    swing: bool,
) -> Result<Evaluation, String> {
    let mut s = setup.clone();
    for (n, v) in names.iter().zip(values) {
        s.set(n, *v).map_err(|e| e.to_string())?;
    }
    let model = s.model().map_err(|e| e.to_string())?;
    // An iterate whose step fails is no gait: its maps fail with the simulator's step.
    let opts = FixedPointOptions {
        step_check: StepCheck::Walk,
        ..FixedPointOptions::for_model(&model)
    };
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
    let limits = one_step();
    let dt = fp.period / SAMPLES as f64;
    let tr = trajectory(&model, cfg, &fp.state_plus, &limits, dt, SAMPLES + 8);
    let step = match (&tr.walk.failure, tr.walk.steps.first()) {
        (None, Some(step)) => *step,
        (Some(f), _) => return Err(format!("the step fails: {:?} at t = {}", f.kind, f.t)),
        (None, None) => return Err("the step did not complete".to_owned()),
    };
    let ratio = |t: f64, n: f64| if n > 0.0 { t.abs() / n } else { f64::INFINITY };
    let frames: Vec<_> = tr.frames.iter().filter(|f| f.step == 0).collect();
    let end = end_of_stance(&model, cfg, &fp.state_plus, fp.period)
        .ok_or_else(|| "the stance's end could not be sampled before the strike".to_owned())?;
    // The sample at `k T / SAMPLES` for each k (a frame the step ended before, at most the last
    // one or two by rounding of `k dt` against `T`, repeats the last frame), then the end.
    let samples: Vec<&Frame> = (0..SAMPLES)
        .filter_map(|k| frames.get(k).or(frames.last()).copied())
        .chain(std::iter::once(&end))
        .collect();
    let stance_ratios: Vec<f64> = samples
        .iter()
        .map(|f| ratio(f.reaction.tangential, f.reaction.normal))
        .collect();
    let stance_friction = stance_ratios.iter().copied().fold(0.0, f64::max);
    let min_normal = frames
        .iter()
        .chain(std::iter::once(&&end))
        .map(|f| f.reaction.normal)
        .fold(f64::INFINITY, f64::min);
    let held = frames
        .iter()
        .chain(std::iter::once(&&end))
        .all(|f| f.contact == crate::model::Contact::Stuck);
    let mut input_samples: Vec<Vec<f64>> = (0..model.inputs())
        .map(|i| {
            samples
                .iter()
                .map(|f| f.u.as_slice().get(i).map_or(f64::INFINITY, |u| u.abs()))
                .collect()
        })
        .collect();
    if ramp_inputs {
        for u in inputs_before_ramp_ends(&model, cfg, &fp.state_plus, fp.period) {
            for (samples, ui) in input_samples.iter_mut().zip(u.as_slice()) {
                samples.push(ui.abs());
            }
        }
    }
    let max_input = input_samples
        .iter()
        .map(|v| v.iter().copied().fold(0.0, f64::max))
        .collect();
    // The swing foot's height at the interior samples (`0 < t < T`: the profile is positive
    // there), each with the profile's value at its own time.
    let swing_heights: Vec<(f64, f64)> = if swing {
        frames
            .iter()
            .take(SAMPLES)
            .skip(1)
            .filter(|f| f.t > 0.0 && f.t < fp.period)
            .map(|f| {
                let q = &f.state.as_slice()[..model.n()];
                (
                    super::swing::swing_height(&model, q),
                    super::swing::clearance_profile(f.t / fp.period),
                )
            })
            .collect()
    } else {
        Vec::new()
    };
    let clearance = swing.then(|| {
        swing_heights
            .iter()
            .map(|(h, w)| h / w)
            .fold(f64::INFINITY, f64::min)
    });
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
        ramps_end: model.ramps_end(),
        max_input,
        input_samples,
        clearance,
        swing_heights,
        samples: frames.len() + 1,
    })
}

/// The limits of a walk of one step.
fn one_step() -> WalkLimits {
    WalkLimits {
        max_steps: 1,
        ..WalkLimits::default()
    }
}

/// The stance's last sample, at `T (1 - END)` (`END`), from the dense output of the step from
/// `start` of period `period`; `None` if the strike came before it.
fn end_of_stance(
    model: &crate::model::Model,
    cfg: &SimConfig,
    start: &[f64],
    period: f64,
) -> Option<Frame> {
    let limits = one_step();
    let tr = trajectory(model, cfg, start, &limits, period * (1.0 - END), 2);
    tr.frames.into_iter().nth(1).filter(|f| f.step == 0)
}

/// The inputs just before each end of a ramp inside the step from `start` (of period `period`):
/// the state at the ramp's end `t_e` from the dense output of the integration up to it (the
/// end is a breakpoint of the integrator), and the input of the ramp's own branch there, at
/// the largest time below `t_e` (the left limit; from `t_e` on the trajectory is held).
fn inputs_before_ramp_ends(
    model: &crate::model::Model,
    cfg: &SimConfig,
    start: &[f64],
    period: f64,
) -> Vec<crate::vector::Vector> {
    let limits = one_step();
    let mut out = Vec::new();
    let mut t = 0.0;
    while let Some(end) = model.next_breakpoint(t).filter(|&e| e < period) {
        let tr = trajectory(model, cfg, start, &limits, end, 2);
        if let Some(f) = tr.frames.get(1).filter(|f| f.step == 0) {
            out.push(model.control_input(end.next_down(), f.state.as_slice(), f.contact));
        }
        t = end;
    }
    out
}
