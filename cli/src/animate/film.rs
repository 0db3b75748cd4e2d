//! What every picture of a walk is drawn from ([`Film`]): the frames of a sampled walk with the
//! walker's pose in each, the slip marks the stance feet have left on the floor by then, the
//! camera, the captions and the playback timing. The writers (SVG, GIF, stick diagram) only
//! draw what is here.

use walker::model::Model;
use walker::sim::{Frame, Trajectory};

use super::caption::{failure_label, mu0_range};
use super::floor_line::FloorLine;
use super::geometry::{Body, Point, Pose};
use super::sticks::Sticks;
use super::view::View;

/// The slip mark of one stance foot: the stretch of floor its foot has slid over, as positions
/// along the floor ([`FloorLine::s`]; `x / cos phi` on one slope, m).
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

/// The floor under one step's stance foot on a floor whose friction changes from step to step
/// (`walker animate --floor`): centred on where the foot landed, reaching halfway to the
/// neighbouring steps' landings, as positions along the floor ([`FloorLine::s`], m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Patch {
    /// The step (`None` for a patch of a floor of patches by position, [`Film::on_patches`]).
    pub step: Option<usize>,
    /// Where the patch begins.
    pub from: f64,
    /// Where it ends.
    pub to: f64,
    /// The step's friction coefficient.
    pub mu0: f64,
    /// Its shade: 0 at the walk's lowest `mu0` (icy), 1 at its highest (dry).
    pub dry: f64,
}

impl Patch {
    /// The colour of a patch of shade `dry`: from ice blue (0) to earth brown (1).
    #[must_use]
    pub fn colour(dry: f64) -> (u8, u8, u8) {
        const ICE: (f64, f64, f64) = (90.0, 165.0, 235.0);
        const DRY: (f64, f64, f64) = (165.0, 120.0, 75.0);
        let d = dry.clamp(0.0, 1.0);
        let mix = |a: f64, b: f64| (a + (b - a) * d).round() as u8;
        (mix(ICE.0, DRY.0), mix(ICE.1, DRY.1), mix(ICE.2, DRY.2))
    }
}

/// A walk ready to be drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    /// The walker's drawn body (its slope `phi` the model's own).
    pub body: Body,
    /// The floor under the walk: the model's slope, or a slope per step.
    pub floor: FloorLine,
    /// The camera and picture size.
    pub view: View,
    /// The frames, every `dt` of walk time, and, if the walk failed, the frame at its failure.
    pub frames: Vec<Frame>,
    /// The pose at each frame.
    pub poses: Vec<Pose>,
    /// The slip mark of each frame's stance foot, as far as it has come by that frame.
    pub marks: Vec<Mark>,
    /// The floor's patches, one per step, where its friction changes from step to step (empty
    /// on a uniform floor; [`Film::on_floor`]).
    pub patches: Vec<Patch>,
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
    /// `width x height` pixels: a rimless wheel ([`Body::of`]), else a stick figure of the
    /// model's points ([`Sticks`]); `None` for a model that is neither.
    #[must_use]
    pub fn new(
        model: &Model,
        tr: &Trajectory,
        speed: f64,
        size: (u32, u32),
        title: String,
    ) -> Option<Self> {
        Self::on_slopes(model, tr, speed, size, title, &[])
    }

    /// [`Film::new`] on a floor whose step `k` has the slope `slopes[k]` (rad; the steps of
    /// `tr` and the one it failed in, if it did): each step on the line of its slope through
    /// its stance foot where the slope changed, as the simulator walks it (`walker::floor`),
    /// and the ground reaction drawn normal and along that line. Empty `slopes`: the model's
    /// own slope.
    #[must_use]
    pub fn on_slopes(
        model: &Model,
        tr: &Trajectory,
        speed: f64,
        (width, height): (u32, u32),
        title: String,
        slopes: &[f64],
    ) -> Option<Self> {
        let (body, sticks) = match Body::of(model) {
            Some(wheel) => (wheel, None),
            None => {
                let s = Sticks::of(model)?;
                (Body::of_sticks(model, s.scale(model)), Some(s))
            }
        };
        let mut frames = tr.frames.clone();
        if let Some(ff) = tr.failure_frame
            && frames.last().is_none_or(|last| ff.time > last.time)
        {
            frames.push(ff);
        }
        let mut floor = FloorLine::straight(body.phi);
        for (k, &phi) in slopes.iter().enumerate() {
            let foot = match k.checked_sub(1) {
                None => frames.first().map(|f| (f.state[0], f.state[1])),
                Some(j) => tr.walk.steps.get(j).map(|r| (r.q_plus[0], r.q_plus[1])),
            };
            if let Some(foot) = foot {
                floor = floor.then(foot, phi);
            }
        }
        let poses: Vec<Pose> = frames
            .iter()
            .map(|f| {
                let body = Body {
                    phi: slopes.get(f.step).copied().unwrap_or(body.phi),
                    ..body
                };
                match &sticks {
                    Some(s) => {
                        let (lines, hub) = s.pose(model, f);
                        body.stick_pose(f, lines, hub)
                    }
                    None => body.pose(f),
                }
            })
            .collect();
        let hubs: Vec<Point> = poses.iter().map(|p| p.hub).collect();
        let view = View::new(&body, &hubs, width, height);
        let mut marks: Vec<Mark> = Vec::with_capacity(tr.frames.len());
        for f in &frames {
            let s = floor.s(f.state[0]);
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
            floor,
            view,
            frames,
            poses,
            marks,
            patches: Vec::new(),
            title,
            failure: failure_label(tr),
            speed,
            hold: 1.0,
        })
    }

    /// This film on a floor whose step `k` has the friction coefficient `mu0[k]`: a patch per
    /// drawn step, shaded from the lowest `mu0` of the drawn steps to the highest.
    #[must_use]
    pub fn on_floor(mut self, mu0: &[f64]) -> Self {
        let mut landed: Vec<(usize, f64)> = Vec::new();
        for m in &self.marks {
            if landed.last().is_none_or(|l| l.0 != m.step) {
                landed.push((m.step, m.landed));
            }
        }
        let (lo, hi) = mu0_range(landed.iter().filter_map(|&(k, _)| mu0.get(k).copied()));
        let l = self.body.l;
        for (i, &(step, s)) in landed.iter().enumerate() {
            let Some(&value) = mu0.get(step) else {
                continue;
            };
            let back = i.checked_sub(1).map(|j| 0.5 * (s - landed[j].1));
            let ahead = landed.get(i + 1).map(|n| 0.5 * (n.1 - s));
            let (back, ahead) = match (back, ahead) {
                (Some(b), Some(a)) => (b, a),
                (Some(b), None) => (b, b.max(l)),
                (None, Some(a)) => (a.max(l), a),
                (None, None) => (l, l),
            };
            self.patches.push(Patch {
                step: Some(step),
                from: s - back,
                to: s + ahead,
                mu0: value,
                dry: if hi > lo {
                    (value - lo) / (hi - lo)
                } else {
                    1.0
                },
            });
        }
        self
    }

    /// This film on a floor of patches by position: `regions` are `(from, to, mu0)` along the
    /// floor (m, `from` or `to` infinite at the outer ends), drawn where they meet the stretch
    /// the walk covers (from a leg's length before its first landing to one after its last),
    /// shaded from the lowest `mu0` drawn to the highest.
    #[must_use]
    pub fn on_patches(mut self, regions: &[(f64, f64, f64)]) -> Self {
        let l = self.body.l;
        let (first, last) = self
            .marks
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), m| {
                (a.min(m.lo), b.max(m.hi))
            });
        let (first, last) = if first <= last {
            (first - 2.0 * l, last + 2.0 * l)
        } else {
            (-2.0 * l, 2.0 * l)
        };
        let shown: Vec<(f64, f64, f64)> = regions
            .iter()
            .filter(|r| r.1 > first && r.0 < last)
            .map(|&(a, b, m)| (a.max(first), b.min(last), m))
            .collect();
        let (lo, hi) = mu0_range(shown.iter().map(|r| r.2));
        for (from, to, mu0) in shown {
            self.patches.push(Patch {
                step: None,
                from,
                to,
                mu0,
                dry: if hi > lo { (mu0 - lo) / (hi - lo) } else { 1.0 },
            });
        }
        self
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
