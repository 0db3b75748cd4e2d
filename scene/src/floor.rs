//! A floor file (`docs/floors.md`): the friction `mu0` and the slope `phi` under each step of a
//! walk (either or both), read and checked once. Three kinds:
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
//! The slope `phi` takes the same three forms as `mu0` (a value, a list, a `[phi]` table of
//! a random floor), each value finite; its range is the model's, checked with the walker.
//!
//! A fourth kind, `patches` (`floor/patches.rs`), gives `mu0` by position along the floor
//! instead of by step: a value outside the patches and `[[patch]]` tables of `from`, `to`
//! (half-open, metres) and `mu0`.

use std::path::Path;

use serde::Deserialize;
use toml::Spanned;

use crate::model::error::Location;
use crate::model::source::SourceMap;

mod distribution;
mod patches;

pub use distribution::normal_mass;
use distribution::{RawDistribution, distribution};
pub use patches::{FloorPatch, MAX_PATCH_POSITION, MAX_PATCHES};
use patches::{RawPatches, patches};

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

/// Why a list of values per step is no floor ([`FloorSpec::steps`], [`FloorSpec::phi_steps`]).
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

/// The values of one quantity per step: the friction `mu0` or the slope `phi` of a [`FloorPlan`].
/// (The variants' field is called `mu0` after the first quantity a floor set; for a slope it
/// holds the values of `phi`.)
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
    /// `mu0` by position along the floor, not by step (a friction floor only): `mu0` outside
    /// the patches, each patch's own on its `[from, to)`. The patches are in order along the
    /// floor and do not overlap.
    Patches {
        /// The friction coefficient outside the patches.
        mu0: f64,
        /// The patches, at least one, in order, not overlapping.
        patches: Vec<FloorPatch>,
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
            FloorSpec::Patches { mu0, patches } => patches
                .iter()
                .fold((*mu0, *mu0), |(a, b), p| (a.min(p.mu0), b.max(p.mu0))),
        }
    }

    /// The friction coefficient at `s` metres along a floor of patches (`None` for the other
    /// kinds, which give it by step): the patch's whose `[from, to)` holds `s`, else the floor's.
    #[must_use]
    pub fn mu0_at(&self, s: f64) -> Option<f64> {
        match self {
            FloorSpec::Patches { mu0, patches } => {
                let i = patches.partition_point(|p| p.from <= s);
                Some(match i.checked_sub(1).map(|j| &patches[j]) {
                    Some(p) if s < p.to => p.mu0,
                    _ => *mu0,
                })
            }
            _ => None,
        }
    }

    /// A `steps` floor of `mu0` values given in a list (a front end's quick floor), each
    /// checked as a file's: at least one, each `> 0` and finite. The error names the position
    /// (`mu0[2]`) and the range.
    ///
    /// # Errors
    /// An empty list, too long a list, or a value that is not `> 0` and finite.
    pub fn steps(mu0: &[f64]) -> Result<FloorSpec, StepsError> {
        Quantity::Mu0.steps(mu0)
    }

    /// A `steps` floor of slopes `phi` given in a list, each checked as a file's: at least
    /// one, each finite (the model's range is checked with the walker). The error names the
    /// position (`phi[2]`).
    ///
    /// # Errors
    /// An empty list, too long a list, or a value that is not finite.
    pub fn phi_steps(phi: &[f64]) -> Result<FloorSpec, StepsError> {
        Quantity::Phi.steps(phi)
    }
}

/// What a floor file describes: the friction `mu0` and the slope `phi` per step, each given
/// or not (at least one). A quantity the floor does not give keeps the walker's own value.
#[derive(Clone, Debug, PartialEq)]
pub struct FloorPlan {
    /// The friction coefficient of each step, if the floor sets it.
    pub mu0: Option<FloorSpec>,
    /// The slope angle of each step (rad), if the floor sets it.
    pub phi: Option<FloorSpec>,
}

impl From<FloorSpec> for FloorPlan {
    /// A floor of friction only.
    fn from(mu0: FloorSpec) -> FloorPlan {
        FloorPlan {
            mu0: Some(mu0),
            phi: None,
        }
    }
}

/// The quantity a [`FloorSpec`] gives: its name in a file and the values it may take.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Quantity {
    /// The friction coefficient: `> 0` and finite.
    Mu0,
    /// The slope angle: finite (its range is the model's).
    Phi,
}

impl Quantity {
    /// The field's name (`mu0`, `phi`).
    pub(crate) fn name(self) -> &'static str {
        match self {
            Quantity::Mu0 => "mu0",
            Quantity::Phi => "phi",
        }
    }

    /// `x` if the quantity can take it.
    pub(crate) fn check(self, x: f64) -> Result<f64, String> {
        match self {
            Quantity::Mu0 => positive(x),
            Quantity::Phi if x.is_finite() => Ok(x),
            Quantity::Phi => Err(format!("{x}: must be finite")),
        }
    }

    fn steps(self, values: &[f64]) -> Result<FloorSpec, StepsError> {
        let name = self.name();
        if values.is_empty() || values.len() > MAX_FLOOR_STEPS {
            return Err(StepsError {
                field: name.to_owned(),
                message: list_length(name, values.len()),
            });
        }
        for (i, &x) in values.iter().enumerate() {
            self.check(x).map_err(|message| StepsError {
                field: format!("{name}[{i}]"),
                message,
            })?;
        }
        Ok(FloorSpec::Steps {
            mu0: values.to_vec(),
        })
    }
}

/// A floor file, read and checked.
#[derive(Clone, Debug, PartialEq)]
pub struct FloorFile {
    /// Where it was read from, as given.
    pub path: String,
    /// What it describes.
    pub spec: FloorPlan,
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
    mu0: Option<Spanned<f64>>,
    phi: Option<Spanned<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSteps {
    #[allow(dead_code, reason = "read by `RawKind`")]
    kind: String,
    mu0: Option<Spanned<Vec<Spanned<f64>>>>,
    phi: Option<Spanned<Vec<Spanned<f64>>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawRandom {
    #[allow(dead_code, reason = "read by `RawKind`")]
    kind: String,
    seed: Spanned<i64>,
    mu0: Option<Spanned<RawDistribution>>,
    phi: Option<Spanned<RawDistribution>>,
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

fn list_length(name: &str, n: usize) -> String {
    let each = if name == "mu0" {
        "each > 0"
    } else {
        "each finite"
    };
    format!("a list of {n} values: must list 1 to {MAX_FLOOR_STEPS} values of {name} ({each})")
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

fn parse(text: &str) -> Result<FloorPlan, At> {
    let kind: RawKind = toml::from_str(text).map_err(|e| syntax(text, &e))?;
    let Some(kind) = kind.kind else {
        return Err(at(
            0,
            "kind",
            "missing: expected kind = \"uniform\", \"steps\", \"random\" or \"patches\"",
        ));
    };
    // At least one of `mu0` and `phi`: a floor that sets nothing is a mistake.
    let neither = |what: &str| {
        at(
            0,
            "mu0",
            format!("missing: a {what} floor gives mu0, phi or both"),
        )
    };
    let list = |raw: Spanned<Vec<Spanned<f64>>>, q: Quantity| -> Result<FloorSpec, At> {
        let name = q.name();
        let items = raw.get_ref();
        if items.is_empty() || items.len() > MAX_FLOOR_STEPS {
            return Err(at(raw.span().start, name, list_length(name, items.len())));
        }
        let mut values = Vec::with_capacity(items.len());
        for (i, v) in items.iter().enumerate() {
            values.push(
                q.check(*v.get_ref())
                    .map_err(|m| at(v.span().start, format!("{name}[{i}]"), m))?,
            );
        }
        Ok(FloorSpec::Steps { mu0: values })
    };
    match kind.get_ref().as_str() {
        "uniform" => {
            let raw: RawUniform = toml::from_str(text).map_err(|e| syntax(text, &e))?;
            let one = |v: Option<Spanned<f64>>, q: Quantity| {
                v.map(|v| {
                    q.check(*v.get_ref())
                        .map(|mu0| FloorSpec::Uniform { mu0 })
                        .map_err(|m| at(v.span().start, q.name(), m))
                })
                .transpose()
            };
            let floor = FloorPlan {
                mu0: one(raw.mu0, Quantity::Mu0)?,
                phi: one(raw.phi, Quantity::Phi)?,
            };
            if floor.mu0.is_none() && floor.phi.is_none() {
                return Err(neither("uniform"));
            }
            Ok(floor)
        }
        "steps" => {
            let raw: RawSteps = toml::from_str(text).map_err(|e| syntax(text, &e))?;
            let floor = FloorPlan {
                mu0: raw.mu0.map(|v| list(v, Quantity::Mu0)).transpose()?,
                phi: raw.phi.map(|v| list(v, Quantity::Phi)).transpose()?,
            };
            if floor.mu0.is_none() && floor.phi.is_none() {
                return Err(neither("steps"));
            }
            Ok(floor)
        }
        "random" => {
            let raw: RawRandom = toml::from_str(text).map_err(|e| syntax(text, &e))?;
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
            let random = |d: Option<Spanned<RawDistribution>>, q: Quantity| {
                d.map(|d| distribution(d, q).map(|mu0| FloorSpec::Random { seed, mu0 }))
                    .transpose()
            };
            let floor = FloorPlan {
                mu0: random(raw.mu0, Quantity::Mu0)?,
                phi: random(raw.phi, Quantity::Phi)?,
            };
            if floor.mu0.is_none() && floor.phi.is_none() {
                return Err(neither("random"));
            }
            Ok(floor)
        }
        "patches" => {
            let raw: RawPatches = toml::from_str(text).map_err(|e| syntax(text, &e))?;
            patches(raw)
        }
        other => Err(at(
            kind.span().start,
            "kind",
            format!(
                "{:?}: expected \"uniform\", \"steps\", \"random\" or \"patches\"",
                other.chars().take(40).collect::<String>()
            ),
        )),
    }
}

#[cfg(test)]
mod tests;
