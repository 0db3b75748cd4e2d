//! [`Parameters`]: the values of a model's parameters by name, each checked against the valid
//! range its model file declares (the one place a parameter's range is written).

use std::sync::Arc;

use super::spec::Spec;

/// Why a parameter value is refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ParamError {
    /// No parameter of the model has this name.
    #[error(
        "`{}` is not a parameter of model `{model}`; its parameters: {known}",
        crate::request::shown::name(name)
    )]
    Unknown {
        /// The name given.
        name: String,
        /// The model.
        model: String,
        /// The model's parameters, comma-separated.
        known: String,
    },
    /// A value outside the parameter's valid range.
    #[error("{name} = {value} is outside its valid range {range}")]
    OutOfRange {
        /// The parameter.
        name: String,
        /// The value given.
        value: f64,
        /// The valid range, as the model file writes it (`(0, inf)`).
        range: String,
    },
}

impl ParamError {
    /// The parameter the error is about.
    #[must_use]
    pub fn name(&self) -> &str {
        match self {
            ParamError::Unknown { name, .. } | ParamError::OutOfRange { name, .. } => name,
        }
    }
}

/// The values of every parameter of one model (its defaults until set), in file order.
#[derive(Clone, Debug)]
pub struct Parameters {
    spec: Arc<Spec>,
    values: Vec<f64>,
}

impl PartialEq for Parameters {
    fn eq(&self, other: &Parameters) -> bool {
        Arc::ptr_eq(&self.spec, &other.spec) && self.values == other.values
    }
}

impl Parameters {
    /// Every parameter of `spec` at its default.
    #[must_use]
    pub fn defaults(spec: &Arc<Spec>) -> Parameters {
        Parameters {
            spec: Arc::clone(spec),
            values: spec.model.parameters.iter().map(|p| p.default).collect(),
        }
    }

    /// The model they belong to.
    #[must_use]
    pub fn spec(&self) -> &Arc<Spec> {
        &self.spec
    }

    /// The values, in the model file's order.
    #[must_use]
    pub fn values(&self) -> &[f64] {
        &self.values
    }

    /// The value of the parameter called `name`.
    #[must_use]
    pub fn get(&self, name: &str) -> Option<f64> {
        self.spec.parameter(name).map(|i| self.values[i])
    }

    /// The value of the parameter at `index` (NaN if there is none).
    #[must_use]
    pub fn at(&self, index: usize) -> f64 {
        self.values.get(index).copied().unwrap_or(f64::NAN)
    }

    /// The value of the parameter at `index`, if `index` is one.
    #[must_use]
    pub fn at_opt(&self, index: Option<usize>) -> Option<f64> {
        index.map(|i| self.at(i))
    }

    /// Sets the parameter called `name` to `value`, checked against its range.
    ///
    /// # Errors
    /// [`ParamError::Unknown`] or [`ParamError::OutOfRange`] (nothing changes then).
    pub fn set(&mut self, name: &str, value: f64) -> Result<(), ParamError> {
        let i = self.index(name)?;
        let p = &self.spec.model.parameters[i];
        if !p.range.contains(value) {
            return Err(ParamError::OutOfRange {
                name: name.to_owned(),
                value,
                range: p.range.to_string(),
            });
        }
        self.values[i] = value;
        Ok(())
    }

    /// The same values with `name` set to `value`.
    ///
    /// # Errors
    /// As [`Parameters::set`].
    pub fn with(&self, name: &str, value: f64) -> Result<Parameters, ParamError> {
        let mut p = self.clone();
        p.set(name, value)?;
        Ok(p)
    }

    /// The index of the parameter called `name`.
    ///
    /// # Errors
    /// [`ParamError::Unknown`], listing the model's parameters.
    pub fn index(&self, name: &str) -> Result<usize, ParamError> {
        self.spec
            .parameter(name)
            .ok_or_else(|| ParamError::Unknown {
                name: name.to_owned(),
                model: self.spec.name().to_owned(),
                known: self
                    .spec
                    .model
                    .parameters
                    .iter()
                    .map(|p| p.name.name.as_str())
                    .collect::<Vec<_>>()
                    .join(", "),
            })
    }

    /// Every value `(name, value)`, in file order.
    pub fn iter(&self) -> impl Iterator<Item = (&str, f64)> {
        self.spec
            .model
            .parameters
            .iter()
            .zip(&self.values)
            .map(|(p, v)| (p.name.name.as_str(), *v))
    }
}
