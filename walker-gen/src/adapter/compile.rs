//! [`Compile`], the builder a build script calls to compile model files into variants a
//! simulator runs (as `prost_build::Config::compile_protos`): per model one derivation, per
//! variant the kernels lowered and emitted, its adapter to the kernel contract, and one
//! registry file that holds them all.
//!
//! ```no_run
//! // build.rs of a crate with a walker of its own:
//! fn main() -> Result<(), Box<dyn std::error::Error>> {
//!     walker_gen::Compile::new()
//!         .model("hopper.toml")
//!         .emit_rerun_if_changed(true)
//!         .generate()?;
//!     Ok(())
//! }
//! // src/lib.rs: `include!(concat!(env!("OUT_DIR"), "/compiled.rs"));` defines
//! // `pub const MODELS: &[walker_contract::Compiled]`.
//! ```
//!
//! Writes into the output directory (default `$OUT_DIR`): `<variant>.rs` per variant (the
//! kernels, as [`crate::emit`] writes them) and `compiled.rs` (the adapter modules and
//! `pub const MODELS: &[Compiled]`, formatted and stamped `@generated`), each only when its
//! bytes change, so cargo recompiles only when a model or the generator changes.

use std::path::{Path, PathBuf};

use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use walker_contract::KernelId;
use walker_scene::model::Model;
use walker_scene::{Friction, ModelSceneFile};

use crate::error::Error;
use crate::model::{ModelScene, derive_model, lower_model};
use crate::options::EmitOptions;

/// One compiled variant of a model: a friction law, the parameters fixed at generation, and
/// whether the Jacobian kernels are compiled too.
#[derive(Clone, Debug, PartialEq)]
pub struct VariantSpec {
    friction: Friction,
    fixed: Vec<(String, f64)>,
    fixed_by: Option<PathBuf>,
    jacobians: bool,
}

impl VariantSpec {
    /// A variant under the friction law `friction` with every parameter given at run time and
    /// no Jacobian kernels.
    #[must_use]
    pub fn new(friction: Friction) -> VariantSpec {
        VariantSpec {
            friction,
            fixed: Vec::new(),
            fixed_by: None,
            jacobians: false,
        }
    }

    /// Fixes the parameter `name` at `value` at generation (the variant runs only while the
    /// parameter has exactly this value; its kernels are smaller and faster).
    #[must_use]
    pub fn fix(mut self, name: &str, value: f64) -> VariantSpec {
        self.fixed.push((name.to_owned(), value));
        self
    }

    /// Fixes the parameters of the `[fix]` table of a scene file of this model (a model scene,
    /// `docs/model-format.md`), so that the values are written in the scene file only.
    #[must_use]
    pub fn fixed_by_scene(mut self, path: impl AsRef<Path>) -> VariantSpec {
        self.fixed_by = Some(path.as_ref().to_path_buf());
        self
    }

    /// Whether the Jacobian kernels (`accel_jacobian`, `impact_jacobian`, ..) are compiled too:
    /// they feed the stiff integrator and the Poincare map's variational equations, and with
    /// every parameter at run time they are large.
    #[must_use]
    pub fn jacobians(mut self, yes: bool) -> VariantSpec {
        self.jacobians = yes;
        self
    }
}

/// A model file and its variants.
#[derive(Clone, Debug)]
struct Entry {
    path: PathBuf,
    variants: Vec<VariantSpec>,
}

/// Compiles model files into the variants a simulator runs; see the module docs.
#[derive(Clone, Debug)]
pub struct Compile {
    models: Vec<Entry>,
    out_dir: Option<PathBuf>,
    contract: String,
    rerun_if_changed: bool,
}

impl Default for Compile {
    fn default() -> Self {
        Compile::new()
    }
}

/// What [`Compile::generate`] wrote.
#[derive(Clone, Debug)]
pub struct CompileReport {
    /// The registry file (`compiled.rs`).
    pub registry: PathBuf,
    /// Each variant's kernel file, with its size in bytes.
    pub kernels: Vec<(PathBuf, usize)>,
}

impl Compile {
    /// No model yet, output to `$OUT_DIR`, the contract at `::walker_contract`, no `cargo:`
    /// lines.
    #[must_use]
    pub fn new() -> Compile {
        Compile {
            models: Vec::new(),
            out_dir: None,
            contract: "::walker_contract".to_owned(),
            rerun_if_changed: false,
        }
    }

    /// Adds a model file (relative paths are relative to the working directory, the package
    /// root in a build script). Its variants are those [`Compile::variant`] adds next; with
    /// none, one per friction law the model lists (`none` aside), every parameter at run time.
    pub fn model(&mut self, path: impl AsRef<Path>) -> &mut Compile {
        self.models.push(Entry {
            path: path.as_ref().to_path_buf(),
            variants: Vec::new(),
        });
        self
    }

    /// Adds a variant to the model added last. The simulator takes the first variant that fits
    /// a run, so give those that fix more parameters first. A variant added before any model
    /// is reported by [`Compile::generate`].
    pub fn variant(&mut self, variant: VariantSpec) -> &mut Compile {
        match self.models.last_mut() {
            Some(entry) => entry.variants.push(variant),
            None => self.models.push(Entry {
                path: PathBuf::new(),
                variants: vec![variant],
            }),
        }
        self
    }

    /// The directory the files are written to (default: `$OUT_DIR`).
    pub fn out_dir(&mut self, path: impl AsRef<Path>) -> &mut Compile {
        self.out_dir = Some(path.as_ref().to_path_buf());
        self
    }

    /// The path the generated adapters name the kernel contract by (default
    /// `::walker_contract`; a crate that re-exports it may give its own path).
    pub fn contract_path(&mut self, path: &str) -> &mut Compile {
        path.clone_into(&mut self.contract);
        self
    }

    /// Whether generating prints `cargo:rerun-if-changed=` for each model and scene file read.
    pub fn emit_rerun_if_changed(&mut self, yes: bool) -> &mut Compile {
        self.rerun_if_changed = yes;
        self
    }

    /// Derives each model once, lowers and emits each variant, and writes the files.
    ///
    /// # Errors
    /// A model or scene file is invalid or cannot be derived, a variant's friction law or
    /// fixed parameter is not the model's, the contract path does not parse, no output
    /// directory is known, or a file cannot be written.
    pub fn generate(&self) -> Result<CompileReport, Error> {
        let out = match &self.out_dir {
            Some(dir) => dir.clone(),
            None => std::env::var_os("OUT_DIR")
                .map(PathBuf::from)
                .ok_or(Error::NoOutFile)?,
        };
        let contract: TokenStream = syn::parse_str::<syn::Path>(&self.contract).map_or_else(
            |e| {
                Err(Error::Adapter {
                    message: format!("contract path `{}`: {e}", self.contract),
                })
            },
            |p| Ok(quote!(#p)),
        )?;
        let mut modules = Vec::new();
        let mut entries = Vec::new();
        let mut report = CompileReport {
            registry: out.join("compiled.rs"),
            kernels: Vec::new(),
        };
        for entry in &self.models {
            if entry.path.as_os_str().is_empty() {
                return Err(Error::Adapter {
                    message: "a variant was added before any model (call Compile::model first)"
                        .to_owned(),
                });
            }
            self.rerun(&entry.path);
            let model = Model::from_file(&entry.path)?;
            let derivation = derive_model(&model)?;
            let variants = if entry.variants.is_empty() {
                default_variants(&model)
            } else {
                entry.variants.clone()
            };
            let mut items = Vec::new();
            for (k, v) in variants.iter().enumerate() {
                let ident = format_ident!("{}_{k}", model.name.replace('-', "_"));
                let fixed = self.fixed_values(&model, v)?;
                let mut scene = ModelScene::new(model.clone());
                scene.friction = v.friction;
                scene.fixed = fixed.iter().cloned().collect();
                let has = |id: &KernelId| derivation.kernels.iter().any(|k| k.name == id.name());
                scene.kernels = Some(
                    KernelId::ALL
                        .iter()
                        .filter(|id| v.jacobians || !id.is_jacobian())
                        .filter(|id| has(id))
                        .map(|id| id.name().to_owned())
                        .collect(),
                );
                scene.name = Some(ident.to_string().replace('_', "-"));
                let module = lower_model(&derivation, &scene)?;
                let options = EmitOptions {
                    checked: false,
                    ..EmitOptions::default()
                };
                let file = format!("{ident}.rs");
                let include = format!("/{file}");
                let source = crate::emit(&module, &options)?;
                write_if_changed(&out.join(&file), &source)?;
                report.kernels.push((out.join(&file), source.len()));
                let shown: Vec<String> = fixed.iter().map(|(n, x)| format!("{n} = {x}")).collect();
                let doc = format!(
                    " `{}`, friction `{:?}`, fixed: {}.",
                    model.name,
                    v.friction,
                    if shown.is_empty() {
                        "none".to_owned()
                    } else {
                        shown.join(", ")
                    }
                );
                modules.push(super::variant_adapter(
                    &model, &module, &ident, &include, &doc, &contract,
                )?);
                let friction = format_ident!("{}", format!("{:?}", v.friction));
                let (names, values): (Vec<_>, Vec<_>) = fixed
                    .iter()
                    .map(|(n, x)| (n.as_str(), proc_macro2::Literal::f64_unsuffixed(*x)))
                    .unzip();
                items.push(quote! {
                    #contract::Variant {
                        friction: #contract::Friction::#friction,
                        fixed: &[#((#names, #values)),*],
                        prepare: #ident::prepare_kernels,
                    }
                });
            }
            let (name, canonical) = (&model.name, model.canonical());
            let text = walker_scene::read_input(&entry.path, walker_scene::limits::MAX_FILE_BYTES)
                .map_err(|e| Error::Adapter {
                    message: format!("{}: {e}", entry.path.display()),
                })?;
            entries.push(quote! {
                #contract::Compiled {
                    name: #name,
                    source: #text,
                    canonical: #canonical,
                    variants: &[#(#items),*],
                }
            });
        }
        let file = quote! {
            #(#modules)*
            /// The models compiled by this crate's build script, with their variants.
            pub const MODELS: &[#contract::Compiled] = &[#(#entries),*];
        };
        let text = super::render(
            file,
            "walker-gen (walker_gen::Compile) from the model files",
        )?;
        write_if_changed(&report.registry, &text)?;
        Ok(report)
    }

    /// Prints `cargo:rerun-if-changed=path` if asked to.
    fn rerun(&self, path: &Path) {
        if self.rerun_if_changed {
            println!("cargo:rerun-if-changed={}", path.display());
        }
    }

    /// The parameters variant `v` of `model` fixes: its own, then the `[fix]` table of its
    /// scene file (which must be a scene of this model).
    fn fixed_values(&self, model: &Model, v: &VariantSpec) -> Result<Vec<(String, f64)>, Error> {
        let mut fixed = v.fixed.clone();
        if let Some(path) = &v.fixed_by {
            self.rerun(path);
            let file = ModelSceneFile::from_file(path).map_err(|e| Error::ModelScene {
                path: path.clone(),
                message: e.to_string(),
            })?;
            if file.model.canonical() != model.canonical() {
                return Err(Error::ModelScene {
                    path: path.clone(),
                    message: format!(
                        "the scene's model is `{}`, not the model `{}` this variant compiles",
                        file.model.name, model.name
                    ),
                });
            }
            fixed.extend(file.fix);
        }
        Ok(fixed)
    }
}

/// One variant per friction law `model` lists (`none` aside: it runs the tanh kernels with
/// `mu0 = 0`), every parameter at run time.
fn default_variants(model: &Model) -> Vec<VariantSpec> {
    let mut laws: Vec<Friction> = model
        .stance
        .friction
        .iter()
        .copied()
        .filter(|f| *f != Friction::None)
        .collect();
    if laws.is_empty() {
        laws.push(Friction::Tanh);
    }
    laws.into_iter().map(VariantSpec::new).collect()
}

/// Writes `text` to `path` unless it is a regular file that already holds these bytes.
fn write_if_changed(path: &Path, text: &str) -> Result<(), Error> {
    if crate::config::holds(path, text) {
        return Ok(());
    }
    std::fs::write(path, text).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })
}
