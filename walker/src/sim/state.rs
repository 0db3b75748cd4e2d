//! The integrated state of a stance phase: `[x, z, th1, th2, xd, zd, th1d, th2d, E]`, the
//! mechanical state and the input-power quadrature `E`.

/// Size of the integrated state (8 mechanical components and the input-power quadrature).
pub const N: usize = 9;

/// The mechanical part `[x, z, th1, th2, xd, zd, th1d, th2d]` of an integrated state.
pub(super) fn mech(y: &[f64; N]) -> [f64; 8] {
    let mut s = [0.0; 8];
    s.copy_from_slice(&y[..8]);
    s
}

/// Whether every number of `v` is finite.
pub(super) fn finite(v: &[f64]) -> bool {
    v.iter().all(|x| x.is_finite())
}
