//! Batches of walks on random floors (`walker::floor::survive`): the same walks and statistics
//! on any number of threads and split into ranges of walks, and sane statistics where every
//! walk fails at once and where none fails.

use std::sync::atomic::{AtomicUsize, Ordering};

use walker::floor::{
    Distribution, FloorSpec, FloorWalker, SurviveReport, survival, survive, survive_stoppable,
};
use walker::setup::Setup;
use walker::sim::SimConfig;

fn uniform(seed: u64, lo: f64, hi: f64) -> FloorSpec {
    FloorSpec::Random {
        seed,
        mu0: Distribution::Uniform { lo, hi },
    }
}

fn batch(floor: FloorSpec, walks: usize, max_steps: usize) -> SurviveReport {
    let setup = Setup::passive_slope().expect("the built-in scene");
    let walker = FloorWalker::new(&setup, floor).expect("floor");
    let start = setup.model().expect("model").start_state();
    survive(
        &walker,
        &SimConfig::default(),
        &start,
        0..walks as u64,
        max_steps,
    )
    .expect("walks")
}

#[test]
fn on_ice_every_walk_falls_in_its_first_step_and_the_statistics_say_so() {
    // The passive wheel on its slope of 0.2 slides back and falls at mu0 <= 0.1.
    let r = batch(uniform(5, 0.02, 0.1), 12, 50);
    let s = &r.survival;
    assert_eq!((s.walks, s.failures, s.censored), (12, 12, 0));
    assert!(r.outcomes.iter().all(|o| o.steps == 0));
    let curve: Vec<(usize, f64)> = s.curve.iter().map(|p| (p.step, p.alive)).collect();
    assert_eq!(curve, vec![(0, 1.0), (1, 0.0)]);
    assert_eq!(s.mfpt.restricted_mean, 0.0);
    let mean = s.mfpt.sample_mean.expect("every walk failed");
    assert_eq!(
        (mean.estimate, mean.lo, mean.hi),
        (Some(0.0), 0.0, Some(0.0))
    );
    assert_eq!(s.mfpt.exponential.estimate, Some(0.0));
    assert_eq!(s.failures_by_kind.values().sum::<usize>(), 12);
    assert!(
        s.failures_by_kind.contains_key("fell-backward"),
        "{:?}",
        s.failures_by_kind
    );
}

#[test]
fn on_a_dry_floor_no_walk_falls_and_only_a_lower_bound_is_reported() {
    let r = batch(uniform(5, 0.25, 0.4), 6, 25);
    let s = &r.survival;
    assert_eq!((s.failures, s.censored), (0, 6));
    assert!(
        r.outcomes
            .iter()
            .all(|o| o.steps == 25 && o.failure.is_none())
    );
    assert_eq!(s.curve.last().map(|p| (p.step, p.alive)), Some((25, 1.0)));
    assert_eq!(s.mfpt.restricted_mean, 25.0);
    assert_eq!(s.mfpt.sample_mean, None);
    let e = s.mfpt.exponential;
    assert_eq!((e.estimate, e.hi), (None, None));
    // 150 step attempts without a fall: the mean is above 150 / 3.0 - 1 at 95%.
    assert!((e.lo - (150.0 / 2.995_732_273_553_991 - 1.0)).abs() < 1e-12);
    assert!(s.failures_by_kind.is_empty());
}

#[test]
fn a_batch_is_the_same_on_one_thread_and_on_several() {
    let floor = FloorSpec::Random {
        seed: 11,
        mu0: Distribution::Markov {
            dry: 0.3,
            icy: 0.05,
            dry_length: 30.0,
            icy_length: 1.5,
        },
    };
    let on = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a pool")
            .install(|| batch(floor.clone(), 10, 20))
    };
    let one = on(1);
    let json = |r: &SurviveReport| serde_json::to_string(r).expect("json");
    for threads in [2, 3] {
        assert_eq!(json(&on(threads)), json(&one));
    }
    // The batch mixes outcomes (about half the walks meet no ice in 20 steps), so the
    // comparison covers both kinds.
    let s = &one.survival;
    assert!(s.failures > 0 && s.censored > 0, "{} failed", s.failures);
}

#[test]
fn a_batch_that_is_never_stopped_is_the_batch_and_a_stopped_one_is_abandoned() {
    let setup = Setup::passive_slope().expect("the built-in scene");
    let floor = uniform(5, 0.2, 0.4);
    let walker = FloorWalker::new(&setup, floor.clone()).expect("floor");
    let start = setup.model().expect("model").start_state();
    let cfg = SimConfig::default();
    let never = survive_stoppable(&walker, &cfg, &start, 0..4, 10, &|| false).expect("walks");
    assert_eq!(never, Some(batch(floor, 4, 10)));
    // Asked to stop before the third step any walk takes: the batch is abandoned, not
    // reported with walks cut short as if they had ended on their own.
    let asked = AtomicUsize::new(0);
    let stop = || asked.fetch_add(1, Ordering::Relaxed) >= 2;
    let stopped = survive_stoppable(&walker, &cfg, &start, 0..4, 10, &stop).expect("walks");
    assert_eq!(stopped, None);
}

#[test]
fn a_batch_split_into_ranges_of_walks_has_the_batchs_walks_and_statistics() {
    let setup = Setup::passive_slope().expect("the built-in scene");
    let floor = FloorSpec::Random {
        seed: 11,
        mu0: Distribution::Markov {
            dry: 0.3,
            icy: 0.05,
            dry_length: 30.0,
            icy_length: 1.5,
        },
    };
    let walker = FloorWalker::new(&setup, floor).expect("floor");
    let start = setup.model().expect("model").start_state();
    let cfg = SimConfig::default();
    let whole = survive(&walker, &cfg, &start, 0..10, 20).expect("walks");
    for cuts in [vec![0, 10], vec![0, 3, 10], vec![0, 1, 2, 7, 9, 10]] {
        let mut outcomes = Vec::new();
        for w in cuts.windows(2) {
            let part = survive(&walker, &cfg, &start, w[0]..w[1], 20).expect("walks");
            // A range's walks are the batch's walks of those indices.
            assert_eq!(part.outcomes, whole.outcomes[w[0] as usize..w[1] as usize]);
            outcomes.extend(part.outcomes);
        }
        let json = |s: &walker::floor::Survival| serde_json::to_string(s).expect("json");
        assert_eq!(
            json(&survival(&outcomes)),
            json(&whole.survival),
            "{cuts:?}"
        );
    }
    // Some walks fail and some reach the limit, so the statistics are not trivial.
    assert!(whole.survival.failures > 0 && whole.survival.censored > 0);
}
