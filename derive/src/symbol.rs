//! The symbols of a model, their table, and their slots in a monomial.
//!
//! A polynomial of this engine lives in `Q[atoms]`, where each atom is either a plain symbol
//! (a coordinate, a velocity, a parameter, an input) or the sine or cosine of a *base angle*.
//! A base angle is an angle symbol divided by a positive integer: the paper's walker has `th1`,
//! `th2`, `alpha/2` and `phi`, where `alpha` enters through its half so that
//! `sin(alpha) = 2 sin(alpha/2) cos(alpha/2)` and `1 - cos(alpha) = 2 sin^2(alpha/2)` need no
//! square root and lose no digits.
//!
//! Symbols and base angles are indices into the model's [`Symbols`] table: nothing here knows a
//! walker, and a model has as many of them as it declares. Slots are self-describing, so that the
//! arithmetic needs no table: slot `2k` is `sin` of base angle `k` and `2k + 1` its `cos` (the
//! reduction `cos^2 -> 1 - sin^2` pairs them by parity), and the plain symbol `i` is slot
//! [`SYM_SLOT_BASE`]` + i`, after every trigonometric slot. A [`Sym`] carries its own base angle
//! and multiple, so that differentiation follows the chain rule through `sin` and `cos` without
//! a lookup; names, LaTeX and roles are the table's.
//!
//! Nothing here knows a walker: the paper's notation, a table written out by hand with its
//! symbols as constants, is `crate::paper`'s ([`Symbols::paper`]).

use crate::error::Error;

/// The first slot of a plain symbol: slots below it are sines (even) and cosines (odd) of base
/// angles.
pub const SYM_SLOT_BASE: usize = 1 << 16;

/// A base angle: an index into [`Symbols::angles`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct BaseAngle(u16);

impl BaseAngle {
    /// The base angle with index `k` of its table.
    pub const fn new(k: u16) -> BaseAngle {
        BaseAngle(k)
    }

    /// Its index in the table.
    pub const fn index(self) -> usize {
        self.0 as usize
    }

    /// The atom slot of `sin` of this angle.
    pub const fn sin_slot(self) -> usize {
        2 * self.0 as usize
    }

    /// The atom slot of `cos` of this angle.
    pub const fn cos_slot(self) -> usize {
        2 * self.0 as usize + 1
    }
}

/// A symbol: an index into [`Symbols::syms`], with its base angle and multiple when it is an
/// angle (`alpha = 2 (alpha/2)`). Symbols compare by index: within one table the index decides
/// the angle.
#[derive(Clone, Copy, Debug)]
pub struct Sym {
    index: u16,
    angle: Option<(BaseAngle, u8)>,
}

impl PartialEq for Sym {
    fn eq(&self, other: &Sym) -> bool {
        self.index == other.index
    }
}

impl Eq for Sym {}

impl std::hash::Hash for Sym {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.index.hash(state);
    }
}

impl PartialOrd for Sym {
    fn partial_cmp(&self, other: &Sym) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Sym {
    fn cmp(&self, other: &Sym) -> std::cmp::Ordering {
        self.index.cmp(&other.index)
    }
}

impl Sym {
    /// A plain (non-angle) symbol with index `i`.
    pub const fn plain(i: u16) -> Sym {
        Sym {
            index: i,
            angle: None,
        }
    }

    /// An angle symbol with index `i`, equal to `multiple` times the base angle `base`.
    pub const fn angle(i: u16, base: BaseAngle, multiple: u8) -> Sym {
        Sym {
            index: i,
            angle: Some((base, multiple)),
        }
    }

    /// Its index in the table.
    pub const fn index(self) -> usize {
        self.index as usize
    }

    /// The atom slot of this symbol.
    pub const fn slot(self) -> usize {
        SYM_SLOT_BASE + self.index as usize
    }

    /// The base angle and the multiple, if this is an angle: `self = multiple * base`.
    pub const fn base_angle(self) -> Option<(BaseAngle, i64)> {
        match self.angle {
            Some((b, k)) => Some((b, k as i64)),
            None => None,
        }
    }
}

/// What role a symbol plays in the model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SymKind {
    /// A generalized coordinate of `q`.
    Coordinate,
    /// A generalized velocity of `qdot`.
    Velocity,
    /// A generalized acceleration of `qddot`.
    Acceleration,
    /// A physical or control parameter, constant during a simulation.
    Parameter,
    /// An input that changes along the motion but is not a state (`u`, `mu`, `t`).
    Input,
    /// An intermediate of a structured solve: a name for one value computed inside a kernel
    /// (an entry of `M`, a pivot of its factorisation, a component of a solution), bound by the
    /// kernel's program before it is used.
    Local,
}

/// What an atom slot holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Atom {
    /// `sin` of a base angle.
    Sin(BaseAngle),
    /// `cos` of a base angle.
    Cos(BaseAngle),
    /// A plain symbol. From [`Atom::of_slot`] it carries no angle (a slot does not know it);
    /// [`Symbols::by_index`] gives the whole symbol.
    Sym(Sym),
}

impl Atom {
    /// The atom in a slot.
    pub fn of_slot(slot: usize) -> Atom {
        if slot >= SYM_SLOT_BASE {
            return Atom::Sym(Sym::plain((slot - SYM_SLOT_BASE) as u16));
        }
        let angle = BaseAngle((slot / 2) as u16);
        if slot.is_multiple_of(2) {
            Atom::Sin(angle)
        } else {
            Atom::Cos(angle)
        }
    }

    /// The slot of this atom.
    pub const fn slot(self) -> usize {
        match self {
            Atom::Sin(a) => a.sin_slot(),
            Atom::Cos(a) => a.cos_slot(),
            Atom::Sym(s) => s.slot(),
        }
    }
}

/// Whether a slot is the cosine of a base angle (the slots the reduction works on).
pub const fn is_cos_slot(slot: usize) -> bool {
    slot < SYM_SLOT_BASE && slot % 2 == 1
}

/// One symbol of a table.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SymbolInfo {
    /// The symbol (its index and, for an angle, its base angle).
    pub sym: Sym,
    /// Plain-text name, as in model, scene files and kernel argument lists.
    pub name: String,
    /// LaTeX rendering.
    pub latex: String,
    /// Its role.
    pub kind: SymKind,
}

/// One base angle of a table: `symbol / multiple`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AngleInfo {
    /// The angle symbol it is a fraction of.
    pub symbol: Sym,
    /// How many base angles make the symbol.
    pub multiple: i64,
}

/// A model's symbol table: every symbol with its name, LaTeX and role, and every base angle.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Symbols {
    syms: Vec<SymbolInfo>,
    angles: Vec<AngleInfo>,
}

impl Symbols {
    /// A table of the given symbols, in index order, with every base angle their angle symbols
    /// name (in base-angle index order): for a table written out by hand, as the paper's.
    pub(crate) fn from_infos(syms: Vec<SymbolInfo>) -> Symbols {
        let angles = syms
            .iter()
            .filter_map(|s| {
                s.sym.base_angle().map(|(b, k)| {
                    (
                        b,
                        AngleInfo {
                            symbol: s.sym,
                            multiple: k,
                        },
                    )
                })
            })
            .collect::<std::collections::BTreeMap<_, _>>()
            .into_values()
            .collect();
        Symbols { syms, angles }
    }

    /// An empty table.
    pub fn new() -> Symbols {
        Symbols::default()
    }

    /// Adds a plain symbol.
    ///
    /// # Errors
    /// [`Error::CheckFailed`] if the name is taken or the table is full.
    pub fn push(&mut self, name: &str, latex: &str, kind: SymKind) -> Result<Sym, Error> {
        let sym = Sym::plain(self.next_index(name)?);
        self.syms.push(SymbolInfo {
            sym,
            name: name.to_owned(),
            latex: latex.to_owned(),
            kind,
        });
        Ok(sym)
    }

    /// Adds an angle symbol whose base angle is the symbol divided by `multiple` (a new base
    /// angle, after the existing ones).
    ///
    /// # Errors
    /// [`Error::CheckFailed`] if the name is taken, the multiple is not in `1..=255` or the
    /// table is full.
    pub fn push_angle(
        &mut self,
        name: &str,
        latex: &str,
        kind: SymKind,
        multiple: i64,
    ) -> Result<Sym, Error> {
        let index = self.next_index(name)?;
        let k = u8::try_from(multiple)
            .ok()
            .filter(|k| *k > 0)
            .ok_or_else(|| Error::CheckFailed {
                what: format!("the base angle of `{name}` is `{name}/{multiple}`: the divisor must be in 1..=255"),
            })?;
        let base = u16::try_from(self.angles.len())
            .ok()
            .filter(|b| usize::from(*b) < SYM_SLOT_BASE / 2)
            .map(BaseAngle)
            .ok_or_else(|| Error::CheckFailed {
                what: "too many angles".to_owned(),
            })?;
        let sym = Sym::angle(index, base, k);
        self.angles.push(AngleInfo {
            symbol: sym,
            multiple,
        });
        self.syms.push(SymbolInfo {
            sym,
            name: name.to_owned(),
            latex: latex.to_owned(),
            kind,
        });
        Ok(sym)
    }

    fn next_index(&self, name: &str) -> Result<u16, Error> {
        if self.syms.iter().any(|s| s.name == name) {
            return Err(Error::CheckFailed {
                what: format!("symbol `{name}` declared twice"),
            });
        }
        u16::try_from(self.syms.len()).map_err(|_| Error::CheckFailed {
            what: "too many symbols".to_owned(),
        })
    }

    /// Every symbol, in index order.
    pub fn syms(&self) -> impl Iterator<Item = Sym> + '_ {
        self.syms.iter().map(|s| s.sym)
    }

    /// Every symbol's entry, in index order.
    pub fn infos(&self) -> &[SymbolInfo] {
        &self.syms
    }

    /// Every base angle's entry, in index order.
    pub fn angles(&self) -> &[AngleInfo] {
        &self.angles
    }

    /// Every base angle, in index order.
    pub fn base_angles(&self) -> impl Iterator<Item = BaseAngle> + '_ {
        (0..self.angles.len()).map(|k| BaseAngle(k as u16))
    }

    /// The number of symbols.
    pub fn len(&self) -> usize {
        self.syms.len()
    }

    /// Whether the table is empty.
    pub fn is_empty(&self) -> bool {
        self.syms.is_empty()
    }

    /// The entry of a symbol by index.
    fn info(&self, index: usize) -> Option<&SymbolInfo> {
        self.syms.get(index)
    }

    /// The symbol with index `index` (with its angle), if the table has it.
    pub fn by_index(&self, index: usize) -> Option<Sym> {
        self.info(index).map(|s| s.sym)
    }

    /// The plain-text name of a symbol (`?` for a symbol of another table).
    pub fn name(&self, s: Sym) -> &str {
        self.info(s.index()).map_or("?", |i| i.name.as_str())
    }

    /// The LaTeX of a symbol.
    pub fn latex(&self, s: Sym) -> &str {
        self.info(s.index()).map_or("?", |i| i.latex.as_str())
    }

    /// The role of a symbol.
    pub fn kind(&self, s: Sym) -> SymKind {
        self.info(s.index()).map_or(SymKind::Input, |i| i.kind)
    }

    /// The role of the symbol with index `index`.
    pub fn kind_of_index(&self, index: usize) -> Option<SymKind> {
        self.info(index).map(|i| i.kind)
    }

    /// The symbol a base angle is a fraction of, and the multiple: `symbol = multiple * angle`.
    pub fn angle(&self, a: BaseAngle) -> Option<(Sym, i64)> {
        self.angles.get(a.index()).map(|i| (i.symbol, i.multiple))
    }

    /// Looks a symbol up by its plain-text name.
    ///
    /// # Errors
    /// [`Error::UnknownSymbol`].
    pub fn lookup(&self, name: &str) -> Result<Sym, Error> {
        self.syms
            .iter()
            .find(|s| s.name == name)
            .map(|s| s.sym)
            .ok_or_else(|| Error::UnknownSymbol {
                name: name.to_owned(),
            })
    }

    /// The symbol an atom slot stands for, or the angle symbol of a trigonometric slot.
    pub fn symbol_of_slot(&self, slot: usize) -> Option<Sym> {
        match Atom::of_slot(slot) {
            Atom::Sym(s) => self.by_index(s.index()),
            Atom::Sin(a) | Atom::Cos(a) => self.angle(a).map(|(s, _)| s),
        }
    }

    /// Plain-text name of an atom slot (`sin(th1)`, `cos(alpha/2)`, `m1`).
    pub fn atom_name(&self, slot: usize) -> String {
        let angle = |a: BaseAngle| match self.angle(a) {
            Some((s, 1)) => self.name(s).to_owned(),
            Some((s, k)) => format!("{}/{k}", self.name(s)),
            None => format!("angle{}", a.index()),
        };
        match Atom::of_slot(slot) {
            Atom::Sin(a) => format!("sin({})", angle(a)),
            Atom::Cos(a) => format!("cos({})", angle(a)),
            Atom::Sym(s) => self
                .info(s.index())
                .map_or_else(|| format!("#{}", s.index()), |i| i.name.clone()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slots_describe_themselves() {
        let (phi, th2, x, g) = (
            BaseAngle::new(3),
            BaseAngle::new(1),
            Sym::plain(0),
            Sym::plain(18),
        );
        assert!(is_cos_slot(phi.cos_slot()));
        assert!(!is_cos_slot(phi.sin_slot()));
        assert!(!is_cos_slot(x.slot() + 1));
        assert_eq!(Atom::of_slot(g.slot()), Atom::Sym(g));
        assert_eq!(Atom::of_slot(th2.sin_slot()), Atom::Sin(th2));
    }
}

/// Values of the atoms at one point, as an expression evaluator reads them.
pub trait Valuation<T> {
    /// The value of an atom slot.
    fn value(&self, slot: usize) -> T;
}

impl<T, F: Fn(usize) -> T> Valuation<T> for F {
    fn value(&self, slot: usize) -> T {
        self(slot)
    }
}

/// The values of every atom of a table at one point: the symbols by index, the sines and
/// cosines by base angle (zero for a slot the table does not have).
#[derive(Clone, Debug, PartialEq)]
pub struct Point<T> {
    trig: Vec<T>,
    syms: Vec<T>,
}

impl<T: Clone + num_traits::Zero> Point<T> {
    /// Every atom of `symbols` at zero (so every cosine too: set the angles with
    /// [`Point::set_sym`] or by slot).
    pub fn zeros(symbols: &Symbols) -> Point<T> {
        Point {
            trig: vec![T::zero(); 2 * symbols.angles().len()],
            syms: vec![T::zero(); symbols.len()],
        }
    }

    /// Sets the value of one atom slot (ignored for a slot the table does not have).
    pub fn set(&mut self, slot: usize, value: T) {
        let cell = if slot >= SYM_SLOT_BASE {
            self.syms.get_mut(slot - SYM_SLOT_BASE)
        } else {
            self.trig.get_mut(slot)
        };
        if let Some(c) = cell {
            *c = value;
        }
    }
}

impl<T: Clone + num_traits::Zero> Valuation<T> for Point<T> {
    fn value(&self, slot: usize) -> T {
        let cell = if slot >= SYM_SLOT_BASE {
            self.syms.get(slot - SYM_SLOT_BASE)
        } else {
            self.trig.get(slot)
        };
        cell.cloned().unwrap_or_else(T::zero)
    }
}

impl Point<f64> {
    /// Sets a symbol, and for an angle the sine and cosine of its base angle
    /// (`sin(x / k)`, `cos(x / k)` for `s = k b`).
    pub fn set_sym(&mut self, s: Sym, x: f64) {
        self.set(s.slot(), x);
        if let Some((b, k)) = s.base_angle() {
            let a = x / k as f64;
            self.set(b.sin_slot(), a.sin());
            self.set(b.cos_slot(), a.cos());
        }
    }
}
