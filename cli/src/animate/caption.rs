//! The words drawn on an animation: the step counter and the time of a frame, the walk's
//! description ([`title`]), and where the walk failed (the failure's name, step and moment).

use walker::model::{FrictionLaw, Model};
use walker::sim::{Frame, Trajectory};

/// The label of `frame`: its step (counted from 1 as a person counts) and its time since the
/// start of the walk, to `decimals` decimals.
#[must_use]
pub fn frame_label(frame: &Frame, decimals: usize) -> String {
    format!("step {}, t = {:.*} s", frame.step + 1, decimals, frame.time)
}

/// The failure's name, step and moment (time since the start of the walk and since the step's
/// impact), if the walk failed.
#[must_use]
pub fn failure_label(tr: &Trajectory) -> Option<String> {
    tr.walk.failure.as_ref().map(|f| {
        format!(
            "{} in step {} at t = {:.3} s ({:.3} s after its impact)",
            f.name(),
            f.step + 1,
            tr.end_time(),
            f.t
        )
    })
}

/// The legend of the forces and the slip trace.
pub const LEGEND: &str = "blue: normal force, red: friction, orange: slip of the stance foot (a force of m_t g is l/2 long)";

/// The line above the walker: which walker, its friction and control settings, the playback
/// speed.
#[must_use]
pub fn title(model: &Model, speed: f64) -> String {
    title_with(model, speed, &format!("mu0 = {}", model.mu0()), None)
}

/// The smallest and the largest of `values` (infinities of the wrong sign if there are none).
#[must_use]
pub fn mu0_range(values: impl IntoIterator<Item = f64>) -> (f64, f64) {
    values
        .into_iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x), b.max(x))
        })
}

/// [`title`] for a walk on a floor whose drawn steps have the friction coefficients `mu0`:
/// their range and the colours of its ends; and, where the floor sets the slope, the range of
/// the drawn steps' slopes `phi` (none given: the model's own slope).
#[must_use]
pub fn title_on_floor(
    model: &Model,
    speed: f64,
    mu0: impl IntoIterator<Item = f64>,
    phi: impl IntoIterator<Item = f64>,
) -> String {
    let (lo, hi) = mu0_range(mu0);
    let text = if hi > lo {
        format!("mu0 by step from {lo} (blue) to {hi} (brown)")
    } else {
        format!("mu0 = {lo}")
    };
    let (a, b) = mu0_range(phi);
    let floor = match (a.is_finite(), b > a) {
        (false, _) => None,
        (true, true) => Some(format!("slope phi by step from {a} to {b} rad")),
        (true, false) => Some(format!("slope phi = {a} rad")),
    };
    title_with(model, speed, &text, floor)
}

/// [`title`] for a walk on a floor of patches by position whose drawn patches have the
/// friction coefficients `mu0`: their range and the colours of its ends.
#[must_use]
pub fn title_on_patches(model: &Model, speed: f64, mu0: impl IntoIterator<Item = f64>) -> String {
    let (lo, hi) = mu0_range(mu0);
    let text = if hi > lo {
        format!("mu0 by position from {lo} (blue) to {hi} (brown)")
    } else {
        format!("mu0 = {lo}")
    };
    title_with(model, speed, &text, None)
}

/// The title with the friction coefficient given as `mu0`, and the floor as `floor` (`None`:
/// the model's own slope, or the level floor).
fn title_with(model: &Model, speed: f64, mu0: &str, floor: Option<String>) -> String {
    let law = match model.friction_law() {
        FrictionLaw::Tanh => format!("{mu0}, c = {} s/m", model.sharpness()),
        FrictionLaw::Coulomb => format!("Coulomb friction, {mu0}"),
    };
    let floor = floor.unwrap_or_else(|| {
        if model.spec().slope.is_some() {
            format!("slope phi = {} rad", model.phi())
        } else {
            "level floor".to_owned()
        }
    });
    let ramp = model
        .ramps_end()
        .map_or_else(String::new, |t| format!(", T_set = {t} s"));
    let walker = format!(
        "{}, {floor}{ramp}",
        model
            .spec()
            .model
            .title
            .as_deref()
            .unwrap_or(model.spec().name())
    );
    let speed = if (speed - 1.0).abs() < 1e-12 {
        "real time".to_owned()
    } else {
        format!("{speed}x real time")
    };
    format!("{walker}, {law}; {speed}")
}
