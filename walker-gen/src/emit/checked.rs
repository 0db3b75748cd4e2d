//! The checked entry points: `pub fn <kernel>_checked` returning `Result<_, KernelError>`, and
//! the `KernelError` enum written once per file.

use proc_macro2::{Ident, Literal, TokenStream};
use quote::quote;

use super::doc::{code_list, doc_attrs, wrap};
use super::writer::{ident, unsuffixed};
use crate::ir::{Kernel, Module, Shape};
use crate::options::EmitOptions;

/// `pub fn <kernel>_checked`: argument checks in argument order, the unchecked kernel, output
/// checks in return order, each one line through the private helpers of `KernelError`.
pub(super) fn checked_fn(k: &Kernel, ret_ty: &TokenStream) -> TokenStream {
    let name = ident(&k.name);
    let checked_name = ident(&format!("{}_checked", k.name));
    let args: Vec<Ident> = k.args.iter().map(|a| ident(a)).collect();
    let arg_checks: Vec<TokenStream> = k
        .args
        .iter()
        .map(|a| {
            let (arg, lit) = (ident(a), Literal::string(a));
            quote!(KernelError::argument(#lit, #arg)?;)
        })
        .collect();
    let places: Vec<TokenStream> = match k.output_shape {
        Shape::Scalar => vec![quote!(out)],
        Shape::Vector(n) => (0..n)
            .map(|i| {
                let i = unsuffixed(i);
                quote!(out[#i])
            })
            .collect(),
        Shape::Matrix(r, c) => (0..r)
            .flat_map(|i| (0..c).map(move |j| (i, j)))
            .map(|(i, j)| {
                let (i, j) = (unsuffixed(i), unsuffixed(j));
                quote!(out[#i][#j])
            })
            .collect(),
    };
    let out_checks: Vec<TokenStream> = places
        .iter()
        .zip(&k.outputs)
        .map(|(place, (out_name, _))| {
            let lit = Literal::string(out_name);
            quote!(KernelError::output(#lit, #place)?;)
        })
        .collect();
    let arg_order = if k.args.is_empty() {
        String::new()
    } else {
        format!(" (in the order {})", code_list(&k.args))
    };
    let out_names: Vec<String> = k.outputs.iter().map(|o| o.0.clone()).collect();
    let docs = doc_attrs(&[
        wrap(&format!(
            "Checked variant of [`{}`]: the same value, or why it would not be finite.",
            k.name
        )),
        String::new(),
        wrap(&format!(
            "Every argument is checked, also one the scene does not read. Cost: the unchecked \
             kernel plus {} finiteness tests. Never panics.",
            k.args.len() + k.outputs.len()
        )),
        String::new(),
        "# Errors".to_owned(),
        String::new(),
        wrap(&format!(
            "[`KernelError::NonFiniteArgument`] naming the first argument{arg_order} that is \
             NaN or infinite; otherwise [`KernelError::NonFiniteOutput`] naming the first output \
             (in the order {}) that is NaN or infinite, for example where a denominator \
             vanishes or a parameter given to [`prepare`] is not finite.",
            code_list(&out_names)
        )),
    ]);
    let many = super::calls::many_arguments(k);
    quote! {
        #(#docs)*
        #many
        #[inline]
        pub fn #checked_name(p: &Prepared, #(#args: F),*) -> Result<#ret_ty, KernelError> {
            #(#arg_checks)*
            let out = #name(p, #(#args),*);
            #(#out_checks)*
            Ok(out)
        }
    }
}

/// The `KernelError` enum of the checked entry points, with `Display` (and, in std mode,
/// `std::error::Error`).
pub(super) fn kernel_error(module: &Module, options: &EmitOptions) -> TokenStream {
    // Emitted only if used, so that a file whose kernels take no argument has no dead code.
    let argument = if module.kernels.iter().any(|k| !k.args.is_empty()) {
        quote! {
            /// `x`, or `Err(NonFiniteArgument { name })` if the argument `x` is NaN or infinite.
            #[inline]
            const fn argument(name: &'static str, x: F) -> Result<F, Self> {
                if x.is_finite() {
                    Ok(x)
                } else {
                    Err(Self::NonFiniteArgument { name })
                }
            }
        }
    } else {
        quote!()
    };
    let std_error = if options.no_std {
        quote!()
    } else {
        quote! {
            impl std::error::Error for KernelError {}
        }
    };
    quote! {
        /// Why a checked kernel (`<kernel>_checked`) returned no value.
        ///
        /// The names are the kernel's argument and output names as in its documentation.
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        pub enum KernelError {
            /// An argument is NaN or infinite (the first such argument in argument order).
            NonFiniteArgument {
                /// The argument's name.
                name: &'static str,
            },
            /// Every argument is finite but an output is NaN or infinite (the first such output
            /// in return order), for example where a denominator vanishes.
            NonFiniteOutput {
                /// The output's name.
                name: &'static str,
            },
        }

        impl KernelError {
            #argument

            /// `x`, or `Err(NonFiniteOutput { name })` if the output `x` is NaN or infinite.
            #[inline]
            const fn output(name: &'static str, x: F) -> Result<F, Self> {
                if x.is_finite() {
                    Ok(x)
                } else {
                    Err(Self::NonFiniteOutput { name })
                }
            }
        }

        impl core::fmt::Display for KernelError {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                match self {
                    Self::NonFiniteArgument { name } => {
                        write!(f, "argument `{name}` is not finite (NaN or infinite)")
                    }
                    Self::NonFiniteOutput { name } => write!(
                        f,
                        "output `{name}` is not finite (NaN or infinite) for finite arguments"
                    ),
                }
            }
        }

        #std_error
    }
}
