//! The camera: which part of the world (m) a picture of `width x height` pixels shows, and
//! where a world point lands in it. A short walk is shown whole (the camera stands still); a
//! walk longer than the picture's width follows the hub.

use super::geometry::{Body, Point};

/// How many leg lengths `l` the picture spans horizontally.
pub const SPAN_LEGS: f64 = 7.0;

/// Pixels of a picture and the world window it shows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// Width (px).
    pub width: u32,
    /// Height (px).
    pub height: u32,
    /// Pixels per metre.
    pub scale: f64,
    /// Whether the camera follows the hub (else it stands still at [`View::fixed`]).
    pub follow: bool,
    /// The world point at the picture's centre when the camera stands still.
    pub fixed: Point,
    /// The pixel row of the centre's height (the hub sits there when followed).
    pub top: f64,
}

impl View {
    /// The view of a walk of `body` whose hub moves over `hubs` (world points), in a picture
    /// of `width x height` pixels: `SPAN_LEGS` leg lengths across; standing still at the middle
    /// of the walk if the hub's path fits into the middle two thirds, else following the hub.
    #[must_use]
    pub fn new(body: &Body, hubs: &[Point], width: u32, height: u32) -> Self {
        let span = SPAN_LEGS * body.l;
        let scale = f64::from(width) / span;
        let (lo, hi) = hubs
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(p.0), b.max(p.0))
            });
        let (zlo, zhi) = hubs
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(p.1), b.max(p.1))
            });
        let fits = hi - lo <= span * 2.0 / 3.0 - 2.0 * body.l
            && zhi - zlo <= f64::from(height) / scale / 3.0;
        let mid = if lo.is_finite() {
            ((lo + hi) / 2.0, (zlo + zhi) / 2.0)
        } else {
            (0.0, body.l)
        };
        View {
            width,
            height,
            scale,
            follow: !fits,
            fixed: mid,
            top: f64::from(height) * 0.45,
        }
    }

    /// A still view of the whole walk (for a stick diagram), `width` pixels wide: the hub's
    /// path with a leg and a third of margin on every side, the height to match.
    #[must_use]
    pub fn fit(body: &Body, hubs: &[Point], width: u32) -> Self {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        let (mut zlo, mut zhi) = (f64::INFINITY, f64::NEG_INFINITY);
        for p in hubs {
            (lo, hi) = (lo.min(p.0), hi.max(p.0));
            (zlo, zhi) = (zlo.min(p.1), zhi.max(p.1));
        }
        if !lo.is_finite() {
            (lo, hi, zlo, zhi) = (0.0, 0.0, body.l, body.l);
        }
        let margin = 1.3 * body.l;
        let span = (hi - lo + 2.0 * margin).max(4.0 * body.l);
        let scale = f64::from(width) / span;
        // Room for three lines of captions and the torso above the highest hub, for the legs
        // and the floor's hatching below the lowest.
        let top = 70.0 + 0.65 * body.l * scale;
        let below = (zhi - zlo + 1.2 * body.l) * scale;
        let height = (top + below).ceil().clamp(100.0, 4000.0) as u32;
        View {
            width,
            height,
            scale,
            follow: false,
            fixed: ((lo + hi) / 2.0, zhi),
            top,
        }
    }

    /// The world point at the picture's centre when the hub is at `hub`.
    #[must_use]
    pub fn centre(&self, hub: Point) -> Point {
        if self.follow { hub } else { self.fixed }
    }

    /// Where the world point `p` lands in pixels (`y` down) with the camera centred at
    /// `centre`, which lands at row [`View::top`].
    #[must_use]
    pub fn to_px(&self, centre: Point, p: Point) -> (f64, f64) {
        (
            f64::from(self.width) / 2.0 + (p.0 - centre.0) * self.scale,
            self.top - (p.1 - centre.1) * self.scale,
        )
    }

    /// The world `x` range visible with the camera centred at `centre`.
    #[must_use]
    pub fn x_range(&self, centre: Point) -> (f64, f64) {
        let half = f64::from(self.width) / 2.0 / self.scale;
        (centre.0 - half, centre.0 + half)
    }
}
