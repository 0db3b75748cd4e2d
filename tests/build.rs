//! Generates the kernels of every model file in `models/` (exact Coulomb friction, so that a
//! test realises any `mu` as `-mu0 sigma`), and for each a small adapter that calls a kernel by
//! name with its arguments by name: the model tests then run the same checks over every model
//! without knowing any model's signatures. Also generates the paper's scenes of
//! `walker/scenes/` (the paper's kernel catalogue, `walker_gen::lower::derive`: the quantities of
//! `models/paper-*.toml` in the paper's notation, lowered by the scene path) with the same
//! adapters, so that `walker-gen --scene` of a paper scene stays under the same tests as the
//! model files' kernels, and the two lowerings are compared.
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use walker_gen::{Config, Friction, Shape};

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
    let mut index = String::from(
        "/// Every model of `models/`: its name and its kernels called by name.\n\
         pub const MODELS: &[GeneratedModel] = &[\n",
    );
    let mut modules = String::new();
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
        entry(
            &mut modules,
            &mut index,
            (&name, &ident),
            &doc,
            &format!("model_{ident}.rs"),
            &module,
        );
    }
    index.push_str("];\n");
    std::fs::write(out.join("models.rs"), modules + &index)?;
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
    let mut modules = String::new();
    let mut index = String::from(
        "/// The paper's scenes: name and kernels called by name.\n\
         pub const SCENES: &[GeneratedModel] = &[\n",
    );
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
        entry(
            &mut modules,
            &mut index,
            (name, &ident),
            &doc,
            &format!("scene_{ident}.rs"),
            &module,
        );
    }
    index.push_str("];\n");
    std::fs::write(out.join("scenes.rs"), modules + &index)?;
    Ok(())
}

/// Appends to `modules` the module `ident` (documented by `doc`) that includes the generated
/// `file` and calls its kernels by name, and to `index` its `GeneratedModel` entry.
fn entry(
    modules: &mut String,
    index: &mut String,
    (name, ident): (&str, &str),
    doc: &str,
    file: &str,
    module: &walker_gen::Module,
) {
    let (arms, outputs) = adapter(module);
    let _ = write!(
        modules,
        "/// {doc}\n\
         #[allow(clippy::all, clippy::pedantic, missing_docs, reason = \"generated\")]\n\
         pub mod {ident} {{\n\
         include!(concat!(env!(\"OUT_DIR\"), \"/{file}\"));\n\
         /// Calls kernel `kernel` with parameters and arguments by name; `None` for a \
         kernel it does not have.\n\
         pub fn call(kernel: &str, param: &dyn Fn(&str) -> f64, arg: &dyn Fn(&str) -> f64) \
         -> Option<Vec<f64>> {{\n\
         let p = prepare(&Params::from_fn(|n| param(n)));\n\
         Some(match kernel {{\n{arms}        _ => return None,\n    }})\n}}\n\
         /// Every kernel and its output names.\n\
         pub const KERNELS: &[(&str, &[&str])] = &[\n{outputs}];\n}}\n"
    );
    let _ = writeln!(
        index,
        "    GeneratedModel {{ name: \"{name}\", call: {ident}::call, kernels: {ident}::KERNELS }},"
    );
}

/// The match arms that call each kernel of `module` by name, and its `KERNELS` entries.
fn adapter(module: &walker_gen::Module) -> (String, String) {
    let mut arms = String::new();
    let mut outputs = String::new();
    for k in &module.kernels {
        let args: Vec<String> = k.args.iter().map(|a| format!("arg(\"{a}\")")).collect();
        let flatten = match k.output_shape {
            Shape::Scalar => "vec![out]",
            Shape::Vector(_) => "out.to_vec()",
            Shape::Matrix(..) => "out.iter().flatten().copied().collect()",
        };
        let _ = writeln!(
            arms,
            "        \"{0}\" => {{ let out = {0}(&p, {1}); {flatten} }}",
            k.name,
            args.join(", ")
        );
        let names: Vec<String> = k.outputs.iter().map(|(n, _)| format!("\"{n}\"")).collect();
        let _ = writeln!(outputs, "    (\"{}\", &[{}]),", k.name, names.join(", "));
    }
    (arms, outputs)
}
