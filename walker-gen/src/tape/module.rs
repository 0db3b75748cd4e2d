//! A whole module on tape ([`TapeModule`]): built from the emitter's plan, it prepares
//! parameter sets and evaluates kernels.

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};

use super::compile::{Leaf, compile};
use super::error::TapeError;
use super::kernel::{KernelIndex, TapeKernel};
use super::program::Program;
use super::select::Funcs;
use super::values::{Prepared, Scratch};
use crate::ir::{Module, Node, NodeId, ParamDecl};
use crate::options::{EmitOptions, Float};
use crate::plan::Plan;

/// Distinguishes the [`Prepared`] values of one [`TapeModule`] from another's.
static NEXT_ID: AtomicU64 = AtomicU64::new(0);

/// Every kernel of a [`Module`], compiled to tapes that compute exactly what the generated
/// Rust computes (see the [module docs](super)).
///
/// ```
/// use walker_gen::tape::{Scratch, TapeModule};
/// use walker_gen::{EmitOptions, Kernel, Module, Shape};
///
/// // A module with one kernel `f(x) = (a + b) * sin x`, runtime parameters `a` and `b`.
/// let mut m = Module::new("demo");
/// let a = m.param("a", "first");
/// let b = m.param("b", "second");
/// let x = m.graph.input("x");
/// let ab = m.graph.add(a, b);
/// let s = m.graph.sin(x);
/// let f = m.graph.mul(ab, s);
/// m.kernels.push(Kernel {
///     name: "f".to_owned(),
///     doc: String::new(),
///     equation: String::new(),
///     args: vec!["x".to_owned()],
///     outputs: vec![("f".to_owned(), f)],
///     output_shape: Shape::Scalar,
/// });
///
/// let tape = TapeModule::new(&m, &EmitOptions::default())?;
/// let prepared = tape.prepare(&[1.0, 2.0])?; // `Params` field order: a, b
/// let k = tape.kernel_index("f").expect("a kernel f");
/// let mut scratch = Scratch::new();
/// let mut out = [0.0];
/// tape.eval(k, &prepared, &[0.5], &mut out, &mut scratch)?;
/// assert_eq!(out[0], (1.0_f64 + 2.0) * 0.5_f64.sin());
/// # Ok::<(), walker_gen::tape::TapeError>(())
/// ```
#[derive(Clone, Debug)]
pub struct TapeModule {
    id: u64,
    params: Vec<ParamDecl>,
    prepare: Program,
    kernels: Vec<TapeKernel>,
    by_name: HashMap<String, KernelIndex>,
}

impl TapeModule {
    /// Compiles every kernel of `module` (and its `prepare`) with the emitter's plan for
    /// `options`: the same hoisting, common subexpressions, `sin_cos` pairs, division
    /// strategy ([`EmitOptions::division`]) and float functions
    /// ([`EmitOptions::float_functions`], [`EmitOptions::no_std`]) as [`crate::emit()`].
    /// [`EmitOptions::checked`] changes nothing here (the checked entry points check, they do
    /// not compute).
    ///
    /// # Errors
    /// [`TapeError::Plan`] where the emitter would refuse the module (bad names, undeclared
    /// inputs, output counts), [`TapeError::Unsupported`] for [`Float::F32`].
    pub fn new(module: &Module, options: &EmitOptions) -> Result<TapeModule, TapeError> {
        if options.float != Float::F64 {
            return Err(TapeError::Unsupported {
                what: "f32 code (Float::F32)",
            });
        }
        let funcs = Funcs::new(options);
        let plan = Plan::new(module, options.division)?;
        let g = &plan.graph;

        // `prepare`: the fields of `Prepared` from the parameters.
        let prepare_roots: Vec<NodeId> = plan.fields.iter().map(|f| f.node).collect();
        let prepare_leaf = |n: NodeId| match g.node(n) {
            Node::Const(c) => Some(Leaf::Const(c.value())),
            Node::Param(p) => u32::try_from(p.index()).ok().map(Leaf::Arg),
            _ => None,
        };
        let prepare = compile(
            g,
            &plan.prepare,
            &prepare_roots,
            module.params.len(),
            &prepare_leaf,
            funcs,
        )?;

        // Kernels: hoisted nodes from `Prepared`, arguments by name, constants.
        let field_of: HashMap<NodeId, u32> = plan
            .fields
            .iter()
            .enumerate()
            .filter_map(|(i, f)| Some((f.node, u32::try_from(i).ok()?)))
            .collect();
        let mut kernels = Vec::with_capacity(module.kernels.len());
        for (k, kp) in module.kernels.iter().zip(&plan.kernels) {
            let arg_of: HashMap<&str, u32> = k
                .args
                .iter()
                .enumerate()
                .filter_map(|(i, a)| Some((a.as_str(), u32::try_from(i).ok()?)))
                .collect();
            // As the writer: a node named by a field of `Prepared` is read from it, else a
            // leaf is written out (a constant, an argument).
            let leaf = |n: NodeId| {
                if let Some(&i) = field_of.get(&n) {
                    return Some(Leaf::Prepared(i));
                }
                match g.node(n) {
                    Node::Const(c) => Some(Leaf::Const(c.value())),
                    Node::Input(i) => arg_of.get(g.input_name(i)).map(|&a| Leaf::Arg(a)),
                    _ => None,
                }
            };
            let program = compile(g, &kp.block, &kp.outputs, k.args.len(), &leaf, funcs)?;
            kernels.push(TapeKernel {
                name: k.name.clone(),
                args: k.args.clone(),
                outputs: k.outputs.iter().map(|o| o.0.clone()).collect(),
                shape: k.output_shape,
                program,
            });
        }
        let by_name = kernels
            .iter()
            .enumerate()
            .map(|(i, k)| (k.name.clone(), KernelIndex(i)))
            .collect();
        Ok(TapeModule {
            id: NEXT_ID.fetch_add(1, Ordering::Relaxed),
            params: module.params.clone(),
            prepare,
            kernels,
            by_name,
        })
    }

    /// The runtime parameters, in the generated `Params`' field order (by their names in the
    /// model or scene: `m1`, `I1`, `T_set`).
    #[must_use]
    pub fn params(&self) -> &[ParamDecl] {
        &self.params
    }

    /// The generated `prepare`: every value the kernels need that depends on the parameters
    /// only. `params` in [`TapeModule::params`] order.
    ///
    /// # Errors
    /// [`TapeError::ParamCount`] if `params` does not hold one value per parameter.
    pub fn prepare(&self, params: &[f64]) -> Result<Prepared, TapeError> {
        let count = || TapeError::ParamCount {
            expected: self.params.len(),
            got: params.len(),
        };
        if params.len() != self.params.len() {
            return Err(count());
        }
        let mut values = vec![0.0; self.prepare.outputs.len()];
        let mut regs = Vec::new();
        self.prepare
            .run(params, &[], &mut values, &mut regs)
            .ok_or_else(|| TapeError::Internal {
                message: "prepare's registers".to_owned(),
            })?;
        Ok(Prepared {
            module: self.id,
            values,
        })
    }

    /// [`TapeModule::prepare`] with the parameters looked up by name (as the generated
    /// `Params::from_fn`): `value` is called once per parameter, in field order.
    #[must_use]
    pub fn prepare_with(&self, mut value: impl FnMut(&str) -> f64) -> Prepared {
        let params: Vec<f64> = self.params.iter().map(|p| value(&p.name)).collect();
        let mut values = vec![0.0; self.prepare.outputs.len()];
        let mut regs = Vec::new();
        // Cannot fail: one value per parameter, and the program's registers were checked when
        // it was built; the values stay NaN if it did.
        if self
            .prepare
            .run(&params, &[], &mut values, &mut regs)
            .is_none()
        {
            values.fill(f64::NAN);
        }
        Prepared {
            module: self.id,
            values,
        }
    }

    /// Every kernel, in the generated file's order.
    #[must_use]
    pub fn kernels(&self) -> &[TapeKernel] {
        &self.kernels
    }

    /// The kernel at `index`.
    #[must_use]
    pub fn kernel(&self, index: KernelIndex) -> Option<&TapeKernel> {
        self.kernels.get(index.0)
    }

    /// The kernel called `name`.
    #[must_use]
    pub fn kernel_index(&self, name: &str) -> Option<KernelIndex> {
        self.by_name.get(name).copied()
    }

    /// The index of every kernel, in order.
    pub fn kernel_indices(&self) -> impl Iterator<Item = KernelIndex> + use<> {
        (0..self.kernels.len()).map(KernelIndex)
    }

    /// A register file large enough for every kernel (calls with it never allocate).
    #[must_use]
    pub fn scratch(&self) -> Scratch {
        let n = self
            .kernels
            .iter()
            .map(TapeKernel::registers)
            .max()
            .unwrap_or(0);
        Scratch::with_registers(n)
    }

    /// Evaluates `kernel` at `args` (in [`TapeKernel::args`] order) with the `prepared` values,
    /// writing its outputs (row-major, [`TapeKernel::output_names`]) to `out`: bit for bit what
    /// the generated function returns, NaN payloads aside (see the module docs).
    ///
    /// Does not allocate once `scratch` holds the kernel's registers. Non-finite arguments
    /// propagate as in the generated unchecked kernel; nothing is checked but the lengths.
    ///
    /// # Errors
    /// [`TapeError::UnknownKernel`], [`TapeError::ForeignPrepared`] (values of another
    /// module), [`TapeError::ArgumentCount`] or [`TapeError::OutputCount`]; `out` is then
    /// unchanged.
    pub fn eval(
        &self,
        kernel: KernelIndex,
        prepared: &Prepared,
        args: &[f64],
        out: &mut [f64],
        scratch: &mut Scratch,
    ) -> Result<(), TapeError> {
        let k = self.kernels.get(kernel.0).ok_or(TapeError::UnknownKernel {
            index: kernel.0,
            count: self.kernels.len(),
        })?;
        if prepared.module != self.id {
            return Err(TapeError::ForeignPrepared);
        }
        if args.len() != k.args.len() {
            return Err(TapeError::ArgumentCount {
                kernel: k.name.clone(),
                expected: k.args.len(),
                got: args.len(),
            });
        }
        if out.len() != k.outputs.len() {
            return Err(TapeError::OutputCount {
                kernel: k.name.clone(),
                expected: k.outputs.len(),
                got: out.len(),
            });
        }
        k.program
            .run(args, &prepared.values, out, &mut scratch.regs)
            .ok_or_else(|| TapeError::Internal {
                message: format!("kernel `{}`'s registers", k.name),
            })
    }
}
