//! From a planned block to a [`Program`]: one instruction per operation node of the block (the
//! nodes the emitted function evaluates, let-bound or inlined, each once), one
//! [`Instr::SinCos`] per sine-cosine pair the schedule computes together, leaves (arguments,
//! constants, `Prepared` values) in their registers, and temporaries given registers by a
//! linear scan that reuses a register once its value is dead.
//!
//! The emitted function evaluates every node of its block exactly once (a node used twice is a
//! `let`; a node used once is written inline where it is used), so the value of each node is
//! the same in both whatever order independent nodes are evaluated in: the tape evaluates them
//! in id order, which is topological.

use std::collections::{HashMap, HashSet};

use super::error::TapeError;
use super::float::Funcs;
use super::instr::{Instr, Reg};
use super::program::Program;
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

/// What one instruction of the block computes, before registers are assigned.
#[derive(Clone, Copy, Debug)]
enum Emit {
    /// One node.
    One(NodeId),
    /// A sine and a cosine of `arg`, computed together.
    Pair {
        sin: NodeId,
        cos: NodeId,
        arg: NodeId,
    },
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
    let in_block: HashMap<NodeId, usize> = block
        .nodes
        .iter()
        .enumerate()
        .map(|(i, &n)| (n, i))
        .collect();

    // The instructions in id order, a sine-cosine pair at the first of its two nodes.
    let mut pair_of: HashMap<NodeId, Emit> = HashMap::new();
    for step in &block.steps {
        if let Step::SinCos { sin, cos, arg } = *step {
            let pair = Emit::Pair { sin, cos, arg };
            pair_of.insert(sin, pair);
            pair_of.insert(cos, pair);
        }
    }
    let mut emits: Vec<Emit> = Vec::with_capacity(block.nodes.len());
    let mut done: HashSet<NodeId> = HashSet::new();
    for &n in &block.nodes {
        if done.contains(&n) {
            continue;
        }
        match pair_of.get(&n) {
            Some(&pair @ Emit::Pair { sin, cos, .. }) => {
                done.insert(sin);
                done.insert(cos);
                emits.push(pair);
            }
            _ => emits.push(Emit::One(n)),
        }
    }

    // Leaves: every operand or root the block does not compute.
    let mut leaves = Leaves {
        n_args,
        consts: Vec::new(),
        const_slot: HashMap::new(),
        gathers: Vec::new(),
        gather_slot: HashMap::new(),
        of: HashMap::new(),
    };
    let operands = |e: &Emit| -> Vec<NodeId> {
        match *e {
            Emit::One(n) => g.node(n).children().collect(),
            Emit::Pair { arg, .. } => vec![arg],
        }
    };
    let outside: Vec<NodeId> = emits
        .iter()
        .flat_map(operands)
        .chain(roots.iter().copied())
        .filter(|n| !in_block.contains_key(n))
        .collect();
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

    // Last use of each computed node, by instruction position; roots live to the end.
    let mut last_use: HashMap<NodeId, usize> = HashMap::new();
    for (i, e) in emits.iter().enumerate() {
        for c in operands(e) {
            if in_block.contains_key(&c) {
                last_use.insert(c, i);
            }
        }
    }
    for r in roots {
        last_use.insert(*r, usize::MAX);
    }

    // Linear scan: a temporary's register is free after its last use.
    let base = leaves.len();
    let mut reg_of: HashMap<NodeId, Reg> = HashMap::new();
    let mut free: Vec<Reg> = Vec::new();
    let mut next = base;
    let mut alloc = |free: &mut Vec<Reg>| -> Result<Reg, TapeError> {
        if let Some(r) = free.pop() {
            return Ok(r);
        }
        let r = index(next)?;
        next += 1;
        Ok(r)
    };
    let mut code = Vec::with_capacity(emits.len());
    for (i, e) in emits.iter().enumerate() {
        let reg = |n: NodeId| -> Result<Reg, TapeError> {
            reg_of
                .get(&n)
                .copied()
                .or_else(|| leaves.reg(n))
                .ok_or_else(|| internal(format!("node #{} read before it is computed", n.index())))
        };
        let ops = operands(e);
        let regs: Vec<Reg> = ops.iter().map(|&n| reg(n)).collect::<Result<_, _>>()?;
        // Operands dead after this instruction give their registers back first, so that the
        // result may take one (an instruction reads its operands before it writes).
        let mut dead: Vec<NodeId> = ops
            .iter()
            .copied()
            .filter(|n| last_use.get(n) == Some(&i))
            .collect();
        dead.dedup();
        for n in &dead {
            if let Some(r) = reg_of.remove(n) {
                free.push(r);
            }
        }
        let instr = match *e {
            Emit::Pair { sin, cos, .. } => {
                let (s, c) = (alloc(&mut free)?, alloc(&mut free)?);
                reg_of.insert(sin, s);
                reg_of.insert(cos, c);
                let a = first(&regs)?;
                Instr::SinCos {
                    f: funcs.sin_cos(),
                    sin: s,
                    cos: c,
                    a,
                }
            }
            Emit::One(n) => {
                let d = alloc(&mut free)?;
                reg_of.insert(n, d);
                instruction(g.node(n), d, &regs, funcs)?
            }
        };
        code.push(instr);
        // A value nothing reads (not expected: every node of a block is reachable from a
        // root) frees its register at once.
        let written: Vec<NodeId> = match *e {
            Emit::One(n) => vec![n],
            Emit::Pair { sin, cos, .. } => vec![sin, cos],
        };
        for n in written {
            if !last_use.contains_key(&n)
                && let Some(r) = reg_of.remove(&n)
            {
                free.push(r);
            }
        }
    }
    let outputs = roots
        .iter()
        .map(|&n| {
            reg_of
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
        code,
        outputs,
        n_regs: next,
    };
    if program.is_consistent() {
        Ok(program)
    } else {
        Err(internal("a register out of range".to_owned()))
    }
}

fn first(regs: &[Reg]) -> Result<Reg, TapeError> {
    regs.first()
        .copied()
        .ok_or_else(|| internal("an operation without operand".to_owned()))
}

fn second(regs: &[Reg]) -> Result<Reg, TapeError> {
    regs.get(1)
        .copied()
        .ok_or_else(|| internal("a binary operation with one operand".to_owned()))
}

/// The instruction computing `node` into `d` from its operands' registers.
fn instruction(node: Node, d: Reg, regs: &[Reg], funcs: Funcs) -> Result<Instr, TapeError> {
    let a = || first(regs);
    let b = || second(regs);
    Ok(match node {
        Node::Add(..) => Instr::Add {
            d,
            a: a()?,
            b: b()?,
        },
        Node::Sub(..) => Instr::Sub {
            d,
            a: a()?,
            b: b()?,
        },
        Node::Mul(..) => Instr::Mul {
            d,
            a: a()?,
            b: b()?,
        },
        Node::Div(..) => Instr::Div {
            d,
            a: a()?,
            b: b()?,
        },
        Node::Neg(_) => Instr::Neg { d, a: a()? },
        Node::Abs(_) => Instr::Abs { d, a: a()? },
        Node::Sqrt(_) => Instr::Call {
            f: funcs.sqrt(),
            d,
            a: a()?,
        },
        Node::Sin(_) => Instr::Call {
            f: funcs.sin(),
            d,
            a: a()?,
        },
        Node::Cos(_) => Instr::Call {
            f: funcs.cos(),
            d,
            a: a()?,
        },
        Node::Tanh(_) => Instr::Call {
            f: funcs.tanh(),
            d,
            a: a()?,
        },
        Node::Powi(_, n) => Instr::Powi {
            f: funcs.powi(),
            d,
            a: a()?,
            n,
        },
        Node::Const(_) | Node::Param(_) | Node::Input(_) => {
            return Err(internal(format!("leaf {node:?} scheduled as an operation")));
        }
    })
}
