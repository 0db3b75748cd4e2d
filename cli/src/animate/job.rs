//! The whole `walker animate` job: walk the model, sample the walk every `speed / fps` seconds
//! from the dense output ([`walker::sim::trajectory()`]), draw it in the requested format, write
//! the file, and say what was written ([`Written`]).

use std::path::{Path, PathBuf};

use serde::Serialize;
use walker::floor::FloorWalker;
use walker::model::Model;
use walker::sim::{SimConfig, Trajectory, WalkLimits, trajectory};

use super::caption::{failure_label, title, title_on_floor, title_on_patches};
use super::error::AnimateError;
use super::film::Film;
use super::gif::animated_gif;
use super::request::{Format, Length, MAX_STEPS, Request};
use super::strobe::{still, strobe_png, strobe_svg};
use super::svg::animated_svg;
use crate::input::InputError;

/// What `walker animate` wrote.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Written {
    /// The file.
    pub file: PathBuf,
    /// Its size (bytes).
    pub bytes: u64,
    /// Frames of the animation (poses of a stick diagram).
    pub frames: usize,
    /// Walk time between frames (s).
    pub dt: f64,
    /// Picture width (px).
    pub width: u32,
    /// Picture height (px).
    pub height: u32,
    /// Playback time of an animation, the hold at its end included (s; 0 for a stick diagram).
    pub playback: f64,
    /// Completed steps of the walk.
    pub steps: usize,
    /// Where the walk failed, in words, if it did.
    pub failure: Option<String>,
}

impl Written {
    /// One line for a person.
    #[must_use]
    pub fn text(&self) -> String {
        let mut s = format!(
            "wrote {} ({} bytes): {} frames every {:.4} s of the walk, {} x {} px",
            self.file.display(),
            self.bytes,
            self.frames,
            self.dt,
            self.width,
            self.height
        );
        if self.playback > 0.0 {
            s.push_str(&format!(", {:.2} s of playback", self.playback));
        }
        s.push_str(&format!("; {} steps", self.steps));
        if let Some(f) = &self.failure {
            s.push_str(&format!("; {f}"));
        }
        s.push('\n');
        s
    }
}

/// The walk of `model` from `initial` as `req` asks, sampled every `req.dt()`.
///
/// # Errors
/// A `--steps` walk that needs more frames than the format allows (the error names `--steps`).
pub fn sample(
    model: &Model,
    cfg: &SimConfig,
    initial: &[f64],
    req: &Request,
) -> Result<Trajectory, InputError> {
    sample_by(req, |limits, dt, frames| {
        Ok(trajectory(model, cfg, initial, limits, dt, frames))
    })
}

/// [`sample`] on a floor whose friction changes from step to step: walk 0 of `walker`'s floor
/// (a random floor's first stream), as `walker simulate --floor` walks it.
///
/// # Errors
/// As [`sample`], or a step's kernels cannot be prepared (named by `flag`).
pub fn sample_on_floor(
    walker: &FloorWalker<'_>,
    cfg: &SimConfig,
    initial: &[f64],
    req: &Request,
    flag: &str,
) -> Result<Trajectory, InputError> {
    sample_by(req, |limits, dt, frames| {
        walker
            .trajectory(0, cfg, initial, limits, dt, frames)
            .map_err(|e| InputError::new(flag, e.to_string()))
    })
}

/// The walk `walk(limits, dt, max_frames)` gives for `req`'s length, sampled every `req.dt()`.
fn sample_by(
    req: &Request,
    walk: impl FnOnce(&WalkLimits, f64, usize) -> Result<Trajectory, InputError>,
) -> Result<Trajectory, InputError> {
    let max = req.max_frames();
    let (limits, max_frames) = match req.length {
        Length::Steps(n) => (
            WalkLimits {
                max_steps: n,
                ..WalkLimits::default()
            },
            max,
        ),
        Length::Duration(d) => (
            WalkLimits {
                max_steps: MAX_STEPS,
                duration: d,
                ..WalkLimits::default()
            },
            // `Request::new` has checked that these are at most `max`.
            req.frames_for(d) as usize,
        ),
    };
    let tr = walk(&limits, req.dt(), max_frames)?;
    if let (Length::Steps(n), true) = (req.length, tr.truncated) {
        return Err(InputError::new(
            "steps",
            format!(
                "{n} steps take {:.1} s, more than the {max} frames a {} may have at --fps {} \
                 and --speed {} (fewer steps, a higher --speed or a lower --fps)",
                tr.end_time(),
                req.format.noun(),
                req.fps,
                req.speed
            ),
        ));
    }
    Ok(tr)
}

/// Draw `tr`, a walk of `model`, as `req` asks and write it to `req.output`.
///
/// # Errors
/// The file could not be drawn or written.
pub fn write(model: &Model, tr: &Trajectory, req: &Request) -> Result<Written, AnimateError> {
    write_on_floor(model, tr, req, &[], &[])
}

/// The friction under a drawn walk: by step, or by position along the floor.
#[derive(Clone, Copy, Debug)]
pub enum Drawn<'a> {
    /// Step `k` on `mu0[k]` (none drawn if empty) and, where `slopes` is not empty, on the
    /// slope `slopes[k]`.
    Steps {
        /// The friction coefficient of each step.
        mu0: &'a [f64],
        /// The slope of each step (rad), where the floor sets it.
        slopes: &'a [f64],
    },
    /// A floor of patches by position: its regions `(from, to, mu0)` along the floor (m).
    Regions(&'a [(f64, f64, f64)]),
}

/// [`write()`] for a walk on a floor whose step `k` has the friction coefficient `mu0[k]`
/// (drawn as patches under the floor line; none if `mu0` is empty) and, where `slopes` is not
/// empty, the slope `slopes[k]` (the floor drawn as the line of each step's slope through its
/// stance foot, [`Film::on_slopes`]).
///
/// # Errors
/// As [`write()`].
pub fn write_on_floor(
    model: &Model,
    tr: &Trajectory,
    req: &Request,
    mu0: &[f64],
    slopes: &[f64],
) -> Result<Written, AnimateError> {
    write_drawn(model, tr, req, Drawn::Steps { mu0, slopes })
}

/// [`write()`] for a walk on a floor of patches by position, whose regions are `(from, to,
/// mu0)` along the floor (m): each region in view drawn as a coloured band under the floor
/// line.
///
/// # Errors
/// As [`write()`].
pub fn write_on_patches(
    model: &Model,
    tr: &Trajectory,
    req: &Request,
    regions: &[(f64, f64, f64)],
) -> Result<Written, AnimateError> {
    write_drawn(model, tr, req, Drawn::Regions(regions))
}

/// [`write()`] with the floor's friction `drawn`.
fn write_drawn(
    model: &Model,
    tr: &Trajectory,
    req: &Request,
    drawn: Drawn<'_>,
) -> Result<Written, AnimateError> {
    let slopes = match drawn {
        Drawn::Steps { slopes, .. } => slopes,
        Drawn::Regions(_) => &[],
    };
    let title = title(model, req.speed);
    let film = Film::on_slopes(model, tr, req.speed, req.size, title, slopes).ok_or_else(|| {
        InputError::new(
            "model",
            format!(
                "model `{}` has no drawing: animations draw rimless wheels (parameters l and \
                 alpha) and stick figures of a model's [[point]]s (two of them on one link)",
                model.spec().name()
            ),
        )
    })?;
    // The title's ranges of mu0 and phi are the drawn steps', the ones the shades and the
    // floor's pieces span.
    let film = match drawn {
        Drawn::Steps { mu0: [], .. } => film,
        Drawn::Steps { mu0, slopes } => {
            let film = film.on_floor(mu0);
            let drawn = film.marks.last().map_or(0, |m| m.step + 1);
            let title = title_on_floor(
                model,
                req.speed,
                film.patches.iter().map(|p| p.mu0),
                slopes.iter().take(drawn).copied(),
            );
            Film { title, ..film }
        }
        Drawn::Regions(regions) => {
            let film = film.on_patches(regions);
            Film {
                title: title_on_patches(model, req.speed, film.patches.iter().map(|p| p.mu0)),
                ..film
            }
        }
    };
    let path = &req.output;
    let draw = |message: String| AnimateError::Draw {
        path: path.clone(),
        message,
    };
    let (film, playback) = match req.format {
        Format::Svg => {
            write_file(path, animated_svg(&film).as_bytes())?;
            let p = film.duration();
            (film, p)
        }
        Format::Gif => {
            write_file(path, &animated_gif(&film).map_err(draw)?)?;
            let p = film.duration();
            (film, p)
        }
        Format::StrobeSvg => {
            let f = still(&film);
            write_file(path, strobe_svg(&f).as_bytes())?;
            (f, 0.0)
        }
        Format::StrobePng => {
            let f = still(&film);
            strobe_png(&f, path).map_err(draw)?;
            (f, 0.0)
        }
    };
    let bytes = std::fs::metadata(path)
        .map_err(|source| AnimateError::Write {
            path: path.clone(),
            source,
        })?
        .len();
    Ok(Written {
        file: path.clone(),
        bytes,
        frames: film.frames.len(),
        dt: tr.dt,
        width: film.view.width,
        height: film.view.height,
        playback,
        steps: tr.walk.steps.len(),
        failure: failure_label(tr),
    })
}

/// Write `bytes` to `path`.
fn write_file(path: &Path, bytes: &[u8]) -> Result<(), AnimateError> {
    std::fs::write(path, bytes).map_err(|source| AnimateError::Write {
        path: path.to_owned(),
        source,
    })
}

/// Walk, sample, draw and write: the whole of `walker animate` for `model` from `initial`.
///
/// # Errors
/// As [`sample`] and [`write()`].
pub fn animate(
    model: &Model,
    cfg: &SimConfig,
    initial: &[f64],
    req: &Request,
) -> Result<Written, AnimateError> {
    let tr = sample(model, cfg, initial, req)?;
    write(model, &tr, req)
}
