//! The physical parameters of a test case ([`Phys`]), Table 1's values, and the generated
//! kernels prepared at them.

/// Physical parameters (docs/kernels.md, "Parameters"). `phi = 0` is the level floor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Phys {
    /// Wheel mass.
    pub m1: f64,
    /// Torso mass.
    pub m2: f64,
    /// Leg length.
    pub l: f64,
    /// Wheel inertia.
    pub i1: f64,
    /// Torso inertia.
    pub i2: f64,
    /// Gravity.
    pub g: f64,
    /// Inter-leg angle.
    pub alpha: f64,
    /// Slope angle (0 on level ground).
    pub phi: f64,
}

/// The run-time settings of a scene's kernels: the friction law and the controller.
#[derive(Debug, Clone, Copy)]
struct Runtime {
    mu0: f64,
    c: f64,
    t_set: f64,
    k_p: f64,
    k_d: f64,
    phi: f64,
}

/// Runtime parameters with every value NaN: a kernel's `Params` that read one not set on
/// purpose would turn the kernels' outputs NaN, and the tests using them would fail.
const UNSET: Runtime = Runtime {
    mu0: f64::NAN,
    c: f64::NAN,
    t_set: f64::NAN,
    k_p: f64::NAN,
    k_d: f64::NAN,
    phi: f64::NAN,
};

impl Phys {
    /// The value of a parameter by its vocabulary name (`m1`, `I1`, `T_set`, ...) at these
    /// physical parameters and `runtime`, for a generated `Params::from_fn`; NaN for a name
    /// that is not a parameter (so that a misspelt one poisons every output).
    fn by_name(&self, rt: Runtime) -> impl FnMut(&'static str) -> f64 {
        let p = *self;
        move |name| match name {
            "m1" => p.m1,
            "m2" => p.m2,
            "l" => p.l,
            "I1" => p.i1,
            "I2" => p.i2,
            "g" => p.g,
            "alpha" => p.alpha,
            "mu0" => rt.mu0,
            "c" => rt.c,
            "T_set" => rt.t_set,
            "K_P" => rt.k_p,
            "K_D" => rt.k_d,
            "phi" => rt.phi,
            _ => f64::NAN,
        }
    }

    /// The `general_level` kernels prepared at these parameters, the tanh law `(mu0, c)` and the
    /// control settings `(T_set, K_P, K_D)`.
    #[must_use]
    pub fn level_kernels(
        &self,
        (mu0, c): (f64, f64),
        (t_set, k_p, k_d): (f64, f64, f64),
    ) -> crate::scenes::general_level::Prepared {
        use crate::scenes::general_level as gl;
        gl::prepare(&gl::Params::from_fn(self.by_name(Runtime {
            mu0,
            c,
            t_set,
            k_p,
            k_d,
            ..UNSET
        })))
    }

    /// The `general_slope` kernels prepared at these parameters and the tanh law `(mu0, c)`.
    #[must_use]
    pub fn slope_kernels(&self, (mu0, c): (f64, f64)) -> crate::scenes::general_slope::Prepared {
        use crate::scenes::general_slope as gs;
        gs::prepare(&gs::Params::from_fn(self.by_name(Runtime {
            mu0,
            c,
            phi: self.phi,
            ..UNSET
        })))
    }

    /// The `general_level_coulomb` kernels prepared at these parameters, the Coulomb
    /// coefficient `mu0` and the control settings `(T_set, K_P, K_D)`.
    #[must_use]
    pub fn level_coulomb_kernels(
        &self,
        mu0: f64,
        (t_set, k_p, k_d): (f64, f64, f64),
    ) -> crate::scenes::general_level_coulomb::Prepared {
        use crate::scenes::general_level_coulomb as glc;
        glc::prepare(&glc::Params::from_fn(self.by_name(Runtime {
            mu0,
            t_set,
            k_p,
            k_d,
            ..UNSET
        })))
    }

    /// The `general_slope_coulomb` kernels prepared at these parameters and the Coulomb
    /// coefficient `mu0`.
    #[must_use]
    pub fn slope_coulomb_kernels(
        &self,
        mu0: f64,
    ) -> crate::scenes::general_slope_coulomb::Prepared {
        use crate::scenes::general_slope_coulomb as gsc;
        gsc::prepare(&gsc::Params::from_fn(self.by_name(Runtime {
            mu0,
            phi: self.phi,
            ..UNSET
        })))
    }

    /// Table 1 with `g = 9.81`, `alpha = pi/6` and the given slope angle.
    #[must_use]
    pub fn table1(phi: f64) -> Phys {
        Phys {
            m1: 2.0,
            m2: 1.0,
            l: 1.0,
            i1: 0.5,
            i2: 1.0,
            g: 9.81,
            alpha: std::f64::consts::PI / 6.0,
            phi,
        }
    }

    /// Total mass `m_t = m1 + m2`.
    #[must_use]
    pub fn mt(&self) -> f64 {
        self.m1 + self.m2
    }
}
