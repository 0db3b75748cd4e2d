//! `walker-load`: a model file that is not compiled into the `walker` library, derived and
//! lowered when a program starts (by `walker-symbolic` and `walker-gen`, as a build script
//! would) and its kernels evaluated by an interpreter of the lowered graph, behind the
//! library's kernel interface ([`walker::model::Kernels`]).
//!
//! The `walker` library links no computer algebra; the front ends (the command line, the
//! Python module) link this crate and give [`runtime_source`] to [`walker::setup`], which calls
//! it for any model file that is not one of the shipped ones.
//!
//! Written here, not taken from a crate: the kernels are our own graph, and evaluating them is
//! the generator's business (`walker_gen::Graph`).

use std::collections::BTreeMap;
use std::sync::{Arc, Mutex};

use walker::model::{Args, KernelId, KernelSource, Kernels, NoKernels, Parameters};
use walker_gen::scene::Friction;
use walker_gen::scene::model::{Model, SymbolKind};
use walker_gen::{Module, ModelScene, derive_model, lower_model};

/// What [`walker::setup`] calls for a model file that is not compiled in: derives it once and
/// gives its kernels for every friction law and parameter set.
#[must_use]
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

/// The kernels of one friction law, lowered: the module and where each kernel argument comes
/// from.
struct Lowered {
    module: Module,
    /// Per kernel (by [`KernelId`]): its index in the module, and the argument sources.
    kernels: Vec<Option<(usize, Vec<Slot>)>>,
}

/// Where a kernel argument's value comes from in [`Args`].
#[derive(Clone, Copy)]
enum Slot {
    Q(usize),
    Qd(usize),
    U(usize),
    V(usize),
    Sigma,
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
        let symbols = self.model.symbols();
        let kernels = KernelId::ALL
            .iter()
            .map(|id| {
                let (index, k) = module
                    .kernels
                    .iter()
                    .enumerate()
                    .find(|(_, k)| k.name == id.name())?;
                let slots = k
                    .args
                    .iter()
                    .map(|a| {
                        if a == "sigma" {
                            return Some(Slot::Sigma);
                        }
                        let s = symbols.iter().find(|s| &s.name == a)?;
                        Some(match s.kind {
                            SymbolKind::Coordinate => Slot::Q(s.index),
                            SymbolKind::Velocity => Slot::Qd(s.index),
                            SymbolKind::Input => Slot::U(s.index),
                            SymbolKind::Aux => Slot::V(s.index),
                            _ => return None,
                        })
                    })
                    .collect::<Option<Vec<_>>>()?;
                Some((index, slots))
            })
            .collect();
        let l = Arc::new(Lowered { module, kernels });
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
        let values: Vec<f64> = lowered
            .module
            .params
            .iter()
            .map(|p| params.get(&p.name).unwrap_or(f64::NAN))
            .collect();
        Ok(Arc::new(Evaluated { lowered, values }))
    }
}

/// Kernels evaluated from the lowered graph at one parameter set.
struct Evaluated {
    lowered: Arc<Lowered>,
    values: Vec<f64>,
}

impl Kernels for Evaluated {
    fn has(&self, k: KernelId) -> bool {
        self.entry(k).is_some()
    }

    fn eval(&self, k: KernelId, args: &Args<'_>, out: &mut [f64]) {
        let Some((index, slots)) = self.entry(k) else {
            out.fill(f64::NAN);
            return;
        };
        let kernel = &self.lowered.module.kernels[*index];
        let value = |slot: &Slot| -> f64 {
            let get = |v: &[f64], i: usize| v.get(i).copied().unwrap_or(f64::NAN);
            match *slot {
                Slot::Q(i) => get(args.q, i),
                Slot::Qd(i) => get(args.qd, i),
                Slot::U(i) => get(args.u, i),
                Slot::V(i) => get(args.v, i),
                Slot::Sigma => args.sigma,
            }
        };
        let names = &kernel.args;
        let input = |name: &str| {
            names
                .iter()
                .position(|a| a == name)
                .map_or(f64::NAN, |i| value(&slots[i]))
        };
        let roots: Vec<_> = kernel.outputs.iter().map(|(_, id)| *id).collect();
        let values = self.lowered.module.graph.eval(&roots, &self.values, &input);
        for (o, v) in out.iter_mut().zip(values) {
            *o = v;
        }
    }
}

impl Evaluated {
    fn entry(&self, k: KernelId) -> Option<&(usize, Vec<Slot>)> {
        let i = KernelId::ALL.iter().position(|id| *id == k)?;
        self.lowered.kernels.get(i)?.as_ref()
    }
}
