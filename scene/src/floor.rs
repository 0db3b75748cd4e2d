//! A floor file (`docs/floors.md`): the friction `mu0` under each step of a walk, read and
//! checked once. Three kinds:
//!
//! ```toml
//! kind = "uniform"            # one mu0 for every step
//! mu0 = 0.4
//! ```
//!
//! ```toml
//! kind = "steps"              # step k walks on mu0[k]; the last value holds after the list
//! mu0 = [0.4, 0.4, 0.05, 0.4]
//! ```
//!
//! ```toml
//! kind = "random"             # mu0 drawn per step, a pure function of (seed, walk, step)
//! seed = 7
//! [mu0]
//! distribution = "uniform"    # or "truncated-normal" (mean, sd, lo, hi)
//! lo = 0.1                    # or "markov" (dry, icy, dry_length, icy_length)
//! hi = 0.5
//! ```
//!
//! Every value is checked here against what a floor can be (`mu0 > 0` and finite, `lo < hi`,
//! a patch length of at least one step, ...); an error names the file, the line and column,
//! the field and the valid range. Whether the walker takes `mu0` at run time, and within the
//! range its model file gives, is checked when the floor meets a walker (`walker::floor`).
//! A per-step slope (`phi`) is refused by name: it is not implemented.

use std::path::Path;

use serde::Deserialize;
use toml::Spanned;

use crate::model::error::Location;
use crate::model::source::SourceMap;

mod distribution;

pub use distribution::normal_mass;
use distribution::{RawDistribution, distribution};

/// The most values a `steps` floor lists (a walk takes at most a million steps; the file is
/// at most [`MAX_FILE_BYTES`](crate::limits::MAX_FILE_BYTES) long anyway).
pub const MAX_FLOOR_STEPS: usize = 1_000_000;

/// The smallest share of a truncated normal's mass its interval `[lo, hi]` may hold: draws are
/// made by rejection from the normal, so this bounds the expected tries per step (100).
pub const MIN_TRUNCATED_MASS: f64 = 0.01;

/// Why a floor file cannot be used. Every variant names the file.
#[derive(Debug, thiserror::Error)]
pub enum FloorFileError {
    /// The file cannot be read (missing, not a regular file, too long, not text).
    #[error("floor file {path}: {reason}")]
    Read {
        /// The file, as given.
        path: String,
        /// What is wrong.
        reason: String,
    },
    /// A value is malformed, unknown, missing or outside its range.
    #[error("{path}:{at}: field `{field}`: {message}")]
    Invalid {
        /// The file, as given.
        path: String,
        /// Where in the file (line and column, from 1).
        at: Location,
        /// The field, dotted (`mu0.lo`, `mu0[2]`).
        field: String,
        /// What is wrong and the valid range.
        message: String,
    },
}

impl FloorFileError {
    /// The field the error is about (`<file>` for a file that cannot be read).
    #[must_use]
    pub fn field(&self) -> &str {
        match self {
            FloorFileError::Read { .. } => "<file>",
            FloorFileError::Invalid { field, .. } => field,
        }
    }
}

/// Why a list of `mu0` per step is no floor ([`FloorSpec::steps`]).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{field} = {message}")]
pub struct StepsError {
    /// The value (`mu0[2]`), or `mu0` for the list.
    pub field: String,
    /// What is wrong and the valid range.
    pub message: String,
}

/// How `mu0` is drawn per step on a random floor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Distribution {
    /// Uniform on `[lo, hi)`.
    Uniform {
        /// The smallest value.
        lo: f64,
        /// The bound above the values.
        hi: f64,
    },
    /// A normal of `mean` and standard deviation `sd`, conditioned on `[lo, hi]`.
    TruncatedNormal {
        /// The normal's mean.
        mean: f64,
        /// The normal's standard deviation, > 0.
        sd: f64,
        /// The smallest value.
        lo: f64,
        /// The largest value.
        hi: f64,
    },
    /// A two-state Markov chain: patches of `dry` and of `icy` friction whose lengths (in
    /// steps) are geometric with means `dry_length` and `icy_length`; the first step's state is
    /// drawn from the chain's stationary distribution.
    Markov {
        /// `mu0` of a dry step.
        dry: f64,
        /// `mu0` of an icy step.
        icy: f64,
        /// The mean length of a dry patch (steps), >= 1.
        dry_length: f64,
        /// The mean length of an icy patch (steps), >= 1.
        icy_length: f64,
    },
}

impl Distribution {
    /// The smallest and the largest value a draw can take.
    #[must_use]
    pub fn bounds(&self) -> (f64, f64) {
        match *self {
            Distribution::Uniform { lo, hi } | Distribution::TruncatedNormal { lo, hi, .. } => {
                (lo, hi)
            }
            Distribution::Markov { dry, icy, .. } => (dry.min(icy), dry.max(icy)),
        }
    }
}

/// What a floor file describes: `mu0` per step.
#[derive(Clone, Debug, PartialEq)]
pub enum FloorSpec {
    /// One `mu0` for every step.
    Uniform {
        /// The friction coefficient.
        mu0: f64,
    },
    /// Step `k` walks on `mu0[k]`; steps past the list on its last value.
    Steps {
        /// The values, at least one.
        mu0: Vec<f64>,
    },
    /// `mu0` drawn per step from `mu0`, seeded.
    Random {
        /// The seed: walk `i` of a batch draws from the stream `(seed, i)`.
        seed: u64,
        /// How `mu0` is drawn.
        mu0: Distribution,
    },
}

impl FloorSpec {
    /// The smallest and the largest `mu0` the floor can give a step.
    #[must_use]
    pub fn bounds(&self) -> (f64, f64) {
        match self {
            FloorSpec::Uniform { mu0 } => (*mu0, *mu0),
            FloorSpec::Steps { mu0 } => mu0
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                    (a.min(x), b.max(x))
                }),
            FloorSpec::Random { mu0, .. } => mu0.bounds(),
        }
    }

    /// A `steps` floor of `mu0` values given in a list (a front end's quick floor), each
    /// checked as a file's: at least one, each `> 0` and finite. The error names the position
    /// (`mu0[2]`) and the range.
    ///
    /// # Errors
    /// An empty list, too long a list, or a value that is not `> 0` and finite.
    pub fn steps(mu0: &[f64]) -> Result<FloorSpec, StepsError> {
        if mu0.is_empty() || mu0.len() > MAX_FLOOR_STEPS {
            return Err(StepsError {
                field: "mu0".to_owned(),
                message: list_length(mu0.len()),
            });
        }
        for (i, &x) in mu0.iter().enumerate() {
            positive(x).map_err(|message| StepsError {
                field: format!("mu0[{i}]"),
                message,
            })?;
        }
        Ok(FloorSpec::Steps { mu0: mu0.to_vec() })
    }
}

/// A floor file, read and checked.
#[derive(Clone, Debug, PartialEq)]
pub struct FloorFile {
    /// Where it was read from, as given.
    pub path: String,
    /// What it describes.
    pub spec: FloorSpec,
}

#[derive(Deserialize)]
struct RawKind {
    kind: Option<Spanned<String>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawUniform {
    #[allow(dead_code, reason = "read by `RawKind`")]
    kind: String,
    mu0: Spanned<f64>,
    phi: Option<Spanned<toml::Value>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSteps {
    #[allow(dead_code, reason = "read by `RawKind`")]
    kind: String,
    mu0: Spanned<Vec<Spanned<f64>>>,
    phi: Option<Spanned<toml::Value>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawRandom {
    #[allow(dead_code, reason = "read by `RawKind`")]
    kind: String,
    seed: Spanned<i64>,
    mu0: Spanned<RawDistribution>,
    phi: Option<Spanned<toml::Value>>,
}

/// An error at byte `offset` of the file: its field and what is wrong.
struct At {
    offset: usize,
    field: String,
    message: String,
}

fn at(offset: usize, field: impl Into<String>, message: impl Into<String>) -> At {
    At {
        offset,
        field: field.into(),
        message: message.into(),
    }
}

/// `x` if it is a friction coefficient a floor can have.
fn positive(x: f64) -> Result<f64, String> {
    if x > 0.0 && x.is_finite() {
        Ok(x)
    } else {
        Err(format!("{x}: must be > 0 and finite"))
    }
}

fn list_length(n: usize) -> String {
    format!("a list of {n} values: must list 1 to {MAX_FLOOR_STEPS} values of mu0 (each > 0)")
}

impl FloorFile {
    /// Reads and checks the floor file at `path`.
    ///
    /// # Errors
    /// [`FloorFileError::Read`] for a file that cannot be read, [`FloorFileError::Invalid`]
    /// for a malformed, unknown, missing or out-of-range field.
    pub fn from_file(path: &Path) -> Result<FloorFile, FloorFileError> {
        let shown = path.display().to_string();
        let text = crate::read::read_input(path, crate::limits::MAX_FILE_BYTES).map_err(|e| {
            FloorFileError::Read {
                path: shown.clone(),
                reason: e.reason(),
            }
        })?;
        FloorFile::from_toml(&text, &shown)
    }

    /// Reads and checks a floor from `text`, read from `path` (for messages).
    ///
    /// # Errors
    /// As [`FloorFile::from_file`].
    pub fn from_toml(text: &str, path: &str) -> Result<FloorFile, FloorFileError> {
        let source = SourceMap::new(text);
        parse(text)
            .map(|spec| FloorFile {
                path: path.to_owned(),
                spec,
            })
            .map_err(|e| FloorFileError::Invalid {
                path: path.to_owned(),
                at: source.location(e.offset),
                field: e.field,
                message: e.message,
            })
    }
}

/// A TOML error as an [`At`]: its place, the key on that line, and the parser's message
/// (without its own rendering of the line).
fn syntax(text: &str, e: &toml::de::Error) -> At {
    let offset = e.span().map_or(0, |s| s.start);
    let line_start = text[..offset.min(text.len())]
        .rfind('\n')
        .map_or(0, |i| i + 1);
    let line = &text[line_start..];
    let line = line.split('\n').next().unwrap_or_default();
    let key = line
        .split_once('=')
        .map(|(k, _)| k.trim().trim_matches('"').to_owned())
        .filter(|k| !k.is_empty() && !k.starts_with('['))
        .unwrap_or_else(|| "<file>".to_owned());
    at(offset, key, e.message().trim_end().to_owned())
}

fn parse(text: &str) -> Result<FloorSpec, At> {
    let kind: RawKind = toml::from_str(text).map_err(|e| syntax(text, &e))?;
    let Some(kind) = kind.kind else {
        return Err(at(
            0,
            "kind",
            "missing: expected kind = \"uniform\", \"steps\" or \"random\"",
        ));
    };
    let reject_phi = |phi: Option<Spanned<toml::Value>>| match phi {
        Some(p) => Err(at(
            p.span().start,
            "phi",
            "a per-step slope is not implemented; set the slope of the walk with --phi (or \
             the scene's `phi`), the same for every step",
        )),
        None => Ok(()),
    };
    match kind.get_ref().as_str() {
        "uniform" => {
            let raw: RawUniform = toml::from_str(text).map_err(|e| syntax(text, &e))?;
            reject_phi(raw.phi)?;
            let mu0 =
                positive(*raw.mu0.get_ref()).map_err(|m| at(raw.mu0.span().start, "mu0", m))?;
            Ok(FloorSpec::Uniform { mu0 })
        }
        "steps" => {
            let raw: RawSteps = toml::from_str(text).map_err(|e| syntax(text, &e))?;
            reject_phi(raw.phi)?;
            let list = raw.mu0.get_ref();
            if list.is_empty() || list.len() > MAX_FLOOR_STEPS {
                return Err(at(raw.mu0.span().start, "mu0", list_length(list.len())));
            }
            let mut mu0 = Vec::with_capacity(list.len());
            for (i, v) in list.iter().enumerate() {
                mu0.push(
                    positive(*v.get_ref())
                        .map_err(|m| at(v.span().start, format!("mu0[{i}]"), m))?,
                );
            }
            Ok(FloorSpec::Steps { mu0 })
        }
        "random" => {
            let raw: RawRandom = toml::from_str(text).map_err(|e| syntax(text, &e))?;
            reject_phi(raw.phi)?;
            let seed = u64::try_from(*raw.seed.get_ref()).map_err(|_| {
                at(
                    raw.seed.span().start,
                    "seed",
                    format!(
                        "{}: must be a whole number in [0, {}]",
                        raw.seed.get_ref(),
                        i64::MAX
                    ),
                )
            })?;
            let mu0 = distribution(raw.mu0)?;
            Ok(FloorSpec::Random { seed, mu0 })
        }
        other => Err(at(
            kind.span().start,
            "kind",
            format!(
                "{:?}: expected \"uniform\", \"steps\" or \"random\"",
                other.chars().take(40).collect::<String>()
            ),
        )),
    }
}

#[cfg(test)]
mod tests;
