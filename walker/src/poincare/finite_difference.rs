//! The Poincare map with its Jacobian by central differences: the independent check of the
//! exact Jacobian (with a step study, [`finite_difference_map_with_step`]), and the fallback
//! where a phase of a step has no Jacobian kernel: one step of the simulator
//! ([`crate::sim::walk`], so every event, stick-slip transition and validity test of the walk
//! applies) and its Jacobian by central differences.
//!
//! Accuracy: the steps are integrated at `rtol = min(rtol, 1e-12)`, `atol = min(atol, 1e-14)`
//! so that the map's own error `delta` is about `1e-12`; with the difference step
//! `h = 1e-4 max(1, |s_j|)` the Jacobian's error is about `delta / h + h^2 |P'''| / 6`: about
//! `1e-8` where the map's third derivative is of order one, but `1e-4` on the simplest walking
//! model, whose third derivative is not (`docs/poincare.md`, `tests/it/poincare_exact.rs`). Where one side of a difference has no step (a stuck foot pushed into a slide that
//! Painleve's paradox forbids), the difference is one-sided, with an error of about `h`
//! (`1e-4`) in that column; where a foot at rest can slide neither way, the map exists only with
//! the foot at rest and the columns of its velocity (`xd`, `zd`) are left zero: perturbations
//! along them are not motions of the walker. Where a stick-slip transition or an impact-regime switch lies within `h` of the point
//! the map is not differentiable there and the difference mixes the two sides. The columns of
//! `x` and `z` are zero: nothing depends on them and the map measures from the new foot.

use crate::model::{FrictionLaw, ImpactRegime, Model};
use crate::sim::{SimConfig, StepResult, WalkLimits, walk};
use crate::vector::Vector;

use super::error::MapError;
use super::result::{JacobianMethod, MapResult};

/// A foot-relative post-impact state and the regime of the impact that led to it.
#[derive(Clone, Copy)]
struct State {
    s: Vector,
    impact: ImpactRegime,
}

/// The tolerances of the steps of [`finite_difference_map`].
fn tight(cfg: &SimConfig) -> SimConfig {
    SimConfig {
        rtol: cfg.rtol.min(1e-12),
        atol: cfg.atol.min(1e-14),
        ..*cfg
    }
}

/// The simulator's step from `s` (time 0 of a step), or its failure as the map's.
pub(super) fn walked(model: &Model, cfg: &SimConfig, s: &[f64]) -> Result<StepResult, MapError> {
    let limits = WalkLimits {
        max_steps: 1,
        ..WalkLimits::default()
    };
    let w = walk(model, cfg, s, &limits);
    if let Some(failure) = w.failure {
        return Err(MapError::Walk(Box::new(failure)));
    }
    w.steps.first().copied().ok_or(MapError::NoHeelStrike {
        t: cfg.max_step_time,
    })
}

/// One step from `s` (time 0 of a step): the foot-relative post-impact state, the period and
/// the step length.
fn one_step(model: &Model, cfg: &SimConfig, s: &[f64]) -> Result<(State, f64, f64), MapError> {
    let step = walked(model, cfg, s)?;
    let mut plus = step.state_plus();
    (plus[0], plus[1]) = (0.0, 0.0);
    let state = State {
        s: plus,
        impact: step.impact,
    };
    Ok((state, step.period, step.dx))
}

/// The relative difference step of [`finite_difference_map`].
pub(super) const DEFAULT_STEP: f64 = 1e-4;

/// The Poincare map at `s` with its Jacobian by central differences (see the module
/// documentation).
pub(crate) fn finite_difference_map(
    model: &Model,
    cfg: &SimConfig,
    s: &[f64],
) -> Result<MapResult, MapError> {
    finite_difference_map_with_step(model, cfg, s, DEFAULT_STEP)
}

/// [`poincare_map`](super::poincare_map) with its Jacobian by central differences of relative
/// step `step` (`h = step max(1, |s_j|)`; the default is `1e-4`): the independent check of the
/// exact Jacobian, and its step study (the error falls as `h^2` until the map's own error
/// `delta / h` takes over).
///
/// # Errors
/// [`MapError`]: the step from `s` could not be taken.
pub fn finite_difference_map_with_step(
    model: &Model,
    cfg: &SimConfig,
    s: &[f64],
    step: f64,
) -> Result<MapResult, MapError> {
    let cfg = tight(cfg);
    let n = model.n();
    let m = 2 * n;
    if s.len() != m {
        return Err(MapError::Shape {
            what: "the state",
            got: s.len(),
            expected: m,
        });
    }
    let (plus, period, dx) = one_step(model, &cfg, s)?;
    let mut jacobian = vec![vec![0.0; m]; m];
    let foot_at_rest = model.friction_law() == FrictionLaw::Coulomb && s[n] == 0.0;
    for j in 2..m {
        let h = step * s[j].abs().max(1.0);
        let (mut up, mut down) = (Vector::from_slice(s), Vector::from_slice(s));
        up[j] += h;
        down[j] -= h;
        let (pu, pd) = (one_step(model, &cfg, &up), one_step(model, &cfg, &down));
        // One-sided where one side has no step (a stuck foot pushed into a slide that
        // Painleve's paradox forbids under exact Coulomb friction).
        let (a, b, xa, xb) = match (&pu, &pd) {
            (Ok((pu, ..)), Ok((pd, ..))) => (pu, pd, up[j], down[j]),
            (Ok((pu, ..)), Err(_)) => (pu, &plus, up[j], s[j]),
            (Err(_), Ok((pd, ..))) => (&plus, pd, s[j], down[j]),
            // A foot at rest that can slide neither way: the map exists only with the foot at
            // rest, and there is no derivative along its velocity to take.
            (Err(_), Err(_)) if foot_at_rest && (j == n || j == n + 1) => continue,
            (Err(e), Err(_)) => return Err(e.clone()),
        };
        for (i, row) in jacobian.iter_mut().enumerate() {
            row[j] = (a.s[i] - b.s[i]) / (xa - xb);
        }
    }
    Ok(MapResult {
        state_plus: plus.s,
        period,
        dx,
        jacobian,
        method: JacobianMethod::FiniteDifferences,
        impact: plus.impact,
    })
}
