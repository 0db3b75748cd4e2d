//! `walker-symbolic`: a focused computer-algebra engine and the Lagrangian mechanics of planar
//! walkers on slippery ground: the underactuated rimless wheel with torso (Asano, Kikuchi,
//! Shibata), and any walker of a model file.
//!
//! - [`symbol`]: a model's symbol table (symbols and base angles are indices into it) and the
//!   self-describing atom slots of a monomial;
//! - [`poly`], [`ratfunc`]: the canonical form, polynomials in symbols and in sines and cosines
//!   of base angles reduced by `cos^2 = 1 - sin^2`, and quotients of them with cancellation;
//! - [`matrix`]: small symbolic matrices (products, Jacobians, inverses by the adjugate);
//! - [`mechanics`]: the walker written once, physically, and every quantity of the paper
//!   derived from it;
//! - [`kernels`]: the derived quantities as named kernels for the code generator;
//! - [`model`]: any model file's symbols, mechanics, phases and kernels, derived the same way;
//! - [`latex`]: readable mathematics for people.

pub mod error;
pub mod kernels;
pub mod latex;
pub mod matrix;
pub mod mechanics;
pub mod model;
pub mod poly;
pub mod ratfunc;
pub mod symbol;
pub mod trig;

pub use error::{Error, Result};
pub use kernels::{Derivation, Kernel, Shape, Staged};
pub use matrix::Matrix;
pub use poly::{Poly, Q};
pub use ratfunc::RatFunc;
pub use symbol::{Atom, BaseAngle, Sym};
