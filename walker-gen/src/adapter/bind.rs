//! A kernel call as tokens: the generated function called with its arguments read through the
//! contract's [`Binding`], from a call's `Args` (`a.q[2]`) or from the locals of a fused
//! method (the state array `y`, `sigma`, the auxiliary inputs `v`, the inputs `u`).

use std::cell::Cell;

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};
use walker_contract::Binding;
use walker_scene::model::Model;

use crate::error::Error;
use crate::ir::{Kernel, Shape};

/// Where a call reads its arguments.
#[derive(Clone, Copy)]
pub(super) enum Source {
    /// The fields of `a: &Args`.
    Args,
    /// A fused method's locals: `y = [q, qd]` (`n` coordinates), `u`, `v`, `sigma`.
    State {
        /// The number of coordinates.
        n: usize,
    },
}

/// Writes kernel calls of one model, and remembers whether any read `sigma` (a fused method
/// names its parameter `_sigma` when none does: the smooth law has no sliding direction).
pub(super) struct Calls<'m> {
    model: &'m Model,
    source: Source,
    sigma: Cell<bool>,
}

impl<'m> Calls<'m> {
    /// Calls of `model`'s kernels reading from `source`.
    pub(super) fn new(model: &'m Model, source: Source) -> Self {
        Calls {
            model,
            source,
            sigma: Cell::new(false),
        }
    }

    /// Whether a call written so far reads `sigma`.
    pub(super) fn read_sigma(&self) -> bool {
        self.sigma.get()
    }

    /// The expression of one bound argument.
    fn arg(&self, b: Binding) -> TokenStream {
        let lit = Literal::usize_unsuffixed;
        match (b, self.source) {
            (Binding::Sigma, Source::Args) => {
                self.sigma.set(true);
                quote!(a.sigma)
            }
            (Binding::Sigma, Source::State { .. }) => {
                self.sigma.set(true);
                quote!(sigma)
            }
            (Binding::Coordinate(i), Source::Args) => {
                let i = lit(i);
                quote!(a.q[#i])
            }
            (Binding::Velocity(i), Source::Args) => {
                let i = lit(i);
                quote!(a.qd[#i])
            }
            (Binding::Input(i), Source::Args) => {
                let i = lit(i);
                quote!(a.u[#i])
            }
            (Binding::Aux(i), Source::Args) => {
                let i = lit(i);
                quote!(a.v[#i])
            }
            (Binding::Coordinate(i), Source::State { .. }) => {
                let i = lit(i);
                quote!(y[#i])
            }
            (Binding::Velocity(i), Source::State { n }) => {
                let i = lit(n + i);
                quote!(y[#i])
            }
            (Binding::Input(i), Source::State { .. }) => {
                let i = lit(i);
                quote!(u[#i])
            }
            (Binding::Aux(i), Source::State { .. }) => {
                let i = lit(i);
                quote!(v[#i])
            }
        }
    }

    /// The call `k(p, args..)`.
    ///
    /// # Errors
    /// An argument the contract cannot bind ([`walker_contract::BindError`]).
    pub(super) fn call(&self, k: &Kernel) -> Result<TokenStream, Error> {
        let name = format_ident!("{}", k.name);
        let args = Binding::all(self.model, &k.args)?
            .into_iter()
            .map(|b| self.arg(b))
            .collect::<Vec<_>>();
        Ok(quote!(#name(p, #(#args),*)))
    }

    /// The call of `k` stored into the slice `out`, flattened row-major.
    ///
    /// # Errors
    /// As [`Calls::call`].
    pub(super) fn store(&self, k: &Kernel) -> Result<TokenStream, Error> {
        let call = self.call(k)?;
        Ok(match k.output_shape {
            Shape::Scalar => quote!(out[0] = #call;),
            Shape::Vector(n) => {
                let n = Literal::usize_unsuffixed(n);
                quote!(out[..#n].copy_from_slice(&#call);)
            }
            Shape::Matrix(r, c) => {
                let len = Literal::usize_unsuffixed(r * c);
                quote!(out[..#len].copy_from_slice(#call.as_flattened());)
            }
        })
    }
}

/// The outputs `o[from..to]` of a kernel call bound to `o`, as an array expression.
pub(super) fn outputs(from: usize, to: usize) -> TokenStream {
    let items = (from..to).map(Literal::usize_unsuffixed);
    quote!([#(o[#items]),*])
}
