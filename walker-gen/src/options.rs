//! What the emitter writes: how divisions are evaluated ([`Division`]), the float type, how
//! `sin_cos` and `tanh` are evaluated, and the [`EmitOptions`] that gather them with the
//! checked entry points.
//!
//! Its own file so that both the emitter and the operation counts ([`crate::stats`](mod@crate::stats)) read the
//! options without importing each other.

/// How divisions are evaluated (see the crate docs, "Numerics").
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Default)]
pub enum Division {
    /// A denominator depending on parameters only is inverted once in `prepare`; a
    /// state-dependent denominator shared by two or more divisions of one kernel is inverted
    /// once per call; those quotients become multiplications by the reciprocal.
    ///
    /// Each such quotient is rounded twice instead of once (relative error at most `2u` instead
    /// of `u`, with `u = 2^-53` for `f64`), which is below the error any numerator or
    /// denominator computed in more than one operation already carries; a division costs
    /// several multiplications in latency and throughput. This is the default.
    #[default]
    SharedReciprocal,
    /// Every quotient is one correctly rounded division, as written in the derivation.
    Exact,
}

/// The float type of the generated code.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Default)]
pub enum Float {
    /// `f64` (the default).
    #[default]
    F64,
    /// `f32`, for small controllers. Constants are folded in `f64` and rounded once.
    F32,
}

impl Float {
    /// `"f64"` or `"f32"`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Float::F64 => "f64",
            Float::F32 => "f32",
        }
    }
}

/// How generated `f64` code in std mode evaluates `sin_cos` and `tanh`.
///
/// Profiles of the simulator showed std's `tanh` (glibc goes through `expm1`, about 18 ns) and
/// `sin_cos` (two library calls with two argument reductions, about 10 ns) taking about half the
/// run time of the stance kernels, whose arithmetic takes about 15 ns.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Default)]
pub enum FloatFunctions {
    /// Private `fn sin_cos` and `fn tanh` written into the file when a kernel uses them (the
    /// default): fdlibm's `__kernel_sin`/`__kernel_cos` with one shared Cody-Waite reduction
    /// (std's `sin_cos` above `2^20 pi/2`), and Cephes' rational for `|x| < 0.625`,
    /// `1 - 2/(exp(2|x|) + 1)` above. Measured errors: at most 0.78 ulp (sin, cos) and 1.32 ulp
    /// (tanh); the tests assert 1 and 2 (`tests/it/fastmath_accuracy.rs`). Other float functions
    /// (`sqrt`, a lone `sin` or `cos`) stay std methods.
    /// Applies only to `f64` in std mode; `f32` and no-std code are as with [`Self::Std`].
    #[default]
    Inline,
    /// std's inherent methods `x.sin_cos()` and `x.tanh()` (results depend on the platform's
    /// `libm`).
    Std,
}

/// What the emitter writes.
///
/// The default is `f64`, std, [`Division::SharedReciprocal`], checked entry points and
/// [`FloatFunctions::Inline`].
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub struct EmitOptions {
    /// The float type `F`.
    pub float: Float,
    /// Whether to call `libm` instead of std's inherent float methods (the file then uses only
    /// `core` and `libm`).
    pub no_std: bool,
    /// How divisions by shared denominators are evaluated.
    pub division: Division,
    /// Whether to emit, next to each kernel `k`, a `k_checked` that rejects non-finite
    /// arguments and outputs with a `KernelError` (emitted once per file). `false` leaves both
    /// out (smallest code, for embedded users); the plain kernels are the same either way.
    pub checked: bool,
    /// Whether `sin_cos` and `tanh` are private functions of the file or std methods (only for
    /// `f64` in std mode).
    pub float_functions: FloatFunctions,
}

impl EmitOptions {
    /// Whether `sin_cos` and `tanh` are the file's own functions: [`FloatFunctions::Inline`]
    /// with `f64` in std mode.
    #[must_use]
    pub fn inline_float_functions(&self) -> bool {
        self.float_functions == FloatFunctions::Inline && !self.no_std && self.float == Float::F64
    }
}

impl Default for EmitOptions {
    fn default() -> Self {
        EmitOptions {
            float: Float::default(),
            no_std: false,
            division: Division::default(),
            checked: true,
            float_functions: FloatFunctions::default(),
        }
    }
}
