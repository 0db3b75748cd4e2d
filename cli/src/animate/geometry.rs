//! The drawn walker in world coordinates (metres, `x` forward, `z` up), computed from its
//! parameters and one [`Frame`]: the rimless wheel's spokes, the torso, the stance foot, the
//! ground reaction's normal and friction parts (the floor is `super::floor_line`'s). The
//! positions follow `docs/kernels.md`: the hub is at `(x + l sin th1, z + l cos th1)`, spoke
//! `k` ends at `hub - l (sin(th1 - k alpha), cos(th1 - k alpha))` (`k = 0` the stance foot,
//! `k = 1` the fore foot of the `fore_foot` kernel), and the torso, of length `2 r` (Fig. 1), is
//! centred at the hub at the angle `th2` from the horizontal.

use std::f64::consts::TAU;

use walker::model::Model;
use walker::sim::Frame;

/// The most spokes drawn: `2 pi / alpha` of them, at most this many (`alpha` is in `(0, pi)`;
/// below `2 pi / 360` the wheel is drawn as 360 spokes).
pub const MAX_SPOKES: usize = 360;

/// The longest drawn force, in leg lengths (a force of 6 `m_t g`).
pub const MAX_FORCE_LEGS: f64 = 3.0;

/// A point `(x, z)` in world coordinates (m).
pub type Point = (f64, f64);

/// What is drawn of a walker, fixed over a walk: its size and the floor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body {
    /// Leg length (the wheel's radius) `l` (m).
    pub l: f64,
    /// Angle between neighbouring spokes `alpha` (rad).
    pub alpha: f64,
    /// Number of spokes drawn: `2 pi / alpha` rounded down, at most [`MAX_SPOKES`].
    pub spokes: usize,
    /// Half the torso's drawn length `r` (m): the paper's Table 1 gives no `r` (only `I2`), so
    /// the torso is drawn with `r = 0.6 l`, as long as the spokes are together.
    pub r: f64,
    /// Slope angle `phi` (rad; 0 on level ground) of the floor under the stance foot, whose
    /// normal and tangent the ground reaction is drawn along.
    pub phi: f64,
    /// The walker's weight `m_t g` (N), the scale of the drawn forces.
    pub weight: f64,
}

impl Body {
    /// The drawn body of `model`: a rimless wheel of radius `l` and spokes `alpha` apart
    /// (the model's parameters of these names), its stance spoke at the third coordinate and
    /// its torso, if it has a fourth coordinate, at that angle from the horizontal; `None` for
    /// a model without `l` and `alpha`.
    #[must_use]
    pub fn of(model: &Model) -> Option<Self> {
        let (l, alpha) = (model.params().get("l")?, model.params().get("alpha")?);
        let spokes = (TAU / alpha + 1e-9).floor();
        let spokes = if spokes.is_finite() && spokes >= 1.0 {
            (spokes as usize).min(MAX_SPOKES)
        } else {
            MAX_SPOKES
        };
        Some(Body {
            l,
            alpha,
            spokes,
            r: if model.n() > 3 { 0.6 * l } else { 0.0 },
            phi: model.phi(),
            weight: model.total_mass() * model.gravity(),
        })
    }

    /// Unit vector along the floor, towards `+x` (down the slope).
    #[must_use]
    pub fn tangent(&self) -> Point {
        (self.phi.cos(), -self.phi.sin())
    }

    /// Unit normal of the floor, pointing up out of it.
    #[must_use]
    pub fn normal(&self) -> Point {
        (self.phi.sin(), self.phi.cos())
    }

    /// Drawn length of a force of one weight `m_t g` (m): half a leg.
    #[must_use]
    pub fn force_scale(&self) -> f64 {
        0.5 * self.l / self.weight
    }

    /// The drawn length (m, signed) of a force component `f` (N): [`Body::force_scale`] times
    /// it, at most [`MAX_FORCE_LEGS`] leg lengths either way (where `lambda` blows up, a
    /// failure, the arrow stays in the picture); 0 if `f` is not finite.
    #[must_use]
    pub fn drawn_force(&self, f: f64) -> f64 {
        let max = MAX_FORCE_LEGS * self.l;
        if f.is_finite() {
            (f * self.force_scale()).clamp(-max, max)
        } else {
            0.0
        }
    }

    /// The walker at `frame`.
    #[must_use]
    pub fn pose(&self, frame: &Frame) -> Pose {
        let (x, z, th1) = (frame.state[0], frame.state[1], frame.state[2]);
        let th2 = if frame.state.len() > 6 {
            frame.state[3]
        } else {
            0.0
        };
        let hub = (x + self.l * th1.sin(), z + self.l * th1.cos());
        let spokes = (0..self.spokes)
            .map(|k| {
                let a = th1 - k as f64 * self.alpha;
                (hub.0 - self.l * a.sin(), hub.1 - self.l * a.cos())
            })
            .collect();
        let (c, s) = (th2.cos(), th2.sin());
        let torso = [
            (hub.0 - self.r * c, hub.1 - self.r * s),
            (hub.0 + self.r * c, hub.1 + self.r * s),
        ];
        let (n, t) = (self.normal(), self.tangent());
        let normal = self.drawn_force(frame.reaction.normal);
        let friction = self.drawn_force(frame.reaction.tangential);
        Pose {
            hub,
            foot: (x, z),
            spokes,
            torso,
            rotation: -(th1 + frame.step as f64 * self.alpha),
            normal_force: (n.0 * normal, n.1 * normal),
            friction_force: (t.0 * friction, t.1 * friction),
            sticks: Vec::new(),
        }
    }

    /// The drawn body of a stick figure (`sticks.rs`) of scale `l`: no
    /// spokes and no torso of its own (its links are drawn instead), on `model`'s floor.
    #[must_use]
    pub fn of_sticks(model: &Model, l: f64) -> Self {
        Body {
            l,
            alpha: TAU,
            spokes: 0,
            r: 0.0,
            phi: model.phi(),
            weight: model.total_mass() * model.gravity(),
        }
    }

    /// The stick figure's pose at `frame`: its `lines` and the camera's point `hub` (from
    /// `Sticks::pose`), the stance foot and the ground reaction as for a
    /// wheel.
    #[must_use]
    pub fn stick_pose(&self, frame: &Frame, lines: Vec<(Point, Point)>, hub: Point) -> Pose {
        Pose {
            hub,
            spokes: Vec::new(),
            torso: [hub, hub],
            rotation: 0.0,
            sticks: lines,
            ..self.pose(frame)
        }
    }
}

/// The walker at one moment, in world coordinates (m).
#[derive(Clone, Debug, PartialEq)]
pub struct Pose {
    /// The hub (the hip, `x_h, z_h`), where the torso's centre is.
    pub hub: Point,
    /// The stance foot `(x, z)`.
    pub foot: Point,
    /// The spokes' ends, the stance foot first, then the fore foot, then on round the wheel.
    pub spokes: Vec<Point>,
    /// The torso's two ends.
    pub torso: [Point; 2],
    /// The wheel body's rotation (rad, counterclockwise positive) from the pose in which its
    /// spoke 0 points straight down: `-(th1 + s alpha)` at step `s`, continuous across impacts
    /// (spoke `s` of the body is the stance leg of step `s`).
    pub rotation: f64,
    /// The normal part of the ground reaction as a drawn vector from the foot (m).
    pub normal_force: Point,
    /// The friction part of the ground reaction as a drawn vector from the foot (m).
    pub friction_force: Point,
    /// A stick figure's links, each from one point to another (empty for a rimless wheel).
    pub sticks: Vec<(Point, Point)>,
}

impl Pose {
    /// The legs a stick diagram draws: the stance leg, the fore leg and the rear leg (the spoke
    /// behind the stance leg, which the wheel falls back onto), fewer if the wheel has fewer
    /// spokes.
    #[must_use]
    pub fn stick_legs(&self) -> Vec<Point> {
        let n = self.spokes.len();
        let mut idx = vec![0, 1, n.saturating_sub(1)];
        idx.retain(|&k| k < n);
        idx.dedup();
        idx.iter().map(|&k| self.spokes[k]).collect()
    }
}
