//! A compiled block ([`Program`]): `prepare`'s body or a kernel's body as straight-line
//! instructions over one register file, and how it is run.
//!
//! Register layout, lowest first:
//!
//! | registers | hold | filled |
//! |---|---|---|
//! | `0 .. n_args` | the arguments (a kernel's, in signature order; or the parameters) | per call |
//! | next `consts.len()` | the block's constants, each once | per call |
//! | next `gathers.len()` | the `Prepared` values the block reads | per call |
//! | the rest | temporaries, reused once their value is dead | by the instructions |
//!
//! Copying the leaves in per call lets every operand be a plain register index (no tag to
//! decode per operand) and lets one [`Scratch`](super::Scratch) serve every kernel.

use super::instr::{Code, Reg, run};

/// One block, compiled.
#[derive(Clone, Debug)]
pub(crate) struct Program {
    /// Registers `0 .. n_args` hold the arguments.
    pub(crate) n_args: usize,
    /// The constants, in the registers after the arguments.
    pub(crate) consts: Vec<f64>,
    /// Indices into the source (`Prepared`) of the values in the registers after the constants.
    pub(crate) gathers: Vec<u32>,
    /// The instructions, in order.
    pub(crate) code: Code,
    /// The register of each output, in output order.
    pub(crate) outputs: Vec<Reg>,
    /// The size of the register file.
    pub(crate) n_regs: usize,
}

impl Program {
    /// Whether every register the program names is in its register file (checked once when it
    /// is built, so that [`Program::run`] never finds one out of range).
    pub(crate) fn is_consistent(&self) -> bool {
        let n = self.n_regs;
        let leaves = self.n_args + self.consts.len() + self.gathers.len();
        let fits = |r: Reg| (r as usize) < n;
        leaves <= n
            && self.outputs.iter().all(|&r| fits(r))
            && self.code.instrs().all(|i| {
                i.reads().iter().all(|&r| fits(r))
                    && i.writes().iter().all(|&w| fits(w) && w as usize >= leaves)
            })
    }

    /// The first register of the temporaries.
    fn leaves(&self) -> usize {
        self.n_args + self.consts.len() + self.gathers.len()
    }

    /// Runs the program: `args` (exactly `n_args` values), `source` the `Prepared` values the
    /// gathers index, the outputs written to `out` (exactly one per output), `regs` grown to
    /// the register file if it is shorter. `None` if a length does not fit (the callers check
    /// them first, to say which).
    pub(crate) fn run(
        &self,
        args: &[f64],
        source: &[f64],
        out: &mut [f64],
        regs: &mut Vec<f64>,
    ) -> Option<()> {
        if args.len() != self.n_args || out.len() != self.outputs.len() {
            return None;
        }
        if regs.len() < self.n_regs {
            regs.resize(self.n_regs, 0.0);
        }
        let r = regs.get_mut(..self.n_regs)?;
        let consts_at = self.n_args;
        let gathers_at = consts_at + self.consts.len();
        r.get_mut(..consts_at)?.copy_from_slice(args);
        r.get_mut(consts_at..gathers_at)?
            .copy_from_slice(&self.consts);
        let gathered = r.get_mut(gathers_at..self.leaves())?;
        for (slot, &i) in gathered.iter_mut().zip(&self.gathers) {
            *slot = *source.get(i as usize)?;
        }
        run(&self.code, r)?;
        for (o, &reg) in out.iter_mut().zip(&self.outputs) {
            *o = *r.get(reg as usize)?;
        }
        Some(())
    }
}
