//! The nodes of a [`Graph`](super::Graph): their ids ([`NodeId`], [`ParamId`], [`InputId`]),
//! constants by their bits ([`Const`]), the operations ([`Node`]) and their children.

/// A node of a [`Graph`](super::Graph). Children are older than their parents.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub struct NodeId(pub(super) u32);

impl NodeId {
    /// The position of the node in its graph (also its creation order).
    #[must_use]
    pub fn index(self) -> usize {
        self.0 as usize
    }

    /// The id at position `i` (ids are only handed out by a graph).
    pub(crate) fn from_index(i: usize) -> NodeId {
        NodeId(index_u32(i))
    }
}

/// A runtime parameter: an index into [`Module::params`](crate::Module::params), a field of the generated `Params`.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub struct ParamId(pub(super) u32);

impl ParamId {
    /// The index into [`Module::params`](crate::Module::params).
    #[must_use]
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// A kernel argument name interned in a [`Graph`](super::Graph) (see [`Graph::input_name`](super::Graph::input_name)).
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub struct InputId(pub(super) u32);

/// A floating-point constant, stored by its bits so that nodes can be hashed.
///
/// `-0.0` is stored as `+0.0` and every NaN as the canonical NaN.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub struct Const(pub(super) u64);

impl Const {
    /// The constant `v`, normalised.
    #[must_use]
    pub fn new(v: f64) -> Self {
        if v == 0.0 {
            Const(0.0_f64.to_bits())
        } else if v.is_nan() {
            Const(f64::NAN.to_bits())
        } else {
            Const(v.to_bits())
        }
    }

    /// The value.
    #[must_use]
    pub fn value(self) -> f64 {
        f64::from_bits(self.0)
    }
}

/// One operation of the IR.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub enum Node {
    /// A literal constant.
    Const(Const),
    /// A runtime parameter (a field of `Params`).
    Param(ParamId),
    /// A kernel argument (state or input, for example `th1`, `u`, `mu`, `xd`).
    Input(InputId),
    /// `a + b`.
    Add(NodeId, NodeId),
    /// `a - b`.
    Sub(NodeId, NodeId),
    /// `a * b`.
    Mul(NodeId, NodeId),
    /// `a / b`.
    Div(NodeId, NodeId),
    /// `-a`.
    Neg(NodeId),
    /// `a^n` for an integer `n`; emitted as a multiplication chain.
    Powi(NodeId, i32),
    /// `sqrt(a)`.
    Sqrt(NodeId),
    /// `sin(a)`.
    Sin(NodeId),
    /// `cos(a)`.
    Cos(NodeId),
    /// `tanh(a)`.
    Tanh(NodeId),
    /// `|a|`.
    Abs(NodeId),
}

impl Node {
    /// The children of the node, in operand order.
    #[must_use]
    pub fn children(&self) -> Children {
        let (arr, len) = match *self {
            Node::Const(_) | Node::Param(_) | Node::Input(_) => ([NodeId(0); 2], 0),
            Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) | Node::Div(a, b) => ([a, b], 2),
            Node::Neg(a)
            | Node::Powi(a, _)
            | Node::Sqrt(a)
            | Node::Sin(a)
            | Node::Cos(a)
            | Node::Tanh(a)
            | Node::Abs(a) => ([a, a], 1),
        };
        Children { arr, len, pos: 0 }
    }

    /// Whether the node is a leaf (constant, parameter or input).
    #[must_use]
    pub fn is_leaf(&self) -> bool {
        matches!(self, Node::Const(_) | Node::Param(_) | Node::Input(_))
    }
}

/// Iterator over the children of a [`Node`].
#[derive(Clone, Debug)]
pub struct Children {
    arr: [NodeId; 2],
    len: usize,
    pos: usize,
}

impl Iterator for Children {
    type Item = NodeId;

    fn next(&mut self) -> Option<NodeId> {
        let item = self
            .arr
            .get(self.pos)
            .copied()
            .filter(|_| self.pos < self.len);
        self.pos += 1;
        item
    }
}

/// `i` as a `u32` id (saturating; a graph never holds `u32::MAX` nodes).
pub(super) fn index_u32(i: usize) -> u32 {
    u32::try_from(i).unwrap_or(u32::MAX)
}
