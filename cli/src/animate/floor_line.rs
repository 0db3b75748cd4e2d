//! The drawn floor ([`FloorLine`]): the line of the model's slope through the origin, or, on a
//! floor that sets the slope per step (`walker animate --floor` with `phi`), a broken line of
//! pieces, one from each step's stance foot whose slope differs from the step before (the
//! floor the simulator walks there: `walker::floor`, "A slope per step").
//!
//! Positions along the floor `s` (m; the slip marks and the patches are kept in them) are the
//! length of floor from `x = 0`: `x / cos phi` on one line through the origin. A piece through
//! the origin computes every position with the arithmetic of that one line, so a floor of one
//! slope is drawn to the bit as before there were pieces.

use super::geometry::Point;

/// One straight piece of floor: from its corner `(x, z)` on (and, for the first, also before
/// it), falling at the slope `phi` towards `+x`; `s` is the position along the floor of the
/// corner.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Piece {
    x: f64,
    z: f64,
    s: f64,
    phi: f64,
}

impl Piece {
    fn z(&self, x: f64) -> f64 {
        self.z - (x - self.x) * self.phi.tan()
    }

    fn s(&self, x: f64) -> f64 {
        self.s + (x - self.x) * (1.0 / self.phi.cos())
    }

    fn x_at(&self, s: f64) -> f64 {
        self.x + (s - self.s) * self.phi.cos()
    }
}

/// The floor under a walk, in world coordinates (m, `x` forward, `z` up): pieces of straight
/// floor in order of `x`, the first reaching back without end, the last forward.
#[derive(Clone, Debug, PartialEq)]
pub struct FloorLine {
    pieces: Vec<Piece>,
}

impl FloorLine {
    /// The line of slope `phi` (rad; the floor `z = -x tan phi`) through the origin.
    #[must_use]
    pub fn straight(phi: f64) -> Self {
        FloorLine {
            pieces: vec![Piece {
                x: 0.0,
                z: 0.0,
                s: 0.0,
                phi,
            }],
        }
    }

    /// This floor, from the point `(x, z)` on it on, falling at the slope `phi`: a new piece
    /// where `phi` differs from the slope there (none where it is the same, so that a floor of
    /// one slope stays one line). A corner at or behind an earlier one (a walker that fell
    /// back) replaces the floor from there on.
    #[must_use]
    pub fn then(mut self, (x, z): Point, phi: f64) -> Self {
        while self.pieces.len() > 1 && self.pieces.last().is_some_and(|p| p.x >= x) {
            self.pieces.pop();
        }
        let here = *self.piece(x);
        if phi.to_bits() != here.phi.to_bits() {
            self.pieces.push(Piece {
                x,
                z,
                s: here.s(x),
                phi,
            });
        }
        self
    }

    /// Whether the floor is one straight line.
    #[must_use]
    pub fn is_straight(&self) -> bool {
        self.pieces.len() == 1
    }

    /// The piece under `x`: the last whose corner is at or behind it, else the first.
    fn piece(&self, x: f64) -> &Piece {
        let i = self.pieces.iter().rposition(|p| p.x <= x).unwrap_or(0);
        &self.pieces[i]
    }

    /// The piece at the position along the floor `s`.
    fn piece_at(&self, s: f64) -> &Piece {
        let i = self.pieces.iter().rposition(|p| p.s <= s).unwrap_or(0);
        &self.pieces[i]
    }

    /// The floor's height at `x` (m).
    #[must_use]
    pub fn z(&self, x: f64) -> f64 {
        self.piece(x).z(x)
    }

    /// The slope of the floor at `x` (rad).
    #[must_use]
    pub fn phi(&self, x: f64) -> f64 {
        self.piece(x).phi
    }

    /// The position along the floor of the point of it at `x` (m).
    #[must_use]
    pub fn s(&self, x: f64) -> f64 {
        self.piece(x).s(x)
    }

    /// The `x` of the position along the floor `s` (m).
    #[must_use]
    pub fn x_at(&self, s: f64) -> f64 {
        self.piece_at(s).x_at(s)
    }

    /// The point of the floor at the position along it `s`.
    #[must_use]
    pub fn point_at(&self, s: f64) -> Point {
        let p = self.piece_at(s);
        let d = s - p.s;
        (p.x + d * p.phi.cos(), p.z + d * -p.phi.sin())
    }

    /// The floor from `x0` to `x1` as a broken line: its points at `x0`, at each corner
    /// between (where a piece after the first begins), and at `x1`.
    #[must_use]
    pub fn between(&self, x0: f64, x1: f64) -> Vec<Point> {
        let mut out = vec![(x0, self.z(x0))];
        out.extend(
            self.pieces
                .iter()
                .skip(1)
                .filter(|p| p.x > x0 && p.x < x1)
                .map(|p| (p.x, p.z)),
        );
        out.push((x1, self.z(x1)));
        out
    }

    /// The pieces as `(corner, corner's position along the floor, slope)`, in order.
    pub fn pieces(&self) -> impl Iterator<Item = (Point, f64, f64)> + '_ {
        self.pieces.iter().map(|p| ((p.x, p.z), p.s, p.phi))
    }
}

#[cfg(test)]
mod tests {
    use super::FloorLine;

    /// One slope through the origin is the line `z = -x tan phi` with `s = x / cos phi` in
    /// the same arithmetic; a second slope from a point on it starts a piece there, continuous in `z`
    /// and in `s`.
    #[test]
    fn pieces_join_where_the_slope_changes() {
        let phi = 0.1_f64;
        let one = FloorLine::straight(phi);
        for x in [-2.0, 0.0, 0.7, 3.0] {
            // Equal as numbers (a zero's sign aside, which the drawing writes as `0`).
            assert_eq!(one.z(x), -x * phi.tan());
            assert_eq!(one.s(x), x * (1.0 / phi.cos()));
        }
        let corner = (1.0, one.z(1.0));
        let two = one.clone().then(corner, 0.1).then(corner, 0.3);
        assert!(one.then(corner, 0.1).is_straight());
        assert_eq!(two.pieces().count(), 2);
        assert_eq!(two.z(0.5), FloorLine::straight(phi).z(0.5));
        assert!((two.z(1.0) - corner.1).abs() <= 1e-15);
        assert!((two.z(2.0) - (corner.1 - 0.3_f64.tan())).abs() <= 1e-15);
        let s = two.s(2.0);
        assert!((s - (1.0 / phi.cos() + 1.0 / 0.3_f64.cos())).abs() <= 1e-14);
        assert!((two.x_at(s) - 2.0).abs() <= 1e-14);
        let p = two.point_at(s);
        assert!((p.0 - 2.0).abs() <= 1e-14 && (p.1 - two.z(2.0)).abs() <= 1e-14);
        assert_eq!(two.between(0.0, 3.0).len(), 3);
        assert_eq!(FloorLine::straight(phi).between(-1.0, 1.0).len(), 2);
        // A corner behind the last replaces the floor from there on.
        let back = two.then((0.5, FloorLine::straight(phi).z(0.5)), 0.2);
        assert_eq!(back.pieces().map(|p| p.2).collect::<Vec<_>>(), [0.1, 0.2]);
    }
}
