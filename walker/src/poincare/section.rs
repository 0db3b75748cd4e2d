//! The Poincare section's independent coordinates `r` ([`Section`], the model file's
//! `[section]`): the embedding of `r` into the full post-impact state, its tangent, the
//! reduction, and the reduced Jacobian `Pi DP E`.
//!
//! On the section the stance foot is at the origin (`x = z = 0`: the map measures from the new
//! foot) and moves along the floor (`zd = -xd tan phi`); the model file names the free
//! components and gives the others as functions of them and of the parameters (the paper's
//! active walker: `r = (xd, th1d)` with `th1 = -alpha/2`, `th2 = 0`, `th2d = th1d`, the
//! controller's invariant manifold `y = -alpha/2`, `ydot = 0`). Without a `[section]` every
//! other component is free.

use walker_scene::model::{Expr, ModelExpr};

use crate::model::Model;
use crate::sim::SimConfig;
use crate::vector::Vector;

use super::error::MapError;
use super::map::{matmul, poincare_map_along};
use super::result::{JacobianMethod, MapResult, StepCheck};

/// The section of a model: which components of the post-impact state are free, and the values
/// of the others.
#[derive(Clone, Debug)]
pub struct Section<'a> {
    model: &'a Model,
    /// The free components (indices into `[q, qd]`).
    free: Vec<usize>,
    /// The other components with their values.
    given: Vec<(usize, &'a ModelExpr)>,
}

impl<'a> Section<'a> {
    /// The section of `model` (its `[section]`, else every component but `x`, `z`, `zd`
    /// free).
    #[must_use]
    pub fn of(model: &'a Model) -> Section<'a> {
        let n = model.n();
        match &model.spec().model.section {
            Some(s) => Section {
                model,
                free: s.free.clone(),
                given: s.given.iter().map(|(i, e)| (*i, e)).collect(),
            },
            None => Section {
                model,
                free: (2..2 * n).filter(|&i| i != n + 1).collect(),
                given: Vec::new(),
            },
        }
    }

    /// The number of independent coordinates.
    #[must_use]
    pub fn dim(&self) -> usize {
        self.free.len()
    }

    /// The free components, as indices into the state `[q, qd]`.
    #[must_use]
    pub fn free(&self) -> &[usize] {
        &self.free
    }

    /// The names of the free components (`xd`, `th1d`).
    #[must_use]
    pub fn names(&self) -> Vec<String> {
        let names = self.model.spec().state_names();
        self.free.iter().map(|&i| names[i].clone()).collect()
    }

    /// The value of `e` at the parameters and the free components `r`.
    fn eval(&self, e: &Expr, r: &[f64]) -> f64 {
        let names = self.model.spec().state_names();
        let params = self.model.params();
        e.eval(&|name| {
            params.get(name).or_else(|| {
                let i = names.iter().position(|s| s == name)?;
                let k = self.free.iter().position(|&f| f == i)?;
                r.get(k).copied()
            })
        })
        .unwrap_or(f64::NAN)
    }

    /// The state on the section with the independent coordinates `r`.
    #[must_use]
    pub fn embed(&self, r: &[f64]) -> Vector {
        let n = self.model.n();
        let mut s = Vector::zeros(2 * n);
        for (k, &i) in self.free.iter().enumerate() {
            s[i] = r[k];
        }
        for &(i, e) in &self.given {
            s[i] = self.eval(&e.expr, r);
        }
        s[n + 1] = 0.0 - s[n] * self.model.phi().tan();
        s
    }

    /// `d embed(r)_i / d r_j` at `r` (`2n` rows of `dim` columns).
    #[must_use]
    pub fn tangent(&self, r: &[f64]) -> Vec<Vec<f64>> {
        let n = self.model.n();
        let names = self.model.spec().state_names();
        let mut e = vec![vec![0.0; self.dim()]; 2 * n];
        for (k, &i) in self.free.iter().enumerate() {
            e[i][k] = 1.0;
        }
        for &(i, expr) in &self.given {
            for (k, &f) in self.free.iter().enumerate() {
                e[i][k] = self.eval(&expr.expr.derivative(&names[f]), r);
            }
        }
        let tphi = self.model.phi().tan();
        let (xd, rest) = e[n..].split_at_mut(1);
        for (zd, xd) in rest[0].iter_mut().zip(&xd[0]) {
            *zd = 0.0 - xd * tphi;
        }
        e
    }

    /// `d embed(r) / dp` at fixed `r` for the parameter `name` (`2n` numbers): the rates of
    /// the given components whose expressions use it (the active walker's `th1 = -alpha/2` in
    /// `alpha`); zero for the free ones. The slope's part `zd = -xd tan phi` is not
    /// differentiated: a parameter in the mechanics has no exact column
    /// ([`super::parameter_column`]).
    #[must_use]
    pub fn rate(&self, r: &[f64], name: &str) -> Vector {
        let mut s = Vector::zeros(2 * self.model.n());
        for &(i, e) in &self.given {
            s[i] = self.eval(&e.expr.derivative(name), r);
        }
        s
    }

    /// The independent coordinates of a post-impact state.
    #[must_use]
    pub fn reduce(&self, s: &[f64]) -> Vec<f64> {
        self.free.iter().map(|&i| s[i]).collect()
    }

    /// The map at the section point `r` with its Jacobian along the section, `DP E` (`2n x
    /// dim`: [`super::poincare_map_along`] with the tangent `E`, by the variational equations
    /// where the model's kernels allow): what the reduced Jacobian needs
    /// ([`Section::reduced`]), for the cost of `dim` sensitivity columns instead of `2n`.
    ///
    /// # Errors
    /// [`MapError`]: the step could not be taken.
    pub fn map(&self, cfg: &SimConfig, r: &[f64]) -> Result<MapResult, MapError> {
        self.map_with(cfg, r, JacobianMethod::Variational, StepCheck::Through)
    }

    /// [`Section::map`] by `method`, checked against the simulator's step where `step_check`
    /// says.
    ///
    /// # Errors
    /// [`MapError`]: the step could not be taken.
    pub fn map_with(
        &self,
        cfg: &SimConfig,
        r: &[f64],
        method: JacobianMethod,
        step_check: StepCheck,
    ) -> Result<MapResult, MapError> {
        let (s, e) = (self.embed(r), self.tangent(r));
        poincare_map_along(self.model, cfg, &s, &e, method, step_check)
    }

    /// The reduced map's Jacobian `Pi DP E` from the map's Jacobian along the section `DP E`
    /// ([`Section::map`]): its rows of the free components.
    #[must_use]
    pub fn reduced(&self, along: &[Vec<f64>]) -> Vec<Vec<f64>> {
        self.free.iter().map(|&row| along[row].clone()).collect()
    }

    /// The reduced map's Jacobian `Pi DP E` from the full one (`2n x 2n`, row by row) at `r`.
    #[must_use]
    pub fn reduced_jacobian(&self, full: &[Vec<f64>], r: &[f64]) -> Vec<Vec<f64>> {
        self.reduced(&matmul(full, &self.tangent(r)))
    }
}
