//! Scenes: which walker structure to generate kernels for, and which parameters are constants.
//!
//! A scene is a small TOML file:
//!
//! ```toml
//! name = "active-level"     # used in the @generated line and the default file name
//! floor = "level"           # "level" | "slope"
//! friction = "tanh"         # "none" | "tanh" (Eqs. 26, 37) | "coulomb" (Eq. 25, stick-slip)
//! torso = "actuated"        # "actuated" (output-following control, Eqs. 30-32) | "passive" (u = 0)
//! impact = "frictionless"   # optional: "frictionless" (the paper's, default) | "coulomb"
//!                           # (plastic impact with Coulomb friction mu0, docs/impacts.md)
//! kernels = ["accel_level", "lambda_level"]   # optional; default: every kernel of the structure
//!
//! [fixed]                   # parameters substituted at generation time
//! m1 = 2.0
//! alpha = 0.5235987755982988   # or alpha_deg = 30.0 (not both)
//! # every parameter of the structure that is not fixed is a runtime field of `Params`
//! ```
//!
//! | parameter | meaning | valid values | exists when |
//! |---|---|---|---|
//! | `m1`, `m2` | masses of wheel and torso | finite, > 0 | always |
//! | `l` | leg length | finite, > 0 | always |
//! | `I1`, `I2` | inertia moments of wheel and torso | finite, > 0 | always |
//! | `g` | gravity | finite, > 0 | always |
//! | `alpha` (`alpha_deg`) | angle between spokes | in (0, pi) (in (0, 180)) | always |
//! | `phi` | slope angle | in [0, pi/2) | `floor = "slope"` |
//! | `mu0` | friction coefficient | finite, >= 0 | `friction` is not `"none"` |
//! | `c` | sharpness of the tanh friction | finite, > 0 | `friction = "tanh"` |
//! | `T_set` | duration of the `y_d` ramp | finite, > 0 | `torso = "actuated"` |
//! | `K_P`, `K_D` | PD gains | finite, >= 0 | `torso = "actuated"` |
//!
//! Rejected as contradictions: a parameter given for a structure that does not have it (the
//! last column), both `alpha` and `alpha_deg`, `floor = "slope"` with `torso = "actuated"` (the
//! paper's slope walker is passive and the derivation only provides passive slope kernels), and
//! a kernel the structure does not have (see [`KernelName::applies_to`]), and
//! `impact = "coulomb"` with `friction = "none"` (the impact's friction coefficient is `mu0`,
//! which a frictionless floor does not have). The impact law is the simulator's default for
//! the scene; it does not change the generated kernels (every structure has both impact
//! maps). Every error names the
//! field it is about ([`SceneError::field`]).

use std::collections::BTreeMap;
use std::path::Path;

use serde::Deserialize;

use crate::catalog::KernelName;
use crate::error::SceneError;
use crate::param::{Param, Range};
use crate::structure::{Floor, Friction, ImpactLaw, Torso};

/// The file layout, as deserialised before validation.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawScene {
    name: String,
    floor: Floor,
    friction: Friction,
    torso: Torso,
    #[serde(default)]
    impact: ImpactLaw,
    #[serde(default)]
    kernels: Option<Vec<String>>,
    #[serde(default)]
    fixed: RawFixed,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
#[allow(
    non_snake_case,
    reason = "field names are the paper's, as written in scene files"
)]
struct RawFixed {
    m1: Option<f64>,
    m2: Option<f64>,
    l: Option<f64>,
    I1: Option<f64>,
    I2: Option<f64>,
    g: Option<f64>,
    alpha: Option<f64>,
    alpha_deg: Option<f64>,
    phi: Option<f64>,
    mu0: Option<f64>,
    c: Option<f64>,
    T_set: Option<f64>,
    K_P: Option<f64>,
    K_D: Option<f64>,
}

/// A validated scene (build one with [`Scene::new`] or load one with [`Scene::from_file`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// Name for the `@generated` line and the default file name.
    pub name: String,
    /// Level floor or slope.
    pub floor: Floor,
    /// Friction model.
    pub friction: Friction,
    /// Actuated or passive torso.
    pub torso: Torso,
    /// The impact law the simulator uses for this scene by default.
    pub impact: ImpactLaw,
    /// The kernels asked for; `None` for every kernel of the structure.
    pub kernels: Option<Vec<KernelName>>,
    /// Parameters substituted at generation time.
    pub fixed: BTreeMap<Param, f64>,
}

impl Scene {
    /// A scene with nothing fixed and every kernel of the structure (validated).
    ///
    /// # Errors
    /// The name is invalid or the structure is contradictory (see [`Scene::validate`]).
    pub fn new(
        name: &str,
        floor: Floor,
        friction: Friction,
        torso: Torso,
    ) -> Result<Scene, SceneError> {
        let scene = Scene {
            name: name.to_owned(),
            floor,
            friction,
            torso,
            impact: ImpactLaw::Frictionless,
            kernels: None,
            fixed: BTreeMap::new(),
        };
        scene.validate()?;
        Ok(scene)
    }

    /// Fixes `param` to `value` (validated).
    ///
    /// # Errors
    /// The value is out of range or the structure lacks the parameter.
    pub fn fix(mut self, param: Param, value: f64) -> Result<Scene, SceneError> {
        self.fixed.insert(param, value);
        self.validate()?;
        Ok(self)
    }

    /// Restricts the kernels to `kernels` (validated).
    ///
    /// # Errors
    /// The list is empty, has duplicates or a kernel the structure lacks.
    pub fn with_kernels(mut self, kernels: &[KernelName]) -> Result<Scene, SceneError> {
        self.kernels = Some(kernels.to_vec());
        self.validate()?;
        Ok(self)
    }

    /// Reads and validates a scene file.
    ///
    /// # Errors
    /// The file cannot be read or the scene is invalid.
    pub fn from_file(path: impl AsRef<Path>) -> Result<Scene, SceneError> {
        let path = path.as_ref();
        let src = crate::read::read_input(path, crate::limits::MAX_FILE_BYTES).map_err(|e| {
            SceneError::Read {
                path: path.display().to_string(),
                source: e.into(),
            }
        })?;
        let origin = path.file_name().map_or_else(
            || path.display().to_string(),
            |n| n.to_string_lossy().into_owned(),
        );
        Scene::from_toml_str(&src, &origin)
    }

    /// Parses and validates a scene from TOML text; `origin` names it in errors.
    ///
    /// # Errors
    /// The TOML is malformed or the scene is invalid.
    pub fn from_toml_str(src: &str, origin: &str) -> Result<Scene, SceneError> {
        let raw: RawScene = toml::from_str(src).map_err(|e| SceneError::Syntax {
            origin: origin.to_owned(),
            field: error_field(src, &e),
            message: e.to_string().trim_end().to_owned(),
        })?;
        Scene::from_raw(raw)
    }

    fn from_raw(raw: RawScene) -> Result<Scene, SceneError> {
        let f = raw.fixed;
        if let (Some(_), Some(_)) = (f.alpha, f.alpha_deg) {
            return Err(SceneError::Contradiction {
                field: "fixed.alpha_deg".to_owned(),
                reason: "give either `alpha` (radians) or `alpha_deg` (degrees), not both"
                    .to_owned(),
            });
        }
        if let Some(deg) = f.alpha_deg
            && !Range::OpenDegrees.contains(deg)
        {
            return Err(SceneError::OutOfRange {
                field: "fixed.alpha_deg".to_owned(),
                value: deg,
                range: Range::OpenDegrees.describe(),
            });
        }
        let values = [
            (Param::M1, f.m1),
            (Param::M2, f.m2),
            (Param::L, f.l),
            (Param::I1, f.I1),
            (Param::I2, f.I2),
            (Param::G, f.g),
            (
                Param::Alpha,
                f.alpha.or(f.alpha_deg.map(degrees_to_radians)),
            ),
            (Param::Phi, f.phi),
            (Param::Mu0, f.mu0),
            (Param::C, f.c),
            (Param::TSet, f.T_set),
            (Param::KP, f.K_P),
            (Param::KD, f.K_D),
        ];
        let fixed = values
            .into_iter()
            .filter_map(|(p, v)| v.map(|v| (p, v)))
            .collect();
        let kernels = match raw.kernels {
            None => None,
            Some(names) => Some(
                names
                    .iter()
                    .map(|n| {
                        KernelName::from_name(n).ok_or_else(|| SceneError::UnknownKernel {
                            name: n.clone(),
                            valid: join(KernelName::ALL.iter().map(|k| k.name())),
                        })
                    })
                    .collect::<Result<Vec<_>, _>>()?,
            ),
        };
        let scene = Scene {
            name: raw.name,
            floor: raw.floor,
            friction: raw.friction,
            torso: raw.torso,
            impact: raw.impact,
            kernels,
            fixed,
        };
        scene.validate()?;
        Ok(scene)
    }

    /// Checks the name, the structure, the fixed values and the kernel list.
    ///
    /// # Errors
    /// The first problem found, naming its field.
    pub fn validate(&self) -> Result<(), SceneError> {
        let name_ok = (1..=64).contains(&self.name.len())
            && self
                .name
                .chars()
                .all(|ch| ch.is_ascii_alphanumeric() || ch == '-' || ch == '_');
        if !name_ok {
            return Err(SceneError::InvalidName {
                value: self.name.clone(),
            });
        }
        if self.floor == Floor::Slope && self.torso == Torso::Actuated {
            return Err(SceneError::Contradiction {
                field: "torso".to_owned(),
                reason: "floor = \"slope\" needs torso = \"passive\": the paper's slope walker \
                         is passive and only passive slope kernels are derived"
                    .to_owned(),
            });
        }
        if self.impact == ImpactLaw::Coulomb && self.friction == Friction::None {
            return Err(SceneError::Contradiction {
                field: "impact".to_owned(),
                reason: "impact = \"coulomb\" needs a friction coefficient mu0, which \
                         friction = \"none\" does not have; use impact = \"frictionless\""
                    .to_owned(),
            });
        }
        for (&p, &v) in &self.fixed {
            let field = format!("fixed.{}", p.name());
            if !p.applies_to(self.floor, self.friction, self.torso) {
                return Err(SceneError::Contradiction {
                    field,
                    reason: p.absent_because(self.floor, self.friction, self.torso),
                });
            }
            if !p.accepts(v) {
                return Err(SceneError::OutOfRange {
                    field,
                    value: v,
                    range: p.valid_range(),
                });
            }
        }
        if let Some(kernels) = &self.kernels {
            if kernels.is_empty() {
                return Err(SceneError::BadKernelList {
                    reason: "the list is empty; omit the field for every kernel of the structure"
                        .to_owned(),
                });
            }
            for (i, k) in kernels.iter().enumerate() {
                if kernels.get(..i).is_some_and(|seen| seen.contains(k)) {
                    return Err(SceneError::BadKernelList {
                        reason: format!("kernel `{k}` is listed twice"),
                    });
                }
                if !k.applies_to(self.floor, self.friction, self.torso) {
                    return Err(SceneError::KernelNotInStructure {
                        name: k.name().to_owned(),
                        structure: self.structure(),
                        valid: join(
                            KernelName::for_structure(self.floor, self.friction, self.torso)
                                .iter()
                                .map(|k| k.name()),
                        ),
                    });
                }
            }
        }
        Ok(())
    }

    /// The structure in words, for example `floor = "level", friction = "tanh", torso = "actuated"`.
    #[must_use]
    pub fn structure(&self) -> String {
        format!(
            "floor = \"{}\", friction = \"{}\", torso = \"{}\"",
            self.floor, self.friction, self.torso
        )
    }

    /// The kernels to generate: the list asked for, or every kernel of the structure.
    #[must_use]
    pub fn kernels(&self) -> Vec<KernelName> {
        self.kernels
            .clone()
            .unwrap_or_else(|| KernelName::for_structure(self.floor, self.friction, self.torso))
    }

    /// The parameters the structure has, in canonical order.
    #[must_use]
    pub fn params(&self) -> Vec<Param> {
        Param::ALL
            .into_iter()
            .filter(|p| p.applies_to(self.floor, self.friction, self.torso))
            .collect()
    }

    /// The parameters that are runtime fields of `Params`: those of the structure not fixed.
    #[must_use]
    pub fn runtime_params(&self) -> Vec<Param> {
        self.params()
            .into_iter()
            .filter(|p| !self.fixed.contains_key(p))
            .collect()
    }

    /// The value `param` is fixed to, if it is fixed.
    #[must_use]
    pub fn fixed_value(&self, param: Param) -> Option<f64> {
        self.fixed.get(&param).copied()
    }

    /// The default output file name: the scene name with `-` as `_`, plus `.rs`.
    #[must_use]
    pub fn default_file_name(&self) -> String {
        format!("{}.rs", self.name.replace('-', "_"))
    }

    /// Lines describing the scene, for the generated file's header comment.
    #[must_use]
    pub fn summary(&self) -> Vec<String> {
        let fixed = if self.fixed.is_empty() {
            "nothing".to_owned()
        } else {
            join(self.fixed.iter().map(|(p, v)| format!("{p} = {v:?}")))
        };
        let runtime = self.runtime_params();
        let runtime = if runtime.is_empty() {
            "none".to_owned()
        } else {
            join(runtime.iter().map(|p| p.name()))
        };
        vec![
            format!("Structure: {}.", self.structure()),
            format!("Fixed at generation time: {fixed}."),
            format!("Runtime parameters (fields of `Params`): {runtime}."),
        ]
    }
}

/// `deg * pi / 180`, nearly correctly rounded: `pi` is carried as two doubles and the product
/// and quotient errors are compensated, so that 30 gives `FRAC_PI_6` (plain `to_radians` is
/// one unit in the last place low there).
fn degrees_to_radians(deg: f64) -> f64 {
    use std::f64::consts::PI;
    const PI_LO: f64 = 1.224_646_799_147_353_2e-16;
    let p = deg * PI;
    let p_err = deg.mul_add(PI, -p) + deg * PI_LO;
    let q = p / 180.0;
    let q_err = (-q).mul_add(180.0, p);
    q + (q_err + p_err) / 180.0
}

fn join<I: IntoIterator<Item = S>, S: AsRef<str>>(items: I) -> String {
    items
        .into_iter()
        .map(|s| s.as_ref().to_owned())
        .collect::<Vec<_>>()
        .join(", ")
}

/// The field a TOML error is about: the missing field for "missing field", else the key at
/// the error's position.
fn error_field(src: &str, e: &toml::de::Error) -> String {
    let at = e.span().and_then(|s| field_at(src, s.start));
    let missing = e
        .message()
        .strip_prefix("missing field `")
        .and_then(|rest| rest.split('`').next());
    match (missing, at) {
        (Some(name), Some(table))
            if !table.contains('.') && src.contains(&format!("[{table}]")) =>
        {
            format!("{table}.{name}")
        }
        (Some(name), _) => name.to_owned(),
        (None, Some(field)) => field,
        (None, None) => "<file>".to_owned(),
    }
}

/// The dotted key at byte `offset` of TOML text `src`: the key of that line, prefixed by the
/// last `[table]` header before it. A heuristic for error messages.
fn field_at(src: &str, offset: usize) -> Option<String> {
    let before = src.get(..offset)?;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let line = src.get(line_start..)?.lines().next()?.trim();
    // An empty header (`[]`) or key (`= 1`) names nothing: the caller falls back to the file.
    let header = |l: &str| {
        l.trim()
            .strip_prefix('[')
            .and_then(|h| h.split(']').next())
            .map(|h| h.trim().to_owned())
            .filter(|h| !h.is_empty())
    };
    if let Some(h) = header(line) {
        return Some(h);
    }
    let key = line.split_once('=')?.0.trim().trim_matches('"').to_owned();
    if key.is_empty() {
        return None;
    }
    let table = src.get(..line_start)?.lines().rev().find_map(header);
    Some(match table {
        Some(t) => format!("{t}.{key}"),
        None => key,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn alpha_deg_thirty_is_pi_over_six() {
        let s = Scene::from_toml_str(
            "name = \"a\"\nfloor = \"level\"\nfriction = \"none\"\ntorso = \"passive\"\n\
             [fixed]\nalpha_deg = 30\n",
            "t",
        );
        let s = s.expect("valid scene");
        assert_eq!(
            s.fixed_value(Param::Alpha),
            Some(std::f64::consts::FRAC_PI_6)
        );
    }

    #[test]
    fn degrees_convert_to_the_nearest_double() {
        use std::f64::consts::{FRAC_PI_2, FRAC_PI_3, FRAC_PI_4, FRAC_PI_6, FRAC_PI_8};
        for (deg, rad) in [
            (30.0, FRAC_PI_6),
            (45.0, FRAC_PI_4),
            (60.0, FRAC_PI_3),
            (90.0, FRAC_PI_2),
            (22.5, FRAC_PI_8),
        ] {
            assert_eq!(degrees_to_radians(deg), rad, "{deg} degrees");
        }
    }

    #[test]
    fn field_at_finds_table_and_key() {
        let src = "name = \"x\"\n[fixed]\nm1 = \"heavy\"\n";
        let off = src.find("\"heavy\"").unwrap_or(0);
        assert_eq!(field_at(src, off).as_deref(), Some("fixed.m1"));
    }

    #[test]
    fn impact_law_defaults_to_the_papers_and_coulomb_needs_friction() {
        let head = "name = \"a\"\nfloor = \"level\"\ntorso = \"actuated\"\n";
        let scene = |rest: &str| Scene::from_toml_str(&format!("{head}{rest}"), "test");
        let default = scene("friction = \"tanh\"\n").map(|s| s.impact);
        assert_eq!(default.ok(), Some(ImpactLaw::Frictionless));
        let coulomb = scene("friction = \"tanh\"\nimpact = \"coulomb\"\n").map(|s| s.impact);
        assert_eq!(coulomb.ok(), Some(ImpactLaw::Coulomb));
        let none = scene("friction = \"none\"\nimpact = \"coulomb\"\n");
        assert_eq!(
            none.err().map(|e| e.field().to_owned()).as_deref(),
            Some("impact")
        );
        let bad = scene("friction = \"tanh\"\nimpact = \"sticky\"\n");
        assert_eq!(
            bad.err().map(|e| e.field().to_owned()).as_deref(),
            Some("impact")
        );
    }
}
