//! The hash-consed graph and its folding builder (see the module docs for what is folded).

use std::collections::HashMap;

use super::node::{Const, InputId, Node, NodeId, ParamId, index_u32};

/// A hash-consed graph of [`Node`]s with a folding builder.
#[derive(Clone, Debug, Default)]
pub struct Graph {
    nodes: Vec<Node>,
    lookup: HashMap<Node, NodeId>,
    inputs: Vec<String>,
    input_lookup: HashMap<String, InputId>,
}

impl Graph {
    /// An empty graph.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// The number of nodes.
    #[must_use]
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Whether the graph has no nodes.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// The node behind `id`.
    ///
    /// `id` must come from this graph (or from a clone of it); ids of another graph give an
    /// arbitrary node or, past the end, a zero constant.
    #[must_use]
    pub fn node(&self, id: NodeId) -> Node {
        self.nodes
            .get(id.index())
            .copied()
            .unwrap_or(Node::Const(Const::new(0.0)))
    }

    /// Whether `id` names a node of this graph.
    #[must_use]
    pub fn contains(&self, id: NodeId) -> bool {
        id.index() < self.nodes.len()
    }

    /// All nodes with their ids, in creation (topological) order.
    pub fn iter(&self) -> impl Iterator<Item = (NodeId, Node)> + '_ {
        self.nodes
            .iter()
            .enumerate()
            .map(|(i, n)| (NodeId(index_u32(i)), *n))
    }

    /// The name of an interned input.
    #[must_use]
    pub fn input_name(&self, id: InputId) -> &str {
        self.inputs.get(id.0 as usize).map_or("", String::as_str)
    }

    /// The constant value of `id`, if it is a constant.
    #[must_use]
    pub fn as_const(&self, id: NodeId) -> Option<f64> {
        match self.node(id) {
            Node::Const(c) => Some(c.value()),
            _ => None,
        }
    }

    fn intern(&mut self, node: Node) -> NodeId {
        if let Some(&id) = self.lookup.get(&node) {
            return id;
        }
        let id = NodeId(index_u32(self.nodes.len()));
        self.nodes.push(node);
        self.lookup.insert(node, id);
        id
    }

    /// The constant `v` (normalised, see [`Const::new`]).
    pub fn constant(&mut self, v: f64) -> NodeId {
        self.intern(Node::Const(Const::new(v)))
    }

    /// The runtime parameter `p` (declare it first with [`Module::declare_param`](crate::Module::declare_param)).
    pub fn param(&mut self, p: ParamId) -> NodeId {
        self.intern(Node::Param(p))
    }

    /// The kernel argument called `name` (interned: the same name gives the same node).
    pub fn input(&mut self, name: &str) -> NodeId {
        let id = match self.input_lookup.get(name) {
            Some(&id) => id,
            None => {
                let id = InputId(index_u32(self.inputs.len()));
                self.inputs.push(name.to_owned());
                self.input_lookup.insert(name.to_owned(), id);
                id
            }
        };
        self.intern(Node::Input(id))
    }

    /// Folds `f` over two constants if the result is finite.
    fn fold2(&mut self, a: NodeId, b: NodeId, f: impl Fn(f64, f64) -> f64) -> Option<NodeId> {
        let (x, y) = (self.as_const(a)?, self.as_const(b)?);
        let r = f(x, y);
        r.is_finite().then(|| self.constant(r))
    }

    /// Folds `f` over a constant if the result is finite.
    fn fold1(&mut self, a: NodeId, f: impl Fn(f64) -> f64) -> Option<NodeId> {
        let r = f(self.as_const(a)?);
        r.is_finite().then(|| self.constant(r))
    }

    fn negated(&self, id: NodeId) -> Option<NodeId> {
        match self.node(id) {
            Node::Neg(x) => Some(x),
            _ => None,
        }
    }

    fn is_const(&self, id: NodeId, v: f64) -> bool {
        self.as_const(id) == Some(v)
    }

    /// Canonical operand order of commutative operations: constants first, then by id.
    fn ordered(&self, a: NodeId, b: NodeId) -> (NodeId, NodeId) {
        let key = |id: NodeId| (self.as_const(id).is_none(), id);
        if key(a) <= key(b) { (a, b) } else { (b, a) }
    }

    /// `a + b`.
    pub fn add(&mut self, a: NodeId, b: NodeId) -> NodeId {
        if let Some(r) = self.fold2(a, b, |x, y| x + y) {
            return r;
        }
        if self.is_const(a, 0.0) {
            return b;
        }
        if self.is_const(b, 0.0) {
            return a;
        }
        if let Some(c) = self.as_const(b).filter(|c| *c < 0.0) {
            let m = self.constant(-c);
            return self.sub(a, m);
        }
        if let Some(c) = self.as_const(a).filter(|c| *c < 0.0) {
            let m = self.constant(-c);
            return self.sub(b, m);
        }
        match (self.negated(a), self.negated(b)) {
            (Some(x), Some(y)) => {
                let s = self.add(x, y);
                self.neg(s)
            }
            (None, Some(y)) => self.sub(a, y),
            (Some(x), None) => self.sub(b, x),
            (None, None) => {
                let (a, b) = self.ordered(a, b);
                self.intern(Node::Add(a, b))
            }
        }
    }

    /// `a - b`.
    pub fn sub(&mut self, a: NodeId, b: NodeId) -> NodeId {
        if let Some(r) = self.fold2(a, b, |x, y| x - y) {
            return r;
        }
        if a == b {
            return self.constant(0.0);
        }
        if self.is_const(b, 0.0) {
            return a;
        }
        if self.is_const(a, 0.0) {
            return self.neg(b);
        }
        if let Some(y) = self.negated(b) {
            return self.add(a, y);
        }
        if let Some(c) = self.as_const(b).filter(|c| *c < 0.0) {
            let m = self.constant(-c);
            return self.add(a, m);
        }
        if let Some(c) = self.as_const(a).filter(|c| *c < 0.0) {
            let m = self.constant(-c);
            let s = self.add(m, b);
            return self.neg(s);
        }
        if let Some(x) = self.negated(a) {
            let s = self.add(x, b);
            return self.neg(s);
        }
        self.intern(Node::Sub(a, b))
    }

    /// Splits `id` into a sign and a magnitude node: `-x` gives `(true, x)`, a negative constant
    /// `c` gives `(true, -c)`.
    fn split_sign(&mut self, id: NodeId) -> (bool, NodeId) {
        if let Some(x) = self.negated(id) {
            return (true, x);
        }
        match self.as_const(id) {
            Some(c) if c < 0.0 => (true, self.constant(-c)),
            _ => (false, id),
        }
    }

    fn with_sign(&mut self, negative: bool, id: NodeId) -> NodeId {
        if negative { self.neg(id) } else { id }
    }

    /// `a * b`.
    pub fn mul(&mut self, a: NodeId, b: NodeId) -> NodeId {
        if let Some(r) = self.fold2(a, b, |x, y| x * y) {
            return r;
        }
        if self.is_const(a, 0.0) || self.is_const(b, 0.0) {
            return self.constant(0.0);
        }
        if self.is_const(a, 1.0) {
            return b;
        }
        if self.is_const(b, 1.0) {
            return a;
        }
        let (na, a) = self.split_sign(a);
        let (nb, b) = self.split_sign(b);
        let magnitude = if self.is_const(a, 1.0) {
            b
        } else if self.is_const(b, 1.0) {
            a
        } else {
            let (a, b) = self.ordered(a, b);
            self.intern(Node::Mul(a, b))
        };
        self.with_sign(na != nb, magnitude)
    }

    /// `a / b`. Division by a power of two becomes an (exact) multiplication.
    pub fn div(&mut self, a: NodeId, b: NodeId) -> NodeId {
        if let Some(r) = self.fold2(a, b, |x, y| x / y) {
            return r;
        }
        if self.is_const(b, 1.0) {
            return a;
        }
        if let Some(c) = self.as_const(b)
            && let Some(r) = exact_reciprocal(c)
        {
            let r = self.constant(r);
            return self.mul(a, r);
        }
        let (na, a) = self.split_sign(a);
        let (nb, b) = self.split_sign(b);
        let magnitude = if self.is_const(b, 1.0) {
            a
        } else {
            self.intern(Node::Div(a, b))
        };
        self.with_sign(na != nb, magnitude)
    }

    /// `-a`.
    pub fn neg(&mut self, a: NodeId) -> NodeId {
        if let Some(c) = self.as_const(a) {
            return self.constant(-c);
        }
        match self.node(a) {
            Node::Neg(x) => x,
            Node::Sub(x, y) => self.sub(y, x),
            _ => self.intern(Node::Neg(a)),
        }
    }

    /// `a^n`.
    pub fn powi(&mut self, a: NodeId, n: i32) -> NodeId {
        if n == 0 {
            return self.constant(1.0);
        }
        if n == 1 {
            return a;
        }
        if let Some(r) = self.fold1(a, |x| powi_chain(x, n)) {
            return r;
        }
        if let Some(x) = self.negated(a) {
            let p = self.powi(x, n);
            return if n % 2 == 0 { p } else { self.neg(p) };
        }
        self.intern(Node::Powi(a, n))
    }

    /// `a * a`, as `powi(a, 2)`.
    pub fn square(&mut self, a: NodeId) -> NodeId {
        self.powi(a, 2)
    }

    /// `sqrt(a)`.
    pub fn sqrt(&mut self, a: NodeId) -> NodeId {
        if let Some(r) = self.fold1(a, f64::sqrt) {
            return r;
        }
        self.intern(Node::Sqrt(a))
    }

    /// `sin(a)` (not folded for constants, see the module docs).
    pub fn sin(&mut self, a: NodeId) -> NodeId {
        self.intern(Node::Sin(a))
    }

    /// `cos(a)` (not folded for constants, see the module docs).
    pub fn cos(&mut self, a: NodeId) -> NodeId {
        self.intern(Node::Cos(a))
    }

    /// `tanh(a)` (not folded for constants, see the module docs).
    pub fn tanh(&mut self, a: NodeId) -> NodeId {
        if self.is_const(a, 0.0) {
            return a;
        }
        self.intern(Node::Tanh(a))
    }

    /// `|a|`.
    pub fn abs(&mut self, a: NodeId) -> NodeId {
        if let Some(r) = self.fold1(a, f64::abs) {
            return r;
        }
        match self.node(a) {
            Node::Neg(x) => self.abs(x),
            Node::Abs(_) => a,
            _ => self.intern(Node::Abs(a)),
        }
    }

    /// The sum of `terms` (`0` if empty), added left to right.
    pub fn sum(&mut self, terms: &[NodeId]) -> NodeId {
        let mut acc = self.constant(0.0);
        for &t in terms {
            acc = self.add(acc, t);
        }
        acc
    }

    /// The product of `factors` (`1` if empty), multiplied left to right.
    pub fn product(&mut self, factors: &[NodeId]) -> NodeId {
        let mut acc = self.constant(1.0);
        for &f in factors {
            acc = self.mul(acc, f);
        }
        acc
    }

    /// Rebuilds `node` with its children mapped through `f`, through the folding builder.
    pub fn rebuild(&mut self, node: Node, mut f: impl FnMut(NodeId) -> NodeId) -> NodeId {
        match node {
            Node::Const(_) | Node::Param(_) | Node::Input(_) => self.intern(node),
            Node::Add(a, b) => {
                let (a, b) = (f(a), f(b));
                self.add(a, b)
            }
            Node::Sub(a, b) => {
                let (a, b) = (f(a), f(b));
                self.sub(a, b)
            }
            Node::Mul(a, b) => {
                let (a, b) = (f(a), f(b));
                self.mul(a, b)
            }
            Node::Div(a, b) => {
                let (a, b) = (f(a), f(b));
                self.div(a, b)
            }
            Node::Neg(a) => {
                let a = f(a);
                self.neg(a)
            }
            Node::Powi(a, n) => {
                let a = f(a);
                self.powi(a, n)
            }
            Node::Sqrt(a) => {
                let a = f(a);
                self.sqrt(a)
            }
            Node::Sin(a) => {
                let a = f(a);
                self.sin(a)
            }
            Node::Cos(a) => {
                let a = f(a);
                self.cos(a)
            }
            Node::Tanh(a) => {
                let a = f(a);
                self.tanh(a)
            }
            Node::Abs(a) => {
                let a = f(a);
                self.abs(a)
            }
        }
    }

    /// Evaluates `roots` in `f64` with parameter values `params` (indexed by [`ParamId`]) and
    /// inputs given by `input` (by name). A reference interpreter for tests.
    ///
    /// Missing parameters evaluate to NaN.
    #[must_use]
    pub fn eval(&self, roots: &[NodeId], params: &[f64], input: &dyn Fn(&str) -> f64) -> Vec<f64> {
        let mut values: Vec<f64> = Vec::with_capacity(self.nodes.len());
        let top = roots.iter().map(|r| r.index() + 1).max().unwrap_or(0);
        for (i, node) in self.nodes.iter().take(top).enumerate() {
            let v = |id: NodeId| values.get(id.index()).copied().unwrap_or(f64::NAN);
            let x = match *node {
                Node::Const(c) => c.value(),
                Node::Param(p) => params.get(p.index()).copied().unwrap_or(f64::NAN),
                Node::Input(name) => input(self.input_name(name)),
                Node::Add(a, b) => v(a) + v(b),
                Node::Sub(a, b) => v(a) - v(b),
                Node::Mul(a, b) => v(a) * v(b),
                Node::Div(a, b) => v(a) / v(b),
                Node::Neg(a) => -v(a),
                Node::Powi(a, n) => powi_chain(v(a), n),
                Node::Sqrt(a) => v(a).sqrt(),
                Node::Sin(a) => v(a).sin(),
                Node::Cos(a) => v(a).cos(),
                Node::Tanh(a) => v(a).tanh(),
                Node::Abs(a) => v(a).abs(),
            };
            debug_assert_eq!(values.len(), i);
            values.push(x);
        }
        roots
            .iter()
            .map(|r| values.get(r.index()).copied().unwrap_or(f64::NAN))
            .collect()
    }
}

/// `1 / c` if it is exact: `c` a power of two whose reciprocal is a normal number.
fn exact_reciprocal(c: f64) -> Option<f64> {
    let r = 1.0 / c;
    let is_pow2 = |x: f64| x.is_normal() && x.to_bits() & ((1_u64 << 52) - 1) == 0;
    (is_pow2(c) && is_pow2(r)).then_some(r)
}

/// `x^n` by the same square-and-multiply chain that the emitter writes (see `plan`), so that
/// folding and generated code round alike.
pub(crate) fn powi_chain(x: f64, n: i32) -> f64 {
    let mut result = 1.0;
    let mut base = x;
    let mut e = n.unsigned_abs();
    let mut first = true;
    while e > 0 {
        if e & 1 == 1 {
            result = if first { base } else { result * base };
            first = false;
        }
        e >>= 1;
        if e > 0 {
            base *= base;
        }
    }
    if n < 0 { 1.0 / result } else { result }
}
