//! The stick figure of a walker that is not a rimless wheel (a biped of a model file: the
//! compass gait, the three- and five-link bipeds, a user's own): lines between the stance foot
//! and the model's `[[point]]`s, one wherever two of them lie on one rigid link.
//!
//! The links are read from the model's own geometry, not declared: two drawn points are joined
//! where the vector between them turns with one coordinate at most (a thigh from hip to knee
//! turns with the thigh's angle only; hip to foot turns with two). This is probed at the
//! model's start posture, moving each coordinate by 0.1 and by 0.25 in turn (as the design's
//! swing-foot test does, `walker::design::rigid_strike_point`), so a model file needs nothing
//! more than the points it already names to be drawn.

use walker::model::Model;
use walker::sim::Frame;
use walker_scene::limits::MAX_POINTS;

use super::geometry::Point;

/// The coordinates' offsets (rad, or m for a length) the links are probed with.
const PROBES: [f64; 2] = [0.1, 0.25];

/// A vector between two points counts as moved by a probe above this (m, relative to `1 +`
/// its length): rounding of the points' kernel, far below any link's motion.
const MOVED: f64 = 1e-9;

/// The drawn points (0 the stance foot, `k` the model's point `k - 1`) and the lines between
/// them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Sticks {
    /// How many of the model's points are drawn (all, up to [`MAX_POINTS`]).
    points: usize,
    /// The lines, as pairs of drawn points.
    pub links: Vec<(usize, usize)>,
}

impl Sticks {
    /// The stick figure of `model`; `None` for a model without points, or whose points no line
    /// joins.
    #[must_use]
    pub fn of(model: &Model) -> Option<Self> {
        let points = model.spec().model.points.len().min(MAX_POINTS);
        let n = model.n();
        let q0: Vec<f64> = model.start_state().as_slice()[..n].to_vec();
        let at = |q: &[f64]| positions(model, points, q);
        let p0 = at(&q0);
        // The points with coordinate `i` moved by each probe, `i`'s at `i * PROBES.len()`.
        let moved: Vec<Vec<Point>> = (0..n)
            .flat_map(|i| {
                PROBES.map(|dq| {
                    let mut q = q0.clone();
                    q[i] += dq;
                    at(&q)
                })
            })
            .collect();
        let mut links = Vec::new();
        for a in 0..=points {
            for b in a + 1..=points {
                let d0 = sub(p0[b], p0[a]);
                let length = d0.0.hypot(d0.1);
                if length <= MOVED {
                    continue;
                }
                let turns = (0..n)
                    .filter(|i| {
                        moved[i * PROBES.len()..(i + 1) * PROBES.len()]
                            .iter()
                            .any(|p| {
                                let d = sub(p[b], p[a]);
                                (d.0 - d0.0).hypot(d.1 - d0.1) > MOVED * (1.0 + length)
                            })
                    })
                    .count();
                if turns <= 1 {
                    links.push((a, b));
                }
            }
        }
        (!links.is_empty()).then_some(Self { points, links })
    }

    /// The drawing's scale `l` (m; the wheel's radius for a rimless wheel): the largest
    /// distance from the figure's centre ([`Sticks::pose`]'s camera point) to a drawn point at
    /// the model's start posture, over 0.6, so that the views, which keep `0.65 l` above the
    /// centre for a wheel and its torso, hold the figure whole.
    #[must_use]
    pub fn scale(&self, model: &Model) -> f64 {
        let n = model.n();
        let start = model.start_state();
        let (centre, p) = self.centred(model, &start.as_slice()[..n]);
        let reach = p
            .iter()
            .map(|&x| {
                let v = sub(x, centre);
                v.0.hypot(v.1)
            })
            .fold(0.0, f64::max);
        if reach > 0.0 { reach / 0.6 } else { 1.0 }
    }

    /// The lines at `frame`, and the point the camera follows: the middle of the drawn
    /// points' extent.
    #[must_use]
    pub fn pose(&self, model: &Model, frame: &Frame) -> (Vec<(Point, Point)>, Point) {
        let (centre, p) = self.centred(model, &frame.state.as_slice()[..model.n()]);
        let lines = self.links.iter().map(|&(a, b)| (p[a], p[b])).collect();
        (lines, centre)
    }

    /// The middle of the drawn points' extent at the coordinates `q`, and the points.
    fn centred(&self, model: &Model, q: &[f64]) -> (Point, Vec<Point>) {
        let p = positions(model, self.points, q);
        let (mut lo, mut hi) = (p[0], p[0]);
        for &(x, z) in &p {
            lo = (lo.0.min(x), lo.1.min(z));
            hi = (hi.0.max(x), hi.1.max(z));
        }
        ((0.5 * (lo.0 + hi.0), 0.5 * (lo.1 + hi.1)), p)
    }
}

/// The stance foot `(q[0], q[1])` and the model's first `points` points at the coordinates `q`.
fn positions(model: &Model, points: usize, q: &[f64]) -> Vec<Point> {
    let mut out = [0.0; 2 * MAX_POINTS];
    model.points(q, &mut out[..2 * points]);
    std::iter::once((q[0], q[1]))
        .chain((0..points).map(|k| (out[2 * k], out[2 * k + 1])))
        .collect()
}

/// `a - b`.
fn sub(a: Point, b: Point) -> Point {
    (a.0 - b.0, a.1 - b.1)
}
