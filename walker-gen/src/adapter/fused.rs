//! The adapter's fused methods: `Kernels::tracking`, `stance_rhs`, `power_sign` and
//! `sliding_lambda`, each one generated function with the arithmetic of the trait's provided
//! method (`walker_contract::Kernels`), so that no argument struct, slice or dispatch stands
//! between the integrator and the kernels. A method whose kernels the variant lacks is not
//! written (the provided method stays); a kernel the variant lacks inside a written method
//! gives NaN, as its `eval` arm would.

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};
use walker_scene::model::Model;

use super::bind::{Calls, Source, outputs};
use crate::error::Error;
use crate::ir::{Kernel, Module};

/// What the fused methods are written from: the model, its variant's kernels and the path of
/// the kernel contract.
pub(super) struct Fused<'a> {
    pub(super) model: &'a Model,
    pub(super) module: &'a Module,
    pub(super) contract: &'a TokenStream,
}

impl Fused<'_> {
    fn n(&self) -> usize {
        self.model.coordinates.len()
    }

    fn m(&self) -> usize {
        self.model.inputs.len()
    }

    /// The variant's kernel `name`, if it has it.
    fn kernel(&self, name: &str) -> Option<&Kernel> {
        self.module.kernels.iter().find(|k| k.name == name)
    }

    /// The four methods, those the variant's kernels allow.
    pub(super) fn methods(&self) -> Result<TokenStream, Error> {
        let tracking = self.tracking()?;
        let stance = self.stance_rhs()?;
        let sign = self.power_sign()?;
        let lambda = self.sliding_lambda()?;
        Ok(quote!(#tracking #stance #sign #lambda))
    }

    /// The outputs' rates `r = [y, ydot]` (`output_rates`) and Eq. 32's auxiliary inputs `v`
    /// from them.
    fn aux_inputs(&self, calls: &Calls<'_>, rates: &Kernel) -> Result<TokenStream, Error> {
        let m = Literal::usize_unsuffixed(self.m());
        let rates = calls.call(rates)?;
        Ok(quote! {
            let r = #rates;
            let mut v = [0.0; #m];
            for i in 0..#m {
                v[i] = control.aux_input(i, r[i], r[#m + i]);
            }
        })
    }

    /// `Kernels::tracking` for a model with inputs whose variant has the output and input
    /// rates: the outputs' rates, `v`, the closed loop `k`, the inputs' rates.
    fn tracking(&self) -> Result<TokenStream, Error> {
        let (Some(rates), Some(w)) = (self.kernel("output_rates"), self.kernel("input_rates"))
        else {
            return Ok(TokenStream::new());
        };
        if self.m() == 0 {
            return Ok(TokenStream::new());
        }
        let c = self.contract;
        let calls = Calls::new(self.model, Source::Args);
        let m = Literal::usize_unsuffixed(self.m());
        let two_m = Literal::usize_unsuffixed(2 * self.m());
        let rates = calls.store(rates)?;
        let w = calls.store(w)?;
        let mut arms = Vec::new();
        for name in ["closed_loop", "closed_loop_stick"] {
            if let Some(k) = self.kernel(name) {
                let id = super::kernel_variant(name)?;
                let store = calls.store(k)?;
                arms.push(quote!(KernelId::#id => { #store }));
            }
        }
        Ok(quote! {
            fn tracking(
                &self,
                k: KernelId,
                a: &Args<'_>,
                control: &#c::Tracking<'_>,
                out: &mut [f64],
                w: &mut [f64],
            ) {
                let p = &self.0;
                let mut r = [0.0; #two_m];
                {
                    let out = &mut r[..];
                    #rates
                }
                let mut v = [0.0; #m];
                for i in 0..#m {
                    v[i] = control.aux_input(i, r[i], r[#m + i]);
                }
                let a = &Args { v: &v, ..*a };
                match k {
                    #(#arms)*
                    _ => out.fill(f64::NAN),
                }
                {
                    let out = w;
                    #w
                }
            }
        })
    }

    /// `qdd` (then `u` with inputs) from a kernel whose outputs start with them, as a block.
    fn split(&self, calls: &Calls<'_>, name: &str) -> Result<TokenStream, Error> {
        let (n, m) = (self.n(), self.m());
        let (nl, ml) = (Literal::usize_unsuffixed(n), Literal::usize_unsuffixed(m));
        let Some(k) = self.kernel(name) else {
            return Ok(if m == 0 {
                quote!([f64::NAN; #nl])
            } else {
                quote!(([f64::NAN; #nl], [f64::NAN; #ml]))
            });
        };
        let call = calls.call(k)?;
        let value = if m == 0 {
            outputs(0, n)
        } else {
            let (qdd, u) = (outputs(0, n), outputs(n, n + m));
            quote!((#qdd, #u))
        };
        Ok(quote!({
            let o = #call;
            #value
        }))
    }

    /// `Kernels::stance_rhs`: `dy = [qd, qdd]` and the input power's integrand.
    fn stance_rhs(&self) -> Result<TokenStream, Error> {
        let (n, m) = (self.n(), self.m());
        let c = self.contract;
        let calls = Calls::new(self.model, Source::State { n });
        let (nl, ml) = (Literal::usize_unsuffixed(n), Literal::usize_unsuffixed(m));
        let (body, result, control) = if m == 0 {
            let (stick, accel) = (self.split(&calls, "stick")?, self.split(&calls, "accel")?);
            (
                quote!(let qdd: [f64; #nl] = if stuck #stick else #accel;),
                quote!(0.0),
                false,
            )
        } else {
            let (Some(rates), Some(w)) = (self.kernel("output_rates"), self.kernel("input_rates"))
            else {
                return Ok(TokenStream::new());
            };
            let aux = self.aux_inputs(&calls, rates)?;
            let w = calls.call(w)?;
            let stick = self.split(&calls, "closed_loop_stick")?;
            let free = self.split(&calls, "closed_loop")?;
            (
                quote! {
                    #aux
                    let w = #w;
                    let (qdd, u): ([f64; #nl], [f64; #ml]) = if stuck #stick else #free;
                },
                quote!(#c::power(&u, &w)),
                true,
            )
        };
        let sigma = name(calls.read_sigma(), "sigma");
        let control = name(control, "control");
        let two_n = Literal::usize_unsuffixed(2 * n);
        let state = state(2 * n);
        let message = format!("a derivative of {} numbers", 2 * n);
        Ok(quote! {
            fn stance_rhs(
                &self,
                stuck: bool,
                #sigma: f64,
                y: &[f64],
                #control: &#c::Tracking<'_>,
                dy: &mut [f64],
            ) -> f64 {
                let p = &self.0;
                #state
                let dy: &mut [f64; #two_n] = dy.try_into().expect(#message);
                #body
                dy[..#nl].copy_from_slice(&y[#nl..]);
                dy[#nl..].copy_from_slice(&qdd);
                #result
            }
        })
    }

    /// `Kernels::power_sign` for a model with inputs: `prod u_i w_i`.
    fn power_sign(&self) -> Result<TokenStream, Error> {
        let (n, m) = (self.n(), self.m());
        let (Some(rates), Some(w)) = (self.kernel("output_rates"), self.kernel("input_rates"))
        else {
            return Ok(TokenStream::new());
        };
        if m == 0 {
            return Ok(TokenStream::new());
        }
        let c = self.contract;
        let calls = Calls::new(self.model, Source::State { n });
        let ml = Literal::usize_unsuffixed(m);
        let inputs = |name: &str| -> Result<TokenStream, Error> {
            let Some(k) = self.kernel(name) else {
                return Ok(quote!([f64::NAN; #ml]));
            };
            let call = calls.call(k)?;
            let u = outputs(n, n + m);
            Ok(quote!({
                let o = #call;
                #u
            }))
        };
        let aux = self.aux_inputs(&calls, rates)?;
        let w = calls.call(w)?;
        let (stick, free) = (inputs("closed_loop_stick")?, inputs("closed_loop")?);
        let sigma = name(calls.read_sigma(), "sigma");
        let state = state(2 * n);
        Ok(quote! {
            fn power_sign(
                &self,
                stuck: bool,
                #sigma: f64,
                y: &[f64],
                control: &#c::Tracking<'_>,
            ) -> f64 {
                let p = &self.0;
                #state
                #aux
                let w = #w;
                let u: [f64; #ml] = if stuck #stick else #free;
                w.iter().zip(&u).map(|(wi, ui)| wi * ui).product()
            }
        })
    }

    /// `Kernels::sliding_lambda`: `lambda` with the closed loop's inputs of that point.
    fn sliding_lambda(&self) -> Result<TokenStream, Error> {
        let (n, m) = (self.n(), self.m());
        let Some(lambda) = self.kernel("lambda") else {
            return Ok(TokenStream::new());
        };
        let c = self.contract;
        let calls = Calls::new(self.model, Source::State { n });
        let mut body = TokenStream::new();
        if m > 0 {
            let (Some(rates), Some(closed_loop)) =
                (self.kernel("output_rates"), self.kernel("closed_loop"))
            else {
                return Ok(TokenStream::new());
            };
            let aux = self.aux_inputs(&calls, rates)?;
            let call = calls.call(closed_loop)?;
            let u = outputs(n, n + m);
            body = quote! {
                #aux
                let o = #call;
                let u = #u;
            };
        }
        let lambda = calls.call(lambda)?;
        let sigma = name(calls.read_sigma(), "sigma");
        let control = name(m > 0, "control");
        let state = state(2 * n);
        Ok(quote! {
            fn sliding_lambda(&self, #sigma: f64, y: &[f64], #control: &#c::Tracking<'_>) -> f64 {
                let p = &self.0;
                #state
                #body
                #lambda
            }
        })
    }
}

/// The state slice `y` read as the array `[q, qd]` of `two_n` numbers.
fn state(two_n: usize) -> TokenStream {
    let len = Literal::usize_unsuffixed(two_n);
    let message = format!("a state of {two_n} numbers");
    quote!(let y: &[f64; #len] = y[..#len].try_into().expect(#message);)
}

/// A fused method's parameter `param`: itself if the body reads it, else `_param`.
fn name(read: bool, param: &str) -> proc_macro2::Ident {
    if read {
        format_ident!("{param}")
    } else {
        format_ident!("_{param}")
    }
}
