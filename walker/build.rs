//! Generates the kernels of the shipped model files into `OUT_DIR` with `walker-gen`, one module
//! per compiled variant (a friction law, some parameters fixed at generation), each with an
//! adapter that implements the library's kernel interface (`walker::model::Kernels`).
//!
//! Reads: `models/*.toml` named in [`MODELS`]. Writes: `<variant>.rs` per variant and
//! `compiled.rs` (the modules, their adapters and the registry `MODELS`, formatted and stamped
//! as generated), each rewritten only when its bytes change, so cargo recompiles only when a
//! model or the generator changes.
//! Every model is derived once; its variants are lowered from that derivation.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use walker_gen::scene::ModelSceneFile;
use walker_gen::scene::model::{Model, SymbolKind};
use walker_gen::{EmitOptions, Friction, ModelScene, Shape, derive_model, emit, lower_model};

/// The kernels the simulator calls (the model's others, such as `mass_matrix`, are left out).
const SIMULATED: &[&str] = &[
    "accel",
    "closed_loop",
    "lambda",
    "stick",
    "closed_loop_stick",
    "impact",
    "impact_double",
    "impact_coulomb",
    "events",
    "relabel",
    "points",
    "energy",
    "output_rates",
    "input_rates",
];

/// The Jacobian kernels: compiled only where parameters are fixed (with every parameter
/// symbolic they are large), and there they feed the stiff integrator and the Poincare map.
const JACOBIANS: &[&str] = &[
    "accel_jacobian",
    "closed_loop_jacobian",
    "impact_jacobian",
    "output_rates_jacobian",
    "input_rates_jacobian",
    "relabel_jacobian",
];

/// A compiled variant: a friction law and the parameters fixed at generation, those of the
/// `[fix]` table of a built-in scene (`models/scenes/<scene>.toml`), or none.
struct Variant {
    friction: Friction,
    fixed_by: Option<&'static str>,
}

const fn variant(friction: Friction, fixed_by: Option<&'static str>) -> Variant {
    Variant { friction, fixed_by }
}

/// The shipped models compiled into the library, each with its variants (those fixing more
/// parameters first: the registry takes the first that fits).
const MODELS: &[(&str, &[Variant])] = &[
    (
        "paper-active",
        &[
            variant(Friction::Tanh, Some("active-level")),
            variant(Friction::Tanh, None),
            variant(Friction::Coulomb, None),
        ],
    ),
    (
        "paper-passive",
        &[
            variant(Friction::Tanh, Some("passive-slope")),
            variant(Friction::Tanh, None),
            variant(Friction::Coulomb, None),
        ],
    ),
    (
        "rimless-wheel",
        &[
            variant(Friction::Tanh, None),
            variant(Friction::Coulomb, None),
        ],
    ),
    (
        "compass-gait",
        &[
            variant(Friction::Tanh, None),
            variant(Friction::Coulomb, None),
        ],
    ),
    (
        "three-link",
        &[
            variant(Friction::Tanh, None),
            variant(Friction::Coulomb, None),
        ],
    ),
];

/// The parameters variant `v` of model `name` fixes: the `[fix]` table of its built-in scene
/// (`models/scenes/<scene>.toml`, which must be a scene of this model), so that Table 1 is
/// written in the scene files only.
fn fixed_values(
    models: &Path,
    name: &str,
    v: &Variant,
) -> Result<Vec<(String, f64)>, Box<dyn std::error::Error>> {
    let Some(scene) = v.fixed_by else {
        return Ok(Vec::new());
    };
    let path = models.join("scenes").join(format!("{scene}.toml"));
    println!("cargo:rerun-if-changed={}", path.display());
    let file = ModelSceneFile::from_file(&path)?;
    if file.model.name != name {
        return Err(format!(
            "{}: the scene's model is `{}`, not `{name}`",
            path.display(),
            file.model.name
        )
        .into());
    }
    Ok(file.fix.into_iter().collect())
}

fn main() {
    if let Err(e) = run() {
        eprintln!("walker build script: {e}");
        std::process::exit(1);
    }
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let out = PathBuf::from(std::env::var("OUT_DIR")?);
    let models = Path::new(env!("CARGO_MANIFEST_DIR")).join("../models");
    let mut index = String::from(
        "/// The shipped models compiled into the library, with their variants.\n\
         pub const MODELS: &[Compiled] = &[\n",
    );
    let mut modules = String::new();
    for (name, variants) in MODELS {
        let path = models.join(format!("{name}.toml"));
        println!("cargo:rerun-if-changed={}", path.display());
        let model = Model::from_file(&path)?;
        let derivation = derive_model(&model)?;
        let mut entries = String::new();
        for (k, v) in variants.iter().enumerate() {
            let ident = format!("{}_{k}", name.replace('-', "_"));
            let fixed = fixed_values(&models, name, v)?;
            let mut scene = ModelScene::new(model.clone());
            scene.friction = v.friction;
            scene.fixed = fixed.iter().cloned().collect();
            let wanted = SIMULATED
                .iter()
                .chain(if fixed.is_empty() { &[][..] } else { JACOBIANS });
            let has = |name: &str| derivation.kernels.iter().any(|k| k.name == name);
            scene.kernels = Some(
                wanted
                    .copied()
                    .filter(|w| has(w))
                    .map(str::to_owned)
                    .collect(),
            );
            scene.name = Some(ident.replace('_', "-"));
            let module = lower_model(&derivation, &scene)?;
            let options = EmitOptions {
                checked: false,
                ..EmitOptions::default()
            };
            write_if_changed(&out.join(format!("{ident}.rs")), &emit(&module, &options)?)?;
            let _ = write!(
                modules,
                "{}",
                adapter(&model, &ident, v.friction, &fixed, &module)?
            );
            let fixed: Vec<String> = fixed
                .iter()
                .map(|(n, x)| format!("(\"{n}\", {x:?})"))
                .collect();
            let _ = writeln!(
                entries,
                "        Variant {{ friction: Friction::{:?}, fixed: &[{}], prepare: {ident}::prepare_kernels }},",
                v.friction,
                fixed.join(", ")
            );
        }
        let _ = write!(
            index,
            "    Compiled {{\n        name: \"{name}\",\n        source: include_str!(\"{}\"),\n        canonical: {:?},\n        variants: &[\n{entries}        ],\n    }},\n",
            path.display(),
            model.canonical()
        );
    }
    index.push_str("];\n");
    let formatted = prettyplease::unparse(&syn::parse_file(&(modules + &index))?);
    write_if_changed(
        &out.join("compiled.rs"),
        &format!(
            "// @generated by walker/build.rs from the shipped model files (walker-gen). Do not edit by hand.\n\n{formatted}"
        ),
    )?;
    Ok(())
}

/// Where a generated call reads its arguments: the fields of an `Args` (`a.q[2]`), or the
/// fused right-hand side's locals (the state array `y`, `sigma`, the auxiliary inputs `v`).
#[derive(Clone, Copy)]
enum Source {
    Args,
    State { n: usize },
}

/// The argument expression of the kernel argument `arg` of `model`, read from `source`.
fn arg_expr(model: &Model, arg: &str, source: Source) -> Result<String, String> {
    if arg == "sigma" {
        return Ok(match source {
            Source::Args => "a.sigma",
            Source::State { .. } => "sigma",
        }
        .to_owned());
    }
    let sym = model
        .symbols()
        .iter()
        .find(|s| s.name == arg)
        .ok_or_else(|| format!("kernel argument `{arg}` is no symbol of `{}`", model.name))?;
    let i = sym.index;
    Ok(match (sym.kind, source) {
        (SymbolKind::Coordinate, Source::Args) => format!("a.q[{i}]"),
        (SymbolKind::Velocity, Source::Args) => format!("a.qd[{i}]"),
        (SymbolKind::Input, Source::Args) => format!("a.u[{i}]"),
        (SymbolKind::Aux, Source::Args) => format!("a.v[{i}]"),
        (SymbolKind::Coordinate, Source::State { .. }) => format!("y[{i}]"),
        (SymbolKind::Velocity, Source::State { n }) => format!("y[{}]", n + i),
        (SymbolKind::Input, Source::State { .. }) => format!("u[{i}]"),
        (SymbolKind::Aux, Source::State { .. }) => format!("v[{i}]"),
        (other, _) => {
            return Err(format!(
                "kernel argument `{arg}`: a {other:?} is not an argument here"
            ));
        }
    })
}

/// The call of kernel `k` of `module` with its arguments read from `source`.
fn call(model: &Model, k: &walker_gen::Kernel, source: Source) -> Result<String, String> {
    let args: Vec<String> = k
        .args
        .iter()
        .map(|a| arg_expr(model, a, source))
        .collect::<Result<_, _>>()?;
    Ok(format!("{}(p, {})", k.name, args.join(", ")))
}

/// The module of one variant and its adapter: `K` implements `Kernels` by calling the
/// generated functions with their arguments taken from `Args`.
fn adapter(
    model: &Model,
    ident: &str,
    friction: Friction,
    fixed: &[(String, f64)],
    module: &walker_gen::Module,
) -> Result<String, String> {
    let mut arms = String::new();
    let mut has = Vec::new();
    let mut stores = std::collections::BTreeMap::new();
    for k in &module.kernels {
        let call = call(model, k, Source::Args)?;
        let id = camel(&k.name);
        has.push(format!("KernelId::{id}"));
        let store = match k.output_shape {
            Shape::Scalar => format!("out[0] = {call};"),
            Shape::Vector(n) => format!("out[..{n}].copy_from_slice(&{call});"),
            Shape::Matrix(r, c) => {
                format!("out[..{}].copy_from_slice({call}.as_flattened());", r * c)
            }
        };
        let _ = writeln!(arms, "            KernelId::{id} => {{ {store} }}");
        stores.insert(k.name.clone(), store);
    }
    let tracking = tracking(&stores, model.inputs.len());
    let stance =
        stance_rhs(model, module)? + &power_sign(model, module)? + &sliding_lambda(model, module)?;
    let fixed: Vec<String> = fixed.iter().map(|(n, x)| format!("{n} = {x}")).collect();
    Ok(format!(
        "/// `models/{model}.toml`, friction `{friction:?}`, fixed: {fixed}.\n\
         #[allow(clippy::all, clippy::pedantic, clippy::suboptimal_flops, missing_docs, reason = \"generated by walker-gen: plain multiply-add keeps the same rounding on every target\")]\n\
         pub mod {ident} {{\n\
         include!(concat!(env!(\"OUT_DIR\"), \"/{ident}.rs\"));\n\
         use crate::model::{{Args, KernelId, Kernels}};\n\
         struct K(Prepared);\n\
         impl Kernels for K {{\n\
         fn has(&self, k: KernelId) -> bool {{ matches!(k, {has}) }}\n\
         #[allow(unreachable_patterns, reason = \"a kernel the variant does not have\")]\n\
         fn eval(&self, k: KernelId, a: &Args<'_>, out: &mut [f64]) {{\n\
         let p = &self.0;\n\
         match k {{\n{arms}            _ => out.fill(f64::NAN),\n        }}\n    }}\n{tracking}{stance}}}\n\
         /// The kernels prepared for the run-time parameters by name.\n\
         pub fn prepare_kernels(value: &dyn Fn(&str) -> f64) -> std::sync::Arc<dyn Kernels> {{\n\
         std::sync::Arc::new(K(prepare(&Params::from_fn(|name| value(name)))))\n\
         }}\n}}\n",
        model = model.name,
        fixed = if fixed.is_empty() {
            "none".to_owned()
        } else {
            fixed.join(", ")
        },
        has = has.join(" | "),
    ))
}

/// The adapter's `Kernels::tracking` for a model with `m > 0` inputs whose variant has the
/// output and input rates and the closed loops (`stores`: each kernel's call storing into
/// `out`): the same arithmetic as the trait's default, without its dispatch between the three
/// calls; empty otherwise (the default).
fn tracking(stores: &std::collections::BTreeMap<String, String>, m: usize) -> String {
    let (Some(rates), Some(w)) = (stores.get("output_rates"), stores.get("input_rates")) else {
        return String::new();
    };
    if m == 0 {
        return String::new();
    }
    let arm = |kernel: &str| {
        stores.get(kernel).map_or_else(String::new, |store| {
            format!("            KernelId::{} => {{ {store} }}\n", camel(kernel))
        })
    };
    format!(
        "fn tracking(&self, k: KernelId, a: &Args<'_>, control: &crate::model::Tracking<'_>, out: &mut [f64], w: &mut [f64]) {{\n\
         let p = &self.0;\n\
         let mut r = [0.0; {two_m}];\n\
         {{ let out = &mut r[..]; {rates} }}\n\
         let mut v = [0.0; {m}];\n\
         for i in 0..{m} {{ v[i] = control.aux_input(i, r[i], r[{m} + i]); }}\n\
         let a = &Args {{ v: &v, ..*a }};\n\
         match k {{\n{cl}{cls}            _ => out.fill(f64::NAN),\n        }}\n\
         {{ let out = w; {w} }}\n\
         }}\n",
        two_m = 2 * m,
        cl = arm("closed_loop"),
        cls = arm("closed_loop_stick"),
    )
}

/// The adapter's `Kernels::stance_rhs`: the stance right-hand side as one function with the
/// arithmetic of the trait's default (the outputs' rates, Eq. 32's `v`, the closed loop or the
/// stuck closed loop, the inputs' rates and the power `sum |u_i w_i|`; without inputs `accel`
/// or `stick`), reading the state as an array, so that no `Args`, slice or dispatch stands
/// between the integrator and the kernels. A kernel the variant lacks gives NaN, as its `eval`
/// arm would; a model with inputs but without their rates keeps the default.
fn stance_rhs(model: &Model, module: &walker_gen::Module) -> Result<String, String> {
    let (n, m) = (model.coordinates.len(), model.inputs.len());
    let source = Source::State { n };
    let kernel = |name: &str| find(module, name);
    // `qdd` (then `u` when `m > 0`) from a kernel whose outputs start with them.
    let split = |name: &str| -> Result<String, String> {
        let Some(k) = kernel(name) else {
            return Ok(if m == 0 {
                format!("[f64::NAN; {n}]")
            } else {
                format!("([f64::NAN; {n}], [f64::NAN; {m}])")
            });
        };
        let value = if m == 0 {
            outputs(0, n)
        } else {
            format!("({}, {})", outputs(0, n), outputs(n, n + m))
        };
        Ok(format!("let o = {}; {value}", call(model, k, source)?))
    };
    let (body, result) = if m == 0 {
        (
            format!(
                "let qdd: [f64; {n}] = if stuck {{ {} }} else {{ {} }};\n",
                split("stick")?,
                split("accel")?
            ),
            "0.0",
        )
    } else {
        let (Some(rates), Some(w)) = (kernel("output_rates"), kernel("input_rates")) else {
            return Ok(String::new());
        };
        (
            format!(
                "{}let w = {};\n\
                 let (qdd, u): ([f64; {n}], [f64; {m}]) = if stuck {{ {} }} else {{ {} }};\n",
                aux_inputs(model, rates, source)?,
                call(model, w, source)?,
                split("closed_loop_stick")?,
                split("closed_loop")?,
            ),
            "crate::model::power(&u, &w)",
        )
    };
    let params = format!(
        "stuck: bool, {}: f64, y: &[f64], {}: &crate::model::Tracking<'_>, dy: &mut [f64]",
        param(&body, "sigma", "sigma"),
        param(&body, "control.", "control"),
    );
    let two_n = 2 * n;
    let body = format!(
        "let dy: &mut [f64; {two_n}] = dy.try_into().expect(\"a derivative of {two_n} numbers\");\n\
         {body}\
         dy[..{n}].copy_from_slice(&y[{n}..]);\n\
         dy[{n}..].copy_from_slice(&qdd);\n\
         {result}"
    );
    Ok(method("stance_rhs", &params, n, &body))
}

/// The adapter's `Kernels::power_sign` for a model with inputs: `prod u_i w_i` from the
/// closed loop (or the stuck one) and the inputs' rates, as one function with the arithmetic
/// of the trait's default. A passive walker, or a variant without these kernels, keeps the
/// default.
fn power_sign(model: &Model, module: &walker_gen::Module) -> Result<String, String> {
    let (n, m) = (model.coordinates.len(), model.inputs.len());
    let source = Source::State { n };
    let kernel = |name: &str| find(module, name);
    let (Some(rates), Some(w)) = (kernel("output_rates"), kernel("input_rates")) else {
        return Ok(String::new());
    };
    if m == 0 {
        return Ok(String::new());
    }
    // `u` from a closed loop's outputs `[qdd, u, ..]`.
    let inputs = |name: &str| -> Result<String, String> {
        let Some(k) = kernel(name) else {
            return Ok(format!("[f64::NAN; {m}]"));
        };
        Ok(format!(
            "let o = {}; {}",
            call(model, k, source)?,
            outputs(n, n + m)
        ))
    };
    let body = format!(
        "{}let w = {};\n\
         let u: [f64; {m}] = if stuck {{ {} }} else {{ {} }};\n\
         w.iter().zip(&u).map(|(wi, ui)| wi * ui).product()",
        aux_inputs(model, rates, source)?,
        call(model, w, source)?,
        inputs("closed_loop_stick")?,
        inputs("closed_loop")?,
    );
    let params = format!(
        "stuck: bool, {}: f64, y: &[f64], control: &crate::model::Tracking<'_>",
        param(&body, "sigma", "sigma"),
    );
    Ok(method("power_sign", &params, n, &body))
}

/// The adapter's `Kernels::sliding_lambda`: `lambda` at the state with the closed loop's
/// inputs of that point (the outputs' rates, Eq. 32's `v`, `closed_loop`, then `lambda`), as
/// one function with the arithmetic of the trait's default; without inputs `lambda` alone. A
/// variant without these kernels keeps the default.
fn sliding_lambda(model: &Model, module: &walker_gen::Module) -> Result<String, String> {
    let (n, m) = (model.coordinates.len(), model.inputs.len());
    let source = Source::State { n };
    let kernel = |name: &str| find(module, name);
    let Some(lambda) = kernel("lambda") else {
        return Ok(String::new());
    };
    let mut body = String::new();
    if m > 0 {
        let (Some(rates), Some(closed_loop)) = (kernel("output_rates"), kernel("closed_loop"))
        else {
            return Ok(String::new());
        };
        body = format!(
            "{}let o = {};\nlet u = {};\n",
            aux_inputs(model, rates, source)?,
            call(model, closed_loop, source)?,
            outputs(n, n + m)
        );
    }
    body.push_str(&call(model, lambda, source)?);
    let params = format!(
        "{}: f64, y: &[f64], {}: &crate::model::Tracking<'_>",
        param(&body, "sigma", "sigma"),
        param(&body, "control.", "control"),
    );
    Ok(method("sliding_lambda", &params, n, &body))
}

/// The outputs' rates `r = [y, ydot]` (the `output_rates` call `rates`) and Eq. 32's auxiliary
/// inputs `v` from them, as generated statements.
fn aux_inputs(model: &Model, rates: &walker_gen::Kernel, source: Source) -> Result<String, String> {
    let m = model.inputs.len();
    Ok(format!(
        "let r = {};\n\
         let mut v = [0.0; {m}];\n\
         for i in 0..{m} {{ v[i] = control.aux_input(i, r[i], r[{m} + i]); }}\n",
        call(model, rates, source)?
    ))
}

/// The kernel of `module` called `name`, if the variant has it.
fn find<'m>(module: &'m walker_gen::Module, name: &str) -> Option<&'m walker_gen::Kernel> {
    module.kernels.iter().find(|k| k.name == name)
}

/// The outputs `o[from..to]` of a kernel call bound to `o`, as an array expression.
fn outputs(from: usize, to: usize) -> String {
    let items: Vec<String> = (from..to).map(|i| format!("o[{i}]")).collect();
    format!("[{}]", items.join(", "))
}

/// A generated `Kernels` method `name(&self, params) -> f64` of a model with `n` coordinates:
/// the prepared parameters as `p`, the state slice `y` read as the array `[q, qd]` of `2n`
/// numbers, then `body`.
fn method(name: &str, params: &str, n: usize, body: &str) -> String {
    let two_n = 2 * n;
    format!(
        "fn {name}(&self, {params}) -> f64 {{\n\
         let p = &self.0;\n\
         let y: &[f64; {two_n}] = y[..{two_n}].try_into().expect(\"a state of {two_n} numbers\");\n\
         {body}\n\
         }}\n"
    )
}

/// The name of the parameter `param` in a generated signature: itself if the body reads it
/// (contains `name`), otherwise `_param` (the smooth law has no `sigma`, a passive walker no
/// control).
fn param(body: &str, name: &str, param: &str) -> String {
    if body.contains(name) {
        param.to_owned()
    } else {
        format!("_{param}")
    }
}

/// `closed_loop_stick` as `ClosedLoopStick`.
fn camel(name: &str) -> String {
    name.split('_')
        .map(|w| {
            let mut c = w.chars();
            c.next()
                .map(|f| f.to_ascii_uppercase().to_string() + c.as_str())
                .unwrap_or_default()
        })
        .collect()
}

/// Writes `text` to `path` unless it already holds these bytes.
fn write_if_changed(path: &Path, text: &str) -> std::io::Result<()> {
    if std::fs::read(path).is_ok_and(|old| old == text.as_bytes()) {
        return Ok(());
    }
    std::fs::write(path, text)
}
