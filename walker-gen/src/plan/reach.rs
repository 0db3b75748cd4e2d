//! Queries on the graph the passes share: the nodes reachable from some roots, and which nodes
//! depend on a kernel argument.

use crate::ir::{Graph, Node, NodeId};

/// Nodes reachable from `roots`, not descending below nodes where `stop` holds (those are
/// included), in id order.
pub(super) fn reachable(g: &Graph, roots: &[NodeId], stop: impl Fn(NodeId) -> bool) -> Vec<NodeId> {
    let mut seen = vec![false; g.len()];
    let mut stack: Vec<NodeId> = roots.to_vec();
    while let Some(n) = stack.pop() {
        match seen.get_mut(n.index()) {
            Some(s) if !*s => *s = true,
            _ => continue,
        }
        if !stop(n) {
            stack.extend(g.node(n).children());
        }
    }
    seen.iter()
        .enumerate()
        .filter(|(_, s)| **s)
        .map(|(i, _)| NodeId::from_index(i))
        .collect()
}

/// Per node: whether it depends on a kernel input.
pub(super) fn input_dependence(g: &Graph) -> Vec<bool> {
    let mut dep: Vec<bool> = Vec::with_capacity(g.len());
    for (_, node) in g.iter() {
        let d = matches!(node, Node::Input(_))
            || node
                .children()
                .any(|c| dep.get(c.index()).copied().unwrap_or(false));
        dep.push(d);
    }
    dep
}
