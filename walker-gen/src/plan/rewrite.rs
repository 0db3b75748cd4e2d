//! Passes 2 and 3, which rewrite the graph: powers become square-and-multiply chains, and
//! divisions by a shared or parameter-only denominator become multiplications by its
//! reciprocal.

use std::collections::{BTreeMap, HashMap};

use super::reach::{input_dependence, reachable};
use crate::ir::{Graph, Node, NodeId};

/// `x^n` as a square-and-multiply chain (see `powi_chain` in `ir/graph.rs`).
pub(super) fn power_chain(g: &mut Graph, x: NodeId, n: i32) -> NodeId {
    let mut result: Option<NodeId> = None;
    let mut base = x;
    let mut e = n.unsigned_abs();
    while e > 0 {
        if e & 1 == 1 {
            result = Some(match result {
                None => base,
                Some(r) => g.mul(r, base),
            });
        }
        e >>= 1;
        if e > 0 {
            base = g.mul(base, base);
        }
    }
    let positive = result.unwrap_or_else(|| g.constant(1.0));
    if n < 0 {
        let one = g.constant(1.0);
        g.div(one, positive)
    } else {
        positive
    }
}

/// Rewrites every node so that no `Powi` remains; returns the new id of each old node.
pub(super) fn expand_powers(g: &mut Graph) -> Vec<NodeId> {
    let old: Vec<Node> = g.iter().map(|(_, n)| n).collect();
    let mut map: Vec<NodeId> = Vec::with_capacity(old.len());
    for node in old {
        let m = |c: NodeId, map: &Vec<NodeId>| map.get(c.index()).copied().unwrap_or(c);
        let new = match node {
            Node::Powi(x, n) => {
                let x = m(x, &map);
                power_chain(g, x, n)
            }
            _ => g.rebuild(node, |c| m(c, &map)),
        };
        map.push(new);
    }
    map
}

/// Rewrites the divisions reachable from `roots` as multiplications by a reciprocal where
/// [`Division::SharedReciprocal`](crate::Division::SharedReciprocal) says so; returns the new roots.
pub(super) fn reciprocals(g: &mut Graph, roots: &[NodeId]) -> Vec<NodeId> {
    let dep = input_dependence(g);
    let depends = |n: NodeId| dep.get(n.index()).copied().unwrap_or(true);
    let nodes = reachable(g, roots, |_| false);
    let mut shared: BTreeMap<NodeId, usize> = BTreeMap::new();
    for &n in &nodes {
        if let Node::Div(_, d) = g.node(n)
            && depends(n)
        {
            *shared.entry(d).or_default() += 1;
        }
    }
    let mut map: HashMap<NodeId, NodeId> = HashMap::new();
    for &n in &nodes {
        let node = g.node(n);
        let m = |c: NodeId, map: &HashMap<NodeId, NodeId>| map.get(&c).copied().unwrap_or(c);
        let new = match node {
            Node::Div(a, d)
                if depends(n) && (!depends(d) || shared.get(&d).copied().unwrap_or(0) >= 2) =>
            {
                let (a, d) = (m(a, &map), m(d, &map));
                let one = g.constant(1.0);
                let r = g.div(one, d);
                g.mul(a, r)
            }
            _ => g.rebuild(node, |c| m(c, &map)),
        };
        map.insert(n, new);
    }
    roots
        .iter()
        .map(|r| map.get(r).copied().unwrap_or(*r))
        .collect()
}
