//! The generated `f32` kernels of the hopper against the closed forms of its physics, written
//! by hand here from the model file (a wheel of mass `m`, inertia `I` about its centre of mass,
//! which is `r = l - d` from the foot along the stance spoke):
//!
//! - `M = [[m, 0, m r cos th], [0, m, -m r sin th], [m r cos th, -m r sin th, I + m r^2]]`;
//! - with the foot held, a compound pendulum about the foot: `thdd = m g r sin th / (I + m r^2)`
//!   and the floor carries the weight plus the centripetal and tangential reactions, so that in
//!   the world frame `F = m (a_com) + m g e_z`.
//!
//! Tolerance: `1e-5` relative to the largest entry. Each output is a handful of `f32`
//! operations (machine epsilon `1.2e-7`), with no cancellation at these postures.

use approx::assert_relative_eq;
use own_walker::hopper::{Params, mass_matrix, prepare, stick};

const G: f32 = 9.81;

fn params() -> Params {
    Params {
        m: 3.0,
        i: 0.2,
        l: 0.8,
        d: 0.1,
        alpha: 0.5,
        phi: 0.1,
        mu0: 0.6,
        c: 100.0,
    }
}

#[test]
fn mass_matrix_is_the_rigid_wheels() {
    let p = params();
    let r = p.l - p.d;
    let prepared = prepare(&p);
    for th in [-0.3f32, 0.0, 0.2, 0.45] {
        let m = mass_matrix(&prepared, th);
        let (s, c) = th.sin_cos();
        let want = [
            [p.m, 0.0, p.m * r * c],
            [0.0, p.m, -p.m * r * s],
            [p.m * r * c, -p.m * r * s, p.i + p.m * r * r],
        ];
        for (row, want_row) in m.iter().zip(want) {
            for (got, want) in row.iter().zip(want_row) {
                assert_relative_eq!(*got, want, epsilon = 1e-5, max_relative = 1e-5);
            }
        }
    }
}

#[test]
fn with_the_foot_held_it_is_a_compound_pendulum() {
    let p = params();
    let r = p.l - p.d;
    let prepared = prepare(&p);
    for (th, thd) in [(0.1f32, 0.5f32), (-0.2, 1.2), (0.3, -0.4)] {
        let out = stick(&prepared, th, thd);
        let thdd = p.m * G * r * th.sin() / (p.i + p.m * r * r);
        assert_relative_eq!(out[0], 0.0);
        assert_relative_eq!(out[1], 0.0);
        assert_relative_eq!(out[2], thdd, max_relative = 1e-5);
        // The centre of mass at (r sin th, r cos th) from the foot: its acceleration, and the
        // floor's force F = m a + m g e_z, resolved along the slope's tangent
        // (cos phi, -sin phi) and normal (sin phi, cos phi).
        let (s, c) = th.sin_cos();
        let ax = r * (c * thdd - s * thd * thd);
        let az = r * (-s * thdd - c * thd * thd);
        let (fx, fz) = (p.m * ax, p.m * az + p.m * G);
        let (sp, cp) = p.phi.sin_cos();
        let scale = p.m * G;
        assert_relative_eq!(out[3], fx * cp - fz * sp, epsilon = 1e-5 * scale);
        assert_relative_eq!(out[4], fx * sp + fz * cp, epsilon = 1e-5 * scale);
    }
}
