//! The compiled-variant registry: what a crate that compiled a model's kernels (walker's own
//! build script, or a user's) hands to the simulator. walker-gen writes one [`Compiled`] per
//! model, with one [`Variant`] per friction law and set of parameters fixed at generation, into
//! the crate's `OUT_DIR/compiled.rs` as `pub const MODELS: &[Compiled]`.

use std::sync::Arc;

use walker_scene::Friction;

use crate::kernels::Kernels;

/// A compiled variant's constructor: its kernels prepared at the run-time parameters given by
/// name.
pub type Prepare = fn(&dyn Fn(&str) -> f64) -> Arc<dyn Kernels>;

/// One compiled variant of a model: its kernels generated for a friction law with some
/// parameters fixed at generation.
#[derive(Clone, Copy)]
pub struct Variant {
    /// The friction law the kernels were generated for.
    pub friction: Friction,
    /// The parameters substituted at generation, with their values.
    pub fixed: &'static [(&'static str, f64)],
    /// Prepares the kernels: the run-time parameters by name.
    pub prepare: Prepare,
}

/// The variants of a model compiled into a crate.
#[derive(Clone, Copy)]
pub struct Compiled {
    /// The model's name.
    pub name: &'static str,
    /// The model file's text (the compiled kernels were generated from it).
    pub source: &'static str,
    /// The model's canonical text ([`walker_scene::model::Model::canonical`]): a model file
    /// whose parsed content has this text runs these kernels, whatever its layout and comments.
    pub canonical: &'static str,
    /// The variants, those fixing more parameters first (they are faster where they apply).
    pub variants: &'static [Variant],
}

impl std::fmt::Debug for Compiled {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Compiled")
            .field("name", &self.name)
            .field("variants", &self.variants.len())
            .finish_non_exhaustive()
    }
}

impl std::fmt::Debug for Variant {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Variant")
            .field("friction", &self.friction)
            .field("fixed", &self.fixed)
            .finish_non_exhaustive()
    }
}
