//! The integrated state of a stance phase, `[q, qd, E]`: the mechanical state of a model with
//! `n` coordinates and the input-power quadrature `E`, in an array of `S = 2n + 1` numbers (the
//! integrators work on fixed-size arrays; [`with_state_size`] picks `S` for a model).

use crate::vector::Vector;

/// The mechanical part `[q, qd]` of an integrated state.
pub(super) fn mech<const S: usize>(y: &[f64; S]) -> Vector {
    Vector::from_slice(&y[..S - 1])
}

/// The integrated state of the mechanical state `s` (`2n` numbers) with `E = 0`.
pub(super) fn integrated<const S: usize>(s: &[f64]) -> [f64; S] {
    let mut y = [0.0; S];
    y[..S - 1].copy_from_slice(&s[..S - 1]);
    y
}

/// Whether every number of `v` is finite.
pub(super) fn finite(v: &[f64]) -> bool {
    v.iter().all(|x| x.is_finite())
}

/// Evaluates `$body` with the constant `$s` set to the integrated state's size `2 n + 1` for a
/// model with `$n` coordinates (3 to [`crate::vector::MAX_COORDINATES`]); `$other` for any
/// other `n`.
macro_rules! with_state_size {
    ($n:expr, $s:ident => $body:expr, _ => $other:expr) => {
        match $n {
            3 => {
                const $s: usize = 7;
                $body
            }
            4 => {
                const $s: usize = 9;
                $body
            }
            5 => {
                const $s: usize = 11;
                $body
            }
            6 => {
                const $s: usize = 13;
                $body
            }
            7 => {
                const $s: usize = 15;
                $body
            }
            8 => {
                const $s: usize = 17;
                $body
            }
            _ => $other,
        }
    };
}
pub(crate) use with_state_size;
