//! What the caller holds between calls: the [`Prepared`] values of one parameter set and the
//! [`Scratch`] register file of one thread.

/// The values `prepare` computes from one parameter set (the fields of the generated
/// `Prepared`, in field order), for the [`TapeModule`](super::TapeModule) that made them.
///
/// A plain owned value (`Send + Sync`): prepare once per parameter set, share it between
/// threads, each with its own [`Scratch`].
#[derive(Clone, Debug, PartialEq)]
pub struct Prepared {
    /// The [`TapeModule`](super::TapeModule) that made these values (its id).
    pub(crate) module: u64,
    pub(crate) values: Vec<f64>,
}

impl Prepared {
    /// The values, in the generated `Prepared`'s field order.
    #[must_use]
    pub fn values(&self) -> &[f64] {
        &self.values
    }
}

/// The register file of kernel calls: one per thread, reused by every call.
///
/// A call grows it to the kernel's [`registers`](super::TapeKernel::registers) if it is
/// shorter; after that, calls do not allocate. [`TapeModule::scratch`](super::TapeModule::scratch)
/// returns one already large enough for every kernel of a module.
#[derive(Clone, Debug, Default)]
pub struct Scratch {
    pub(crate) regs: Vec<f64>,
}

impl Scratch {
    /// An empty register file (it grows on the first call).
    #[must_use]
    pub fn new() -> Scratch {
        Scratch::default()
    }

    /// A register file of `registers` values.
    #[must_use]
    pub fn with_registers(registers: usize) -> Scratch {
        Scratch {
            regs: vec![0.0; registers],
        }
    }

    /// The number of registers it holds.
    #[must_use]
    pub fn registers(&self) -> usize {
        self.regs.len()
    }
}
