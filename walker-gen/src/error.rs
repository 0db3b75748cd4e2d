//! Errors of the generator.

use std::path::PathBuf;

use walker_scene::SceneError;

/// A module that cannot be emitted (a bug in the lowering, or a hand-built module).
#[derive(Debug, thiserror::Error)]
pub enum EmitError {
    /// A name that is not a lower-case Rust identifier, is a keyword, or is reserved (`p`,
    /// `prepare`, `t<digits>`, `k<digits>`, a leading `_`).
    #[error(
        "{what} `{name}` is not a usable name (lower-case identifier, no keyword, not reserved)"
    )]
    BadName {
        /// What the name is of.
        what: String,
        /// The name.
        name: String,
    },
    /// Two items with the same name.
    #[error("{what} `{name}` is declared twice")]
    Duplicate {
        /// What the name is of.
        what: String,
        /// The name.
        name: String,
    },
    /// A `Param` node whose id is not in `Module::params`.
    #[error("parameter #{index} is used but not declared in Module::params")]
    UndeclaredParam {
        /// The parameter index.
        index: usize,
    },
    /// A kernel's output count does not match its shape.
    #[error("kernel `{kernel}` has {outputs} outputs but shape {shape}")]
    ShapeMismatch {
        /// The kernel.
        kernel: String,
        /// The number of outputs.
        outputs: usize,
        /// The declared shape.
        shape: String,
    },
    /// An output node that is not in the module's graph.
    #[error("kernel `{kernel}` refers to node #{index}, which is not in the graph")]
    ForeignNode {
        /// The kernel.
        kernel: String,
        /// The node index.
        index: usize,
    },
    /// An input the outputs use that is not among the kernel's arguments.
    #[error("kernel `{kernel}` uses input `{input}`, which is not one of its arguments")]
    UndeclaredInput {
        /// The kernel.
        kernel: String,
        /// The input.
        input: String,
    },
    /// The emitted tokens did not parse (a generator bug).
    #[error("generated code does not parse (walker-gen bug): {message}")]
    Syntax {
        /// The parser's message.
        message: String,
    },
}

/// Any failure of [`crate::Config::generate`], [`crate::Config::generate_all`] and [`crate::Config::render`].
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The scene is invalid.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// The model file is invalid (the message names file, line and column).
    #[error(transparent)]
    Model(#[from] walker_scene::model::ModelError),
    /// The module cannot be emitted.
    #[error(transparent)]
    Emit(#[from] EmitError),
    /// The lowering of the symbolic derivation failed for a kernel.
    #[error("lowering kernel `{kernel}`: {message}")]
    Lower {
        /// The kernel.
        kernel: String,
        /// What went wrong.
        message: String,
    },
    /// Reading or writing the output file failed.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
    /// Neither `scene_file`, `scene_files` nor `scene` was called.
    #[error("no scene: call Config::scene_file or Config::scene")]
    NoScene,
    /// A single-scene call (`render`, `stats`, `module`, `load_scene`, `generate`, or
    /// `generate_all` with an `out_file`) on a configuration of several scenes.
    #[error(
        "{count} scenes given: render, stats, module, generate and out_file take one scene; \
         use Config::generate_all with Config::out_dir"
    )]
    SeveralScenes {
        /// How many scenes were given.
        count: usize,
    },
    /// A model scene file (a scene naming a model file) is invalid.
    #[error("{}: {message}", path.display())]
    ModelScene {
        /// The scene file.
        path: PathBuf,
        /// What is wrong, naming the field.
        message: String,
    },
    /// Both scenes and a model were given to one configuration.
    #[error("scenes and a model given: a configuration generates either scenes or one model")]
    SceneAndModel,
    /// No `out_file`, no `out_dir` and no `OUT_DIR` in the environment.
    #[error("no output file: call Config::out_file or Config::out_dir (OUT_DIR is not set)")]
    NoOutFile,
    /// A kernel argument the kernel contract cannot bind (a generator or model bug).
    #[error(transparent)]
    Bind(#[from] walker_contract::BindError),
    /// A compiled variant's adapter or registry cannot be written ([`crate::Compile`]).
    #[error("compiled variants: {message}")]
    Adapter {
        /// What went wrong.
        message: String,
    },
}
