//! `walker-load`: a model file that is not compiled into the `walker` library, derived and
//! lowered when a program starts (by `walker-symbolic` and `walker-gen`, as a build script
//! would) and its kernels evaluated by walker-gen's tape (a register machine that computes, bit
//! for bit, what the generated Rust computes; 3 to 6 times slower), behind the library's
//! kernel interface ([`walker::model::Kernels`]).
//!
//! The `walker` library links no computer algebra; the front ends (the command line, the
//! Python module) link this crate and give [`runtime_source`] to [`walker::setup`], which calls
//! it for any model file that is not one of the shipped ones.
//!
//! Written here, not taken from a crate: the kernels are our own graph, and evaluating them is
//! the generator's business (`walker_gen::tape`).

use std::cell::RefCell;
use std::collections::BTreeMap;
use std::sync::{Arc, Mutex};

use walker::contract::Binding;
use walker::model::{Args, KernelId, KernelSource, Kernels, NoKernels, Parameters};
use walker_gen::scene::Friction;
use walker_gen::scene::model::Model;
use walker_gen::tape::{KernelIndex, Prepared, Scratch, TapeModule};
use walker_gen::{EmitOptions, ModelScene, derive_model, lower_model};

thread_local! {
    /// The register file of this thread's kernel calls (it grows to the largest kernel called).
    static SCRATCH: RefCell<Scratch> = RefCell::new(Scratch::new());
}

/// What [`walker::setup`] calls for a model file that is not compiled in: derives it once and
/// gives its kernels for every friction law and parameter set.
pub fn runtime_source() -> impl Fn(&Model) -> Result<Arc<dyn KernelSource>, String> + Sync {
    |model: &Model| {
        let source = Derived::new(model.clone())?;
        Ok(Arc::new(source) as Arc<dyn KernelSource>)
    }
}

/// A model derived at run time: its derivation, and its kernels lowered per friction law
/// (lowered on first use and kept).
pub struct Derived {
    model: Model,
    derivation: walker_gen::model::ModelDerivation,
    lowered: Mutex<BTreeMap<u8, Arc<Lowered>>>,
}

/// The kernels of one friction law, lowered and compiled to a tape, and where each kernel
/// argument comes from.
struct Lowered {
    tape: TapeModule,
    /// Per kernel (by [`KernelId`]): its index in the tape, its number of outputs, and its
    /// arguments' bindings (the kernel contract's, which the generated adapters use too).
    kernels: Vec<Option<(KernelIndex, usize, Vec<Binding>)>>,
}

impl Derived {
    /// Derives `model`.
    ///
    /// # Errors
    /// The derivation fails (its message names the file, line and column where it can).
    pub fn new(model: Model) -> Result<Derived, String> {
        let derivation = derive_model(&model).map_err(|e| e.to_string())?;
        Ok(Derived {
            model,
            derivation,
            lowered: Mutex::new(BTreeMap::new()),
        })
    }

    fn lowered(&self, law: Friction) -> Result<Arc<Lowered>, String> {
        let key = law as u8;
        let mut cache = self.lowered.lock().map_err(|e| e.to_string())?;
        if let Some(l) = cache.get(&key) {
            return Ok(Arc::clone(l));
        }
        let mut scene = ModelScene::new(self.model.clone());
        scene.friction = law;
        let module = lower_model(&self.derivation, &scene).map_err(|e| e.to_string())?;
        let tape = TapeModule::new(&module, &EmitOptions::default()).map_err(|e| e.to_string())?;
        let kernels = KernelId::ALL
            .iter()
            .map(|id| {
                let index = tape.kernel_index(id.name())?;
                let k = tape.kernel(index)?;
                let slots = Binding::all(&self.model, k.args()).ok()?;
                Some((index, k.output_len(), slots))
            })
            .collect();
        let l = Arc::new(Lowered { tape, kernels });
        cache.insert(key, Arc::clone(&l));
        Ok(l)
    }
}

impl KernelSource for Derived {
    fn prepare(&self, law: Friction, params: &Parameters) -> Result<Arc<dyn Kernels>, NoKernels> {
        let lowered = self.lowered(law).map_err(|message| NoKernels::Source {
            model: self.model.name.clone(),
            message,
        })?;
        let prepared = lowered
            .tape
            .prepare_with(|name| params.get(name).unwrap_or(f64::NAN));
        Ok(Arc::new(Taped { lowered, prepared }))
    }
}

/// The most arguments and outputs of a kernel evaluated without allocating (larger ones, of
/// models beyond the simulator's size, are NaN).
const MAX_ARGS: usize = 64;
const MAX_OUTPUTS: usize = 256;

/// A model's kernels on the tape, prepared for one parameter set.
struct Taped {
    lowered: Arc<Lowered>,
    prepared: Prepared,
}

impl Kernels for Taped {
    fn has(&self, k: KernelId) -> bool {
        self.entry(k).is_some()
    }

    fn eval(&self, k: KernelId, args: &Args<'_>, out: &mut [f64]) {
        let Some((index, outputs, slots)) = self.entry(k) else {
            out.fill(f64::NAN);
            return;
        };
        if slots.len() > MAX_ARGS || *outputs > MAX_OUTPUTS {
            out.fill(f64::NAN);
            return;
        }
        let mut values = [0.0; MAX_ARGS];
        for (v, binding) in values.iter_mut().zip(slots) {
            *v = binding.read(args);
        }
        let mut result = [0.0; MAX_OUTPUTS];
        let done = SCRATCH.with(|scratch| {
            self.lowered.tape.eval(
                *index,
                &self.prepared,
                &values[..slots.len()],
                &mut result[..*outputs],
                &mut scratch.borrow_mut(),
            )
        });
        if done.is_err() {
            out.fill(f64::NAN);
            return;
        }
        let n = out.len().min(*outputs);
        out[..n].copy_from_slice(&result[..n]);
        out[n..].fill(f64::NAN);
    }
}

impl Taped {
    fn entry(&self, k: KernelId) -> Option<&(KernelIndex, usize, Vec<Binding>)> {
        let i = KernelId::ALL.iter().position(|id| *id == k)?;
        self.lowered.kernels.get(i)?.as_ref()
    }
}
