//! The animations of `walker reproduce` ([`write_animations`]): Fig. 5's gait (the active
//! walker at `mu0 = 0.4`, `T_set = 0.3`, `omega0 = 0.8`, six steps, as the figure's walk) and
//! the passive wheel falling backward (Fig. 14: `phi = 0.10`, `mu0 = 0.19`, `omega0 = 0.5`),
//! each as an animated SVG and GIF, and Fig. 14 also as a stick diagram (SVG and PNG), as the
//! paper prints it.

use std::path::Path;

use walker::model::Model;
use walker::sim::SimConfig;

use super::error::WriteError;
use super::models::{active, passive, start};
use crate::animate::{AnimateError, Request, animate};

/// One picture: the file name, the walk's steps, the playback speed, frames (poses) per second
/// of playback and whether it is a stick diagram.
struct Picture {
    name: &'static str,
    steps: usize,
    speed: f64,
    fps: f64,
    strobe: bool,
}

/// The pictures of Fig. 5's gait.
const FIG5: [Picture; 2] = [
    Picture {
        name: "fig5_animation.svg",
        steps: 6,
        speed: 1.0,
        fps: 30.0,
        strobe: false,
    },
    Picture {
        name: "fig5_animation.gif",
        steps: 6,
        speed: 1.0,
        fps: 25.0,
        strobe: false,
    },
];

/// The pictures of Fig. 14's fall, played at half speed (the fall takes under a second).
const FIG14: [Picture; 4] = [
    Picture {
        name: "fig14_animation.svg",
        steps: 5,
        speed: 0.5,
        fps: 30.0,
        strobe: false,
    },
    Picture {
        name: "fig14_animation.gif",
        steps: 5,
        speed: 0.5,
        fps: 25.0,
        strobe: false,
    },
    Picture {
        name: "fig14_strobe.svg",
        steps: 5,
        speed: 1.0,
        fps: 20.0,
        strobe: true,
    },
    Picture {
        name: "fig14_strobe.png",
        steps: 5,
        speed: 1.0,
        fps: 20.0,
        strobe: true,
    },
];

/// The picture `p` of `model`'s walk from `omega0`, written into `out`.
fn draw(out: &Path, model: &Model, omega0: f64, p: &Picture) -> Result<(), WriteError> {
    let path = out.join(p.name);
    let err = |e: AnimateError| match e {
        AnimateError::Write { path, source } => WriteError::File { path, source },
        AnimateError::Draw { path, message } => WriteError::Figure { path, message },
        AnimateError::Input(e) => WriteError::Figure {
            path: path.clone(),
            message: e.to_string(),
        },
    };
    let req = Request::new(Some(p.steps), None, p.speed, Some(p.fps), &path, p.strobe)
        .map_err(|e| err(e.into()))?;
    let cfg = SimConfig::default();
    animate(model, &cfg, &start(model, omega0)?, &req).map_err(err)?;
    Ok(())
}

/// Write the animations of Figs. 5 and 14 into `out`.
///
/// # Errors
/// A file could not be drawn or written (the error names it).
pub fn write_animations(out: &Path) -> Result<(), WriteError> {
    let fig5 = active(0.4, 0.3)?;
    for p in &FIG5 {
        draw(out, &fig5, 0.8, p)?;
    }
    let fig14 = passive(0.19, 0.10)?;
    for p in &FIG14 {
        draw(out, &fig14, 0.5, p)?;
    }
    Ok(())
}
