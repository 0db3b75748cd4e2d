//! Pass 5: which nodes of a block get a `let` (and which sines pair with their cosines in one
//! `sin_cos`), in topological order, named `t0, t1, ...`.

use std::collections::{BTreeSet, HashMap};

use super::block::{Block, Step};
use super::reach::reachable;
use crate::ir::{Graph, Node, NodeId};

/// The deepest operation nesting an inlined expression may have before it gets a `let`.
pub(super) const MAX_INLINE_DEPTH: usize = 16;

pub(super) fn is_call(node: Node) -> bool {
    matches!(
        node,
        Node::Sqrt(_) | Node::Sin(_) | Node::Cos(_) | Node::Tanh(_)
    )
}

/// Schedules one block: `roots` are evaluated, nodes where `external` holds are read from
/// outside (arguments, fields, constants), nodes in `fixed_names` get a `let` with that name.
pub(super) fn schedule(
    g: &Graph,
    roots: &[NodeId],
    external: &dyn Fn(NodeId) -> bool,
    fixed_names: &HashMap<NodeId, String>,
) -> Block {
    let nodes: Vec<NodeId> = reachable(g, roots, external)
        .into_iter()
        .filter(|n| !external(*n))
        .collect();
    let in_block: BTreeSet<NodeId> = nodes.iter().copied().collect();
    let mut uses: HashMap<NodeId, usize> = HashMap::new();
    let mut inner_use: BTreeSet<NodeId> = BTreeSet::new();
    for &n in &nodes {
        for c in g.node(n).children() {
            if in_block.contains(&c) {
                *uses.entry(c).or_default() += 1;
                inner_use.insert(c);
            }
        }
    }
    for r in roots {
        if in_block.contains(r) {
            *uses.entry(*r).or_default() += 1;
        }
    }
    let mut cos_of: HashMap<NodeId, NodeId> = HashMap::new();
    for &n in &nodes {
        if let Node::Cos(x) = g.node(n) {
            cos_of.insert(x, n);
        }
    }
    let mut pair_of: HashMap<NodeId, (NodeId, NodeId, NodeId)> = HashMap::new();
    let mut paired_sin = BTreeSet::new();
    for &n in &nodes {
        if let Node::Sin(x) = g.node(n)
            && let Some(&c) = cos_of.get(&x)
        {
            pair_of.insert(n, (n, c, x));
            pair_of.insert(c, (n, c, x));
            paired_sin.insert(n);
        }
    }
    let mut bound: BTreeSet<NodeId> = nodes
        .iter()
        .copied()
        .filter(|n| {
            fixed_names.contains_key(n)
                || pair_of.contains_key(n)
                || uses.get(n).copied().unwrap_or(0) > 1
                || (is_call(g.node(*n)) && inner_use.contains(n))
        })
        .collect();
    // Bound the nesting of inlined expressions (line length, and recursion in the emitter).
    let mut depth: HashMap<NodeId, usize> = HashMap::new();
    for &n in &nodes {
        let d = 1 + g
            .node(n)
            .children()
            .filter(|c| in_block.contains(c) && !bound.contains(c))
            .map(|c| depth.get(&c).copied().unwrap_or(0))
            .max()
            .unwrap_or(0);
        if d > MAX_INLINE_DEPTH && inner_use.contains(&n) {
            bound.insert(n);
        }
        depth.insert(n, if bound.contains(&n) { 0 } else { d });
    }
    let mut block = Block {
        nodes: nodes.clone(),
        paired_sin,
        ..Block::default()
    };
    let mut counter = 0_usize;
    let mut fresh = || {
        let name = format!("t{counter}");
        counter += 1;
        name
    };
    for &n in &nodes {
        if !bound.contains(&n) || block.names.contains_key(&n) {
            continue;
        }
        if let Some(&(sin, cos, arg)) = pair_of.get(&n) {
            for m in [sin, cos] {
                let name = fixed_names.get(&m).cloned().unwrap_or_else(&mut fresh);
                block.names.insert(m, name);
            }
            block.steps.push(Step::SinCos { sin, cos, arg });
        } else {
            let name = fixed_names.get(&n).cloned().unwrap_or_else(&mut fresh);
            block.names.insert(n, name);
            block.steps.push(Step::Let(n));
        }
    }
    block
}
