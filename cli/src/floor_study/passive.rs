//! The passive walkers' part of the floor study (metastable passive walking): the rimless wheel
//! and the compass gait on random slopes (uniform around a nominal slope, with growing spread)
//! and on random friction (a uniform `mu0` range reaching below the friction the gait needs),
//! the mean first-passage time by Monte Carlo and, for the wheel on slopes, by the mesh (Byl
//! and Tedrake's chain, [`walker::floor::mesh`]), and the failures by kind.
//!
//! Both walkers run under exact Coulomb friction in stance and at the strike. On the slope
//! floors `mu0 = 0.8` holds every strike, so the new stance foot is at rest and a change of
//! slope meets no sliding foot; the friction floors are walked on each model's own slope.

use rayon::prelude::*;
use walker::compiled::MODELS;
use walker::floor::mesh::{MeshOptions, mesh_mfpt, start_setup};
use walker::floor::{
    Distribution, FloorPlan, FloorSpec, FloorWalker, Survival, SurviveOutcome, survival,
};
use walker::model::{Friction, ImpactLaw};
use walker::poincare::{FixedPointOptions, fixed_point};
use walker::setup::{Setup, walker_of};
use walker::sim::{SimConfig, WalkLimits};
use walker::vector::Vector;

use super::data::Size;
use crate::reproduce::WriteError;

/// A passive walker of the study.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Walker {
    /// `models/rimless-wheel.toml`: twelve spokes, the paper's wheel without its torso.
    Wheel,
    /// `models/compass-gait.toml`: Goswami, Thuilot and Espiau's compass gait.
    Compass,
}

impl Walker {
    /// The shipped model's name.
    #[must_use]
    pub fn model(self) -> &'static str {
        match self {
            Walker::Wheel => "rimless-wheel",
            Walker::Compass => "compass-gait",
        }
    }

    /// Its name in the text.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Walker::Wheel => "rimless wheel",
            Walker::Compass => "compass gait",
        }
    }
}

/// What a case draws per step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Draw {
    /// `phi` uniform on `[nominal - spread, nominal + spread)`, `mu0 = 0.8` (every strike
    /// holds).
    Slope {
        /// The nominal slope (rad).
        nominal: f64,
        /// The half-width of the range (rad).
        spread: f64,
    },
    /// `mu0` uniform on `[lo, hi)` on the model's own slope.
    Friction {
        /// The range's lower end.
        lo: f64,
        /// Its upper end.
        hi: f64,
    },
}

/// A case of the passive study.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Case {
    /// The walker.
    pub walker: Walker,
    /// The floor's draws.
    pub draw: Draw,
    /// The floor's seed.
    pub seed: u64,
    /// Whether the mesh estimates it too (the wheel on slopes: its section is one coordinate
    /// once the foot is held, so the mesh can be fine; the compass gait's three allow no mesh
    /// fine enough to converge within the limits).
    pub mesh: bool,
}

/// The friction that holds every strike on the slope floors.
pub const HELD_MU0: f64 = 0.8;

/// The wheel's nominal slope and spreads: slopes from 0.02 rad (on which it rolls on for
/// ever) down to level ground, where it stalls.
pub const WHEEL_SLOPES: (f64, [f64; 3]) = (0.02, [0.01, 0.015, 0.02]);

/// The compass gait's nominal slope (3 degrees, its gait's) and spreads.
pub const COMPASS_SLOPES: (f64, [f64; 3]) = (0.052_359_877_559_829_89, [0.01, 0.015, 0.02]);

/// The mesh's points per coordinate, coarse to fine (the estimate is the finest; its error
/// the change from the one before), and its slope samples.
pub const MESH_POINTS: [usize; 3] = [33, 65, 129];

/// The slope samples of the mesh.
pub const MESH_SAMPLES: usize = 8;

/// The mesh that measures the samples' error: the middle mesh of [`MESH_POINTS`] with twice
/// the samples.
pub const MESH_CHECK: (usize, usize) = (65, 16);

/// How many uniform floors span a friction range (its ends included).
pub const UNIFORM_FRICTION_POINTS: usize = 8;

/// The study's cases: each walker on its three slope spreads, then on its friction range.
#[must_use]
pub fn cases() -> Vec<Case> {
    let mut out = Vec::new();
    for (walker, (nominal, spreads), seed) in [
        (Walker::Wheel, WHEEL_SLOPES, 11),
        (Walker::Compass, COMPASS_SLOPES, 21),
    ] {
        for (i, spread) in spreads.into_iter().enumerate() {
            out.push(Case {
                walker,
                draw: Draw::Slope { nominal, spread },
                seed: seed + i as u64,
                mesh: walker == Walker::Wheel,
            });
        }
    }
    out.push(Case {
        walker: Walker::Wheel,
        draw: Draw::Friction { lo: 0.05, hi: 0.5 },
        seed: 31,
        mesh: false,
    });
    out.push(Case {
        walker: Walker::Compass,
        draw: Draw::Friction { lo: 0.22, hi: 0.6 },
        seed: 32,
        mesh: false,
    });
    out
}

impl Case {
    /// The floor.
    #[must_use]
    pub fn plan(&self) -> FloorPlan {
        match self.draw {
            Draw::Slope { nominal, spread } => FloorPlan {
                mu0: None,
                phi: Some(FloorSpec::Random {
                    seed: self.seed,
                    mu0: Distribution::Uniform {
                        lo: nominal - spread,
                        hi: nominal + spread,
                    },
                }),
            },
            Draw::Friction { lo, hi } => FloorPlan {
                mu0: Some(FloorSpec::Random {
                    seed: self.seed,
                    mu0: Distribution::Uniform { lo, hi },
                }),
                phi: None,
            },
        }
    }

    /// The case's name in the files (`rimless-wheel slope 0.02 +- 0.01`).
    #[must_use]
    pub fn name(&self) -> String {
        match self.draw {
            Draw::Slope { nominal, spread } => {
                format!("{} slope {nominal:.4} +- {spread}", self.walker.model())
            }
            Draw::Friction { lo, hi } => format!("{} mu0 [{lo}, {hi})", self.walker.model()),
        }
    }

    /// The walker under exact Coulomb friction in stance and at the strike, with `mu0 = 0.8`
    /// on a slope floor.
    ///
    /// # Errors
    /// The model is not compiled in or does not load (a defect of the shipped files).
    pub fn setup(&self) -> Result<Setup, WriteError> {
        let name = self.walker.model();
        let err = |e: &dyn std::fmt::Display| WriteError::Setup(format!("{name}: {e}"));
        let c = MODELS
            .iter()
            .find(|c| c.name == name)
            .ok_or_else(|| err(&"not a compiled model"))?;
        let file = walker_scene::model::Model::from_toml(c.source, &format!("models/{name}.toml"))
            .map_err(|e| err(&e))?;
        let mut setup = Setup::of(walker_of(file, None).map_err(|e| err(&e))?);
        setup.friction = Friction::Coulomb;
        setup.impact = ImpactLaw::Coulomb;
        if let Draw::Slope { .. } = self.draw {
            setup.set("mu0", HELD_MU0).map_err(|e| err(&e))?;
        }
        Ok(setup)
    }
}

/// The passive study's size: [`Size`]'s walks and step limit, each times ten (a passive step
/// costs a tenth of the active walker's, and the estimates need the failures).
#[must_use]
pub fn passive_size(size: Size) -> Size {
    Size {
        walks: 10 * size.walks,
        max_steps: 10 * size.max_steps,
    }
}

/// The mesh's estimate of one case at one mesh size.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshPoint {
    /// Points per coordinate.
    pub points: usize,
    /// Slope samples.
    pub samples: usize,
    /// The reachable states.
    pub reachable: usize,
    /// The MFPT from the fixed point (steps before a failure; `None`: infinite).
    pub from_fixed_point: Option<f64>,
    /// The MFPT from the second eigenvalue.
    pub eigen: Option<f64>,
}

/// One case's results.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// The case.
    pub case: Case,
    /// The Monte Carlo walks' statistics.
    pub survival: Survival,
    /// The mesh at [`MESH_POINTS`], coarse to fine, then at [`MESH_CHECK`] (empty where the
    /// mesh is not computed).
    pub mesh: Vec<MeshPoint>,
    /// For a friction case, `(mu0, steps, failure)` of one walk on each uniform floor spanning
    /// the range, `mu0` rising.
    pub uniform: Vec<(f64, usize, Option<String>)>,
}

impl Outcome {
    /// The mesh at `points` and `samples`, if computed.
    #[must_use]
    pub fn mesh_at(&self, points: usize, samples: usize) -> Option<&MeshPoint> {
        self.mesh
            .iter()
            .find(|m| m.points == points && m.samples == samples)
    }

    /// The mesh's MFPT from the fixed point at each of [`MESH_POINTS`] (with
    /// [`MESH_SAMPLES`]), coarse to fine; `None` where infinite or not computed.
    #[must_use]
    pub fn refinements(&self) -> Vec<Option<f64>> {
        MESH_POINTS
            .iter()
            .map(|&n| self.mesh_at(n, MESH_SAMPLES)?.from_fixed_point)
            .collect()
    }

    /// The mesh's estimate (the finest mesh's MFPT from the fixed point) and its error: its
    /// change from the mesh before plus the change that twice the samples make
    /// ([`MESH_CHECK`]), as for the friction floors' test of the mesh. `None` if not computed
    /// or infinite.
    #[must_use]
    pub fn mesh_estimate(&self) -> Option<(f64, f64)> {
        let t = self.refinements();
        let fine = (*t.last()?)?;
        let before = t.get(t.len().checked_sub(2)?).copied().flatten()?;
        let (n, m) = MESH_CHECK;
        let at = self.mesh_at(n, MESH_SAMPLES)?.from_fixed_point?;
        let more = self.mesh_at(n, m)?.from_fixed_point?;
        Some((fine, (fine - before).abs() + (more - at).abs()))
    }

    /// The smallest `mu0` of the uniform floors from which the walker completes the step limit
    /// on every higher one: the friction the gait needs, to the spacing of the floors.
    #[must_use]
    pub fn needed_mu0(&self) -> Option<f64> {
        let mut needed = None;
        for (mu0, _, failure) in self.uniform.iter().rev() {
            if failure.is_some() {
                break;
            }
            needed = Some(*mu0);
        }
        needed
    }
}

/// The `n` values from `lo` to `hi`, both included.
fn span(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64)
        .collect()
}

/// Walks and meshes every case of the passive study at `size` (the study's size: the
/// passive walks are [`passive_size`]).
///
/// # Errors
/// A setup, a floor or a mesh that the library refuses (a defect of the study's constants).
pub fn collect(size: Size) -> Result<Vec<Outcome>, WriteError> {
    let size = passive_size(size);
    let cfg = SimConfig::default();
    let setup_err = |e: &dyn std::fmt::Display| WriteError::Setup(e.to_string());
    cases()
        .into_iter()
        .map(|case| {
            let plan = case.plan();
            // The walker stands on the slope the chain starts on (the floor's central slope
            // sample) and starts at its gait there; a friction case at the model's start.
            let setup = start_setup(&case.setup()?, &plan, MESH_SAMPLES);
            let walker = FloorWalker::new(&setup, plan.clone()).map_err(|e| setup_err(&e))?;
            let model = setup.model().map_err(|e| setup_err(&e))?;
            let mut mesh = Vec::new();
            if case.mesh {
                let sizes = MESH_POINTS.iter().map(|&n| (n, MESH_SAMPLES));
                for (points, samples) in sizes.chain([MESH_CHECK]) {
                    let opts = MeshOptions {
                        points,
                        samples,
                        ..MeshOptions::default()
                    };
                    let r = mesh_mfpt(&walker, &cfg, &opts).map_err(|e| setup_err(&e))?;
                    mesh.push(MeshPoint {
                        points,
                        samples,
                        reachable: r.reachable,
                        from_fixed_point: r.mfpt.from_fixed_point,
                        eigen: r.mfpt.eigen,
                    });
                }
            }
            let start: Vector = match case.draw {
                // The gait on the central slope: the mesh's fixed point.
                Draw::Slope { .. } => {
                    fixed_point(&model, &cfg, &FixedPointOptions::for_model(&model))
                        .map_err(|e| setup_err(&e))?
                        .state_plus
                }
                Draw::Friction { .. } => model.start_state(),
            };
            let outcomes: Vec<SurviveOutcome> = (0..size.walks as u64)
                .into_par_iter()
                .map(|i| {
                    let limits = WalkLimits {
                        max_steps: size.max_steps,
                        ..WalkLimits::default()
                    };
                    let w = walker
                        .walk(i, &cfg, &start, &limits)
                        .map_err(|e| setup_err(&e))?;
                    Ok(SurviveOutcome {
                        walk: i,
                        steps: w.steps.len(),
                        failure: w.failure.as_ref().map(|f| f.name().to_owned()),
                    })
                })
                .collect::<Result<_, WriteError>>()?;
            let uniform = match case.draw {
                Draw::Friction { lo, hi } => span(lo, hi, UNIFORM_FRICTION_POINTS)
                    .into_par_iter()
                    .map(|mu0| {
                        let at = setup.with("mu0", mu0).map_err(|e| setup_err(&e))?;
                        let m = at.model().map_err(|e| setup_err(&e))?;
                        let limits = WalkLimits {
                            max_steps: size.max_steps,
                            ..WalkLimits::default()
                        };
                        let w = walker::sim::walk(&m, &cfg, &m.start_state(), &limits);
                        Ok((
                            mu0,
                            w.steps.len(),
                            w.failure.as_ref().map(|f| f.name().to_owned()),
                        ))
                    })
                    .collect::<Result<_, WriteError>>()?,
                Draw::Slope { .. } => Vec::new(),
            };
            Ok(Outcome {
                case,
                survival: survival(&outcomes),
                mesh,
                uniform,
            })
        })
        .collect()
}
