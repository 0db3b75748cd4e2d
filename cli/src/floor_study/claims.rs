//! What the floor study checks: Fig. 8's lift-off boundary carried over to an ice patch, and
//! the two ways a floor that changes from step to step differs from a uniform one (its best
//! `T_set`, and a walker that walks on every uniform floor of its range but falls on it).

use crate::gallery::claims::Claim;

use super::cases::{FLOORS, LAWS, PATCH, T_SETS};
use super::data::Study;

/// The law whose claims compare with the paper's Fig. 8: the paper's tanh law.
const PAPER_LAW: usize = 0;

/// The study's claims, each computed from its walks.
#[must_use]
pub fn claims(study: &Study) -> Vec<Claim> {
    let mut out = vec![patch_claim(study)];
    out.extend((0..FLOORS.len()).map(|f| best_claim(study, f)));
    out.push(fell_claim(study));
    out
}

/// `T_set = 0.2` lifts off below `mu0 = 0.46` on uniform floors (Fig. 8), so a single icy
/// step fells it; the ramps from 0.25 to 0.5 s cross every patch tried, under both laws.
fn patch_claim(study: &Study) -> Claim {
    let longest = |law: usize, t: f64| {
        study
            .crossings
            .iter()
            .find(|c| c.law == law && c.t_set == t)
            .and_then(super::data::Crossing::longest)
    };
    let mut found = Vec::new();
    let mut holds = true;
    for (law, l) in LAWS.iter().enumerate() {
        let short = longest(law, 0.2);
        holds &= short == Some(0);
        let crossing = T_SETS
            .iter()
            .filter(|&&t| (0.25..=0.5).contains(&t))
            .all(|&t| longest(law, t) == Some(PATCH.longest));
        holds &= crossing;
        found.push(format!(
            "{}: T_set = 0.2 crosses {}; 0.25 to 0.5 cross {} steps: {}",
            l.name,
            short.map_or("nothing (does not walk the dry floor)".to_owned(), |k| {
                format!("{k} icy steps")
            }),
            PATCH.longest,
            if crossing { "all" } else { "not all" }
        ));
    }
    Claim::new(
        format!(
            "An ice patch (mu0 = {}) on a dry floor (mu0 = {}) fells T_set = 0.2 at its first \
             step, where Fig. 8 has it lift off on any floor below mu0 = 0.46, under both \
             laws; every T_set from 0.25 to 0.5 crosses patches of up to {} steps.",
            PATCH.icy, PATCH.dry, PATCH.longest
        ),
        found.join("; "),
        holds,
    )
}

/// The `T_set` that walks farthest (mean distance in the step limit) on random floor `f`
/// under the paper's law is not the one that walks farthest on the uniform floor at its mean
/// `mu0`: Fig. 8's answer does not carry over.
fn best_claim(study: &Study, f: usize) -> Claim {
    let floor = &FLOORS[f];
    let best = |g: &dyn Fn(f64) -> Option<f64>| {
        T_SETS
            .iter()
            .filter_map(|&t| g(t).map(|d| (t, d)))
            .max_by(|a, b| a.1.total_cmp(&b.1))
    };
    let random = best(&|t| {
        study
            .survey(PAPER_LAW, f, t)
            .map(super::data::Survey::mean_distance)
    });
    let uniform = best(&|t| study.uniform(PAPER_LAW, f, t).map(|u| u.at_mean.distance));
    let holds = matches!((random, uniform), (Some(r), Some(u)) if r.0 != u.0);
    let show = |b: Option<(f64, f64)>| {
        b.map_or("none".to_owned(), |(t, d)| {
            format!("T_set = {t} ({d:.2} m)")
        })
    };
    Claim::new(
        format!(
            "On the {} floor ({}), the T_set that walks farthest in {} steps under the \
             paper's law is not the one that walks farthest on a uniform floor at its mean \
             mu0 = {:.3} (Fig. 8's question): the best ramp depends on how the floor changes, \
             not only on its mean.",
            floor.name,
            floor.about,
            study.size.max_steps,
            floor.mean()
        ),
        format!(
            "farthest on the {} floor: {}; on the uniform floor: {}",
            floor.name,
            show(random),
            show(uniform)
        ),
        holds,
    )
}

/// Some `T_set` completes the step limit on every uniform floor spanning a random floor's
/// range, under some law, but not every walk on the random floor: the changes from step to
/// step fell it.
fn fell_claim(study: &Study) -> Claim {
    let cases: Vec<String> = study
        .surveys
        .iter()
        .filter(|v| {
            v.survival.failures > 0
                && study
                    .uniform(v.law, v.floor, v.t_set)
                    .is_some_and(super::data::Uniform::walks_everywhere)
        })
        .map(|v| {
            format!(
                "{} friction, {} floor, T_set = {}: {} of {} walks fell",
                LAWS[v.law].name,
                FLOORS[v.floor].name,
                v.t_set,
                v.survival.failures,
                v.survival.walks
            )
        })
        .collect();
    Claim::new(
        format!(
            "A floor that changes from step to step fells walkers that walk on every uniform \
             floor of its range: some T_set completes {} steps on each of the uniform floors \
             spanning the random floor's range, yet falls on the random floor.",
            study.size.max_steps
        ),
        if cases.is_empty() {
            "no such T_set".to_owned()
        } else {
            cases.join("; ")
        },
        !cases.is_empty(),
    )
}
