//! Generates the kernels of every model file in `models/` (exact Coulomb friction, so that a
//! test realises any `mu` as `-mu0 sigma`), and for each a small adapter that calls a kernel by
//! name with its arguments by name: the model tests then run the same checks over every model
//! without knowing any model's signatures. Also generates the paper's scenes of
//! `walker/scenes/` (the paper's kernel catalogue, `walker_gen::lower::derive`: the quantities of
//! `models/paper-*.toml` in the paper's notation, lowered by the scene path) with the same
//! adapters, so that `walker-gen --scene` of a paper scene stays under the same tests as the
//! model files' kernels, and the two lowerings are compared.
use std::path::{Path, PathBuf};

use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use walker_gen::adapter::{by_name_adapter, render};
use walker_gen::{Config, Friction};

fn main() {
    if let Err(e) = run() {
        eprintln!("walker-tests build script: {e}");
        std::process::exit(1);
    }
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::var("OUT_DIR")?);
    let models = Path::new(env!("CARGO_MANIFEST_DIR")).join("../models");
    println!("cargo:rerun-if-changed={}", models.display());
    let mut files: Vec<PathBuf> = std::fs::read_dir(&models)?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    let mut modules = Index::default();
    for path in &files {
        println!("cargo:rerun-if-changed={}", path.display());
        let name = path
            .file_stem()
            .and_then(|s| s.to_str())
            .ok_or("a model file name")?
            .to_owned();
        let ident = name.replace('-', "_");
        let mut config = Config::new();
        // The tests call the unchecked kernels only: no checked entry points (half the code).
        config
            .model_file(path)
            .friction(Friction::Coulomb)
            .checked(false);
        let module = config.module()?;
        std::fs::write(out.join(format!("model_{ident}.rs")), config.render()?)?;
        let doc = format!("The kernels of `models/{name}.toml` (generated with Coulomb friction).");
        modules.add((&name, &ident), &doc, &format!("model_{ident}.rs"), &module);
    }
    std::fs::write(
        out.join("models.rs"),
        modules.render(
            "MODELS",
            "Every model of `models/`: its name and its kernels called by name.",
        )?,
    )?;
    scenes(&out)?;
    Ok(())
}

/// The paper's scenes of `walker/scenes/` generated here: the paper's two setups
/// with Table 1 fixed, the same structures with every parameter at run time, and both under
/// exact Coulomb friction with stick-slip.
const SCENES: [&str; 6] = [
    "active-level",
    "passive-slope",
    "general-level",
    "general-slope",
    "general-level-coulomb",
    "general-slope-coulomb",
];

/// `scene_<name>.rs` per scene of [`SCENES`], lowered from one derivation, and `scenes.rs`: per
/// scene a module that includes its kernels and an adapter that calls them by name.
fn scenes(out: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../walker/scenes");
    let derivation = walker_gen::lower::derive()?;
    let mut modules = Index::default();
    for name in SCENES {
        let path = dir.join(format!("{name}.toml"));
        println!("cargo:rerun-if-changed={}", path.display());
        let mut config = Config::new();
        // Unchecked kernels only, as for the model files.
        config.scene_file(&path).checked(false);
        let module = walker_gen::lower::lower(&derivation, &config.load_scene()?)?;
        let ident = name.replace('-', "_");
        let source = walker_gen::emit(&module, &config.options())?;
        std::fs::write(out.join(format!("scene_{ident}.rs")), source)?;
        let doc = format!(
            "The kernels of `walker/scenes/{name}.toml`, generated from the paper's catalogue."
        );
        modules.add((name, &ident), &doc, &format!("scene_{ident}.rs"), &module);
    }
    std::fs::write(
        out.join("scenes.rs"),
        modules.render(
            "SCENES",
            "The paper's scenes: name and kernels called by name.",
        )?,
    )?;
    Ok(())
}

/// Modules that call their kernels by name (walker-gen's by-name adapter), and the index of
/// them.
#[derive(Default)]
struct Index {
    modules: Vec<TokenStream>,
    entries: Vec<TokenStream>,
}

impl Index {
    /// Adds the module `ident` (documented by `doc`) over the generated `file` of `module`, and
    /// its `GeneratedModel` entry named `name`.
    fn add(
        &mut self,
        (name, ident): (&str, &str),
        doc: &str,
        file: &str,
        module: &walker_gen::Module,
    ) {
        let ident = format_ident!("{ident}");
        self.modules
            .push(by_name_adapter(module, &ident, &format!("/{file}"), doc));
        self.entries.push(quote! {
            GeneratedModel { name: #name, call: #ident::call, kernels: #ident::KERNELS }
        });
    }

    /// The modules and the index `pub const <name>: &[GeneratedModel]`, documented by `doc`,
    /// as a formatted file.
    fn render(self, name: &str, doc: &str) -> Result<String, walker_gen::Error> {
        let (modules, entries, name) = (self.modules, self.entries, format_ident!("{name}"));
        render(
            quote! {
                #(#modules)*
                #[doc = #doc]
                pub const #name: &[GeneratedModel] = &[#(#entries),*];
            },
            "tests/build.rs (walker-gen's by-name adapters)",
        )
    }
}
