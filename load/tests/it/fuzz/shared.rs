//! The derivation shared across the mutants of the fuzz suite (`fuzz_models.rs`) that differ
//! only in what the derivation does not see, and the time each stage of a case took.

use std::collections::HashMap;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use walker::model::KernelSource;
use walker_gen::scene::model::Model;

/// What the derivation of `model` sees: its canonical text ([`Model::canonical`]: what the
/// generated code depends on) without the parameters' valid ranges, which only the loader
/// (every value at load) and the simulator (every value set) read. The defaults stay in:
/// the derivation's floating-point checks (a singular `M` or `A`) evaluate at them
/// (`derive/src/model/mechanics.rs`, `generic_point`), and so does `[start]` (the control
/// check, `derive/src/model/control_check.rs`).
#[must_use]
pub fn derivation_key(model: &Model) -> String {
    let mut key = model.canonical();
    for p in &model.parameters {
        let with = format!("parameter {} [{}] {} ", p.name.name, p.unit, p.range);
        let without = format!("parameter {} [{}] ", p.name.name, p.unit);
        key = key.replacen(&with, &without, 1);
    }
    key
}

/// A derivation's kernel source, or its error.
type Derivation = Result<Arc<dyn KernelSource>, String>;

/// The run-time kernel source of the walks, as `walker_load::runtime_source` gives it, with
/// each derivation kept by [`derivation_key`]: a model derived once serves every mutant with
/// its key (its own parameters, ranges and start applied by the simulator as for any model).
#[derive(Default)]
pub struct SharedSource {
    kept: Mutex<HashMap<String, Derivation>>,
    /// Derivations made (distinct keys).
    pub derived: Mutex<usize>,
    /// Time spent deriving.
    pub time: Mutex<Duration>,
}

impl SharedSource {
    /// The kernel source of `model`: kept, or derived now (by `walker_load`) and kept.
    ///
    /// # Errors
    /// The derivation's error (kept too: the same key fails the same way).
    pub fn source(&self, model: &Model) -> Result<Arc<dyn KernelSource>, String> {
        let key = derivation_key(model);
        let mut kept = self.kept.lock().map_err(|e| e.to_string())?;
        if let Some(r) = kept.get(&key) {
            return r.clone();
        }
        let t = Instant::now();
        let r = walker_load::runtime_source()(model);
        if let (Ok(mut time), Ok(mut derived)) = (self.time.lock(), self.derived.lock()) {
            *time += t.elapsed();
            *derived += 1;
        }
        kept.insert(key, r.clone());
        r
    }
}
