//! A straight-line block (`prepare`'s body or a kernel's body) and its steps.

use std::collections::{BTreeSet, HashMap};

use crate::ir::NodeId;

/// One step of a block.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Step {
    /// `let name = <node>;`
    Let(NodeId),
    /// `let (s, c) = arg.sin_cos();`
    SinCos {
        /// The `Sin` node.
        sin: NodeId,
        /// The `Cos` node.
        cos: NodeId,
        /// Their common argument.
        arg: NodeId,
    },
}

/// A straight-line block: `prepare`'s body or a kernel's body.
#[derive(Clone, Debug, Default)]
pub(crate) struct Block {
    /// The `let`s, in emission order.
    pub steps: Vec<Step>,
    /// The name of every `let`-bound node.
    pub names: HashMap<NodeId, String>,
    /// Every operation node the block evaluates (let-bound or inline), in id order.
    pub nodes: Vec<NodeId>,
    /// `Sin` nodes computed together with their `Cos` by one `sin_cos`.
    pub paired_sin: BTreeSet<NodeId>,
}
