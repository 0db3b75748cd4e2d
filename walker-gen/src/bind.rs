//! The scene's parameters as graph nodes: constants where the scene fixes them, runtime
//! parameters (fields of `Params`) otherwise.

use std::collections::BTreeMap;

use crate::ir::{Module, NodeId};
use walker_scene::{Param, Scene};

/// Graph nodes for the parameters of a scene's structure.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParamNodes {
    nodes: BTreeMap<Param, NodeId>,
}

impl ParamNodes {
    /// Makes a node for every parameter of `scene`'s structure: a constant for a fixed one, a
    /// runtime parameter otherwise. Every runtime parameter is declared in `module`, in
    /// canonical order, even if no kernel reads it, so that `Params` has the same fields for
    /// every kernel selection of a structure.
    pub fn declare(scene: &Scene, module: &mut Module) -> ParamNodes {
        let nodes = scene
            .params()
            .into_iter()
            .map(|p| {
                let node = match scene.fixed_value(p) {
                    Some(v) => module.graph.constant(v),
                    None => module.param(p.name(), p.doc()),
                };
                (p, node)
            })
            .collect();
        ParamNodes { nodes }
    }

    /// The node of `param`, or `None` if the scene's structure does not have it.
    #[must_use]
    pub fn get(&self, param: Param) -> Option<NodeId> {
        self.nodes.get(&param).copied()
    }
}
