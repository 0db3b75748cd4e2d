//! A model file as a scene: the model's kernels (derived by `walker-symbolic` from any model file,
//! `docs/model-format.md`) lowered with the parameters a user fixes and the friction law they
//! choose, through the same lowering as the paper's scenes.
//!
//! A parameter is a runtime field of `Params` unless it is fixed (`--fix name=value`) or the model
//! declares it `stage = "generation"` (then its default is substituted unless fixed otherwise).

use std::collections::BTreeMap;

use walker_scene::Friction;
use walker_scene::model::{Model, Stage};
use walker_symbolic::model::ModelDerivation;

use crate::error::Error;
use crate::ir::Module;
use crate::lower::{Binding, FrictionBinding, Lowering};

/// A model and the choices that make it a scene.
#[derive(Clone, Debug)]
pub struct ModelScene {
    /// The model.
    pub model: Model,
    /// Parameters substituted at generation, by name.
    pub fixed: BTreeMap<String, f64>,
    /// The friction law of the stance foot (one the model lists).
    pub friction: Friction,
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
        let friction = model
            .stance
            .friction
            .iter()
            .copied()
            .find(|f| *f != Friction::None)
            .unwrap_or(Friction::None);
        ModelScene {
            model,
            fixed: BTreeMap::new(),
            friction,
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
    let mut module = Module::new(&model.name);
    let symbols = &derivation.symbols;
    let sym = |name: &str| {
        symbols
            .lookup(name)
            .map_err(|e| invalid(name, e.to_string()))
    };
    let mut binding = Binding {
        symbols,
        params: BTreeMap::new(),
        fixed: BTreeMap::new(),
        zero: Vec::new(),
        friction: None,
    };
    for p in &model.parameters {
        let s = sym(&p.name.name)?;
        let node = match scene.fixed_value(&p.name.name) {
            Some(v) => {
                binding.fixed.insert(s, v);
                module.graph.constant(v)
            }
            None => {
                let doc = format!("{} `{}` ({}).", capitalised(&p.doc), p.name.name, p.unit);
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
    for k in &derivation.kernels {
        let lowered = Lowering {
            binding: &binding,
            kernel: k.name,
        }
        .kernel(&mut module.graph, k)?;
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
