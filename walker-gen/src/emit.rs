//! Rust source from a [`Module`]: tokens with `quote`, checked by `syn`, formatted by
//! `prettyplease`, stamped with the `@generated` line.
//!
//! Layout of a generated file (see the crate docs for an example):
//!
//! 1. the `@generated` line and a header comment (scene structure, fixed values, options);
//! 2. `pub type F = f64;` (or `f32`);
//! 3. `pub struct Params` (the runtime parameters), `pub struct Prepared` (what `prepare`
//!    computes from them) and `pub fn prepare(p: &Params) -> Prepared`;
//! 4. one `pub fn` per kernel taking `p: &Prepared` and its arguments (the unchecked fast
//!    path), followed, when [`EmitOptions::checked`] is set, by `pub fn <kernel>_checked`
//!    returning `Result<_, KernelError>`, and once per file the `KernelError` enum.
//!
//! The output depends only on the module and the options: no paths, no time, no hash-map
//! order. Floating-point functions are inherent methods (`x.sin()`, `x.sqrt()`) in std
//! mode and `libm` calls (`libm::sin`, `libm::sincos`; `libm::sinf`... for `f32`) in no-std
//! mode; `abs` is `core`'s inherent method in both modes (an exact bit operation). In std mode
//! with `f64`, `sin_cos` and `tanh` are by default ([`FloatFunctions::Inline`]) private
//! functions written into the file when a kernel uses them, `fn sin_cos` (fdlibm's kernels with
//! one shared argument reduction) and `fn tanh` (Cephes' rational below 0.625, `exp` above):
//! their source is `src/fastmath/{sin_cos,tanh}.rs`, appended verbatim (comments, licence notice
//! and measured accuracy included) and tested as such by `tests/fastmath_accuracy.rs`. Constants are
//! written with the shortest digits that round-trip (`{:?}`), suffixed with the float type;
//! a constant equal to one of `core::f64::consts` is written by that name.

use std::collections::HashMap;

use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;

use crate::error::EmitError;
use crate::ir::{Kernel, Module, Node, NodeId, Shape};
use crate::plan::{Block, Division, Plan, Step};
use crate::stats;

/// The float type of the generated code.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Default)]
pub enum Float {
    /// `f64` (the default).
    #[default]
    F64,
    /// `f32`, for small controllers. Constants are folded in `f64` and rounded once.
    F32,
}

impl Float {
    /// `"f64"` or `"f32"`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Float::F64 => "f64",
            Float::F32 => "f32",
        }
    }
}

/// How generated `f64` code in std mode evaluates `sin_cos` and `tanh`.
///
/// Profiles of the simulator showed std's `tanh` (glibc goes through `expm1`, about 18 ns) and
/// `sin_cos` (two library calls with two argument reductions, about 10 ns) taking about half the
/// run time of the stance kernels, whose arithmetic takes about 15 ns.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Default)]
pub enum FloatFunctions {
    /// Private `fn sin_cos` and `fn tanh` written into the file when a kernel uses them (the
    /// default): fdlibm's `__kernel_sin`/`__kernel_cos` with one shared Cody-Waite reduction
    /// (std's `sin_cos` above `2^20 pi/2`), and Cephes' rational for `|x| < 0.625`,
    /// `1 - 2/(exp(2|x|) + 1)` above. Measured errors: at most 0.78 ulp (sin, cos) and 1.32 ulp
    /// (tanh); the tests assert 1 and 2 (`tests/fastmath_accuracy.rs`). Other float functions
    /// (`sqrt`, a lone `sin` or `cos`) stay std methods.
    /// Applies only to `f64` in std mode; `f32` and no-std code are as with [`Self::Std`].
    #[default]
    Inline,
    /// std's inherent methods `x.sin_cos()` and `x.tanh()` (results depend on the platform's
    /// `libm`).
    Std,
}

/// What the emitter writes.
///
/// The default is `f64`, std, [`Division::SharedReciprocal`], checked entry points and
/// [`FloatFunctions::Inline`].
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub struct EmitOptions {
    /// The float type `F`.
    pub float: Float,
    /// Whether to call `libm` instead of std's inherent float methods (the file then uses only
    /// `core` and `libm`).
    pub no_std: bool,
    /// How divisions by shared denominators are evaluated.
    pub division: Division,
    /// Whether to emit, next to each kernel `k`, a `k_checked` that rejects non-finite
    /// arguments and outputs with a `KernelError` (emitted once per file). `false` leaves both
    /// out (smallest code, for embedded users); the plain kernels are the same either way.
    pub checked: bool,
    /// Whether `sin_cos` and `tanh` are private functions of the file or std methods (only for
    /// `f64` in std mode).
    pub float_functions: FloatFunctions,
}

impl EmitOptions {
    /// Whether `sin_cos` and `tanh` are the file's own functions: [`FloatFunctions::Inline`]
    /// with `f64` in std mode.
    #[must_use]
    pub fn inline_float_functions(&self) -> bool {
        self.float_functions == FloatFunctions::Inline && !self.no_std && self.float == Float::F64
    }
}

impl Default for EmitOptions {
    fn default() -> Self {
        EmitOptions {
            float: Float::default(),
            no_std: false,
            division: Division::default(),
            checked: true,
            float_functions: FloatFunctions::default(),
        }
    }
}

/// Emits `module` as formatted Rust source.
///
/// # Errors
/// The module is inconsistent (see [`EmitError`]).
pub fn emit(module: &Module, options: &EmitOptions) -> Result<String, EmitError> {
    let plan = Plan::new(module, options.division)?;
    emit_plan(module, &plan, options)
}

/// The private float functions of [`FloatFunctions::Inline`]: name and source, in the order
/// they are appended to a file. The source is written verbatim (it is `rustfmt`-formatted, and
/// its comments carry fdlibm's notice); `tests/fastmath_accuracy.rs` includes the same files.
const INLINE_HELPERS: [(&str, &str); 2] = [
    ("sin_cos", include_str!("fastmath/sin_cos.rs")),
    ("tanh", include_str!("fastmath/tanh.rs")),
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
fn has_tanh(plan: &Plan, block: &Block) -> bool {
    block
        .nodes
        .iter()
        .any(|&n| matches!(plan.graph.node(n), Node::Tanh(_)))
}

/// The names of the inline float functions any block of `plan` calls.
fn inline_calls_of_file(plan: &Plan, options: &EmitOptions) -> Vec<&'static str> {
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
fn inline_note(plan: &Plan, block: &Block, options: &EmitOptions) -> String {
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

// Precedence levels, loosest first.
const SUM: u8 = 1;
const PRODUCT: u8 = 2;
const UNARY: u8 = 3;
const POSTFIX: u8 = 4;
const ATOM: u8 = 5;

fn ident(name: &str) -> Ident {
    Ident::new(name, Span::call_site())
}

fn ident_expr(name: &str) -> TokenStream {
    let i = ident(name);
    quote!(#i)
}

fn paren_if(t: TokenStream, cond: bool) -> TokenStream {
    if cond { quote!((#t)) } else { t }
}

fn unsuffixed(n: usize) -> Literal {
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
enum Scope {
    /// `prepare`: parameters are `p.<field>` of `Params`.
    Prepare,
    /// A kernel: hoisted nodes are `p.<field>` of `Prepared`.
    Kernel,
}

struct Writer<'a> {
    module: &'a Module,
    plan: &'a Plan,
    options: &'a EmitOptions,
    names: &'a HashMap<NodeId, String>,
    scope: Scope,
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
    fn expr(&self, n: NodeId) -> (TokenStream, u8) {
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
    /// file's own function (`tanh`) with [`FloatFunctions::Inline`].
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
    fn definition(&self, n: NodeId) -> (TokenStream, u8) {
        let g = &self.plan.graph;
        match g.node(n) {
            Node::Const(c) => self.literal(c.value()),
            Node::Param(p) => {
                let field = self
                    .module
                    .params
                    .get(p.index())
                    .map_or_else(|| format!("param{}", p.index()), |d| d.field());
                let field = ident(&field);
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
    fn lets(&self, block: &Block) -> Vec<TokenStream> {
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

fn doc_attrs(lines: &[String]) -> Vec<TokenStream> {
    lines
        .iter()
        .flat_map(|l| l.split('\n').map(str::to_owned).collect::<Vec<_>>())
        .map(|l| {
            let l = l.trim_end();
            let l = if l.is_empty() {
                String::new()
            } else {
                format!(" {l}")
            };
            quote!(#[doc = #l])
        })
        .collect()
}

/// `text` broken at spaces into lines of at most 96 characters (a `/// ` line of at most 100),
/// for the doc comments of the checked entry points. A longer word stays whole.
fn wrap(text: &str) -> String {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split(' ').filter(|w| !w.is_empty()) {
        if !line.is_empty() && line.len() + 1 + word.len() > 96 {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    lines.push(line);
    lines.join("\n")
}

fn code_list(items: &[String]) -> String {
    items
        .iter()
        .map(|s| format!("`{s}`"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn returns_doc(k: &Kernel) -> String {
    let names: Vec<&str> = k.outputs.iter().map(|o| o.0.as_str()).collect();
    match k.output_shape {
        Shape::Scalar => format!("Returns `{}`.", names.join("")),
        Shape::Vector(_) => format!("Returns `[{}]`.", names.join(", ")),
        Shape::Matrix(_, c) => {
            let rows: Vec<String> = names
                .chunks(c.max(1))
                .map(|r| format!("[{}]", r.join(", ")))
                .collect();
            format!("Returns, row-major, `[{}]`.", rows.join(", "))
        }
    }
}

/// `const` if the block calls no float function (arithmetic and `abs` are `const`).
fn const_if_possible(plan: &Plan, block: &Block) -> TokenStream {
    let calls = block.nodes.iter().any(|&n| {
        matches!(
            plan.graph.node(n),
            Node::Sqrt(_) | Node::Sin(_) | Node::Cos(_) | Node::Tanh(_) | Node::Powi(..)
        )
    });
    if calls { quote!() } else { quote!(const) }
}

/// The derives of a struct of `F` fields: `Eq` too when it has no fields.
fn derives(empty: bool) -> TokenStream {
    if empty {
        quote!(#[derive(Debug, Clone, Copy, PartialEq, Eq)])
    } else {
        quote!(#[derive(Debug, Clone, Copy, PartialEq)])
    }
}

fn kernel_fn(
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
    Some(quote! {
        #(#docs)*
        #[inline]
        #[must_use]
        pub #constness fn #name(#p: &Prepared, #(#args),*) -> #ret_ty {
            #(#lets)*
            #ret
        }

        #checked
    })
}

/// `pub fn <kernel>_checked`: argument checks in argument order, the unchecked kernel, output
/// checks in return order, each one line through the private helpers of `KernelError`.
fn checked_fn(k: &Kernel, ret_ty: &TokenStream) -> TokenStream {
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
    quote! {
        #(#docs)*
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
fn kernel_error(module: &Module, options: &EmitOptions) -> TokenStream {
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

fn params_and_prepare(module: &Module, plan: &Plan, options: &EmitOptions) -> TokenStream {
    let fields: Vec<TokenStream> = module
        .params
        .iter()
        .map(|p| {
            let docs = doc_attrs(std::slice::from_ref(&p.doc));
            let f = ident(&p.field());
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
        .map(|p| {
            let f = ident(&p.field());
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

fn header(module: &Module, options: &EmitOptions, inline: &[&str]) -> String {
    let mut lines = vec![
        format!(
            "// @generated by walker-gen from scene {}. Do not edit by hand.",
            module.scene_name
        ),
        "//".to_owned(),
    ];
    for note in module.notes.iter().flat_map(|n| n.lines()) {
        lines.push(format!("// {note}").trim_end().to_owned());
    }
    let names: Vec<String> = inline.iter().map(|s| (*s).to_owned()).collect();
    lines.push(format!(
        "// Float type: {}; float functions: {}{}.",
        options.float.name(),
        if options.no_std {
            "libm (no_std)"
        } else {
            "inherent methods (std)"
        },
        if names.is_empty() {
            String::new()
        } else {
            format!("; inline (end of file): {}", code_list(&names))
        }
    ));
    lines.push(format!(
        "// Divisions: {}.",
        match options.division {
            Division::SharedReciprocal => "shared denominators as one reciprocal",
            Division::Exact => "exact, one per quotient",
        }
    ));
    lines.push(format!(
        "// Checked entry points: {}.",
        if options.checked {
            "`<kernel>_checked` returning `Result<_, KernelError>`"
        } else {
            "none"
        }
    ));
    let mut out = lines.join("\n");
    out.push_str("\n\n");
    out
}

pub(crate) fn emit_plan(
    module: &Module,
    plan: &Plan,
    options: &EmitOptions,
) -> Result<String, EmitError> {
    if options.checked
        && let Some(k) = module.kernels.iter().find(|k| {
            k.name
                .strip_suffix("_checked")
                .is_some_and(|base| module.kernels.iter().any(|o| o.name == base))
        })
    {
        return Err(EmitError::Duplicate {
            what: "kernel (a checked entry point has this name)".to_owned(),
            name: k.name.clone(),
        });
    }
    let ty = ident(options.float.name());
    let params = params_and_prepare(module, plan, options);
    let kernels: Vec<TokenStream> = (0..module.kernels.len())
        .filter_map(|i| kernel_fn(module, plan, options, i))
        .collect();
    let kernel_error = if options.checked && !module.kernels.is_empty() {
        kernel_error(module, options)
    } else {
        quote!()
    };
    let tokens = quote! {
        /// The float type of every value in this file.
        pub type F = #ty;

        #params

        #kernel_error

        #(#kernels)*
    };
    let file: syn::File = syn::parse2(tokens).map_err(|e| EmitError::Syntax {
        message: e.to_string(),
    })?;
    // One item at a time, so that items are separated by a blank line.
    let items: Vec<String> = file
        .items
        .into_iter()
        .map(|item| {
            prettyplease::unparse(&syn::File {
                shebang: None,
                frontmatter: None,
                attrs: Vec::new(),
                items: vec![item],
            })
        })
        .collect();
    let inline = inline_calls_of_file(plan, options);
    let mut out = header(module, options, &inline);
    out.push_str(&items.join("\n"));
    // Verbatim, after the formatted items: comments (the licence notice) survive.
    for (_, source) in INLINE_HELPERS.iter().filter(|h| inline.contains(&h.0)) {
        out.push('\n');
        out.push_str(source);
    }
    Ok(out)
}
