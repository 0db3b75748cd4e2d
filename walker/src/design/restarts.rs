//! Random restarts of a design: the request's start and `count` more, drawn uniformly within
//! the bounds from a seed, each solved; the best design is returned with every solve's
//! outcome, so that one sees whether the optimum found is local.

use crate::floor::draw::StepDraws;
use crate::setup::Setup;
use crate::sim::SimConfig;

use super::error::DesignError;
use super::request::DesignRequest;
use super::result::{Design, DesignStatus, Restart};
use super::solve::solve_from;

/// The most restarts a design takes.
pub const MAX_RESTARTS: usize = 100;

/// The starts of `count` restarts under `seed`: each parameter uniform in `[lo, hi]`, drawn in
/// the order of the request's `vary`, restart after restart, from the random floors' generator
/// at (seed, stream 0, word 0) (`crate::floor::draw`: ChaCha8 keyed by the seed), the same on
/// every machine.
#[must_use]
pub fn restart_starts(req: &DesignRequest, count: usize, seed: u64) -> Vec<Vec<f64>> {
    let mut draws = StepDraws::new(seed, 0, 0);
    (0..count)
        .map(|_| {
            req.vary
                .iter()
                .map(|v| (v.lo + draws.uniform() * (v.hi - v.lo)).clamp(v.lo, v.hi))
                .collect()
        })
        .collect()
}

/// How good a design of `req` is, for choosing the best of the restarts: a feasible design
/// (optimal or not) before an infeasible one, then the better objective (the smaller, or the
/// larger for a maximised one, [`super::Objective::sign`]).
fn rank(req: &DesignRequest, d: &Design) -> (bool, f64) {
    (
        d.status == DesignStatus::Infeasible,
        req.objective.sign() * d.value,
    )
}

/// The design `req` from its own start and from `count` starts drawn within the bounds under
/// `seed` ([`restart_starts`]); the best one (by `rank`: the earliest among equals), with
/// [`Design::restarts`] listing every solve in order. A start without a periodic gait is
/// recorded with its error and skipped.
///
/// # Errors
/// An invalid request ([`DesignRequest::check`]), `count` above [`MAX_RESTARTS`], or no
/// periodic gait at any start (the request's own start's error).
pub fn design_with_restarts(
    setup: &Setup,
    cfg: &SimConfig,
    req: &DesignRequest,
    count: usize,
    seed: u64,
) -> Result<Design, DesignError> {
    req.check(setup, cfg)?;
    if count > MAX_RESTARTS {
        return Err(DesignError::Restarts {
            count,
            max: MAX_RESTARTS,
        });
    }
    let own: Vec<f64> = req.vary.iter().map(|v| v.start).collect();
    let starts = std::iter::once(own).chain(restart_starts(req, count, seed));
    let mut best: Option<Design> = None;
    let mut first_error = None;
    let mut restarts = Vec::new();
    for x0 in starts {
        match solve_from(setup, cfg, req, &x0) {
            Ok(d) => {
                restarts.push(Restart {
                    start: x0,
                    status: Some(d.status),
                    value: Some(d.value),
                    parameters: d.parameters.iter().map(|p| p.value).collect(),
                    kkt_residual: Some(d.kkt_residual),
                    error: None,
                    evaluations: d.evaluations,
                });
                if best.as_ref().is_none_or(|b| rank(req, &d) < rank(req, b)) {
                    best = Some(d);
                }
            }
            Err(e) => {
                restarts.push(Restart {
                    start: x0,
                    status: None,
                    value: None,
                    parameters: Vec::new(),
                    kkt_residual: None,
                    error: Some(e.to_string()),
                    evaluations: 0,
                });
                first_error.get_or_insert(e);
            }
        }
    }
    match (best, first_error) {
        (Some(mut d), _) => {
            d.restarts = restarts;
            Ok(d)
        }
        (None, Some(e)) => Err(e),
        (None, None) => unreachable!("the request's own start is always solved"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::{Margins, Objective, Vary};

    fn request() -> DesignRequest {
        DesignRequest {
            vary: vec![
                Vary {
                    name: "a".into(),
                    lo: -1.0,
                    hi: 2.0,
                    start: 0.0,
                },
                Vary {
                    name: "b".into(),
                    lo: 0.5,
                    hi: 0.6,
                    start: 0.55,
                },
            ],
            objective: Objective::Friction,
            margins: Margins::default(),
            max_evaluations: 10,
            max_input: Vec::new(),
            tol: 1e-10,
            bounds: crate::design::GaitBounds::default(),
        }
    }

    #[test]
    fn restart_starts_lie_within_the_bounds_and_depend_on_the_seed_alone() {
        let req = request();
        let a = restart_starts(&req, 50, 7);
        assert_eq!(a, restart_starts(&req, 50, 7));
        assert_ne!(a, restart_starts(&req, 50, 8));
        assert_eq!(a.len(), 50);
        for x in &a {
            assert!(
                (-1.0..=2.0).contains(&x[0]) && (0.5..=0.6).contains(&x[1]),
                "{x:?}"
            );
        }
        // Uniform over the range: 50 draws spread over more than half of each range (the
        // chance of 50 uniform draws within one half-width window is below 1e-13).
        for (i, v) in req.vary.iter().enumerate() {
            let (lo, hi) = a
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| {
                    (l.min(x[i]), h.max(x[i]))
                });
            assert!(hi - lo > 0.5 * (v.hi - v.lo), "{lo} {hi}");
        }
    }
}
