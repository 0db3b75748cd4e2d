//! From a planned block to a [`Program`]: one instruction per operation node of the block (the
//! nodes the emitted function evaluates, let-bound or inlined, each once), except that a product
//! used once by a sum, difference or product shares its user's instruction ([`fusions`]); one
//! `SinCos` per sine-cosine pair the schedule computes together; leaves (arguments, constants,
//! `Prepared` values) in their registers; the instructions ordered to form long runs of one
//! operation, and temporaries given registers by a linear scan that reuses a register once its
//! value is dead.
//!
//! The emitted function evaluates every node of its block exactly once (a node used twice is a
//! `let`; a node used once is written inline where it is used), and a node's value does not
//! depend on when it is evaluated, only on its operands' values: so the tape may evaluate the
//! nodes in any order that computes operands first, and gets the same value for each. It picks
//! the order that makes the interpreter fast (see [`schedule`]).

use std::collections::{BTreeMap, BTreeSet, HashMap, HashSet};

use super::error::TapeError;
use super::instr::{Code, Instr, Op, Reg};
use super::program::Program;
use super::select::Funcs;
use crate::ir::{Graph, Node, NodeId};
use crate::plan::{Block, Step};

/// Where a block reads a node it does not compute.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Leaf {
    /// Argument `i` of the block (a kernel argument in signature order; a parameter of
    /// `prepare` in `Params` field order).
    Arg(u32),
    /// A constant.
    Const(f64),
    /// Value `i` of `Prepared`.
    Prepared(u32),
}

/// One instruction of the block before registers are assigned: its operation, the nodes it
/// computes (one; a sine and a cosine for `SinCos`) and the nodes it reads.
#[derive(Clone, Debug)]
struct Emit {
    op: Op,
    results: Vec<NodeId>,
    operands: Vec<NodeId>,
}

/// A leaf's place in its region of the register file (see [`Program`]).
#[derive(Clone, Copy, Debug)]
enum Slot {
    Arg(u32),
    Const(u32),
    Prepared(u32),
}

/// The registers of the leaves, in [`Program`]'s layout.
struct Leaves {
    n_args: usize,
    consts: Vec<f64>,
    const_slot: HashMap<u64, u32>,
    gathers: Vec<u32>,
    gather_slot: HashMap<u32, u32>,
    /// Per leaf node: its region and the index in it.
    of: HashMap<NodeId, Slot>,
}

impl Leaves {
    fn new(n_args: usize) -> Leaves {
        Leaves {
            n_args,
            consts: Vec::new(),
            const_slot: HashMap::new(),
            gathers: Vec::new(),
            gather_slot: HashMap::new(),
            of: HashMap::new(),
        }
    }

    fn add(&mut self, n: NodeId, leaf: Leaf) -> Result<(), TapeError> {
        let slot = match leaf {
            Leaf::Arg(i) if (i as usize) < self.n_args => Slot::Arg(i),
            Leaf::Arg(i) => {
                return Err(internal(format!("argument #{i} of {} read", self.n_args)));
            }
            Leaf::Const(c) => {
                let next = index(self.consts.len())?;
                let i = *self.const_slot.entry(c.to_bits()).or_insert(next);
                if i == next {
                    self.consts.push(c);
                }
                Slot::Const(i)
            }
            Leaf::Prepared(p) => {
                let next = index(self.gathers.len())?;
                let i = *self.gather_slot.entry(p).or_insert(next);
                if i == next {
                    self.gathers.push(p);
                }
                Slot::Prepared(i)
            }
        };
        self.of.insert(n, slot);
        Ok(())
    }

    /// The register of leaf node `n`, once every leaf is known.
    fn reg(&self, n: NodeId) -> Option<Reg> {
        let consts = self.n_args;
        let gathers = consts + self.consts.len();
        let r = match *self.of.get(&n)? {
            Slot::Arg(i) => i as usize,
            Slot::Const(i) => consts + i as usize,
            Slot::Prepared(i) => gathers + i as usize,
        };
        Reg::try_from(r).ok()
    }

    fn len(&self) -> usize {
        self.n_args + self.consts.len() + self.gathers.len()
    }
}

fn index(i: usize) -> Result<u32, TapeError> {
    u32::try_from(i).map_err(|_| internal("more than 2^32 registers".to_owned()))
}

fn internal(message: String) -> TapeError {
    TapeError::Internal { message }
}

/// Compiles `block`, which computes `roots`, reading the nodes it does not compute through
/// `leaf`; `n_args` arguments.
pub(crate) fn compile(
    g: &Graph,
    block: &Block,
    roots: &[NodeId],
    n_args: usize,
    leaf: &dyn Fn(NodeId) -> Option<Leaf>,
    funcs: Funcs,
) -> Result<Program, TapeError> {
    let emits = emits(g, block, roots, funcs)?;
    let computed: HashSet<NodeId> = emits.iter().flat_map(|e| e.results.clone()).collect();

    // Leaves: every operand or root the block does not compute.
    let mut leaves = Leaves::new(n_args);
    let outside = emits
        .iter()
        .flat_map(|e| e.operands.iter().copied())
        .chain(roots.iter().copied())
        .filter(|n| !computed.contains(n));
    for n in outside {
        if leaves.of.contains_key(&n) {
            continue;
        }
        let l = leaf(n).ok_or_else(|| {
            internal(format!(
                "node #{} ({:?}) is neither computed nor read by the block",
                n.index(),
                g.node(n)
            ))
        })?;
        leaves.add(n, l)?;
    }

    let order = schedule(&emits);
    let allocated = allocate(&emits, &order, roots, &leaves)?;
    let outputs = roots
        .iter()
        .map(|&n| {
            allocated
                .live
                .get(&n)
                .copied()
                .or_else(|| leaves.reg(n))
                .ok_or_else(|| internal(format!("output node #{} not computed", n.index())))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let program = Program {
        n_args,
        consts: leaves.consts,
        gathers: leaves.gathers,
        code: Code::new(&allocated.instrs)
            .ok_or_else(|| internal("2^32 instructions".to_owned()))?,
        outputs,
        n_regs: allocated.n_regs,
    };
    if program.is_consistent() {
        Ok(program)
    } else {
        Err(internal("a register out of range".to_owned()))
    }
}

/// The instructions of `block`, in id order: one per node, one per sine-cosine pair (at the
/// first of its two nodes), and a product used once, by a sum, difference or product, fused
/// into its user ([`fusions`]).
fn emits(g: &Graph, block: &Block, roots: &[NodeId], funcs: Funcs) -> Result<Vec<Emit>, TapeError> {
    let fused = fusions(g, block, roots);
    let absorbed: HashSet<NodeId> = fused.values().copied().collect();
    let mut pair_of: HashMap<NodeId, (NodeId, NodeId, NodeId)> = HashMap::new();
    for step in &block.steps {
        if let Step::SinCos { sin, cos, arg } = *step {
            pair_of.insert(sin, (sin, cos, arg));
            pair_of.insert(cos, (sin, cos, arg));
        }
    }
    let mut done: HashSet<NodeId> = HashSet::new();
    let mut emits = Vec::with_capacity(block.nodes.len());
    for &n in &block.nodes {
        if done.contains(&n) || absorbed.contains(&n) {
            continue;
        }
        if let Some(&m) = fused.get(&n) {
            emits.push(fuse(g, n, m)?);
        } else if let Some(&(sin, cos, arg)) = pair_of.get(&n) {
            done.extend([sin, cos]);
            emits.push(Emit {
                op: Op::SinCos(funcs.sin_cos()),
                results: vec![sin, cos],
                operands: vec![arg],
            });
        } else {
            let node = g.node(n);
            emits.push(Emit {
                op: op(node, funcs)?,
                results: vec![n],
                operands: node.children().collect(),
            });
        }
    }
    Ok(emits)
}

/// Which product each sum, difference or product of `block` absorbs (by its node): a product
/// of the block whose only use is that operand (once; not an output, nor absorbing one
/// itself). In id order, so that a product's own choice is made before its user's. The
/// generated code writes such a product inline in its user's expression; the tape computes
/// both in one instruction, each operation rounded as there.
fn fusions(g: &Graph, block: &Block, roots: &[NodeId]) -> HashMap<NodeId, NodeId> {
    let in_block: HashSet<NodeId> = block.nodes.iter().copied().collect();
    let mut uses: HashMap<NodeId, usize> = HashMap::new();
    for &n in &block.nodes {
        for c in g.node(n).children() {
            *uses.entry(c).or_default() += 1;
        }
    }
    for &r in roots {
        // An output is kept in its register to the end: never absorbed.
        *uses.entry(r).or_default() += 2;
    }
    let mut fused: HashMap<NodeId, NodeId> = HashMap::new();
    let mut absorbed: HashSet<NodeId> = HashSet::new();
    for &n in &block.nodes {
        let (Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b)) = g.node(n) else {
            continue;
        };
        let fusable = |m: NodeId| {
            in_block.contains(&m)
                && matches!(g.node(m), Node::Mul(..))
                && uses.get(&m) == Some(&1)
                && !fused.contains_key(&m)
        };
        if let Some(m) = [a, b]
            .into_iter()
            .find(|&m| fusable(m) && !absorbed.contains(&m))
        {
            fused.insert(n, m);
            absorbed.insert(m);
        }
    }
    fused
}

/// The fused instruction computing `n` (a sum, difference or product) with its operand `m`, a
/// product `x * y`, in it.
fn fuse(g: &Graph, n: NodeId, m: NodeId) -> Result<Emit, TapeError> {
    let Node::Mul(x, y) = g.node(m) else {
        return Err(internal(format!(
            "node #{} fused but no product",
            m.index()
        )));
    };
    // `(x * y) op c`, or `c - (x * y)`; `+` and `*` commute exactly (also in the sign of zero).
    let (op, c) = match g.node(n) {
        Node::Add(a, b) => (Op::MulAdd, if a == m { b } else { a }),
        Node::Mul(a, b) => (Op::MulMul, if a == m { b } else { a }),
        Node::Sub(a, b) if a == m => (Op::MulSub, b),
        Node::Sub(a, _) => (Op::SubMul, a),
        other => return Err(internal(format!("{other:?} fused with a product"))),
    };
    Ok(Emit {
        op,
        results: vec![n],
        operands: vec![x, y, c],
    })
}

/// The operation that computes `node`.
fn op(node: Node, funcs: Funcs) -> Result<Op, TapeError> {
    Ok(match node {
        Node::Add(..) => Op::Add,
        Node::Sub(..) => Op::Sub,
        Node::Mul(..) => Op::Mul,
        Node::Div(..) => Op::Div,
        Node::Neg(_) => Op::Neg,
        Node::Abs(_) => Op::Abs,
        Node::Sqrt(_) => Op::Call(funcs.sqrt()),
        Node::Sin(_) => Op::Call(funcs.sin()),
        Node::Cos(_) => Op::Call(funcs.cos()),
        Node::Tanh(_) => Op::Call(funcs.tanh()),
        Node::Powi(_, n) => Op::Powi(funcs.powi(), n),
        Node::Const(_) | Node::Param(_) | Node::Input(_) => {
            return Err(internal(format!("leaf {node:?} scheduled as an operation")));
        }
    })
}

/// An order of `emits` (indices) that computes operands first and keeps instructions of one
/// operation together: list scheduling that takes a ready instruction of the operation it took
/// last while there is one (also one that just became ready), else one of the operation with
/// the most ready instructions (the lowest operation, then the lowest index, on ties).
///
/// The interpreter dispatches once per run of one operation: on the shipped models this order
/// has from 1.7 (paper-active) to 4.6 (five-link) times fewer runs than instructions, and the
/// instructions of a run are often independent, so the processor overlaps them as it does the
/// compiled code's. In id order, one dispatch per instruction, the indirect branch of a long
/// kernel was mispredicted so often that five-link's `closed_loop` took 5.4 us instead of 0.9
/// (before products were fused).
fn schedule(emits: &[Emit]) -> Vec<usize> {
    let producer: HashMap<NodeId, usize> = emits
        .iter()
        .enumerate()
        .flat_map(|(i, e)| e.results.iter().map(move |&n| (n, i)))
        .collect();
    let mut waiting = vec![0_usize; emits.len()];
    let mut users: Vec<Vec<usize>> = vec![Vec::new(); emits.len()];
    for (j, e) in emits.iter().enumerate() {
        for o in &e.operands {
            if let (Some(&i), Some(w)) = (producer.get(o), waiting.get_mut(j)) {
                *w += 1;
                if let Some(u) = users.get_mut(i) {
                    u.push(j);
                }
            }
        }
    }
    let mut ready: BTreeMap<Op, BTreeSet<usize>> = BTreeMap::new();
    for (j, e) in emits.iter().enumerate() {
        if waiting.get(j) == Some(&0) {
            ready.entry(e.op).or_default().insert(j);
        }
    }
    let mut order = Vec::with_capacity(emits.len());
    let mut current: Option<Op> = None;
    loop {
        let op = match current.filter(|op| ready.get(op).is_some_and(|s| !s.is_empty())) {
            Some(op) => op,
            None => {
                // The most ready instructions; on a tie the first (lowest) operation.
                let best = ready.iter().filter(|(_, s)| !s.is_empty()).fold(
                    None::<(Op, usize)>,
                    |best, (&op, s)| match best {
                        Some((_, n)) if n >= s.len() => best,
                        _ => Some((op, s.len())),
                    },
                );
                match best {
                    Some((op, _)) => op,
                    None => break,
                }
            }
        };
        let Some(j) = ready.get_mut(&op).and_then(BTreeSet::pop_first) else {
            break;
        };
        order.push(j);
        for &u in users.get(j).map_or(&[][..], Vec::as_slice) {
            if let (Some(w), Some(e)) = (waiting.get_mut(u), emits.get(u)) {
                *w -= 1;
                if *w == 0 {
                    ready.entry(e.op).or_default().insert(u);
                }
            }
        }
        current = Some(op);
    }
    order
}

/// What [`allocate`] returns.
struct Allocated {
    /// The instructions, in order, with their registers.
    instrs: Vec<Instr>,
    /// The register of every computed node live at the end (the roots).
    live: HashMap<NodeId, Reg>,
    /// The size of the register file.
    n_regs: usize,
}

/// The instructions in `order` with registers: leaves where [`Leaves`] put them, temporaries
/// by a linear scan that frees a register after the last use of its value (roots live to the
/// end).
fn allocate(
    emits: &[Emit],
    order: &[usize],
    roots: &[NodeId],
    leaves: &Leaves,
) -> Result<Allocated, TapeError> {
    if order.len() != emits.len() {
        return Err(internal(
            "the schedule leaves an instruction out (a cycle)".to_owned(),
        ));
    }
    // Last use of each node, by position in `order`; roots live to the end.
    let mut last_use: HashMap<NodeId, usize> = HashMap::new();
    for (pos, &j) in order.iter().enumerate() {
        for &o in emits.get(j).map_or(&[][..], |e| e.operands.as_slice()) {
            last_use.insert(o, pos);
        }
    }
    for r in roots {
        last_use.insert(*r, usize::MAX);
    }
    let mut reg_of: HashMap<NodeId, Reg> = HashMap::new();
    let mut free: Vec<Reg> = Vec::new();
    let mut next = leaves.len();
    let mut instrs = Vec::with_capacity(order.len());
    for (pos, &j) in order.iter().enumerate() {
        let e = emits
            .get(j)
            .ok_or_else(|| internal("an instruction out of range".to_owned()))?;
        let regs: Vec<Reg> = e
            .operands
            .iter()
            .map(|&n| {
                reg_of
                    .get(&n)
                    .copied()
                    .or_else(|| leaves.reg(n))
                    .ok_or_else(|| {
                        internal(format!("node #{} read before it is computed", n.index()))
                    })
            })
            .collect::<Result<_, _>>()?;
        // Operands dead after this instruction give their registers back first, so that a
        // result may take one (an instruction reads its operands before it writes).
        for n in &e.operands {
            if last_use.get(n) == Some(&pos)
                && let Some(r) = reg_of.remove(n)
            {
                free.push(r);
            }
        }
        let mut results = [0; 2];
        for (slot, &n) in results.iter_mut().zip(&e.results) {
            let r = match free.pop() {
                Some(r) => r,
                None => {
                    next += 1;
                    index(next - 1)?
                }
            };
            reg_of.insert(n, r);
            *slot = r;
        }
        let operand = |i: usize| regs.get(i).copied().unwrap_or(0);
        let regs = match e.op {
            Op::SinCos(_) => [results[0], results[1], operand(0), 0],
            _ => [results[0], operand(0), operand(1), operand(2)],
        };
        instrs.push(Instr { op: e.op, regs });
        // A value nothing reads (not expected: every node of a block is reachable from a
        // root) frees its register at once.
        for n in &e.results {
            if !last_use.contains_key(n)
                && let Some(r) = reg_of.remove(n)
            {
                free.push(r);
            }
        }
    }
    Ok(Allocated {
        instrs,
        live: reg_of,
        n_regs: next,
    })
}
