//! What every picture of a walk is drawn from ([`Film`]): the frames of a sampled walk with the
//! walker's pose in each, the slip marks the stance feet have left on the floor by then, the
//! camera, the captions and the playback timing. The writers (SVG, GIF, stick diagram) only
//! draw what is here.

use walker::model::Model;
use walker::sim::{Frame, Trajectory};

use super::caption::failure_label;
use super::geometry::{Body, Point, Pose};
use super::view::View;

/// The slip mark of one stance foot: the stretch of floor its foot has slid over, as distances
/// along the floor `x / cos phi` (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mark {
    /// The step whose stance foot left the mark.
    pub step: usize,
    /// Where the foot landed.
    pub landed: f64,
    /// The rearmost point reached so far.
    pub lo: f64,
    /// The foremost point reached so far.
    pub hi: f64,
}

/// A walk ready to be drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    /// The walker's drawn body and floor.
    pub body: Body,
    /// The camera and picture size.
    pub view: View,
    /// The frames, every `dt` of walk time, and, if the walk failed, the frame at its failure.
    pub frames: Vec<Frame>,
    /// The pose at each frame.
    pub poses: Vec<Pose>,
    /// The slip mark of each frame's stance foot, as far as it has come by that frame.
    pub marks: Vec<Mark>,
    /// The line printed above the walker (which walker, its parameters).
    pub title: String,
    /// Where the walk failed, if it did ([`failure_label`]).
    pub failure: Option<String>,
    /// Playback speed (walk seconds per second of playback).
    pub speed: f64,
    /// Playback time the last frame is held before the animation repeats (s).
    pub hold: f64,
}

impl Film {
    /// The film of `tr`, a walk of `model`, played at `speed` times real time in pictures of
    /// `width x height` pixels; `None` for a model without a drawing ([`Body::of`]).
    #[must_use]
    pub fn new(
        model: &Model,
        tr: &Trajectory,
        speed: f64,
        (width, height): (u32, u32),
        title: String,
    ) -> Option<Self> {
        let body = Body::of(model)?;
        let mut frames = tr.frames.clone();
        if let Some(ff) = tr.failure_frame
            && frames.last().is_none_or(|last| ff.time > last.time)
        {
            frames.push(ff);
        }
        let poses: Vec<Pose> = frames.iter().map(|f| body.pose(f)).collect();
        let hubs: Vec<Point> = poses.iter().map(|p| p.hub).collect();
        let view = View::new(&body, &hubs, width, height);
        let along = 1.0 / body.phi.cos();
        let mut marks: Vec<Mark> = Vec::with_capacity(tr.frames.len());
        for f in &frames {
            let s = f.state[0] * along;
            let mark = match marks.last() {
                Some(m) if m.step == f.step => Mark {
                    lo: m.lo.min(s),
                    hi: m.hi.max(s),
                    ..*m
                },
                _ => Mark {
                    step: f.step,
                    landed: s,
                    lo: s,
                    hi: s,
                },
            };
            marks.push(mark);
        }
        Some(Film {
            body,
            view,
            frames,
            poses,
            marks,
            title,
            failure: failure_label(tr),
            speed,
            hold: 1.0,
        })
    }

    /// The last slip mark of every step up to frame `i` (the marks on the floor then).
    #[must_use]
    pub fn marks_at(&self, i: usize) -> Vec<Mark> {
        let mut out: Vec<Mark> = Vec::new();
        for m in self.marks.iter().take(i.saturating_add(1)) {
            match out.last_mut() {
                Some(last) if last.step == m.step => *last = *m,
                _ => out.push(*m),
            }
        }
        out
    }

    /// Playback time of frame `i` since the first frame (s).
    #[must_use]
    pub fn playback_time(&self, i: usize) -> f64 {
        let t0 = self.frames.first().map_or(0.0, |f| f.time);
        self.frames
            .get(i)
            .map_or(0.0, |f| (f.time - t0) / self.speed)
    }

    /// Total playback time (s): the frames and the hold at the end.
    #[must_use]
    pub fn duration(&self) -> f64 {
        self.playback_time(self.frames.len().saturating_sub(1)) + self.hold
    }
}
