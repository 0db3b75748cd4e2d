//! The walker's parameters in the shared vocabulary ([`walker_scene::Param`]): which field of
//! [`Physical`] or [`Runtime`] holds each one, the paper's values, and the one place where
//! they are handed to the generated kernels' `Params` (by name, through `Params::from_fn`).

use walker_scene::Param;

/// The physical parameters of the walker (Table 1 and `g`).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Physical {
    /// Mass of the rimless wheel `m1` (kg).
    pub m1: f64,
    /// Mass of the torso `m2` (kg).
    pub m2: f64,
    /// Leg length `l` (m).
    pub l: f64,
    /// Inertia moment of the wheel `I1` (kg m^2).
    pub i1: f64,
    /// Inertia moment of the torso `I2` (kg m^2).
    pub i2: f64,
    /// Gravitational acceleration `g` (m/s^2).
    pub g: f64,
    /// Angle between neighbouring spokes `alpha` (rad).
    pub alpha: f64,
}

/// Parameters of the friction law and of the output-following control.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Runtime {
    /// Coefficient of sliding friction `mu0` (Eqs. 26, 37).
    pub mu0: f64,
    /// Sharpness `c` of the tanh friction law (s/m).
    pub c: f64,
    /// Duration `T_set` of the `y_d` ramp (s; active walker only).
    pub t_set: f64,
    /// Proportional gain `K_P` (Eq. 32; active walker only).
    pub k_p: f64,
    /// Derivative gain `K_D` (Eq. 32; active walker only).
    pub k_d: f64,
    /// Slope angle `phi` (rad; passive wheel only, 0 on level ground).
    pub phi: f64,
}

/// Ties each field of a parameter struct to its [`Param`]: `get` and `set` by parameter, and
/// the paper's values as a constant. The only place the fields are listed against the
/// vocabulary.
macro_rules! parameter_struct {
    ($ty:ident, $paper:ident, { $($field:ident: $param:ident),* $(,)? }) => {
        impl $ty {
            /// The paper's values (Table 1 with `g = 9.81`; Section 4's settings), from the
            /// parameter table of `walker-scene`.
            pub const $paper: $ty = $ty { $($field: Param::$param.default_value()),* };

            /// The parameters this struct holds.
            pub const PARAMS: &'static [Param] = &[$(Param::$param),*];

            /// The value of `param`, if this struct holds it.
            #[must_use]
            pub fn get(&self, param: Param) -> Option<f64> {
                match param {
                    $(Param::$param => Some(self.$field),)*
                    #[allow(unreachable_patterns, reason = "the other struct's parameters")]
                    _ => None,
                }
            }

            /// Sets `param` to `value`; `false` (and no change) if this struct does not hold it.
            pub fn set(&mut self, param: Param, value: f64) -> bool {
                match param {
                    $(Param::$param => self.$field = value,)*
                    #[allow(unreachable_patterns, reason = "the other struct's parameters")]
                    _ => return false,
                }
                true
            }
        }
    };
}

parameter_struct!(Physical, TABLE1, {
    m1: M1, m2: M2, l: L, i1: I1, i2: I2, g: G, alpha: Alpha,
});

parameter_struct!(Runtime, PAPER, {
    mu0: Mu0, c: C, t_set: TSet, k_p: KP, k_d: KD, phi: Phi,
});

impl Physical {
    /// Total mass `m_t = m1 + m2` (Eq. 2), used in the specific resistance.
    #[must_use]
    pub fn total_mass(&self) -> f64 {
        self.m1 + self.m2
    }
}

impl Default for Runtime {
    /// The paper's settings: `c = 100`, `K_P = K_D = 0`, `T_set = 0.3`, `mu0 = 0.4`, `phi = 0`.
    fn default() -> Self {
        Self::PAPER
    }
}

/// The value of `param` in `physical` or `runtime`.
#[must_use]
pub fn value(physical: &Physical, runtime: &Runtime, param: Param) -> f64 {
    physical
        .get(param)
        .or_else(|| runtime.get(param))
        .unwrap_or(f64::NAN)
}

/// The value of the parameter called `name` in the vocabulary (`m1`, `I1`, `T_set`, ...), for
/// a generated `Params::from_fn`. A name outside the vocabulary gives NaN, which the kernels
/// propagate and the simulator reports as non-finite; the generator only emits the names of
/// `walker_scene::Param` (its fields come from the scene's parameter list).
#[must_use]
pub fn by_name(physical: &Physical, runtime: &Runtime, name: &str) -> f64 {
    Param::from_name(name).map_or(f64::NAN, |p| value(physical, runtime, p))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_parameter_has_exactly_one_home() {
        for p in Param::ALL {
            let homes = usize::from(Physical::PARAMS.contains(&p))
                + usize::from(Runtime::PARAMS.contains(&p));
            assert_eq!(homes, 1, "{p}");
        }
    }

    #[test]
    fn get_reads_what_set_wrote() {
        let (mut ph, mut rt) = (Physical::TABLE1, Runtime::PAPER);
        for (k, p) in Param::ALL.into_iter().enumerate() {
            let v = 10.0 + k as f64;
            assert!(ph.set(p, v) || rt.set(p, v), "{p}");
            assert_eq!(value(&ph, &rt, p), v, "{p}");
            assert_eq!(by_name(&ph, &rt, p.name()), v, "{p}");
        }
    }

    #[test]
    fn table1_is_the_paper() {
        let t = Physical::TABLE1;
        assert_eq!(
            (t.m1, t.m2, t.l, t.i1, t.i2, t.g),
            (2.0, 1.0, 1.0, 0.5, 1.0, 9.81)
        );
        assert_eq!(t.alpha, std::f64::consts::PI / 6.0);
    }
}
