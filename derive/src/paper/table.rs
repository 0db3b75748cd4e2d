//! The paper's notation as a symbol table: every symbol of the paper's walker (Fig. 1, Table 1,
//! Sections 3-5) with its name, LaTeX and role, in one table for the level and slope kernels,
//! and each as a constant (`Sym::Th1`, `BaseAngle::HalfAlpha`, ...) for the code that writes the
//! walker as the paper prints it: this module, `docs/equations.md` and the errata tests. The
//! engine (`crate::symbol`) knows no walker; the paper's quantities come from its model files
//! and are renamed into this table by name (`quantities.rs`).

use crate::symbol::{BaseAngle, Sym, SymKind, SymbolInfo, Symbols};

/// The paper's walker: its symbols as constants, in the order of [`Symbols::paper`].
macro_rules! paper_symbols {
    (
        angles { $( $(#[$adoc:meta])* $angle:ident = $aslot:expr; )* }
        symbols { $( $(#[$doc:meta])* $var:ident = $idx:expr, $name:literal, $latex:literal, $kind:ident $(, $base:ident * $mult:expr)?; )* }
    ) => {
        #[allow(non_upper_case_globals, reason = "the paper's notation, as the former enum variants")]
        impl BaseAngle {
            $( $(#[$adoc])* pub const $angle: BaseAngle = BaseAngle::new($aslot); )*
        }

        #[allow(non_upper_case_globals, reason = "the paper's notation, as the former enum variants")]
        impl Sym {
            $( $(#[$doc])* pub const $var: Sym = paper_symbols!(@sym $idx $(, $base, $mult)?); )*
        }

        impl Symbols {
            /// The table of the paper's walker (Fig. 1, Table 1, Sections 3-5): one table for
            /// its level and slope kernels, in the slot order every derivation so far used.
            pub fn paper() -> Symbols {
                Symbols::from_infos(vec![
                    $( SymbolInfo {
                        sym: Sym::$var,
                        name: $name.to_owned(),
                        latex: $latex.to_owned(),
                        kind: SymKind::$kind,
                    }, )*
                ])
            }
        }
    };
    (@sym $idx:expr) => { Sym::plain($idx) };
    (@sym $idx:expr, $base:ident, $mult:expr) => { Sym::angle($idx, BaseAngle::$base, $mult) };
}

paper_symbols! {
    angles {
        /// The stance-leg angle `theta_1`.
        Th1 = 0;
        /// The torso angle `theta_2`.
        Th2 = 1;
        /// Half the inter-leg angle, `alpha / 2`.
        HalfAlpha = 2;
        /// The slope angle `phi`.
        Phi = 3;
    }
    symbols {
        /// Horizontal position of the stance-leg end.
        X = 0, "x", "x", Coordinate;
        /// Vertical position of the stance-leg end.
        Z = 1, "z", "z", Coordinate;
        /// Stance-leg angle from the vertical.
        Th1 = 2, "th1", "\\theta_1", Coordinate, Th1 * 1;
        /// Torso angle from the horizontal.
        Th2 = 3, "th2", "\\theta_2", Coordinate, Th2 * 1;
        /// Time derivative of `x`.
        Xd = 4, "xd", "\\dot{x}", Velocity;
        /// Time derivative of `z`.
        Zd = 5, "zd", "\\dot{z}", Velocity;
        /// Time derivative of `th1`.
        Th1d = 6, "th1d", "\\dot{\\theta}_1", Velocity;
        /// Time derivative of `th2`.
        Th2d = 7, "th2d", "\\dot{\\theta}_2", Velocity;
        /// Second time derivative of `x`.
        Xdd = 8, "xdd", "\\ddot{x}", Acceleration;
        /// Second time derivative of `z`.
        Zdd = 9, "zdd", "\\ddot{z}", Acceleration;
        /// Second time derivative of `th1`.
        Th1dd = 10, "th1dd", "\\ddot{\\theta}_1", Acceleration;
        /// Second time derivative of `th2`.
        Th2dd = 11, "th2dd", "\\ddot{\\theta}_2", Acceleration;
        /// Mass of the rimless wheel.
        M1 = 12, "m1", "m_1", Parameter;
        /// Mass of the torso.
        M2 = 13, "m2", "m_2", Parameter;
        /// Leg length (radius of the wheel).
        L = 14, "l", "l", Parameter;
        /// Half the torso length.
        R = 15, "r", "r", Parameter;
        /// Inertia moment of the wheel.
        I1 = 16, "I1", "I_1", Parameter;
        /// Inertia moment of the torso.
        I2 = 17, "I2", "I_2", Parameter;
        /// Gravity acceleration.
        G = 18, "g", "g", Parameter;
        /// Angle between neighbouring legs.
        Alpha = 19, "alpha", "\\alpha", Parameter, HalfAlpha * 2;
        /// Slope angle.
        Phi = 20, "phi", "\\phi", Parameter, Phi * 1;
        /// Friction coefficient with direction (Eq. 24).
        Mu = 21, "mu", "\\mu", Input;
        /// Joint torque between stance leg and torso.
        U = 22, "u", "u", Input;
        /// Magnitude of the sliding friction coefficient (Eqs. 25-26).
        Mu0 = 23, "mu0", "\\mu_0", Parameter;
        /// Sharpness of the `tanh` friction law (Eq. 26).
        C = 24, "c", "c", Parameter;
        /// Time since the last impact.
        T = 25, "t", "t", Input;
        /// Duration of the output ramp `y_d` (Section 3.2).
        TSet = 26, "T_set", "T_{\\mathrm{set}}", Parameter;
        /// Proportional gain (Eq. 32).
        Kp = 27, "K_P", "K_P", Parameter;
        /// Derivative gain (Eq. 32).
        Kd = 28, "K_D", "K_D", Parameter;
        /// Auxiliary input of the output-following control (Eq. 31).
        V = 29, "v", "v", Input;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paper_table_resolves_its_constants() {
        let t = Symbols::paper();
        assert_eq!(t.lookup("alpha"), Ok(Sym::Alpha));
        assert_eq!(t.angle(BaseAngle::HalfAlpha), Some((Sym::Alpha, 2)));
        assert_eq!(t.angles().len(), 4);
        assert_eq!(t.atom_name(BaseAngle::HalfAlpha.cos_slot()), "cos(alpha/2)");
        assert_eq!(t.atom_name(Sym::Th1d.slot()), "th1d");
        for (i, s) in t.syms().enumerate() {
            assert_eq!(s.index(), i);
        }
    }
}
