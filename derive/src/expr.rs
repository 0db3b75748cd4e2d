//! A hash-consed expression arena: equal subtrees are one node.
//!
//! Expressions are how the physics is written down and how derived results are handed on
//! (to the generator and to the LaTeX printer). Algebra happens in the canonical form,
//! [`RatFunc`]: [`Arena::to_ratfunc`] converts into it, [`Arena::from_ratfunc`] back.

use std::collections::HashMap;

use num_traits::{One, ToPrimitive, Zero};

use crate::error::{Error, Result};
use crate::poly::{Poly, Q};
use crate::ratfunc::RatFunc;
use crate::symbol::{Atom, BaseAngle, NUM_ATOMS, Sym};
use crate::trig::sin_cos_combination;

/// Handle of a node in an [`Arena`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Id(u32);

/// Elementary functions.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Func {
    /// Sine.
    Sin,
    /// Cosine.
    Cos,
    /// Hyperbolic tangent (friction law, Eq. 26).
    Tanh,
    /// Sign function (Coulomb friction, Eq. 25).
    Sign,
}

/// A node of the arena.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Node {
    /// An exact rational constant.
    Num(Q),
    /// A symbol.
    Sym(Sym),
    /// A sum of at least two operands, sorted by id.
    Add(Box<[Id]>),
    /// A product of at least two operands, sorted by id.
    Mul(Box<[Id]>),
    /// An integer power (nonzero, not one).
    Pow(Id, i32),
    /// A function application.
    Func(Func, Id),
}

/// The arena.
#[derive(Default, Clone, Debug)]
pub struct Arena {
    nodes: Vec<Node>,
    index: HashMap<Node, Id>,
    canon: HashMap<Id, RatFunc>,
}

impl Arena {
    /// An empty arena.
    pub fn new() -> Arena {
        Arena::default()
    }

    /// Number of distinct nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Whether the arena is empty.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// The node of a handle.
    pub fn node(&self, id: Id) -> &Node {
        &self.nodes[id.0 as usize]
    }

    fn intern(&mut self, node: Node) -> Id {
        if let Some(&id) = self.index.get(&node) {
            return id;
        }
        let id = Id(self.nodes.len() as u32);
        self.nodes.push(node.clone());
        self.index.insert(node, id);
        id
    }

    /// A rational constant.
    pub fn num(&mut self, q: Q) -> Id {
        self.intern(Node::Num(q))
    }

    /// An integer constant.
    pub fn int(&mut self, n: i64) -> Id {
        self.num(Q::from_integer(n.into()))
    }

    /// A symbol.
    pub fn sym(&mut self, s: Sym) -> Id {
        self.intern(Node::Sym(s))
    }

    /// A symbol by name; an error for an unknown name.
    pub fn sym_named(&mut self, name: &str) -> Result<Id> {
        let s = Sym::from_name(name)?;
        Ok(self.sym(s))
    }

    fn as_num(&self, id: Id) -> Option<&Q> {
        match self.node(id) {
            Node::Num(q) => Some(q),
            _ => None,
        }
    }

    /// A sum: flattened, numbers folded, operands sorted.
    pub fn add(&mut self, terms: &[Id]) -> Id {
        let mut ops = Vec::new();
        let mut k = Q::zero();
        for &t in terms {
            match self.node(t).clone() {
                Node::Num(q) => k += q,
                Node::Add(inner) => {
                    for &i in inner.iter() {
                        match self.as_num(i) {
                            Some(q) => k += q.clone(),
                            None => ops.push(i),
                        }
                    }
                }
                _ => ops.push(t),
            }
        }
        if !k.is_zero() {
            ops.push(self.num(k));
        }
        ops.sort();
        match ops.len() {
            0 => self.int(0),
            1 => ops[0],
            _ => self.intern(Node::Add(ops.into_boxed_slice())),
        }
    }

    /// A product: flattened, numbers folded, operands sorted.
    pub fn mul(&mut self, factors: &[Id]) -> Id {
        let mut ops = Vec::new();
        let mut k = Q::one();
        for &f in factors {
            match self.node(f).clone() {
                Node::Num(q) => k *= q,
                Node::Mul(inner) => {
                    for &i in inner.iter() {
                        match self.as_num(i) {
                            Some(q) => k *= q.clone(),
                            None => ops.push(i),
                        }
                    }
                }
                _ => ops.push(f),
            }
        }
        if k.is_zero() {
            return self.int(0);
        }
        if !k.is_one() {
            ops.push(self.num(k));
        }
        ops.sort();
        match ops.len() {
            0 => self.int(1),
            1 => ops[0],
            _ => self.intern(Node::Mul(ops.into_boxed_slice())),
        }
    }

    /// `a - b`.
    pub fn sub(&mut self, a: Id, b: Id) -> Id {
        let nb = self.neg(b);
        self.add(&[a, nb])
    }

    /// `-a`.
    pub fn neg(&mut self, a: Id) -> Id {
        let m1 = self.int(-1);
        self.mul(&[m1, a])
    }

    /// `a / b`.
    pub fn div(&mut self, a: Id, b: Id) -> Id {
        let ib = self.pow(b, -1);
        self.mul(&[a, ib])
    }

    /// `a^n`.
    pub fn pow(&mut self, a: Id, n: i32) -> Id {
        if n == 0 {
            return self.int(1);
        }
        if n == 1 {
            return a;
        }
        if let Some(q) = self.as_num(a).cloned()
            && !(q.is_zero() && n < 0)
        {
            let e = n.unsigned_abs() as usize;
            let r = if n < 0 {
                num_traits::pow(q.recip(), e)
            } else {
                num_traits::pow(q, e)
            };
            return self.num(r);
        }
        if let Node::Pow(b, m) = *self.node(a)
            && let Some(k) = m.checked_mul(n)
        {
            return self.pow(b, k);
        }
        self.intern(Node::Pow(a, n))
    }

    /// A function application.
    pub fn func(&mut self, f: Func, a: Id) -> Id {
        self.intern(Node::Func(f, a))
    }

    /// `sin(a)`.
    pub fn sin(&mut self, a: Id) -> Id {
        self.func(Func::Sin, a)
    }

    /// `cos(a)`.
    pub fn cos(&mut self, a: Id) -> Id {
        self.func(Func::Cos, a)
    }

    /// The canonical form of an expression: a rational function in the atoms, with every
    /// trigonometric function expanded into sines and cosines of base angles.
    pub fn to_ratfunc(&mut self, id: Id) -> Result<RatFunc> {
        if let Some(r) = self.canon.get(&id) {
            return Ok(r.clone());
        }
        let r = match self.node(id).clone() {
            Node::Num(q) => RatFunc::constant(q),
            Node::Sym(s) => RatFunc::sym(s),
            Node::Add(ops) => {
                let mut acc = RatFunc::zero();
                for &o in ops.iter() {
                    acc = acc.add(&self.to_ratfunc(o)?);
                }
                acc
            }
            Node::Mul(ops) => {
                let mut acc = RatFunc::one();
                for &o in ops.iter() {
                    acc = acc.mul(&self.to_ratfunc(o)?);
                }
                acc
            }
            Node::Pow(b, n) => self.to_ratfunc(b)?.powi(n)?,
            Node::Func(f @ (Func::Sin | Func::Cos), a) => {
                let arg = self.to_ratfunc(a)?;
                let combo = angle_combination(&arg)?;
                let (s, c) = sin_cos_combination(&combo);
                if f == Func::Sin { s.into() } else { c.into() }
            }
            Node::Func(f, _) => {
                return Err(Error::Unsupported {
                    what: format!(
                        "{f:?} has no canonical form; it enters the kernels through an input"
                    ),
                });
            }
        };
        self.canon.insert(id, r.clone());
        Ok(r)
    }

    /// An expression for a rational function: numerator over denominator, each a sum of
    /// monomials with the rational content pulled out.
    pub fn from_ratfunc(&mut self, r: &RatFunc) -> Id {
        let n = self.from_poly(r.num());
        if r.is_poly() {
            return n;
        }
        let d = self.from_poly(r.den());
        self.div(n, d)
    }

    /// An expression for a polynomial (a sum of monomials).
    pub fn from_poly(&mut self, p: &Poly) -> Id {
        let mut terms = Vec::with_capacity(p.len());
        for (m, c) in p.terms() {
            let mut factors = vec![self.num(c.clone())];
            for (slot, e) in m.factors() {
                let a = self.atom(slot);
                factors.push(self.pow(a, i32::from(e)));
            }
            terms.push(self.mul(&factors));
        }
        self.add(&terms)
    }

    /// The expression of an atom slot (`sin(alpha/2)` for the half-angle atoms).
    pub fn atom(&mut self, slot: usize) -> Id {
        match Atom::of_slot(slot) {
            Some(Atom::Sym(s)) => self.sym(s),
            Some(Atom::Sin(a)) => {
                let arg = self.base_angle(a);
                self.sin(arg)
            }
            Some(Atom::Cos(a)) => {
                let arg = self.base_angle(a);
                self.cos(arg)
            }
            None => self.int(0),
        }
    }

    /// The expression of a base angle (`alpha/2` is `1/2 * alpha`).
    pub fn base_angle(&mut self, a: BaseAngle) -> Id {
        let (s, k) = a.symbol_and_multiple();
        let sym = self.sym(s);
        let inv = self.num(Q::new(1.into(), k.into()));
        self.mul(&[inv, sym])
    }

    /// Evaluates in `f64` with a value for every symbol slot (trigonometric atoms are computed).
    pub fn eval(&self, id: Id, values: &[f64; NUM_ATOMS]) -> f64 {
        match self.node(id) {
            Node::Num(q) => q.to_f64().unwrap_or(f64::NAN),
            Node::Sym(s) => values[s.slot()],
            Node::Add(ops) => ops.iter().map(|&o| self.eval(o, values)).sum(),
            Node::Mul(ops) => ops.iter().map(|&o| self.eval(o, values)).product(),
            Node::Pow(b, n) => self.eval(*b, values).powi(*n),
            Node::Func(f, a) => {
                let x = self.eval(*a, values);
                match f {
                    Func::Sin => x.sin(),
                    Func::Cos => x.cos(),
                    Func::Tanh => x.tanh(),
                    Func::Sign => {
                        if x > 0.0 {
                            1.0
                        } else if x < 0.0 {
                            -1.0
                        } else {
                            0.0
                        }
                    }
                }
            }
        }
    }
}

/// The integer combination of base angles that a canonical angle expression is.
fn angle_combination(arg: &RatFunc) -> Result<Vec<(BaseAngle, i64)>> {
    let bad = |what: String| Error::UnsupportedAngle { what };
    if !arg.is_poly() {
        return Err(bad(format!("{arg:?} is not linear in the angles")));
    }
    let mut combo = Vec::new();
    for (m, c) in arg.num().terms() {
        let mut factors = m.factors();
        let (Some((slot, 1)), None) = (factors.next(), factors.next()) else {
            return Err(bad(format!(
                "{arg:?} is not a linear combination of angle symbols"
            )));
        };
        let Some(Atom::Sym(sym)) = Atom::of_slot(slot) else {
            return Err(bad(format!("{arg:?} has a trigonometric atom inside")));
        };
        let Some(base) = BaseAngle::of_symbol(sym) else {
            return Err(bad(format!("`{}` is not an angle", sym.name())));
        };
        let (_, k) = base.symbol_and_multiple();
        let n = c * Q::from_integer(k.into());
        if !n.is_integer() {
            return Err(bad(format!(
                "{c} * {} is not an integer multiple of its base angle",
                sym.name()
            )));
        }
        let n = n
            .to_integer()
            .to_i64()
            .ok_or_else(|| bad("multiple too large".into()))?;
        combo.push((base, n));
    }
    Ok(combo)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hash_consing_shares_equal_subtrees() {
        let mut a = Arena::new();
        let x = a.sym(Sym::X);
        let l = a.sym(Sym::L);
        let p = a.mul(&[x, l]);
        let q = a.mul(&[l, x]);
        assert_eq!(p, q);
        let n = a.len();
        let _ = a.add(&[p, q]);
        let _ = a.add(&[q, p]);
        assert_eq!(a.len(), n + 1);
    }

    #[test]
    fn sin_of_sum_expands() {
        let mut a = Arena::new();
        let al = a.sym(Sym::Alpha);
        let th = a.sym(Sym::Th1);
        let diff = a.sub(al, th);
        let s = a.sin(diff);
        let r = a.to_ratfunc(s).expect("canonical");
        // sin(alpha - th1) = sin(alpha) cos(th1) - cos(alpha) sin(th1)
        let sa = a.sin(al);
        let ca = a.cos(al);
        let st = a.sin(th);
        let ct = a.cos(th);
        let t1 = a.mul(&[sa, ct]);
        let t2 = a.mul(&[ca, st]);
        let e = a.sub(t1, t2);
        assert_eq!(r, a.to_ratfunc(e).expect("canonical"));
    }

    #[test]
    fn nonlinear_angle_is_an_error() {
        let mut a = Arena::new();
        let th = a.sym(Sym::Th1);
        let sq = a.pow(th, 2);
        let s = a.sin(sq);
        assert!(matches!(
            a.to_ratfunc(s),
            Err(Error::UnsupportedAngle { .. })
        ));
        let m = a.sym(Sym::M1);
        let s = a.sin(m);
        assert!(matches!(
            a.to_ratfunc(s),
            Err(Error::UnsupportedAngle { .. })
        ));
    }

    #[test]
    fn division_by_zero_is_an_error() {
        let mut a = Arena::new();
        let x = a.sym(Sym::X);
        let z = a.sub(x, x);
        let q = a.div(x, z);
        assert_eq!(a.to_ratfunc(q), Err(Error::DivisionByZero));
    }
}
