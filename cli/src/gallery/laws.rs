//! The contact laws the gallery sweeps under: the friction law of the stance foot (the paper's
//! tanh law, Eq. 26, or exact Coulomb friction with stick-slip) and the impact law at the heel
//! strike (the paper's frictionless impact, or the plastic impact with Coulomb friction of
//! `docs/impacts.md`).

use walker::model::{Friction, ImpactLaw, Model};
use walker::setup::Setup;

/// A friction law in stance and an impact law.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Laws {
    /// The stance foot's friction law.
    pub friction: Friction,
    /// The impact law.
    pub impact: ImpactLaw,
}

/// The four combinations, the paper's first and the exact one (Coulomb friction in stance and
/// at the impact) last.
pub const LAWS: [Laws; 4] = [
    Laws {
        friction: Friction::Tanh,
        impact: ImpactLaw::Frictionless,
    },
    Laws {
        friction: Friction::Coulomb,
        impact: ImpactLaw::Frictionless,
    },
    Laws {
        friction: Friction::Tanh,
        impact: ImpactLaw::Coulomb,
    },
    Laws {
        friction: Friction::Coulomb,
        impact: ImpactLaw::Coulomb,
    },
];

/// The exact laws: Coulomb friction in stance and at the impact.
pub const EXACT: Laws = LAWS[3];

impl Laws {
    /// A short label for legends and panel titles (`tanh stance, frictionless impact`).
    #[must_use]
    pub fn label(&self) -> String {
        let stance = match self.friction {
            Friction::Tanh => "tanh",
            Friction::Coulomb => "Coulomb",
            Friction::None => "no friction",
        };
        let impact = match self.impact {
            ImpactLaw::Frictionless => "frictionless",
            ImpactLaw::Coulomb => "Coulomb",
        };
        format!("{stance} stance, {impact} impact")
    }

    /// The laws as the CSV files and the CLI's flags name them (`tanh`, `frictionless`).
    #[must_use]
    pub fn names(&self) -> (String, String) {
        (self.friction.to_string(), self.impact.to_string())
    }
}

impl Laws {
    /// The model of `setup` under these laws on the slope `phi` (NaN: the model's own floor) at
    /// the friction coefficient `mu0`.
    ///
    /// # Errors
    /// A value out of its parameter's range, or kernels that cannot be prepared (the message).
    pub fn model(&self, setup: &Setup, phi: f64, mu0: f64) -> Result<Model, String> {
        let mut s = setup.clone();
        s.friction = self.friction;
        s.impact = self.impact;
        let spec = s.walker.spec().clone();
        let name = |i: usize| spec.model.parameters[i].name.name.clone();
        if let (Some(i), false) = (spec.slope, phi.is_nan()) {
            s.set(&name(i), phi).map_err(|e| e.to_string())?;
        }
        if let Some(i) = spec.mu0 {
            s.set(&name(i), mu0).map_err(|e| e.to_string())?;
        }
        s.model().map_err(|e| e.to_string())
    }
}
