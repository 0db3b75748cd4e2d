//! The model file's layout as serde reads it, before any check: every name and expression
//! keeps its byte span so that later errors can name a line and column.

use std::collections::BTreeMap;

use serde::Deserialize;
use toml::Spanned;

/// A string with its span (quotes included).
pub(crate) type Str = Spanned<String>;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawModel {
    pub(crate) format: Spanned<i64>,
    pub(crate) name: Str,
    #[serde(default)]
    pub(crate) title: Option<String>,
    #[serde(default)]
    pub(crate) reference: Option<String>,
    #[serde(default)]
    pub(crate) doc: Option<String>,
    pub(crate) coordinate: Spanned<Vec<Spanned<RawCoordinate>>>,
    #[serde(default)]
    pub(crate) parameter: Vec<Spanned<RawParameter>>,
    pub(crate) floor: Spanned<RawFloor>,
    pub(crate) body: Spanned<Vec<Spanned<RawBody>>>,
    #[serde(default)]
    pub(crate) point: Vec<Spanned<RawPoint>>,
    pub(crate) stance: Spanned<RawStance>,
    pub(crate) strike: Spanned<RawStrike>,
    #[serde(default)]
    pub(crate) fall: Vec<Spanned<RawFall>>,
    #[serde(default)]
    pub(crate) relabel: Option<Spanned<BTreeMap<Str, Str>>>,
    #[serde(default)]
    pub(crate) start: Option<Spanned<BTreeMap<Str, Str>>>,
    #[serde(default)]
    pub(crate) section: Option<Spanned<RawSection>>,
    #[serde(default)]
    pub(crate) impact: Option<Spanned<RawImpact>>,
    #[serde(default)]
    pub(crate) input: Vec<Spanned<RawInput>>,
    #[serde(default)]
    pub(crate) control: Option<Spanned<RawControl>>,
    #[serde(default)]
    pub(crate) output: Vec<Spanned<RawOutput>>,
    #[serde(default)]
    pub(crate) descriptors: Option<Spanned<RawDescriptors>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawCoordinate {
    pub(crate) name: Str,
    pub(crate) unit: Str,
    pub(crate) doc: String,
    #[serde(default)]
    pub(crate) latex: Option<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawParameter {
    pub(crate) name: Str,
    pub(crate) unit: String,
    pub(crate) doc: String,
    pub(crate) range: Str,
    pub(crate) default: Spanned<f64>,
    #[serde(default)]
    pub(crate) stage: Option<Str>,
    #[serde(default)]
    pub(crate) latex: Option<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawFloor {
    pub(crate) gravity: Str,
    #[serde(default)]
    pub(crate) slope: Option<Str>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawBody {
    pub(crate) name: Str,
    pub(crate) mass: Str,
    pub(crate) com: Spanned<Vec<Str>>,
    #[serde(default)]
    pub(crate) inertia: Option<Str>,
    #[serde(default)]
    pub(crate) angle: Option<Str>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawPoint {
    pub(crate) name: Str,
    pub(crate) at: Spanned<Vec<Str>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawStance {
    pub(crate) friction: Spanned<Vec<Str>>,
    #[serde(default)]
    pub(crate) mu0: Option<Str>,
    #[serde(default)]
    pub(crate) c: Option<Str>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawStrike {
    pub(crate) point: Str,
    #[serde(default)]
    pub(crate) guard: Option<Str>,
    #[serde(default)]
    pub(crate) ahead: Option<bool>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawFall {
    pub(crate) name: Str,
    #[serde(default)]
    pub(crate) point: Option<Str>,
    #[serde(default)]
    pub(crate) guard: Option<Str>,
    pub(crate) doc: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawSection {
    pub(crate) free: Spanned<Vec<Str>>,
    #[serde(default)]
    pub(crate) given: BTreeMap<Str, Str>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawImpact {
    #[serde(default)]
    pub(crate) law: Option<Str>,
    #[serde(default)]
    pub(crate) locks: Vec<Str>,
    #[serde(default)]
    pub(crate) double_support: Option<bool>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawInput {
    pub(crate) name: Str,
    pub(crate) doc: String,
    pub(crate) force: Spanned<Vec<Str>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawControl {
    pub(crate) kp: Str,
    pub(crate) kd: Str,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawOutput {
    pub(crate) name: Str,
    pub(crate) h: Str,
    #[serde(default)]
    pub(crate) aux: Option<Str>,
    pub(crate) desired: Spanned<RawDesired>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawDesired {
    pub(crate) shape: Str,
    #[serde(default)]
    pub(crate) from: Option<Str>,
    #[serde(default)]
    pub(crate) to: Option<Str>,
    #[serde(default)]
    pub(crate) duration: Option<Str>,
    #[serde(default)]
    pub(crate) value: Option<Str>,
    #[serde(default)]
    pub(crate) points: Option<Spanned<Vec<Str>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawDescriptors {
    #[serde(default)]
    pub(crate) report: Option<Spanned<Vec<Str>>>,
    #[serde(default)]
    pub(crate) power_until: Option<Str>,
}
