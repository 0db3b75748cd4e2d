//! Which float functions a block calls: the private `sin_cos` and `tanh` of
//! [`crate::FloatFunctions::Inline`] appended to a file, the note that names them in an operation count,
//! whether a block may be a `const fn`, and whether a kernel's signature needs clippy's
//! allowance for many arguments.

use proc_macro2::TokenStream;
use quote::quote;

use super::doc::code_list;
use crate::ir::Node;
use crate::options::EmitOptions;
use crate::plan::{Block, Plan, Step};

/// The private float functions of [`crate::FloatFunctions::Inline`]: name and source, in the order
/// they are appended to a file. The source is written verbatim (it is `rustfmt`-formatted, and
/// its comments carry fdlibm's notice); `tests/it/fastmath_accuracy.rs` includes the same files.
pub(super) const INLINE_HELPERS: [(&str, &str); 2] = [
    ("sin_cos", include_str!("../fastmath/sin_cos.rs")),
    ("tanh", include_str!("../fastmath/tanh.rs")),
];

/// The names of the inline float functions `block` calls, in [`INLINE_HELPERS`] order (none
/// unless [`EmitOptions::inline_float_functions`]).
fn inline_calls(plan: &Plan, block: &Block, options: &EmitOptions) -> Vec<&'static str> {
    if !options.inline_float_functions() {
        return Vec::new();
    }
    INLINE_HELPERS
        .iter()
        .map(|h| h.0)
        .filter(|&name| match name {
            "sin_cos" => block.steps.iter().any(|s| matches!(s, Step::SinCos { .. })),
            "tanh" => has_tanh(plan, block),
            _ => false,
        })
        .collect()
}

/// Whether `block` evaluates a `tanh` (a friction law).
pub(super) fn has_tanh(plan: &Plan, block: &Block) -> bool {
    block
        .nodes
        .iter()
        .any(|&n| matches!(plan.graph.node(n), Node::Tanh(_)))
}

/// The names of the inline float functions any block of `plan` calls.
pub(super) fn inline_calls_of_file(plan: &Plan, options: &EmitOptions) -> Vec<&'static str> {
    let mut used: Vec<&'static str> = plan
        .kernels
        .iter()
        .map(|k| &k.block)
        .chain([&plan.prepare])
        .flat_map(|b| inline_calls(plan, b, options))
        .collect();
    used.sort_by_key(|name| INLINE_HELPERS.iter().position(|h| h.0 == *name));
    used.dedup();
    used
}

/// A second line for an operation count whose transcendental calls include the file's own
/// functions (`"\nTranscendental calls inline in this file: `sin_cos`, `tanh`."`), else nothing.
pub(super) fn inline_note(plan: &Plan, block: &Block, options: &EmitOptions) -> String {
    let used = inline_calls(plan, block, options);
    if used.is_empty() {
        String::new()
    } else {
        let names: Vec<String> = used.iter().map(|s| (*s).to_owned()).collect();
        format!(
            "\nTranscendental calls inline in this file: {}.",
            code_list(&names)
        )
    }
}

/// `const` if the block calls no float function (arithmetic and `abs` are `const`).
pub(super) fn const_if_possible(plan: &Plan, block: &Block) -> TokenStream {
    let calls = block.nodes.iter().any(|&n| {
        matches!(
            plan.graph.node(n),
            Node::Sqrt(_) | Node::Sin(_) | Node::Cos(_) | Node::Tanh(_) | Node::Powi(..)
        )
    });
    if calls { quote!() } else { quote!(const) }
}

/// `#[allow(clippy::too_many_arguments)]` for a kernel with more than clippy's seven parameters
/// (`p` and the state components it reads: a model with many coordinates), nothing otherwise.
pub(super) fn many_arguments(k: &crate::ir::Kernel) -> TokenStream {
    if k.args.len() < 7 {
        return quote!();
    }
    quote! {
        #[allow(
            clippy::too_many_arguments,
            reason = "one argument per state component the kernel reads, as the model declares them"
        )]
    }
}
