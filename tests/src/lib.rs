//! Verification suite of the generated kernels (`walker::kernels::*`).
//!
//! This crate holds a *generic* implementation of the walker's dynamics written directly from
//! the paper (Asano, Kikuchi, Shibata, Sections 2-3 and 5.1) with `nalgebra`: the matrices
//! `M`, `h`, `J`, `J_mu`, `J_I` are written out as matrices and every derived quantity is
//! obtained by a *linear solve*, never by the closed forms the generator produces:
//!
//! - stance accelerations and the reaction: one augmented (KKT) system
//!   `[[M, -Jhat^T], [J, 0]] [qdd; lambda] = [S u - h; 0]` solved by LU;
//! - `lambda` also by Eq. 22 (with `M^-1` applied by LU), `Y` by Eq. 28 with
//!   `M.try_inverse()`, `A` and `B` by Eqs. 30-31;
//! - every impact map by solving Eq. 1 with its constraints as one linear system
//!   `[[M, -J_I^T], [J_I, 0]] [qd+; lambda_I] = [M qd-; 0]`;
//! - the stick phase (the stance foot at rest; not in the paper) by the KKT system with the two
//!   rows that hold the foot's position, `[[M, -J_p^T], [J_p, 0]] [qdd; F] = [S u - h; 0]`,
//!   `J_p = d(x, z)/dq`, the Cartesian ground force `F` resolved along the floor's unit tangent
//!   and normal afterwards (the derivation constrains the tangent and normal coordinates
//!   directly);
//! - the closed loops (Eq. 31 sliding, and its stick counterpart) by three KKT solves:
//!   `A = S^T x_S`, `B = S^T x_h` from the right-hand sides `[S; 0]`, `[h; 0]`, then
//!   `u = (v + B) / A` and the system solved again at that `u`.
//!
//! Next to each value the generic path returns an *error scale* `s` (documented per function):
//! a conditioning-based magnitude such that a backward-stable evaluation of the same quantity,
//! by any algorithm, differs from the exact value by at most a small multiple of `eps * s`.
//! The tests assert `|generated - reference| <= C * eps * s` with the constant `C` stated and
//! argued next to each assertion; near a singular denominator the condition number (and with
//! it the bound) is huge, which is the argued behaviour, never a silent skip.
//!
//! The integration tests:
//!
//! - `kernels_vs_nalgebra`: proptest over wide random parameters and states, every kernel of
//!   `general_level` / `general_slope` and of the Coulomb scenes `general_level_coulomb` /
//!   `general_slope_coulomb` against this generic path, and the Coulomb sliding kernels
//!   against the tanh ones where `tanh` saturates;
//! - `kernels_vs_sympy`: every kernel of the same modules against the 30-digit SymPy
//!   reference values in `tests/data/<kernel>.json`, with a per-kernel report of the worst
//!   error in ulps (printed, and written to `target/kernel_ulps.txt`);
//! - `invariants`: energy conservation (RK4 stance, drift ~ h^4), horizontal momentum, the
//!   impact constraints after the impact, angular momentum about the new contact point,
//!   `J M^-1 Y = 0`;
//! - `specialisation`: the Table 1 scenes (`active_level`, `passive_slope`) agree with the
//!   general kernels at those parameters, and the frictionless scene has no `tanh`.
//!
//! # Running
//!
//! `cargo test -p walker-tests` runs the quick mode (256 random cases per property, well under
//! a minute in the test profile). For the long mode set `WALKER_LONG_TESTS=1`, which multiplies
//! the number of cases by [`LONG_FACTOR`]; `PROPTEST_CASES=N` replaces the base count 256:
//!
//! ```text
//! WALKER_LONG_TESTS=1 cargo test -p walker-tests --release -- --nocapture
//! ```

use nalgebra::{DMatrix, DVector, Matrix4, RowVector4, Vector4};
use walker::params::{Physical, Runtime, by_name};

/// Machine epsilon of `f64` (the spacing of floats at 1.0, twice the unit roundoff).
pub const EPS: f64 = f64::EPSILON;

/// Multiplier of the case counts when `WALKER_LONG_TESTS=1`.
pub const LONG_FACTOR: u32 = 40;

/// Number of random cases per property: `PROPTEST_CASES` (default 256), times
/// [`LONG_FACTOR`] when the environment variable `WALKER_LONG_TESTS` is `1`.
#[must_use]
pub fn cases() -> u32 {
    let base = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse::<u32>().ok())
        .unwrap_or(256);
    let long = std::env::var("WALKER_LONG_TESTS").is_ok_and(|v| v == "1");
    if long {
        base.saturating_mul(LONG_FACTOR)
    } else {
        base
    }
}

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
    /// These parameters as the simulator's [`Physical`] (`phi` is a runtime parameter there).
    fn physical(&self) -> Physical {
        Physical {
            m1: self.m1,
            m2: self.m2,
            l: self.l,
            i1: self.i1,
            i2: self.i2,
            g: self.g,
            alpha: self.alpha,
        }
    }

    /// The value of a parameter by its vocabulary name (`m1`, `I1`, `T_set`, ...) at these
    /// physical parameters and `runtime`, for a generated `Params::from_fn`.
    fn by_name(&self, runtime: Runtime) -> impl FnMut(&'static str) -> f64 {
        let physical = self.physical();
        move |name| by_name(&physical, &runtime, name)
    }

    /// The `general_level` kernels prepared at these parameters, the tanh law `(mu0, c)` and the
    /// control settings `(T_set, K_P, K_D)`.
    #[must_use]
    pub fn level_kernels(
        &self,
        (mu0, c): (f64, f64),
        (t_set, k_p, k_d): (f64, f64, f64),
    ) -> walker::kernels::general_level::Prepared {
        use walker::kernels::general_level as gl;
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
    pub fn slope_kernels(&self, (mu0, c): (f64, f64)) -> walker::kernels::general_slope::Prepared {
        use walker::kernels::general_slope as gs;
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
    ) -> walker::kernels::general_level_coulomb::Prepared {
        use walker::kernels::general_level_coulomb as glc;
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
    ) -> walker::kernels::general_slope_coulomb::Prepared {
        use walker::kernels::general_slope_coulomb as gsc;
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

/// The input vector `S = [0, 0, 1, -1]` (Eq. 20).
#[must_use]
pub fn s_vec() -> Vector4<f64> {
    Vector4::new(0.0, 0.0, 1.0, -1.0)
}

/// Inertia matrix `M(q)` of Eq. 2.
#[must_use]
pub fn mass_matrix(p: &Phys, th1: f64) -> Matrix4<f64> {
    let mt = p.mt();
    let (s, c) = th1.sin_cos();
    Matrix4::new(
        mt,
        0.0,
        mt * p.l * c,
        0.0,
        0.0,
        mt,
        -mt * p.l * s,
        0.0,
        mt * p.l * c,
        -mt * p.l * s,
        mt * p.l * p.l + p.i1,
        0.0,
        0.0,
        0.0,
        0.0,
        p.i2,
    )
}

/// `h(q, qd)` of Eq. 20 and its absolute-value evaluation (every term replaced by its
/// magnitude), the error scale of a direct evaluation.
#[must_use]
pub fn bias(p: &Phys, th1: f64, th1d: f64) -> (Vector4<f64>, Vector4<f64>) {
    let mt = p.mt();
    let (s, c) = th1.sin_cos();
    let w2 = th1d * th1d;
    let h = Vector4::new(
        -mt * p.l * w2 * s,
        mt * (p.g - p.l * w2 * c),
        -mt * p.g * p.l * s,
        0.0,
    );
    let habs = Vector4::new(
        mt * p.l * w2 * s.abs(),
        mt * (p.g + p.l * w2 * c.abs()),
        mt * p.g * p.l * s.abs(),
        0.0,
    );
    (h, habs)
}

/// Stance constraint `J = [tan phi, 1, 0, 0]` (Eqs. 21, 36).
#[must_use]
pub fn j_stance(phi: f64) -> RowVector4<f64> {
    RowVector4::new(phi.tan(), 1.0, 0.0, 0.0)
}

/// Friction Jacobian `J_mu = [mu, -mu tan phi, 0, 0]` (Eqs. 24, 38).
#[must_use]
pub fn j_mu(phi: f64, mu: f64) -> RowVector4<f64> {
    RowVector4::new(mu, -mu * phi.tan(), 0.0, 0.0)
}

/// Fore-foot impact row: normal velocity of the fore foot on the floor (Eq. 3 on level ground,
/// Eq. 42 on the slope): `[tan phi, 1, l (sin(phi - th1) - sin(phi - th1 + alpha)) / cos phi, 0]`.
#[must_use]
pub fn j_fore(p: &Phys, th1: f64) -> RowVector4<f64> {
    let a = p.l * ((p.phi - th1).sin() - (p.phi - th1 + p.alpha).sin()) / p.phi.cos();
    RowVector4::new(p.phi.tan(), 1.0, a, 0.0)
}

/// Rear-foot impact row (Eq. 4, and the slope's rear foot of Eq. 46): the stance constraint.
#[must_use]
pub fn j_rear(p: &Phys) -> RowVector4<f64> {
    j_stance(p.phi)
}

/// Torso lock row `th1d - th2d = 0` (Eq. 5).
#[must_use]
pub fn j_lock() -> RowVector4<f64> {
    RowVector4::new(0.0, 0.0, 1.0, -1.0)
}

/// The friction law of the `tanh` scenes: `-mu0 tanh(c xd)` on level ground (Eq. 26),
/// `-mu0 tanh(c xd / cos phi)` on the slope (Eq. 37).
#[must_use]
pub fn mu_law(mu0: f64, c: f64, phi: f64, xd: f64) -> f64 {
    if phi == 0.0 {
        -mu0 * (c * xd).tanh()
    } else {
        -mu0 * (c * xd / phi.cos()).tanh()
    }
}

/// The velocity `xd` at which [`mu_law`] gives (up to rounding) `mu`: `xd = cos phi *
/// atanh(-mu / mu0) / c`. Requires `|mu| < mu0`.
#[must_use]
pub fn xd_for_mu(mu: f64, mu0: f64, c: f64, phi: f64) -> f64 {
    (-mu / mu0).atanh() / c * phi.cos()
}

/// Solution of a square linear system with its conditioning (2-norm, by SVD).
#[derive(Debug, Clone)]
pub struct Solved {
    /// The solution.
    pub x: DVector<f64>,
    /// `cond_2(K) = sigma_max / sigma_min`.
    pub cond: f64,
    /// `||K^-1||_2 = 1 / sigma_min`.
    pub inv_norm: f64,
}

impl Solved {
    /// Error scale of the solution for a right-hand side whose entries carry rounding errors
    /// relative to `b_abs` (the absolute-value evaluation of `b`):
    /// `cond(K) ||x|| + ||K^-1|| ||b_abs||`. The perturbation bound of a linear system,
    /// `||dx|| <= ||K^-1|| (||dK|| ||x|| + ||db||)`, with `||dK|| <= c eps ||K||` and
    /// `||db|| <= c eps ||b_abs||` for any backward-stable method, is `c eps` times this.
    #[must_use]
    pub fn scale(&self, b_abs: &DVector<f64>) -> f64 {
        self.cond * self.x.norm() + self.inv_norm * b_abs.norm()
    }
}

/// Solves `k x = b` by LU with partial pivoting and measures `k`'s conditioning by SVD.
///
/// # Errors
/// `k` is exactly singular (LU fails).
pub fn solve(k: &DMatrix<f64>, b: &DVector<f64>) -> Result<Solved, String> {
    let x = k.clone().lu().solve(b).ok_or("singular system")?;
    let sv = k.clone().svd(false, false).singular_values;
    let smax = sv.max();
    let smin = sv.min();
    Ok(Solved {
        x,
        cond: smax / smin,
        inv_norm: 1.0 / smin,
    })
}

/// The stance KKT matrix `[[M, -Jhat^T], [J, 0]]` with `Jhat = J + J_mu`.
#[must_use]
pub fn stance_kkt(p: &Phys, th1: f64, mu: f64) -> DMatrix<f64> {
    let m = mass_matrix(p, th1);
    let j = j_stance(p.phi);
    let jh = j + j_mu(p.phi, mu);
    let mut k = DMatrix::zeros(5, 5);
    k.view_mut((0, 0), (4, 4)).copy_from(&m);
    for i in 0..4 {
        k[(i, 4)] = -jh[i];
        k[(4, i)] = j[i];
    }
    k
}

/// Stance dynamics by the generic path.
#[derive(Debug, Clone)]
pub struct Stance {
    /// Accelerations `qdd` (Eq. 27), from the KKT solve.
    pub qdd: Vector4<f64>,
    /// Vertical reaction `lambda` from the same KKT solve.
    pub lambda_kkt: f64,
    /// `lambda` by Eq. 22 (`M^-1` applied by LU).
    pub lambda_eq22: f64,
    /// Error scale of `qdd` and `lambda` ([`Solved::scale`] of the KKT system).
    pub scale: f64,
    /// `cond_2` of the KKT matrix.
    pub cond: f64,
}

/// Solves the stance dynamics (Eq. 19 with Eq. 21/36) at `q = (., ., th1, .)`, `th1d`, `u`,
/// `mu`.
///
/// # Errors
/// The KKT matrix or `M` is exactly singular.
pub fn stance(p: &Phys, th1: f64, th1d: f64, u: f64, mu: f64) -> Result<Stance, String> {
    let (h, habs) = bias(p, th1, th1d);
    let su = s_vec() * u;
    let r = su - h;
    let k = stance_kkt(p, th1, mu);
    let mut b = DVector::zeros(5);
    let mut b_abs = DVector::zeros(5);
    for i in 0..4 {
        b[i] = r[i];
        b_abs[i] = su[i].abs() + habs[i];
    }
    let sol = solve(&k, &b)?;
    // Eq. 22: lambda = -J M^-1 (S u - h) / (J M^-1 Jhat^T).
    let m = mass_matrix(p, th1);
    let lu = m.lu();
    let j = j_stance(p.phi);
    let jh = j + j_mu(p.phi, mu);
    let minv_r = lu.solve(&r).ok_or("singular M")?;
    let minv_jh = lu.solve(&jh.transpose()).ok_or("singular M")?;
    let lambda_eq22 = -(j * minv_r)[0] / (j * minv_jh)[0];
    Ok(Stance {
        qdd: Vector4::new(sol.x[0], sol.x[1], sol.x[2], sol.x[3]),
        lambda_kkt: sol.x[4],
        lambda_eq22,
        scale: sol.scale(&b_abs),
        cond: sol.cond,
    })
}

/// `Y` of Eq. 28 (with `M.try_inverse()`) and its error scale `cond(K) max(1, ||Y||_2)`, `K`
/// the stance KKT matrix: `Y` is a rational function of `M`, `J`, `Jhat` whose only
/// denominator is the Schur complement `J M^-1 Jhat^T` of `K`, so its relative sensitivity to
/// relative perturbations of the data is bounded by `cond(K)` (up to a modest factor).
///
/// # Errors
/// `M` or the Schur complement is singular.
pub fn projection(p: &Phys, th1: f64, mu: f64) -> Result<(Matrix4<f64>, f64), String> {
    let m = mass_matrix(p, th1);
    let minv = m.try_inverse().ok_or("singular M")?;
    let j = j_stance(p.phi);
    let jh = j + j_mu(p.phi, mu);
    let d = (j * minv * jh.transpose())[0];
    if d == 0.0 {
        return Err("singular Schur complement".into());
    }
    let y = Matrix4::identity() - jh.transpose() * (j * minv) / d;
    let cond = solve(&stance_kkt(p, th1, mu), &DVector::zeros(5))?.cond;
    Ok((y, cond * y.norm().max(1.0)))
}

/// `A` and `B` of Eqs. 30-31 (`A = S^T M^-1 Y S`, `B = S^T M^-1 Y h`, from Eq. 28's `Y`), with
/// their error scales. `A` (`B`) is `S^T` times the KKT solution for the right-hand side `[S; 0]`
/// (`[h; 0]`), so the scales are `||S|| * Solved::scale` of those systems.
///
/// # Errors
/// `M` or the KKT matrix is singular.
pub fn control(p: &Phys, th1: f64, th1d: f64, mu: f64) -> Result<[f64; 4], String> {
    let m = mass_matrix(p, th1);
    let minv = m.try_inverse().ok_or("singular M")?;
    let (y, _) = projection(p, th1, mu)?;
    let (h, habs) = bias(p, th1, th1d);
    let s = s_vec();
    let a = (s.transpose() * minv * y * s)[0];
    let bb = (s.transpose() * minv * y * h)[0];
    let k = stance_kkt(p, th1, mu);
    let mut rs = DVector::zeros(5);
    let mut rh = DVector::zeros(5);
    let mut rh_abs = DVector::zeros(5);
    for i in 0..4 {
        rs[i] = s[i];
        rh[i] = h[i];
        rh_abs[i] = habs[i];
    }
    let sa = solve(&k, &rs)?;
    let sb = solve(&k, &rh)?;
    let rs_abs = rs.abs();
    let n_s = s.norm();
    Ok([a, bb, n_s * sa.scale(&rs_abs), n_s * sb.scale(&rh_abs)])
}

/// The stick KKT matrix `[[M, -J_p^T], [J_p, 0]]`, `J_p = d(x, z)/dq = [[1, 0, 0, 0],
/// [0, 1, 0, 0]]`: the foot's position held, whatever the floor (not in the paper).
#[must_use]
pub fn stick_kkt(p: &Phys, th1: f64) -> DMatrix<f64> {
    let m = mass_matrix(p, th1);
    let mut k = DMatrix::zeros(6, 6);
    k.view_mut((0, 0), (4, 4)).copy_from(&m);
    for c in 0..2 {
        k[(c, 4 + c)] = -1.0;
        k[(4 + c, c)] = 1.0;
    }
    k
}

/// Which contact the foot makes: sliding with friction coefficient `mu` (one constraint row,
/// Eqs. 19, 21-24, 36-38) or stuck (two rows, see [`stick_kkt`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Contact {
    /// Sliding, `mu` the friction coefficient with its direction (Eq. 24).
    Slide(f64),
    /// Stuck (the stick phase of Coulomb friction; not in the paper).
    Stick,
}

impl Contact {
    /// The KKT matrix of the contact.
    #[must_use]
    pub fn kkt(self, p: &Phys, th1: f64) -> DMatrix<f64> {
        match self {
            Contact::Slide(mu) => stance_kkt(p, th1, mu),
            Contact::Stick => stick_kkt(p, th1),
        }
    }
}

/// The stick phase by the generic path.
#[derive(Debug, Clone)]
pub struct Stick {
    /// Accelerations (the first two are zero up to rounding).
    pub qdd: Vector4<f64>,
    /// `[lambda_t, lambda_n]`: the ground force along the floor's unit tangent
    /// `(cos phi, -sin phi)` and its unit normal `(sin phi, cos phi)`.
    pub lambda: [f64; 2],
    /// Error scale ([`Solved::scale`] of the KKT system; the rotation of the force into
    /// tangent and normal is orthogonal and adds a few roundings only).
    pub scale: f64,
    /// `cond_2` of the KKT matrix.
    pub cond: f64,
}

/// The ground force `F = (F_x, F_z)` on the foot resolved along the floor's unit tangent and
/// normal: `[F . (cos phi, -sin phi), F . (sin phi, cos phi)]`.
#[must_use]
pub fn resolve_on_floor(phi: f64, fx: f64, fz: f64) -> [f64; 2] {
    let (s, c) = phi.sin_cos();
    [fx * c - fz * s, fx * s + fz * c]
}

/// Solves the stick phase at `th1`, `th1d` with torque `u` (`u = 0` for the passive wheel).
///
/// # Errors
/// The KKT matrix is exactly singular.
pub fn stick(p: &Phys, th1: f64, th1d: f64, u: f64) -> Result<Stick, String> {
    let (h, habs) = bias(p, th1, th1d);
    let su = s_vec() * u;
    let mut b = DVector::zeros(6);
    let mut b_abs = DVector::zeros(6);
    for i in 0..4 {
        b[i] = su[i] - h[i];
        b_abs[i] = su[i].abs() + habs[i];
    }
    let sol = solve(&stick_kkt(p, th1), &b)?;
    Ok(Stick {
        qdd: Vector4::new(sol.x[0], sol.x[1], sol.x[2], sol.x[3]),
        lambda: resolve_on_floor(p.phi, sol.x[4], sol.x[5]),
        scale: sol.scale(&b_abs),
        cond: sol.cond,
    })
}

/// A closed loop (Eq. 31 and its stick counterpart) by the generic path.
#[derive(Debug, Clone)]
pub struct ClosedLoop {
    /// `A`, `B` with `yddot = A u - B` (Eq. 30).
    pub a: f64,
    /// See `a`.
    pub b: f64,
    /// `u = (v + B) / A` (Eq. 31).
    pub u: f64,
    /// Accelerations at that `u`.
    pub qdd: Vector4<f64>,
    /// The multipliers at that `u`: for sliding the one reaction `lambda` (vertical, Eqs.
    /// 22-23, as [`stance_kkt`] scales its row); for sticking `[lambda_t, lambda_n]` (the
    /// Cartesian force resolved by [`resolve_on_floor`]).
    pub lambda: Vec<f64>,
    /// Error scale of `u`: `(|v| + s_B + |u| s_A) / |A|` with `s_A`, `s_B` the error scales of
    /// `A`, `B` (`||S|| Solved::scale` of their systems): first-order propagation through
    /// `u = (v + B) / A`, the `|v|` for the rounding of `v + B`.
    pub scale_u: f64,
    /// Error scale of `qdd` and the multipliers: [`Solved::scale`] of the system at `u`, plus
    /// `||x_S|| scale_u`, `x_S` the solution for `[S; 0]` (how an error of `u` moves them).
    pub scale: f64,
    /// `cond_2` of the KKT matrix.
    pub cond: f64,
}

/// Solves the closed loop with auxiliary input `v` for a contact: `A`, `B` by two KKT solves,
/// `u = (v + B) / A`, then the KKT system at that `u`.
///
/// # Errors
/// The KKT matrix is exactly singular.
pub fn closed_loop(
    p: &Phys,
    th1: f64,
    th1d: f64,
    v: f64,
    contact: Contact,
) -> Result<ClosedLoop, String> {
    let k = contact.kkt(p, th1);
    let n = k.nrows();
    let (h, habs) = bias(p, th1, th1d);
    let s = s_vec();
    let mut rs = DVector::zeros(n);
    let mut rh = DVector::zeros(n);
    let mut rh_abs = DVector::zeros(n);
    for i in 0..4 {
        rs[i] = s[i];
        rh[i] = h[i];
        rh_abs[i] = habs[i];
    }
    let xs = solve(&k, &rs)?;
    let xh = solve(&k, &rh)?;
    let ydd = |x: &DVector<f64>| x[2] - x[3];
    let (a, b) = (ydd(&xs.x), ydd(&xh.x));
    let n_s = s.norm();
    let (sa, sb) = (n_s * xs.scale(&rs.abs()), n_s * xh.scale(&rh_abs));
    let u = (v + b) / a;
    let scale_u = (v.abs() + sb + u.abs() * sa) / a.abs();
    let mut r = DVector::zeros(n);
    let mut r_abs = DVector::zeros(n);
    for i in 0..4 {
        r[i] = s[i] * u - h[i];
        r_abs[i] = (s[i] * u).abs() + habs[i];
    }
    let sol = solve(&k, &r)?;
    let lambda = match contact {
        Contact::Slide(_) => vec![sol.x[4]],
        Contact::Stick => resolve_on_floor(p.phi, sol.x[4], sol.x[5]).to_vec(),
    };
    Ok(ClosedLoop {
        a,
        b,
        u,
        qdd: Vector4::new(sol.x[0], sol.x[1], sol.x[2], sol.x[3]),
        lambda,
        scale_u,
        scale: sol.scale(&r_abs) + xs.x.norm() * scale_u,
        cond: sol.cond,
    })
}

/// An impact by the generic path.
#[derive(Debug, Clone)]
pub struct Impact {
    /// Impulses, one per constraint row.
    pub lambda: Vec<f64>,
    /// Post-impact velocities (old coordinates).
    pub qd_plus: Vector4<f64>,
    /// Error scale ([`Solved::scale`] with `b_abs = [|M| |qd-|; 0]`).
    pub scale: f64,
    /// `cond_2` of the impact KKT matrix.
    pub cond: f64,
}

/// Solves Eq. 1 with the constraint rows `rows` as one linear system
/// `[[M, -J_I^T], [J_I, 0]] [qd+; lambda_I] = [M qd-; 0]`.
///
/// # Errors
/// The system is exactly singular.
pub fn impact(
    p: &Phys,
    rows: &[RowVector4<f64>],
    th1: f64,
    qd: Vector4<f64>,
) -> Result<Impact, String> {
    let m = mass_matrix(p, th1);
    let n = 4 + rows.len();
    let mut k = DMatrix::zeros(n, n);
    k.view_mut((0, 0), (4, 4)).copy_from(&m);
    for (r, row) in rows.iter().enumerate() {
        for i in 0..4 {
            k[(i, 4 + r)] = -row[i];
            k[(4 + r, i)] = row[i];
        }
    }
    let mq = m * qd;
    let mq_abs = m.abs() * qd.abs();
    let mut b = DVector::zeros(n);
    let mut b_abs = DVector::zeros(n);
    for i in 0..4 {
        b[i] = mq[i];
        b_abs[i] = mq_abs[i];
    }
    let sol = solve(&k, &b)?;
    Ok(Impact {
        lambda: (0..rows.len()).map(|r| sol.x[4 + r]).collect(),
        qd_plus: Vector4::new(sol.x[0], sol.x[1], sol.x[2], sol.x[3]),
        scale: sol.scale(&b_abs),
        cond: sol.cond,
    })
}

/// The constraint rows of the four impact kernels (docs/kernels.md), by kernel name.
#[must_use]
pub fn impact_rows(kernel: &str, p: &Phys, th1: f64) -> Vec<RowVector4<f64>> {
    match kernel {
        "impact3_level" => vec![j_fore(p, th1), j_rear(p), j_lock()],
        "impact2_level" => vec![j_fore(p, th1), j_lock()],
        "impact_slope" => vec![j_fore(p, th1)],
        "impact2_slope" => vec![j_fore(p, th1), j_rear(p)],
        _ => Vec::new(),
    }
}

/// Fore-foot position and velocity `[x_f, z_f, xd_f, zd_f]` (docs/kernels.md) and their
/// absolute-value evaluation (the rounding of `th1 - alpha` enters through `|th1| + |alpha|`).
#[must_use]
pub fn fore_foot(
    p: &Phys,
    x: f64,
    z: f64,
    th1: f64,
    xd: f64,
    zd: f64,
    th1d: f64,
) -> ([f64; 4], [f64; 4]) {
    let (s, c) = th1.sin_cos();
    let (sa, ca) = (th1 - p.alpha).sin_cos();
    let l = p.l;
    let v = [
        x + l * s - l * sa,
        z + l * c - l * ca,
        xd + l * c * th1d - l * ca * th1d,
        zd - l * s * th1d + l * sa * th1d,
    ];
    let arg = 1.0 + th1.abs() + p.alpha.abs();
    let a = [
        x.abs() + l * (1.0 + arg),
        z.abs() + l * (1.0 + arg),
        xd.abs() + l * th1d.abs() * (1.0 + arg),
        zd.abs() + l * th1d.abs() * (1.0 + arg),
    ];
    (v, a)
}

/// Kinetic and potential energy `[T, V]` (docs/kernels.md) as `T = 1/2 qd^T M qd`,
/// `V = m_t g (z + l cos th1)`, with their absolute-value evaluations.
#[must_use]
pub fn energy(p: &Phys, z: f64, th1: f64, qd: Vector4<f64>) -> ([f64; 2], [f64; 2]) {
    let m = mass_matrix(p, th1);
    let t = 0.5 * (qd.transpose() * m * qd)[0];
    let t_abs = 0.5 * (qd.abs().transpose() * m.abs() * qd.abs())[0];
    let mt = p.mt();
    let c = th1.cos();
    let v = mt * p.g * (z + p.l * c);
    let v_abs = mt * p.g * (z.abs() + p.l * c.abs());
    ([t, v], [t_abs, v_abs])
}

/// Horizontal position of the hip and the centre of mass of the whole walker.
#[must_use]
pub fn hip(p: &Phys, x: f64, z: f64, th1: f64) -> (f64, f64) {
    (x + p.l * th1.sin(), z + p.l * th1.cos())
}

/// Angular momentum of the walker about the point `(px, pz)` (sense of positive `th1`):
/// `m_t ((z_h - pz) xd_h - (x_h - px) zd_h) + I1 th1d + I2 th2d`.
#[must_use]
pub fn angular_momentum(p: &Phys, q: Vector4<f64>, qd: Vector4<f64>, px: f64, pz: f64) -> f64 {
    let (xh, zh) = hip(p, q[0], q[1], q[2]);
    let (s, c) = q[2].sin_cos();
    let xdh = qd[0] + p.l * c * qd[2];
    let zdh = qd[1] - p.l * s * qd[2];
    p.mt() * ((zh - pz) * xdh - (xh - px) * zdh) + p.i1 * qd[2] + p.i2 * qd[3]
}

/// Units in the last place of `x` (for `x = 0`: the smallest subnormal).
#[must_use]
pub fn ulp(x: f64) -> f64 {
    let a = x.abs();
    if a == 0.0 || !a.is_finite() {
        return f64::from_bits(1);
    }
    let next = f64::from_bits(a.to_bits() + 1);
    next - a
}
