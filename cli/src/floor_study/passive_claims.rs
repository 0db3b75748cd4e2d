//! What the passive part of the floor study checks, each claim computed from its walks and
//! meshes: the mean first-passage time falls as the slopes spread, the mesh agrees with Monte
//! Carlo and converges, the friction ranges reach below what the gaits need, and random slopes
//! and random friction fell the walkers in different ways.

use crate::gallery::claims::Claim;

use super::passive::{Draw, MESH_CHECK, MESH_POINTS, Outcome, Walker};

/// Failures that are slips of the stance foot: the foot left the floor (`lift-off`) or the
/// contact could not be kept (`contact-inconsistent`).
pub const SLIPS: [&str; 2] = ["lift-off", "contact-inconsistent"];

/// The passive study's claims.
#[must_use]
pub fn claims(outcomes: &[Outcome]) -> Vec<Claim> {
    vec![
        spread_claim(outcomes),
        agree_claim(outcomes),
        converge_claim(outcomes),
        needed_claim(outcomes),
        kinds_claim(outcomes),
    ]
}

/// The Monte Carlo MFPT (constant failure rate) of an outcome.
fn mc(o: &Outcome) -> Option<f64> {
    o.survival.mfpt.exponential.estimate
}

/// The slope cases of `walker`, spread rising.
fn slopes(outcomes: &[Outcome], walker: Walker) -> Vec<(f64, &Outcome)> {
    outcomes
        .iter()
        .filter_map(|o| match o.case.draw {
            Draw::Slope { spread, .. } if o.case.walker == walker => Some((spread, o)),
            _ => None,
        })
        .collect()
}

/// For each walker, the Monte Carlo MFPT falls strictly with every wider spread of the slopes.
fn spread_claim(outcomes: &[Outcome]) -> Claim {
    let mut holds = true;
    let mut found = Vec::new();
    for walker in [Walker::Wheel, Walker::Compass] {
        let cases = slopes(outcomes, walker);
        let times: Vec<Option<f64>> = cases.iter().map(|(_, o)| mc(o)).collect();
        let falls = cases.len() >= 3
            && times.windows(2).all(|w| match (w[0], w[1]) {
                (Some(a), Some(b)) => b < a,
                _ => false,
            });
        holds &= falls;
        let shown: Vec<String> = cases
            .iter()
            .zip(&times)
            .map(|((s, _), t)| {
                format!(
                    "+-{s}: {}",
                    t.map_or("no failure".to_owned(), |t| format!("{t:.1}"))
                )
            })
            .collect();
        found.push(format!("{}: {}", walker.label(), shown.join(", ")));
    }
    Claim::new(
        "On random slopes (uniform around the nominal slope), the mean first-passage time of \
         the rimless wheel and of the compass gait falls monotonically as the spread grows.",
        found.join("; "),
        holds,
    )
}

/// On every case the mesh estimates, its MFPT from the fixed point, widened by its error (the
/// change from the mesh before), meets the Monte Carlo 95% interval.
fn agree_claim(outcomes: &[Outcome]) -> Claim {
    let meshed: Vec<&Outcome> = outcomes.iter().filter(|o| o.case.mesh).collect();
    let mut holds = !meshed.is_empty();
    let mut found = Vec::new();
    for o in meshed {
        let e = &o.survival.mfpt.exponential;
        let ok = match (o.mesh_estimate(), e.hi) {
            (Some((t, err)), Some(hi)) => t + err >= e.lo && t - err <= hi,
            _ => false,
        };
        holds &= ok;
        found.push(format!(
            "{}: mesh {}, Monte Carlo {} [{:.1}, {}]",
            o.case.name(),
            o.mesh_estimate()
                .map_or("infinite".to_owned(), |(t, err)| format!(
                    "{t:.1} +- {err:.1}"
                )),
            mc(o).map_or("-".to_owned(), |t| format!("{t:.1}")),
            e.lo,
            e.hi.map_or("unbounded".to_owned(), |h| format!("{h:.1}"))
        ));
    }
    Claim::new(
        format!(
            "Monte Carlo and the mesh (Byl and Tedrake's chain, the slope of the step before in \
             its state) agree within their errors on every case the mesh estimates: the mesh's \
             MFPT from the gait, widened by its error (its change from the mesh before plus the \
             change from {} to {} slope samples at N = {}), meets the Monte Carlo 95% interval.",
            super::passive::MESH_SAMPLES,
            MESH_CHECK.1,
            MESH_CHECK.0
        ),
        found.join("; "),
        holds,
    )
}

/// The largest relative change of the mesh's last refinement taken as converged.
pub const CONVERGED: f64 = 0.05;

/// On every meshed case the last refinement moves the estimate by less than [`CONVERGED`] of
/// it.
fn converge_claim(outcomes: &[Outcome]) -> Claim {
    let meshed: Vec<&Outcome> = outcomes.iter().filter(|o| o.case.mesh).collect();
    let mut holds = !meshed.is_empty();
    let mut found = Vec::new();
    for o in meshed {
        let t = o.refinements();
        let last = match t.as_slice() {
            [.., Some(a), Some(b)] => Some((b - a).abs() / b),
            _ => None,
        };
        holds &= last.is_some_and(|c| c < CONVERGED);
        let shown: Vec<String> = MESH_POINTS
            .iter()
            .zip(&t)
            .map(|(n, t)| {
                format!(
                    "N = {n}: {}",
                    t.map_or("infinite".to_owned(), |t| format!("{t:.2}"))
                )
            })
            .collect();
        found.push(format!(
            "{}: {} (last change {})",
            o.case.name(),
            shown.join(", "),
            last.map_or("-".to_owned(), |c| format!("{:.1}%", 100.0 * c))
        ));
    }
    Claim::new(
        format!(
            "The mesh has converged on the wheel's random slopes: on every case its last \
             refinement ({} to {} points per coordinate) moves the estimate by less than {}%.",
            MESH_POINTS[MESH_POINTS.len() - 2],
            MESH_POINTS[MESH_POINTS.len() - 1],
            100.0 * CONVERGED
        ),
        found.join("; "),
        holds,
    )
}

/// Every friction range reaches below the friction the gait needs: the walker fails on the
/// uniform floor at the range's low end and completes the limit on the floors from some
/// value in the range up.
fn needed_claim(outcomes: &[Outcome]) -> Claim {
    let mut holds = true;
    let mut found = Vec::new();
    for o in outcomes {
        let Draw::Friction { lo, hi } = o.case.draw else {
            continue;
        };
        let needed = o.needed_mu0();
        holds &= needed.is_some_and(|m| m > lo && m <= hi);
        found.push(format!(
            "{}: completes every uniform floor from mu0 = {}",
            o.case.name(),
            needed.map_or("none".to_owned(), |m| format!("{m:.3}"))
        ));
    }
    Claim::new(
        "The random friction reaches below what each gait needs: on uniform floors spanning the \
         range, the walker fails at the low end and completes the step limit from a value \
         inside the range up.",
        found.join("; "),
        holds,
    )
}

/// The share of an outcome's failures that are slips.
fn slip_share(o: &Outcome) -> f64 {
    let slips: usize = o
        .survival
        .failures_by_kind
        .iter()
        .filter(|(k, _)| SLIPS.contains(&k.as_str()))
        .map(|(_, n)| n)
        .sum();
    slips as f64 / o.survival.failures.max(1) as f64
}

/// On random slopes (the foot held) no failure is a slip; on random friction most are.
fn kinds_claim(outcomes: &[Outcome]) -> Claim {
    let mut holds = true;
    let mut found = Vec::new();
    for o in outcomes {
        let share = slip_share(o);
        let ok = o.survival.failures > 0
            && match o.case.draw {
                Draw::Slope { .. } => share == 0.0,
                Draw::Friction { .. } => share > 0.5,
            };
        holds &= ok;
        found.push(format!(
            "{}: {}",
            o.case.name(),
            o.survival.failures_text(" ", ", ")
        ));
    }
    Claim::new(
        format!(
            "Random slopes and random friction fell the passive walkers in different ways: on \
             random slopes (every strike held) no failure is a slip ({}), the walkers stall or \
             fall; on random friction most failures are slips.",
            SLIPS.join(", ")
        ),
        found.join("; "),
        holds,
    )
}
