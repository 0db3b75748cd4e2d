//! The chain of a walker on a floor ([`mesh_mfpt`]): the gait's fixed point, the box, one
//! step per mesh point and floor sample (on all cores), and the transitions of the chain.

use rayon::prelude::*;

use crate::model::Model;
use crate::poincare::{FixedPointOptions, Section, Status, fixed_point};
use crate::sim::{SimConfig, WalkLimits, walk};

use super::super::walker::FloorWalker;
use super::chain::Chain;
use super::error::MeshError;
use super::grid::Grid;
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
/// floor's central value, [`FloorSamples::central`]), one step of the walker per mesh point
/// and floor sample, the end interpolated onto the mesh, absorbed on a failure or out of the
/// box.
///
/// # Errors
/// A setting out of range or too large ([`MeshOptions::check`], [`MeshOptions::check_sizes`]),
/// a `steps` floor, a floor that sets the slope, a floor the walker cannot take, or no gait at
/// the central value.
pub fn mesh_mfpt(
    walker: &FloorWalker<'_>,
    cfg: &SimConfig,
    opts: &MeshOptions,
) -> Result<MeshReport, MeshError> {
    opts.check()?;
    let floor = walker.floor();
    let Some(friction) = floor.mu0.as_ref().filter(|_| floor.phi.is_none()) else {
        return Err(MeshError::SlopeFloor);
    };
    if matches!(friction, walker_scene::FloorSpec::Patches { .. }) {
        return Err(MeshError::PatchesFloor);
    }
    let samples = FloorSamples::of(friction, opts.samples).ok_or(MeshError::StepsFloor)?;
    let mu0 = samples.central();
    let central = walker.model_at(mu0)?;
    let section = Section::of(&central);
    let (dim, names) = (section.dim(), section.names());
    opts.check_sizes(dim, &names, samples.floor_states(), samples.values.len())?;
    let models = samples
        .values
        .iter()
        .map(|&v| walker.model_at(v))
        .collect::<Result<Vec<Model>, _>>()?;
    let fp = fixed_point(&central, cfg, &FixedPointOptions::for_model(&central))
        .map_err(|source| MeshError::NoGait { mu0, source })?;
    match fp.status {
        Status::Converged | Status::Family => {}
        Status::NotConverged => {
            return Err(MeshError::NotAGait {
                mu0,
                status: "not converged",
            });
        }
        Status::InvalidGait => {
            return Err(MeshError::NotAGait {
                mu0,
                status: "not a valid gait",
            });
        }
    }
    let centre = section.reduce(&fp.state_plus);
    let half_widths = match &opts.bounds {
        MeshBox::HalfWidths(w) => w.clone(),
        MeshBox::Spread { scale } => spread(walker, cfg, &section, &centre)
            .iter()
            .zip(&centre)
            .map(|(d, c)| (scale * d).max(MIN_RELATIVE_HALF_WIDTH * (1.0 + c.abs())))
            .collect(),
    };
    let grid = Grid::new(&centre, &half_widths, opts.points);
    let p = grid.len();
    // One step per (floor value, mesh point), in parallel; collected in order.
    let ends: Vec<(End, f64)> = (0..samples.values.len() * p)
        .into_par_iter()
        .map(|job| step(&models[job / p], cfg, &grid, grid.point(job % p)))
        .collect();
    let off_section = ends.iter().map(|e| e.1).fold(0.0, f64::max);
    let s = samples.floor_states();
    let mut chain = Chain {
        rows: vec![Vec::new(); s * p],
        fall: vec![0.0; s * p],
        leave: vec![0.0; s * p],
    };
    for from in 0..s {
        for (j, &prob) in samples.prob[from].iter().enumerate() {
            if prob <= 0.0 {
                continue;
            }
            let to = samples.next[j] * p;
            for point in 0..p {
                let state = from * p + point;
                match &ends[j * p + point].0 {
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
    // The walker starts at the fixed point, the floor's state drawn from its stationary law.
    let start: Vec<(usize, f64)> = (0..s)
        .flat_map(|f| {
            let pi = samples.start[f];
            at_centre.iter().map(move |&(q, w)| (f * p + q, w * pi))
        })
        .collect();
    let passage = chain.passage(&start);
    let completed = |t: f64| t.is_finite().then_some(t - 1.0);
    let [_, r_lo, r_hi] = passage.inverse;
    Ok(MeshReport {
        section: names,
        centre,
        half_widths,
        points: opts.points,
        samples: samples.values.clone(),
        floor_states: samples.states.iter().map(|&n| n.to_owned()).collect(),
        states: s * p,
        reachable: passage.reachable,
        steps_simulated: samples.values.len() * p,
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

/// One step of `model` from the mesh point `r`: where it ends, and how far its end is from
/// the section.
fn step(model: &Model, cfg: &SimConfig, grid: &Grid, r: Vec<f64>) -> (End, f64) {
    let section = Section::of(model);
    let limits = WalkLimits {
        max_steps: 1,
        ..WalkLimits::default()
    };
    let w = walk(model, cfg, &section.embed(&r), &limits);
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
