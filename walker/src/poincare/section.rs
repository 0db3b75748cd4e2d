//! The section's reduced coordinates `r = (xd+, th1d+)`: the embedding of `r` into the full
//! post-impact state, its tangent, the reduction, and the reduced Jacobian `Pi DP E`.

use crate::model::{Kind, Model};

/// The state on the section with the reduced coordinates `r = (xd, th1d)` (see the module
/// documentation): the active walker's `[0, 0, -alpha/2, 0, xd, 0, th1d, th1d]`, the passive
/// wheel's `[0, 0, phi - alpha/2, 0, xd, -xd tan phi, th1d, 0]`.
pub fn embed(model: &Model, r: [f64; 2]) -> [f64; 8] {
    let th1 = model.rear_contact_angle();
    match model.kind() {
        Kind::ActiveLevel => [0.0, 0.0, th1, 0.0, r[0], 0.0, r[1], r[1]],
        Kind::PassiveSlope => [
            0.0,
            0.0,
            th1,
            0.0,
            r[0],
            -r[0] * model.runtime.phi.tan(),
            r[1],
            0.0,
        ],
    }
}

/// `d embed(r)_i / d r_j`.
pub fn embed_tangent(model: &Model) -> [[f64; 2]; 8] {
    let mut e = [[0.0; 2]; 8];
    e[4][0] = 1.0;
    e[6][1] = 1.0;
    match model.kind() {
        Kind::ActiveLevel => e[7][1] = 1.0,
        Kind::PassiveSlope => e[5][0] = -model.runtime.phi.tan(),
    }
    e
}

/// The reduced coordinates `(xd, th1d)` of a post-impact state.
pub fn reduce(s: &[f64; 8]) -> [f64; 2] {
    [s[4], s[6]]
}

/// The reduced map's Jacobian `Pi DP E` from the full one.
pub fn reduced_jacobian(model: &Model, full: &[[f64; 8]; 8]) -> [[f64; 2]; 2] {
    let e = embed_tangent(model);
    let mut out = [[0.0; 2]; 2];
    for (a, &row) in [4usize, 6].iter().enumerate() {
        for (b, o) in out[a].iter_mut().enumerate() {
            *o = (0..8).map(|k| full[row][k] * e[k][b]).sum();
        }
    }
    out
}
