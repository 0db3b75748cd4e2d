//! A model's symbol table: every symbol of the typed model, in its canonical order, interned
//! with its role, its LaTeX and, for an angle, its base angle (the symbol divided by the model's
//! divisor, `alpha/2` for the paper's `alpha`).

use walker_scene::model::{Model, SymbolKind};

use crate::error::Result;
use crate::symbol::{Sym, SymKind, Symbols};

/// The engine's table of a model, and the symbol of each of the model's symbols by index.
#[derive(Clone, Debug)]
pub struct ModelSymbols {
    /// The model file's path, for errors that name file, line and column.
    pub path: String,
    /// The table.
    pub table: Symbols,
    /// The generalized coordinates `q`.
    pub q: Vec<Sym>,
    /// The velocities `qdot`.
    pub qd: Vec<Sym>,
    /// The accelerations `qddot`.
    pub qdd: Vec<Sym>,
    /// The inputs `u`, in file order.
    pub inputs: Vec<Sym>,
    /// The outputs' auxiliary inputs `v`, in file order.
    pub aux: Vec<Sym>,
    /// The signed friction coefficient `mu` (Eq. 24).
    pub mu: Sym,
    /// The time since the last impact.
    pub t: Sym,
}

fn latex_of(model: &Model, name: &str, kind: SymbolKind, index: usize) -> String {
    let coordinate = |i: usize| {
        model.coordinates.get(i).map_or_else(
            || name.to_owned(),
            |c| c.latex.clone().unwrap_or_else(|| c.name.name.clone()),
        )
    };
    match kind {
        SymbolKind::Coordinate => coordinate(index),
        SymbolKind::Velocity => format!("\\dot{{{}}}", coordinate(index)),
        SymbolKind::Acceleration => format!("\\ddot{{{}}}", coordinate(index)),
        SymbolKind::Parameter => model
            .parameters
            .get(index)
            .and_then(|p| p.latex.clone())
            .unwrap_or_else(|| name.to_owned()),
        SymbolKind::Mu => "\\mu".to_owned(),
        _ => name.to_owned(),
    }
}

impl ModelSymbols {
    /// Interns every symbol of `model` in its canonical order (coordinates, velocities,
    /// accelerations, parameters, inputs, `mu`, auxiliary inputs, `t`): a symbol's index in the
    /// engine's table is its index in [`Model::symbols`].
    ///
    /// # Errors
    /// A base-angle divisor above 255, or more symbols than a table holds: at the declaration of
    /// the symbol refused.
    pub fn new(model: &Model) -> Result<ModelSymbols> {
        let mut table = Symbols::new();
        let (mut q, mut qd, mut qdd, mut inputs, mut aux) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let (mut mu, mut t) = (None, None);
        for s in model.symbols() {
            let kind = match s.kind {
                SymbolKind::Coordinate => SymKind::Coordinate,
                SymbolKind::Velocity => SymKind::Velocity,
                SymbolKind::Acceleration => SymKind::Acceleration,
                SymbolKind::Parameter => SymKind::Parameter,
                SymbolKind::Input | SymbolKind::Mu | SymbolKind::Aux | SymbolKind::Time => {
                    SymKind::Input
                }
            };
            let latex = latex_of(model, &s.name, s.kind, s.index);
            let sym = if s.angle {
                table.push_angle(&s.name, &latex, kind, s.base_divisor as i64)
            } else {
                table.push(&s.name, &latex, kind)
            }
            .map_err(|e| super::located::symbol_error(model, &s.name, e))?;
            match s.kind {
                SymbolKind::Coordinate => q.push(sym),
                SymbolKind::Velocity => qd.push(sym),
                SymbolKind::Acceleration => qdd.push(sym),
                SymbolKind::Input => inputs.push(sym),
                SymbolKind::Aux => aux.push(sym),
                SymbolKind::Mu => mu = Some(sym),
                SymbolKind::Time => t = Some(sym),
                SymbolKind::Parameter => {}
            }
        }
        let missing = |what: &str| crate::error::Error::CheckFailed {
            what: format!("the model's symbols have no `{what}`"),
        };
        Ok(ModelSymbols {
            path: model.path.clone(),
            table,
            q,
            qd,
            qdd,
            inputs,
            aux,
            mu: mu.ok_or_else(|| missing("mu"))?,
            t: t.ok_or_else(|| missing("t"))?,
        })
    }

    /// The symbol called `name`.
    ///
    /// # Errors
    /// [`crate::Error::UnknownSymbol`].
    pub fn get(&self, name: &str) -> Result<Sym> {
        self.table.lookup(name)
    }
}
