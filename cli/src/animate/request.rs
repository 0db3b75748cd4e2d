//! What `walker animate` is asked for ([`Request`]): how long a walk, how fast it plays, how
//! many frames a second, which file, checked against the bounds below (a bad value is an
//! [`InputError`] naming the flag and its valid range, exit code 2). The bounds keep every
//! request's time, memory and file size modest.

use std::path::{Path, PathBuf};

use crate::input::{InputError, check};

/// The most steps a walk may be asked for (`--steps`), and the most a `--duration` walk takes.
pub const MAX_STEPS: usize = 1000;
/// The longest walk (`--duration`, s).
pub const MAX_DURATION: f64 = 600.0;
/// The slowest and fastest playback (`--speed`, walk seconds per second of playback).
pub const SPEED_RANGE: (f64, f64) = (0.01, 100.0);
/// The fewest and most frames per second of playback (`--fps`): GIF delays are whole
/// centiseconds and browsers play delays below 2 cs slowly, so at most 50.
pub const FPS_RANGE: (f64, f64) = (1.0, 50.0);
/// The most frames of an animated SVG: each costs about 400 bytes (measured 410 for a 40-step
/// walk of 330 frames; a 6-step walk at 30 fps is about 100 frames and 34 KB), so an SVG stays
/// below about 1.3 MB.
pub const MAX_SVG_FRAMES: usize = 3000;
/// The most poses of a stick diagram.
pub const MAX_STROBE_POSES: usize = 400;
/// The picture size of the animations (px).
pub const SIZE: (u32, u32) = (640, 360);
/// The default number of steps.
pub const DEFAULT_STEPS: usize = 6;
/// The default frames per second of an animation.
pub const DEFAULT_FPS: f64 = 30.0;
/// The default poses per second of playback of a stick diagram (at speed 1, a pose every
/// 0.1 s of the walk).
pub const DEFAULT_STROBE_FPS: f64 = 10.0;

/// How long the walk is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Length {
    /// This many steps (or fewer, if the walk fails).
    Steps(usize),
    /// This long (s; or shorter, if the walk fails).
    Duration(f64),
}

/// What is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// An animated SVG (SMIL).
    Svg,
    /// An animated GIF.
    Gif,
    /// A stick diagram as SVG.
    StrobeSvg,
    /// A stick diagram as PNG.
    StrobePng,
}

impl Format {
    /// The format of `path` by its extension (`.svg`, `.gif`; with `strobe`, `.svg`, `.png`).
    ///
    /// # Errors
    /// Another extension (the error names `--output`).
    pub fn of(path: &Path, strobe: bool) -> Result<Self, InputError> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match (ext.as_deref(), strobe) {
            (Some("svg"), false) => Ok(Format::Svg),
            (Some("gif"), false) => Ok(Format::Gif),
            (Some("svg"), true) => Ok(Format::StrobeSvg),
            (Some("png"), true) => Ok(Format::StrobePng),
            (_, false) => Err(InputError::new(
                "output",
                format!("{}: must be FILE.svg or FILE.gif", path.display()),
            )),
            (_, true) => Err(InputError::new(
                "output",
                format!(
                    "{}: must be FILE.svg or FILE.png with --strobe",
                    path.display()
                ),
            )),
        }
    }

    /// Whether this is a stick diagram.
    #[must_use]
    pub fn is_strobe(self) -> bool {
        matches!(self, Format::StrobeSvg | Format::StrobePng)
    }

    /// The most frames (animations) or poses (stick diagrams) of this format in pictures of
    /// `size`: [`MAX_SVG_FRAMES`], [`super::gif::MAX_GIF_PIXELS`] over the pixels of a frame,
    /// [`MAX_STROBE_POSES`].
    #[must_use]
    pub fn max_frames(self, size: (u32, u32)) -> usize {
        match self {
            Format::Svg => MAX_SVG_FRAMES,
            Format::Gif => {
                let px = u64::from(size.0) * u64::from(size.1);
                usize::try_from(super::gif::MAX_GIF_PIXELS / px.max(1)).unwrap_or(usize::MAX)
            }
            Format::StrobeSvg | Format::StrobePng => MAX_STROBE_POSES,
        }
    }
}

/// A checked request of `walker animate`.
#[derive(Clone, Debug, PartialEq)]
pub struct Request {
    /// How long the walk is.
    pub length: Length,
    /// Playback speed (walk seconds per second of playback).
    pub speed: f64,
    /// Frames (poses, for a stick diagram) per second of playback.
    pub fps: f64,
    /// The file written.
    pub output: PathBuf,
    /// What is written.
    pub format: Format,
    /// Picture size of an animation (px).
    pub size: (u32, u32),
}

impl Request {
    /// The request of the flags `--steps`, `--duration`, `--speed`, `--fps`, `--output` and
    /// `--strobe` (at most one of `steps` and `duration`; neither: [`DEFAULT_STEPS`]).
    ///
    /// # Errors
    /// A value outside its range (the error names the flag and the range), an output that is
    /// not a `.svg`, `.gif` or (with `--strobe`) `.png` file, or a `--duration` that needs more
    /// frames than the format allows.
    pub fn new(
        steps: Option<usize>,
        duration: Option<f64>,
        speed: f64,
        fps: Option<f64>,
        output: &Path,
        strobe: bool,
    ) -> Result<Self, InputError> {
        let format = Format::of(output, strobe)?;
        let (s0, s1) = SPEED_RANGE;
        check(
            "speed",
            speed,
            (s0..=s1).contains(&speed),
            &format!("in [{s0}, {s1}]"),
        )?;
        let (f0, f1) = FPS_RANGE;
        let fps = fps.unwrap_or(if strobe {
            DEFAULT_STROBE_FPS
        } else {
            DEFAULT_FPS
        });
        check(
            "fps",
            fps,
            (f0..=f1).contains(&fps),
            &format!("in [{f0}, {f1}]"),
        )?;
        let length = match (steps, duration) {
            (Some(_), Some(_)) => {
                return Err(InputError::new(
                    "duration",
                    "give --steps or --duration, not both",
                ));
            }
            (Some(n), None) if n == 0 || n > MAX_STEPS => {
                return Err(InputError::new(
                    "steps",
                    format!("{n}: must be in [1, {MAX_STEPS}]"),
                ));
            }
            (Some(n), None) => Length::Steps(n),
            (None, Some(d)) => Length::Duration(check(
                "duration",
                d,
                d > 0.0 && d <= MAX_DURATION,
                &format!("in (0, {MAX_DURATION}]"),
            )?),
            (None, None) => Length::Steps(DEFAULT_STEPS),
        };
        let req = Request {
            length,
            speed,
            fps,
            output: output.to_owned(),
            format,
            size: SIZE,
        };
        if let Length::Duration(d) = length {
            let need = req.frames_for(d);
            let max = req.max_frames();
            if need > max as f64 {
                return Err(InputError::new(
                    "duration",
                    format!(
                        "{d} s at --fps {fps} and --speed {speed} needs {need} frames; a {} has \
                         at most {max} (a shorter walk, a higher --speed or a lower --fps)",
                        req.format.noun()
                    ),
                ));
            }
        }
        Ok(req)
    }

    /// Walk time between frames (s): `speed / fps`.
    #[must_use]
    pub fn dt(&self) -> f64 {
        self.speed / self.fps
    }

    /// Frames at `0, dt, ..` up to `time` (s) of walk.
    #[must_use]
    pub fn frames_for(&self, time: f64) -> f64 {
        (time / self.dt() + 1e-9).floor() + 1.0
    }

    /// The most frames (or poses) of this request's format.
    #[must_use]
    pub fn max_frames(&self) -> usize {
        self.format.max_frames(self.size)
    }
}

impl Format {
    /// What the format makes, in words.
    #[must_use]
    pub fn noun(self) -> &'static str {
        match self {
            Format::Svg => "SVG animation",
            Format::Gif => "GIF animation",
            Format::StrobeSvg | Format::StrobePng => "stick diagram",
        }
    }
}
