//! The three-link biped's own claims (`models/three-link.toml`: Grizzle, Abba and Plestan's
//! biped with torso under output-following control, on a level floor, each walk from its own
//! start): the stable period-one gait its start lies on, the friction its grazing heel strike
//! needs and where it therefore walks, how it fails below that, and why neither the tanh law
//! nor the frictionless impact walks it. Every bound is argued in its claim's text; the numbers
//! are the run's (`walker/tests/it/three_link.rs` checks the same walker against a reference).

use walker::model::{Contact, Friction, ImpactLaw, ImpactRegime, Model, Slide};
use walker::poincare::{FixedPointOptions, Section, Status, newton};
use walker::sim::SimConfig;
use walker::sweep::SweepPoint;
use walker::vector::Vector;

use super::claims::{Claim, or_missing};
use super::data::{ModelRun, Sweep};
use super::designed::{ABOVE, STEPS};
use super::held::Held;
use super::laws::{EXACT, Laws};
use super::outcome::{Outcome, foot_at_failure};
use crate::reproduce::ranges::describe;

/// The file's start lies this close to the cycle's post-impact state, in every component: its
/// angles are the set values (`-beta`, `beta`, `th_T`), off the cycle's by the tracking error
/// at the strike (a few 1e-4 rad), its rates the cycle's to the three digits it gives.
const ON_THE_GAIT: f64 = 5e-4;

/// The step length is the chord `2 r sin(beta)` to this (m): at the strike the legs mirror each
/// other up to the tracking error of `y_legs` (about 1e-4 rad).
const CHORD: f64 = 2e-4;

/// The sweep's walk at the default `mu0` and the fixed point agree in `T` to this (relative):
/// the walk stops once periodic to 1e-9, the fixed point's residual is below 1e-11.
const SAME_GAIT: f64 = 1e-8;

/// A grazing strike: the foot's normal velocity is at most this share of its forward one.
const GRAZING: f64 = 1e-3;

/// The forward speed of the striking foot is `2 r cos(beta) th_std` to this share (the legs
/// mirror each other at the strike up to the tracking error).
const FOOT_SPEED: f64 = 1e-2;

/// The first heel strike's threshold, bisected to [`BISECT`], and `W_nn / |W_tn|` at the held
/// gait's strike agree to this: the first strike is the start's, its posture off the cycle's by
/// the start's error contracted once (below 1e-3 rad), and its foot still approaches the floor
/// (at `v_n / v_t` below [`GRAZING`]), each moving the threshold by a few 1e-4.
const THRESHOLD: f64 = 1e-3;

/// The bisection of the first heel strike's threshold stops at this width.
const BISECT: f64 = 1e-5;

/// A foot that slides through a grazing heel strike keeps its forward speed to this share: the
/// normal impulse that ends the compression is tiny, and the friction impulse at most `mu0`
/// times it.
const KEEPS_SPEED: f64 = 0.05;

/// A foot that slides out moves faster than this along the floor (m/s) when the walk ends.
const SLIDES_OUT: f64 = 1.0;

/// A foot that the tanh law nearly holds creeps slower than this (m/s): `mu0 tanh(c xd)` reaches
/// the friction the stance needs at `xd` of a few `1 / c`, `c = 100 s/m`.
const CREEPS: f64 = 0.1;

/// The inputs' sensitivity to the command at a tanh walk's failure exceeds the same state's
/// with the foot stuck by this factor: the sliding stance's decoupling matrix `A` is singular
/// there, the stuck stance's is not.
const SINGULAR: f64 = 1e3;

/// The change of the torso rate (rad/s) by which that sensitivity is measured.
const NUDGE: f64 = 1e-7;

/// The frictionless impulse of a grazing strike is below this share of the sticking impact's
/// normal impulse: it stops only the foot's normal velocity, the sticking one its forward one.
const TINY_IMPULSE: f64 = 1e-2;

/// A state's components by the model's coordinate names.
struct Index {
    n: usize,
    th_st: usize,
    th_t: usize,
}

impl Index {
    fn of(m: &Model) -> Option<Index> {
        let spec = m.spec();
        Some(Index {
            n: m.n(),
            th_st: spec.state_index("th_st")?,
            th_t: spec.state_index("th_t")?,
        })
    }
}

/// The model at its defaults under `laws` at `mu0`.
fn model(run: &ModelRun, laws: Laws, mu0: f64) -> Option<Model> {
    let setup = run.entry.setup().ok()?;
    laws.model(&setup, run.slopes[0].phi, mu0).ok()
}

/// A default parameter of the model.
fn param(run: &ModelRun, name: &str) -> Option<f64> {
    run.entry.setup().ok()?.params.get(name)
}

/// The held gait on the level floor.
fn held(run: &ModelRun) -> Option<&Held> {
    run.slopes.first()?.held.as_ref().ok()
}

/// What the claims about the held gait start from: the held gait, the model at its default
/// `mu0` under exact Coulomb friction, and where its angles are in the state.
fn held_model(run: &ModelRun) -> Option<(&Held, Model, Index)> {
    let h = held(run)?;
    let m = model(run, EXACT, param(run, "mu0")?)?;
    let ix = Index::of(&m)?;
    Some((h, m, ix))
}

/// The `(lo, hi)` of `xs`, `(NaN, NaN)` if empty.
fn span(xs: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = xs.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
        (a.min(x), b.max(x))
    });
    if lo.is_finite() {
        (lo, hi)
    } else {
        (f64::NAN, f64::NAN)
    }
}

/// The friction the first half of the held step needs at most (`|lambda_t / lambda_n|`), from
/// the held gait's profile: right after the heel strike the stance leg pushes its foot forward.
fn early_need(h: &Held) -> f64 {
    h.profile
        .iter()
        .filter(|(t, _)| *t < 0.5)
        .map(|(_, r)| r.abs())
        .fold(0.0, f64::max)
}

/// The stable period-one gait at the defaults, and the start on it.
fn gait(run: &ModelRun) -> Option<Claim> {
    let mu0 = param(run, "mu0")?;
    let (r, beta) = (param(run, "r")?, param(run, "beta")?);
    let m = model(run, EXACT, mu0)?;
    let cfg = SimConfig::default();
    let start = m.start_state();
    let opts = FixedPointOptions::for_model(&m);
    let fp = newton(&m, &cfg, &Section::of(&m).reduce(&start), &opts).ok()?;
    let off = start
        .iter()
        .zip(fp.state_plus.iter())
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    let chord = 2.0 * r * beta.sin();
    let pts = &run.sweep(EXACT)?.chains[0];
    let at = pts
        .iter()
        .min_by(|a, b| (a.value - mu0).abs().total_cmp(&(b.value - mu0).abs()))?;
    let swept = at.last.map_or(f64::NAN, |s| s.period);
    let held = run.outcome(0, at) == Outcome::Held;
    let rho = fp.max_modulus();
    let ok = fp.status == Status::Converged
        && fp.impact == ImpactRegime::Stick
        && rho < 1.0
        && off <= ON_THE_GAIT
        && (fp.dx - chord).abs() <= CHORD
        && held
        && (swept - fp.period).abs() <= SAME_GAIT * fp.period;
    Some(Claim::new(
        format!(
            "three-link biped, level, at its defaults (mu0 = {mu0}, {}): its start lies on a \
             stable period-one gait with its foot held: Newton's method from the start \
             converges, every component of the start within {ON_THE_GAIT:e} of \
             the cycle's post-impact state (the file gives the angles' set values and the rates \
             to three digits), the largest multiplier below 1, the heel strike sticking, the \
             step the chord 2 r sin(beta) = {chord:.6} m to {CHORD:e} m (the legs mirror each \
             other at the strike up to the tracking error); and the sweep's walk at mu0 = {:.2} \
             holds its foot in the same gait, T the same to {SAME_GAIT:e}.",
            EXACT.label(),
            at.value
        ),
        format!(
            "{:?} in {} iterations: T = {:.4} s, V = {:.4} m/s, dx = {:.6} m, largest \
             multiplier {rho:.3}, impact {:?}; the start off by up to {off:.1e}; the sweep at \
             mu0 = {:.2}: {}, T = {swept:.9} s (the cycle's {:.9} s)",
            fp.status,
            fp.iterations,
            fp.period,
            fp.speed,
            fp.dx,
            fp.impact,
            at.value,
            run.outcome(0, at).label(),
            fp.period
        ),
        ok,
    ))
}

/// Whether the first heel strike of the walk from the start at `mu0` sticks.
fn first_strike_sticks(run: &ModelRun, mu0: f64) -> bool {
    run.walk(0, EXACT, mu0, 1)
        .and_then(|w| w.steps.first().map(|s| s.impact == ImpactRegime::Stick))
        .unwrap_or(false)
}

/// The grazing heel strike's friction, where the first one starts to stick, and the range of
/// `mu0` where the walker walks.
fn threshold(run: &ModelRun) -> Option<Claim> {
    let (h, m, ix) = held_model(run)?;
    let (r, beta) = (param(run, "r")?, param(run, "beta")?);
    let ing = m.impact_ingredients(&h.pre);
    let [v_t, v_n, _] = ing.v;
    let ratio = ing.w[1][1] / ing.w[0][1].abs();
    let expected = 2.0 * r * beta.cos() * h.pre[ix.n + ix.th_st];
    let pts = &run.sweep(EXACT)?.chains[0];
    let held_at = |p: &SweepPoint| run.outcome(0, p) == Outcome::Held;
    // Bisect between the last grid point that does not walk and the first that does.
    let first = pts.iter().position(held_at)?;
    let (mut lo, mut hi) = (pts.get(first.checked_sub(1)?)?.value, pts[first].value);
    let bracket = !first_strike_sticks(run, lo) && first_strike_sticks(run, hi);
    while hi - lo > BISECT {
        let mid = 0.5 * (lo + hi);
        if first_strike_sticks(run, mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let mu_star = 0.5 * (lo + hi);
    let walks_exactly = pts.iter().all(|p| held_at(p) == (p.value >= mu_star));
    let early_end = |p: &SweepPoint| p.failure.as_ref().is_some_and(|f| f.step <= 1);
    let below_end_early = pts.iter().filter(|p| p.value < mu_star).all(early_end);
    let ok = v_n < 0.0
        && -v_n <= GRAZING * v_t.abs()
        && (v_t - expected).abs() <= FOOT_SPEED * expected.abs()
        && bracket
        && (mu_star - ratio).abs() <= THRESHOLD
        && walks_exactly
        && below_end_early;
    Some(Claim::new(
        format!(
            "three-link biped, level, {}: the swing foot strikes grazing, moving forward at 2 r \
             cos(beta) th_std = {expected:.4} m/s (to {:.0} %) and down at most {GRAZING:e} of \
             that, so only friction can stop it, and Stronge's impact sticks only where mu0 >= \
             W_nn/|W_tn| = {ratio:.4} at the held gait's strike (the sticking impulse's \
             |Lambda_t/Lambda_n| is {:.4}; the stance needs only {:.4}): the first heel strike \
             from the start sticks from there, to {THRESHOLD:e}, and the walker walks its gait \
             with the foot held at every grid mu0 above that and at none below, where every \
             walk ends within its first two steps.",
            EXACT.label(),
            100.0 * FOOT_SPEED,
            h.impact_ratio(),
            h.stance_ratio
        ),
        format!(
            "v_t = {v_t:.4} m/s, v_n = {v_n:.2e} m/s; the first strike sticks from mu0 = \
             {mu_star:.5} (bisected to {BISECT:e} between {:.2} and {:.2}: {bracket}); {}; \
             the walks below end in step 0 or 1: {below_end_early}",
            pts[first - 1].value,
            pts[first].value,
            describe(pts, |p| Some(run.outcome(0, p).label()))
        ),
        ok,
    ))
}

/// Whether the walk of `p` ended in its first stance before mid-stance by lift-off, its foot
/// sliding out forward faster than [`SLIDES_OUT`].
fn slides_out(p: &SweepPoint, ix: &Index) -> bool {
    let v = foot_at_failure(p, 0.0).map_or(f64::NAN, |f| f.0);
    p.failure
        .as_ref()
        .is_some_and(|f| f.step == 0 && f.name() == "lift-off" && f.state[ix.th_st] < 0.0)
        && v > SLIDES_OUT
}

/// How the walks below the heel strike's threshold fail, in three bands of `mu0` set by the
/// friction the held gait needs.
fn below(run: &ModelRun) -> Option<Claim> {
    let (h, m, ix) = held_model(run)?;
    let early = early_need(h);
    let late = h.stance_ratio;
    let strike = h.impact_ratio();
    let ing = m.impact_ingredients(&h.pre);
    let v_t = ing.v[0];
    let pts = &run.sweep(EXACT)?.chains[0];
    let band = |lo: f64, hi: f64| -> Vec<&SweepPoint> {
        pts.iter()
            .filter(|p| p.value >= lo && p.value < hi)
            .collect()
    };
    let (a, b, c) = (band(0.0, early), band(early, late), band(late, strike));
    // Below what the early stance needs: the foot slides out forward in the first stance and
    // the walk ends there, before mid-stance, by lift-off, as under the tanh law.
    let a_ok = !a.is_empty() && a.iter().all(|p| slides_out(p, &ix));
    // Below what the late stance needs: the foot slides backward late in the first stance,
    // and the walk ends there with it sliding backward, or the step ends with the foot stuck
    // for less than the step and the walk ends in the next.
    let b_ok = !b.is_empty()
        && b.iter().all(|p| {
            let Some(f) = &p.failure else { return false };
            let v = foot_at_failure(p, 0.0).map_or(f64::NAN, |f| f.0);
            match (f.step, p.last) {
                (0, _) => v < 0.0 && f.state[ix.th_st] > 0.0,
                (1, Some(s)) => {
                    s.stuck_time < s.period && s.impact == ImpactRegime::Slide(Slide::Forward)
                }
                _ => false,
            }
        });
    // Above what the stance needs: the first step holds its foot, its heel strike slides
    // forward and leaves the new foot at nearly the speed it arrived with, and the next
    // stance ends, its foot slid forward, when the slide stops and the stuck foot would need
    // more than mu0 (contact-inconsistent) or first, the torques blowing up with the sliding
    // stance's A singular (lambda-numerator-huge).
    let c_ok = !c.is_empty()
        && c.iter().all(|p| {
            let (Some(f), Some(s)) = (&p.failure, p.last) else {
                return false;
            };
            let slid = foot_at_failure(p, 0.0).map_or(f64::NAN, |f| f.1);
            f.step == 1
                && s.stuck_time >= s.period
                && s.impact == ImpactRegime::Slide(Slide::Forward)
                && s.qd_plus[0] <= v_t
                && s.qd_plus[0] >= (1.0 - KEEPS_SPEED) * v_t
                && slid > 0.0
                && matches!(f.name(), "contact-inconsistent" | "lambda-numerator-huge")
        });
    let names = |ps: &[&SweepPoint]| -> String {
        let v: Vec<SweepPoint> = ps.iter().map(|p| (*p).clone()).collect();
        describe(&v, |p| {
            p.failure
                .as_ref()
                .map(|f| format!("{} in step {}", f.name(), f.step))
        })
    };
    let (vlo, vhi) = span(c.iter().filter_map(|p| p.last.map(|s| s.qd_plus[0])));
    Some(Claim::new(
        format!(
            "three-link biped, level, {}, below the heel strike's {strike:.4}: the held stance \
             needs up to {early:.4} in its first half (the stance leg pushing the foot forward) \
             and up to {late:.4} at its end (backward). Below {early:.4} the foot slides out \
             forward early in the first stance (faster than {SLIDES_OUT} m/s) and the walk ends \
             there, before mid-stance, its normal force vanishing (lift-off), as under the tanh \
             law; up to {late:.4} the foot slides backward late in the first stance and the walk \
             ends there (at the strike) or in the next step, after a heel strike that slides \
             forward; up to {strike:.4} the first stance \
             holds its foot but its heel strike slides forward, the new foot keeping its speed \
             ({v_t:.4} m/s) to {:.0} %, and the next stance ends with it slid forward: \
             contact-inconsistent once the slide stops, or lambda-numerator-huge while it \
             slides.",
            EXACT.label(),
            100.0 * KEEPS_SPEED
        ),
        format!(
            "below {early:.4}: {} ({a_ok}); up to {late:.4}: {} ({b_ok}); up to {strike:.4}: \
             {} ({c_ok}; the new foot at {vlo:.4} to {vhi:.4} m/s)",
            names(&a),
            names(&b),
            names(&c)
        ),
        a_ok && b_ok && c_ok,
    ))
}

/// `|du| / |dv|`: the inputs' change over the command's when the torso rate changes by
/// [`NUDGE`] (the command changes by `K_D` times that), in the contact `contact`.
fn sensitivity(m: &Model, ix: &Index, t: f64, s: &Vector, contact: Contact) -> f64 {
    let mut ds = *s;
    ds[ix.n + ix.th_t] += NUDGE;
    let (u, du) = (
        m.control_input(t, s, contact),
        m.control_input(t, &ds, contact),
    );
    let d = u
        .iter()
        .zip(du.iter())
        .map(|(a, b)| (b - a) * (b - a))
        .sum::<f64>()
        .sqrt();
    d / (m.gains().1 * NUDGE)
}

/// The sweeps under `friction` in stance or under `impact`.
fn sweeps_with(run: &ModelRun, keep: impl Fn(&Laws) -> bool) -> Vec<&Sweep> {
    run.sweeps.iter().filter(|s| keep(&s.laws)).collect()
}

/// The tanh law cannot walk it: its sliding stance's `A` is singular in the first stance.
fn tanh(run: &ModelRun) -> Option<Claim> {
    let early = early_need(held(run)?);
    let stuck = model(run, EXACT, param(run, "mu0")?)?;
    let ix = Index::of(&stuck)?;
    let mut found = Vec::new();
    let (mut ok, mut n) = (true, 0);
    let mut ratios = Vec::new();
    let mut creeps = 0.0_f64;
    for s in sweeps_with(run, |l| l.friction == Friction::Tanh) {
        let pts = &s.chains[0];
        for p in pts {
            n += 1;
            let Some(f) = &p.failure else {
                ok = false;
                continue;
            };
            if p.value < early {
                // The tanh law cannot hold the foot either: it slides out as with Coulomb
                // friction.
                ok &= slides_out(p, &ix);
                continue;
            }
            let m = model(run, s.laws, p.value)?;
            let sliding = sensitivity(&m, &ix, f.t, &f.state, Contact::Smooth);
            let held = sensitivity(&stuck, &ix, f.t, &f.state, Contact::Stuck);
            let creep = f.state[ix.n].abs();
            ratios.push(sliding / held);
            creeps = creeps.max(creep);
            ok &= f.step == 0
                && f.name() == "lift-off"
                && f.state[ix.th_st] < 0.0
                && creep < CREEPS
                && sliding > SINGULAR * held;
        }
        found.push(format!("{}: {}", s.laws.label(), failures(pts)));
    }
    let (lo, hi) = span(ratios.iter().copied());
    let (tlo, thi) = span(
        sweeps_with(run, |l| l.friction == Friction::Tanh)
            .iter()
            .flat_map(|s| s.chains[0].iter())
            .filter_map(|p| p.failure.as_ref().map(|f| f.t)),
    );
    Some(Claim::new(
        format!(
            "three-link biped, level, the tanh law in stance (c = {}), with either impact: \
             every walk ends in its first stance, before mid-stance, by lift-off. Below the \
             {early:.4} the early stance needs, its foot slides out forward (faster than \
             {SLIDES_OUT} m/s), as with Coulomb friction. Above, the foot never sticks but \
             creeps (slower than {CREEPS} m/s), so the controller decouples the outputs with the \
             sliding stance's A, and that becomes singular (opposite torques on the two legs \
             move no output) where lambda changes sign through its pole: at the failure the \
             inputs' change over the command's (the torso rate nudged by {NUDGE:e} rad/s) \
             exceeds that of the same state with the foot stuck {SINGULAR:e} times.",
            param(run, "c")?
        ),
        format!(
            "{}; at t = {tlo:.4} to {thi:.4} s; above {early:.4} the foot creeps at up to \
             {creeps:.2e} m/s and the sensitivity is {lo:.2e} to {hi:.2e} times the stuck \
             foot's, over {n} walks",
            found.join("; ")
        ),
        ok && n > 0,
    ))
}

/// The frictionless impact cannot walk it: its grazing heel strike leaves both feet on the
/// floor.
fn frictionless(run: &ModelRun) -> Option<Claim> {
    let (h, _, ix) = held_model(run)?;
    let early = early_need(h);
    let pl = h.painleve;
    let mut ok = pl.double_support() && pl.normal_impulse.abs() <= TINY_IMPULSE * h.impulse[1];
    let mut found = Vec::new();
    for s in sweeps_with(run, |l| l.impact == ImpactLaw::Frictionless) {
        let pts = &s.chains[0];
        ok &= pts.iter().all(|p| {
            let Some(f) = &p.failure else { return false };
            if f.step != 0 {
                return false;
            }
            match s.laws.friction {
                // Where the stance holds the foot early on, the walk reaches the strike.
                Friction::Coulomb if p.value >= early => f.name() == "double-support",
                // Otherwise it ends before mid-stance (see the tanh law's claim and the bands
                // below the heel strike's friction).
                _ => f.name() == "lift-off" && f.state[ix.th_st] < 0.0,
            }
        });
        found.push(format!("{}: {}", s.laws.label(), failures(pts)));
    }
    Some(Claim::new(
        format!(
            "three-link biped, level, the paper's frictionless impact: it stops only the \
             striking foot's normal velocity, which at the grazing strike is nearly zero, so its \
             impulse is tiny (below {TINY_IMPULSE:e} of the sticking impact's {:.2} N s) and \
             does not lift the old stance foot: the walker stays in double support. Every walk \
             ends in its first step: with Coulomb friction in stance by double-support at the \
             first heel strike wherever the early stance holds the foot (mu0 >= {early:.4}), \
             before mid-stance by lift-off below that and under the tanh law.",
            h.impulse[1]
        ),
        format!(
            "at the held gait's strike Lambda_n = {:.3e} N s, the old foot's test impulse \
             {:+.3e} N s; {}",
            pl.normal_impulse,
            pl.rear_impulse,
            found.join("; ")
        ),
        ok,
    ))
}

/// A design's objective (the larger of the stance's KS aggregate and the strike's ratio) and
/// the held gait's own largest ratio agree to this: the aggregate over-estimates the stance's
/// maximum by at most 0.015 (`docs/design.md`), the strike's ratio is the same number.
const DESIGN_AGREES: f64 = 0.02;

/// The designed gait needs at least this much less friction than the hand-made one: a real
/// gain (`docs/design.md` found 0.18), not a rounding of the same gait.
const DESIGN_GAIN: f64 = 0.05;

/// The designed gait beside the hand-made one: it needs less friction, and the simulator alone
/// walks it held on a floor just above that need, where the hand-made gait's strike slips.
fn designed(run: &ModelRun) -> Option<Claim> {
    let d = run.designed.as_ref()?.as_ref().ok()?;
    let hand = held(run)?;
    let need = d.need();
    let held_steps = d.held_steps();
    let ok = need + DESIGN_GAIN <= hand.needs()
        && (d.held.needs() - need).abs() <= DESIGN_AGREES
        && d.walk.failure.is_none()
        && held_steps == STEPS
        && d.mu0 < hand.needs();
    Some(Claim::new(
        format!(
            "three-link biped, a designed gait (`walker design --objective friction`, varying \
             `T_set`, `th_T`, `beta`; docs/design.md): it needs at least {DESIGN_GAIN} less \
             friction than the hand-made gait, its held gait's own ratio is the design's to \
             {DESIGN_AGREES}, and the simulator alone walks it {STEPS} steps with the foot stuck \
             through every stance and every strike sticking on a floor of mu0 = need + {ABOVE}, \
             below what the hand-made gait needs."
        ),
        format!(
            "design {}, needs {need:.5} at {} (KKT residual {:.1e}, {} gait evaluations); its \
             held gait's ratio {:.5}; the walk at mu0 = {:.5}: {} of {} steps held{}; the \
             hand-made gait needs {:.4}",
            serde_json::to_value(d.design.status)
                .ok()
                .and_then(|v| v.as_str().map(str::to_owned))
                .unwrap_or_default(),
            d.parameters(),
            d.design.kkt_residual,
            d.design.evaluations,
            d.held.needs(),
            d.mu0,
            held_steps,
            d.walk.steps.len(),
            d.walk
                .failure
                .as_ref()
                .map_or_else(String::new, |f| format!(", then {}", f.name())),
            hand.needs()
        ),
        ok,
    ))
}

/// The three-link biped's claims, on its level floor.
#[must_use]
pub fn claims(run: &ModelRun) -> Vec<Claim> {
    vec![
        or_missing(
            gait(run),
            "three-link biped: the stable gait at the defaults",
        ),
        or_missing(
            threshold(run),
            "three-link biped: the heel strike's friction and where it walks",
        ),
        or_missing(below(run), "three-link biped: how it fails below"),
        or_missing(tanh(run), "three-link biped: the tanh law"),
        or_missing(
            frictionless(run),
            "three-link biped: the frictionless impact",
        ),
        or_missing(designed(run), "three-link biped: a designed gait"),
    ]
}

/// The failures of a sweep's points as ranges of `mu0` (`lift-off in step 0 for 0.02-0.14`).
fn failures(pts: &[SweepPoint]) -> String {
    describe(pts, |p| {
        p.failure
            .as_ref()
            .map(|f| format!("{} in step {}", f.name(), f.step))
    })
}
