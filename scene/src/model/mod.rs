//! Model files: a planar walker as data (`docs/model-format.md`), parsed once into a typed,
//! checked [`Model`].
//!
//! [`parse`] reads expressions into the [`expr`] AST (exact numbers, symbols, `+ - * / ^`,
//! `sin`, `cos`); [`angles`] reads `sin`/`cos` arguments as angle combinations and finds each
//! angle's base-angle divisor; [`interval`] reads parameter ranges; [`Model::from_file`] and
//! [`Model::from_toml`] load a file, and every [`ModelError`] names the file, line and column.
//!
//! ```
//! use walker_scene::model::Model;
//! let m = Model::from_toml(include_str!("../../../models/paper-passive.toml"), "paper-passive.toml")?;
//! assert_eq!(m.base_angle_divisor("alpha"), Some(2));
//! # Ok::<(), walker_scene::model::ModelError>(())
//! ```

pub mod angles;
mod control;
pub mod divisors;
mod enclosure;
pub mod error;
pub mod expr;
pub mod fields;
pub mod identity;
pub mod interval;
pub mod load;
pub mod parse;
pub mod rational;
mod raw;
pub mod reserved;
mod sections;
mod size;
pub(crate) mod source;
pub mod symbols;
pub mod types;
mod validate;

pub use divisors::ExprRole;
pub use error::{Location, ModelError, ModelErrorKind};
pub use expr::{BinOp, Expr, ExprKind, Func, Number, Span};
pub use interval::{Bound, Interval};
pub use parse::{ParseError, ParseErrorKind, parse_expr};
pub use rational::Rational;
pub use symbols::{Symbol, SymbolKind};
pub use types::{
    Body, Control, Coordinate, CoordinateUnit, Descriptor, Desired, Fall, FallCondition, Floor,
    Impact, Input, MAX_BEZIER_POINTS, Model, ModelExpr, Name, Output, Parameter, Point, Relabel,
    Section, Stage, Stance, StartValue, Strike,
};
