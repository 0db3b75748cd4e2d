//! The typed model: what a model file says, checked, with every expression parsed and every
//! name resolved. Built only by the loader ([`Model::from_toml`](crate::model::Model::from_toml)).

use crate::model::error::Location;
use crate::model::expr::{Expr, Span};
use crate::model::interval::Interval;
use crate::model::symbols::{Symbol, SymbolTable};
use crate::structure::{Friction, ImpactLaw};

/// An expression of the file: its text, its tree, and where the text starts in the file.
#[derive(Clone, Debug)]
pub struct ModelExpr {
    /// The string as written (after TOML unescaping).
    pub text: String,
    /// The parsed tree; spans are byte offsets into `text`.
    pub expr: Expr,
    /// Where the string's text starts in the file (its opening quote when it has escapes or
    /// spans lines).
    pub location: Location,
    /// Whether `text` stands in the file character for character from `location`.
    pub(crate) verbatim: bool,
}

impl ModelExpr {
    /// The file location of a span of `text`: exact for plain strings; the string's start
    /// when the string has escapes or spans lines.
    #[must_use]
    pub fn location_of(&self, span: Span) -> Location {
        locate(&self.text, self.location, self.verbatim, span)
    }
}

/// The file location of byte `span.start` of a string `text` whose text starts at `start`
/// (exact when `verbatim`, else the string's start).
pub(crate) fn locate(text: &str, start: Location, verbatim: bool, span: Span) -> Location {
    if !verbatim {
        return start;
    }
    let offset = span.start.min(text.len());
    let chars = text.get(..offset).map_or(0, |s| s.chars().count());
    Location {
        line: start.line,
        column: start.column + chars,
    }
}

/// A name with the place it is declared.
#[derive(Clone, PartialEq, Eq, Debug)]
pub struct Name {
    /// The name.
    pub name: String,
    /// Where it is written.
    pub location: Location,
}

/// Whether a coordinate is a length or an angle.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub enum CoordinateUnit {
    /// `"m"`.
    Length,
    /// `"rad"`.
    Angle,
}

/// A generalised coordinate (`[[coordinate]]`).
#[derive(Clone, Debug)]
pub struct Coordinate {
    /// Its name.
    pub name: Name,
    /// Length or angle.
    pub unit: CoordinateUnit,
    /// What it measures.
    pub doc: String,
    /// LaTeX (default: the name).
    pub latex: Option<String>,
}

/// When a parameter gets its value.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Default)]
pub enum Stage {
    /// A field of the generated `Params`, given at run time.
    #[default]
    Run,
    /// Substituted into the kernels when they are generated.
    Generation,
    /// A value of the start of a walk only (`[start]`): in no kernel and no other expression,
    /// so not a field of the generated `Params` (the paper's initial angular velocity
    /// `omega0`, Eq. 33).
    Start,
}

/// A parameter (`[[parameter]]`).
#[derive(Clone, Debug)]
pub struct Parameter {
    /// Its name.
    pub name: Name,
    /// The unit as written; `"rad"` makes it an angle.
    pub unit: String,
    /// One line.
    pub doc: String,
    /// The valid values.
    pub range: Interval,
    /// The default value, inside `range`.
    pub default: f64,
    /// When it gets its value.
    pub stage: Stage,
    /// LaTeX.
    pub latex: Option<String>,
}

impl Parameter {
    /// Whether it is an angle (unit `rad`).
    #[must_use]
    pub fn is_angle(&self) -> bool {
        self.unit == "rad"
    }
}

/// The floor (`[floor]`).
#[derive(Clone, Debug)]
pub struct Floor {
    /// The gravity parameter.
    pub gravity: Name,
    /// The slope angle parameter; `None`: level.
    pub slope: Option<Name>,
}

/// A rigid body (`[[body]]`).
#[derive(Clone, Debug)]
pub struct Body {
    /// Its name.
    pub name: Name,
    /// Its mass.
    pub mass: ModelExpr,
    /// Its centre of mass, `[x, z]`.
    pub com: [ModelExpr; 2],
    /// Its moment of inertia about the centre of mass, and its orientation (an angle
    /// combination); `None`: a point mass.
    pub rotation: Option<(ModelExpr, ModelExpr)>,
}

/// A named point (`[[point]]`).
#[derive(Clone, Debug)]
pub struct Point {
    /// Its name.
    pub name: Name,
    /// Where it is, `[x, z]`.
    pub at: [ModelExpr; 2],
}

/// The stance foot's friction (`[stance]`).
#[derive(Clone, Debug)]
pub struct Stance {
    /// The friction laws a scene may choose, in file order, without repeats.
    pub friction: Vec<Friction>,
    /// The friction coefficient parameter (present unless the only law is `none`).
    pub mu0: Option<Name>,
    /// The tanh law's sharpness parameter (present with `tanh`).
    pub c: Option<Name>,
}

impl Stance {
    /// The friction law a model runs by default: its first law other than `none` (`none` when
    /// it lists no other).
    #[must_use]
    pub fn default_friction(&self) -> Friction {
        self.friction
            .iter()
            .copied()
            .find(|f| *f != Friction::None)
            .unwrap_or(Friction::None)
    }
}

/// The strike (`[strike]`).
#[derive(Clone, Debug)]
pub struct Strike {
    /// The striking point, a declared point.
    pub point: Name,
    /// The guard; `None`: the point's signed distance from the floor.
    pub guard: Option<ModelExpr>,
    /// Whether a zero counts only with the point ahead of the stance foot.
    pub ahead: bool,
}

/// What ends the walk in a fall.
#[derive(Clone, Debug)]
pub enum FallCondition {
    /// A declared point touching the floor.
    Point(Name),
    /// A guard reaching zero.
    Guard(ModelExpr),
}

/// A named failure (`[[fall]]`).
#[derive(Clone, Debug)]
pub struct Fall {
    /// The failure's name.
    pub name: Name,
    /// When it happens.
    pub condition: FallCondition,
    /// What happened.
    pub doc: String,
}

/// One line of `[relabel]`: a coordinate's value after the impact.
#[derive(Clone, Debug)]
pub struct Relabel {
    /// The coordinate (not `x` or `z`), by index into the coordinates.
    pub coordinate: usize,
    /// Its new value, in the coordinates before the impact.
    pub value: ModelExpr,
}

/// One line of `[start]`: a coordinate's or a velocity's value at the start of a walk (just
/// after an impact), in the parameters.
#[derive(Clone, Debug)]
pub struct StartValue {
    /// The coordinate, by index into the coordinates.
    pub coordinate: usize,
    /// Whether the value is the coordinate's velocity rather than the coordinate.
    pub velocity: bool,
    /// The value, in the parameters.
    pub value: ModelExpr,
}

/// The Poincare section just after an impact (`[section]`): the components of the post-impact
/// state that Newton's method and continuation work in, and the others as functions of them.
/// `x` and `z` are zero on the section (the map measures from the new stance foot) and the
/// foot's velocity normal to the floor is zero (`zd = -xd tan phi`).
#[derive(Clone, Debug)]
pub struct Section {
    /// The free components, as indices into the mechanical state `[q, qd]` (coordinate `i` is
    /// `i`, its velocity `n + i`), in the file's order.
    pub free: Vec<usize>,
    /// The other components with their values, in the parameters and the free components.
    pub given: Vec<(usize, ModelExpr)>,
}

/// The impact (`[impact]`).
#[derive(Clone, Debug)]
pub struct Impact {
    /// The default impact law.
    pub law: ImpactLaw,
    /// Expressions whose rates the impact sets to zero.
    pub locks: Vec<ModelExpr>,
    /// Whether to test that the old stance foot stays on the floor.
    pub double_support: bool,
}

/// An input (`[[input]]`).
#[derive(Clone, Debug)]
pub struct Input {
    /// Its name.
    pub name: Name,
    /// One line.
    pub doc: String,
    /// The generalised force per unit input, one expression per coordinate.
    pub force: Vec<ModelExpr>,
}

/// The output-following controller's gains (`[control]`).
#[derive(Clone, Debug)]
pub struct Control {
    /// The proportional gain parameter.
    pub kp: Name,
    /// The derivative gain parameter.
    pub kd: Name,
}

/// A desired trajectory.
#[derive(Clone, Debug)]
pub enum Desired {
    /// The quintic ramp from `from` to `to` over `duration`, then held.
    Quintic {
        /// The value at `t = 0`.
        from: ModelExpr,
        /// The value from `t = duration` on.
        to: ModelExpr,
        /// The ramp's duration.
        duration: ModelExpr,
    },
    /// A constant.
    Hold {
        /// The value.
        value: ModelExpr,
    },
    /// The Bezier polynomial of order `points.len() - 1` in `s = t / duration` with these
    /// control points, `y_d = sum_k points[k] C(M, k) s^k (1 - s)^(M - k)`, over `[0,
    /// duration]`, then held at its last point.
    Bezier {
        /// The control points `a_0 .. a_M` (2 to [`MAX_BEZIER_POINTS`]).
        points: Vec<ModelExpr>,
        /// The duration.
        duration: ModelExpr,
    },
}

/// The most control points of a Bezier desired trajectory (order 15).
pub const MAX_BEZIER_POINTS: usize = 16;

/// A controlled output (`[[output]]`).
#[derive(Clone, Debug)]
pub struct Output {
    /// Its name.
    pub name: Name,
    /// `y = h(q)`.
    pub h: ModelExpr,
    /// The name of its auxiliary input `v`.
    pub aux: Name,
    /// Its desired trajectory.
    pub desired: Desired,
}

/// A gait descriptor (`[descriptors]`).
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub enum Descriptor {
    /// `"T"`, the step period.
    Period,
    /// `"dx"`, the step length along the floor.
    StepLength,
    /// `"V"`, the speed.
    Speed,
    /// `"power"`, the mean input power (Eq. 34).
    Power,
    /// `"specific_resistance"` (Eq. 47).
    SpecificResistance,
}

impl Descriptor {
    /// Every descriptor, in the order of the format's list.
    pub const ALL: [Descriptor; 5] = [
        Descriptor::Period,
        Descriptor::StepLength,
        Descriptor::Speed,
        Descriptor::Power,
        Descriptor::SpecificResistance,
    ];

    /// The name in the file.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Descriptor::Period => "T",
            Descriptor::StepLength => "dx",
            Descriptor::Speed => "V",
            Descriptor::Power => "power",
            Descriptor::SpecificResistance => "specific_resistance",
        }
    }

    /// Whether it needs inputs.
    #[must_use]
    pub fn needs_inputs(self) -> bool {
        matches!(self, Descriptor::Power | Descriptor::SpecificResistance)
    }
}

/// A checked model.
#[derive(Clone, Debug)]
pub struct Model {
    /// Where it was loaded from (the path, or the origin given to the string loader).
    pub path: String,
    /// Its name, `[a-z][a-z0-9-]*`.
    pub name: String,
    /// One line.
    pub title: Option<String>,
    /// Where it is from.
    pub reference: Option<String>,
    /// Free text.
    pub doc: Option<String>,
    /// The coordinates, in the order of `q`; the first two are lengths.
    pub coordinates: Vec<Coordinate>,
    /// The parameters, in file order.
    pub parameters: Vec<Parameter>,
    /// The floor.
    pub floor: Floor,
    /// The bodies.
    pub bodies: Vec<Body>,
    /// The named points.
    pub points: Vec<Point>,
    /// The stance foot's friction.
    pub stance: Stance,
    /// The strike.
    pub strike: Strike,
    /// The falls.
    pub falls: Vec<Fall>,
    /// The relabelling, in coordinate order.
    pub relabel: Vec<Relabel>,
    /// The default start of a walk (`[start]`), coordinates then velocities, each in coordinate
    /// order; what it does not name starts at zero. The outputs' `A` must be regular there.
    pub start: Vec<StartValue>,
    /// The Poincare section (`None`: every component free but `x`, `z` and `zd`).
    pub section: Option<Section>,
    /// The impact.
    pub impact: Impact,
    /// The inputs.
    pub inputs: Vec<Input>,
    /// The controller's gains (present exactly when there are inputs).
    pub control: Option<Control>,
    /// The outputs, as many as inputs.
    pub outputs: Vec<Output>,
    /// The descriptors to report.
    pub descriptors: Vec<Descriptor>,
    /// The time since the impact up to which the input power of a step is integrated
    /// (`[descriptors] power_until`, in the parameters); `None`: the whole step. The paper
    /// integrates to `T_set` (Section 4.2), where its output stops moving.
    pub power_until: Option<ModelExpr>,
    pub(crate) symbols: SymbolTable,
}

impl Model {
    /// Every symbol, in canonical order.
    #[must_use]
    pub fn symbols(&self) -> &[Symbol] {
        &self.symbols.symbols
    }

    /// The symbol of that name.
    #[must_use]
    pub fn symbol(&self, name: &str) -> Option<&Symbol> {
        self.symbols.get(name)
    }

    /// The index of a symbol in [`Model::symbols`].
    #[must_use]
    pub fn symbol_index(&self, name: &str) -> Option<usize> {
        self.symbols.index.get(name).copied()
    }

    /// Whether `name` is an angle symbol.
    #[must_use]
    pub fn is_angle(&self, name: &str) -> bool {
        self.symbols.get(name).is_some_and(|s| s.angle)
    }

    /// The base-angle divisor of an angle symbol (2 for the paper's `alpha`, which appears as
    /// `alpha/2`); `None` if `name` is not an angle.
    #[must_use]
    pub fn base_angle_divisor(&self, name: &str) -> Option<u64> {
        self.symbols
            .get(name)
            .filter(|s| s.angle)
            .map(|s| s.base_divisor)
    }
}
