//! [`Vector`]: a short vector of numbers stored inline, the type of every state, coordinate and
//! velocity list the library returns.
//!
//! A model has `n` coordinates (at most [`MAX_COORDINATES`]), so its mechanical state `[q, qd]`
//! has `2n` numbers; results hold many of them (every step of a walk, every sample), so they are
//! kept inline rather than on the heap: a `Vector` is `Copy`, derefs to a slice (`v[2]`,
//! `v.iter()`, `&v[..n]`) and is written to JSON as an array, as the fixed-size arrays of the
//! paper's walker were. Written by hand because the crates that do this (arrayvec, smallvec)
//! are not `Copy`.

use std::fmt;
use std::ops::{Deref, DerefMut};

use serde::{Serialize, Serializer};

/// The most coordinates a model may have in the simulator (the five-link biped has seven): the
/// loader's limit, so that a model with more is refused at load.
pub const MAX_COORDINATES: usize = walker_scene::limits::MAX_COORDINATES;

/// The most numbers a [`Vector`] holds: a mechanical state `[q, qd]` of [`MAX_COORDINATES`].
pub const MAX_LEN: usize = 2 * MAX_COORDINATES;

/// A vector of at most [`MAX_LEN`] numbers, stored inline.
#[derive(Clone, Copy)]
pub struct Vector {
    len: usize,
    data: [f64; MAX_LEN],
}

impl Vector {
    /// The empty vector.
    pub const EMPTY: Vector = Vector {
        len: 0,
        data: [0.0; MAX_LEN],
    };

    /// `len` zeros (at most [`MAX_LEN`]; longer is cut to it).
    #[must_use]
    pub fn zeros(len: usize) -> Vector {
        Vector {
            len: len.min(MAX_LEN),
            ..Vector::EMPTY
        }
    }

    /// The numbers of `values` (at most [`MAX_LEN`] of them; more are cut off).
    #[must_use]
    pub fn from_slice(values: &[f64]) -> Vector {
        let mut v = Vector::zeros(values.len());
        let n = v.len;
        v.data[..n].copy_from_slice(&values[..n]);
        v
    }

    /// `a` followed by `b` (cut to [`MAX_LEN`]).
    #[must_use]
    pub fn concat(a: &[f64], b: &[f64]) -> Vector {
        let mut v = Vector::from_slice(a);
        for &x in b {
            v.push(x);
        }
        v
    }

    /// Appends `x` (ignored when full).
    pub fn push(&mut self, x: f64) {
        if self.len < MAX_LEN {
            self.data[self.len] = x;
            self.len += 1;
        }
    }

    /// The numbers.
    #[must_use]
    pub fn as_slice(&self) -> &[f64] {
        &self.data[..self.len]
    }

    /// The first half and the second half (`[q, qd]` of a mechanical state).
    #[must_use]
    pub fn halves(&self) -> (&[f64], &[f64]) {
        self.as_slice().split_at(self.len / 2)
    }
}

impl Default for Vector {
    fn default() -> Vector {
        Vector::EMPTY
    }
}

impl Deref for Vector {
    type Target = [f64];
    fn deref(&self) -> &[f64] {
        &self.data[..self.len]
    }
}

impl DerefMut for Vector {
    fn deref_mut(&mut self) -> &mut [f64] {
        &mut self.data[..self.len]
    }
}

impl PartialEq for Vector {
    fn eq(&self, other: &Vector) -> bool {
        self.as_slice() == other.as_slice()
    }
}

impl fmt::Debug for Vector {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.as_slice().fmt(f)
    }
}

impl Serialize for Vector {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.as_slice().serialize(s)
    }
}

impl<'a> IntoIterator for &'a Vector {
    type Item = &'a f64;
    type IntoIter = std::slice::Iter<'a, f64>;
    fn into_iter(self) -> Self::IntoIter {
        self.as_slice().iter()
    }
}

impl From<&[f64]> for Vector {
    fn from(values: &[f64]) -> Vector {
        Vector::from_slice(values)
    }
}

impl<const K: usize> From<[f64; K]> for Vector {
    fn from(values: [f64; K]) -> Vector {
        Vector::from_slice(&values)
    }
}

impl<const K: usize> PartialEq<[f64; K]> for Vector {
    fn eq(&self, other: &[f64; K]) -> bool {
        self.as_slice() == other.as_slice()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_vector_is_its_numbers_and_nothing_beyond_them() {
        let v = Vector::from_slice(&[1.0, 2.0, 3.0]);
        assert_eq!(v.len(), 3);
        assert_eq!(v, [1.0, 2.0, 3.0]);
        assert_ne!(v, Vector::from_slice(&[1.0, 2.0]));
        assert_eq!(
            serde_json::to_string(&v).ok().as_deref(),
            Some("[1.0,2.0,3.0]")
        );
        let v = Vector::concat(&[1.0, 2.0], &[3.0, 4.0]);
        assert_eq!(v.halves(), (&[1.0, 2.0][..], &[3.0, 4.0][..]));
    }

    #[test]
    fn a_full_vector_keeps_its_first_max_len_numbers() {
        let long: Vec<f64> = (0..MAX_LEN + 3).map(|k| k as f64).collect();
        let mut v = Vector::from_slice(&long);
        v.push(99.0);
        assert_eq!(v.len(), MAX_LEN);
        assert_eq!(v.as_slice(), &long[..MAX_LEN]);
    }
}
