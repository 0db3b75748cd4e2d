//! Continuation of limit cycles in `mu0` along chains of `T_set` or `phi`, each cycle starting
//! Newton's method from its neighbour.

use serde::Serialize;

use crate::model::Model;
use crate::sim::SimConfig;

use super::fixed_point::{FixedPoint, FixedPointOptions, Status, fixed_point, newton};
use super::section::Section;

/// One point of a continuation in `mu0`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ContinuationPoint {
    /// The chain's parameter: `T_set` (active walker) or `phi` (passive wheel).
    pub chain: f64,
    /// Friction coefficient.
    pub mu0: f64,
    /// The cycle, or `None` when the search failed (no step from the initial condition).
    pub cycle: Option<FixedPoint>,
}

impl ContinuationPoint {
    /// A converged, valid gait whose multipliers are all strictly inside the unit circle.
    pub fn is_stable(&self) -> bool {
        self.cycle
            .as_ref()
            .is_some_and(|c| c.status == Status::Converged && c.max_modulus() < 1.0)
    }
}

/// Continuation in `mu0` along `mu0s` for every chain value (`T_set` for the active walker,
/// `phi` for the passive wheel; `model_for(chain, mu0)` builds the model, `None` where it
/// cannot): each cycle starts Newton's method from the previous one on the chain, and falls
/// back to the warm-up walk of [`fixed_point`] when that does not give a converged cycle.
pub fn continuation(
    model_for: impl Fn(f64, f64) -> Option<Model>,
    chains: &[f64],
    mu0s: &[f64],
    cfg: &SimConfig,
) -> Vec<ContinuationPoint> {
    let ok = |c: &FixedPoint| matches!(c.status, Status::Converged | Status::Family);
    let mut out = Vec::new();
    for &chain in chains {
        let mut prev: Option<Vec<f64>> = None;
        for &mu0 in mu0s {
            let Some(model) = model_for(chain, mu0) else {
                prev = None;
                out.push(ContinuationPoint {
                    chain,
                    mu0,
                    cycle: None,
                });
                continue;
            };
            let opts = FixedPointOptions::for_model(&model);
            let from_prev = prev
                .as_ref()
                .and_then(|r| newton(&model, cfg, r, &opts).ok())
                .filter(ok);
            let cycle = from_prev.or_else(|| fixed_point(&model, cfg, &opts).ok());
            prev = cycle
                .as_ref()
                .filter(|c| ok(c))
                .map(|c| Section::of(&model).reduce(&c.state_plus));
            out.push(ContinuationPoint { chain, mu0, cycle });
        }
    }
    out
}
