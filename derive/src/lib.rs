//! `walker-symbolic`: a focused computer-algebra engine and the Lagrangian mechanics of planar
//! walkers on slippery ground: the underactuated rimless wheel with torso (Asano, Kikuchi,
//! Shibata), and any walker of a model file.
//!
//! - [`budget`]: the bound on one derivation's work;
//! - [`symbol`]: a model's symbol table (symbols and base angles are indices into it) and the
//!   self-describing atom slots of a monomial;
//! - [`poly`], [`ratfunc`]: the canonical form, polynomials in symbols and in sines and cosines
//!   of base angles reduced by `cos^2 = 1 - sin^2`, and quotients of them with cancellation;
//! - [`matrix`]: small symbolic matrices (products, Jacobians, inverses by the adjugate);
//! - [`trig`]: sines and cosines of sums of angles by the addition formulas;
//! - [`kernels`]: the kernel as data, what the code generator reads;
//! - [`model`]: any model file's symbols, mechanics, phases and kernels, derived from its
//!   energies and geometry;
//! - [`paper`]: the paper's walker in its own notation, its quantities taken from its model
//!   files by [`model`], and its named kernels ([`Derivation`]);
//! - [`latex`]: readable mathematics for people.

pub mod budget;
pub mod error;
pub mod kernels;
pub mod latex;
pub mod matrix;
pub mod model;
pub mod paper;
pub mod poly;
pub mod ratfunc;
pub mod symbol;
pub mod trig;

pub use error::{Error, Result};
pub use kernels::{Kernel, Shape, Staged};
pub use matrix::Matrix;
pub use paper::Derivation;
pub use poly::{Poly, Q};
pub use ratfunc::RatFunc;
pub use symbol::{Atom, BaseAngle, Sym};
