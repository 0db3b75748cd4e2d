//! The swing foot's height above the floor, for the clearance constraint: the model's striking
//! point (`[strike] point`, the foot that becomes the next stance foot) measured normal to the
//! floor line through the stance foot, and the test that refuses a walker whose striking point
//! is fixed to the stance foot (a rimless wheel's next spoke: no swing foot to lift).

use crate::model::Model;

/// The profile of the clearance constraint at the normalised stance time `s = t / T`: `4 s (1
/// - s)`, 0 where the swing foot leaves the floor (`s = 0`) and where it strikes (`s = 1`), 1
///   at mid-stance. The constraint asks for a height of at least `H` times it.
#[must_use]
pub fn clearance_profile(s: f64) -> f64 {
    4.0 * s * (1.0 - s)
}

/// The height of the striking point above the floor at the coordinates `q`, normal to the floor
/// line through the stance foot `(q[0], q[1])`: `(x_p - x) sin(phi) + (z_p - z) cos(phi)` for a
/// floor of slope `phi` descending towards `+x` (`z_p - z` on a level floor). The model's strike
/// guard is this height only for a model that leaves `[strike] guard` out; the shipped bipeds
/// give an angle there (the three-link biped's `beta - th_st`), so the height is read from the
/// `points` kernel.
#[must_use]
pub fn swing_height(model: &Model, q: &[f64]) -> f64 {
    let (x, z) = strike_point(model, q);
    let (s, c) = model.phi().sin_cos();
    (x - q[0]) * s + (z - q[1]) * c
}

/// The striking point at `q`.
fn strike_point(model: &Model, q: &[f64]) -> (f64, f64) {
    let mut p = [0.0; 2 * walker_scene::limits::MAX_POINTS];
    let k = model
        .spec()
        .model
        .points
        .len()
        .min(walker_scene::limits::MAX_POINTS);
    model.points(q, &mut p[..2 * k]);
    let i = model.spec().strike_point;
    (p[2 * i], p[2 * i + 1])
}

/// The coordinates' offsets (rad, or m for a length) at which [`rigid_strike_point`] moves each
/// coordinate past the stance foot's from the model's start configuration.
const PROBES: [f64; 2] = [0.1, 0.25];

/// Why the walker has no swing foot, or `None` where it has one: the striking point's distance
/// from the stance foot is the same (to `1e-9` relative) at the model's start configuration and
/// with each coordinate after the stance foot's moved by 0.1 and by 0.25 in turn, so that it is
/// fixed to the stance foot's body (a rimless wheel's next spoke, the paper's walker's fore
/// foot). There the clearance is the spokes' geometry at the stance leg's angle, which no
/// controller shapes: a bound on it would be a bound on the stance angle's timing, not on a
/// foot's lift.
#[must_use]
pub fn rigid_strike_point(model: &Model) -> Option<String> {
    let n = model.n();
    let q0: Vec<f64> = model.start_state().as_slice()[..n].to_vec();
    let distance = |q: &[f64]| {
        let (x, z) = strike_point(model, q);
        (x - q[0]).hypot(z - q[1])
    };
    let d0 = distance(&q0);
    let moves = (2..n).any(|i| {
        PROBES.iter().any(|dq| {
            let mut q = q0.clone();
            q[i] += dq;
            (distance(&q) - d0).abs() > 1e-9 * (1.0 + d0)
        })
    });
    (!moves).then(|| {
        let point = &model.spec().model.points[model.spec().strike_point].name.name;
        format!(
            "its striking point `{point}` stays {d0:.6} m from the stance foot in every posture (fixed to the stance body, as a rimless wheel's next spoke), so no controller lifts it"
        )
    })
}
