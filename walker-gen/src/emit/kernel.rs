//! One kernel as a `pub fn <kernel>(p: &Prepared, args..)`: the unchecked fast path, its doc
//! (paper equation, arguments, returns, operation count) and, when asked, its checked variant.

use proc_macro2::TokenStream;
use quote::quote;

use super::calls::{const_if_possible, has_tanh, inline_note, many_arguments};
use super::checked::checked_fn;
use super::doc::{code_list, doc_attrs, returns_doc, wrap};
use super::writer::{Scope, Writer, ident, unsuffixed};
use crate::ir::{Module, Shape};
use crate::options::EmitOptions;
use crate::plan::Plan;
use crate::stats;

pub(super) fn kernel_fn(
    module: &Module,
    plan: &Plan,
    options: &EmitOptions,
    index: usize,
) -> Option<TokenStream> {
    let k = module.kernels.get(index)?;
    let kp = plan.kernels.get(index)?;
    let w = Writer {
        module,
        plan,
        options,
        names: &kp.block.names,
        scope: Scope::Kernel,
    };
    let lets = w.lets(&kp.block);
    let outs: Vec<TokenStream> = kp.outputs.iter().map(|&n| w.expr(n).0).collect();
    let (ret_ty, ret) = match k.output_shape {
        Shape::Scalar => (
            quote!(F),
            outs.first().cloned().unwrap_or_else(|| quote!(0.0)),
        ),
        Shape::Vector(n) => {
            let n = unsuffixed(n);
            (quote!([F; #n]), quote!([#(#outs),*]))
        }
        Shape::Matrix(r, c) => {
            let rows: Vec<TokenStream> = outs
                .chunks(c.max(1))
                .map(|row| quote!([#(#row),*]))
                .collect();
            let (r, c) = (unsuffixed(r), unsuffixed(c));
            (quote!([[F; #c]; #r]), quote!([#(#rows),*]))
        }
    };
    let args: Vec<TokenStream> = k
        .args
        .iter()
        .map(|a| {
            let name = if kp.used_args.contains(a) {
                ident(a)
            } else {
                ident(&format!("_{a}"))
            };
            quote!(#name: F)
        })
        .collect();
    let unused: Vec<String> = k
        .args
        .iter()
        .filter(|a| !kp.used_args.contains(*a))
        .cloned()
        .collect();
    let p = ident(if kp.uses_prepared { "p" } else { "_p" });
    let summary = k.doc.split("\n\n").map(wrap).collect::<Vec<_>>();
    let mut doc = vec![summary.join("\n\n"), String::new()];
    if !k.equation.is_empty() {
        doc.push(format!("Paper: {}.", k.equation));
        doc.push(String::new());
    }
    let args_doc = if k.args.is_empty() {
        "no state arguments".to_owned()
    } else {
        code_list(&k.args)
    };
    doc.push(format!(
        "Arguments: {args_doc}; parameters through `p` from [`prepare`]."
    ));
    if !unused.is_empty() {
        doc.push(format!(
            "Not used by this scene (kept for a uniform signature): {}.",
            code_list(&unused)
        ));
    }
    doc.push(returns_doc(k));
    doc.push(String::new());
    doc.push(format!(
        "Operations per call: {}.{}",
        stats::block_counts(&plan.graph, &kp.block).summary(),
        inline_note(plan, &kp.block, options)
    ));
    doc.push(String::new());
    let saturates = has_tanh(plan, &kp.block);
    doc.push(wrap(&format!(
        "Unchecked fast path: no checks; non-finite inputs propagate to non-finite outputs \
         ({}an argument the scene does not read has no effect); never panics.{}",
        if saturates {
            "but the friction law's `tanh` maps an infinite argument to a finite value, and "
        } else {
            "but "
        },
        if options.checked {
            format!(
                " [`{}_checked`] rejects non-finite arguments and outputs.",
                k.name
            )
        } else {
            String::new()
        }
    )));
    let docs = doc_attrs(&doc);
    let name = ident(&k.name);
    let constness = const_if_possible(plan, &kp.block);
    let checked = if options.checked {
        checked_fn(k, &ret_ty)
    } else {
        quote!()
    };
    let many = many_arguments(k);
    Some(quote! {
        #(#docs)*
        #many
        #[inline]
        #[must_use]
        pub #constness fn #name(#p: &Prepared, #(#args),*) -> #ret_ty {
            #(#lets)*
            #ret
        }

        #checked
    })
}
