//! The expression writer: a [`Writer`] turns graph nodes into Rust expressions of type `F`
//! with the fewest parentheses (by precedence), constants with round-trip digits or their
//! `core::f64::consts` name, and float functions as std methods, `libm` calls or the file's
//! own functions; and the `let` statements of a block.

use std::collections::HashMap;

use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;

use super::calls::INLINE_HELPERS;
use crate::ir::{Module, Node, NodeId};
use crate::options::{EmitOptions, Float};
use crate::plan::{Block, Plan, Step};

// Precedence levels, loosest first.
const SUM: u8 = 1;
const PRODUCT: u8 = 2;
const UNARY: u8 = 3;
const POSTFIX: u8 = 4;
const ATOM: u8 = 5;

pub(super) fn ident(name: &str) -> Ident {
    Ident::new(name, Span::call_site())
}

fn ident_expr(name: &str) -> TokenStream {
    let i = ident(name);
    quote!(#i)
}

fn paren_if(t: TokenStream, cond: bool) -> TokenStream {
    if cond { quote!((#t)) } else { t }
}

pub(super) fn unsuffixed(n: usize) -> Literal {
    Literal::usize_unsuffixed(n)
}

/// The named constants of `core::f64::consts` (also clippy's `approx_constant` list).
const NAMED: [(&str, f64, f32); 19] = {
    use std::f32::consts as s;
    use std::f64::consts as d;
    [
        ("PI", d::PI, s::PI),
        ("TAU", d::TAU, s::TAU),
        ("FRAC_PI_2", d::FRAC_PI_2, s::FRAC_PI_2),
        ("FRAC_PI_3", d::FRAC_PI_3, s::FRAC_PI_3),
        ("FRAC_PI_4", d::FRAC_PI_4, s::FRAC_PI_4),
        ("FRAC_PI_6", d::FRAC_PI_6, s::FRAC_PI_6),
        ("FRAC_PI_8", d::FRAC_PI_8, s::FRAC_PI_8),
        ("FRAC_1_PI", d::FRAC_1_PI, s::FRAC_1_PI),
        ("FRAC_2_PI", d::FRAC_2_PI, s::FRAC_2_PI),
        ("FRAC_2_SQRT_PI", d::FRAC_2_SQRT_PI, s::FRAC_2_SQRT_PI),
        ("SQRT_2", d::SQRT_2, s::SQRT_2),
        ("FRAC_1_SQRT_2", d::FRAC_1_SQRT_2, s::FRAC_1_SQRT_2),
        ("E", d::E, s::E),
        ("LN_2", d::LN_2, s::LN_2),
        ("LN_10", d::LN_10, s::LN_10),
        ("LOG2_E", d::LOG2_E, s::LOG2_E),
        ("LOG10_E", d::LOG10_E, s::LOG10_E),
        ("LOG2_10", d::LOG2_10, s::LOG2_10),
        ("LOG10_2", d::LOG10_2, s::LOG10_2),
    ]
};

/// Where a block reads its leaves from.
#[derive(Clone, Copy)]
pub(super) enum Scope {
    /// `prepare`: parameters are `p.<field>` of `Params`.
    Prepare,
    /// A kernel: hoisted nodes are `p.<field>` of `Prepared`.
    Kernel,
}

pub(super) struct Writer<'a> {
    pub(super) module: &'a Module,
    pub(super) plan: &'a Plan,
    pub(super) options: &'a EmitOptions,
    pub(super) names: &'a HashMap<NodeId, String>,
    pub(super) scope: Scope,
}

impl Writer<'_> {
    /// A literal of type `F` and its precedence.
    fn literal(&self, v: f64) -> (TokenStream, u8) {
        let (magnitude, negative) = (v.abs(), v.is_sign_negative() && v != 0.0);
        let ty = ident(self.options.float.name());
        let body = if magnitude.is_nan() {
            quote!(F::NAN)
        } else if magnitude.is_infinite() {
            quote!(F::INFINITY)
        } else {
            let (named, digits) = match self.options.float {
                Float::F64 => (
                    NAMED.iter().find(|c| c.1 == magnitude).map(|c| c.0),
                    format!("{magnitude:?}_f64"),
                ),
                Float::F32 => {
                    #[allow(
                        clippy::cast_possible_truncation,
                        reason = "rounding to f32 is the point"
                    )]
                    let m = magnitude as f32;
                    if m.is_infinite() {
                        return self.signed(quote!(F::INFINITY), negative);
                    }
                    (
                        NAMED.iter().find(|c| c.2 == m).map(|c| c.0),
                        format!("{m:?}_f32"),
                    )
                }
            };
            match (named, digits.parse::<Literal>()) {
                (Some(name), _) => {
                    let name = ident(name);
                    quote!(core::#ty::consts::#name)
                }
                (None, Ok(lit)) => quote!(#lit),
                (None, Err(_)) => quote!(F::NAN),
            }
        };
        self.signed(body, negative)
    }

    fn signed(&self, body: TokenStream, negative: bool) -> (TokenStream, u8) {
        if negative {
            (quote!(-#body), UNARY)
        } else {
            (body, ATOM)
        }
    }

    /// The expression for `n`: its name if it has one, else its definition.
    pub(super) fn expr(&self, n: NodeId) -> (TokenStream, u8) {
        if let Some(name) = self.names.get(&n) {
            return (ident_expr(name), ATOM);
        }
        if let Scope::Kernel = self.scope
            && let Some(field) = self.plan.field_of.get(&n)
        {
            let field = ident(field);
            return (quote!(p.#field), POSTFIX);
        }
        self.definition(n)
    }

    fn operand(&self, n: NodeId, paren_below: u8) -> TokenStream {
        let (t, prec) = self.expr(n);
        paren_if(t, prec < paren_below)
    }

    fn binary(&self, a: NodeId, op: TokenStream, b: NodeId, prec: u8) -> (TokenStream, u8) {
        let a = self.operand(a, prec);
        let b = self.operand(b, prec + 1);
        (quote!(#a #op #b), prec)
    }

    /// The precedence `n` is written with, without building its tokens.
    fn precedence(&self, n: NodeId) -> u8 {
        if self.names.contains_key(&n) {
            return ATOM;
        }
        if matches!(self.scope, Scope::Kernel) && self.plan.field_of.contains_key(&n) {
            return POSTFIX;
        }
        match self.plan.graph.node(n) {
            Node::Const(c) if c.value().is_sign_negative() && c.value() != 0.0 => UNARY,
            Node::Const(_) | Node::Input(_) => ATOM,
            Node::Add(..) | Node::Sub(..) => SUM,
            Node::Mul(..) | Node::Div(..) => PRODUCT,
            Node::Neg(_) => UNARY,
            _ => POSTFIX,
        }
    }

    /// The operands of a commutative operation in the order that needs fewer parentheses:
    /// `(a + b) + c` rather than `c + (a + b)`. Exact: IEEE `+` and `*` commute.
    fn flatter(&self, a: NodeId, b: NodeId, prec: u8) -> (NodeId, NodeId) {
        if self.precedence(b) == prec && self.precedence(a) != prec {
            (b, a)
        } else {
            (a, b)
        }
    }

    /// A float function: an inherent method in std mode, `libm::<name>` in no-std mode, or the
    /// file's own function (`tanh`) with [`FloatFunctions::Inline`](crate::FloatFunctions::Inline).
    fn call(&self, arg: NodeId, name: &str) -> (TokenStream, u8) {
        if self.options.inline_float_functions() && INLINE_HELPERS.iter().any(|h| h.0 == name) {
            let f = ident(name);
            let (a, _) = self.expr(arg);
            (quote!(#f(#a)), POSTFIX)
        } else if self.options.no_std {
            let f = ident(&self.libm_name(name));
            let (a, _) = self.expr(arg);
            (quote!(libm::#f(#a)), POSTFIX)
        } else {
            self.method(arg, name)
        }
    }

    fn method(&self, arg: NodeId, name: &str) -> (TokenStream, u8) {
        let f = ident(name);
        let recv = self.operand(arg, POSTFIX);
        (quote!(#recv.#f()), POSTFIX)
    }

    fn libm_name(&self, name: &str) -> String {
        let base = match name {
            "sin_cos" => "sincos",
            "powi" => "pow",
            other => other,
        };
        match self.options.float {
            Float::F64 => base.to_owned(),
            Float::F32 => format!("{base}f"),
        }
    }

    /// The definition of `n` (ignoring its own name).
    pub(super) fn definition(&self, n: NodeId) -> (TokenStream, u8) {
        let g = &self.plan.graph;
        match g.node(n) {
            Node::Const(c) => self.literal(c.value()),
            Node::Param(p) => {
                let field = ident(&self.module.param_field(p.index()));
                (quote!(p.#field), POSTFIX)
            }
            Node::Input(i) => (ident_expr(g.input_name(i)), ATOM),
            Node::Add(a, b) => {
                let (a, b) = self.flatter(a, b, SUM);
                self.binary(a, quote!(+), b, SUM)
            }
            Node::Sub(a, b) => self.binary(a, quote!(-), b, SUM),
            Node::Mul(a, b) => {
                let (a, b) = self.flatter(a, b, PRODUCT);
                self.binary(a, quote!(*), b, PRODUCT)
            }
            Node::Div(a, b) => self.binary(a, quote!(/), b, PRODUCT),
            Node::Neg(a) => {
                let a = self.operand(a, UNARY);
                (quote!(-#a), UNARY)
            }
            Node::Powi(a, e) => {
                // Not reached: the plan expands powers. Kept total for hand-built plans.
                let e = Literal::i32_unsuffixed(e);
                if self.options.no_std {
                    let f = ident(&self.libm_name("powi"));
                    let (a, _) = self.expr(a);
                    (quote!(libm::#f(#a, #e as F)), POSTFIX)
                } else {
                    let recv = self.operand(a, POSTFIX);
                    (quote!(#recv.powi(#e)), POSTFIX)
                }
            }
            Node::Sqrt(a) => self.call(a, "sqrt"),
            Node::Sin(a) => self.call(a, "sin"),
            Node::Cos(a) => self.call(a, "cos"),
            Node::Tanh(a) => self.call(a, "tanh"),
            Node::Abs(a) => self.method(a, "abs"),
        }
    }

    /// The `let` statements of a block.
    pub(super) fn lets(&self, block: &Block) -> Vec<TokenStream> {
        block
            .steps
            .iter()
            .map(|step| match *step {
                Step::Let(n) => {
                    let name = ident(self.names.get(&n).map_or("_", String::as_str));
                    let (value, _) = self.definition(n);
                    quote!(let #name = #value;)
                }
                Step::SinCos { sin, cos, arg } => {
                    let s = ident(self.names.get(&sin).map_or("_", String::as_str));
                    let c = ident(self.names.get(&cos).map_or("_", String::as_str));
                    let value = if self.options.inline_float_functions() {
                        let (a, _) = self.expr(arg);
                        quote!(sin_cos(#a))
                    } else if self.options.no_std {
                        let f = ident(&self.libm_name("sin_cos"));
                        let (a, _) = self.expr(arg);
                        quote!(libm::#f(#a))
                    } else {
                        self.method(arg, "sin_cos").0
                    };
                    quote!(let (#s, #c) = #value;)
                }
            })
            .collect()
    }
}
