//! What the plan of a module holds (the fields of `Prepared`, `prepare`'s block, one plan per
//! kernel) and [`Plan::new`], which runs the passes in order.

use std::collections::{BTreeSet, HashMap};

use super::block::Block;
use super::reach::{input_dependence, reachable};
use super::rewrite::{expand_powers, reciprocals};
use super::schedule::schedule;
use super::validate::validate;
use crate::error::EmitError;
use crate::ir::{Graph, Module, Node, NodeId, ParamId};
use crate::options::Division;

/// A field of `Prepared`.
#[derive(Clone, Debug)]
#[cfg_attr(
    not(feature = "emit"),
    allow(dead_code, reason = "read by the emitter (the `emit` feature)")
)]
pub(crate) struct Field {
    /// The hoisted node.
    pub node: NodeId,
    /// The field name (`k0`, ... or the parameter's field name for a bare parameter).
    pub name: String,
    /// The parameter, if the field is a bare parameter.
    pub param: Option<ParamId>,
}

/// The plan of one kernel.
#[derive(Clone, Debug)]
#[cfg_attr(
    not(feature = "emit"),
    allow(dead_code, reason = "read by the emitter (the `emit` feature)")
)]
pub(crate) struct KernelPlan {
    /// The output nodes (after rewrites), in output order.
    pub outputs: Vec<NodeId>,
    /// The body.
    pub block: Block,
    /// The arguments the body reads.
    pub used_args: BTreeSet<String>,
    /// Whether the body reads `Prepared`.
    pub uses_prepared: bool,
}

/// The plan of a whole module.
#[derive(Clone, Debug)]
pub(crate) struct Plan {
    /// The module's graph plus the rewritten nodes.
    pub graph: Graph,
    /// Fields of `Prepared`, in id order.
    pub fields: Vec<Field>,
    /// Field name by node.
    pub field_of: HashMap<NodeId, String>,
    /// The body of `prepare`.
    pub prepare: Block,
    /// One plan per kernel, in module order.
    pub kernels: Vec<KernelPlan>,
}

impl Plan {
    /// Validates `module` and plans its evaluation.
    pub(crate) fn new(module: &Module, division: Division) -> Result<Plan, EmitError> {
        validate(module)?;
        let mut g = module.graph.clone();
        let powers = expand_powers(&mut g);
        let mut outputs: Vec<Vec<NodeId>> = module
            .kernels
            .iter()
            .map(|k| {
                k.outputs
                    .iter()
                    .map(|(_, n)| powers.get(n.index()).copied().unwrap_or(*n))
                    .collect()
            })
            .collect();
        if division == Division::SharedReciprocal {
            for roots in &mut outputs {
                *roots = reciprocals(&mut g, roots);
            }
        }
        let dep = input_dependence(&g);
        let hoisted = |n: NodeId| {
            !dep.get(n.index()).copied().unwrap_or(true) && !matches!(g.node(n), Node::Const(_))
        };
        let leaf = |n: NodeId| g.node(n).is_leaf() || hoisted(n);

        // Frontier: hoisted nodes read directly by kernels.
        let mut frontier: BTreeSet<NodeId> = BTreeSet::new();
        for roots in &outputs {
            for n in reachable(&g, roots, leaf) {
                if hoisted(n) {
                    frontier.insert(n);
                }
            }
        }
        let mut fields = Vec::new();
        let mut field_of = HashMap::new();
        let mut fixed_names = HashMap::new();
        let mut k = 0_usize;
        for &n in &frontier {
            let (name, param) = match g.node(n) {
                Node::Param(p) => (module.param_field(p.index()), Some(p)),
                _ => {
                    let name = format!("k{k}");
                    k += 1;
                    fixed_names.insert(n, name.clone());
                    (name, None)
                }
            };
            field_of.insert(n, name.clone());
            fields.push(Field {
                node: n,
                name,
                param,
            });
        }
        let roots: Vec<NodeId> = frontier.iter().copied().collect();
        let prepare_external = |n: NodeId| g.node(n).is_leaf();
        let prepare = schedule(&g, &roots, &prepare_external, &fixed_names);

        let mut kernels = Vec::new();
        for roots in outputs {
            let block = schedule(&g, &roots, &leaf, &HashMap::new());
            let mut used_args = BTreeSet::new();
            let mut uses_prepared = false;
            for n in reachable(&g, &roots, leaf) {
                match g.node(n) {
                    Node::Input(i) => {
                        used_args.insert(g.input_name(i).to_owned());
                    }
                    _ if hoisted(n) => uses_prepared = true,
                    _ => {}
                }
            }
            kernels.push(KernelPlan {
                outputs: roots,
                block,
                used_args,
                uses_prepared,
            });
        }
        Ok(Plan {
            graph: g,
            fields,
            field_of,
            prepare,
            kernels,
        })
    }
}
