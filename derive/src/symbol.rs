//! The symbols of the model and their slots in a monomial.
//!
//! A polynomial of this engine lives in `Q[atoms]`, where each atom is either a plain symbol
//! (a coordinate, a velocity, a parameter, an input) or the sine or cosine of a *base angle*.
//! Base angles are `th1`, `th2`, `alpha/2` and `phi`: `alpha` enters through its half so that
//! `sin(alpha) = 2 sin(alpha/2) cos(alpha/2)` and `1 - cos(alpha) = 2 sin^2(alpha/2)` need no
//! square root and lose no digits.
//!
//! Slots are fixed: atom `2k` is `sin` of base angle `k` and atom `2k + 1` its `cos`, so that the
//! reduction `cos^2 -> 1 - sin^2` needs no lookup table.

use crate::error::Error;

/// Number of atom slots in a monomial.
pub const NUM_ATOMS: usize = 48;

/// The base angles whose sine and cosine are atoms.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum BaseAngle {
    /// The stance-leg angle `theta_1`.
    Th1 = 0,
    /// The torso angle `theta_2`.
    Th2 = 1,
    /// Half the inter-leg angle, `alpha / 2`.
    HalfAlpha = 2,
    /// The slope angle `phi`.
    Phi = 3,
}

/// Number of base angles.
pub const NUM_ANGLES: usize = 4;

impl BaseAngle {
    /// All base angles, in slot order.
    pub const ALL: [BaseAngle; NUM_ANGLES] = [
        BaseAngle::Th1,
        BaseAngle::Th2,
        BaseAngle::HalfAlpha,
        BaseAngle::Phi,
    ];

    /// The atom slot of `sin` of this angle.
    pub const fn sin_slot(self) -> usize {
        2 * self as usize
    }

    /// The atom slot of `cos` of this angle.
    pub const fn cos_slot(self) -> usize {
        2 * self as usize + 1
    }

    /// The symbol this base angle is measured in, and how many base angles make one unit of it
    /// (`alpha = 2 * (alpha/2)`).
    pub const fn symbol_and_multiple(self) -> (Sym, i64) {
        match self {
            BaseAngle::Th1 => (Sym::Th1, 1),
            BaseAngle::Th2 => (Sym::Th2, 1),
            BaseAngle::HalfAlpha => (Sym::Alpha, 2),
            BaseAngle::Phi => (Sym::Phi, 1),
        }
    }

    /// The base angle of an angle symbol, if it is one.
    pub const fn of_symbol(sym: Sym) -> Option<BaseAngle> {
        match sym {
            Sym::Th1 => Some(BaseAngle::Th1),
            Sym::Th2 => Some(BaseAngle::Th2),
            Sym::Alpha => Some(BaseAngle::HalfAlpha),
            Sym::Phi => Some(BaseAngle::Phi),
            _ => None,
        }
    }
}

/// What role a symbol plays in the model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SymKind {
    /// A generalized coordinate of `q`.
    Coordinate,
    /// A generalized velocity of `qdot`.
    Velocity,
    /// A generalized acceleration of `qddot`.
    Acceleration,
    /// A physical or control parameter, constant during a simulation.
    Parameter,
    /// An input that changes along the motion but is not a state (`u`, `mu`, `t`).
    Input,
}

macro_rules! symbols {
    ($( $(#[$doc:meta])* $var:ident = $slot:expr, $name:literal, $latex:literal, $kind:ident; )*) => {
        /// A symbol of the model, with a fixed atom slot.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum Sym {
            $( $(#[$doc])* $var = $slot, )*
        }

        impl Sym {
            /// Every symbol, in slot order.
            pub const ALL: &'static [Sym] = &[$(Sym::$var),*];

            /// The atom slot of this symbol.
            pub const fn slot(self) -> usize {
                self as usize
            }

            /// The plain-text name (as used in scene files and kernel argument lists).
            pub const fn name(self) -> &'static str {
                match self { $(Sym::$var => $name,)* }
            }

            /// The LaTeX rendering, in the paper's notation.
            pub const fn latex(self) -> &'static str {
                match self { $(Sym::$var => $latex,)* }
            }

            /// The role of the symbol.
            pub const fn kind(self) -> SymKind {
                match self { $(Sym::$var => SymKind::$kind,)* }
            }
        }
    };
}

symbols! {
    /// Horizontal position of the stance-leg end.
    X = 8, "x", "x", Coordinate;
    /// Vertical position of the stance-leg end.
    Z = 9, "z", "z", Coordinate;
    /// Stance-leg angle from the vertical.
    Th1 = 10, "th1", "\\theta_1", Coordinate;
    /// Torso angle from the horizontal.
    Th2 = 11, "th2", "\\theta_2", Coordinate;
    /// Time derivative of `x`.
    Xd = 12, "xd", "\\dot{x}", Velocity;
    /// Time derivative of `z`.
    Zd = 13, "zd", "\\dot{z}", Velocity;
    /// Time derivative of `th1`.
    Th1d = 14, "th1d", "\\dot{\\theta}_1", Velocity;
    /// Time derivative of `th2`.
    Th2d = 15, "th2d", "\\dot{\\theta}_2", Velocity;
    /// Second time derivative of `x`.
    Xdd = 16, "xdd", "\\ddot{x}", Acceleration;
    /// Second time derivative of `z`.
    Zdd = 17, "zdd", "\\ddot{z}", Acceleration;
    /// Second time derivative of `th1`.
    Th1dd = 18, "th1dd", "\\ddot{\\theta}_1", Acceleration;
    /// Second time derivative of `th2`.
    Th2dd = 19, "th2dd", "\\ddot{\\theta}_2", Acceleration;
    /// Mass of the rimless wheel.
    M1 = 20, "m1", "m_1", Parameter;
    /// Mass of the torso.
    M2 = 21, "m2", "m_2", Parameter;
    /// Leg length (radius of the wheel).
    L = 22, "l", "l", Parameter;
    /// Half the torso length.
    R = 23, "r", "r", Parameter;
    /// Inertia moment of the wheel.
    I1 = 24, "I1", "I_1", Parameter;
    /// Inertia moment of the torso.
    I2 = 25, "I2", "I_2", Parameter;
    /// Gravity acceleration.
    G = 26, "g", "g", Parameter;
    /// Angle between neighbouring legs.
    Alpha = 27, "alpha", "\\alpha", Parameter;
    /// Slope angle.
    Phi = 28, "phi", "\\phi", Parameter;
    /// Friction coefficient with direction (Eq. 24).
    Mu = 29, "mu", "\\mu", Input;
    /// Joint torque between stance leg and torso.
    U = 30, "u", "u", Input;
    /// Magnitude of the sliding friction coefficient (Eqs. 25-26).
    Mu0 = 31, "mu0", "\\mu_0", Parameter;
    /// Sharpness of the `tanh` friction law (Eq. 26).
    C = 32, "c", "c", Parameter;
    /// Time since the last impact.
    T = 33, "t", "t", Input;
    /// Duration of the output ramp `y_d` (Section 3.2).
    TSet = 34, "T_set", "T_{\\mathrm{set}}", Parameter;
    /// Proportional gain (Eq. 32).
    Kp = 35, "K_P", "K_P", Parameter;
    /// Derivative gain (Eq. 32).
    Kd = 36, "K_D", "K_D", Parameter;
    /// Auxiliary input of the output-following control (Eq. 31).
    V = 37, "v", "v", Input;
}

impl Sym {
    /// Looks a symbol up by its plain-text name.
    pub fn from_name(name: &str) -> Result<Sym, Error> {
        Sym::ALL
            .iter()
            .copied()
            .find(|s| s.name() == name)
            .ok_or_else(|| Error::UnknownSymbol {
                name: name.to_owned(),
            })
    }
}

/// What an atom slot holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Atom {
    /// `sin` of a base angle.
    Sin(BaseAngle),
    /// `cos` of a base angle.
    Cos(BaseAngle),
    /// A plain symbol.
    Sym(Sym),
}

impl Atom {
    /// The atom in a slot, if any.
    pub fn of_slot(slot: usize) -> Option<Atom> {
        if slot < 2 * NUM_ANGLES {
            let angle = BaseAngle::ALL[slot / 2];
            return Some(if slot.is_multiple_of(2) {
                Atom::Sin(angle)
            } else {
                Atom::Cos(angle)
            });
        }
        Sym::ALL
            .iter()
            .copied()
            .find(|s| s.slot() == slot)
            .map(Atom::Sym)
    }

    /// The slot of this atom.
    pub const fn slot(self) -> usize {
        match self {
            Atom::Sin(a) => a.sin_slot(),
            Atom::Cos(a) => a.cos_slot(),
            Atom::Sym(s) => s.slot(),
        }
    }
}
