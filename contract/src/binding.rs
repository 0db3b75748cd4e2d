//! The argument binding: where each argument of a generated kernel comes from. A generated
//! kernel takes its arguments by name (`kernel(p, th1, th1d, ..)`, in the order the derivation
//! lists them); [`Binding::of`] says which number of a kernel call ([`Args`]) each name is:
//! the generator writes its adapter with it, the run-time tape reads its arguments with it, so
//! the two cannot disagree.

use walker_scene::model::{Model, SymbolKind};

use crate::args::Args;

/// The name of the sliding direction's argument (`mu = -mu0 sigma` under exact Coulomb
/// friction); reserved in model files (`walker_scene::model::reserved`).
pub const SIGMA: &str = "sigma";

/// Which number of a kernel call an argument is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Binding {
    /// The coordinate `q[i]`.
    Coordinate(usize),
    /// The velocity `qd[i]`.
    Velocity(usize),
    /// The input `u[i]`.
    Input(usize),
    /// The auxiliary input `v[i]` of output `i` (Eq. 32).
    Aux(usize),
    /// The sliding direction `sigma`.
    Sigma,
}

/// An argument name that is no argument a kernel call can give.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum BindError {
    /// The name is no symbol of the model.
    #[error("kernel argument `{arg}` is no symbol of model `{model}`")]
    Unknown {
        /// The argument.
        arg: String,
        /// The model.
        model: String,
    },
    /// The symbol is of a kind no kernel call gives (a parameter, an acceleration, `t`).
    #[error("kernel argument `{arg}` of model `{model}` is {kind}, not an argument of a call")]
    NotAnArgument {
        /// The argument.
        arg: String,
        /// The model.
        model: String,
        /// Its kind, in words.
        kind: &'static str,
    },
}

impl Binding {
    /// The binding of the kernel argument `arg` of `model`.
    ///
    /// # Errors
    /// [`BindError`] when `arg` is no coordinate, velocity, input, auxiliary input or `sigma`.
    pub fn of(model: &Model, arg: &str) -> Result<Binding, BindError> {
        if arg == SIGMA {
            return Ok(Binding::Sigma);
        }
        let sym = model
            .symbols()
            .iter()
            .find(|s| s.name == arg)
            .ok_or_else(|| BindError::Unknown {
                arg: arg.to_owned(),
                model: model.name.clone(),
            })?;
        let i = sym.index;
        Ok(match sym.kind {
            SymbolKind::Coordinate => Binding::Coordinate(i),
            SymbolKind::Velocity => Binding::Velocity(i),
            SymbolKind::Input => Binding::Input(i),
            SymbolKind::Aux => Binding::Aux(i),
            other => {
                return Err(BindError::NotAnArgument {
                    arg: arg.to_owned(),
                    model: model.name.clone(),
                    kind: other.describe(),
                });
            }
        })
    }

    /// The bindings of the arguments `args` of one kernel of `model`, in order.
    ///
    /// # Errors
    /// The first argument [`Binding::of`] refuses.
    pub fn all<S: AsRef<str>>(model: &Model, args: &[S]) -> Result<Vec<Binding>, BindError> {
        args.iter()
            .map(|a| Binding::of(model, a.as_ref()))
            .collect()
    }

    /// The argument's value in the call `a` (NaN where the call does not give it: an input
    /// of a call made without inputs).
    #[inline]
    #[must_use]
    pub fn read(self, a: &Args<'_>) -> f64 {
        let get = |v: &[f64], i: usize| v.get(i).copied().unwrap_or(f64::NAN);
        match self {
            Binding::Coordinate(i) => get(a.q, i),
            Binding::Velocity(i) => get(a.qd, i),
            Binding::Input(i) => get(a.u, i),
            Binding::Aux(i) => get(a.v, i),
            Binding::Sigma => a.sigma,
        }
    }
}
