//! The runtime parameters of a file: `pub struct Params` (with `Params::from_fn`),
//! `pub struct Prepared` and `pub fn prepare(p: &Params) -> Prepared`.

use proc_macro2::TokenStream;
use quote::quote;

use super::calls::{const_if_possible, inline_note};
use super::doc::doc_attrs;
use super::writer::{Scope, Writer, ident};
use crate::ir::Module;
use crate::options::EmitOptions;
use crate::plan::Plan;
use crate::stats;

/// The derives of a struct of `F` fields: `Eq` too when it has no fields.
pub(super) fn derives(empty: bool) -> TokenStream {
    if empty {
        quote!(#[derive(Debug, Clone, Copy, PartialEq, Eq)])
    } else {
        quote!(#[derive(Debug, Clone, Copy, PartialEq)])
    }
}

pub(super) fn params_and_prepare(
    module: &Module,
    plan: &Plan,
    options: &EmitOptions,
) -> TokenStream {
    let fields: Vec<TokenStream> = module
        .params
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let docs = doc_attrs(std::slice::from_ref(&p.doc));
            let f = ident(&module.param_field(i));
            quote!(#(#docs)* pub #f: F,)
        })
        .collect();
    let params_doc = doc_attrs(&[
        format!(
            "Runtime parameters of scene `{}` (everything the scene does not fix).",
            module.scene_name
        ),
        String::new(),
        "Pass them to [`prepare`] once per parameter set.".to_owned(),
    ]);
    let w = Writer {
        module,
        plan,
        options,
        names: &plan.prepare.names,
        scope: Scope::Prepare,
    };
    let lets = w.lets(&plan.prepare);
    let prepared_fields: Vec<TokenStream> = plan
        .fields
        .iter()
        .map(|f| {
            let name = ident(&f.name);
            quote!(#name: F,)
        })
        .collect();
    let inits: Vec<TokenStream> = plan
        .fields
        .iter()
        .map(|f| {
            let name = ident(&f.name);
            if f.param.is_some() {
                let (value, _) = w.definition(f.node);
                quote!(#name: #value)
            } else {
                quote!(#name)
            }
        })
        .collect();
    let p = ident(if plan.fields.is_empty() { "_p" } else { "p" });
    let prepare_doc = doc_attrs(&[
        "Computes everything the kernels need that depends on the parameters only.".to_owned(),
        String::new(),
        "Call once per parameter set, then pass the result to every kernel.".to_owned(),
        String::new(),
        format!(
            "Operations: {}.{}",
            stats::block_counts(&plan.graph, &plan.prepare).summary(),
            inline_note(plan, &plan.prepare, options)
        ),
    ]);
    let lookups: Vec<TokenStream> = module
        .params
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let f = ident(&module.param_field(i));
            let name = &p.name;
            quote!(#f: value(#name),)
        })
        .collect();
    let value = if lookups.is_empty() {
        quote!(_value)
    } else {
        quote!(mut value)
    };
    let params_derive = derives(fields.is_empty());
    let prepared_derive = derives(prepared_fields.is_empty());
    let constness = const_if_possible(plan, &plan.prepare);
    quote! {
        #(#params_doc)*
        #params_derive
        pub struct Params {
            #(#fields)*
        }

        impl Params {
            /// The parameters looked up by their names in the scene and `docs/kernels.md`
            /// (`m1`, `I1`, `T_set`, ...): `value` is called once per field, in field order.
            #[must_use]
            pub fn from_fn(#value: impl FnMut(&'static str) -> F) -> Self {
                Self { #(#lookups)* }
            }
        }

        /// Parameter-dependent values computed once by [`prepare`] and read by the kernels.
        #prepared_derive
        pub struct Prepared {
            #(#prepared_fields)*
        }

        #(#prepare_doc)*
        #[must_use]
        pub #constness fn prepare(#p: &Params) -> Prepared {
            #(#lets)*
            Prepared { #(#inits),* }
        }
    }
}
