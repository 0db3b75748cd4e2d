//! The floor's contact geometry: a point's signed distance from the floor and its coordinate
//! along it, whose gradients are the unit normal and the unit tangent.

use crate::ratfunc::RatFunc;
use crate::symbol::BaseAngle;
use walker_scene::Floor;

/// Signed distance of a point `(x, z)` from the floor: `z` on level ground,
/// `z cos phi + x sin phi` on the slope `z = -x tan phi`. Its gradient is the unit normal.
pub fn floor_gap(floor: Floor, x: &RatFunc, z: &RatFunc) -> RatFunc {
    match floor {
        Floor::Level => z.clone(),
        Floor::Slope => {
            &(z * &RatFunc::cos_of(BaseAngle::Phi)) + &(x * &RatFunc::sin_of(BaseAngle::Phi))
        }
    }
}

/// The foot's coordinate along the floor: `x` on level ground, `x cos phi - z sin phi` on the
/// slope (along the unit tangent `(cos phi, -sin phi)`, positive down the slope).
pub fn floor_tangent(floor: Floor, x: &RatFunc, z: &RatFunc) -> RatFunc {
    match floor {
        Floor::Level => x.clone(),
        Floor::Slope => {
            &(x * &RatFunc::cos_of(BaseAngle::Phi)) - &(z * &RatFunc::sin_of(BaseAngle::Phi))
        }
    }
}
