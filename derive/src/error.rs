//! Errors of the symbolic engine: values, never panics.

/// Everything that can go wrong in a derivation.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum Error {
    /// A division whose divisor is identically zero.
    #[error("division by an expression that is identically zero")]
    DivisionByZero,
    /// The inverse of a matrix whose determinant is identically zero.
    #[error("matrix {name} is singular: its determinant is identically zero")]
    SingularMatrix {
        /// Which matrix.
        name: String,
    },
    /// A symbol name that the model does not know.
    #[error("unknown symbol `{name}`")]
    UnknownSymbol {
        /// The name asked for.
        name: String,
    },
    /// Matrix dimensions that do not fit the operation.
    #[error("dimension mismatch in {op}: {left:?} and {right:?}")]
    Dimension {
        /// The operation.
        op: &'static str,
        /// Shape of the left operand.
        left: (usize, usize),
        /// Shape of the right operand.
        right: (usize, usize),
    },
    /// A trigonometric argument that is not an integer combination of base angles.
    #[error("unsupported trigonometric argument: {what}")]
    UnsupportedAngle {
        /// Why the argument is not supported.
        what: String,
    },
    /// A kernel that the derivation does not have.
    #[error("unknown kernel `{name}`")]
    UnknownKernel {
        /// The name asked for.
        name: String,
    },
    /// A closed form too large to serve (the model's kernels are structured solves instead).
    #[error(
        "{what} is too large in closed form ({terms}, at most {limit}): this model's stance \
         and impact kernels are structured solves"
    )]
    TooLarge {
        /// The expression.
        what: String,
        /// Its size (terms of numerators and denominators).
        terms: usize,
        /// The limit.
        limit: usize,
    },
    /// A derivation that spent its budget of work ([`crate::budget::DERIVATION_BUDGET`]).
    #[error(
        "model `{model}`: deriving {stage} took more than the derivation budget of {budget} term \
         products; the model's expressions grow too large in the canonical form (simplify them, \
         or use fewer coordinates)"
    )]
    Budget {
        /// The model's name.
        model: String,
        /// What was being derived when the budget ran out.
        stage: String,
        /// The budget, in term products.
        budget: u64,
    },
    /// A symbolic check of the model failed (a derivation bug, reported rather than panicking).
    #[error("check failed: {what}")]
    CheckFailed {
        /// The check.
        what: String,
    },
}

/// Result type of the engine.
pub type Result<T> = std::result::Result<T, Error>;
