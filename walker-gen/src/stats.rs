//! Operation counts of the generated code, and of the generic linear-algebra path for comparison.
//!
//! Kernel counts are taken from the evaluation plan, so they are exactly what the emitted code
//! does per call, after common subexpressions and hoisting: each `let` and each inlined
//! operation once, `sin_cos` as one transcendental call, `x*x` as one multiplication. The
//! parameter-only part, run once by `prepare`, is counted separately.
//!
//! The generic counts are exact for the algorithms described at each function (dense
//! storage, no use of known zeros; comparisons and pivot search are not counted).

use std::fmt::{self, Write as _};
use std::ops::{Add, AddAssign};

use serde::Serialize;

use crate::error::EmitError;
use crate::ir::{Graph, Module, Node};
use crate::options::EmitOptions;
use crate::plan::{Block, Plan};

/// Floating-point operation counts.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Default, Serialize)]
pub struct OpCounts {
    /// Additions and subtractions.
    pub add_sub: usize,
    /// Multiplications.
    pub mul: usize,
    /// Divisions.
    pub div: usize,
    /// Negations.
    pub neg: usize,
    /// Square roots.
    pub sqrt: usize,
    /// Transcendental calls (`sin`, `cos`, `sin_cos` counted once, `tanh`).
    pub transcendental: usize,
    /// `abs` (a bit operation).
    pub abs: usize,
}

impl OpCounts {
    /// The sum of all counts.
    #[must_use]
    pub fn total(&self) -> usize {
        self.add_sub + self.mul + self.div + self.neg + self.sqrt + self.transcendental + self.abs
    }

    /// A one-line summary, for example `3 add/sub, 5 mul, 1 div, 1 transcendental`; zero counts
    /// are left out.
    #[must_use]
    pub fn summary(&self) -> String {
        let parts: Vec<String> = [
            (self.add_sub, "add/sub"),
            (self.mul, "mul"),
            (self.div, "div"),
            (self.neg, "neg"),
            (self.sqrt, "sqrt"),
            (self.transcendental, "transcendental"),
            (self.abs, "abs"),
        ]
        .iter()
        .filter(|(n, _)| *n > 0)
        .map(|(n, what)| format!("{n} {what}"))
        .collect();
        if parts.is_empty() {
            "no arithmetic".to_owned()
        } else {
            parts.join(", ")
        }
    }
}

impl Add for OpCounts {
    type Output = OpCounts;

    fn add(self, o: OpCounts) -> OpCounts {
        OpCounts {
            add_sub: self.add_sub + o.add_sub,
            mul: self.mul + o.mul,
            div: self.div + o.div,
            neg: self.neg + o.neg,
            sqrt: self.sqrt + o.sqrt,
            transcendental: self.transcendental + o.transcendental,
            abs: self.abs + o.abs,
        }
    }
}

impl AddAssign for OpCounts {
    fn add_assign(&mut self, o: OpCounts) {
        *self = *self + o;
    }
}

impl std::iter::Sum for OpCounts {
    fn sum<I: Iterator<Item = OpCounts>>(iter: I) -> OpCounts {
        iter.fold(OpCounts::default(), Add::add)
    }
}

/// The counts of one generated kernel (per call).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct KernelStats {
    /// The kernel name.
    pub name: String,
    /// Operations per call.
    pub ops: OpCounts,
    /// Number of `let` bindings (common subexpressions and call results).
    pub lets: usize,
    /// Number of `Prepared` fields the kernel reads.
    pub prepared_reads: usize,
    /// How the kernel is evaluated where the generator chose between its closed form and its
    /// structured solve (a model's stance and impact kernels), with the other form's count.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub form: Option<String>,
}

/// The counts of one generated file.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Stats {
    /// The scene name.
    pub scene: String,
    /// Operations of `prepare` (once per parameter set).
    pub prepare: OpCounts,
    /// Number of fields of `Prepared`.
    pub prepared_fields: usize,
    /// One entry per kernel, in file order.
    pub kernels: Vec<KernelStats>,
}

/// Counts the operations of `module` as [`crate::emit::emit`] would write them.
///
/// # Errors
/// The module cannot be emitted (see [`EmitError`]).
pub fn stats(module: &Module, options: &EmitOptions) -> Result<Stats, EmitError> {
    let plan = Plan::new(module, options.division)?;
    Ok(from_plan(module, &plan))
}

pub(crate) fn block_counts(g: &Graph, block: &Block) -> OpCounts {
    let mut c = OpCounts::default();
    for &n in &block.nodes {
        match g.node(n) {
            Node::Const(_) | Node::Param(_) | Node::Input(_) | Node::Powi(..) => {}
            Node::Add(..) | Node::Sub(..) => c.add_sub += 1,
            Node::Mul(..) => c.mul += 1,
            Node::Div(..) => c.div += 1,
            Node::Neg(_) => c.neg += 1,
            Node::Sqrt(_) => c.sqrt += 1,
            Node::Sin(_) if block.paired_sin.contains(&n) => {}
            Node::Sin(_) | Node::Cos(_) | Node::Tanh(_) => c.transcendental += 1,
            Node::Abs(_) => c.abs += 1,
        }
    }
    c
}

/// Latencies in cycles of the scalar double-precision operations, from Agner Fog's instruction
/// tables (Intel Skylake; AMD Zen 2 is within a cycle or two but for its slower square root):
/// `ADDSD`, `SUBSD`, `MULSD` 4; `DIVSD` 13-14; `SQRTSD` 15-16; a sign flip or `abs` (`XORPD`,
/// `ANDPD`) 1. A transcendental call (`sin_cos`, `tanh`: tens of cycles, varying with the
/// argument) is given 40: both forms of a kernel call the same ones.
fn latency(node: &Node) -> usize {
    match node {
        Node::Const(_) | Node::Param(_) | Node::Input(_) => 0,
        Node::Add(..) | Node::Sub(..) | Node::Mul(..) => 4,
        // Emitted as a chain of squarings and products (none remain after planning).
        Node::Powi(_, n) => 4 * (32 - n.unsigned_abs().leading_zeros() as usize),
        Node::Div(..) => 14,
        Node::Sqrt(_) => 16,
        Node::Neg(_) | Node::Abs(_) => 1,
        Node::Sin(_) | Node::Cos(_) | Node::Tanh(_) => 40,
    }
}

/// The kernel's critical path: the latency, in cycles ([`latency`]), of its longest chain of
/// dependent operations from its arguments and the `Prepared` fields (read, not computed) to
/// its outputs. An out-of-order core overlaps everything else, so a kernel called in a chain
/// (each stage of an integration step needs the previous one's result) costs at least this;
/// two kernels with about the same operation count differ by it (a structured solve's two
/// dependent divisions against a closed form's one reciprocal).
pub(crate) fn critical_path(plan: &Plan, kernel: usize) -> usize {
    let kp = &plan.kernels[kernel];
    let mut ready: std::collections::HashMap<crate::ir::NodeId, usize> =
        std::collections::HashMap::new();
    // `block.nodes` is in id order, and a node's children have smaller ids.
    for &n in &kp.block.nodes {
        if plan.field_of.contains_key(&n) {
            continue;
        }
        let node = plan.graph.node(n);
        let start = node
            .children()
            .map(|c| ready.get(&c).copied().unwrap_or(0))
            .max()
            .unwrap_or(0);
        ready.insert(n, start + latency(&node));
    }
    kp.outputs
        .iter()
        .map(|o| ready.get(o).copied().unwrap_or(0))
        .max()
        .unwrap_or(0)
}

pub(crate) fn from_plan(module: &Module, plan: &Plan) -> Stats {
    let kernels = module
        .kernels
        .iter()
        .zip(&plan.kernels)
        .map(|(k, kp)| {
            let mut reads = std::collections::BTreeSet::new();
            for &n in kp.block.nodes.iter().chain(&kp.outputs) {
                let node = plan.graph.node(n);
                let direct = plan.field_of.get(&n).map(|_| n);
                for c in node.children().chain(direct) {
                    if plan.field_of.contains_key(&c) {
                        reads.insert(c);
                    }
                }
            }
            KernelStats {
                name: k.name.clone(),
                ops: block_counts(&plan.graph, &kp.block),
                lets: kp.block.names.len(),
                prepared_reads: reads.len(),
                form: module.forms.get(&k.name).cloned(),
            }
        })
        .collect();
    Stats {
        scene: module.scene_name.clone(),
        prepare: block_counts(&plan.graph, &plan.prepare),
        prepared_fields: plan.fields.len(),
        kernels,
    }
}

fn row(out: &mut String, name: &str, c: &OpCounts, extra: &str) {
    let line = format!(
        "{name:<22} {:>7} {:>5} {:>5} {:>5} {:>5} {:>7} {:>7} {:>7}  {extra}",
        c.add_sub,
        c.mul,
        c.div,
        c.neg,
        c.sqrt,
        c.transcendental,
        c.abs,
        c.total()
    );
    let _ = writeln!(out, "{}", line.trim_end());
}

fn header(out: &mut String, title: &str) {
    let _ = writeln!(
        out,
        "{title:<22} {:>7} {:>5} {:>5} {:>5} {:>5} {:>7} {:>7} {:>7}",
        "add/sub", "mul", "div", "neg", "sqrt", "transc", "abs", "total"
    );
}

impl Stats {
    /// The counts as a plain-text table, followed by the generic reference costs.
    #[must_use]
    pub fn table(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "scene {}: operations per call, after CSE and hoisting",
            self.scene
        );
        header(&mut out, "kernel");
        for k in &self.kernels {
            row(
                &mut out,
                &k.name,
                &k.ops,
                &match &k.form {
                    None => format!("{} lets, {} prepared", k.lets, k.prepared_reads),
                    Some(form) => format!("{} lets, {} prepared; {form}", k.lets, k.prepared_reads),
                },
            );
        }
        row(
            &mut out,
            "prepare (once)",
            &self.prepare,
            &format!("{} fields", self.prepared_fields),
        );
        let _ = writeln!(out);
        header(&mut out, "generic reference");
        for (name, c) in generic_reference() {
            row(&mut out, name, &c, "");
        }
        out
    }
}

impl fmt::Display for Stats {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.table())
    }
}

/// A step of a generic (matrix-based) evaluation, for cost comparison.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum GenericStep {
    /// LU factorisation of an `n x n` matrix and solves for `rhs` right-hand sides
    /// ([`generic_cost_lu`]).
    Lu {
        /// Matrix size.
        n: usize,
        /// Number of right-hand sides.
        rhs: usize,
    },
    /// Inverse of an `n x n` matrix by Gauss-Jordan ([`generic_cost_gauss_jordan_inverse`]).
    GaussJordanInverse {
        /// Matrix size.
        n: usize,
    },
    /// Dot product of two `n`-vectors ([`generic_cost_dot`]).
    Dot {
        /// Vector length.
        n: usize,
    },
    /// `rows x cols` matrix times vector ([`generic_cost_mat_vec`]).
    MatVec {
        /// Rows.
        rows: usize,
        /// Columns.
        cols: usize,
    },
    /// `(r x k)` times `(k x c)` ([`generic_cost_mat_mat`]).
    MatMat {
        /// Rows of the left factor.
        r: usize,
        /// Inner dimension.
        k: usize,
        /// Columns of the right factor.
        c: usize,
    },
}

impl GenericStep {
    /// The operation count of the step.
    #[must_use]
    pub fn cost(self) -> OpCounts {
        match self {
            GenericStep::Lu { n, rhs } => generic_cost_lu(n, rhs),
            GenericStep::GaussJordanInverse { n } => generic_cost_gauss_jordan_inverse(n),
            GenericStep::Dot { n } => generic_cost_dot(n),
            GenericStep::MatVec { rows, cols } => generic_cost_mat_vec(rows, cols),
            GenericStep::MatMat { r, k, c } => generic_cost_mat_mat(r, k, c),
        }
    }
}

/// The total cost of a sequence of generic steps.
#[must_use]
pub fn generic_cost(steps: &[GenericStep]) -> OpCounts {
    steps.iter().map(|s| s.cost()).sum()
}

/// LU factorisation (Doolittle, unit lower factor, as with partial pivoting but not counting
/// the pivot search) of a dense `n x n` matrix, then forward and back substitution for `rhs`
/// right-hand sides.
///
/// - factorisation: multipliers `l_ik = a_ik / a_kk`: `n(n-1)/2` divisions; updates
///   `a_ij -= l_ik a_kj`: `(n-1)n(2n-1)/6` multiplications and as many subtractions;
/// - per right-hand side: forward substitution `n(n-1)/2` multiply-subtract pairs, back
///   substitution `n(n-1)/2` pairs and `n` divisions.
///
/// For `n = 4`: 6 div, 14 mul, 14 sub to factor; 12 mul, 12 sub, 4 div per right-hand side.
#[must_use]
pub fn generic_cost_lu(n: usize, rhs: usize) -> OpCounts {
    let tri = n * n.saturating_sub(1) / 2;
    let update = n.saturating_sub(1) * n * (2 * n).saturating_sub(1) / 6;
    OpCounts {
        add_sub: update + rhs * 2 * tri,
        mul: update + rhs * 2 * tri,
        div: tri + rhs * n,
        ..OpCounts::default()
    }
}

/// Inverse of a dense `n x n` matrix by Gauss-Jordan elimination on the `n x 2n` augmented
/// matrix `[A | I]`, updating every column: per pivot one reciprocal, `2n` multiplications to
/// scale the pivot row and `2n` multiply-subtract pairs in each of the other `n - 1` rows.
///
/// Totals: `n` divisions, `2n^3` multiplications, `2n^2(n-1)` subtractions; for `n = 4`:
/// 4 div, 128 mul, 96 sub.
#[must_use]
pub fn generic_cost_gauss_jordan_inverse(n: usize) -> OpCounts {
    OpCounts {
        add_sub: 2 * n * n * n.saturating_sub(1),
        mul: 2 * n * n * n,
        div: n,
        ..OpCounts::default()
    }
}

/// Dot product of two `n`-vectors: `n` multiplications, `n - 1` additions.
#[must_use]
pub fn generic_cost_dot(n: usize) -> OpCounts {
    OpCounts {
        add_sub: n.saturating_sub(1),
        mul: n,
        ..OpCounts::default()
    }
}

/// Dense `rows x cols` matrix times a vector: `rows` dot products of length `cols`.
#[must_use]
pub fn generic_cost_mat_vec(rows: usize, cols: usize) -> OpCounts {
    OpCounts {
        add_sub: rows * cols.saturating_sub(1),
        mul: rows * cols,
        ..OpCounts::default()
    }
}

/// Dense `(r x k)` times `(k x c)`: `r c` dot products of length `k`.
#[must_use]
pub fn generic_cost_mat_mat(r: usize, k: usize, c: usize) -> OpCounts {
    OpCounts {
        add_sub: r * c * k.saturating_sub(1),
        mul: r * c * k,
        ..OpCounts::default()
    }
}

/// Reference rows printed under every stats table: the 4x4 building blocks of the generic path
/// (`M qdd = rhs` solved per call with `M` assembled from the state).
#[must_use]
pub fn generic_reference() -> Vec<(&'static str, OpCounts)> {
    vec![
        ("4x4 LU + 1 solve", generic_cost_lu(4, 1)),
        ("4x4 LU + 2 solves", generic_cost_lu(4, 2)),
        ("4x4 Gauss-Jordan inv", generic_cost_gauss_jordan_inverse(4)),
        ("4x4 mat-vec", generic_cost_mat_vec(4, 4)),
        ("4x4 mat-mat", generic_cost_mat_mat(4, 4, 4)),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lu_4x4_matches_hand_count() {
        let c = generic_cost_lu(4, 1);
        assert_eq!((c.div, c.mul, c.add_sub), (6 + 4, 14 + 12, 14 + 12));
    }

    #[test]
    fn gauss_jordan_4x4_matches_hand_count() {
        let c = generic_cost_gauss_jordan_inverse(4);
        assert_eq!((c.div, c.mul, c.add_sub), (4, 128, 96));
    }

    #[test]
    fn composite_is_the_sum() {
        let steps = [GenericStep::Lu { n: 4, rhs: 2 }, GenericStep::Dot { n: 4 }];
        assert_eq!(
            generic_cost(&steps),
            generic_cost_lu(4, 2) + generic_cost_dot(4)
        );
    }
}
