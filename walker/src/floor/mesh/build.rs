//! The chain of a walker on a floor ([`mesh_mfpt`]): the gait's fixed point, the box, one
//! step per mesh point and floor sample (and slope before, on a floor that sets the slope;
//! on all cores), and the transitions of the chain.

use rayon::prelude::*;

use walker_scene::{FloorPlan, FloorSpec};

use crate::model::Model;
use crate::poincare::{FixedPointOptions, Section, Status, fixed_point};
use crate::setup::Setup;
use crate::sim::{SimConfig, WalkLimits, walk};

use super::super::walker::FloorWalker;
use super::chain::Chain;
use super::error::MeshError;
use super::grid::Grid;
use super::joint::JointFloor;
use super::options::{MeshBox, MeshOptions, PILOT_STEPS, PILOT_WALKS};
use super::report::{MeshMfpt, MeshReport};
use super::samples::FloorSamples;

/// The smallest half-width of a box from the spread, relative to `1 + |centre|`: a floor that
/// never moves the walker off its fixed point (a uniform floor) still gets a box.
const MIN_RELATIVE_HALF_WIDTH: f64 = 1e-6;

/// Where one step from a mesh point on one floor value ends.
enum End {
    /// A failure of the walker.
    Fell,
    /// A state outside the box.
    Left,
    /// A state in the box, as weights on mesh points.
    Lands(Vec<(usize, f64)>),
}

/// The Markov-chain approximation of the mean first-passage time of `walker` on its floor
/// (Byl and Tedrake 2009): the section meshed around the gait's fixed point (found at the
/// floor's central values, [`FloorSamples::central`]), one step of the walker per mesh point
/// and floor sample, the end interpolated onto the mesh, absorbed on a failure or out of the
/// box.
///
/// On a floor that sets the slope the chain's floor state also carries the slope sample the
/// step before walked on (`super::joint`): a step from the mesh point `r` after a step on
/// slope `phi_j` starts from `r` on the section of `phi_j` (the strike landed there), walks on
/// the sample's slope `phi_k` (a foot sliding onto another slope is a fall, the walker's
/// [`crate::sim::FailureKind::SlopeKink`]), and lands on `(r', k)`, `r'` on the section of
/// `phi_k`. So each mesh point takes one step per slope it can start from and per floor sample.
/// The chain starts at the fixed point on the central slope; a Monte Carlo walk from the same
/// start stands on that slope before its first step (the walker's own `phi`:
/// [`start_setup`]).
///
/// # Errors
/// A setting out of range or too large ([`MeshOptions::check`], [`MeshOptions::check_sizes`]),
/// a `steps` or `patches` floor, a floor the walker cannot take, or no gait at the central
/// values.
pub fn mesh_mfpt(
    walker: &FloorWalker<'_>,
    cfg: &SimConfig,
    opts: &MeshOptions,
) -> Result<MeshReport, MeshError> {
    opts.check()?;
    let floor = joint_floor(walker.floor(), opts.samples)?;
    let (mu0_c, phi_c) = floor.central();
    // The value the gait is sought at, as the errors name it: the slope where the floor
    // sets one, else the friction coefficient.
    let (quantity, value) = match (mu0_c, phi_c) {
        (_, Some(phi)) => ("phi", phi),
        (mu0, None) => ("mu0", mu0.unwrap_or(f64::NAN)),
    };
    let central = walker.model_on(mu0_c, phi_c)?;
    let section = Section::of(&central);
    let (dim, names) = (section.dim(), section.names());
    let (values, slopes) = (floor.values(), floor.slopes());
    let sloped = floor.phi_values().is_some();
    // On a floor that sets the slope the coordinates held at the fixed point are known after
    // the pilot walks: the floor's own size is checked now, the mesh's below.
    let early = if sloped { dim } else { 0 };
    opts.check_sizes(dim, early, &names, floor.floor_states(), values * slopes)?;
    let models = (0..values)
        .map(|v| {
            let (mu0, phi) = floor.value(v);
            walker.model_on(mu0, phi)
        })
        .collect::<Result<Vec<Model>, _>>()?;
    // The model of each slope a step can start from (its section places the start): the
    // first value on that slope.
    let before: Vec<&Model> = (0..slopes).map(|j| &models[j]).collect();
    let fp =
        fixed_point(&central, cfg, &FixedPointOptions::for_model(&central)).map_err(|source| {
            MeshError::NoGait {
                quantity,
                value,
                source,
            }
        })?;
    match fp.status {
        Status::Converged | Status::Family => {}
        Status::NotConverged => {
            return Err(MeshError::NotAGait {
                quantity,
                value,
                status: "not converged",
            });
        }
        Status::InvalidGait => {
            return Err(MeshError::NotAGait {
                quantity,
                value,
                status: "not a valid gait",
            });
        }
    }
    let centre = section.reduce(&fp.state_plus);
    let (half_widths, held) = match &opts.bounds {
        MeshBox::HalfWidths(w) => (w.clone(), vec![false; dim]),
        MeshBox::Spread { scale } => {
            let d = spread(walker, cfg, &section, &centre);
            // On a floor that sets the slope, a coordinate no pilot walk moves off the fixed
            // point (the foot's velocity of a walker whose strikes stick) is held there: its
            // other points would be feet sliding by the box's width, which the chain would
            // fell at the next change of slope, and it would cost a factor N in states.
            let held = d.iter().map(|&x| sloped && x == 0.0).collect();
            let w = d
                .iter()
                .zip(&centre)
                .map(|(d, c)| (scale * d).max(MIN_RELATIVE_HALF_WIDTH * (1.0 + c.abs())))
                .collect();
            (w, held)
        }
    };
    let grid = if sloped {
        let count = held.iter().filter(|&&h| h).count();
        opts.check_sizes(dim, count, &names, floor.floor_states(), values * slopes)?;
        Grid::with_exact_centre(&centre, &half_widths, opts.points, &held)
    } else {
        Grid::new(&centre, &half_widths, opts.points)
    };
    let p = grid.len();
    // One step per (slope before, floor value, mesh point), in parallel; collected in order.
    // On a floor of friction only there is one slope before, and each step starts on its own
    // model's section, as it always did.
    let ends: Vec<(End, f64)> = (0..slopes * values * p)
        .into_par_iter()
        .map(|job| {
            let (j, v) = (job / (values * p), (job / p) % values);
            let model = &models[v];
            let from = if sloped { before[j] } else { model };
            let kink = floor
                .phi_values()
                .is_some_and(|phi| phi[j].to_bits() != phi[floor.slope_of_value(v)].to_bits());
            step(from, model, kink, cfg, &grid, grid.point(job % p))
        })
        .collect();
    let off_section = ends.iter().map(|e| e.1).fold(0.0, f64::max);
    let s = floor.floor_states();
    let mut chain = Chain {
        rows: vec![Vec::new(); s * p],
        fall: vec![0.0; s * p],
        leave: vec![0.0; s * p],
    };
    for from in 0..s {
        let j = floor.slope_of_state(from);
        for v in 0..values {
            let prob = floor.prob(from, v);
            if prob <= 0.0 {
                continue;
            }
            let to = floor.next(v) * p;
            for point in 0..p {
                let state = from * p + point;
                match &ends[(j * values + v) * p + point].0 {
                    End::Fell => chain.fall[state] += prob,
                    End::Left => chain.leave[state] += prob,
                    End::Lands(w) => {
                        chain.rows[state].extend(w.iter().map(|&(q, x)| (to + q, prob * x)))
                    }
                }
            }
        }
    }
    let at_centre = grid.weights(&centre).unwrap_or_default();
    // The walker starts at the fixed point, the friction's state drawn from its stationary
    // law, on the central slope.
    let start_law = floor.start();
    let start: Vec<(usize, f64)> = (0..s)
        .flat_map(|f| {
            let pi = start_law[f];
            at_centre.iter().map(move |&(q, w)| (f * p + q, w * pi))
        })
        // A floor state the start is not on (a slope other than the central one) is no start:
        // the chain may never reach it.
        .filter(|&(_, w)| w > 0.0)
        .collect();
    let passage = chain.passage(&start);
    let completed = |t: f64| t.is_finite().then_some(t - 1.0);
    let [_, r_lo, r_hi] = passage.inverse;
    Ok(MeshReport {
        held: names
            .iter()
            .zip(&held)
            .filter(|(_, h)| **h)
            .map(|(n, _)| n.clone())
            .collect(),
        section: names,
        centre,
        half_widths,
        points: opts.points,
        samples: floor.mu0_values().map(<[f64]>::to_vec).unwrap_or_default(),
        slopes: floor.phi_values().map(<[f64]>::to_vec),
        floor_states: floor.state_names(),
        states: s * p,
        reachable: passage.reachable,
        steps_simulated: slopes * values * p,
        off_section,
        lambda2: passage.lambda2[0],
        lambda2_bounds: [passage.lambda2[1], passage.lambda2[2]],
        mfpt: MeshMfpt {
            eigen: passage.steps.and_then(|_| completed(passage.inverse[0])),
            eigen_bounds: [completed(r_lo), completed(r_hi)],
            from_fixed_point: passage.steps.and_then(completed),
        },
        fall_share: passage.fall_share,
    })
}

/// The chain's floor of `plan` with `samples` samples per independent distribution.
///
/// # Errors
/// A `patches` floor, or a `steps` floor (of either quantity): no per-step distribution.
fn joint_floor(plan: &FloorPlan, samples: usize) -> Result<JointFloor, MeshError> {
    let part = |spec: &Option<FloorSpec>| -> Result<Option<FloorSamples>, MeshError> {
        match spec {
            None => Ok(None),
            Some(FloorSpec::Patches { .. }) => Err(MeshError::PatchesFloor),
            Some(spec) => FloorSamples::of(spec, samples)
                .map(Some)
                .ok_or(MeshError::StepsFloor),
        }
    };
    Ok(JointFloor::new(part(&plan.mu0)?, part(&plan.phi)?))
}

/// The slope a walk from the mesh's fixed point stands on before its first step: the central
/// sample of the floor's `phi` with `samples` samples (the chain's start), or `None` for a
/// floor that sets no slope or has no per-step distribution of it.
#[must_use]
pub fn start_slope(plan: &FloorPlan, samples: usize) -> Option<f64> {
    joint_floor(plan, samples).ok()?.central().1
}

/// `setup` standing on the slope the chain starts on ([`start_slope`]): its own `phi` set to
/// it, so that a walk of [`FloorWalker::walk`] from the mesh's fixed point (and the pilot
/// walks that size the box) starts where the chain does. Unchanged for a floor that sets no
/// slope, a model without one, or a slope the parameter refuses (the floor's own checks then
/// name it).
#[must_use]
pub fn start_setup(setup: &Setup, plan: &FloorPlan, samples: usize) -> Setup {
    let name = setup
        .walker
        .spec()
        .slope
        .map(|i| setup.walker.spec().model.parameters[i].name.name.clone());
    match (name, start_slope(plan, samples)) {
        (Some(name), Some(phi)) => setup.with(&name, phi).unwrap_or_else(|_| setup.clone()),
        _ => setup.clone(),
    }
}

/// One step of `model` from the mesh point `r` on the section of `from` (the model of the
/// slope the step before walked on; `model` itself on a floor of friction only): where it
/// ends, and how far its end is from the section. With `kink` (the slope changes) a sliding
/// foot is a fall.
fn step(
    from: &Model,
    model: &Model,
    kink: bool,
    cfg: &SimConfig,
    grid: &Grid,
    r: Vec<f64>,
) -> (End, f64) {
    let start = Section::of(from).embed(&r);
    let n = model.n();
    if kink && (start[n] != 0.0 || start[n + 1] != 0.0) {
        return (End::Fell, 0.0);
    }
    let section = Section::of(model);
    let limits = WalkLimits {
        max_steps: 1,
        ..WalkLimits::default()
    };
    let w = walk(model, cfg, &start, &limits);
    let Some(end) = w.last_state().filter(|_| w.failure.is_none()) else {
        return (End::Fell, 0.0);
    };
    let next = section.reduce(&end);
    let back = section.embed(&next);
    // x and z (components 0 and 1) are cyclic: the next step measures from the new foot.
    let off = (2..end.len())
        .map(|i| (end[i] - back[i]).abs())
        .fold(0.0, f64::max);
    match grid.weights(&next) {
        Some(w) => (End::Lands(w), off),
        None => (End::Left, off),
    }
}

/// The largest deviation from `centre` per coordinate of the states of the pilot walks from
/// the fixed point on the floor (their completed steps; walk `i` on the floor's stream `i`).
fn spread(
    walker: &FloorWalker<'_>,
    cfg: &SimConfig,
    section: &Section<'_>,
    centre: &[f64],
) -> Vec<f64> {
    let start = section.embed(centre);
    let limits = WalkLimits {
        max_steps: PILOT_STEPS,
        ..WalkLimits::default()
    };
    (0..PILOT_WALKS)
        .into_par_iter()
        .map(|i| {
            let mut dev = vec![0.0_f64; centre.len()];
            if let Ok(w) = walker.walk(i, cfg, &start, &limits) {
                for s in &w.steps {
                    let r = section.reduce(&s.state_plus());
                    for (d, (x, c)) in dev.iter_mut().zip(r.iter().zip(centre)) {
                        *d = d.max((x - c).abs());
                    }
                }
            }
            dev
        })
        .reduce(
            || vec![0.0; centre.len()],
            |a, b| a.iter().zip(&b).map(|(x, y)| x.max(*y)).collect(),
        )
}
