//! A [`Walker`]: a model file ([`Spec`]) and where its kernels come from ([`KernelSource`]):
//! variants compiled at build time ([`Compiled`], this library's or a user crate's), or an
//! implementation given at run time (the `walker-load` crate derives a model file and evaluates its kernels).
//! [`Walker::model`] prepares the kernels for a set of parameters: a [`Model`] to simulate.

use std::sync::Arc;

use walker_scene::{Friction, ImpactLaw};

use walker_contract::{Compiled, KernelId, Kernels, Variant};

use super::contact::FrictionLaw;
use super::parameters::Parameters;
use super::prepared::Model;
use super::spec::Spec;

/// Why a model's kernels cannot be prepared.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum NoKernels {
    /// The model file does not list the friction law.
    #[error("model `{model}` does not list the friction law `{law}`; it lists {listed}")]
    FrictionLaw {
        /// The model.
        model: String,
        /// The law asked for.
        law: Friction,
        /// The laws the model lists.
        listed: String,
    },
    /// No compiled variant has this friction law with these parameters (a variant fixes some
    /// parameters at generation).
    #[error(
        "no kernels of model `{model}` are compiled for the friction law `{law}` with these \
         parameters; {hint}"
    )]
    NotCompiled {
        /// The model.
        model: String,
        /// The law asked for.
        law: Friction,
        /// What would work.
        hint: String,
    },
    /// The kernels lack one the friction or impact law needs (a source generated without it).
    #[error("the kernels of model `{model}` have no `{kernel}`, which {why} needs")]
    Missing {
        /// The model.
        model: String,
        /// The missing kernel.
        kernel: &'static str,
        /// What needs it.
        why: &'static str,
    },
    /// A run-time source failed (its own message).
    #[error("model `{model}`: {message}")]
    Source {
        /// The model.
        model: String,
        /// What went wrong.
        message: String,
    },
}

/// Where a model's kernels come from.
pub trait KernelSource: Send + Sync {
    /// The kernels for the friction law `law` (`Tanh` or `Coulomb`; the simulator runs `None`
    /// as `Tanh` with `mu0 = 0`), prepared for `params`.
    ///
    /// # Errors
    /// [`NoKernels`] when this source has no such kernels.
    fn prepare(&self, law: Friction, params: &Parameters) -> Result<Arc<dyn Kernels>, NoKernels>;
}

impl KernelSource for Compiled {
    /// The first variant with the friction law `law` whose every fixed parameter has exactly
    /// the value of `params`.
    fn prepare(&self, law: Friction, params: &Parameters) -> Result<Arc<dyn Kernels>, NoKernels> {
        let fits = |v: &&Variant| {
            v.friction == law
                && v.fixed
                    .iter()
                    .all(|(name, value)| params.get(name).is_some_and(|p| p == *value))
        };
        let Some(v) = self.variants.iter().find(fits) else {
            let laws: Vec<String> = self
                .variants
                .iter()
                .filter(|v| v.friction == law)
                .map(|v| {
                    let fixed: Vec<String> =
                        v.fixed.iter().map(|(n, x)| format!("{n} = {x}")).collect();
                    if fixed.is_empty() {
                        "every parameter at run time".to_owned()
                    } else {
                        fixed.join(", ")
                    }
                })
                .collect();
            return Err(NoKernels::NotCompiled {
                model: self.name.to_owned(),
                law,
                hint: if laws.is_empty() {
                    "compiled laws: ".to_owned()
                        + &self
                            .variants
                            .iter()
                            .map(|v| v.friction.to_string())
                            .collect::<Vec<_>>()
                            .join(", ")
                } else {
                    format!("compiled with {}", laws.join("; "))
                },
            });
        };
        let values = params.values();
        let spec = params.spec();
        let by_name = |name: &str| spec.parameter(name).map_or(f64::NAN, |i| values[i]);
        Ok((v.prepare)(&by_name))
    }
}

/// A walker: a model file and where its kernels come from.
#[derive(Clone)]
pub struct Walker {
    spec: Arc<Spec>,
    source: Arc<dyn KernelSource>,
}

impl std::fmt::Debug for Walker {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Walker")
            .field("model", &self.spec.name())
            .finish_non_exhaustive()
    }
}

impl Walker {
    /// The walker of `spec` with kernels from `source`.
    #[must_use]
    pub fn new(spec: Arc<Spec>, source: Arc<dyn KernelSource>) -> Walker {
        Walker { spec, source }
    }

    /// The model file.
    #[must_use]
    pub fn spec(&self) -> &Arc<Spec> {
        &self.spec
    }

    /// Every parameter at its default.
    #[must_use]
    pub fn defaults(&self) -> Parameters {
        Parameters::defaults(&self.spec)
    }

    /// The model with the friction law `friction` and the impact law `impact`, its kernels
    /// prepared for `params` (`Friction::None` runs the tanh kernels with `mu0 = 0`).
    ///
    /// # Errors
    /// The model does not list `friction`, or its source has no such kernels.
    pub fn model(
        &self,
        params: &Parameters,
        friction: Friction,
        impact: ImpactLaw,
    ) -> Result<Model, NoKernels> {
        if !self.spec.has_friction(friction) {
            return Err(NoKernels::FrictionLaw {
                model: self.spec.name().to_owned(),
                law: friction,
                listed: self
                    .spec
                    .model
                    .stance
                    .friction
                    .iter()
                    .map(ToString::to_string)
                    .collect::<Vec<_>>()
                    .join(", "),
            });
        }
        let (law, kernel_law, params) = match friction {
            Friction::Coulomb => (FrictionLaw::Coulomb, Friction::Coulomb, params.clone()),
            Friction::Tanh => (FrictionLaw::Tanh, Friction::Tanh, params.clone()),
            Friction::None if self.spec.mu0.is_none() => {
                (FrictionLaw::Tanh, Friction::None, params.clone())
            }
            Friction::None => {
                let mut p = params.clone();
                if let Some(i) = self.spec.mu0 {
                    let name = self.spec.model.parameters[i].name.name.clone();
                    // A range that refuses zero cannot describe a frictionless floor.
                    p.set(&name, 0.0).map_err(|e| NoKernels::Source {
                        model: self.spec.name().to_owned(),
                        message: e.to_string(),
                    })?;
                }
                (FrictionLaw::Tanh, Friction::Tanh, p)
            }
        };
        let kernels = self.source.prepare(kernel_law, &params)?;
        for (kernel, why) in self.required(friction, impact) {
            if !kernels.has(kernel) {
                return Err(NoKernels::Missing {
                    model: self.spec.name().to_owned(),
                    kernel: kernel.name(),
                    why,
                });
            }
        }
        Ok(Model::new(params, kernels, law).with_impact_law(impact))
    }

    /// The kernels a walk under `friction` and `impact` evaluates, each with what needs it
    /// (the Jacobians are optional: without them the Poincare map differentiates numerically).
    fn required(&self, friction: Friction, impact: ImpactLaw) -> Vec<(KernelId, &'static str)> {
        let spec = &self.spec;
        let mut need = vec![
            (KernelId::Lambda, "the stance"),
            (KernelId::Events, "the strike and the falls"),
            (KernelId::Impact, "the impact"),
            (KernelId::Relabel, "the impact"),
        ];
        if spec.is_actuated() {
            need.push((KernelId::ClosedLoop, "the controlled stance"));
            need.push((KernelId::InputRates, "the input power"));
        } else {
            need.push((KernelId::Accel, "the stance"));
        }
        if friction == Friction::Coulomb {
            need.push((KernelId::Stick, "Coulomb friction's stick phase"));
            if spec.is_actuated() {
                need.push((KernelId::ClosedLoopStick, "Coulomb friction's stick phase"));
            }
        }
        if impact == ImpactLaw::Coulomb {
            need.push((KernelId::ImpactCoulomb, "the impact with Coulomb friction"));
        }
        if spec.double_support() {
            need.push((KernelId::ImpactDouble, "the double-support test"));
        }
        need
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::panic, reason = "tests")]
mod tests {
    use super::*;
    use crate::model::Args;
    use crate::setup::Setup;

    /// A source whose kernels lack `hidden`.
    struct Without(Arc<dyn KernelSource>, KernelId);

    struct Hidden(Arc<dyn Kernels>, KernelId);

    impl Kernels for Hidden {
        fn has(&self, k: KernelId) -> bool {
            k != self.1 && self.0.has(k)
        }
        fn eval(&self, k: KernelId, args: &Args<'_>, out: &mut [f64]) {
            self.0.eval(k, args, out);
        }
    }

    impl KernelSource for Without {
        fn prepare(&self, law: Friction, p: &Parameters) -> Result<Arc<dyn Kernels>, NoKernels> {
            Ok(Arc::new(Hidden(self.0.prepare(law, p)?, self.1)))
        }
    }

    #[test]
    fn a_law_whose_kernel_is_missing_is_refused_by_name() {
        let setup = Setup::active_level().unwrap();
        let w = &setup.walker;
        let params = setup.params.clone();
        for (hidden, friction, impact) in [
            (KernelId::ImpactCoulomb, Friction::Tanh, ImpactLaw::Coulomb),
            (
                KernelId::ClosedLoopStick,
                Friction::Coulomb,
                ImpactLaw::Frictionless,
            ),
            (KernelId::Stick, Friction::Coulomb, ImpactLaw::Frictionless),
        ] {
            let without = Walker::new(
                w.spec().clone(),
                Arc::new(Without(w.source.clone(), hidden)),
            );
            // With the kernel the model prepares; without it the error names the kernel.
            assert!(w.model(&params, friction, impact).is_ok());
            match without.model(&params, friction, impact) {
                Err(NoKernels::Missing { kernel, .. }) => assert_eq!(kernel, hidden.name()),
                other => panic!("{hidden:?}: {:?}", other.map(|_| ())),
            }
        }
        // Stick is not needed by the tanh law.
        let without = Walker::new(
            w.spec().clone(),
            Arc::new(Without(w.source.clone(), KernelId::Stick)),
        );
        assert!(
            without
                .model(&params, Friction::Tanh, ImpactLaw::Frictionless)
                .is_ok()
        );
    }
}
