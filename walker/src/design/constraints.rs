//! The design's constraints: which a request has on a walker, their values `g(p) <= 0` as
//! the program sees them, and their rows (value, limit, sense) in the result.

use super::evaluate::Evaluation;
use super::request::{DesignRequest, Margins};

/// The sharpness `rho` of the Kreisselmeier-Steinhauser aggregate of the stance's samples
/// ([`ks`]): it exceeds their largest value by at most `ln(400) / rho = 0.015` (by 0.0017 at
/// the paper walker's shaped design; `rho` 100 and 200 gave 0.012 and 0.004 and a worse
/// design, 1000 a constraint too sharp for the solver to converge on).
const RHO: f64 = 400.0;
/// The clearance constraint's value where a step has no interior sample (never for a completed
/// step of 400 samples): violated.
const NO_SAMPLES: f64 = 1.0;
/// Ratios beyond this (a normal force at or below zero) are capped so the solver sees numbers.
pub(super) const CAP: f64 = 1e3;

/// One constraint of a design.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    /// Every multiplier's modulus `<= 1 - margin`.
    Multipliers,
    /// The heel strike's impulse ratio `<= mu0 - margin`.
    ImpactFriction,
    /// The smallest normal force on the stance `>= margin`.
    NormalForce,
    /// The stance's friction ratios (aggregated) `<= mu0 - margin`.
    StanceFriction,
    /// The strike at least `margin` after the end of the last ramp: `T - T_set >= margin`
    /// (a strike before it is no gait of the model: the walk fails with
    /// `impact-before-t-set`). Only for a model with ramps.
    StrikeAfterRamp,
    /// `max |u_i| <= U_i` along the stance (aggregated), for input `i`.
    Input(usize),
    /// The swing foot's height `h >= H 4 s (1 - s)` at every interior stance sample
    /// (aggregated as `1 - h / (H 4 s (1 - s))`, relative to the profile).
    Clearance,
    /// The mean speed `V >= V_min`.
    MinSpeed,
    /// The mean speed `V <= V_max`.
    MaxSpeed,
    /// The mean input power `p <= P`.
    MaxPower,
}

impl Kind {
    /// The constraint's name in the result.
    pub(super) fn name(self) -> String {
        match self {
            Kind::Multipliers => "multipliers".to_owned(),
            Kind::ImpactFriction => "impact-friction".to_owned(),
            Kind::NormalForce => "normal-force".to_owned(),
            Kind::StanceFriction => "stance-friction".to_owned(),
            Kind::StrikeAfterRamp => "strike-after-ramp".to_owned(),
            Kind::Input(i) => format!("input-{i}"),
            Kind::Clearance => "clearance".to_owned(),
            Kind::MinSpeed => "min-speed".to_owned(),
            Kind::MaxSpeed => "max-speed".to_owned(),
            Kind::MaxPower => "max-power".to_owned(),
        }
    }
}

/// The constraints of `req` on a walker with ramps (`ramps`) and `inputs` inputs, in the
/// order of the program and of the result: the four of every design, then the strike after
/// the ramps, then one per bounded input, then the clearance, the least and the most speed and
/// the most power where the request has them (after the others, so that a design without them
/// has the rows it had).
pub(super) fn kinds(req: &DesignRequest, ramps: bool, inputs: usize) -> Vec<Kind> {
    let mut k = vec![
        Kind::Multipliers,
        Kind::ImpactFriction,
        Kind::NormalForce,
        Kind::StanceFriction,
    ];
    if ramps {
        k.push(Kind::StrikeAfterRamp);
    }
    if !req.max_input.is_empty() {
        k.extend((0..inputs).map(Kind::Input));
    }
    let b = &req.bounds;
    for (kind, asked) in [
        (Kind::Clearance, b.clearance.is_some()),
        (Kind::MinSpeed, b.min_speed.is_some()),
        (Kind::MaxSpeed, b.max_speed.is_some()),
        (Kind::MaxPower, b.max_power.is_some()),
    ] {
        if asked {
            k.push(kind);
        }
    }
    k
}

/// The bound on input `i` of `req` (one for all, or one per input).
pub(super) fn input_bound(req: &DesignRequest, i: usize) -> f64 {
    req.max_input
        .get(i)
        .or(req.max_input.first())
        .copied()
        .unwrap_or(f64::INFINITY)
}

/// The constraint `kind` as the program sees it, `g <= 0`, at the evaluation `e` on a floor of
/// `mu0`: the stance's ratios and the inputs aggregated by [`ks`] (the inputs relative to their
/// bound, so that `rho` means the same for every input), ratios capped at [`CAP`].
pub(super) fn program_value(kind: Kind, e: &Evaluation, mu0: f64, req: &DesignRequest) -> f64 {
    let m = &req.margins;
    match kind {
        Kind::Multipliers => e.fixed_point.max_modulus() - (1.0 - m.multiplier),
        Kind::ImpactFriction => e.impact_friction.min(CAP) - (mu0 - m.friction),
        Kind::NormalForce => m.normal - e.min_normal.max(-CAP),
        Kind::StanceFriction => stance_ks(e) - (mu0 - m.friction),
        Kind::StrikeAfterRamp => {
            m.ramp - (e.fixed_point.period - e.ramps_end.unwrap_or(f64::NEG_INFINITY)).min(CAP)
        }
        Kind::Input(i) => {
            let u = input_bound(req, i);
            let r: Vec<f64> = e
                .input_samples
                .get(i)
                .map_or(&[][..], Vec::as_slice)
                .iter()
                .map(|v| (v / u).min(CAP))
                .collect();
            if r.is_empty() { 0.0 } else { ks(&r) - 1.0 }
        }
        Kind::Clearance => {
            let h = req.bounds.clearance.unwrap_or(0.0);
            let r: Vec<f64> = e
                .swing_heights
                .iter()
                .map(|(z, w)| (1.0 - z / (h * w)).clamp(-CAP, CAP))
                .collect();
            if r.is_empty() { NO_SAMPLES } else { ks(&r) }
        }
        Kind::MinSpeed => {
            let v = req.bounds.min_speed.unwrap_or(0.0);
            (1.0 - e.fixed_point.speed / v).min(CAP)
        }
        Kind::MaxSpeed => {
            let v = req.bounds.max_speed.unwrap_or(f64::INFINITY);
            (e.fixed_point.speed / v - 1.0).min(CAP)
        }
        Kind::MaxPower => {
            let p = req.bounds.max_power.unwrap_or(f64::INFINITY);
            (e.power / p - 1.0).min(CAP)
        }
    }
}

/// The constraint `kind` as the result reports it: what it measures at `e`, its limit, and
/// its sense (`<=` or `>=`), on a floor of `mu0` with the margins `m`.
pub(super) fn row(
    kind: Kind,
    e: &Evaluation,
    mu0: f64,
    req: &DesignRequest,
) -> (f64, f64, &'static str) {
    let m: &Margins = &req.margins;
    match kind {
        Kind::Multipliers => (e.fixed_point.max_modulus(), 1.0 - m.multiplier, "<="),
        Kind::ImpactFriction => (e.impact_friction, mu0 - m.friction, "<="),
        Kind::NormalForce => (e.min_normal, m.normal, ">="),
        Kind::StanceFriction => (e.stance_friction, mu0 - m.friction, "<="),
        Kind::StrikeAfterRamp => (
            e.fixed_point.period - e.ramps_end.unwrap_or(f64::NEG_INFINITY),
            m.ramp,
            ">=",
        ),
        Kind::Input(i) => (
            e.max_input.get(i).copied().unwrap_or(0.0),
            input_bound(req, i),
            "<=",
        ),
        Kind::Clearance => (
            e.clearance.unwrap_or(f64::NEG_INFINITY),
            req.bounds.clearance.unwrap_or(0.0),
            ">=",
        ),
        Kind::MinSpeed => (
            e.fixed_point.speed,
            req.bounds.min_speed.unwrap_or(0.0),
            ">=",
        ),
        Kind::MaxSpeed => (
            e.fixed_point.speed,
            req.bounds.max_speed.unwrap_or(f64::INFINITY),
            "<=",
        ),
        Kind::MaxPower => (e.power, req.bounds.max_power.unwrap_or(f64::INFINITY), "<="),
    }
}

/// The Kreisselmeier-Steinhauser aggregate `max + ln(sum_k exp(rho (v_k - max))) / rho` of
/// `v`: a smooth upper bound of its largest value, by at most `ln(len) / rho`. One smooth
/// constraint on the whole stance, where one constraint per sample gives linearisations that
/// contradict each other when a peak moves in time with the parameters, and the plain maximum
/// has a kink where two peaks are equal (as at a design whose friction is shaped).
pub(super) fn ks(v: &[f64]) -> f64 {
    let top = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    top + v.iter().map(|x| (RHO * (x - top)).exp()).sum::<f64>().ln() / RHO
}

/// The stance's friction ratios (capped at [`CAP`]) aggregated by [`ks`].
pub(super) fn stance_ks(e: &Evaluation) -> f64 {
    let ratios: Vec<f64> = e.stance_ratios.iter().map(|r| r.min(CAP)).collect();
    ks(&ratios)
}
