//! The study's walks and their statistics. Every walk of the study (the random floors' seeded
//! walks, the uniform floors, the ice patches) is one task of one parallel loop (rayon), and
//! the results are collected in task order, so that they do not depend on the number of
//! threads.

use rayon::prelude::*;
use walker::floor::{FloorSpec, FloorWalker, Survival, SurviveOutcome, survival};
use walker::setup::Setup;
use walker::sim::{SimConfig, WalkLimits};
use walker::vector::Vector;

use super::cases::{FLOORS, LAWS, Law, PATCH, T_SETS, UNIFORM_POINTS};
use crate::progress::Progress;
use crate::reproduce::WriteError;

/// How many walks and how long.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Size {
    /// Seeded walks per random floor, law and `T_set`.
    pub walks: usize,
    /// The step limit of a walk on a random or a uniform floor.
    pub max_steps: usize,
}

/// The most seeded walks per law, floor and `T_set`.
pub const MAX_WALKS: usize = 2000;

/// The longest step limit.
pub const MAX_STEPS: usize = 10_000;

/// The study's size from the flags `--walks` and `--max-steps`.
///
/// # Errors
/// A count that is not a whole number in its range (named by its flag).
pub fn size_of(walks: &str, max_steps: &str) -> Result<Size, crate::input::InputError> {
    use walker::request::{Field, count_text};
    Ok(Size {
        walks: count_text(Field::Walks, walks, 1, MAX_WALKS)?,
        max_steps: count_text(Field::MaxSteps, max_steps, 1, MAX_STEPS)?,
    })
}

/// How one walk ended.
#[derive(Clone, Debug, PartialEq)]
pub struct End {
    /// The steps it completed.
    pub steps: usize,
    /// The distance it walked (m): the sum of its steps' lengths `dx`.
    pub distance: f64,
    /// Its failure's name, or `None` at the step limit.
    pub failure: Option<String>,
}

/// The walks of one law and `T_set` on one random floor.
#[derive(Clone, Debug)]
pub struct Survey {
    /// The law's index in [`LAWS`].
    pub law: usize,
    /// The floor's index in [`FLOORS`].
    pub floor: usize,
    /// `T_set` (s).
    pub t_set: f64,
    /// Each walk's end, in walk order.
    pub ends: Vec<End>,
    /// Their survival statistics.
    pub survival: Survival,
}

impl Survey {
    /// The mean distance walked (m), a fallen walk counting to its fall.
    #[must_use]
    pub fn mean_distance(&self) -> f64 {
        self.ends.iter().map(|e| e.distance).sum::<f64>() / self.ends.len().max(1) as f64
    }
}

/// One law's and `T_set`'s walks on uniform floors spanning a random floor's range.
#[derive(Clone, Debug)]
pub struct Uniform {
    /// The law's index.
    pub law: usize,
    /// The random floor's index.
    pub floor: usize,
    /// `T_set` (s).
    pub t_set: f64,
    /// `(mu0, end)` for each uniform floor, `mu0` rising.
    pub walks: Vec<(f64, End)>,
    /// The walk on the uniform floor at the random floor's mean `mu0`.
    pub at_mean: End,
}

impl Uniform {
    /// Whether the walker completes every walk on the uniform floors.
    #[must_use]
    pub fn walks_everywhere(&self) -> bool {
        self.walks.iter().all(|(_, e)| e.failure.is_none())
    }
}

/// One law's and `T_set`'s walks across ice patches of `0..=PATCH.longest` steps.
#[derive(Clone, Debug)]
pub struct Crossing {
    /// The law's index.
    pub law: usize,
    /// `T_set` (s).
    pub t_set: f64,
    /// The end of the walk across each patch length `k`, in `k` order.
    pub ends: Vec<End>,
}

impl Crossing {
    /// Whether the walk across `k` icy steps crossed (completed every step after it).
    #[must_use]
    pub fn crossed(&self, k: usize) -> bool {
        self.ends.get(k).is_some_and(|e| e.failure.is_none())
    }

    /// The longest patch crossed with every shorter one crossed too; `None` if the walker
    /// does not even walk the dry floor (`k = 0`).
    #[must_use]
    pub fn longest(&self) -> Option<usize> {
        (0..self.ends.len()).take_while(|&k| self.crossed(k)).last()
    }
}

/// Everything the study walked.
#[derive(Clone, Debug)]
pub struct Study {
    /// How many walks and how long.
    pub size: Size,
    /// The random floors' surveys, law by law, floor by floor, `T_set` by `T_set`.
    pub surveys: Vec<Survey>,
    /// The uniform floors, in the same order.
    pub uniform: Vec<Uniform>,
    /// The ice patches, law by law, `T_set` by `T_set`.
    pub crossings: Vec<Crossing>,
}

impl Study {
    /// The survey of `law`, `floor` and `t_set`.
    #[must_use]
    pub fn survey(&self, law: usize, floor: usize, t_set: f64) -> Option<&Survey> {
        self.surveys
            .iter()
            .find(|s| s.law == law && s.floor == floor && s.t_set == t_set)
    }

    /// The uniform floors of `law`, `floor` and `t_set`.
    #[must_use]
    pub fn uniform(&self, law: usize, floor: usize, t_set: f64) -> Option<&Uniform> {
        self.uniform
            .iter()
            .find(|u| u.law == law && u.floor == floor && u.t_set == t_set)
    }
}

/// A walker on a floor: a law, a `T_set` and the floor.
struct Case {
    setup: Setup,
    floor: FloorSpec,
}

/// A walk of the study: the case, the walk's index (its random stream), its step limit.
struct Task {
    case: usize,
    walk: u64,
    max_steps: usize,
}

/// The paper's active walker under `law` with `T_set`.
fn setup(law: Law, t_set: f64) -> Result<Setup, WriteError> {
    let err = |e: walker::setup::SetupError| WriteError::Setup(e.to_string());
    let mut s = Setup::active_level().map_err(err)?;
    s.friction = law.friction;
    s.impact = law.impact;
    s.set("T_set", t_set).map_err(err)?;
    Ok(s)
}

/// The `UNIFORM_POINTS` values from `lo` to `hi`, both included.
fn span(lo: f64, hi: f64) -> Vec<f64> {
    (0..UNIFORM_POINTS)
        .map(|i| lo + (hi - lo) * i as f64 / (UNIFORM_POINTS - 1) as f64)
        .collect()
}

/// Walks the whole study of `size` on all cores.
///
/// # Errors
/// A setup or a floor that the library refuses (a defect of the study's constants).
pub fn collect(size: Size) -> Result<Study, WriteError> {
    let mut cases = Vec::new();
    let mut tasks = Vec::new();
    let mut add = |cases: &mut Vec<Case>, setup: Setup, floor: FloorSpec, walks: u64, steps| {
        for walk in 0..walks {
            tasks.push(Task {
                case: cases.len(),
                walk,
                max_steps: steps,
            });
        }
        cases.push(Case { setup, floor });
    };
    for law in LAWS {
        for floor in FLOORS {
            for t_set in T_SETS {
                let s = setup(law, t_set)?;
                add(
                    &mut cases,
                    s.clone(),
                    floor.spec(),
                    size.walks as u64,
                    size.max_steps,
                );
                let (lo, hi) = floor.mu0.bounds();
                for mu0 in span(lo, hi).into_iter().chain([floor.mean()]) {
                    add(
                        &mut cases,
                        s.clone(),
                        FloorSpec::Uniform { mu0 },
                        1,
                        size.max_steps,
                    );
                }
            }
        }
        for t_set in T_SETS {
            let s = setup(law, t_set)?;
            for k in 0..=PATCH.longest {
                add(&mut cases, s.clone(), PATCH.floor(k), 1, PATCH.steps(k));
            }
        }
    }
    let walkers = cases
        .iter()
        .map(|c| {
            FloorWalker::new(&c.setup, c.floor.clone())
                .map_err(|e| WriteError::Setup(e.to_string()))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let starts = cases
        .iter()
        .map(|c| {
            c.setup
                .model()
                .map(|m| m.start_state())
                .map_err(|e| WriteError::Setup(e.to_string()))
        })
        .collect::<Result<Vec<Vector>, _>>()?;
    let progress = Progress::new("floor study", tasks.len());
    let cfg = SimConfig::default();
    let ends = tasks
        .par_iter()
        .map(|t| {
            let limits = WalkLimits {
                max_steps: t.max_steps,
                ..WalkLimits::default()
            };
            let w = walkers[t.case]
                .walk(t.walk, &cfg, &starts[t.case], &limits)
                .map_err(|e| WriteError::Setup(e.to_string()))?;
            progress.tick();
            Ok(End {
                steps: w.steps.len(),
                distance: w.steps.iter().map(|s| s.dx).sum(),
                failure: w.failure.as_ref().map(|f| f.name().to_owned()),
            })
        })
        .collect::<Result<Vec<End>, WriteError>>()?;
    progress.finish();
    Ok(assemble(size, &tasks, ends))
}

/// The study from the ends of its tasks, in the order [`collect`] made them.
fn assemble(size: Size, tasks: &[Task], ends: Vec<End>) -> Study {
    let mut by_case: Vec<Vec<End>> = Vec::new();
    for (t, e) in tasks.iter().zip(ends) {
        if by_case.len() <= t.case {
            by_case.resize_with(t.case + 1, Vec::new);
        }
        by_case[t.case].push(e);
    }
    let mut cases = by_case.into_iter();
    let mut study = Study {
        size,
        surveys: Vec::new(),
        uniform: Vec::new(),
        crossings: Vec::new(),
    };
    for law in 0..LAWS.len() {
        for (floor, spec) in FLOORS.iter().enumerate() {
            for t_set in T_SETS {
                let ends = cases.next().unwrap_or_default();
                let outcomes: Vec<SurviveOutcome> = ends
                    .iter()
                    .enumerate()
                    .map(|(i, e)| SurviveOutcome {
                        walk: i as u64,
                        steps: e.steps,
                        failure: e.failure.clone(),
                    })
                    .collect();
                study.surveys.push(Survey {
                    law,
                    floor,
                    t_set,
                    survival: survival(&outcomes),
                    ends,
                });
                let (lo, hi) = spec.mu0.bounds();
                let mut walks: Vec<(f64, End)> = span(lo, hi)
                    .into_iter()
                    .map(|mu0| (mu0, first(cases.next())))
                    .collect();
                let at_mean = first(cases.next());
                walks.sort_by(|a, b| a.0.total_cmp(&b.0));
                study.uniform.push(Uniform {
                    law,
                    floor,
                    t_set,
                    walks,
                    at_mean,
                });
            }
        }
        for t_set in T_SETS {
            let ends = (0..=PATCH.longest).map(|_| first(cases.next())).collect();
            study.crossings.push(Crossing { law, t_set, ends });
        }
    }
    study
}

/// The one walk of a case.
fn first(ends: Option<Vec<End>>) -> End {
    ends.and_then(|e| e.into_iter().next()).unwrap_or(End {
        steps: 0,
        distance: 0.0,
        failure: Some("not-walked".to_owned()),
    })
}
