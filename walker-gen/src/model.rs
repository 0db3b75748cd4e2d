//! A model file as a scene: the model's kernels (derived by `walker-symbolic` from any model file,
//! `docs/model-format.md`) lowered with the parameters a user fixes and the friction law they
//! choose, through the same lowering as the paper's scenes.
//!
//! A parameter is a runtime field of `Params` unless it is fixed (`--fix name=value`) or the model
//! declares it `stage = "generation"` (then its default is substituted unless fixed otherwise).

use std::collections::BTreeMap;

use walker_scene::Friction;
use walker_scene::model::{Model, Stage};
pub use walker_symbolic::model::ModelDerivation;

use crate::error::Error;
use crate::ir::Module;
use crate::lower::{Binding, Form, FrictionBinding, Lowering};

/// A model and the choices that make it a scene.
#[derive(Clone, Debug)]
pub struct ModelScene {
    /// The model.
    pub model: Model,
    /// Parameters substituted at generation, by name.
    pub fixed: BTreeMap<String, f64>,
    /// The friction law of the stance foot (one the model lists).
    pub friction: Friction,
    /// The kernels to generate, by name (`None`: every kernel of the model).
    pub kernels: Option<Vec<String>>,
    /// The generated module's name (`None`: the model's name).
    pub name: Option<String>,
}

fn invalid(field: &str, message: String) -> Error {
    Error::Lower {
        kernel: format!("(model: {field})"),
        message,
    }
}

impl ModelScene {
    /// The model with nothing fixed beyond its generation-stage parameters, and its first
    /// friction law other than `none` (or `none`).
    pub fn new(model: Model) -> ModelScene {
        let friction = model.stance.default_friction();
        ModelScene {
            model,
            fixed: BTreeMap::new(),
            friction,
            kernels: None,
            name: None,
        }
    }

    /// Checks the choices against the model: every fixed name is a parameter and its value in
    /// the parameter's range; the friction law is one the model lists.
    ///
    /// # Errors
    /// [`Error::Lower`] naming the parameter or `friction`, and the valid values.
    pub fn validate(&self) -> Result<(), Error> {
        for (name, v) in &self.fixed {
            let Some(p) = self.model.parameters.iter().find(|p| &p.name.name == name) else {
                let known: Vec<&str> = self
                    .model
                    .parameters
                    .iter()
                    .map(|p| p.name.name.as_str())
                    .collect();
                return Err(invalid(
                    name,
                    format!(
                        "`{name}` is not a parameter of the model; its parameters: {}",
                        known.join(", ")
                    ),
                ));
            };
            if !p.range.contains(*v) {
                return Err(invalid(
                    name,
                    format!("{name} = {v} is outside its valid range {}", p.range),
                ));
            }
        }
        if !self.model.stance.friction.contains(&self.friction) {
            return Err(invalid(
                "friction",
                format!(
                    "the model does not list the friction law `{}`; it lists {:?}",
                    friction_name(self.friction),
                    self.model
                        .stance
                        .friction
                        .iter()
                        .map(|f| friction_name(*f))
                        .collect::<Vec<_>>()
                ),
            ));
        }
        Ok(())
    }

    /// The value a parameter is fixed at, if any: fixed by the scene, else the default of a
    /// generation-stage parameter.
    pub fn fixed_value(&self, name: &str) -> Option<f64> {
        self.fixed.get(name).copied().or_else(|| {
            self.model
                .parameters
                .iter()
                .find(|p| p.name.name == name && p.stage == Stage::Generation)
                .map(|p| p.default)
        })
    }
}

/// Lowers every kernel of `derivation` (derived from `scene.model`) into one [`Module`] named
/// after the model.
///
/// # Errors
/// Invalid choices ([`ModelScene::validate`]), or a kernel that cannot be lowered.
pub fn lower_model(derivation: &ModelDerivation, scene: &ModelScene) -> Result<Module, Error> {
    scene.validate()?;
    let model = &scene.model;
    let mut module = Module::new(scene.name.as_deref().unwrap_or(&model.name));
    if let Some(wanted) = &scene.kernels {
        for name in wanted {
            if derivation.kernels.iter().all(|k| k.name != name) {
                let known: Vec<&str> = derivation.kernels.iter().map(|k| k.name).collect();
                return Err(invalid(
                    "kernels",
                    format!(
                        "`{name}` is not a kernel of the model; its kernels: {}",
                        known.join(", ")
                    ),
                ));
            }
        }
    }
    let symbols = &derivation.symbols;
    let sym = |name: &str| {
        symbols
            .lookup(name)
            .map_err(|e| invalid(name, e.to_string()))
    };
    let mut binding = Binding::new(symbols);
    // Parameters of the start are in no kernel: no field of `Params`.
    for p in model.parameters.iter().filter(|p| p.stage != Stage::Start) {
        let s = sym(&p.name.name)?;
        let node = match scene.fixed_value(&p.name.name) {
            Some(v) => {
                binding.fixed.insert(s, v);
                module.graph.constant(v)
            }
            None => {
                let doc = format!(
                    "{} `{}` ({}).",
                    capitalised(&code_words(&p.doc)),
                    p.name.name,
                    p.unit
                );
                module.param(&p.name.name, &doc)
            }
        };
        binding.params.insert(s, node);
    }
    let syms = &derivation.syms;
    match scene.friction {
        Friction::None => binding.zero.push(syms.mu),
        law => {
            let stance = &model.stance;
            let mu0 = stance
                .mu0
                .as_ref()
                .ok_or_else(|| invalid("stance.mu0", "the friction law needs `mu0`".into()))?;
            let slope = match &model.floor.slope {
                None => None,
                Some(name) => match sym(&name.name)?.base_angle() {
                    Some((b, 1)) => Some(b),
                    _ => {
                        return Err(invalid(
                            "floor.slope",
                            "the slope angle must appear whole (base-angle divisor 1)".into(),
                        ));
                    }
                },
            };
            binding.friction = Some(FrictionBinding {
                mu: syms.mu,
                law,
                velocity: symbols.name(syms.qd[0]).to_owned(),
                mu0: sym(&mu0.name)?,
                c: stance.c.as_ref().map(|c| sym(&c.name)).transpose()?,
                slope,
            });
        }
    }
    let selected = derivation.kernels.iter().filter(|k| {
        scene
            .kernels
            .as_ref()
            .is_none_or(|wanted| wanted.iter().any(|w| w == k.name))
    });
    for k in selected {
        let lowering = Lowering {
            binding: &binding,
            kernel: k.name,
        };
        let form = if k.closed
            && k.solve.is_some()
            && walker_contract::KernelId::from_name(k.name)
                .is_some_and(walker_contract::KernelId::once_per_step)
        {
            let solve = kernel_cost(&module, &lowering, k, Form::Solve)?.ops;
            module.forms.insert(
                k.name.to_owned(),
                format!(
                    "{}, once per step ({}: {solve} ops)",
                    Form::Closed.name(),
                    Form::Solve.name()
                ),
            );
            Form::Closed
        } else if k.closed && k.solve.is_some() {
            let closed = kernel_cost(&module, &lowering, k, Form::Closed)?;
            let solve = kernel_cost(&module, &lowering, k, Form::Solve)?;
            let (form, other, chosen, cost) = if solve.time() < closed.time() {
                (Form::Solve, Form::Closed, solve, closed)
            } else {
                (Form::Closed, Form::Solve, closed, solve)
            };
            module.forms.insert(
                k.name.to_owned(),
                format!(
                    "{}, {} cycles ({}: {} ops, {} cycles)",
                    form.name(),
                    chosen.path,
                    other.name(),
                    cost.ops,
                    cost.path
                ),
            );
            form
        } else if k.closed {
            Form::Closed
        } else {
            module.forms.insert(
                k.name.to_owned(),
                format!("{} (no closed form)", Form::Solve.name()),
            );
            Form::Solve
        };
        let lowered = lowering.kernel_form(&mut module.graph, k, form)?;
        module.kernels.push(lowered);
    }
    module.notes.insert(
        0,
        format!(
            "model: {} ({})",
            model.name,
            model.title.as_deref().unwrap_or("")
        ),
    );
    module
        .notes
        .insert(1, format!("friction: {}", friction_name(scene.friction)));
    let fixed: Vec<String> = binding
        .fixed
        .iter()
        .map(|(s, v)| format!("{} = {v}", symbols.name(*s)))
        .collect();
    module.notes.insert(
        2,
        if fixed.is_empty() {
            "fixed: none".to_owned()
        } else {
            format!("fixed: {}", fixed.join(", "))
        },
    );
    Ok(module)
}

/// What a call of a kernel costs: its operations and its critical path.
#[derive(Clone, Copy, Debug)]
struct Cost {
    /// Operations per call (after CSE and hoisting, as `walker-gen stats` counts them).
    ops: usize,
    /// The latency of its longest chain of dependent operations, in cycles
    /// ([`crate::stats::critical_path`]).
    path: usize,
}

impl Cost {
    /// The estimated time of a call in cycles, for choosing between forms, and the operation
    /// count to break ties: the critical path plus half the operation count (two
    /// floating-point pipes), as if the chain and the rest did not overlap. Neither part alone
    /// chooses well. The operation count alone took the paper's passive walker's `accel` as a
    /// structured solve (64 operations against 82) whose two dependent divisions make its
    /// critical path 124 cycles against 94: a long walk ran 11 % slower than with the closed
    /// form. The critical path alone, or the larger of the two, took the compass gait's `stick`
    /// as a closed form (94 cycles against 114, but 179 operations against 63): its walk ran
    /// 21 % slower than with the structured solve (`BENCHMARKS.md`, section 8).
    fn time(self) -> (usize, usize) {
        (self.path + self.ops.div_ceil(2), self.ops)
    }
}

/// The cost of a call of `k` lowered in `form` into a copy of `module`.
fn kernel_cost(
    module: &Module,
    lowering: &Lowering,
    k: &walker_symbolic::Kernel,
    form: Form,
) -> Result<Cost, Error> {
    let mut trial = module.clone();
    let lowered = lowering.kernel_form(&mut trial.graph, k, form)?;
    trial.kernels.push(lowered);
    let plan = crate::plan::Plan::new(&trial, crate::options::EmitOptions::default().division)?;
    let stats = crate::stats::from_plan(&trial, &plan);
    Ok(Cost {
        ops: stats.kernels.last().map_or(0, |s| s.ops.total()),
        path: crate::stats::critical_path(&plan, trial.kernels.len() - 1),
    })
}

/// A model file's prose for a doc comment: each word with an underscore (a name, as `y_d`) set
/// in backticks unless the text already quotes it, so that the generated docs render as code
/// and pass clippy's `doc_markdown`.
fn code_words(text: &str) -> String {
    text.split(' ')
        .map(|word| {
            let start = word.find(|c: char| c.is_ascii_alphanumeric() || c == '_');
            let end = word.rfind(|c: char| c.is_ascii_alphanumeric() || c == '_');
            match (start, end) {
                (Some(a), Some(b)) if !word.contains('`') && word[a..=b].contains('_') => {
                    format!("{}`{}`{}", &word[..a], &word[a..=b], &word[b + 1..])
                }
                _ => word.to_owned(),
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

fn capitalised(s: &str) -> String {
    let mut c = s.chars();
    c.next()
        .map(|f| f.to_uppercase().chain(c).collect())
        .unwrap_or_default()
}

/// The friction law's name in model and scene files.
pub fn friction_name(f: Friction) -> &'static str {
    match f {
        Friction::None => "none",
        Friction::Tanh => "tanh",
        Friction::Coulomb => "coulomb",
    }
}

/// Derives a model's kernels once (every variant of it is lowered from this), [`Error::Lower`]
/// naming `(derivation)` if it fails.
///
/// # Errors
/// The derivation fails (a singular mass matrix, an output whose `A` is singular, ...).
pub fn derive_model(model: &Model) -> Result<ModelDerivation, Error> {
    ModelDerivation::new(model).map_err(|e| Error::Lower {
        kernel: "(derivation)".to_owned(),
        message: e.to_string(),
    })
}
