//! The model's symbols in their canonical order, which of them are angles, and each angle's
//! base-angle divisor.
//!
//! The order: coordinates `q`, velocities `<q>d`, accelerations `<q>dd`, parameters in file
//! order, inputs, `mu`, the outputs' auxiliary inputs, `t`. A symbol's position in
//! [`Model::symbols`](crate::model::Model::symbols) is its index; the derivation interns by it.

use std::collections::HashMap;

/// What a symbol stands for.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub enum SymbolKind {
    /// A coordinate `q_i`.
    Coordinate,
    /// A velocity `q_i d`.
    Velocity,
    /// An acceleration `q_i dd`.
    Acceleration,
    /// A parameter.
    Parameter,
    /// An input.
    Input,
    /// `mu`, the signed friction coefficient of the stance phase.
    Mu,
    /// An output's auxiliary input `v`.
    Aux,
    /// `t`, the time since the last impact.
    Time,
}

impl SymbolKind {
    /// The kind in words, for messages.
    #[must_use]
    pub fn describe(self) -> &'static str {
        match self {
            SymbolKind::Coordinate => "a coordinate",
            SymbolKind::Velocity => "a velocity",
            SymbolKind::Acceleration => "an acceleration",
            SymbolKind::Parameter => "a parameter",
            SymbolKind::Input => "an input",
            SymbolKind::Mu => "the stance friction coefficient",
            SymbolKind::Aux => "an output's auxiliary input",
            SymbolKind::Time => "the time",
        }
    }
}

/// One symbol of a model.
#[derive(Clone, PartialEq, Eq, Debug)]
pub struct Symbol {
    /// The name.
    pub name: String,
    /// What it stands for.
    pub kind: SymbolKind,
    /// Its index among the symbols of its kind (the coordinate's index for a velocity).
    pub index: usize,
    /// Whether it is an angle (a coordinate or parameter with unit `rad`).
    pub angle: bool,
    /// For an angle, the least common denominator of its coefficients in the model's
    /// `sin`/`cos` arguments, guards and relabelling: the base angle is the symbol divided by
    /// it. 1 for every other symbol.
    pub base_divisor: u64,
}

/// The symbols of a model, in canonical order, with a name index.
#[derive(Clone, Debug, Default)]
pub(crate) struct SymbolTable {
    pub(crate) symbols: Vec<Symbol>,
    pub(crate) index: HashMap<String, usize>,
}

impl SymbolTable {
    /// Appends a symbol; `false` if the name is taken.
    pub(crate) fn push(&mut self, name: &str, kind: SymbolKind, index: usize, angle: bool) -> bool {
        if self.index.contains_key(name) {
            return false;
        }
        self.index.insert(name.to_owned(), self.symbols.len());
        self.symbols.push(Symbol {
            name: name.to_owned(),
            kind,
            index,
            angle,
            base_divisor: 1,
        });
        true
    }

    pub(crate) fn get(&self, name: &str) -> Option<&Symbol> {
        self.index.get(name).and_then(|&i| self.symbols.get(i))
    }
}
