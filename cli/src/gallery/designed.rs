//! A designed gait beside the hand-made one (issue 34): for the three-link biped, whose
//! hand-made gait needs `mu0 >= 0.5748` at its heel strike, `walker design --objective friction`
//! varying the ramp's duration `T_set`, the torso's set angle `th_T` and the strike posture
//! `beta` (`docs/design.md`), its held gait and the friction it needs along the step, and a walk
//! of [`STEPS`] steps by the simulator alone on a floor [`ABOVE`] above that need.

use walker::design::{Design, DesignRequest, Margins, Objective, Vary, design};
use walker::model::{Friction, ImpactLaw, ImpactRegime};
use walker::setup::Setup;
use walker::sim::{SimConfig, Walk, WalkLimits, walk};

use super::held::{Held, held};
use super::laws::EXACT;

/// The models that get a designed gait.
pub const MODELS: [&str; 1] = ["three-link"];

/// The varied parameters and their bounds (those of `docs/design.md`); each starts from the
/// model file's value.
const VARY: [(&str, f64, f64); 3] = [("T_set", 0.2, 1.0), ("th_T", 0.1, 0.8), ("beta", 0.2, 0.5)];

/// The solver's evaluation limit: the design converges in about 30 (`docs/design.md`).
const MAX_EVALUATIONS: usize = 40;

/// The floor of the check walk lies this far above the friction the design needs: the design's
/// own margin (`Margins::friction`), so that the walk's friction is what the design promised.
pub const ABOVE: f64 = 0.01;

/// The check walk's length in steps.
pub const STEPS: usize = 100;

/// The designed gait of a model: the design, its held gait (friction profile) and the walk by
/// the simulator alone at `mu0 = need + ABOVE`.
#[derive(Clone, Debug)]
pub struct Designed {
    /// The design (`walker design --json`'s content).
    pub design: Design,
    /// The designed gait held (`mu0` large), with the friction it needs along its step.
    pub held: Held,
    /// The walk of [`STEPS`] steps from the design's fixed point at `mu0 = need + ABOVE`.
    pub walk: Walk,
    /// That `mu0`.
    pub mu0: f64,
}

impl Designed {
    /// The friction the designed gait needs (the design's objective).
    #[must_use]
    pub fn need(&self) -> f64 {
        self.design.value
    }

    /// `T_set = 0.2, th_T = 0.1, beta = 0.2`: the designed parameters, for texts.
    #[must_use]
    pub fn parameters(&self) -> String {
        self.design
            .parameters
            .iter()
            .map(|p| format!("{} = {:.5}", p.name, p.value))
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// The steps of the check walk whose foot stayed stuck through the whole stance and whose
    /// heel strike stuck.
    #[must_use]
    pub fn held_steps(&self) -> usize {
        self.walk
            .steps
            .iter()
            .filter(|s| s.stuck_time >= s.period * (1.0 - 1e-12) && s.impact == ImpactRegime::Stick)
            .count()
    }
}

/// The designed gait of `setup` (a model of [`MODELS`]) under exact Coulomb friction in stance
/// and at the impact.
///
/// # Errors
/// The design fails, or its gait has no held gait or walk (the message says which).
pub fn designed(setup: &Setup) -> Result<Designed, String> {
    let mut s = setup.clone();
    s.friction = Friction::Coulomb;
    s.impact = ImpactLaw::Coulomb;
    let vary = VARY
        .iter()
        .map(|&(name, lo, hi)| {
            let start = s
                .params
                .get(name)
                .ok_or_else(|| format!("no parameter {name}"))?;
            Ok(Vary {
                name: name.to_owned(),
                lo,
                hi,
                start,
            })
        })
        .collect::<Result<Vec<_>, String>>()?;
    let req = DesignRequest {
        vary,
        objective: Objective::Friction,
        margins: Margins::default(),
        max_evaluations: MAX_EVALUATIONS,
        tol: 1e-10,
        max_input: Vec::new(),
        bounds: walker::design::GaitBounds::default(),
    };
    let cfg = SimConfig::default();
    let d = design(&s, &cfg, &req).map_err(|e| format!("design: {e}"))?;
    let mut gait = setup.clone();
    for p in &d.parameters {
        gait.set(&p.name, p.value).map_err(|e| e.to_string())?;
    }
    let held = held(&gait, f64::NAN).map_err(|e| format!("designed gait: {e}"))?;
    let mu0 = d.value + ABOVE;
    let model = EXACT.model(&gait, f64::NAN, mu0)?;
    let limits = WalkLimits {
        max_steps: STEPS,
        duration: f64::INFINITY,
        record: false,
        periodic: None,
    };
    let walk = walk(&model, &cfg, &d.gait.fixed_point.state_plus, &limits);
    Ok(Designed {
        design: d,
        held,
        walk,
        mu0,
    })
}
