//! The sections after the declarations: floor, bodies, points, stance, strike, falls,
//! relabelling, start and impact, each checked against the symbol table (the actuated sections are in
//! [`control`](super::control)); then each angle's base-angle divisor.

use std::collections::HashSet;

use crate::model::angles::angle_combination;
use crate::model::control::Actuation;
use crate::model::divisors::base_divisors;
use crate::model::error::{ModelError, ModelErrorKind};
use crate::model::load::{Loader, Use, is_identifier, is_kebab_name};
use crate::model::raw::RawSection;
use crate::model::raw::{RawModel, Str};
use crate::model::symbols::SymbolKind;
use crate::model::types::{
    Body, Coordinate, Fall, FallCondition, Floor, Impact, Model, ModelExpr, Name, Parameter, Point,
    Relabel, Section, Stage, Stance, StartValue, Strike,
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
                format!(
                    "{field} = `{}`: expected an angle parameter (unit \"rad\")",
                    crate::limits::echo(name)
                ),
            )),
            _ => Err(self.error(
                s.span(),
                ModelErrorKind::UnknownReference,
                format!(
                    "{field} = `{}`: expected the name of a declared parameter",
                    crate::limits::echo(name)
                ),
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
                format!(
                    "{what} name `{}`: expected {expected}",
                    crate::limits::echo(name)
                ),
            ));
        }
        if name.len() > crate::limits::MAX_NAME_CHARS {
            return Err(self.error(
                s.span(),
                ModelErrorKind::Limit,
                format!(
                    "{what} name `{}` has {} characters: expected at most {}",
                    crate::limits::echo(name),
                    name.len(),
                    crate::limits::MAX_NAME_CHARS
                ),
            ));
        }
        if !seen.insert(name.clone()) {
            return Err(self.error(
                s.span(),
                ModelErrorKind::Duplicate,
                format!("{what} `{}` is declared twice", crate::limits::echo(name)),
            ));
        }
        Ok(self.name(s))
    }

    /// The index in `[q, qd]` of the state component `name` (a coordinate or a velocity).
    fn state_component(&self, name: &str, n: usize) -> Option<usize> {
        match self.symbols.get(name) {
            Some(sym) if sym.kind == SymbolKind::Coordinate => Some(sym.index),
            Some(sym) if sym.kind == SymbolKind::Velocity => Some(n + sym.index),
            _ => None,
        }
    }

    /// `[section]`: the free components and the others' values; every component but `x`,
    /// `z` and `zd` is exactly one of the two, and the values use parameters and free
    /// components only.
    fn section(
        &self,
        sec: &toml::Spanned<RawSection>,
        coordinates: &[Coordinate],
    ) -> Result<Section, ModelError> {
        let n = coordinates.len();
        let raw = sec.get_ref();
        let implied = |i: usize| i == 0 || i == 1 || i == n + 1;
        let component = |s: &Str, what: &str| -> Result<usize, ModelError> {
            let name = s.get_ref();
            let i = self.state_component(name, n).ok_or_else(|| {
                self.error(
                    s.span(),
                    ModelErrorKind::UnknownReference,
                    format!(
                        "section {what} `{}`: expected a coordinate or a velocity",
                        crate::limits::echo(name)
                    ),
                )
            })?;
            if implied(i) {
                return Err(self.error(
                    s.span(),
                    ModelErrorKind::Inconsistent,
                    format!(
                        "section {what} `{name}`: on the section the stance foot is at the origin \
                         (x = z = 0) and moves along the floor (zd = -xd tan phi); list the other \
                         components"
                    ),
                ));
            }
            Ok(i)
        };
        let mut seen = vec![false; 2 * n];
        let mut free = Vec::new();
        for s in raw.free.get_ref() {
            let i = component(s, "free")?;
            if std::mem::replace(&mut seen[i], true) {
                return Err(self.error(
                    s.span(),
                    ModelErrorKind::Duplicate,
                    format!(
                        "section: `{}` is listed twice",
                        crate::limits::echo(s.get_ref())
                    ),
                ));
            }
            free.push(i);
        }
        let mut given = Vec::new();
        for (key, value) in &raw.given {
            let i = component(key, "given")?;
            if std::mem::replace(&mut seen[i], true) {
                return Err(self.error(
                    key.span(),
                    ModelErrorKind::Duplicate,
                    format!(
                        "section: `{}` is both free and given, or given twice",
                        key.get_ref()
                    ),
                ));
            }
            let what = format!("section given `{}`", crate::limits::echo(key.get_ref()));
            let e = self.expr(value, &what, Use::Guard)?;
            for (name, span) in e.expr.symbols() {
                let ok = self
                    .symbols
                    .get(name)
                    .is_some_and(|s| s.kind == SymbolKind::Parameter)
                    || self
                        .state_component(name, n)
                        .is_some_and(|j| free.contains(&j));
                if !ok {
                    return Err(ModelError::invalid(
                        self.path,
                        e.location_of(span),
                        ModelErrorKind::SymbolNotAllowed,
                        format!(
                            "{what}: `{name}`: expected a parameter or a free component ({})",
                            raw.free
                                .get_ref()
                                .iter()
                                .map(|s| s.get_ref().as_str())
                                .collect::<Vec<_>>()
                                .join(", ")
                        ),
                    ));
                }
            }
            given.push((i, e));
        }
        given.sort_by_key(|(i, _)| *i);
        if let Some(i) = (0..2 * n).find(|&i| !implied(i) && !seen[i]) {
            let name = if i < n {
                coordinates[i].name.name.clone()
            } else {
                format!("{}d", coordinates[i - n].name.name)
            };
            return Err(self.error(
                sec.span(),
                ModelErrorKind::Inconsistent,
                format!("section: `{}` is neither free nor given; every component of the state but x, z and zd is one of the two", crate::limits::echo(&name)),
            ));
        }
        Ok(Section { free, given })
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
                        format!(
                            "impact law `{}`: expected \"frictionless\" or \"coulomb\"",
                            crate::limits::echo(other)
                        ),
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
                        format!("relabel `{}`: {why}", crate::limits::echo(key.get_ref())),
                    ));
                };
                let value = self.expr(
                    value,
                    &format!("relabel `{}`", crate::limits::echo(key.get_ref())),
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
                        format!(
                            "start `{}`: expected a coordinate or a velocity",
                            crate::limits::echo(name)
                        ),
                    ));
                };
                let value = self.expr(
                    value,
                    &format!("start `{}`", crate::limits::echo(name)),
                    Use::Constant,
                )?;
                start.push(StartValue {
                    coordinate,
                    velocity,
                    value,
                });
            }
            start.sort_by_key(|v| (v.velocity, v.coordinate));
        }

        let section = raw
            .section
            .as_ref()
            .map(|sec| self.section(sec, &coordinates))
            .transpose()?;

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
            power_until,
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
            section,
            impact,
            inputs,
            control,
            outputs,
            descriptors,
            power_until,
            symbols: self.symbols,
        };
        start_parameters_only_at_the_start(&model)?;
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

/// Checks that a parameter of stage `start` appears only in `[start]`: it is no field of the
/// generated `Params`, so no kernel, guard, desired trajectory or named role may read it.
fn start_parameters_only_at_the_start(model: &Model) -> Result<(), ModelError> {
    let is_start = |name: &str| {
        model
            .parameters
            .iter()
            .any(|p| p.name.name == name && p.stage == Stage::Start)
    };
    let named = [
        Some(&model.floor.gravity),
        model.floor.slope.as_ref(),
        model.stance.mu0.as_ref(),
        model.stance.c.as_ref(),
        model.control.as_ref().map(|c| &c.kp),
        model.control.as_ref().map(|c| &c.kd),
    ];
    if let Some(name) = named.into_iter().flatten().find(|n| is_start(&n.name)) {
        return Err(ModelError::invalid(
            &model.path,
            name.location,
            ModelErrorKind::SymbolNotAllowed,
            format!(
                "`{}` is a parameter of the start (stage \"start\"); expected a parameter of \
                 the dynamics",
                name.name
            ),
        ));
    }
    let mut exprs: Vec<&ModelExpr> = model.expressions().into_iter().map(|(_, e)| e).collect();
    exprs.extend(model.power_until.as_ref());
    if let Some(section) = &model.section {
        exprs.extend(section.given.iter().map(|(_, e)| e));
    }
    for e in exprs {
        if let Some((name, span)) = e.expr.symbols().into_iter().find(|(n, _)| is_start(n)) {
            return Err(ModelError::invalid(
                &model.path,
                e.location_of(span),
                ModelErrorKind::SymbolNotAllowed,
                format!(
                    "`{name}` is a parameter of the start (stage \"start\"): it may appear in \
                     [start] only"
                ),
            ));
        }
    }
    Ok(())
}
