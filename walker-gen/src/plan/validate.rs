//! Pass 1: the module is valid Rust to emit (identifiers, no clash with generated names,
//! declared inputs and parameters, output counts).

use std::collections::BTreeSet;

use super::reach::reachable;
use crate::error::EmitError;
use crate::ir::{Module, Node, NodeId};

/// Names of functions a generated file may define besides the kernels: `prepare` and the
/// inline float functions ([`crate::FloatFunctions::Inline`]). No kernel may take
/// them, nor an argument, except `prepare` (an argument would shadow the function in the
/// kernel's body).
pub(super) const RESERVED_FNS: [&str; 3] = ["prepare", "sin_cos", "tanh"];

/// Reserved generated names: `t<digits>` (lets) and `k<digits>` (fields).
pub(super) fn is_generated_name(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some('t' | 'k')) && s.len() > 1 && chars.all(|c| c.is_ascii_digit())
}

pub(super) const KEYWORDS: [&str; 52] = [
    "as", "break", "const", "continue", "crate", "else", "enum", "extern", "false", "fn", "for",
    "if", "impl", "in", "let", "loop", "match", "mod", "move", "mut", "pub", "ref", "return",
    "self", "Self", "static", "struct", "super", "trait", "true", "type", "unsafe", "use", "where",
    "while", "async", "await", "dyn", "abstract", "become", "box", "do", "final", "macro",
    "override", "priv", "typeof", "unsized", "virtual", "yield", "try", "gen",
];

/// A lower-case Rust identifier that is not a keyword.
pub(super) fn is_snake_ident(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some('a'..='z' | '_'))
        && chars.all(|c| matches!(c, 'a'..='z' | '0'..='9' | '_'))
        && s != "_"
        && !KEYWORDS.contains(&s)
}

pub(super) fn validate(module: &Module) -> Result<(), EmitError> {
    let g = &module.graph;
    if module.scene_name.contains(['\n', '\r']) || module.scene_name.is_empty() {
        return Err(EmitError::BadName {
            what: "scene name".to_owned(),
            name: module.scene_name.clone(),
        });
    }
    let mut fields = BTreeSet::new();
    for (i, p) in module.params.iter().enumerate() {
        let field = module.param_field(i);
        if !is_snake_ident(&field) || is_generated_name(&field) || field == "p" {
            return Err(EmitError::BadName {
                what: "parameter".to_owned(),
                name: p.name.clone(),
            });
        }
        if !fields.insert(field) {
            return Err(EmitError::Duplicate {
                what: "parameter field".to_owned(),
                name: module.param_field(i),
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
