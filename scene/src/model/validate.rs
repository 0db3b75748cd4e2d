//! The physical sense of a loaded model, checked at the end of loading and before any
//! derivation, every error with the file, line and column of the field and what was expected:
//!
//! - a mass or an inertia is an expression of the parameters only (no coordinate), finite and
//!   positive at the defaults and, by interval arithmetic, over the parameters' whole ranges;
//! - a guard (the strike's, a fall's) is a function of the configuration: coordinates and
//!   parameters, no velocity or time (the simulator evaluates it from the coordinates alone),
//!   with at least one coordinate, and not zero at every configuration;
//! - `[start]` puts the stance foot on the floor (`z = -x tan(slope)`) moving along it
//!   (`zd = -xd tan(slope)`), to [`START_TOLERANCE`];
//! - every `[start]` value, `[section]` value, desired trajectory and `power_until` is finite
//!   at the defaults; a ramp's `duration` and `power_until` are positive at the defaults and
//!   over the ranges.

use crate::model::enclosure::{Enclosure, End, enclose};
use crate::model::error::{Location, ModelError, ModelErrorKind};
use crate::model::symbols::SymbolKind;
use crate::model::types::{Desired, FallCondition, Model, ModelExpr};

/// How far the start's foot may be from the floor, and its velocity from the floor's
/// direction, relative to the values' size (`max(1, |x|, |z|)`): the start values are written
/// as decimals or derived from the parameters in floating point, so a start exactly on the
/// floor in exact arithmetic is so to a few ulps; 1e-9 is far above that and far below any
/// height that matters to a walk (a nanometre).
pub const START_TOLERANCE: f64 = 1e-9;

/// How small a guard may be at every sampled configuration and still count as not zero
/// everywhere: a guard that cancels exactly (`th - th`, `sin(th)^2 + cos(th)^2 - 1`) is zero to
/// rounding, a few 1e-16, at every configuration.
const ZERO_GUARD: f64 = 1e-12;

/// The configurations a guard is sampled at.
const GUARD_SAMPLES: usize = 16;

/// Checks the model's physical sense.
pub(crate) fn validate(model: &Model) -> Result<(), ModelError> {
    let v = Validator { model };
    for b in &model.bodies {
        let what = format!("body `{}`", b.name.name);
        v.constant_positive(&b.mass, &format!("{what} mass"), "a mass")?;
        if let Some((inertia, _)) = &b.rotation {
            v.constant_positive(inertia, &format!("{what} inertia"), "a moment of inertia")?;
        }
    }
    if let Some(g) = &model.strike.guard {
        v.guard(g, "strike guard")?;
    }
    for f in &model.falls {
        if let FallCondition::Guard(g) = &f.condition {
            v.guard(g, &format!("fall `{}` guard", f.name.name))?;
        }
    }
    v.start()?;
    for o in &model.outputs {
        let what = format!("output `{}` desired", o.name.name);
        match &o.desired {
            Desired::Quintic { from, to, duration } => {
                v.finite(from, &format!("{what} from"))?;
                v.finite(to, &format!("{what} to"))?;
                v.constant_positive(duration, &format!("{what} duration"), "a duration")?;
            }
            Desired::Hold { value } => {
                v.finite(value, &format!("{what} value"))?;
            }
            Desired::Bezier { points, duration } => {
                for (k, p) in points.iter().enumerate() {
                    v.finite(p, &format!("{what} points[{k}]"))?;
                }
                v.constant_positive(duration, &format!("{what} duration"), "a duration")?;
            }
        }
    }
    if let Some(p) = &model.power_until {
        v.constant_positive(p, "descriptors power_until", "a time after the impact")?;
    }
    Ok(())
}

struct Validator<'a> {
    model: &'a Model,
}

impl Validator<'_> {
    fn error(&self, at: Location, kind: ModelErrorKind, message: String) -> ModelError {
        ModelError::invalid(&self.model.path, at, kind, message)
    }

    /// A parameter's default.
    fn default(&self, name: &str) -> Option<f64> {
        self.model
            .parameters
            .iter()
            .find(|p| p.name.name == name)
            .map(|p| p.default)
    }

    /// A parameter's range as an enclosure.
    fn range(&self, name: &str) -> Option<Enclosure> {
        let p = self.model.parameters.iter().find(|p| p.name.name == name)?;
        Some(Enclosure {
            lo: End {
                value: p.range.low.value(),
                open: !p.range.low_closed,
            },
            hi: End {
                value: p.range.high.value(),
                open: !p.range.high_closed,
            },
        })
    }

    fn kind(&self, name: &str) -> Option<SymbolKind> {
        self.model.symbol(name).map(|s| s.kind)
    }

    /// A value at the defaults that is finite.
    fn finite(&self, e: &ModelExpr, what: &str) -> Result<f64, ModelError> {
        self.finite_with(e, what, &|n| self.default(n), "the parameters' defaults")
    }

    fn finite_with(
        &self,
        e: &ModelExpr,
        what: &str,
        value: &dyn Fn(&str) -> Option<f64>,
        at: &str,
    ) -> Result<f64, ModelError> {
        match e.expr.eval(value) {
            Some(x) if x.is_finite() => Ok(x),
            other => Err(self.error(
                e.location,
                ModelErrorKind::Physics,
                format!(
                    "{what} = `{}` is {} at {at}: expected a finite value",
                    crate::limits::echo(&e.text),
                    other.map_or_else(|| "undefined".to_owned(), |x| x.to_string())
                ),
            )),
        }
    }

    /// An expression of the parameters alone, finite and positive at the defaults and over
    /// the parameters' ranges.
    fn constant_positive(&self, e: &ModelExpr, what: &str, noun: &str) -> Result<(), ModelError> {
        for (name, span) in e.expr.symbols() {
            if let Some(kind) = self.kind(name)
                && kind != SymbolKind::Parameter
            {
                return Err(self.error(
                    e.location_of(span),
                    ModelErrorKind::SymbolNotAllowed,
                    format!(
                        "{what}: `{name}` is {}; {noun} is a constant of the model: expected \
                         parameters and numbers only",
                        kind.describe()
                    ),
                ));
            }
        }
        let x = self.finite(e, what)?;
        if x <= 0.0 {
            return Err(self.error(
                e.location,
                ModelErrorKind::Physics,
                format!(
                    "{what} = `{}` is {x} at the parameters' defaults: expected {noun} > 0",
                    crate::limits::echo(&e.text)
                ),
            ));
        }
        let shown = enclose(&e.expr, &|n| self.range(n));
        if !shown.is_some_and(|r| r.positive()) {
            let ranges: Vec<String> = e
                .expr
                .symbols()
                .into_iter()
                .map(|(n, _)| n)
                .collect::<std::collections::BTreeSet<_>>()
                .into_iter()
                .filter_map(|n| {
                    let p = self.model.parameters.iter().find(|p| p.name.name == n)?;
                    Some(format!("{n} in {}", p.range))
                })
                .collect();
            return Err(self.error(
                e.location,
                ModelErrorKind::Physics,
                format!(
                    "{what} = `{}` is not shown positive over the parameters' ranges ({}): \
                     expected {noun} > 0 for every admissible value; narrow the ranges (a mass \
                     parameter's range is \"(0, inf)\"), or give the combination its own \
                     parameter",
                    crate::limits::echo(&e.text),
                    ranges.join(", ")
                ),
            ));
        }
        Ok(())
    }

    /// A guard: coordinates and parameters, at least one coordinate, not zero at every
    /// configuration.
    fn guard(&self, e: &ModelExpr, what: &str) -> Result<(), ModelError> {
        let mut coordinates = 0;
        for (name, span) in e.expr.symbols() {
            match self.kind(name) {
                Some(SymbolKind::Coordinate) => coordinates += 1,
                Some(SymbolKind::Parameter) | None => {}
                Some(kind) => {
                    return Err(self.error(
                        e.location_of(span),
                        ModelErrorKind::SymbolNotAllowed,
                        format!(
                            "{what}: `{name}` is {}; expected a coordinate or a parameter (a \
                             guard is a function of the configuration, evaluated from the \
                             coordinates alone)",
                            kind.describe()
                        ),
                    ));
                }
            }
        }
        if coordinates == 0 {
            return Err(self.error(
                e.location,
                ModelErrorKind::Physics,
                format!(
                    "{what} = `{}` has no coordinate: expected an expression of the \
                     coordinates that changes sign during a stance (one of the parameters \
                     alone never does)",
                    crate::limits::echo(&e.text)
                ),
            ));
        }
        let n = self.model.coordinates.len();
        let mut seed: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut largest: f64 = 0.0;
        for _ in 0..GUARD_SAMPLES {
            let q: Vec<f64> = (0..n)
                .map(|_| {
                    // A 64-bit LCG (Knuth's MMIX constants): reproducible samples in [-1.5, 1.5).
                    seed = seed
                        .wrapping_mul(6_364_136_223_846_793_005)
                        .wrapping_add(1_442_695_040_888_963_407);
                    (seed >> 11) as f64 / (1_u64 << 53) as f64 * 3.0 - 1.5
                })
                .collect();
            let value = |name: &str| match self.model.symbol(name) {
                Some(s) if s.kind == SymbolKind::Coordinate => q.get(s.index).copied(),
                _ => self.default(name),
            };
            if let Some(x) = e.expr.eval(&value)
                && x.is_finite()
            {
                largest = largest.max(x.abs());
            } else {
                // Not finite somewhere: not zero everywhere (the simulator stops at a
                // non-finite guard as at any non-finite value).
                largest = f64::INFINITY;
            }
        }
        if largest <= ZERO_GUARD {
            return Err(self.error(
                e.location,
                ModelErrorKind::Physics,
                format!(
                    "{what} = `{}` is zero at every configuration tried (at most {largest:e} at \
                     {GUARD_SAMPLES} configurations, parameters at their defaults): expected an \
                     expression that is positive during a stance and falls through zero at the \
                     event",
                    crate::limits::echo(&e.text)
                ),
            ));
        }
        Ok(())
    }

    /// `[start]`: finite values, the foot on the floor moving along it; `[section]` values
    /// finite at the start.
    fn start(&self) -> Result<(), ModelError> {
        let n = self.model.coordinates.len();
        let mut state = vec![0.0; 2 * n];
        for s in &self.model.start {
            let name = if s.velocity {
                format!("{}d", self.model.coordinates[s.coordinate].name.name)
            } else {
                self.model.coordinates[s.coordinate].name.name.clone()
            };
            let x = self.finite(&s.value, &format!("start `{name}`"))?;
            state[s.coordinate + if s.velocity { n } else { 0 }] = x;
        }
        let tan = self
            .model
            .floor
            .slope
            .as_ref()
            .and_then(|s| self.default(&s.name))
            .map_or(0.0, f64::tan);
        let entry = |i: usize, velocity: bool| {
            self.model
                .start
                .iter()
                .find(|s| s.coordinate == i && s.velocity == velocity)
        };
        let slope = match &self.model.floor.slope {
            Some(s) => format!("-x tan({})", s.name),
            None => "0".to_owned(),
        };
        for (x, z, what) in [(0, 1, "position"), (n, n + 1, "velocity")] {
            let (xv, zv) = (state[x], state[z]);
            let off = zv + xv * tan;
            let scale = 1.0_f64.max(xv.abs()).max(zv.abs());
            if off.abs() > START_TOLERANCE * scale {
                let velocity = what == "velocity";
                let entry = entry(1, velocity)
                    .or_else(|| entry(0, velocity))
                    .map(|s| s.value.location);
                let (xn, zn) = (
                    &self.model.coordinates[0].name.name,
                    &self.model.coordinates[1].name.name,
                );
                let (xs, zs) = if what == "position" {
                    (xn.clone(), zn.clone())
                } else {
                    (format!("{xn}d"), format!("{zn}d"))
                };
                return Err(self.error(
                    entry.unwrap_or(Location { line: 1, column: 1 }),
                    ModelErrorKind::Physics,
                    format!(
                        "start: the stance foot's {what} ({xs} = {xv}, {zs} = {zv}) is {off:e} off \
                         the floor at the parameters' defaults: expected the foot on the floor \
                         moving along it, {zs} = {} (to {START_TOLERANCE:e} relative)",
                        slope.replace('x', &xs)
                    ),
                ));
            }
        }
        if let Some(section) = &self.model.section {
            let value = |name: &str| match self.model.symbol(name) {
                Some(s) if s.kind == SymbolKind::Coordinate => state.get(s.index).copied(),
                Some(s) if s.kind == SymbolKind::Velocity => state.get(n + s.index).copied(),
                _ => self.default(name),
            };
            for (i, e) in &section.given {
                let name = if *i < n {
                    self.model.coordinates[*i].name.name.clone()
                } else {
                    format!("{}d", self.model.coordinates[*i - n].name.name)
                };
                self.finite_with(
                    e,
                    &format!("section given `{name}`"),
                    &value,
                    "the parameters' defaults and the start",
                )?;
            }
        }
        Ok(())
    }
}
