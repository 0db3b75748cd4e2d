//! The loader: model file text to a checked [`Model`], or the first error with its file, line,
//! column and what was expected.
//!
//! serde reads the layout (`raw.rs`), keeping the span of every name and
//! expression; this file then checks the declarations (names, units, ranges) and builds the
//! symbol table, and `sections.rs` and `control.rs` check the rest against it. Beyond
//! the format's own list of checks, each expression may use only the symbols its field is
//! about: positions, masses, inertias, forces, outputs, locks and the relabelling use
//! coordinates and parameters; guards parse with velocities and `t` too, which the validation
//! (`validate.rs`, run last) then refuses with their place; desired trajectories use parameters
//! only. The model's size is checked first (`size.rs`), against [`crate::limits`].

use std::ops::Range;
use std::path::Path;

use crate::limits::{MAX_FILE_BYTES, MAX_NAME_CHARS, echo};
use crate::model::angles::{angle_outside_trig, check_trig_arguments, zero_divisor};
use crate::model::error::{ModelError, ModelErrorKind};
use crate::model::fields::param_fields;
use crate::model::interval::Interval;
use crate::model::parse::{ParseErrorKind, parse_expr};
use crate::model::raw::{RawModel, Str};
use crate::model::reserved::reserved_because;
use crate::model::source::SourceMap;
use crate::model::symbols::{SymbolKind, SymbolTable};
use crate::model::types::{
    Coordinate, CoordinateUnit, Model, ModelExpr, Name, Parameter, Stage, locate,
};

/// The names of the expression language no declaration may take (besides every coordinate's
/// velocity and acceleration); [`reserved`](crate::model::reserved) has every reserved name.
pub const RESERVED: [&str; 4] = ["t", "mu", "sin", "cos"];

/// The symbols an expression may use, and whether it is a position.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Use {
    /// A centre of mass or a point: coordinates and parameters, angles only inside sin/cos.
    Position,
    /// Coordinates and parameters.
    Configuration,
    /// Coordinates, velocities, parameters and `t`.
    Guard,
    /// Parameters only.
    Constant,
}

impl Use {
    fn allows(self, kind: SymbolKind) -> bool {
        match self {
            Use::Position | Use::Configuration => {
                matches!(kind, SymbolKind::Coordinate | SymbolKind::Parameter)
            }
            Use::Guard => matches!(
                kind,
                SymbolKind::Coordinate
                    | SymbolKind::Velocity
                    | SymbolKind::Parameter
                    | SymbolKind::Time
            ),
            Use::Constant => kind == SymbolKind::Parameter,
        }
    }

    fn expected(self) -> &'static str {
        match self {
            Use::Position | Use::Configuration => "a coordinate or a parameter",
            Use::Guard => "a coordinate, a velocity, a parameter or `t`",
            Use::Constant => "a parameter",
        }
    }
}

impl Model {
    /// Loads and checks a model file.
    ///
    /// # Errors
    ///
    /// [`ModelError::Read`] if the file cannot be read, is not a regular file or is longer
    /// than [`MAX_FILE_BYTES`], else the first problem found, with its line and column.
    pub fn from_file(path: &Path) -> Result<Model, ModelError> {
        let shown = path.display().to_string();
        let text = crate::read::read_input(path, MAX_FILE_BYTES).map_err(|e| ModelError::Read {
            path: shown.clone(),
            source: e.into(),
        })?;
        Model::from_toml(&text, &shown)
    }

    /// Checks a model given as TOML text; `path` names it in errors.
    ///
    /// # Errors
    ///
    /// The first problem found, with its line and column.
    pub fn from_toml(text: &str, path: &str) -> Result<Model, ModelError> {
        let cx = Loader {
            path,
            map: SourceMap::new(text),
            symbols: SymbolTable::default(),
        };
        let raw: RawModel = toml::from_str(text).map_err(|e| {
            let offset = e.span().map_or(0, |s| s.start);
            cx.error_at(
                offset,
                ModelErrorKind::Toml,
                crate::limits::echo_at_most(e.message().trim(), 20 * crate::limits::MAX_ECHO_CHARS),
            )
        })?;
        cx.build(raw)
    }
}

/// The state of one load: the file, and the symbols declared so far.
pub(crate) struct Loader<'a> {
    pub(crate) path: &'a str,
    pub(crate) map: SourceMap<'a>,
    pub(crate) symbols: SymbolTable,
}

/// Whether `s` is an identifier: an ASCII letter, then ASCII letters, digits and `_`.
#[must_use]
pub fn is_identifier(s: &str) -> bool {
    let mut chars = s.chars();
    chars.next().is_some_and(|c| c.is_ascii_alphabetic())
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Whether `s` is a model or failure name, `[a-z][a-z0-9-]*`.
#[must_use]
pub fn is_kebab_name(s: &str) -> bool {
    let mut chars = s.chars();
    chars.next().is_some_and(|c| c.is_ascii_lowercase())
        && chars.all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-')
}

impl Loader<'_> {
    /// Checks that a declared name is an identifier of at most [`MAX_NAME_CHARS`] characters,
    /// echoing a bad one escaped and cut.
    pub(crate) fn check_name(&self, s: &Str) -> Result<(), ModelError> {
        let name = s.get_ref();
        if !is_identifier(name) {
            return Err(self.error(
                s.span(),
                ModelErrorKind::BadName,
                format!(
                    "`{}` is not a name: expected an ASCII letter followed by letters, digits or `_`",
                    echo(name)
                ),
            ));
        }
        if name.len() > MAX_NAME_CHARS {
            return Err(self.error(
                s.span(),
                ModelErrorKind::Limit,
                format!(
                    "the name `{}` has {} characters: expected at most {MAX_NAME_CHARS}",
                    echo(name),
                    name.len()
                ),
            ));
        }
        Ok(())
    }

    /// An error at a byte offset of the file.
    pub(crate) fn error_at(
        &self,
        offset: usize,
        kind: ModelErrorKind,
        message: String,
    ) -> ModelError {
        ModelError::invalid(self.path, self.map.location(offset), kind, message)
    }

    /// An error at the start of a spanned value.
    pub(crate) fn error(
        &self,
        span: Range<usize>,
        kind: ModelErrorKind,
        message: String,
    ) -> ModelError {
        self.error_at(span.start, kind, message)
    }

    /// A name with its location.
    pub(crate) fn name(&self, s: &Str) -> Name {
        Name {
            name: s.get_ref().clone(),
            location: self.map.location(s.span().start),
        }
    }

    /// Checks a declared identifier: its shape, reserved names, and that it is new.
    fn declare(
        &mut self,
        s: &Str,
        kind: SymbolKind,
        index: usize,
        angle: bool,
    ) -> Result<(), ModelError> {
        let name = s.get_ref();
        self.check_name(s)?;
        let argument = matches!(
            kind,
            SymbolKind::Coordinate | SymbolKind::Input | SymbolKind::Aux
        );
        if argument && name.chars().any(|c| c.is_ascii_uppercase()) {
            return Err(self.error(
                s.span(),
                ModelErrorKind::BadName,
                format!(
                    "`{name}`: {} is an argument of the generated functions, so its name is \
                     lower case (`{}`)",
                    kind.describe(),
                    name.to_ascii_lowercase()
                ),
            ));
        }
        if let Some(why) = reserved_because(name) {
            return Err(self.error(
                s.span(),
                ModelErrorKind::Reserved,
                format!(
                    "`{name}` is reserved: {why}; expected another name for {} \
                     (docs/model-format.md lists the reserved names)",
                    kind.describe()
                ),
            ));
        }
        if let Some(existing) = self.symbols.get(name) {
            let derived = match existing.kind {
                SymbolKind::Velocity => Some("velocity"),
                SymbolKind::Acceleration => Some("acceleration"),
                _ => None,
            };
            let (kind, message) = match derived {
                Some(what) => {
                    let coordinate = self
                        .symbols
                        .symbols
                        .get(existing.index)
                        .map_or("", |c| c.name.as_str());
                    (
                        ModelErrorKind::Reserved,
                        format!(
                            "`{name}` is reserved: it is the {what} of coordinate `{coordinate}`"
                        ),
                    )
                }
                None => (
                    ModelErrorKind::Duplicate,
                    format!(
                        "`{name}` is declared twice: it is already {}",
                        existing.kind.describe()
                    ),
                ),
            };
            return Err(self.error(s.span(), kind, message));
        }
        if kind == SymbolKind::Parameter {
            let mut names: Vec<&str> = self
                .symbols
                .symbols
                .iter()
                .filter(|o| o.kind == SymbolKind::Parameter)
                .map(|o| o.name.as_str())
                .collect();
            names.push(name);
            let fields = param_fields(&names);
            let clash = (0..fields.len()).find_map(|i| {
                (i + 1..fields.len())
                    .find(|&j| fields[i] == fields[j])
                    .map(|j| (names[i], names[j], &fields[i]))
            });
            if let Some((a, b, field)) = clash {
                return Err(self.error(
                    s.span(),
                    ModelErrorKind::Duplicate,
                    format!(
                        "parameters `{a}` and `{b}` would both be the field `{field}` of the \
                         generated `Params` (docs/model-format.md, \"Names\"): rename one"
                    ),
                ));
            }
        }
        self.symbols.push(name, kind, index, angle);
        Ok(())
    }

    /// Parses and checks one expression of the file.
    pub(crate) fn expr(&self, s: &Str, what: &str, use_: Use) -> Result<ModelExpr, ModelError> {
        let (location, verbatim) = self.map.string_start(s.span(), s.get_ref());
        let text = s.get_ref().clone();
        let fail = |e: &ModelExpr, span, kind, message: String| {
            ModelError::invalid(self.path, e.location_of(span), kind, message)
        };
        let expr = parse_expr(&text).map_err(|e| {
            let kind = match e.kind {
                ParseErrorKind::NumberTooLong { .. } => ModelErrorKind::Limit,
                _ => ModelErrorKind::Syntax,
            };
            ModelError::invalid(
                self.path,
                locate(&text, location, verbatim, e.span),
                kind,
                format!("{what}: {e}"),
            )
        })?;
        let me = ModelExpr {
            text,
            expr,
            location,
            verbatim,
        };
        for (name, span) in me.expr.symbols() {
            match self.symbols.get(name) {
                None => {
                    return Err(fail(
                        &me,
                        span,
                        ModelErrorKind::UnknownSymbol,
                        format!(
                            "{what}: unknown symbol `{}`: expected {}",
                            echo(name),
                            use_.expected()
                        ),
                    ));
                }
                Some(sym) if !use_.allows(sym.kind) => {
                    return Err(fail(
                        &me,
                        span,
                        ModelErrorKind::SymbolNotAllowed,
                        format!(
                            "{what}: `{name}` is {}; expected {}",
                            sym.kind.describe(),
                            use_.expected()
                        ),
                    ));
                }
                Some(_) => {}
            }
        }
        let is_angle = |n: &str| self.symbols.get(n).is_some_and(|s| s.angle);
        if let Err((func, err)) = check_trig_arguments(&me.expr, &is_angle) {
            return Err(fail(
                &me,
                err.span(),
                ModelErrorKind::NotAnAngleCombination,
                format!(
                    "{what}: `{}` of something that is not an angle combination: {err}; expected angles with rational coefficients, as `th1 - alpha/2`",
                    func.name()
                ),
            ));
        }
        if let Some(span) = zero_divisor(&me.expr) {
            return Err(fail(
                &me,
                span,
                ModelErrorKind::DivisionByZero,
                format!("{what}: division by zero"),
            ));
        }
        if use_ == Use::Position
            && let Some((name, span)) = angle_outside_trig(&me.expr, &is_angle)
        {
            return Err(fail(
                &me,
                span,
                ModelErrorKind::AngleAsLength,
                format!(
                    "{what}: an angle used as a length: `{name}` is an angle; a position uses angles only inside sin and cos"
                ),
            ));
        }
        Ok(me)
    }

    /// The whole model.
    fn build(mut self, raw: RawModel) -> Result<Model, ModelError> {
        if *raw.format.get_ref() != 1 {
            return Err(self.error(
                raw.format.span(),
                ModelErrorKind::Format,
                format!(
                    "format {} is not supported: expected 1",
                    raw.format.get_ref()
                ),
            ));
        }
        if !is_kebab_name(raw.name.get_ref()) || raw.name.get_ref().len() > MAX_NAME_CHARS {
            return Err(self.error(
                raw.name.span(),
                ModelErrorKind::BadName,
                format!(
                    "model name `{}`: expected [a-z][a-z0-9-]*, at most {MAX_NAME_CHARS} characters",
                    echo(raw.name.get_ref())
                ),
            ));
        }
        self.check_size(&raw)?;
        let coordinates = self.coordinates(&raw)?;
        let parameters = self.parameters(&raw)?;
        self.later_symbols(&raw)?;
        let model = self.sections(raw, coordinates, parameters)?;
        crate::model::validate::validate(&model)?;
        Ok(model)
    }

    fn coordinates(&mut self, raw: &RawModel) -> Result<Vec<Coordinate>, ModelError> {
        let list = raw.coordinate.get_ref();
        if list.len() < 3 {
            return Err(self.error(
                raw.coordinate.span(),
                ModelErrorKind::Count,
                format!(
                    "{} [[coordinate]]: expected at least three (x, z, then an angle or length)",
                    list.len()
                ),
            ));
        }
        // The velocity and acceleration names first, so that a coordinate taking one is
        // reported as reserved wherever it is declared.
        let mut out = Vec::with_capacity(list.len());
        for (i, c) in list.iter().enumerate() {
            let c = c.get_ref();
            let unit = match c.unit.get_ref().as_str() {
                "m" => CoordinateUnit::Length,
                "rad" => CoordinateUnit::Angle,
                other => {
                    return Err(self.error(
                        c.unit.span(),
                        ModelErrorKind::Toml,
                        format!(
                            "coordinate unit `{}`: expected \"m\" (a length) or \"rad\" (an angle)",
                            echo(other)
                        ),
                    ));
                }
            };
            if i < 2 && unit != CoordinateUnit::Length {
                return Err(self.error(
                    c.unit.span(),
                    ModelErrorKind::Inconsistent,
                    format!(
                        "coordinate `{}` must be a length (unit \"m\"): the first two coordinates are the stance foot's x and z",
                        echo(c.name.get_ref())
                    ),
                ));
            }
            out.push(Coordinate {
                name: self.name(&c.name),
                unit,
                doc: c.doc.clone(),
                latex: c.latex.clone(),
            });
        }
        for c in list {
            let name = c.get_ref().name.get_ref();
            for other in list {
                let o = other.get_ref().name.get_ref();
                if name == &format!("{o}d") || name == &format!("{o}dd") {
                    return Err(self.error(
                        c.get_ref().name.span(),
                        ModelErrorKind::Reserved,
                        format!("`{}` is reserved: it is the velocity or acceleration of coordinate `{o}`", crate::limits::echo(name)),
                    ));
                }
            }
        }
        for (i, (c, typed)) in list.iter().zip(&out).enumerate() {
            self.declare(
                &c.get_ref().name,
                SymbolKind::Coordinate,
                i,
                typed.unit == CoordinateUnit::Angle,
            )?;
        }
        for (c, suffix) in list.iter().flat_map(|c| [(c, "d"), (c, "dd")]) {
            let derived = format!("{}{suffix}", c.get_ref().name.get_ref());
            if let Some(why) = reserved_because(&derived) {
                return Err(self.error(
                    c.get_ref().name.span(),
                    ModelErrorKind::Reserved,
                    format!(
                        "coordinate `{}` gives the rate `{derived}`, and `{derived}` is \
                         reserved: {why}; expected another name for the coordinate",
                        c.get_ref().name.get_ref()
                    ),
                ));
            }
        }
        for (suffix, kind) in [
            ("d", SymbolKind::Velocity),
            ("dd", SymbolKind::Acceleration),
        ] {
            for (i, c) in out.iter().enumerate() {
                self.symbols
                    .push(&format!("{}{suffix}", c.name.name), kind, i, false);
            }
        }
        Ok(out)
    }

    fn parameters(&mut self, raw: &RawModel) -> Result<Vec<Parameter>, ModelError> {
        let mut out = Vec::with_capacity(raw.parameter.len());
        for (i, p) in raw.parameter.iter().enumerate() {
            let p = p.get_ref();
            self.declare(&p.name, SymbolKind::Parameter, i, p.unit == "rad")?;
            let range: Interval = p.range.get_ref().parse().map_err(|e| {
                self.error(
                    p.range.span(),
                    ModelErrorKind::Range,
                    format!("range of `{}`: {e}", p.name.get_ref()),
                )
            })?;
            let default = *p.default.get_ref();
            if !range.contains(default) {
                return Err(self.error(
                    p.default.span(),
                    ModelErrorKind::Range,
                    format!(
                        "default of `{}` = {default} lies outside its range {range}: expected a \
                         finite value inside it",
                        p.name.get_ref()
                    ),
                ));
            }
            let stage = match p.stage.as_ref().map(|s| s.get_ref().as_str()) {
                None | Some("run") => Stage::Run,
                Some("generation") => Stage::Generation,
                Some("start") => Stage::Start,
                Some(other) => {
                    let span = p.stage.as_ref().map_or(0..0, Str::span);
                    return Err(self.error(
                        span,
                        ModelErrorKind::Toml,
                        format!(
                            "stage `{}`: expected \"run\", \"generation\" or \"start\"",
                            echo(other)
                        ),
                    ));
                }
            };
            out.push(Parameter {
                name: self.name(&p.name),
                unit: p.unit.clone(),
                doc: p.doc.clone(),
                range,
                default,
                stage,
                latex: p.latex.clone(),
            });
        }
        Ok(out)
    }

    /// Inputs, `mu`, the outputs' auxiliary inputs and `t`, in the canonical order.
    fn later_symbols(&mut self, raw: &RawModel) -> Result<(), ModelError> {
        for (i, input) in raw.input.iter().enumerate() {
            self.declare(&input.get_ref().name, SymbolKind::Input, i, false)?;
        }
        self.symbols.push("mu", SymbolKind::Mu, 0, false);
        for (i, output) in raw.output.iter().enumerate() {
            let o = output.get_ref();
            match &o.aux {
                Some(aux) => self.declare(aux, SymbolKind::Aux, i, false)?,
                None => {
                    let aux = format!("v_{}", o.name.get_ref());
                    if is_identifier(o.name.get_ref())
                        && !self.symbols.push(&aux, SymbolKind::Aux, i, false)
                    {
                        return Err(self.error(
                            o.name.span(),
                            ModelErrorKind::Duplicate,
                            format!("the output's auxiliary input `{aux}` (the default `v_<name>`) is already declared; give `aux`"),
                        ));
                    }
                }
            }
        }
        self.symbols.push("t", SymbolKind::Time, 0, false);
        Ok(())
    }
}
