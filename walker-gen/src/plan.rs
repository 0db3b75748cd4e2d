//! The evaluation plan: what the emitter writes, decided before any syntax is produced.
//!
//! Passes, in order:
//!
//! 1. **validate** the module (identifiers, declared inputs and parameters, output counts);
//! 2. **expand powers**: `powi(x, n)` becomes a square-and-multiply chain (`x*x`, `x2*x2*x`...,
//!    `1/(...)` for negative `n`), the same chain [`crate::ir::Graph::powi`] folds with; no `powi`
//!    call is emitted;
//! 3. **reciprocals** ([`Division::SharedReciprocal`]): per kernel, `a / d` becomes `a * (1/d)`
//!    when `d` depends on parameters only (the reciprocal is then hoisted into `prepare`) or when
//!    two or more divisions of the kernel share the state-dependent `d`;
//! 4. **hoisting**: a node whose leaves are all parameters and constants (and that is not itself
//!    a constant) is computed in `prepare`; the *frontier* (hoisted nodes used directly by a
//!    kernel) becomes the fields of `Prepared`, inner hoisted nodes are `let`s of `prepare`;
//! 5. **schedule**: in each block (`prepare` or a kernel), a node gets a `let` iff it is used
//!    more than once in the block, or it is a function call (sqrt, sin, cos, tanh) used inside
//!    another expression, or its sine and cosine are both needed (one `sin_cos`), or inlining
//!    it would nest operations deeper than 16 levels (long sums are cut into `let`s of at most
//!    that depth); everything else is inlined. `let`s appear in node-id (topological) order and are named `t0, t1, ...`
//!    in that order, so the output depends on the module only.

use std::collections::{BTreeMap, BTreeSet, HashMap};

use crate::error::EmitError;
use crate::ir::{Graph, Module, Node, NodeId, ParamId};

/// How divisions are evaluated (see the crate docs, "Numerics").
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Default)]
pub enum Division {
    /// A denominator depending on parameters only is inverted once in `prepare`; a
    /// state-dependent denominator shared by two or more divisions of one kernel is inverted
    /// once per call; those quotients become multiplications by the reciprocal.
    ///
    /// Each such quotient is rounded twice instead of once (relative error at most `2u` instead
    /// of `u`, with `u = 2^-53` for `f64`), which is below the error any numerator or
    /// denominator computed in more than one operation already carries; a division costs
    /// several multiplications in latency and throughput. This is the default.
    #[default]
    SharedReciprocal,
    /// Every quotient is one correctly rounded division, as written in the derivation.
    Exact,
}

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

/// A field of `Prepared`.
#[derive(Clone, Debug)]
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

/// Names of functions a generated file may define besides the kernels: `prepare` and the
/// inline float functions ([`crate::FloatFunctions::Inline`]). No kernel may take
/// them, nor an argument, except `prepare` (an argument would shadow the function in the
/// kernel's body).
const RESERVED_FNS: [&str; 3] = ["prepare", "sin_cos", "tanh"];

/// Reserved generated names: `t<digits>` (lets) and `k<digits>` (fields).
fn is_generated_name(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some('t' | 'k')) && s.len() > 1 && chars.all(|c| c.is_ascii_digit())
}

const KEYWORDS: [&str; 52] = [
    "as", "break", "const", "continue", "crate", "else", "enum", "extern", "false", "fn", "for",
    "if", "impl", "in", "let", "loop", "match", "mod", "move", "mut", "pub", "ref", "return",
    "self", "Self", "static", "struct", "super", "trait", "true", "type", "unsafe", "use", "where",
    "while", "async", "await", "dyn", "abstract", "become", "box", "do", "final", "macro",
    "override", "priv", "typeof", "unsized", "virtual", "yield", "try", "gen",
];

/// A lower-case Rust identifier that is not a keyword.
fn is_snake_ident(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some('a'..='z' | '_'))
        && chars.all(|c| matches!(c, 'a'..='z' | '0'..='9' | '_'))
        && s != "_"
        && !KEYWORDS.contains(&s)
}

fn validate(module: &Module) -> Result<(), EmitError> {
    let g = &module.graph;
    if module.scene_name.contains(['\n', '\r']) || module.scene_name.is_empty() {
        return Err(EmitError::BadName {
            what: "scene name".to_owned(),
            name: module.scene_name.clone(),
        });
    }
    let mut fields = BTreeSet::new();
    for p in &module.params {
        let field = p.field();
        if !is_snake_ident(&field) || is_generated_name(&field) || field == "p" {
            return Err(EmitError::BadName {
                what: "parameter".to_owned(),
                name: p.name.clone(),
            });
        }
        if !fields.insert(field) {
            return Err(EmitError::Duplicate {
                what: "parameter field".to_owned(),
                name: p.field(),
            });
        }
    }
    for (_, node) in g.iter() {
        if let Node::Param(p) = node
            && p.index() >= module.params.len()
        {
            return Err(EmitError::UndeclaredParam { index: p.index() });
        }
    }
    let mut names = BTreeSet::new();
    for k in &module.kernels {
        if !is_snake_ident(&k.name) || RESERVED_FNS.contains(&k.name.as_str()) {
            return Err(EmitError::BadName {
                what: "kernel".to_owned(),
                name: k.name.clone(),
            });
        }
        if !names.insert(k.name.as_str()) {
            return Err(EmitError::Duplicate {
                what: "kernel".to_owned(),
                name: k.name.clone(),
            });
        }
        let mut args = BTreeSet::new();
        for a in &k.args {
            // `prepare` is never called from a kernel, so it may be shadowed.
            let reserved = a == "p"
                || (a != "prepare" && RESERVED_FNS.contains(&a.as_str()))
                || a.starts_with('_');
            if !is_snake_ident(a) || is_generated_name(a) || reserved {
                return Err(EmitError::BadName {
                    what: format!("argument of kernel `{}`", k.name),
                    name: a.clone(),
                });
            }
            if !args.insert(a.as_str()) {
                return Err(EmitError::Duplicate {
                    what: format!("argument of kernel `{}`", k.name),
                    name: a.clone(),
                });
            }
        }
        if k.output_shape.is_empty() || k.outputs.len() != k.output_shape.len() {
            return Err(EmitError::ShapeMismatch {
                kernel: k.name.clone(),
                outputs: k.outputs.len(),
                shape: format!("{:?}", k.output_shape),
            });
        }
        let roots: Vec<NodeId> = k.outputs.iter().map(|o| o.1).collect();
        if let Some(bad) = roots.iter().find(|r| !g.contains(**r)) {
            return Err(EmitError::ForeignNode {
                kernel: k.name.clone(),
                index: bad.index(),
            });
        }
        for n in reachable(g, &roots, |_| false) {
            if let Node::Input(i) = g.node(n) {
                let name = g.input_name(i);
                if !args.contains(name) {
                    return Err(EmitError::UndeclaredInput {
                        kernel: k.name.clone(),
                        input: name.to_owned(),
                    });
                }
            }
        }
    }
    Ok(())
}

/// Nodes reachable from `roots`, not descending below nodes where `stop` holds (those are
/// included), in id order.
fn reachable(g: &Graph, roots: &[NodeId], stop: impl Fn(NodeId) -> bool) -> Vec<NodeId> {
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
fn input_dependence(g: &Graph) -> Vec<bool> {
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

/// `x^n` as a square-and-multiply chain (see `powi_chain` in `ir/graph.rs`).
fn power_chain(g: &mut Graph, x: NodeId, n: i32) -> NodeId {
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
fn expand_powers(g: &mut Graph) -> Vec<NodeId> {
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
/// [`Division::SharedReciprocal`] says so; returns the new roots.
fn reciprocals(g: &mut Graph, roots: &[NodeId]) -> Vec<NodeId> {
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

/// The deepest operation nesting an inlined expression may have before it gets a `let`.
const MAX_INLINE_DEPTH: usize = 16;

fn is_call(node: Node) -> bool {
    matches!(
        node,
        Node::Sqrt(_) | Node::Sin(_) | Node::Cos(_) | Node::Tanh(_)
    )
}

/// Schedules one block: `roots` are evaluated, nodes where `external` holds are read from
/// outside (arguments, fields, constants), nodes in `fixed_names` get a `let` with that name.
fn schedule(
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
                Node::Param(p) => {
                    let name = module
                        .params
                        .get(p.index())
                        .map_or_else(|| format!("param{}", p.index()), |d| d.field());
                    (name, Some(p))
                }
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ir::{Kernel, Shape};

    fn module_with(outputs: impl FnOnce(&mut Module) -> Vec<NodeId>) -> Module {
        let mut m = Module::new("t");
        let outs = outputs(&mut m);
        m.kernels.push(Kernel {
            name: "k".to_owned(),
            doc: String::new(),
            equation: String::new(),
            args: vec!["x".to_owned()],
            output_shape: Shape::Vector(outs.len()),
            outputs: outs
                .into_iter()
                .enumerate()
                .map(|(i, n)| (format!("o{i}"), n))
                .collect(),
        });
        m
    }

    #[test]
    fn parameter_only_nodes_are_hoisted() {
        let m = module_with(|m| {
            let a = m.param("a", "");
            let b = m.param("b", "");
            let x = m.graph.input("x");
            let ab = m.graph.add(a, b);
            vec![m.graph.mul(ab, x)]
        });
        let plan = Plan::new(&m, Division::Exact).expect("valid");
        assert_eq!(plan.fields.len(), 1);
        assert_eq!(plan.fields.first().map(|f| f.name.as_str()), Some("k0"));
    }

    #[test]
    fn shared_denominator_becomes_one_reciprocal() {
        let m = module_with(|m| {
            let x = m.graph.input("x");
            let s = m.graph.sin(x);
            let one = m.graph.constant(1.0);
            let d = m.graph.add(one, x);
            vec![m.graph.div(s, d), m.graph.div(x, d)]
        });
        let plan = Plan::new(&m, Division::SharedReciprocal).expect("valid");
        let divs = plan
            .kernels
            .iter()
            .flat_map(|k| &k.block.nodes)
            .filter(|n| matches!(plan.graph.node(**n), Node::Div(..)))
            .count();
        assert_eq!(divs, 1);
    }

    #[test]
    fn undeclared_input_is_rejected() {
        let m = module_with(|m| vec![m.graph.input("y")]);
        assert!(matches!(
            Plan::new(&m, Division::Exact),
            Err(EmitError::UndeclaredInput { .. })
        ));
    }

    #[test]
    fn reserved_and_duplicate_names_are_rejected() {
        for name in ["sin_cos", "tanh", "prepare"] {
            let mut m = module_with(|m| vec![m.graph.input("x")]);
            m.kernels[0].args = vec![name.to_owned()];
            assert_eq!(
                matches!(
                    Plan::new(&m, Division::Exact),
                    Err(EmitError::BadName { .. })
                ),
                name != "prepare",
                "argument {name}"
            );
            let mut m = module_with(|m| vec![m.graph.input("x")]);
            m.kernels[0].name = name.to_owned();
            assert!(matches!(
                Plan::new(&m, Division::Exact),
                Err(EmitError::BadName { .. })
            ));
        }
        let mut m = module_with(|m| vec![m.graph.input("x")]);
        m.kernels[0].args = vec!["p".to_owned()];
        assert!(matches!(
            Plan::new(&m, Division::Exact),
            Err(EmitError::BadName { .. })
        ));
        let mut m = module_with(|m| vec![m.graph.input("x")]);
        m.declare_param("k0", "");
        assert!(matches!(
            Plan::new(&m, Division::Exact),
            Err(EmitError::BadName { .. })
        ));
        let mut m = module_with(|m| vec![m.graph.input("x")]);
        let twin = m.kernels[0].clone();
        m.kernels.push(twin);
        assert!(matches!(
            Plan::new(&m, Division::Exact),
            Err(EmitError::Duplicate { .. })
        ));
        let mut m = module_with(|m| vec![m.graph.input("x")]);
        m.kernels[0].output_shape = Shape::Matrix(2, 2);
        assert!(matches!(
            Plan::new(&m, Division::Exact),
            Err(EmitError::ShapeMismatch { .. })
        ));
    }

    #[test]
    fn sine_and_cosine_pair() {
        let m = module_with(|m| {
            let x = m.graph.input("x");
            vec![m.graph.sin(x), m.graph.cos(x)]
        });
        let plan = Plan::new(&m, Division::Exact).expect("valid");
        let steps = plan.kernels.first().map(|k| k.block.steps.clone());
        assert!(matches!(steps.as_deref(), Some([Step::SinCos { .. }])));
    }
}
