//! The sections after the declarations: floor, bodies, points, stance, strike, falls,
//! relabelling, start and impact, each checked against the symbol table (the actuated sections are in
//! [`control`](super::control)); then each angle's base-angle divisor.

use std::collections::HashSet;

use crate::model::angles::angle_combination;
use crate::model::control::Actuation;
use crate::model::divisors::base_divisors;
use crate::model::error::{ModelError, ModelErrorKind};
use crate::model::load::{Loader, Use, is_identifier, is_kebab_name};
use crate::model::raw::{RawModel, Str};
use crate::model::symbols::SymbolKind;
use crate::model::types::{
    Body, Coordinate, Fall, FallCondition, Floor, Impact, Model, ModelExpr, Name, Parameter, Point,
    Relabel, Stance, StartValue, Strike,
};
use crate::structure::{Friction, ImpactLaw};

impl Loader<'_> {
    /// A reference to a declared parameter (an angle one when `angle`).
    pub(crate) fn parameter_ref(
        &self,
        s: &Str,
        field: &str,
        angle: bool,
    ) -> Result<Name, ModelError> {
        let name = s.get_ref();
        match self.symbols.get(name) {
            Some(sym) if sym.kind == SymbolKind::Parameter && (!angle || sym.angle) => {
                Ok(self.name(s))
            }
            Some(sym) if sym.kind == SymbolKind::Parameter => Err(self.error(
                s.span(),
                ModelErrorKind::UnknownReference,
                format!("{field} = `{name}`: expected an angle parameter (unit \"rad\")"),
            )),
            _ => Err(self.error(
                s.span(),
                ModelErrorKind::UnknownReference,
                format!("{field} = `{name}`: expected the name of a declared parameter"),
            )),
        }
    }

    /// A `[x, z]` pair of positions.
    fn position(
        &self,
        pair: &toml::Spanned<Vec<Str>>,
        what: &str,
    ) -> Result<[ModelExpr; 2], ModelError> {
        match pair.get_ref().as_slice() {
            [x, z] => Ok([
                self.expr(x, &format!("{what} x"), Use::Position)?,
                self.expr(z, &format!("{what} z"), Use::Position)?,
            ]),
            other => Err(self.error(
                pair.span(),
                ModelErrorKind::Count,
                format!(
                    "{what}: expected [x, z], two expressions; found {}",
                    other.len()
                ),
            )),
        }
    }

    /// A unique name in its own namespace (`seen`), an identifier or a kebab name.
    pub(crate) fn unique(
        &self,
        s: &Str,
        what: &str,
        kebab: bool,
        seen: &mut HashSet<String>,
    ) -> Result<Name, ModelError> {
        let name = s.get_ref();
        let ok = if kebab {
            is_kebab_name(name)
        } else {
            is_identifier(name)
        };
        if !ok {
            let expected = if kebab {
                "[a-z][a-z0-9-]*"
            } else {
                "an ASCII letter followed by letters, digits or `_`"
            };
            return Err(self.error(
                s.span(),
                ModelErrorKind::BadName,
                format!("{what} name `{name}`: expected {expected}"),
            ));
        }
        if !seen.insert(name.clone()) {
            return Err(self.error(
                s.span(),
                ModelErrorKind::Duplicate,
                format!("{what} `{name}` is declared twice"),
            ));
        }
        Ok(self.name(s))
    }

    pub(crate) fn sections(
        self,
        raw: RawModel,
        coordinates: Vec<Coordinate>,
        parameters: Vec<Parameter>,
    ) -> Result<Model, ModelError> {
        let floor_raw = raw.floor.get_ref();
        let floor = Floor {
            gravity: self.parameter_ref(&floor_raw.gravity, "gravity", false)?,
            slope: floor_raw
                .slope
                .as_ref()
                .map(|s| self.parameter_ref(s, "slope", true))
                .transpose()?,
        };

        if raw.body.get_ref().is_empty() {
            return Err(self.error(
                raw.body.span(),
                ModelErrorKind::Count,
                "expected at least one [[body]]".to_owned(),
            ));
        }
        let mut seen = HashSet::new();
        let mut bodies = Vec::new();
        for b in raw.body.get_ref() {
            let (span, b) = (b.span(), b.get_ref());
            let name = self.unique(&b.name, "body", false, &mut seen)?;
            let what = format!("body `{}`", name.name);
            let mass = self.expr(&b.mass, &format!("{what} mass"), Use::Configuration)?;
            let com = self.position(&b.com, &format!("{what} com"))?;
            let rotation = match (&b.inertia, &b.angle) {
                (None, None) => None,
                (Some(i), Some(a)) => {
                    let inertia = self.expr(i, &format!("{what} inertia"), Use::Configuration)?;
                    let angle = self.expr(a, &format!("{what} angle"), Use::Configuration)?;
                    let is_angle = |n: &str| self.symbols.get(n).is_some_and(|s| s.angle);
                    angle_combination(&angle.expr, &is_angle).map_err(|e| {
                        ModelError::invalid(
                            self.path,
                            angle.location_of(e.span()),
                            ModelErrorKind::NotAnAngleCombination,
                            format!("{what} angle is not an angle combination: {e}; expected angles with rational coefficients, as `th1 - th2`"),
                        )
                    })?;
                    Some((inertia, angle))
                }
                (Some(_), None) => {
                    return Err(self.error(
                        span,
                        ModelErrorKind::Inconsistent,
                        format!("{what}: `inertia` needs `angle`, the body's orientation"),
                    ));
                }
                (None, Some(a)) => {
                    return Err(self.error(
                        a.span(),
                        ModelErrorKind::Inconsistent,
                        format!("{what}: `angle` without `inertia`: expected both or neither"),
                    ));
                }
            };
            bodies.push(Body {
                name,
                mass,
                com,
                rotation,
            });
        }

        let mut seen = HashSet::new();
        let mut points = Vec::new();
        for p in &raw.point {
            let p = p.get_ref();
            let name = self.unique(&p.name, "point", false, &mut seen)?;
            let at = self.position(&p.at, &format!("point `{}` at", name.name))?;
            points.push(Point { name, at });
        }
        let point_ref = |s: &Str, field: &str| -> Result<Name, ModelError> {
            if seen.contains(s.get_ref()) {
                Ok(self.name(s))
            } else {
                Err(self.error(
                    s.span(),
                    ModelErrorKind::UnknownReference,
                    format!(
                        "{field} = `{}`: expected the name of a declared [[point]]",
                        s.get_ref()
                    ),
                ))
            }
        };

        let st = raw.stance.get_ref();
        let mut friction = Vec::new();
        for f in st.friction.get_ref() {
            let law = match f.get_ref().as_str() {
                "none" => Friction::None,
                "tanh" => Friction::Tanh,
                "coulomb" => Friction::Coulomb,
                other => {
                    return Err(self.error(
                        f.span(),
                        ModelErrorKind::Toml,
                        format!(
                            "friction law `{other}`: expected \"none\", \"tanh\" or \"coulomb\""
                        ),
                    ));
                }
            };
            if friction.contains(&law) {
                return Err(self.error(
                    f.span(),
                    ModelErrorKind::Duplicate,
                    format!("friction law `{law}` is listed twice"),
                ));
            }
            friction.push(law);
        }
        if friction.is_empty() {
            return Err(self.error(
                st.friction.span(),
                ModelErrorKind::Count,
                "friction: expected at least one of \"none\", \"tanh\", \"coulomb\"".to_owned(),
            ));
        }
        let impact_raw = raw.impact.as_ref().map(|i| i.get_ref());
        let law = match impact_raw.and_then(|i| i.law.as_ref()) {
            None => ImpactLaw::Frictionless,
            Some(l) => match l.get_ref().as_str() {
                "frictionless" => ImpactLaw::Frictionless,
                "coulomb" => ImpactLaw::Coulomb,
                other => {
                    return Err(self.error(
                        l.span(),
                        ModelErrorKind::Toml,
                        format!("impact law `{other}`: expected \"frictionless\" or \"coulomb\""),
                    ));
                }
            },
        };
        let needs_mu0 = friction.iter().any(|f| *f != Friction::None) || law == ImpactLaw::Coulomb;
        let mu0 = match &st.mu0 {
            Some(m) => Some(self.parameter_ref(m, "mu0", false)?),
            None if needs_mu0 => {
                return Err(self.error(raw.stance.span(), ModelErrorKind::Inconsistent, "[stance] needs `mu0`, the friction coefficient parameter, for the friction laws listed (or the coulomb impact law)".to_owned()));
            }
            None => None,
        };
        let c = match &st.c {
            Some(c) => Some(self.parameter_ref(c, "c", false)?),
            None if friction.contains(&Friction::Tanh) => {
                return Err(self.error(raw.stance.span(), ModelErrorKind::Inconsistent, "[stance] needs `c`, the tanh law's sharpness parameter, since \"tanh\" is listed".to_owned()));
            }
            None => None,
        };
        let stance = Stance { friction, mu0, c };

        let sk = raw.strike.get_ref();
        let strike = Strike {
            point: point_ref(&sk.point, "strike point")?,
            guard: sk
                .guard
                .as_ref()
                .map(|g| self.expr(g, "strike guard", Use::Guard))
                .transpose()?,
            ahead: sk.ahead.unwrap_or(true),
        };

        let mut seen_falls = HashSet::new();
        let mut falls = Vec::new();
        for f in &raw.fall {
            let (span, f) = (f.span(), f.get_ref());
            let name = self.unique(&f.name, "fall", true, &mut seen_falls)?;
            let condition = match (&f.point, &f.guard) {
                (Some(p), None) => FallCondition::Point(point_ref(p, "fall point")?),
                (None, Some(g)) => FallCondition::Guard(self.expr(
                    g,
                    &format!("fall `{}` guard", name.name),
                    Use::Guard,
                )?),
                _ => {
                    return Err(self.error(
                        span,
                        ModelErrorKind::Inconsistent,
                        format!(
                            "fall `{}`: expected exactly one of `point` and `guard`",
                            name.name
                        ),
                    ));
                }
            };
            falls.push(Fall {
                name,
                condition,
                doc: f.doc.clone(),
            });
        }

        let mut relabel = Vec::new();
        if let Some(r) = &raw.relabel {
            for (key, value) in r.get_ref() {
                let index = coordinates
                    .iter()
                    .position(|c| &c.name.name == key.get_ref());
                let Some(index) = index.filter(|&i| i >= 2) else {
                    let why = if index.is_some() {
                        "the stance foot's coordinates move to the striking point and are not relabelled"
                    } else {
                        "expected a coordinate"
                    };
                    return Err(self.error(
                        key.span(),
                        ModelErrorKind::UnknownReference,
                        format!("relabel `{}`: {why}", key.get_ref()),
                    ));
                };
                let value = self.expr(
                    value,
                    &format!("relabel `{}`", key.get_ref()),
                    Use::Configuration,
                )?;
                relabel.push(Relabel {
                    coordinate: index,
                    value,
                });
            }
            relabel.sort_by_key(|r| r.coordinate);
        }

        let mut start = Vec::new();
        if let Some(r) = &raw.start {
            for (key, value) in r.get_ref() {
                let name = key.get_ref();
                let found = coordinates
                    .iter()
                    .position(|c| &c.name.name == name)
                    .map(|i| (i, false))
                    .or_else(|| match self.symbols.get(name) {
                        Some(sym) if sym.kind == SymbolKind::Velocity => Some((sym.index, true)),
                        _ => None,
                    });
                let Some((coordinate, velocity)) = found else {
                    return Err(self.error(
                        key.span(),
                        ModelErrorKind::UnknownReference,
                        format!("start `{name}`: expected a coordinate or a velocity"),
                    ));
                };
                let value = self.expr(value, &format!("start `{name}`"), Use::Constant)?;
                start.push(StartValue {
                    coordinate,
                    velocity,
                    value,
                });
            }
            start.sort_by_key(|v| (v.velocity, v.coordinate));
        }

        let impact = Impact {
            law,
            locks: impact_raw
                .map(|i| {
                    i.locks
                        .iter()
                        .map(|l| self.expr(l, "impact lock", Use::Configuration))
                        .collect()
                })
                .transpose()?
                .unwrap_or_default(),
            double_support: impact_raw.and_then(|i| i.double_support).unwrap_or(true),
        };

        let Actuation {
            inputs,
            control,
            outputs,
            descriptors,
        } = self.actuation(&raw, coordinates.len())?;

        let mut model = Model {
            path: self.path.to_owned(),
            name: raw.name.into_inner(),
            title: raw.title,
            reference: raw.reference,
            doc: raw.doc,
            coordinates,
            parameters,
            floor,
            bodies,
            points,
            stance,
            strike,
            falls,
            relabel,
            start,
            impact,
            inputs,
            control,
            outputs,
            descriptors,
            symbols: self.symbols,
        };
        let divisors = base_divisors(&model).map_err(|(e, at)| {
            ModelError::invalid(
                &model.path,
                at.location_of(e.span()),
                ModelErrorKind::NotAnAngleCombination,
                format!("an angle's coefficients: {e}"),
            )
        })?;
        for sym in &mut model.symbols.symbols {
            if let Some(d) = divisors.get(&sym.name) {
                sym.base_divisor = *d;
            }
        }
        Ok(model)
    }
}
