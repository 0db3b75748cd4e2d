//! The parameter vocabulary: every parameter's name (as in scene files and `docs/kernels.md`),
//! its doc line with unit, its valid range, and the structures that have it. Written once and
//! read by the generator (the fields of each generated `Params`), the simulator's validation, the
//! CLI and the tests.

use std::fmt;

use crate::structure::{Floor, Friction, Torso};

/// A model parameter (paper notation; Table 1 for the values used there).
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub enum Param {
    /// `m1`: mass of the rimless wheel (kg).
    M1,
    /// `m2`: mass of the torso (kg).
    M2,
    /// `l`: leg length, the radius of the wheel (m).
    L,
    /// `I1`: inertia moment of the wheel (kg m^2).
    I1,
    /// `I2`: inertia moment of the torso (kg m^2).
    I2,
    /// `g`: gravitational acceleration (m/s^2).
    G,
    /// `alpha`: angle between neighbouring spokes (rad).
    Alpha,
    /// `phi`: slope angle (rad).
    Phi,
    /// `mu0`: coefficient of sliding friction (-).
    Mu0,
    /// `c`: sharpness of the tanh friction law (s/m).
    C,
    /// `T_set`: duration of the `y_d` ramp (s).
    TSet,
    /// `K_P`: proportional gain (1/s^2).
    KP,
    /// `K_D`: derivative gain (1/s).
    KD,
}

/// One row of the parameter table.
#[derive(Clone, Copy, Debug)]
struct Row {
    param: Param,
    name: &'static str,
    unit: &'static str,
    doc: &'static str,
    range: Range,
    default: f64,
}

/// Every parameter with its name, unit, doc line, valid range and the paper's value (Table 1,
/// `g = 9.81`, and the settings of Section 4: `mu0 = 0.4`, `c = 100`, `T_set = 0.3`,
/// `K_P = K_D = 0`, level ground), in canonical (and `Params` field) order.
const PARAMS: [Row; 13] = [
    Row {
        param: Param::M1,
        name: "m1",
        unit: "kg",
        doc: "Mass of the rimless wheel `m1` (kg).",
        range: Range::Positive,
        default: 2.0,
    },
    Row {
        param: Param::M2,
        name: "m2",
        unit: "kg",
        doc: "Mass of the torso `m2` (kg).",
        range: Range::Positive,
        default: 1.0,
    },
    Row {
        param: Param::L,
        name: "l",
        unit: "m",
        doc: "Leg length (wheel radius) `l` (m).",
        range: Range::Positive,
        default: 1.0,
    },
    Row {
        param: Param::I1,
        name: "I1",
        unit: "kg m^2",
        doc: "Inertia moment of the wheel `I1` (kg m^2).",
        range: Range::Positive,
        default: 0.5,
    },
    Row {
        param: Param::I2,
        name: "I2",
        unit: "kg m^2",
        doc: "Inertia moment of the torso `I2` (kg m^2).",
        range: Range::Positive,
        default: 1.0,
    },
    Row {
        param: Param::G,
        name: "g",
        unit: "m/s^2",
        doc: "Gravitational acceleration `g` (m/s^2).",
        range: Range::Positive,
        default: 9.81,
    },
    Row {
        param: Param::Alpha,
        name: "alpha",
        unit: "rad",
        doc: "Angle between neighbouring spokes `alpha` (rad).",
        range: Range::OpenPi,
        // `PI / 6.0`, one unit in the last place below `FRAC_PI_6`: the value every result so
        // far was computed with (the Table 1 scene files give `alpha_deg = 30`, FRAC_PI_6).
        default: std::f64::consts::PI / 6.0,
    },
    Row {
        param: Param::Phi,
        name: "phi",
        unit: "rad",
        doc: "Slope angle `phi` (rad).",
        range: Range::HalfOpenHalfPi,
        default: 0.0,
    },
    Row {
        param: Param::Mu0,
        name: "mu0",
        unit: "-",
        doc: "Coefficient of sliding friction `mu0` (dimensionless).",
        range: Range::NonNegative,
        default: 0.4,
    },
    Row {
        param: Param::C,
        name: "c",
        unit: "s/m",
        doc: "Sharpness `c` of the tanh friction law (s/m).",
        range: Range::Positive,
        default: 100.0,
    },
    Row {
        param: Param::TSet,
        name: "T_set",
        unit: "s",
        doc: "Duration `T_set` of the `y_d` ramp (s).",
        range: Range::Positive,
        default: 0.3,
    },
    Row {
        param: Param::KP,
        name: "K_P",
        unit: "1/s^2",
        doc: "Proportional gain `K_P` of the output control (1/s^2).",
        range: Range::NonNegative,
        default: 0.0,
    },
    Row {
        param: Param::KD,
        name: "K_D",
        unit: "1/s",
        doc: "Derivative gain `K_D` of the output control (1/s).",
        range: Range::NonNegative,
        default: 0.0,
    },
];

/// A valid range of a parameter value.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(crate) enum Range {
    Positive,
    NonNegative,
    OpenPi,
    HalfOpenHalfPi,
    OpenDegrees,
}

impl Range {
    pub(crate) fn contains(self, v: f64) -> bool {
        use std::f64::consts::{FRAC_PI_2, PI};
        v.is_finite()
            && match self {
                Range::Positive => v > 0.0,
                Range::NonNegative => v >= 0.0,
                Range::OpenPi => v > 0.0 && v < PI,
                Range::HalfOpenHalfPi => (0.0..FRAC_PI_2).contains(&v),
                Range::OpenDegrees => v > 0.0 && v < 180.0,
            }
    }

    pub(crate) fn describe(self) -> &'static str {
        match self {
            Range::Positive => "finite and > 0",
            Range::NonNegative => "finite and >= 0",
            Range::OpenPi => "in (0, pi)",
            Range::HalfOpenHalfPi => "in [0, pi/2)",
            Range::OpenDegrees => "in (0, 180)",
        }
    }
}

impl Param {
    /// Every parameter, in canonical order.
    pub const ALL: [Param; 13] = [
        Param::M1,
        Param::M2,
        Param::L,
        Param::I1,
        Param::I2,
        Param::G,
        Param::Alpha,
        Param::Phi,
        Param::Mu0,
        Param::C,
        Param::TSet,
        Param::KP,
        Param::KD,
    ];

    const fn row(self) -> Row {
        PARAMS[self as usize]
    }

    /// The position in [`Param::ALL`].
    #[must_use]
    pub fn index(self) -> usize {
        self as usize
    }

    /// The name in scene files and in `docs/kernels.md` (`m1`, `I1`, `T_set`...).
    #[must_use]
    pub fn name(self) -> &'static str {
        self.row().name
    }

    /// A one-line description with unit, for doc comments.
    #[must_use]
    pub fn doc(self) -> &'static str {
        self.row().doc
    }

    /// The unit (`kg`, `m`, `rad`, `s/m`...; `-` for a dimensionless number).
    #[must_use]
    pub fn unit(self) -> &'static str {
        self.row().unit
    }

    /// The paper's value: Table 1 with `g = 9.81`, and Section 4's `mu0 = 0.4`, `c = 100`,
    /// `T_set = 0.3`, `K_P = K_D = 0`, `phi = 0`.
    #[must_use]
    pub const fn default_value(self) -> f64 {
        self.row().default
    }

    /// The valid values, in words (for example `"finite and > 0"`).
    #[must_use]
    pub fn valid_range(self) -> &'static str {
        self.row().range.describe()
    }

    /// Whether `value` is valid for the parameter.
    #[must_use]
    pub fn accepts(self, value: f64) -> bool {
        self.row().range.contains(value)
    }

    /// The parameter called `name` in scene files.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Param> {
        PARAMS
            .iter()
            .find(|row| row.name == name)
            .map(|row| row.param)
    }

    /// Whether a walker with this structure has the parameter.
    #[must_use]
    pub fn applies_to(self, floor: Floor, friction: Friction, torso: Torso) -> bool {
        match self {
            Param::M1 | Param::M2 | Param::L | Param::I1 | Param::I2 | Param::G | Param::Alpha => {
                true
            }
            Param::Phi => floor == Floor::Slope,
            Param::Mu0 => friction != Friction::None,
            Param::C => friction == Friction::Tanh,
            Param::TSet | Param::KP | Param::KD => torso == Torso::Actuated,
        }
    }

    /// Why a structure lacks the parameter (for error messages).
    pub(crate) fn absent_because(self, floor: Floor, friction: Friction, torso: Torso) -> String {
        match self {
            Param::Phi => format!(
                "floor = \"{floor}\" has no slope angle; remove it or use floor = \"slope\""
            ),
            Param::Mu0 | Param::C => format!(
                "friction = \"{friction}\" has no parameter `{}`; remove it or change `friction`",
                self.name()
            ),
            Param::TSet | Param::KP | Param::KD => {
                format!("torso = \"{torso}\" has no control; remove it or use torso = \"actuated\"")
            }
            _ => String::new(),
        }
    }
}

impl fmt::Display for Param {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
